#1=[12 OR 3]
#2=FIX[-1.2]
#3=FUP[-1.2]
#4=[12 AND 10]
#5=[12 XOR 10]
G0 X#1 Y#2 Z#3
G0 X#4 Y#5
IF [[1 EQ 1] AND [2 EQ 2]] THEN #6=7
G0 X#6
#7=[1.5 OR 1]
M30
%
; FEATURES: ISO-MAC-08
; Fanuc Macro B as Fanuc defines it (issue 7 part 3): AND/OR/XOR are bitwise on integers in
; values ([12 OR 3] = 15, [12 AND 10] = 8, [12 XOR 10] = 6) and logical where they join
; conditions; FIX truncates toward zero (FIX[-1.2] = -1), FUP rounds away from zero
; (FUP[-1.2] = -2). The IR says so (band/bor/bxor, TRUNC, AWAYFROMZERO); a bitwise operator on
; a non-integer is an error. RS274NGC (.ngc) keeps LinuxCNC's meaning (iso-rs274-owords.ngc).
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: assign target=#1 value=(bor 12 3)
; IR: assign target=#2 value=(TRUNC -1.2)
; IR: assign target=#3 value=(AWAYFROMZERO -1.2)
; IR: if cond=(and (eq 1 1) (eq 2 2))
; RUN: not %ncc run %s --trace=canon -q > %t 2> %t.err
; RUN: FileCheck %s --input-file=%t
; RUN: FileCheck %s --input-file=%t.err --check-prefix=ERR
; RUN: not %ncc run %s --trace=canon -q --engine=jit > %t.jit 2> %t.jerr
; RUN: FileCheck %s --input-file=%t.jit
; RUN: FileCheck %s --input-file=%t.jerr --check-prefix=ERR
; CHECK: STRAIGHT_TRAVERSE(15.0000, -1.0000, -2.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(8.0000, 6.0000, -2.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(7.0000, 6.0000, -2.0000,
; ERR: iso-mac-08-fanuc-semantics.nc:10:{{[0-9]+}}: error: bitwise 'bor' needs integer operands
