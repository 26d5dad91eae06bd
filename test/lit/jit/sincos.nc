G21 G90 G1 F100
#1=0
WHILE [#1 LT 2000] DO1
#2=#1*0.36+#1*#1*0.001
X[10*COS[#2]] Y[10*SIN[#2]] Z[SIN[#9]+COS[#1*90]]
#1=#1+1
END1
M30
%
; FEATURES: ISO-MAC-08
; SIN and COS of one angle: the JIT computes both with one sincos call (llvm.sin/llvm.cos of the
; degree product, the pair moved into one block after O2), with the bits of the eval engine's
; sin and cos: every move of the loop compared (angles up to 4,700 degrees, multiples of 90, a
; vacant argument).
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j
; RUN: diff %t.e %t.j
; RUN: FileCheck %s < %t.j
; CHECK: linear X10 Y0 Z1 A0
; CHECK-NEXT: linear X9.999801510422818 Y0.0630059691260798 Z6.123233995736766e-17 A0
; RUN: %ncc compile --emit=llvm %s | FileCheck %s --check-prefix=IR --implicit-check-not="call double @ncc_builtin_sin" --implicit-check-not="call double @ncc_builtin_cos"
; IR: call double @llvm.cos.f64
; IR: call double @llvm.sin.f64
; RUN: %ncc compile --emit=obj %s -o %t.o
; RUN: llvm-nm %t.o | FileCheck %s --check-prefix=OBJ
; OBJ: U sincos
