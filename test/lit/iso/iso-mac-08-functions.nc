#5 = SIN[30] + COS[60] + TAN[45] + ASIN[0.5] + ACOS[0.5] + ATAN[1]
#6 = ATAN[1]/[2] + SQRT[16] + ABS[-3] + ROUND[2.5] + FIX[2.7] + FUP[2.2] + LN[10] + EXP[1]
#7 = ATAN[1,2] + ATAN[1]/2
#10=sin[#1]
G1 X SIN[30]
%
; FEATURES: ISO-MAC-08
; Builtin functions (upper-case Call names); ATAN[a]/[b] and ATAN[a,b] are ATAN2.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: assign target=#5 value=(add (add (add (add (add (SIN 30) (COS 60)) (TAN 45)) (ASIN 0.5)) (ACOS 0.5)) (ATAN 1))
; CHECK: assign target=#6 value=(add (add (add (add (add (add (add (ATAN2 1 2) (SQRT 16)) (ABS -3)) (ROUND 2.5)) (TRUNC 2.7)) (AWAYFROMZERO 2.2)) (LN 10)) (EXP 1))
; CHECK: assign target=#7 value=(add (ATAN2 1 2) (div (ATAN 1) 2))
; CHECK: assign target=#10 value=(SIN #1)
; CHECK: move X=(SIN 30)
