O1
#1=100
M98 P#1
M98 P[#1+100] L2
M30
O100
G0 X1
M99
O200
G91 G0 Y1
G90
M99
%
; FEATURES: ISO-M-03
; M98 P with a computed program number (P#1, P[expr]): the program O<n> is found when the
; call runs; L repeats. Both engines.
; RUN: %ncc run %s --trace=canon -q | FileCheck %s
; RUN: %ncc run %s --trace=canon -q --engine=jit | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(1.0000, 1.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(1.0000, 2.0000, 0.0000,
; RUN: printf '#2=7\nM98 P#2\nM30\n' > %t.nc
; RUN: not %ncc run %t.nc 2>&1 | FileCheck %s --check-prefix=ERR
; ERR: error: call to unknown program 'O7'
