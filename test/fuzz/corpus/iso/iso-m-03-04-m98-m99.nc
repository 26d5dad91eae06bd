O0001 (MAIN)
M98 P1234
M98 P00021234
M98 P30021
M98 P21 L4
M30
O1234 (SUB)
G91 G1 X10
M99
O21
G0 Z1
M99
%
; FEATURES: ISO-M-03 ISO-M-04 ISO-SUB-01
; M98 P<count 4 digits><program 4 digits> or P<program> L<count>; subprograms follow the main
; program in the same file as O-number programs and end with M99.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: func @main
; CHECK: call callee="O1234" count=1 frame=shared loc(1:2:1)
; CHECK: call callee="O1234" count=2 frame=shared loc(1:3:1)
; CHECK: call callee="O21" count=3 frame=shared loc(1:4:1)
; CHECK: call callee="O21" count=4 frame=shared loc(1:5:1)
; CHECK: stop kind=end_rewind
; CHECK-NEXT: }
; CHECK-NEXT: func @O1234 loc(1:7:1)
; CHECK-NEXT: block loc(1:7:1)
; CHECK-NEXT: comment text="SUB"
; CHECK-NEXT: block loc(1:8:1)
; CHECK-NEXT: mode distance=incremental
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=10
; CHECK-NEXT: block loc(1:9:1)
; CHECK-NEXT: return loc(1:9:1)
; CHECK-NEXT: }
; CHECK-NEXT: func @O21 loc(1:10:1)
; CHECK: return
