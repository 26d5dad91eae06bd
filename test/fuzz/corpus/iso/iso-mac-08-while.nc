N50 WHILE [#1 GT 0] DO1
#1 = #1 - 1
WHILE [#3 LT 2] DO2
G1 X#3
#3 = #3 + 1
END2
END1
DO3
IF [#1 LT 0] GOTO 99
#1 = #1 - 1
END3
N99 M30
%
; FEATURES: ISO-MAC-08
; WHILE [c] DOm ... ENDm (nested), DOm ... ENDm without WHILE = endless loop.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: block n=50 loc(1:1:1)
; CHECK-NEXT: while cond=(gt #1 0) id=1 loc(1:1:5) {
; CHECK-NEXT: block loc(1:2:1)
; CHECK-NEXT: assign target=#1 value=(sub #1 1)
; CHECK-NEXT: block loc(1:3:1)
; CHECK-NEXT: while cond=(lt #3 2) id=2 loc(1:3:1) {
; CHECK-NEXT: block loc(1:4:1)
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=#3
; CHECK-NEXT: block loc(1:5:1)
; CHECK-NEXT: assign target=#3 value=(add #3 1)
; CHECK-NEXT: block loc(1:6:1)
; CHECK-NEXT: }
; CHECK-NEXT: block loc(1:7:1)
; CHECK-NEXT: }
; CHECK-NEXT: block loc(1:8:1)
; CHECK-NEXT: while cond=true id=3 loc(1:8:1) {
; CHECK-NEXT: block loc(1:9:1)
; CHECK-NEXT: if cond=(lt #1 0)
; CHECK-NEXT: goto n=99
; CHECK-NEXT: }
; CHECK: block loc(1:11:1)
; CHECK-NEXT: }
; CHECK-NEXT: block n=99
