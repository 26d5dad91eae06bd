; FEATURES: HEI-MOT-09
; FK free contour programming: tangential arcs and lines (FCT, FLT), a line whose end the next
; circle fixes (FL AN+90, then FC with its centre: they touch at X20 Y40), a circle through three
; points (start, P1, end), each lowered as an L or C move.
; RUN: %ncc run %s --trace=canon 2>&1 | FileCheck %s
; From X10 Y0 (heading +X) FCT R10 turns left about X10 Y10 to X20 Y10.
; CHECK: STRAIGHT_FEED(10.0000, 0.0000, {{.*}}
; CHECK-NEXT: ARC_FEED(20.0000, 10.0000, 10.0000, 10.0000, 1, {{.*}}
; FLT LEN5 goes on up (tangent), FLT X20 Y30 further.
; CHECK-NEXT: STRAIGHT_FEED(20.0000, 15.0000, {{.*}}
; CHECK-NEXT: STRAIGHT_FEED(20.0000, 30.0000, {{.*}}
; FL AN+90 ends where it touches the circle of block 8 (X20 Y40); the arc runs clockwise to X30.
; CHECK-NEXT: STRAIGHT_FEED(20.0000, 40.0000, {{.*}}
; CHECK-NEXT: ARC_FEED(30.0000, 40.0000, 25.0000, 40.0000, -1, {{.*}}
; CHECK-NEXT: STRAIGHT_FEED(30.0000, 0.0000, {{.*}}
; The circle through X30 Y0, P1 = X20 Y-10 and X10 Y0: centre X20 Y0, clockwise.
; CHECK-NEXT: ARC_FEED(10.0000, 0.0000, 20.0000, 0.0000, -1, {{.*}}
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 0.0000,
0 BEGIN PGM FK MM
1 TOOL CALL 1 Z S1000
2 L X+0 Y+0 Z-5 R0 F100
3 L X+10
4 FCT DR+ R10 X+20 Y+10
5 FLT LEN5
6 FLT X+20 Y+30
7 FL AN+90
8 FC DR- R5 CCX+25 CCY+40 X+30
9 FL X+30 Y+0
10 FC DR- P1X+20 P1Y-10 X+10 Y+0
11 L Z+5 FMAX
12 END PGM FK MM
