G0 X0 Y0 Z10
G54 P1 G0 X0 Y0
G54 P2 X1
G54 P6 X0 Y0 Z0
G54 P5 X0
G55 X0
G54 X0
M30
; FEATURES: ISO-CS-03
; The 808D's extended work offsets G54 P1…P93 (manual L1972, L5426, L6224) select the machine's
; [offsets] g54p entries; plain G54 (no P) is the first settable offset again.
; RUN: %ncc run %s --machine=%S/Inputs/808d-extended-offsets.toml --trace=canon -q | FileCheck %s
; CHECK: STRAIGHT_TRAVERSE(10.0000, 0.0000, 10.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(100.0000, 1.0000, 10.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(201.0000, 1.0000, 10.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(600.0000, 6.0000, -5.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(0.0000, 6.0000, -5.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(20.0000, 6.0000, -5.0000,
; CHECK-NEXT: STRAIGHT_TRAVERSE(10.0000, 6.0000, -5.0000,
; The frame records name the selection: settable offsets 7… (P1-P3 share G59.1-G59.3's slots).
; RUN: %ncc compile %s --machine=%S/Inputs/808d-extended-offsets.toml --emit=motion | FileCheck %s --check-prefix=FRAME
; FRAME: frame_change "G59.1" {{.*}} m03=100 {{.*}} wcs=7 @2:1
; FRAME: frame_change "G59.2" {{.*}} m03=200 {{.*}} wcs=8 @3:1
; FRAME: frame_change "G54 P6" {{.*}} m03=600 {{.*}} m23=-5 wcs=12 @4:1
; FRAME: frame_change "G54 P5" {{.*}} m03=0 {{.*}} wcs=11 @5:1
; Translated for an 808D (family "iso") the selections keep their codes and read back equal; a
; Sinumerik target selects P1-P3 as G507-G509 (the same slots) and bakes P4… into the positions.
; RUN: %ncc translate %s --machine=%S/Inputs/808d-extended-offsets.toml --to=iso --verify -o %t.iso.nc 2>&1 | FileCheck %s --check-prefix=VERIFY
; RUN: FileCheck %s --check-prefix=ISO --input-file=%t.iso.nc
; RUN: %ncc translate %s --machine=%S/Inputs/808d-extended-offsets.toml --to=sinumerik --verify -o %t.mpf 2>&1 | FileCheck %s --check-prefix=VERIFY
; RUN: FileCheck %s --check-prefix=SIN --input-file=%t.mpf
; VERIFY: verified:
; ISO: G54 P1
; ISO-NEXT: X0. Y0.
; ISO-NEXT: G54 P2
; ISO-NEXT: X1.
; ISO-NEXT: G54 P6
; ISO-NEXT: X0. Y0. Z0.
; ISO-NEXT: G54 P5
; ISO-NEXT: X0.
; ISO-NEXT: G55
; SIN: N30 G507
; SIN: N50 G508
; SIN: ; ncc: from here the positions include the frame of G54 P6: no code for it on this target
; SIN-NEXT: N70 X400 Y4 Z-5
; The NC IR: work_offset index 6 + n.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: work_offset index=7 loc(1:2:1)
; IR: work_offset index=8 loc(1:3:1)
; IR: work_offset index=12 loc(1:4:1)
; Refused: the external offset P0 (the PLC's), P out of 1…93, P with a point or a variable.
; RUN: printf 'G54 P0\nM30\n' > %t0.nc
; RUN: not %ncc run %t0.nc -q 2>&1 | FileCheck %s --check-prefix=P0
; P0: :1:5: error: G54 P0 (the external work offset, set by the PLC) is not supported: its value is not known [unsupported-code]
; RUN: printf 'G54 P94\nM30\n' > %t1.nc
; RUN: not %ncc run %t1.nc -q 2>&1 | FileCheck %s --check-prefix=BAD
; RUN: printf 'G54 P1.5\nM30\n' > %t2.nc
; RUN: not %ncc run %t2.nc -q 2>&1 | FileCheck %s --check-prefix=BAD
; RUN: printf '#1=2\nG54 P#1\nM30\n' > %t3.nc
; RUN: not %ncc run %t3.nc -q 2>&1 | FileCheck %s --check-prefix=BAD
; BAD: error: G54 P needs a whole number 1 to 93 (an extended work offset) written as a constant [bad-offset-index]
; A machine file that gives G54 P1 and "g59.1" (one slot) differently is refused.
; RUN: printf 'schema = 1\n[machine]\nname = "m"\n[axes.X]\nmax_velocity = 1\nmax_accel = 1\n[offsets]\n"g59.1" = [1, 0, 0]\ng54p = [[2, 0, 0]]\n' > %t.toml
; RUN: not %ncc machine --check %t.toml 2>&1 | FileCheck %s --check-prefix=TOML
; TOML: g54p[0] (G54 P1) and "g59.1" are one offset: give it once
; The 808D's G10 L2 P0 writes the external offset (rs274: the active system) and G10 L2 in G91
; adds (L6236-6243): both refused, never written as rs274 would.
; RUN: printf 'G10 L2 P0 X5\nM30\n' > %t4.nc
; RUN: not %ncc run %t4.nc -q 2>&1 | FileCheck %s --check-prefix=L2P0
; L2P0: :1:8: error: G10 L2 P0 writes the 808D's external work offset (set by the PLC): not supported [unsupported-code]
; RUN: printf 'G91 G10 L2 P1 X5\nM30\n' > %t5.nc
; RUN: not %ncc run %t5.nc -q 2>&1 | FileCheck %s --check-prefix=L2INC
; L2INC: :1:5: error: G10 L2 in G91 adds the values to the work offset (808D): not supported, write it in G90 [unsupported-code]
