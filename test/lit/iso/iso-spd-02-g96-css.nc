N4 G50 S1500
N6 G96 S150 M03
N7 G00 X40. Z5.
N8 G01 Z0 F0.15
N9 X80. Z-30.
N10 W-10.
N11 G2 X120. W-20. R20.
N12 G01 U10.
N13 G97 S500
N14 G96 S100
N15 G00 X10.
N16 G01 Z-80.
N17 G50 S1000
N18 G01 X0
N19 G97
N20 M30
; FEATURES: ISO-SPD-02 ISO-SPD-03 ISO-CS-04
; Spec example 13 (seed L2565-2573) in G-code system A (G50 S1500 for the example's system-B G92
; S, whose U W system B does not have), on a lathe with diameter programming and no offsets
; (machine X = radius). CSS: rpm = 1000 S / (2 pi r), at most the G50 S limit; the feed per
; revolution becomes the move's mean path speed. r = 20 mm at X40: 150 m/min gives 1193.66 rpm,
; 0.15 mm/rev 179.05 mm/min; at X10 (r = 5) 100 m/min would be 3183 rpm: the 1500 limit holds,
; then the 1000 of N17. G97 without S keeps the speed reached (808D manual L2586): 1000 rpm at X0.
; RUN: %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=motion | FileCheck %s
; CHECK:      spindle_mode 0 1500 0 N4 @1:8
; CHECK-NEXT: spindle_mode 1 1500 0 N6 @2:4
; CHECK-NEXT: spindle_speed 150 N6 @2:4
; CHECK-NEXT: spindle_cw 0 N6 @2:13
; CHECK-NEXT: rapid X20 Y0 Z5 A0 B0 C0 N7 @3:4
; CHECK-NEXT: feed_rate 0.15 N8 @4:11
; CHECK-NEXT: linear X20 Y0 Z0 A0 B0 C0 F179.049310{{[0-9]*}} N8 @4:4
; CHECK-NEXT: linear X40 Y0 Z-30 A0 B0 C0 F119.366207{{[0-9]*}} N9 @5:1
; CHECK-NEXT: linear X40 Y0 Z-40 A0 B0 C0 F89.524655{{[0-9]*}} N10 @6:1
; CHECK-NEXT: arc X60 Y0 Z-60 A0 B0 C0 center(60, 0, -40) plane=zx turns=-1 F75.760353{{[0-9]*}} N11 @7:5
; CHECK-NEXT: linear X65 Y0 Z-60 A0 B0 C0 F57.295779{{[0-9]*}} N12 @8:5
; CHECK-NEXT: spindle_mode 0 1500 0 N13 @9:5
; CHECK-NEXT: spindle_speed 500 N13 @9:5
; CHECK-NEXT: spindle_mode 1 1500 0 N14 @10:5
; CHECK-NEXT: spindle_speed 100 N14 @10:5
; CHECK-NEXT: rapid X5 Y0 Z-60 A0 B0 C0 N15 @11:5
; CHECK-NEXT: linear X5 Y0 Z-80 A0 B0 C0 F225.000000{{[0-9]*}} N16 @12:5
; CHECK-NEXT: spindle_mode 1 1000 0 N17 @13:9
; CHECK-NEXT: linear X0 Y0 Z-80 A0 B0 C0 F149.999999{{[0-9]*}} N18 @14:5
; CHECK-NEXT: spindle_mode 0 1000 0 N19 @15:5
; CHECK-NEXT: spindle_speed 1000 N19 @15:5
; The summary's cycle time uses those feeds.
; RUN: %ncc run %s --machine=%S/Inputs/lathe0.toml | FileCheck %s --check-prefix=SUM
; SUM: moves: 9 (rapid 2, linear 6, arc 1)
; The example as printed (system B: G92 S1500) stops at its W and U words, which system B does not
; have; its G92 S and G96 lines are accepted.
; RUN: not %ncc compile %S/Inputs/13-t-g96-css.nc --machine=%S/Inputs/lathe-b.toml --emit=motion 2>&1 | FileCheck %s --check-prefix=EX13 --implicit-check-not=error:
; EX13: 13-t-g96-css.nc:9:5: error: W in G-code system B
; EX13: 13-t-g96-css.nc:10:14: error: W in G-code system B
; EX13: 13-t-g96-css.nc:11:9: error: U in G-code system B
