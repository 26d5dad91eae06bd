WHILE [#1 LT 3] DO1
WHILE [#2 LT 3] DO2
END1
END2
END3
DO4
IF [#1] GOTO
IF #1 GOTO 5
IF [#1 LT 2] X5
WHILE [#1] DO
#0 = 5
#1 = FOO[2]
#1 = [1 + 2
#1 = 1 +
GOTO 5 X1
%
; FEATURES: ISO-MAC-08
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-mac-08-errors.nc:3:1: error: END1 does not match DO2 [loop-mismatch]
; CHECK: iso-mac-08-errors.nc:5:1: error: END3 does not match DO1 [loop-mismatch]
; CHECK: iso-mac-08-errors.nc:7:13: error: GOTO needs a block number [syntax]
; CHECK: iso-mac-08-errors.nc:8:4: error: IF needs a condition in brackets: IF [...] [syntax]
; CHECK: iso-mac-08-errors.nc:9:14: error: expected GOTO or THEN after IF [...] [syntax]
; CHECK: iso-mac-08-errors.nc:10:14: error: DO needs a loop number (DO1) [syntax]
; CHECK: iso-mac-08-errors.nc:11:1: error: #0 is always vacant and cannot be assigned [syntax]
; CHECK: iso-mac-08-errors.nc:12:6: error: unknown function 'FOO' [unknown-code]
; CHECK-NEXT: #1 = FOO[2]
; CHECK-NEXT: {{^     \^$}}
; CHECK: iso-mac-08-errors.nc:13:6: error: missing ']' [syntax]
; CHECK: iso-mac-08-errors.nc:14:9: error: expected a value [syntax]
; CHECK: iso-mac-08-errors.nc:15:8: error: unexpected text after the macro statement [syntax]
; CHECK: iso-mac-08-errors.nc:6:1: error: DO4 without END4 [loop-mismatch]
; CHECK: iso-mac-08-errors.nc:1:1: error: DO1 without END1 [loop-mismatch]
