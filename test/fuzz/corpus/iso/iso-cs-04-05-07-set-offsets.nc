G92 X0 Y0 Z0
G92.1
G92.1 X0 Y0
G10 L2 P1 X10 Y10
G10 L20 P2 X1
%
; FEATURES: ISO-CS-04 ISO-CS-05 ISO-CS-07
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: set_offset kind=g92 X=0 Y=0 Z=0 loc(1:1:1)
; CHECK-NOT: move
; CHECK: set_offset kind=g92_1 loc(1:2:1)
; CHECK: set_offset kind=g92_1 X=0 Y=0 loc(1:3:1)
; CHECK: set_offset kind=g10l2 index=1 X=10 Y=10 loc(1:4:1)
; CHECK: set_offset kind=g10l20 index=2 X=1 loc(1:5:1)
