N5 G00 X100. /3 YY100
%
; FEATURES: ISO-LEX-05
; Spec L372: `N5 G00 X100. /3 YY100` is a syntax error unless level 3 is active.
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; RUN: %ncc compile %s --emit=ir --block-delete 3 | FileCheck %s --check-prefix=SKIP
; CHECK: iso-lex-05-skip-syntax.nc:1:17: error: unknown word 'YY' [unknown-code]
; CHECK-NEXT: N5 G00 X100. /3 YY100
; CHECK-NEXT: {{^                \^$}}
; SKIP: block n=5
; SKIP-NEXT: mode motion=rapid
; SKIP-NEXT: move X=100.0 loc
