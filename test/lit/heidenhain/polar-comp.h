; FEATURES: HEI-MOT-02 HEI-MOT-07
; Polar moves under radius compensation: IPA is counted from the last programmed point (the
; core's $_x/$_y are the programmed position, also with RL), so the compensated path (tool 3,
; radius 3) runs inside the programmed one: (20, 0) -> (0, 20) -> (-20, 0) -> arc R20 to (0, -20).
; RUN: %ncc run %s --trace=canon --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml | FileCheck %s
; RUN: %ncc compile --emit=motion --engine=eval %s --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.e
; RUN: %ncc compile --emit=motion --engine=jit %s --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml > %t.j
; RUN: diff %t.e %t.j
; On the Y axis the two offset lines meet at 20 - 3 * sqrt(2); the second meets the arc of radius 17.
; CHECK: N5 {{ *}}STRAIGHT_FEED(0.0000, 15.7574, -155.0000,
; CHECK-NEXT: N6 {{ *}}STRAIGHT_FEED(-16.9576, -1.2002, -155.0000,
; CHECK-NEXT: N7 {{ *}}ARC_FEED({{-?}}0.0000, -17.0000, 0.0000, 0.0000, 1, -155.0000,
; CHECK-NEXT: N8 {{ *}}STRAIGHT_FEED(30.0000, -30.0000, -155.0000,
0 BEGIN PGM COMP MM
1 TOOL CALL 3 Z S1000
2 L X-20 Y-20 Z+0 R0 FMAX M3
3 CC X+0 Y+0
4 L X+20 Y+0 RL F100
5 LP PR+20 PA+90
6 LP IPA+90
7 CP IPA+90 DR+
8 L X+30 Y-30 R0
9 END PGM COMP MM
