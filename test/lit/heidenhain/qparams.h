; FEATURES: HEI-QPR-03 HEI-QP-01 HEI-QP-02 HEI-QP-06 HEI-MOT-11 HEI-QPR-05
; Q parameters: Q (global), QL (local), QR, all 0 at the start; formulas with the TNC's
; precedence (^ before * / before + -) and functions in degrees; FN 0-FN 8 and FN 13; FN 9-FN 12
; jump to labels; Q parameters in coordinates and feeds (`X+Q1`, `X-Q1`, `FQ2`). Each value is
; shown as the X of a rapid move.
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.e
; CHECK: rapid X0 Y0 Z0 {{.*}} N1
; CHECK-NEXT: rapid X0 Y0 Z0 {{.*}} N2
; 3 + 2 * SIN(90)^2 = 5; 2^3^2 = 512 (right-associative); (1 + 2) * 3 = 9
; CHECK-NEXT: rapid X5 Y512 Z9 {{.*}} N6
; SQ 3 + INT 2.7 + FRAC 2.5 + SGN -4 + LOG 100 + NEG 1 = 9 + 2 + 0.5 - 1 + 2 - 1
; CHECK-NEXT: rapid X11.5 Y0 Z0 {{.*}} N8
; SQRT 16, ABS -3, ATAN 1, ASIN 1, ACOS 0, LN EXP 2, TAN 45, COS 180
; CHECK-NEXT: rapid X4 Y3 Z45 {{.*}} N12
; CHECK-NEXT: rapid X4 Y3 Z45 {{.*}} N13
; CHECK-NEXT: rapid X90 Y90 Z2 {{.*}} N15
; CHECK-NEXT: rapid X{{1|0.99999+}} Y-1 Z0 {{.*}} N17
; FN 0 … FN 8, FN 13: 35, +Q1 - +Q2 with Q2 = 5 gives 30, 6 * 7, 10 DIV 4, SQRT 81, SIN 30, COS 60, 3 LEN 4, 1 ANG -1
; CHECK-NEXT: rapid X35 Y30 Z42 {{.*}} N28
; CHECK-NEXT: rapid X2.5 Y9 Z{{0.5|0.49999+[0-9]*}} {{.*}} N29
; CHECK-NEXT: rapid X{{0.5|0.50000+[0-9]*}} Y5 Z315 {{.*}} N30
; A loop by FN 12: X counts 1, 2, 3; X-Q1 negates; the feed from FQ5.
; CHECK-NEXT: rapid X1 Y0 Z0 {{.*}} N33
; CHECK-NEXT: rapid X2 Y0 Z0 {{.*}} N33
; CHECK-NEXT: rapid X3 Y0 Z0 {{.*}} N33
; CHECK-NEXT: feed_rate 250
; CHECK-NEXT: linear X-3 Y0 Z0 {{.*}} F250 N36
; FN 9 jumps over the next block when equal; FN 10 and FN 11 do not jump.
; CHECK-NEXT: rapid X7 Y0 Z0 {{.*}} N42
; CHECK-NEXT: program_end 2
; Out of range, a string parameter, an unknown FN, a jump to a missing label: located errors.
; RUN: printf '0 BEGIN PGM E MM\n1 Q2000 = 1\n2 QL500 = 1\n3 QS1 = 1\n4 FN 16: F-PRINT\n5 FN 9: IF +1 EQU +1 GOTO LBL 7\n6 Q1 = 2 +\n7 Q1 = SIN(30\n8 END PGM E MM\n' > %t.err.h
; RUN: not %ncc compile --emit=ir %t.err.h 2>&1 | FileCheck %s --check-prefix=ERR
; ERR: err.h:2:4: error: Q2000 is out of range (Q0 to Q1999) [syntax]
; ERR: err.h:3:5: error: QL500 is out of range (QL0 to QL499) [syntax]
; ERR: err.h:4:9: error: a string in quotes or a QS parameter was expected [syntax]
; ERR: err.h:5:6: error: FN 16 is not simulated yet [unsupported-code]
; ERR: err.h:7:11: error: the formula ends early [syntax]
; ERR: err.h:8:14: error: ')' expected [syntax]
; ERR: err.h:6:31: error: jump to LBL7 that is not defined in this program [missing-block]
; FN 14 stops the run with its number:
; RUN: printf '0 BEGIN PGM E MM\n1 L X+1 R0 FMAX\n2 FN 14: ERROR = 1000\n3 L X+2 R0 FMAX\n4 END PGM E MM\n' > %t.fn14.h
; RUN: not %ncc run %t.fn14.h 2>&1 | FileCheck %s --check-prefix=FN14
; FN14: fn14.h:3:3: error: FN 14: error 1000 [abort]
0 BEGIN PGM QPARAMS MM
1 L X+Q1 Y+QL1 Z+QR1 R0 FMAX
2 L X+0 Y+0 Z+0 R0 FMAX
3 Q1 = 3 + 2 * SIN(90) ^ 2
4 Q2 = 2 ^ 3 ^ 2
5 q3 = (1 + 2) * 3
6 L X+Q1 Y+Q2 Z+Q3 R0 FMAX
7 QL1 = SQ 3 + INT 2.7 + FRAC 2.5 + SGN -4 + LOG 100 + NEG 1
8 L X+QL1 Y+0 Z+0 R0 FMAX
9 Q1 = SQRT 16
10 Q2 = ABS -3
11 QR3 = ATAN 1
12 L X+Q1 Y+Q2 Z+QR3 R0 FMAX
13 L X+Q1 Y+Q2 Z+QR3 R0 FMAX
14 Q4 = ASIN 1
15 Q5 = ACOS 0
16 Q6 = LN EXP 2
15 L X+Q4 Y+Q5 Z+Q6 R0 FMAX
16 Q7 = TAN 45
17 Q8 = COS 180
17 L X+Q7 Y+Q8 Z+0 R0 FMAX
20 FN 0: Q1 = +35
21 Q2 = 5
22 FN 2: Q2 = +Q1 - +Q2
23 FN 3: Q3 = +6 * +7
24 FN 4: Q4 = +10 DIV +4
25 FN 5: Q5 = SQRT +81
26 FN 6: Q6 = SIN +30
27 FN 7: Q7 = COS +60
28 L X+Q1 Y+Q2 Z+Q3 R0 FMAX
29 L X+Q4 Y+Q5 Z+Q6 R0 FMAX
27 FN 8: Q8 = +3 LEN +4
27 FN 13: Q9 = +1 ANG -1
30 L X+Q7 Y+Q8 Z+Q9 R0 FMAX
31 Q1 = 0
32 LBL 1
32 Q1 = Q1 + 1
33 L X+Q1 Y+0 Z+0 R0 FMAX
34 FN 12: IF +Q1 LT +3 GOTO LBL 1
35 Q5 = 250
36 L X-Q1 FQ5
37 FN 9: IF +Q5 EQU +250 GOTO LBL "SKIP"
38 L X+99 R0 FMAX
39 LBL "SKIP"
40 FN 10: IF +Q5 NE +250 GOTO LBL 1
41 FN 11: IF +Q5 GT +250 GOTO LBL 1
42 L X+7 R0 FMAX
43 M2
44 END PGM QPARAMS MM
