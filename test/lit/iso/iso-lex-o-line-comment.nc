%
O0100 ;bracket, first op
G0 X1
M30
%
; FEATURES: ISO-LEX-01
; A comment on the program-number line is a comment record whether the program is streamed
; block by block (ncc run) or compiled whole (found by the iso fuzzer: the streamed run
; dropped it).
; RUN: %ncc run %s --trace=canon -o - -q | FileCheck %s
; RUN: %ncc compile %s --emit=motion | FileCheck %s --check-prefix=WHOLE
; CHECK: COMMENT("bracket, first op")
; CHECK: STRAIGHT_TRAVERSE(1.0000
; WHOLE: comment "bracket, first op" @2:7
; WHOLE-NEXT: rapid X1
