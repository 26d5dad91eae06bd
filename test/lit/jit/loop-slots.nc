O1000 (LOOP VARIABLES IN SLOTS)
G21 G90 G17 G94 F1000.
#100=0
#101=0
WHILE [#101 LT 10] DO1
#100=#100+#101
#101=#101+1
END1
G1 X#100 Y#101
#102=0
WHILE [#102 LT 3] DO1
M98 P2000
#102=#102+1
END1
G1 X#103
#104=0
#106=0
WHILE [#104 LT 4] DO1
#105=#110
IF [#110 EQ #0] THEN #106=#106+1
IF [#110 EQ 0] THEN #106=#106+100
#104=#104+1
END1
G1 X#106 Y#105
#107=0
WHILE [1 EQ 1] DO1
#107=#107+2
IF [#107 GT 7] GOTO 50
END1
N50 G1 X#107
#1=5
#108=0
WHILE [#108 LT 2] DO1
#1=#1*2
#108=#108+1
G1 Z-#1
END1
G1 X#1
M30
O2000
#103=#103+10
M99
%
%
; FEATURES: ISO-MAC-08
; The JIT keeps a loop's variables in stack slots (registers after optimisation) when nothing
; but the loop's own reads and writes can reach them, and stores them back at the exit: a sum
; read after its loop; a loop that calls a subprogram changing a common (no slots); a vacant
; common copied and compared in a loop (vacant is not 0); a goto out of a loop (no slots); frame
; locals with a move per iteration. Both engines give the same trace and the same block count.
; RUN: %ncc run %s --engine=eval --trace=canon -q > %t.e
; RUN: %ncc run %s --engine=jit --trace=canon -q > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: STRAIGHT_FEED(45.0000, 10.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(30.0000, 10.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(4.0000, 10.0000, 0.0000,
; CHECK-NEXT: N50 STRAIGHT_FEED(8.0000, 10.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(8.0000, 10.0000, -10.0000,
; CHECK-NEXT: STRAIGHT_FEED(8.0000, 10.0000, -20.0000,
; CHECK-NEXT: STRAIGHT_FEED(20.0000, 10.0000, -20.0000,
; RUN: %ncc run %s --engine=eval | grep '^blocks:' > %t.be
; RUN: %ncc run %s --engine=jit | grep '^blocks:' > %t.bj
; RUN: diff %t.be %t.bj
; RUN: FileCheck %s --check-prefix=BLOCKS < %t.bj
; BLOCKS: blocks: {{[1-9][0-9]+}}
; Slots for the first, third and fifth loop (2 + 4 + 2 variables; #0 is always vacant), none for
; the loops with M98 and GOTO.
; RUN: %ncc compile --emit=llvm %s | FileCheck %s --check-prefix=IR
; IR-COUNT-8: %kept{{[0-9]*}} = alloca double
; IR-NOT: %kept{{[0-9]*}} = alloca
