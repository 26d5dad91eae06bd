G18 G0 X40. Z10.
G28 U0 W0
G0 X40. Z10.
G28 U10.
M30
%
; FEATURES: ISO-MOT-12 ISO-REF-01
; A lathe's G28 U W: the intermediate point is incremental (U0 W0: where the tool stands), then the
; named axes go to the reference point (here machine 0). U is a diameter.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=motion | FileCheck %s
; CHECK:      rapid X20 Y0 Z10 A0 B0 C0 @1:5
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0 @2:1
; CHECK-NEXT: rapid X0 Y0 Z0 A0 B0 C0 @2:1
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0 @3:1
; CHECK-NEXT: rapid X25 Y0 Z10 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X0 Y0 Z10 A0 B0 C0 @4:1
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=ir | FileCheck %s --check-prefix=IR
; IR: home ref=1 X=0 Z=0 ic=XZ
; IR: home ref=1 X=10.0 ic=X
