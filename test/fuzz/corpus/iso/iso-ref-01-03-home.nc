G91 G28 Z0
G90 G28 X10 Y20
G30 P3 X30. Y50.
G30 Z5
%
; FEATURES: ISO-REF-01 ISO-REF-03
; G28 / G30: the axis words are the intermediate point; G30 P selects the reference point.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: mode distance=incremental loc(1:1:1)
; CHECK-NEXT: home ref=1 Z=0 loc(1:1:5)
; CHECK-NOT: move
; CHECK: home ref=1 X=10 Y=20 loc(1:2:5)
; CHECK: home ref=3 X=30.0 Y=50.0 loc(1:3:1)
; CHECK: home ref=2 Z=5 loc(1:4:1)
