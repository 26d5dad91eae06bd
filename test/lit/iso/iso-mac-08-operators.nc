#1 = 1 + 2 * 3 - 4 / 2
#2 = #1 GT 3
#3 = [1 + 2] * 3
#4 = 7 MOD 3 AND 1 OR 2 XOR 3
#5 = #1 EQ #0
#6 = [#1 NE 2] AND [#2 GE 1] OR [#3 LT 4] OR [#4 LE 5]
#7 = -[#1] * -2
#8=#1gt#2
%
; FEATURES: ISO-MAC-08
; Fanuc precedence: brackets/functions, then * / AND MOD, then + - OR XOR, then comparisons;
; left associative. Operator names are case-insensitive and need no blanks.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: assign target=#1 value=(sub (add 1 (mul 2 3)) (div 4 2))
; CHECK: assign target=#2 value=(gt #1 3)
; CHECK: assign target=#3 value=(mul (add 1 2) 3)
; CHECK: assign target=#4 value=(bxor (bor (band (mod 7 3) 1) 2) 3)
; CHECK: assign target=#5 value=(eq #1 vacant)
; CHECK: assign target=#6 value=(or (or (and (ne #1 2) (ge #2 1)) (lt #3 4)) (le #4 5))
; CHECK: assign target=#7 value=(mul (neg #1) -2)
; CHECK: assign target=#8 value=(gt #1 #2)
