G21 G90 G1 F100
#100=0
WHILE [#100 GE 0] DO1
#100=#100+1
END1
X#100
M30
%
; FEATURES: ISO-MAC-08
; A loop whose variables live in slots still stops at the iteration limit, with the eval
; engine's diagnostic at the same place; with a higher limit the value after the loop is the
; count the limit allowed (the slot is stored back).
; RUN: not %ncc run %s --engine=eval --max-loop-iterations=100 -q 2>&1 | FileCheck %s
; RUN: not %ncc run %s --engine=jit --max-loop-iterations=100 -q 2>&1 | FileCheck %s
; CHECK: loop-slots-runaway.nc:3:1: error: loop did not terminate after 100 iterations (limit --max-loop-iterations)
; CHECK-NEXT: WHILE [#100 GE 0] DO1
; RUN: sed -e 's/GE 0/LT 99/' %s > %t.nc
; RUN: %ncc run %t.nc --engine=jit --max-loop-iterations=100 --trace=canon -q | FileCheck %s --check-prefix=OK
; RUN: %ncc run %t.nc --engine=eval --max-loop-iterations=100 --trace=canon -q | FileCheck %s --check-prefix=OK
; OK: STRAIGHT_FEED(99.0000, 0.0000, 0.0000,
; RUN: %ncc compile --emit=llvm %s | FileCheck %s --check-prefix=IR
; IR: %kept = alloca double
