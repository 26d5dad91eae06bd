G90 G0 X0 Y0 Z10
G81 X1 Z-1 R1 F100
G80
X5
G1 X6 F100
G81 X7 Z-1 R1
G80 Y2
M30
%
; FEATURES: ISO-CYM-15
; Fanuc/808D: canned cycles are group 09 beside group 01, so after G80 the G0-G3 mode that was
; active before the cycle moves the axes (the 808D example 57 ends with `G49 Z0` after G80).
; LinuxCNC's G80 leaves no motion mode: the same program in .ngc is rs274's error.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: mode motion=cycle_cancel loc(1:3:1)
; RUN: %ncc run %s --trace=canon -o - -q | FileCheck %s
; RUN: %ncc run %s --engine=jit --trace=canon -o - -q | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(1.0000, 0.0000, 10.0000
; CHECK: STRAIGHT_TRAVERSE(5.0000, 0.0000, 10.0000
; CHECK: STRAIGHT_FEED(6.0000, 0.0000, 10.0000
; CHECK: STRAIGHT_TRAVERSE(7.0000, 0.0000, 1.0000
; CHECK: STRAIGHT_FEED(7.0000, 2.0000, 10.0000
; RUN: head -4 %s > %t.ngc
; RUN: not %ncc run %t.ngc 2>&1 | FileCheck %s --check-prefix=NGC
; NGC: ngc:4:1: error: Cannot use axis values with G80 [motion-mode-none]
