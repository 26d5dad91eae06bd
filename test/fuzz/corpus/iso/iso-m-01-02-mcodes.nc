M00
M1
M8
M7
M9
M7 M8
M29 M3 M8 M50
M2
M30
%
; FEATURES: ISO-M-01 ISO-M-02
; Stops, coolant, and machine-defined M codes as `aux` after the motion.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: stop kind=program loc(1:1:1)
; CHECK: stop kind=optional loc(1:2:1)
; CHECK: coolant flood=on loc(1:3:1)
; CHECK: coolant mist=on loc(1:4:1)
; CHECK: coolant mist=off flood=off loc(1:5:1)
; CHECK: coolant mist=on flood=on loc(1:6:1)
; CHECK: block loc(1:7:1)
; CHECK-NEXT: spindle dir=cw
; CHECK-NEXT: coolant flood=on
; CHECK-NEXT: aux m=29
; CHECK-NEXT: aux m=50
; CHECK: stop kind=end loc(1:8:1)
; CHECK: stop kind=end_rewind loc(1:9:1)
