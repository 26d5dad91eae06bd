G18 G94 G0 X60. Z5.
G91 G1 X-10. Z-5. F100.
G90 G77 X40. Z-20.
X30.
G0 X60.
M30
%
; FEATURES: ISO-FEED-02 ISO-CYT-01
; G-code system B on a lathe (Inputs/lathe-b.toml, 808D Table 1-4): G94 is feed per minute,
; G91/G90 the distance modes (a G91 X is an incremental diameter), G77 the turning cycle (G90 of
; system A), modal with repeats.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe-b.toml --emit=motion | FileCheck %s
; CHECK:      feed_mode 0 @1:5
; CHECK-NEXT: plane 1 @1:1
; CHECK-NEXT: rapid X30 Y0 Z5 A0 B0 C0 @1:9
; CHECK-NEXT: feed_rate 100 @2:19
; CHECK-NEXT: linear X25 Y0 Z0 A0 B0 C0 F100 @2:5
; CHECK-NEXT: cycle_begin "iso.turn_z" @3:5
; CHECK-NEXT: rapid X20 Y0 Z0 A0 B0 C0 @3:5
; CHECK-NEXT: linear X20 Y0 Z-20 A0 B0 C0 F100 @3:5
; CHECK-NEXT: linear X25 Y0 Z-20 A0 B0 C0 F100 @3:5
; CHECK-NEXT: rapid X25 Y0 Z0 A0 B0 C0 @3:5
; CHECK-NEXT: cycle_end @3:5
; CHECK-NEXT: cycle_begin "iso.turn_z" @4:1
; CHECK-NEXT: rapid X15 Y0 Z0 A0 B0 C0 @4:1
; CHECK-NEXT: linear X15 Y0 Z-20 A0 B0 C0 F100 @4:1
; CHECK-NEXT: linear X25 Y0 Z-20 A0 B0 C0 F100 @4:1
; CHECK-NEXT: rapid X25 Y0 Z0 A0 B0 C0 @4:1
; CHECK-NEXT: cycle_end @4:1
; CHECK-NEXT: rapid X30 Y0 Z0 A0 B0 C0 @5:1
; U and W are not increments in system B (the manual does not say they are), system A's G50 is
; no code of system B, and the skip function G31 is not done. (G12.1 compiles: the run needs a C axis,
; iso-transform.test.)
; RUN: not %ncc compile %S/Inputs/system-b-errors.nc --machine=%S/Inputs/lathe-b.toml --emit=ir 2>&1 | FileCheck %s --check-prefix=ERR
; ERR: system-b-errors.nc:2:4: error: U in G-code system B: the 808D manual does not say it is an increment (use G91) [unsupported-code]
; ERR: system-b-errors.nc:3:1: error: G50 is not a turning G code (808D G-code system B) [unknown-code]
; ERR-NOT: system-b-errors.nc:4
