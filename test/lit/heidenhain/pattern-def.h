; FEATURES: HEI-PAT-01 HEI-PAT-02 HEI-PAT-03 HEI-PAT-04 HEI-PAT-05 HEI-PAT-06 HEI-CYC-04
; PATTERN DEF, all six forms, each run by CYCL CALL PAT FMAX with cycle 200 (one infeed to Z-5):
; one STRAIGHT_FEED per hole, at the positions computed by hand (default machine: tool 1 is 100
; long, Z machine = Z work + 100).
; POS: (25, 33.5); POS2 X+15 IY+6.5 -> (15, 40); POS3 IX+10 Y+0 with its surface Z-5 -> (25, 0),
; bottom Z-10.
; ROW1 from (10, 10), D 8, ROT 90: (10, 10) (10, 18) (10, 26).
; PAT1 3 x 2, DX 10 DY 5: row 0 forward, row 1 back (the meander ncc chooses, as cycle 221).
; PAT1 2 x 2 with ROTY 30: the second axis turned to 120 degrees: (0,0) (10,0) (5, 8.6603) (-5, 8.6603).
; FRAME1 3 x 3: the 8 border points of the grid.
; CIRC1 D80 about (25, 33) from 45 degrees, 8 points: 25 + 40 cos(45 + 45k), 33 + 40 sin(…).
; PITCHCIRC1 D80 from 45 degrees in steps of 30: 45, 75, 105 degrees (40 cos 75 = 10.3528, 40 sin 75 = 38.6370).
; RUN: %ncc run %s --trace=canon 2>/dev/null > %t.canon
; RUN: grep STRAIGHT_FEED %t.canon | cut -d'(' -f2 | cut -d, -f1-3 | FileCheck %s
; RUN: %ncc compile --emit=motion --engine=eval %s > %t.e 2>/dev/null
; RUN: %ncc compile --emit=motion --engine=jit %s > %t.j 2>/dev/null
; RUN: diff %t.e %t.j
; RUN: %ncc compile --emit=ir %s 2>/dev/null | FileCheck %s --check-prefix=IR
; IR: cycle pattern="hei.PATTERN.POS" action=call p.X1=25 p.Y1=33.5 p.Z1=0 p.X2=15 p.Y2=(add 33.5 6.5) p.Z2=0 p.X3=(add 15 10) p.Y3=0 p.Z3=-5 p.FMAX=1
; IR: cycle pattern="hei.PATTERN.ROW" action=call p.X=10 p.Y=10 p.D=8 p.NUM=3 p.ROT=90 p.Z=0 p.FMAX=1
; CHECK: 25.0000, 33.5000, 95.0000
; CHECK-NEXT: 15.0000, 40.0000, 95.0000
; CHECK-NEXT: 25.0000, 0.0000, 90.0000
; CHECK-NEXT: 10.0000, 10.0000, 95.0000
; CHECK-NEXT: 10.0000, 18.0000, 95.0000
; CHECK-NEXT: 10.0000, 26.0000, 95.0000
; CHECK-NEXT: 0.0000, 0.0000, 95.0000
; CHECK-NEXT: 10.0000, 0.0000, 95.0000
; CHECK-NEXT: 20.0000, 0.0000, 95.0000
; CHECK-NEXT: 20.0000, 5.0000, 95.0000
; CHECK-NEXT: 10.0000, 5.0000, 95.0000
; CHECK-NEXT: 0.0000, 5.0000, 95.0000
; CHECK-NEXT: 0.0000, 0.0000, 95.0000
; CHECK-NEXT: 10.0000, 0.0000, 95.0000
; CHECK-NEXT: 5.0000, 8.6603, 95.0000
; CHECK-NEXT: -5.0000, 8.6603, 95.0000
; CHECK-NEXT: 0.0000, 0.0000, 95.0000
; CHECK-NEXT: 10.0000, 0.0000, 95.0000
; CHECK-NEXT: 20.0000, 0.0000, 95.0000
; CHECK-NEXT: 20.0000, 10.0000, 95.0000
; CHECK-NEXT: 0.0000, 10.0000, 95.0000
; CHECK-NEXT: 0.0000, 20.0000, 95.0000
; CHECK-NEXT: 10.0000, 20.0000, 95.0000
; CHECK-NEXT: 20.0000, 20.0000, 95.0000
; CHECK-NEXT: 53.2843, 61.2843, 95.0000
; CHECK-NEXT: 25.0000, 73.0000, 95.0000
; CHECK-NEXT: -3.2843, 61.2843, 95.0000
; CHECK-NEXT: -15.0000, 33.0000, 95.0000
; CHECK-NEXT: -3.2843, 4.7157, 95.0000
; CHECK-NEXT: 25.0000, -7.0000, 95.0000
; CHECK-NEXT: 53.2843, 4.7157, 95.0000
; CHECK-NEXT: 65.0000, 33.0000, 95.0000
; CHECK-NEXT: 53.2843, 61.2843, 95.0000
; CHECK-NEXT: 35.3528, 71.6370, 95.0000
; CHECK-NEXT: 14.6472, 71.6370, 95.0000
; CHECK-NOT: {{.}}
; Translated to Klartext, ISO and Sinumerik, each reads back to the same path (docs/EMIT.md; ISO
; and Sinumerik select G54 / G500, so they run on a machine whose G54 is zero).
; RUN: %ncc translate %s --to=heidenhain --machine=%srcroot/examples/machines/heidenhain-tnc640-mill.toml --verify -o %t.to.h 2>&1 | FileCheck %s --check-prefix=TRANSLATED
; RUN: %ncc translate %s --to=iso --machine=%srcroot/test/lit/emit/Inputs/emit-mill.toml --verify -o %t.to.nc 2>&1 | FileCheck %s --check-prefix=TRANSLATED
; RUN: %ncc translate %s --to=sinumerik --machine=%srcroot/test/lit/emit/Inputs/emit-mill.toml --verify -o %t.to.mpf 2>&1 | FileCheck %s --check-prefix=TRANSLATED
; TRANSLATED: verified:
0 BEGIN PGM FORMS MM
1 TOOL CALL 1 Z S1000 F300
2 L Z+50 R0 FMAX M3
3 CYCL DEF 200 DRILLING
  Q200=2 ;SET-UP CLEARANCE
  Q201=-5 ;DEPTH
  Q206=100 ;FEED
  Q202=5 ;PLUNGING DEPTH
  Q210=0
  Q203=+0 ;SURFACE
  Q204=10 ;2ND SET-UP CLEARANCE
  Q211=0
4 PATTERN DEF
  POS1 (X+25 Y+33,5 Z+0)
  POS2 (X+15 IY+6,5 Z+0)
  POS3 (IX+10 Y+0 Z-5)
5 CYCL CALL PAT FMAX
6 PATTERN DEF ROW1 (X+10 Y+10 D+8 NUM3 ROT+90 Z+0)
7 CYCL CALL PAT FMAX
8 PATTERN DEF PAT1
  (X+0 Y+0 DX+10 DY+5 NUMX3 NUMY2 ROT+0 ROTX+0 ROTY+0 Z+0)
9 CYCL CALL PAT FMAX
10 PATTERN DEF PAT1 (X+0 Y+0 DX+10 DY+10 NUMX2 NUMY2 ROT+0 ROTX+0 ROTY+30 Z+0)
11 CYCL CALL PAT FMAX
12 PATTERN DEF FRAME1 (X+0 Y+0 DX+10 DY+10 NUMX3 NUMY3 ROT+0 ROTX+0 ROTY+0 Z+0)
13 CYCL CALL PAT FMAX
14 PATTERN DEF CIRC1 (X+25 Y+33 D80 START+45 NUM8 Z+0)
15 CYCL CALL PAT FMAX
16 PATTERN DEF PITCHCIRC1 (X+25 Y+33 D80 START+45 STEP30 NUM3 Z+0)
17 CYCL CALL PAT FMAX
18 M2
19 END PGM FORMS MM
