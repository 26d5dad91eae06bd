G0 X0 Y0 Z0
G18 G90 G0 X5 Y20 Z5
G99 G81 X10 Z5 Y-10 R12 F100
Z15
G80
G19 G91 G98 G81 Y5 Z3 X-10 R-5 F100
G80
G17 G90 G81 X1 Y1 Z-3 R2
G80
M30
; FEATURES: ISO-CYM-17
; The drilling axis follows the plane (808D table 2-23): G17 Z, G18 Y, G19 X; the block's other
; plane words place the hole. G90: R and the depth word are coordinates; G91 (figure 2-32): R
; is the distance from the initial level to the R level, the depth word the distance from R to
; the bottom. G18 G99: from Y20 rapid to R Y12, feed to Y-10, back to R; the next hole at Z15.
; G19 G91 from X10: the hole at Y17 Z18 (incremental), R level X5, bottom X-5, G98 back to X10.
; (The 808D's GUD _ZSFI[0] = 1, Z the drilling axis in every plane, is not modelled: ncc takes 0.)
; RUN: %ncc run %s --trace=canon -o - -q | FileCheck %s
; RUN: %ncc run %s --engine=jit --trace=canon -o - -q | FileCheck %s
; CHECK:      SELECT_PLANE(CANON_PLANE_XZ)
; CHECK-NEXT: STRAIGHT_TRAVERSE(5.0000, 20.0000, 5.0000,
; CHECK:      STRAIGHT_TRAVERSE(10.0000, 20.0000, 5.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 12.0000, 5.0000,
; CHECK-NEXT: STRAIGHT_FEED(10.0000, -10.0000, 5.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 12.0000, 5.0000,
; CHECK:      STRAIGHT_TRAVERSE(10.0000, 12.0000, 15.0000,
; CHECK-NEXT: STRAIGHT_FEED(10.0000, -10.0000, 15.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 12.0000, 15.0000,
; CHECK:      SELECT_PLANE(CANON_PLANE_YZ)
; CHECK:      STRAIGHT_TRAVERSE(10.0000, 17.0000, 18.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(5.0000, 17.0000, 18.0000,
; CHECK-NEXT: STRAIGHT_FEED(-5.0000, 17.0000, 18.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 17.0000, 18.0000,
; CHECK:      SELECT_PLANE(CANON_PLANE_XY)
; CHECK:      STRAIGHT_TRAVERSE(1.0000, 1.0000, 18.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(1.0000, 1.0000, 2.0000,
; CHECK-NEXT: STRAIGHT_FEED(1.0000, 1.0000, -3.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(1.0000, 1.0000, 18.0000,
; In G18 the depth is Y: a first cycle block without it is an error (rs274's message).
; RUN: printf 'G18 G0 X0 Y0 Z0\nG81 X1 Z1 R2 F100\nM30\n' > %t.nc
; RUN: not %ncc run %t.nc -q 2>&1 | FileCheck %s --check-prefix=NOY
; NOY: 2:1: error: Y value unspecified in xz plane canned cycle [cycle-missing-word]
