G1 X1
M98 P4321
%
; FEATURES: ISO-M-03
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-m-03-missing-subprogram.nc:2:1: error: subprogram O4321 not found (searched {{.*}}) [missing-subprogram]
; CHECK-NEXT: M98 P4321
; CHECK-NEXT: {{^\^$}}
