; FEATURES: HEI-THR-04 HEI-THR-05
; Cycle 262 THREAD MILLING (L4656-L4816) and the direction rules of thread milling (L4565-L4610),
; default machine (tool 1 radius r = 5, Z machine = Z work + 100). An inside thread D16 (R = 8)
; 5 deep from Z0 at (50, 50), pitch 1.5: the tool centre runs on the circle R - r = 3.
; Pen and paper (docs/CYCLES.md "Heidenhain thread milling"):
; * the approach is a half circle from the centre to (53, 50) about (51.5, 50) (radius 1.5), the
;   departure the mirrored half circle back; along them the tool climbs with the helix's slope:
;   1.5 x pi x 1.5 / (2 x pi x 3) = 0.375 (a quarter pitch), so the compensating move puts the tool
;   0.375 before the start plane;
; * the helix feed is Q207 referred to the cutting edge: 400 x 3 / 8 = 150 at the centre; Q512 200
;   on the half circles;
; * 1 (N4): right-hand, climb (Q351 +1): counter-clockwise (rotation 1) and up (Z+): Q355 = 0, one
;   turn at the depth from Z-5 (machine 95) to Z-3.5, approach from Z-5.375, departure to Z-3.125;
; * 2 (N6): right-hand, up-cut: clockwise and down (Z-): Q355 = 1, one helix over the length from
;   Z0 to Z-5: 5 / 1.5 = 3 1/3 turns (rotation -4), ending 120 degrees clockwise from +x at
;   (50 + 3 cos -120, 50 + 3 sin -120) = (48.5, 47.4019); approach from Z+0.375, departure about the
;   midpoint (49.25, 48.7010) to the centre at Z-5.375;
; * 3 (N8): left-hand, up-cut: clockwise and up (Z+): Q355 = 2, turns shifted 2 x 1.5 = 3:
;   ceil(5 / 3) = 2 helices, Z-5 to Z-3.5 and Z-2 to Z-0.5, each with its own approach and
;   departure, between them at Q253 along the axis;
; * 4 (N10): left-hand, climb: counter-clockwise and down (Z-): one turn ending at the depth, from
;   Z-3.5 to Z-5, approach from Z-3.125.
; Each ends at the 2nd set-up clearance Z10 over the centre.
; RUN: %ncc run %s --trace=canon 2>/dev/null | grep -E 'STRAIGHT|ARC|FEED_RATE' | sed 's/^ *[0-9]* //' > %t.canon
; RUN: FileCheck %s < %t.canon
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e 2>/dev/null
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j 2>/dev/null
; RUN: diff %t.e %t.j
; CHECK: N4 {{ *}}STRAIGHT_TRAVERSE(50.0000, 50.0000, 102.0000,
; CHECK-NEXT: N4 {{ *}}SET_FEED_RATE(750.0000)
; CHECK-NEXT: N4 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 95.0000,
; CHECK-NEXT: N4 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 94.6250,
; CHECK-NEXT: N4 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N4 {{ *}}ARC_FEED(53.0000, 50.0000, 51.5000, 50.0000, 1, 95.0000,
; CHECK-NEXT: N4 {{ *}}SET_FEED_RATE(150.0000)
; CHECK-NEXT: N4 {{ *}}ARC_FEED(53.0000, 50.0000, 50.0000, 50.0000, 1, 96.5000,
; CHECK-NEXT: N4 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N4 {{ *}}ARC_FEED(50.0000, 50.0000, 51.5000, 50.0000, 1, 96.8750,
; CHECK-NEXT: N4 {{ *}}STRAIGHT_TRAVERSE(50.0000, 50.0000, 110.0000,
; CHECK: N6 {{ *}}STRAIGHT_TRAVERSE(50.0000, 50.0000, 102.0000,
; CHECK-NEXT: N6 {{ *}}SET_FEED_RATE(750.0000)
; CHECK-NEXT: N6 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 100.0000,
; CHECK-NEXT: N6 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 100.3750,
; CHECK-NEXT: N6 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N6 {{ *}}ARC_FEED(53.0000, 50.0000, 51.5000, 50.0000, -1, 100.0000,
; CHECK-NEXT: N6 {{ *}}SET_FEED_RATE(150.0000)
; CHECK-NEXT: N6 {{ *}}ARC_FEED(48.5000, 47.4019, 50.0000, 50.0000, -4, 95.0000,
; CHECK-NEXT: N6 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N6 {{ *}}ARC_FEED(50.0000, 50.0000, 49.2500, 48.7010, -1, 94.6250,
; CHECK-NEXT: N6 {{ *}}STRAIGHT_TRAVERSE(50.0000, 50.0000, 110.0000,
; CHECK: N8 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 95.0000,
; CHECK-NEXT: N8 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 94.6250,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N8 {{ *}}ARC_FEED(53.0000, 50.0000, 51.5000, 50.0000, -1, 95.0000,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(150.0000)
; CHECK-NEXT: N8 {{ *}}ARC_FEED(53.0000, 50.0000, 50.0000, 50.0000, -1, 96.5000,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N8 {{ *}}ARC_FEED(50.0000, 50.0000, 51.5000, 50.0000, -1, 96.8750,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(750.0000)
; CHECK-NEXT: N8 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 98.0000,
; CHECK-NEXT: N8 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 97.6250,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N8 {{ *}}ARC_FEED(53.0000, 50.0000, 51.5000, 50.0000, -1, 98.0000,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(150.0000)
; CHECK-NEXT: N8 {{ *}}ARC_FEED(53.0000, 50.0000, 50.0000, 50.0000, -1, 99.5000,
; CHECK-NEXT: N8 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N8 {{ *}}ARC_FEED(50.0000, 50.0000, 51.5000, 50.0000, -1, 99.8750,
; CHECK-NEXT: N8 {{ *}}STRAIGHT_TRAVERSE(50.0000, 50.0000, 110.0000,
; CHECK: N10 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 96.5000,
; CHECK-NEXT: N10 {{ *}}STRAIGHT_FEED(50.0000, 50.0000, 96.8750,
; CHECK-NEXT: N10 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N10 {{ *}}ARC_FEED(53.0000, 50.0000, 51.5000, 50.0000, 1, 96.5000,
; CHECK-NEXT: N10 {{ *}}SET_FEED_RATE(150.0000)
; CHECK-NEXT: N10 {{ *}}ARC_FEED(53.0000, 50.0000, 50.0000, 50.0000, 1, 95.0000,
; CHECK-NEXT: N10 {{ *}}SET_FEED_RATE(200.0000)
; CHECK-NEXT: N10 {{ *}}ARC_FEED(50.0000, 50.0000, 51.5000, 50.0000, 1, 94.6250,
; CHECK-NEXT: N10 {{ *}}STRAIGHT_TRAVERSE(50.0000, 50.0000, 110.0000,
0 BEGIN PGM THR262 MM
1 TOOL CALL 1 Z S1000 F300
2 L X+50 Y+50 Z+20 R0 FMAX M3
3 CYCL DEF 262 THREAD MILLING
  Q335=16 ;NOMINAL DIAMETER
  Q239=+1.5 ;THREAD PITCH
  Q201=-5 ;THREAD DEPTH
  Q355=0 ;THREADS PER STEP
  Q253=750 ;F PRE-POSITIONING
  Q351=+1 ;CLIMB OR UP-CUT
  Q200=2 ;SET-UP CLEARANCE
  Q203=+0 ;SURFACE COORDINATE
  Q204=10 ;2ND SET-UP CLEARANCE
  Q207=400 ;FEED RATE FOR MILLING
  Q512=200 ;FEED FOR APPROACH
4 CYCL CALL
5 CYCL DEF 262 THREAD MILLING
  Q335=16 ;NOMINAL DIAMETER
  Q239=+1.5 ;THREAD PITCH
  Q201=-5 ;THREAD DEPTH
  Q355=1 ;THREADS PER STEP
  Q253=750 ;F PRE-POSITIONING
  Q351=-1 ;CLIMB OR UP-CUT
  Q200=2 ;SET-UP CLEARANCE
  Q203=+0 ;SURFACE COORDINATE
  Q204=10 ;2ND SET-UP CLEARANCE
  Q207=400 ;FEED RATE FOR MILLING
  Q512=200 ;FEED FOR APPROACH
6 CYCL CALL
7 CYCL DEF 262 THREAD MILLING
  Q335=16 ;NOMINAL DIAMETER
  Q239=-1.5 ;THREAD PITCH
  Q201=-5 ;THREAD DEPTH
  Q355=2 ;THREADS PER STEP
  Q253=750 ;F PRE-POSITIONING
  Q351=-1 ;CLIMB OR UP-CUT
  Q200=2 ;SET-UP CLEARANCE
  Q203=+0 ;SURFACE COORDINATE
  Q204=10 ;2ND SET-UP CLEARANCE
  Q207=400 ;FEED RATE FOR MILLING
  Q512=200 ;FEED FOR APPROACH
8 CYCL CALL
9 CYCL DEF 262 THREAD MILLING
  Q335=16 ;NOMINAL DIAMETER
  Q239=-1.5 ;THREAD PITCH
  Q201=-5 ;THREAD DEPTH
  Q355=0 ;THREADS PER STEP
  Q253=750 ;F PRE-POSITIONING
  Q351=+1 ;CLIMB OR UP-CUT
  Q200=2 ;SET-UP CLEARANCE
  Q203=+0 ;SURFACE COORDINATE
  Q204=10 ;2ND SET-UP CLEARANCE
  Q207=400 ;FEED RATE FOR MILLING
  Q512=200 ;FEED FOR APPROACH
10 CYCL CALL
11 M2
12 END PGM THR262 MM
