G05 P10123 L3
G5 P0123
G05
G05 P0
G05 P01
G05.1
M30
O10123
M99
O123
M99
%
; FEATURES: ISO-SUB-02
; 808D G05 P<program> L<count> calls a subprogram like M98 (spec L4874-4901); G05 without P,
; G05 P0, G05 P01 and G05.1 are ignored without alarm.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: block loc(1:1:1)
; CHECK-NEXT: call callee="O10123" count=3 frame=shared loc(1:1:1)
; CHECK-NEXT: block loc(1:2:1)
; CHECK-NEXT: call callee="O123" count=1 frame=shared
; CHECK-NEXT: block loc(1:3:1)
; CHECK-NEXT: block loc(1:4:1)
; CHECK-NEXT: block loc(1:5:1)
; CHECK-NEXT: block loc(1:6:1)
; CHECK-NEXT: block loc(1:7:1)
; CHECK-NEXT: stop kind=end_rewind
