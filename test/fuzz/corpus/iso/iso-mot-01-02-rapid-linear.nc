G0 X0 Y0
G1 X10 Y5 F200
Y7
G00 Z1.
%
; FEATURES: ISO-MOT-01 ISO-MOT-02 ISO-FEED-01
; G00/G01 set the motion mode; a block with only axis words moves in the current mode.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: block loc(1:1:1)
; CHECK-NEXT: mode motion=rapid loc(1:1:1)
; CHECK-NEXT: move X=0 Y=0 loc(1:1:1)
; CHECK-NEXT: block loc(1:2:1)
; CHECK-NEXT: feed value=200 loc(1:2:11)
; CHECK-NEXT: mode motion=linear loc(1:2:1)
; CHECK-NEXT: move X=10 Y=5 loc(1:2:1)
; CHECK-NEXT: block loc(1:3:1)
; CHECK-NEXT: move Y=7 loc(1:3:1)
; CHECK-NEXT: block loc(1:4:1)
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: move Z=1.0
