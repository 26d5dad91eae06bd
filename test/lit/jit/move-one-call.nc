O1000 (MOVES IN ONE CALL, AND MOVES THAT READ THE MACHINE)
G21 G90 G17 G94 F1000.
#1=0
WHILE [#1 LT 3] DO1
G1 X[#1+1] Y0
G1 Y[#5022+1]
G1 X[#[#1+100]]
#1=#1+1
END1
M30
%
; FEATURES: ISO-MAC-08
; A computed move whose operands call nothing in the runtime (variables, arithmetic, numeric
; builtins) goes with its line's mode and the waiting blocks in one call (ncrt_exec_move); a
; system variable (#5022) or a computed parameter number (#[…]) reaches the executor first, so
; those moves keep the mode line's call (ncrt_exec_mode) and their own (ncrt_exec). Both engines
; give the same trace.
; RUN: %ncc run %s --engine=eval --trace=canon -q > %t.e
; RUN: %ncc run %s --engine=jit --trace=canon -q > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; (#[#1+100] is vacant: that line's X word is left out, so it does not move.)
; CHECK: STRAIGHT_FEED(1.0000, 0.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(1.0000, 1.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(2.0000, 0.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(2.0000, 1.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(3.0000, 0.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_FEED(3.0000, 1.0000, 0.0000,
; CHECK-NEXT: SET_G5X_OFFSET(
; RUN: %ncc compile --emit=llvm %s | FileCheck %s --check-prefix=IR
; IR: call i32 @ncrt_exec_move(ptr %0, ptr %{{[0-9]+}}, i64 %{{[0-9]+}}, ptr @nc.mode, ptr %cmd.site)
; IR: call double @ncrt_sysvar(
; IR-NOT: @ncrt_exec_move(
; IR: call double @ncrt_param(
; IR: call i32 @ncrt_exec(ptr %0, ptr %cmd.site{{[0-9]+}})
; IR-NOT: @ncrt_exec_move(
; IR: define i32 @ncc_program_main(
; An operand fails after the line's mode changed the plane: the mode still comes first
; (SELECT_PLANE in the trace before the error), as in the eval engine.
; RUN: not %ncc run %S/Inputs/move-error-plane.nc --engine=eval --trace=canon -q > %t.ee 2> %t.eerr
; RUN: not %ncc run %S/Inputs/move-error-plane.nc --engine=jit --trace=canon -q > %t.je 2> %t.jerr
; RUN: diff %t.ee %t.je
; RUN: diff %t.eerr %t.jerr
; RUN: FileCheck %s --check-prefix=ERR < %t.je
; ERR: STRAIGHT_TRAVERSE(1.0000, 1.0000, 0.0000,
; ERR-NEXT: SELECT_PLANE(CANON_PLANE_XZ)
; ERR-NEXT: ON_RESET()
