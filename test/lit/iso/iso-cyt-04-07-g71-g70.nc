G18 G99 S1000 M3
G0 X60. Z5.
G71 U3. R0.5
G71 P10 Q50 U1. W0.5 F0.2
N10 G0 X20.
N20 G1 Z-10. F0.1
N30 X40. Z-20.
N40 Z-30.
N50 X56.
G0 X80. Z20.
G70 P10 Q50
M30
%
; FEATURES: ISO-CYT-04 ISO-CYT-07
; G71 type I on the plain lathe (Inputs/lathe0.toml: no offsets, X a diameter, machine X a radius).
; Start C = X60 Z5 (radius 30); the contour A' = X20 (radius 10) then Z-10, X40 Z-20, Z-30, X56;
; U1 W0.5: the contour shifted by +0.5 in X (radius) and Z. Layers 3 mm deep (radius) at X radius
; 27 24 21 18 15 12, each cut along -Z at the G71 block's F0.2 (mm/rev, S1000: 200 mm/min) until
; it meets the shifted contour, out 0.5 at 45 degrees, back at rapid; then back by the Z
; allowance, across to A' (as N10: rapid), one pass along the shifted contour and back to C. The contour's own F0.1 counts only for G70, which runs the blocks
; as written from X80 Z20 and returns there. After G71 the program goes on after N50.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=motion | FileCheck %s
; CHECK:      rapid X30 Y0 Z5 A0 B0 C0 @2:1
; CHECK-NEXT: feed_rate 0.2 @4:22
; CHECK-NEXT: cycle_begin "contour.rough_z" @4:1
; CHECK-NEXT: rapid X27 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X27 Y0 Z-29.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X27.5 Y0 Z-29 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X27.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X24 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X24 Y0 Z-29.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X24.5 Y0 Z-29 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X24.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X21 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X21 Y0 Z-29.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X21.5 Y0 Z-29 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X21.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X18 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X18 Y0 Z-17 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X18.5 Y0 Z-16.5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X18.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X15 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X15 Y0 Z-14 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X15.5 Y0 Z-13.5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X15.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X12 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X12 Y0 Z-11 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X12.5 Y0 Z-10.5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X12.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X12.5 Y0 Z5.5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X10.5 Y0 Z5.5 A0 B0 C0 @4:1
; CHECK-NEXT: linear X10.5 Y0 Z-9.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: linear X20.5 Y0 Z-19.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: linear X20.5 Y0 Z-29.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: linear X28.5 Y0 Z-29.5 A0 B0 C0 F200 @4:1
; CHECK-NEXT: rapid X30.5 Y0 Z-29.5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X30.5 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: rapid X30 Y0 Z5 A0 B0 C0 @4:1
; CHECK-NEXT: cycle_end @4:1
; CHECK-NEXT: rapid X40 Y0 Z20 A0 B0 C0 @10:1
; CHECK-NEXT: rapid X10 Y0 Z20 A0 B0 C0 N10 @5:5
; CHECK-NEXT: feed_rate 0.1 N20 @6:14
; CHECK-NEXT: linear X10 Y0 Z-10 A0 B0 C0 F100 N20 @6:5
; CHECK-NEXT: linear X20 Y0 Z-20 A0 B0 C0 F100 N30 @7:1
; CHECK-NEXT: linear X20 Y0 Z-30 A0 B0 C0 F100 N40 @8:1
; CHECK-NEXT: linear X28 Y0 Z-30 A0 B0 C0 F100 N50 @9:1
; CHECK-NEXT: rapid X40 Y0 Z20 A0 B0 C0 @11:1
; CHECK-NEXT: program_end 30 @12:1
; In NC IR, the data block, the capture around the section, the jump past the contour.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=ir | FileCheck %s --check-prefix=IR
; IR:      contour action=data use=rough_z U=3.0 R=0.5
; IR:      feed value=0.2
; IR-NEXT: contour action=begin
; IR-NEXT: call_section from="N10" to="N50_to"
; IR-NEXT: contour action=end use=rough_z U=1.0 W=0.5
; IR-NEXT: goto label="N50_end"
; IR-NEXT: label name="N10"
; IR-NEXT: block n=10
; IR:      block n=50
; IR-NEXT: label name="N50_to"
; IR-NEXT: move X=56.0
; IR-NEXT: label name="N50_end"
