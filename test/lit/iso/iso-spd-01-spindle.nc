S1000 M3
S500 M04
M5
G97 S800
%
; FEATURES: ISO-SPD-01
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: speed value=1000 loc(1:1:1)
; CHECK-NEXT: spindle dir=cw loc(1:1:7)
; CHECK: speed value=500
; CHECK-NEXT: spindle dir=ccw
; CHECK: spindle dir=stop loc(1:3:1)
; CHECK: speed mode=rpm value=800 loc(1:4:1)
