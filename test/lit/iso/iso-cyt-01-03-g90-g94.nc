G18 G98 G0 X50. Z2.
G90 X40. Z-20. F100.
X30.
U-30. R-2.
G94 X10. Z-2. F50.
Z-4.
G0 X60.
M30
; FEATURES: ISO-CYT-01 ISO-CYT-03
; The single cycles G90 (along Z) and G94 (along X), system A, on the plain lathe (X diameters,
; machine X radii): modal in group 01, each block four steps from the start point A = X50 Z2
; (radius 25) and back to A; a repeat block gives only what changes (X30: the same Z-20; U-30:
; X20 by U from A, with the taper R-2, a radius, at A's Z); G94 with Z repeats; G0 ends the mode.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=motion | FileCheck %s
; CHECK:      rapid X25 Y0 Z2 A0 B0 C0 @1:9
; CHECK-NEXT: feed_rate 100 @2:16
; CHECK-NEXT: cycle_begin "iso.turn_z" @2:1
; CHECK-NEXT: rapid X20 Y0 Z2 A0 B0 C0 @2:1
; CHECK-NEXT: linear X20 Y0 Z-20 A0 B0 C0 F100 @2:1
; CHECK-NEXT: linear X25 Y0 Z-20 A0 B0 C0 F100 @2:1
; CHECK-NEXT: rapid X25 Y0 Z2 A0 B0 C0 @2:1
; CHECK-NEXT: cycle_end @2:1
; CHECK-NEXT: cycle_begin "iso.turn_z" @3:1
; CHECK-NEXT: rapid X15 Y0 Z2 A0 B0 C0 @3:1
; CHECK-NEXT: linear X15 Y0 Z-20 A0 B0 C0 F100 @3:1
; CHECK-NEXT: linear X25 Y0 Z-20 A0 B0 C0 F100 @3:1
; CHECK-NEXT: rapid X25 Y0 Z2 A0 B0 C0 @3:1
; CHECK-NEXT: cycle_end @3:1
; CHECK-NEXT: cycle_begin "iso.turn_z" @4:1
; CHECK-NEXT: rapid X8 Y0 Z2 A0 B0 C0 @4:1
; CHECK-NEXT: linear X10 Y0 Z-20 A0 B0 C0 F100 @4:1
; CHECK-NEXT: linear X25 Y0 Z-20 A0 B0 C0 F100 @4:1
; CHECK-NEXT: rapid X25 Y0 Z2 A0 B0 C0 @4:1
; CHECK-NEXT: cycle_end @4:1
; CHECK-NEXT: feed_rate 50 @5:15
; CHECK-NEXT: cycle_begin "iso.turn_x" @5:1
; CHECK-NEXT: rapid X25 Y0 Z-2 A0 B0 C0 @5:1
; CHECK-NEXT: linear X5 Y0 Z-2 A0 B0 C0 F50 @5:1
; CHECK-NEXT: linear X5 Y0 Z2 A0 B0 C0 F50 @5:1
; CHECK-NEXT: rapid X25 Y0 Z2 A0 B0 C0 @5:1
; CHECK-NEXT: cycle_end @5:1
; CHECK-NEXT: cycle_begin "iso.turn_x" @6:1
; CHECK-NEXT: rapid X25 Y0 Z-4 A0 B0 C0 @6:1
; CHECK-NEXT: linear X5 Y0 Z-4 A0 B0 C0 F50 @6:1
; CHECK-NEXT: linear X5 Y0 Z2 A0 B0 C0 F50 @6:1
; CHECK-NEXT: rapid X25 Y0 Z2 A0 B0 C0 @6:1
; CHECK-NEXT: cycle_end @6:1
; CHECK-NEXT: rapid X30 Y0 Z2 A0 B0 C0 @7:1
; CHECK-NEXT: program_end 30 @8:1
