N10 G1 X5 (open (nested) comment
%
; FEATURES: ISO-LEX-03
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-lex-03-unterminated-comment.nc:1:11: error: unterminated comment: missing ')' [syntax]
; CHECK-NEXT: N10 G1 X5 (open (nested) comment
; CHECK-NEXT: {{^          \^$}}
