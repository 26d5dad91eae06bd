; FEATURES: ISO-TOOL-05
; Tool nose radius compensation sides (G41 left, G42 right of the direction of travel, seen from +Y:
; +Z to the right, +X up), a G41 <-> G42 switch without G40, and a tool with offsets and wear.
; Inputs/lathe-tnrc.toml, machine = program with X a radius; expected values computed by hand:
; centre = the nose centre, machine = centre + 0.4 x the tip vector (tip 2: -Z +X; tip 3: -Z -X).
; RUN: %ncc compile %s --machine=%S/Inputs/lathe-tnrc.toml --emit=motion 2>&1 | grep -v "^comment" | FileCheck %s --implicit-check-not=error:
G98 F100
; The diagnostics come first (the T2300 section below).
; CHECK:      :{{[0-9]+}}:1: warning: tool nose radius compensation without a tool offset (T<tool><offset>): radius 0 [cutcomp-without-d]
; Inside (a boring bar, tip 2) towards the chuck: G41, the nose below the bore wall X12 (centre
; X11.6, tip X12: the programmed diameter). The bore/taper corner is concave (cut where X11.6 meets
; the taper's offset, Z-10 + 0.4 - 0.4 sqrt2 for the centre), the taper/Z corner convex (an arc about
; (Z-14, X8), clockwise: a right turn with the nose on the left).
T2222
G0 X10 Z5
G41 G0 X24 Z2
G1 Z-10
X16 Z-14
Z-20
G40 G0 X10 Z5
; CHECK:      tool_select 22
; CHECK:      rapid X12 Y0 Z1.6 A0 B0 C0
; CHECK-NEXT: linear X12 Y0 Z-10.2343{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X8.1171{{[0-9]*}} Y0 Z-14.1171{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X8 Y0 Z-14.4 A0 B0 C0 center(8.4, 0, -14.4) plane=zx turns=-1
; CHECK-NEXT: linear X8 Y0 Z-20.4 A0 B0 C0
; CHECK-NEXT: rapid X5 Y0 Z5 A0 B0 C0
; Outside (tip 3): G42 along Z (centre X20.4), then G41 without G40: the Z move ends normal to its
; end (centre Z-10, X20.4), the G41 block starts anew and ends normal to the next move on the new
; side (centre Z-10, X29.6: left of -Z is -X).
T2323
G0 X50 Z5
G42 G0 X40 Z2
G1 Z-10
G41 X60
Z-20
G40 G0 X80 Z5
; CHECK:      tool_select 23
; CHECK:      rapid X20 Y0 Z1.6 A0 B0 C0
; CHECK-NEXT: linear X20 Y0 Z-10.4 A0 B0 C0
; CHECK-NEXT: linear X29.2{{[0-9]*}} Y0 Z-10.4 A0 B0 C0
; CHECK-NEXT: linear X29.2{{[0-9]*}} Y0 Z-20.4 A0 B0 C0
; CHECK-NEXT: rapid X40 Y0 Z5 A0 B0 C0
; Tool 10: tip 3, nose radius 0.7 + wear 0.1, X offset 5, Z offset 10: the nose centre path uses
; 0.8 and the offsets move everything by X+5 Z+10.
T1010
G0 X40 Z10
G42 G0 X20 Z2
G1 Z-10
G40 G0 X40 Z10
; G42 in force without an offset (T2300: radius 0, a warning): the T word that brings one starts it,
; so the next move is the start-up (Fanuc's rule; the 808D manual: "G41/G42 with T").
T2300
G0 X40 Z5
G42 G0 X30 Z2
T2323
G0 X20 Z2
G1 Z-10
G40 G0 X40 Z5
M30
; CHECK:      tool_length 10 H10 X5
; CHECK:      rapid X15 Y0 Z11.2 A0 B0 C0
; CHECK-NEXT: linear X15 Y0 Z-0.{{8|79+[0-9]*}} A0 B0 C0
; CHECK-NEXT: rapid X25 Y0 Z20 A0 B0 C0
; CHECK:      tool_length 0 H0
; CHECK-NEXT: rapid X20 Y0 Z5 A0 B0 C0
; CHECK-NEXT: rapid X15 Y0 Z2 A0 B0 C0
; CHECK:      tool_length 0 H23
; CHECK-NEXT: rapid X10 Y0 Z1.6 A0 B0 C0
; CHECK-NEXT: linear X10 Y0 Z-10.4 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z5 A0 B0 C0
