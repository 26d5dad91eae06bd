; RUN: %ncc compile --emit=ir %s | FileCheck %s
; RUN: not %ncc compile --emit=ir %S/Inputs/cycle-with-g1.nc 2>&1 | FileCheck %s --check-prefix=ERR
; FEATURES: ISO-CYM-15
; In the 808D/Fanuc tables the canned cycles are group 09: `G80 G0` cancels the cycle and rapids
; (the group-01 code ends the cycle anyway), but a cycle and a group-01 code may not share a block.
G99 G81 X10. Y10. Z-5. R2. F100
G80 G0 Z20.
G0 X0 G80
M30
; CHECK: mode motion=drill
; CHECK: block
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: move Z=20.0
; CHECK: block
; CHECK-NEXT: mode motion=rapid
; CHECK-NEXT: move X=0 
; ERR: cycle-with-g1.nc:1:5: error: G81 cannot be programmed in a canned cycle block with G1 [modal-group-conflict]
