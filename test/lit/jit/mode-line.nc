O1000 (A MODE AND A COMPUTED MOVE ON ONE LINE)
G21 G90 G17 G94 F1000.
#1=0
WHILE [#1 LT 3] DO1
G1 X[#1*2] Y[#1]
#1=#1+1
END1
#1=0
WHILE [#1 LT 4] DO1
G0 X[#1] Z5.
G1 Z[0-#1]
#1=#1+1
END1
#1=0
WHILE [#1 LT 2] DO1
G2 X[10+#1] Y0 R20.
G91 G1 X[#1+1]
G90
G81 X[#1] Y1. Z-1. R1.
G1 X[#1+5]
#1=#1+1
END1
M30
%
; FEATURES: ISO-MAC-08
; A loop's line of a motion mode and a computed move: the waiting blocks and the mode go to the
; executor with the move in one call (ncrt_exec_move), which skips a G0/G1 already in force.
; Modes that change every line (G0/G1 alternating), an arc mode, two modes at once (G91 G1) and a
; canned cycle take the full path; both engines give the same trace.
; RUN: %ncc run %s --engine=eval --trace=canon -q > %t.e
; RUN: %ncc run %s --engine=jit --trace=canon -q > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: STRAIGHT_FEED(0.0000, 0.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(2.0000, 1.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(4.0000, 2.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(0.0000, 2.0000, 5.0000,
; CHECK-NEXT: STRAIGHT_FEED(0.0000, 2.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(1.0000, 2.0000, 5.0000,
; CHECK-NEXT: STRAIGHT_FEED(1.0000, 2.0000, -1.0000,
; CHECK: STRAIGHT_FEED(3.0000, 2.0000, -3.0000,
; CHECK-NEXT: ARC_FEED(10.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(11.0000, 0.0000, -3.0000,
; CHECK: STRAIGHT_FEED(5.0000, 1.0000, 1.0000,
; CHECK-NEXT: ARC_FEED(11.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(13.0000, 0.0000, 1.0000,
; RUN: %ncc run %s --engine=eval | grep '^blocks:' > %t.be
; RUN: %ncc run %s --engine=jit | grep '^blocks:' > %t.bj
; RUN: diff %t.be %t.bj
; One call per mode line and its move: G1, G0, G1 Z, G2, G91 G1 (G81 follows the constant G90
; line: a table); the moves without a mode on their line go with the waiting blocks alone.
; (ncrt_exec_mode remains in the operands' error branches: the mode before the error.)
; RUN: %ncc compile --emit=llvm %s | FileCheck %s --check-prefix=IR
; IR-COUNT-5: call i32 @ncrt_exec_move(ptr %0, ptr %{{[0-9]+}}, i64 %{{[0-9]+}}, ptr @nc.mode
; IR-NOT: call i32 @ncrt_exec_move({{.*}}@nc.mode
; An error in the move's operands after the mode: the same trace and message as the eval engine.
; RUN: not %ncc run %S/Inputs/mode-line-error.nc --engine=eval --trace=canon -q > %t.ee 2> %t.eerr
; RUN: not %ncc run %S/Inputs/mode-line-error.nc --engine=jit --trace=canon -q > %t.je 2> %t.jerr
; RUN: diff %t.ee %t.je
; RUN: diff %t.eerr %t.jerr
; RUN: FileCheck %s --check-prefix=ERR < %t.jerr
; ERR: mode-line-error.nc:4:12: error: 'SQRT' argument out of domain
