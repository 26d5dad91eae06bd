G21 G90 G1 F100
#1=-2.5
WHILE [#1 LE 2.5] DO1
X[FIX[#1]] Y[FUP[#1]] Z[ROUND[#1]]
X[ABS[#1]] Y[ROUND[-0.5]] Z[FIX[#9]]
#1=#1+0.5
END1
M30
%
; FEATURES: ISO-MAC-08
; ABS, ROUND, FIX (TRUNC in Macro B) and the other one-operation builtins are inlined by the
; JIT (no call in the loop) with the C functions' results: halves, negative values, a vacant
; argument (0).
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: linear X-2 Y-3 Z-3
; CHECK-NEXT: linear X2.5 Y-1 Z0
; CHECK-NEXT: linear X-2 Y-2 Z-2
; CHECK: linear X0 Y0 Z0
; CHECK-NEXT: linear X0 Y-1 Z0
; CHECK: linear X2 Y3 Z3
; CHECK-NEXT: linear X2.5 Y-1 Z0
; CHECK-NEXT: program_end
; RUN: %ncc compile --emit=llvm %s | FileCheck %s --check-prefix=IR --implicit-check-not="call double @ncc_builtin_trunc" --implicit-check-not="call double @ncc_builtin_round" --implicit-check-not="call double @ncc_builtin_abs"
; IR: call double @llvm.trunc.f64
; IR: call double @llvm.round.f64
