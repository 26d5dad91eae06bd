; FEATURES: HEI-MOT-01 HEI-MOT-02 HEI-MOT-03 HEI-MOT-04 HEI-MOT-05 HEI-MOT-06 HEI-MOT-07 HEI-MOT-08 HEI-MOT-11 HEI-MFN-01
; FEATURES: HEI-MOV-01 HEI-MOV-02 HEI-MOV-03 HEI-MOV-04 HEI-MOV-05 HEI-TOL-01 HEI-TOOL-01 HEI-TOOL-02
; Path blocks: L absolute and incremental, FMAX block-wise, F modal, RL/R0 radius compensation
; with the tool's radius from the machine (tool 3: radius 3), the pole CC, C about it, CR by its
; radius, CT tangential, RND and CHF corners (the core's contour step), LP/CP polar moves with
; IPA, M3/M5/M8/M9/M2.
; RUN: %ncc run %s --trace=canon --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.canon
; RUN: FileCheck %s < %t.canon
; RUN: %ncc compile --emit=motion --engine=eval %s --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.j
; RUN: diff %t.e %t.j
; CHECK: CHANGE_TOOL(3)
; CHECK: SET_SPINDLE_SPEED(0, 2000.0000)
; CHECK: N2 {{ *}}START_SPINDLE_CLOCKWISE(0)
; CHECK-NEXT: N2 {{ *}}FLOOD_ON()
; CHECK-NEXT: N2 {{ *}}STRAIGHT_TRAVERSE(-20.0000, -20.0000, -155.0000,
; CHECK-NEXT: N3 {{ *}}SET_FEED_RATE(150.0000)
; CHECK-NEXT: N3 {{ *}}STRAIGHT_FEED(-20.0000, -20.0000, -160.0000,
; Compensated on the left (radius 3) around the square 0..40 with a rounding R5 and a chamfer 4
; (the TNC's start: the first RL block ends normal to the next element at its first point, here
; (0, 0) + 3 to the left of +Y; convex corners get arcs):
; CHECK-NEXT: N4 {{ *}}STRAIGHT_FEED(-3.0000, 0.0000, -160.0000,
; CHECK-NEXT: N5 {{ *}}STRAIGHT_FEED(-3.0000, 35.0000, -160.0000,
; CHECK-NEXT: N5 {{ *}}ARC_FEED(5.0000, 43.0000, 5.0000, 35.0000, -1, -160.0000,
; CHECK-NEXT: N7 {{ *}}STRAIGHT_FEED(37.1716, 43.0000, -160.0000,
; CHECK-NEXT: N7 {{ *}}ARC_FEED(39.2929, 42.1213, 37.1716, 40.0000, -1, -160.0000,
; CHECK-NEXT: N7 {{ *}}STRAIGHT_FEED(42.1213, 39.2929, -160.0000,
; CHECK-NEXT: N9 {{ *}}ARC_FEED(43.0000, 37.1716, 40.0000, 37.1716, -1, -160.0000,
; CHECK-NEXT: N9 {{ *}}STRAIGHT_FEED(43.0000, 0.0000, -160.0000,
; CHECK-NEXT: N10 {{ *}}ARC_FEED(40.0000, -3.0000, 40.0000, 0.0000, -1, -160.0000,
; CHECK-NEXT: N10 {{ *}}STRAIGHT_FEED(0.0000, -3.0000, -160.0000,
; CHECK-NEXT: N11 {{ *}}STRAIGHT_FEED(-10.0000, -10.0000, -160.0000,
; The pole at (60, 20): C to (80, 20) clockwise about it, CR back with R20 counter-clockwise,
; CT on from there: it leaves (40, 20) downwards, so clockwise about (20, 20) the long way.
; CHECK-NEXT: N13 {{ *}}STRAIGHT_FEED(40.0000, 20.0000, -160.0000,
; CHECK-NEXT: N14 {{ *}}ARC_FEED(80.0000, 20.0000, 60.0000, 20.0000, -1, -160.0000,
; CHECK-NEXT: N15 {{ *}}ARC_FEED(40.0000, 20.0000, 60.0000, 20.0000, 1, -160.0000,
; CHECK-NEXT: N16 {{ *}}ARC_FEED(20.0000, 40.0000, 20.0000, 20.0000, -1, -160.0000,
; Polar: LP PR+10 PA+90 about (60, 20) is (60, 30); LP IPA+90 turns on to (50, 20); CP IPA+450
; is a full turn and a quarter, counter-clockwise, ending at (60, 10); with a second turn.
; CHECK-NEXT: N17 {{ *}}STRAIGHT_FEED(60.0000, 30.0000, -160.0000,
; CHECK-NEXT: N18 {{ *}}STRAIGHT_FEED(50.0000, 20.0000, -160.0000,
; CHECK-NEXT: N19 {{ *}}ARC_FEED(60.0000, 10.0000, 60.0000, 20.0000, 2, -160.0000,
; An incremental pole: CC IX+10 from (60, 10) is (70, 10) with Y from the position.
; CHECK-NEXT: N21 {{ *}}ARC_FEED(80.0000, 10.0000, 70.0000, 10.0000, 1, -160.0000,
; CHECK-NEXT: N22 {{ *}}STRAIGHT_TRAVERSE(80.0000, 10.0000, -145.0000,
; CHECK-NEXT: N22 {{ *}}STOP_SPINDLE_TURNING(0)
; CHECK-NEXT: N22 {{ *}}MIST_OFF()
; CHECK-NEXT: N22 {{ *}}FLOOD_OFF()
; CHECK: N23 {{ *}}PROGRAM_END()
0 BEGIN PGM PATHS MM
1 TOOL CALL 3 Z S2000
2 L X-20 Y-20 Z+0 R0 FMAX M3 M8
3 L Z-5 F150
4 L X+0 Y+0 RL
5 L Y+40
6 RND R5
7 L X+40
8 CHF 4
9 L IY-40
10 L X+0
11 L X-10 Y-10 R0
12 CC X+60 Y+20
13 L X+40 Y+20
14 C X+80 DR-
15 CR X+40 Y+20 R+20 DR+
16 CT X+20 Y+40
17 LP PR+10 PA+90
18 LP IPA+90
19 CP IPA+450 DR+
20 CC IX+10
21 C X+80 Y+10 DR+
22 L Z+10 R0 FMAX M5 M9
23 M2
24 END PGM PATHS MM
