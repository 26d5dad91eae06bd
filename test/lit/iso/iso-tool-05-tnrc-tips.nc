; FEATURES: ISO-TOOL-05
; Every imaginary tool tip on one taper (Inputs/lathe-tnrc.toml: tool 20 + n has tip n, nose radius
; 0.4, no offsets, so machine = program with X a radius): G42 from (Z10, X20), start-up to (Z2, X10),
; the taper to (Z-8, X15), along Z to Z-15, G40 back. The nose centre's path is the same for every
; tip: the start-up ends normal to the taper at (Z2 + 0.4/sqrt5, X10 + 0.8/sqrt5); the taper ends
; normal to itself at (Z-8 + 0.4/sqrt5, X15 + 0.8/sqrt5), the convex corner is an arc about (Z-8,
; X15) to (Z-8, X15.4), the Z move ends at (Z-15, X15.4). The machine position is that plus 0.4 x
; the tip vector (tip 1 (+Z +X), 2 (-Z +X), 3 (-Z -X), 4 (+Z -X), 5 +Z, 6 +X, 7 -Z, 8 -X; 0 and 9
; none), so a tip 3 tool's tip, the point its offsets are measured to, touches the diameter X15
; with its -X side. Expected values computed with the formulas above (Python, the first 4 decimals).
; RUN: %ncc compile %s --machine=%S/Inputs/lathe-tnrc.toml --emit=motion 2>&1 | FileCheck %s
G98 G0 X40 Z10 F100
T2121
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2222
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2323
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2424
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2525
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2626
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2727
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2828
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2020
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
T2929
G0 X40 Z10
G42 G0 X20 Z2
G1 X30 Z-8
Z-15
G40 G0 X40 Z10
M30
; CHECK:      tool_select 21
; CHECK:      rapid X10.7577{{[0-9]*}} Y0 Z2.5788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.7577{{[0-9]*}} Y0 Z-7.4211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.8 Y0 Z-7.6 A0 B0 C0 center(15.4, 0, -7.6) plane=zx turns=1
; CHECK-NEXT: linear X15.8 Y0 Z-14.6 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 22
; CHECK:      rapid X10.7577{{[0-9]*}} Y0 Z1.7788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.7577{{[0-9]*}} Y0 Z-8.2211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.8 Y0 Z-8.4 A0 B0 C0 center(15.4, 0, -8.4) plane=zx turns=1
; CHECK-NEXT: linear X15.8 Y0 Z-15.4 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 23
; CHECK:      rapid X9.9577{{[0-9]*}} Y0 Z1.7788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X14.9577{{[0-9]*}} Y0 Z-8.2211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15 Y0 Z-8.4 A0 B0 C0 center(14.6, 0, -8.4) plane=zx turns=1
; CHECK-NEXT: linear X15 Y0 Z-15.4 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 24
; CHECK:      rapid X9.9577{{[0-9]*}} Y0 Z2.5788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X14.9577{{[0-9]*}} Y0 Z-7.4211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15 Y0 Z-7.6 A0 B0 C0 center(14.6, 0, -7.6) plane=zx turns=1
; CHECK-NEXT: linear X15 Y0 Z-14.6 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 25
; CHECK:      rapid X10.3577{{[0-9]*}} Y0 Z2.5788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.3577{{[0-9]*}} Y0 Z-7.4211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.4 Y0 Z-7.6 A0 B0 C0 center(15, 0, -7.6) plane=zx turns=1
; CHECK-NEXT: linear X15.4 Y0 Z-14.6 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 26
; CHECK:      rapid X10.7577{{[0-9]*}} Y0 Z2.1788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.7577{{[0-9]*}} Y0 Z-7.8211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.8 Y0 Z-8 A0 B0 C0 center(15.4, 0, -8) plane=zx turns=1
; CHECK-NEXT: linear X15.8 Y0 Z-15 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 27
; CHECK:      rapid X10.3577{{[0-9]*}} Y0 Z1.7788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.3577{{[0-9]*}} Y0 Z-8.2211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.4 Y0 Z-8.4 A0 B0 C0 center(15, 0, -8.4) plane=zx turns=1
; CHECK-NEXT: linear X15.4 Y0 Z-15.4 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 28
; CHECK:      rapid X9.9577{{[0-9]*}} Y0 Z2.1788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X14.9577{{[0-9]*}} Y0 Z-7.8211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15 Y0 Z-8 A0 B0 C0 center(14.6, 0, -8) plane=zx turns=1
; CHECK-NEXT: linear X15 Y0 Z-15 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 20
; CHECK:      rapid X10.3577{{[0-9]*}} Y0 Z2.1788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.3577{{[0-9]*}} Y0 Z-7.8211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.4 Y0 Z-8 A0 B0 C0 center(15, 0, -8) plane=zx turns=1
; CHECK-NEXT: linear X15.4 Y0 Z-15 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
; CHECK:      tool_select 29
; CHECK:      rapid X10.3577{{[0-9]*}} Y0 Z2.1788{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: linear X15.3577{{[0-9]*}} Y0 Z-7.8211{{[0-9]*}} A0 B0 C0
; CHECK-NEXT: arc X15.4 Y0 Z-8 A0 B0 C0 center(15, 0, -8) plane=zx turns=1
; CHECK-NEXT: linear X15.4 Y0 Z-15 A0 B0 C0
; CHECK-NEXT: rapid X20 Y0 Z10 A0 B0 C0
