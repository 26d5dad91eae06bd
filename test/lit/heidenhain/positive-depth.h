; FEATURES: HEI-LNT-06 HEI-CYC-08
; A positive depth in a 2xx cycle (seed002a L779-797, L1802-1813): with the TNC's machine
; parameter displayDepthErr on (ncc's default, key display_depth_err) the control stops with an
; error; with it off the pre-positioning is inverted: the tool goes at rapid to the set-up
; clearance BELOW the surface (machine Z 100 - 2 = 98 for surface Z+0, tool length 100), the
; manual's collision warning, and drills up to the depth +3 (103).
; RUN: not %ncc run %s -q -o %t 2>&1 | FileCheck %s --check-prefix=ERR
; RUN: not %ncc lint %s 2>&1 | FileCheck %s --check-prefix=ERR
; ERR: positive-depth.h:[[@LINE+23]]:{{[0-9]+}}: error: hei.200: the depth Q201=+3 is positive: the TNC stops with an error (machine parameter displayDepthErr, key display_depth_err; without it the cycle pre-positions below the surface) [positive-depth]
; RUN: printf 'schema = 1\n[controller]\nfamily = "heidenhain"\ndisplay_depth_err = false\n[axes.X]\nmax_velocity = 100\nmax_accel = 1000\n[axes.Y]\nmax_velocity = 100\nmax_accel = 1000\n[axes.Z]\nmax_velocity = 100\nmax_accel = 1000\n[[tools]]\nnumber = 1\nedges = [{ d = 1, length = 100 }]\n' > %t.toml
; RUN: %ncc run %s --machine=%t.toml --trace=canon -q -o - | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(10.0000, 10.0000, 200.0000,
; CHECK-NEXT: SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 10.0000, 98.0000,
; CHECK-NEXT: SET_FEED_RATE(150.0000)
; CHECK-NEXT: STRAIGHT_FEED(10.0000, 10.0000, 103.0000,
0 BEGIN PGM PD MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-20
2 BLK FORM 0.2 X+100 Y+100 Z+0
3 TOOL CALL 1 Z S4500
4 L Z+100 R0 FMAX
5 CYCL DEF 200 DRILLING ~
  Q200=2 ;SET-UP CLEARANCE ~
  Q201=+3 ;DEPTH ~
  Q206=150 ;FEED RATE FOR PLNGNG ~
  Q202=5 ;PLUNGING DEPTH ~
  Q210=0 ;DWELL TIME AT TOP ~
  Q203=+0 ;SURFACE COORDINATE ~
  Q204=50 ;2ND SET-UP CLEARANCE ~
  Q211=0.25 ;DWELL TIME AT DEPTH ~
  Q395=0 ;DEPTH REFERENCE
6 L X+10 Y+10 R0 FMAX M99
7 L Z+100 R0 FMAX M30
8 END PGM PD MM
