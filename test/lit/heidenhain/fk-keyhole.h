; FEATURES: HEI-MOT-09
; The manual's FK contour (seed002a 08, L10684-L10704, blocks 16-26 as written there): a circle
; R30 about X30 Y30, a channel 20 wide at 60 degrees (lines AN+60 and AN-120 at D10 from the
; centre) and a circle R20 about the polar centre CCPR+55 CCPA+60 from FPOL X30 Y30, clockwise
; all round: a keyhole pocket. Each FSELECT picks ncc's solution of that number (lines with the
; point PD on their left first; where a line meets a circle, the point farther along the line
; first); the chosen ones give the keyhole, hand-computed below (21.3397 = 30 - 10 cos 30).
; RUN: %ncc run %s --trace=canon 2>&1 | FileCheck %s
; CHECK: N16 {{ *}}STRAIGHT_FEED(0.0000, 30.0000,
; The big circle clockwise from X0 Y30 to where the channel's left line (through X21.3397 Y35)
; leaves it: t = sqrt(30^2 - 10^2) = 28.2843 along 60 degrees.
; CHECK-NEXT: N17 {{ *}}ARC_FEED(35.4819, 59.4949, 30.0000, 30.0000, -1,
; Up the channel to where the line enters the R20 circle (centre X57.5 Y77.6314): t = 55 - 17.3205.
; CHECK-NEXT: N18 {{ *}}STRAIGHT_FEED(40.1795, 67.6314,
; Round the end circle to the right line (through X38.6603 Y25), t = 37.6795 on it.
; CHECK-NEXT: N21 {{ *}}ARC_FEED(57.5000, 57.6314, 57.5000, 77.6314, -1,
; Down the channel to the big circle (t = 28.2843), then round it back to X0 Y30.
; CHECK-NEXT: N23 {{ *}}STRAIGHT_FEED(52.8024, 49.4949,
; CHECK-NEXT: N25 {{ *}}ARC_FEED(0.0000, 30.0000, 30.0000, 30.0000, -1,
; CHECK-NEXT: N27 {{ *}}STRAIGHT_TRAVERSE(0.0000, 30.0000,
0 BEGIN PGM C20 MM
3 TOOL CALL 1 Z S2500
4 L Z+5 R0 FMAX
15 L Z-5 F500
16 L X+0 Y+30
17 FC DR- R30 CCX+30 CCY+30
18 FL AN+60 PDX+30 PDY+30 D10
19 FSELECT 3
20 FPOL X+30 Y+30
21 FC DR- R20 CCPR+55 CCPA+60
22 FSELECT 2
23 FL AN-120 PDX+30 PDY+30 D10
24 FSELECT 3
25 FC X+0 DR- R30 CCX+30 CCY+30
26 FSELECT 2
27 L Z+5 FMAX
28 END PGM C20 MM
