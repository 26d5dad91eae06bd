#1=0
WH [#1 LT 3] DO1
#1=#1+1
EN1
#2=RO[2.5]+FI[-1.5]+FU[1.2]+SQ[16]+AB[-1]
#3=[12 AN 10] + [1 XO 3] + [7 MO 4]
IF [#1 EQ 3] TH #4=1
IF [#1 NE 3] GO 100
G0 X#1 Y#2 Z#3
G0 X#4 Y[AT[1]/[1]]
N100 M30
%
; FEATURES: ISO-MAC-08
; Fanuc Custom Macro B two-letter abbreviations (issue 7 part 3): WH WHILE, EN END, TH THEN,
; GO GOTO, RO ROUND, FI FIX, FU FUP, SQ SQRT, AB ABS, AT ATAN, AN AND, XO XOR, MO MOD. Both
; engines: #2 = 3 - 1 + 2 + 4 + 1, #3 = 8 + 2 + 3 (bitwise AN/XO), Y = ATAN[1]/[1].
; RUN: %ncc run %s --trace=canon -q | FileCheck %s
; RUN: %ncc run %s --trace=canon -q --engine=jit | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(3.0000, 9.0000, 13.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(1.0000, 45.0000, 13.0000,
; RS274NGC has no abbreviations: WH is an unknown word there.
; RUN: printf 'WH [1 LT 0] DO1\nEN1\nM2\n' > %t.ngc
; RUN: not %ncc run %t.ngc 2>&1 | FileCheck %s --check-prefix=NGC
; NGC: error: unknown word 'WH'
; A bare GO (no IF or WH in the program) is a GOTO too: the stream's pre-scan sends the program
; to the whole-program parse (it used to stop with "not streamable").
; RUN: printf 'G1 X1 F100\nGO 3\nG1 X2\nN3 G1 X3\nM30\n' > %t.go.nc
; RUN: %ncc run %t.go.nc --trace=canon -q | FileCheck %s --check-prefix=GO
; GO: STRAIGHT_FEED(1.0000,
; GO-NEXT: N3 {{ *}}STRAIGHT_FEED(3.0000,
