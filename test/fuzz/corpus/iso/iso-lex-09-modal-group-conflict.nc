G90 G91 X10
G1 X1 G0 Y2
G81 G1 Z-1
G17 G18
M3 M4
M3 M8 M9
G1 X1 X2
G0 G43 G44 Z1 H1
%
; FEATURES: ISO-M-05 ISO-CYM-15
; (ISO-LEX-09 "last wins" is deliberately not followed: see below)
; Two codes of one modal group in a block. The 808D manual says the last one wins (L6492);
; ncc follows LinuxCNC and reports an error, so the ambiguity is visible (documented choice).
; A group-01 code and a cycle code may not share a block (ISO-CYM-15).
; RUN: not %ncc compile %s --emit=ir 2>&1 | FileCheck %s
; CHECK: iso-lex-09-modal-group-conflict.nc:1:5: error: two G codes from the same modal group: G90 and G91 [modal-group-conflict]
; CHECK-NEXT: G90 G91 X10
; CHECK-NEXT: {{^    \^$}}
; CHECK: iso-lex-09-modal-group-conflict.nc:2:7: error: two G codes from the same modal group: G1 and G0 [modal-group-conflict]
; CHECK: iso-lex-09-modal-group-conflict.nc:3:5: error: G1 cannot be programmed in a canned cycle block with G81 [modal-group-conflict]
; CHECK: iso-lex-09-modal-group-conflict.nc:4:5: error: two G codes from the same modal group: G17 and G18 [modal-group-conflict]
; CHECK: iso-lex-09-modal-group-conflict.nc:5:4: error: two M codes from the same modal group: M3 and M4 [modal-group-conflict]
; CHECK: iso-lex-09-modal-group-conflict.nc:6:7: error: two M codes from the same modal group: M8 and M9 [modal-group-conflict]
; CHECK: iso-lex-09-modal-group-conflict.nc:7:7: error: two X words in one block [duplicate-word]
; CHECK: iso-lex-09-modal-group-conflict.nc:8:8: error: G44 (negative tool length compensation) is not supported [unsupported-code]
