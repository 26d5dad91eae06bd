; FEATURES: ISO-MOT-07 ISO-TOOL-04
; A rounding under cutter compensation joins the programmed contour, which is then offset (default
; mill, T1 radius 5, G42: the tool right of the path). By hand: the entry from (-20, -20) to (0, 0)
; meets the first line's offset y = -5 at x = 5/sqrt2 - (5 - 5/sqrt2) = 2.0711 (a concave corner);
; ,R5 at (40, 0) is the arc about (35, 5); the tool outside it runs radius 10 from (35, -5) to
; (45, 5), tangent to both offsets; then x = 45 up to y = 40, and G40 out to (60, 60).
; RUN: %ncc compile %s --emit=motion 2>&1 | grep -v "^comment" | FileCheck %s --implicit-check-not=error:
G17 G21 G90
T1 M6
G0 X-20 Y-20 Z0
G1 F100
G42 D1 X0 Y0
X40 ,R5
Y40
G40 X60 Y60
M30
; CHECK:      linear X2.0710{{[0-9]*}} Y-5 Z0 A0 B0 C0 F100
; CHECK-NEXT: linear X35 Y-5 Z0 A0 B0 C0 F100
; CHECK-NEXT: arc X45 Y5{{(.00000000000000[0-9])?}} Z0 A0 B0 C0 center(35, 5, 0) plane=xy turns=1 F100
; CHECK-NEXT: linear X45 Y40 Z0 A0 B0 C0 F100
; CHECK-NEXT: linear X60 Y60 Z0 A0 B0 C0 F100
