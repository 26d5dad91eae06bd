:1
M98 P100
M30
:0100
G0 X5
M99
%
; FEATURES: ISO-LEX-08
; Fanuc `:` is the program-number address like O (`:0100` = O0100), issue 7 part 3; a program
; with a second `:` program is not streamed as flat.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: func @main
; IR: func @O100
; RUN: %ncc run %s --trace=canon -q | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000,
; RUN: printf ':1\nG0 X1\nM30\n:2\nG0 X2\nM99\n' > %t.nc
; RUN: %ncc run %t.nc --trace=canon -q | FileCheck %s --check-prefix=TWO
; TWO: STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000,
; TWO-NOT: STRAIGHT_TRAVERSE
