G10 L2 P1 X10. Y5.
G17 G90 G54 G0 X0 Y0 Z0
G16 X100. Y45.
Y90.
G1 X50. Z-1. F100
X20. Y-30
G15
X10. Y20.
M30
; FEATURES: ISO-MOT-11
; G16 (808D L9346-9395): in G17 X is the polar radius and Y the angle (degrees) about the
; workpiece zero (here G54 = X10 Y5); a missing word keeps the current radius or angle; Z moves
; as usual; G15 returns to Cartesian X Y. Both engines give the same positions.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: block loc(1:3:1)
; IR-NEXT: move polar_r=100.0 polar_a=45.0
; IR: block loc(1:4:1)
; IR-NEXT: move polar_a=90.0
; IR: move Z=-1.0 polar_r=50.0
; IR: move polar_r=20.0 polar_a=-30
; IR: move X=10.0 Y=20.0
; RUN: %ncc run %s --trace=canon | FileCheck %s
; RUN: %ncc run %s --trace=canon --engine=jit | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(10.0000, 5.0000, 0.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(80.7107, 75.7107, 0.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 105.0000, 0.0000,
; CHECK: STRAIGHT_FEED(10.0000, 55.0000, -1.0000,
; CHECK-NEXT: STRAIGHT_FEED(27.3205, -5.0000, -1.0000,
; CHECK-NEXT: STRAIGHT_FEED(20.0000, 25.0000, -1.0000,
