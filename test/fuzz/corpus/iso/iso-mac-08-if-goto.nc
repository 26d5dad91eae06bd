#1 = 0
N10 IF [#1 GE 3] GOTO 50
IF [#1 EQ 1] THEN #2 = 7
#1 = #1 + 1
GOTO 10
GOTO #5
N50 IF [#1 EQ 3] THEN G1 X#1
M30
%
; FEATURES: ISO-MAC-08
; IF [c] GOTO n, IF [c] THEN statement, GOTO n / GOTO #var; goto targets are block numbers.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: block n=10 loc(1:2:1)
; CHECK-NEXT: if cond=(ge #1 3) loc(1:2:5) {
; CHECK-NEXT: goto n=50
; CHECK-NEXT: }
; CHECK-NEXT: block loc(1:3:1)
; CHECK-NEXT: if cond=(eq #1 1) loc(1:3:1) {
; CHECK-NEXT: assign target=#2 value=7 loc(1:3:19)
; CHECK-NEXT: }
; CHECK: block loc(1:5:1)
; CHECK-NEXT: goto n=10 loc(1:5:1)
; CHECK-NEXT: block
; CHECK-NEXT: goto n=#5
; CHECK-NEXT: block n=50
; CHECK-NEXT: if cond=(eq #1 3) loc(1:7:5) {
; CHECK-NEXT: mode motion=linear
; CHECK-NEXT: move X=#1
; CHECK-NEXT: }
