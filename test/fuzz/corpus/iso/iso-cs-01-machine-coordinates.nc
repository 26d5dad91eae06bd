G53 G0 X0 Z0
G1 G53 Z-10
G53 X5
%
; FEATURES: ISO-CS-01
; G53: one move in machine coordinates, rapid or feed by the motion mode.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: machine_move rapid=true X=0 Z=0 loc(1:1:1)
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: block
; CHECK-NEXT: machine_move rapid=false Z=-10
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: block
; CHECK-NEXT: machine_move rapid=false X=5
