G12.5 X1
G1.55 X1
M3.5
G1 X1 $3
G1 E5
G96 S100
M99 P1.5
G10 L3 P1 R2
G43 Z1
M98 P-5
%
; FEATURES: ISO-LEX-01
; Unknown codes and characters are errors with a caret at the word; known but not yet
; lowered codes say so ([unsupported-code]); unused words are errors.
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-diag-unknown-codes.nc:1:1: error: unknown G code G12.5 [unknown-code]
; CHECK-NEXT: G12.5 X1
; CHECK-NEXT: {{^\^$}}
; CHECK: iso-diag-unknown-codes.nc:2:1: error: unknown G code G1.55 [unknown-code]
; CHECK: iso-diag-unknown-codes.nc:3:1: error: an M code must be an integer 0..99999999 [unknown-code]
; CHECK: iso-diag-unknown-codes.nc:4:7: error: unexpected character '$' [syntax]
; CHECK: iso-diag-unknown-codes.nc:5:4: error: E word is not used by any code of this block [unused-word]
; CHECK: iso-diag-unknown-codes.nc:6:1: error: G96 (constant surface speed) needs a lathe (machine kind = "lathe"): a milling spindle has no radius to keep the speed at [unsupported-code]
; CHECK: iso-diag-unknown-codes.nc:7:5: error: M99 P must be a block number (a whole number) [syntax]
; CHECK: iso-diag-unknown-codes.nc:8:5: error: G10 L3 is not supported (only L1, L2, L10-L13 and L20) [unsupported-code]
; CHECK: iso-diag-unknown-codes.nc:9:1: error: G43 needs an H word (tool length offset number) [missing-word]
; CHECK: iso-diag-unknown-codes.nc:10:5: error: M98 P must be a constant program number [syntax]
