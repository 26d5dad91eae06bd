G18 G21 G54
T0101
G0 X40. U2.
G41 D1 X20.
G31 F1.
G43 H1
G91 X1.
T#1
G83 Z1.
G87 X1.
G96
G10 P1 X1. Q3
G10 P1 Z1. W2.
G50 S0
M30
%
; FEATURES: ISO-MOT-12
; Lathe mode errors: X with U, D with tool nose radius compensation, the turning codes ncc does not do
; (G31 without an axis word, the C-axis drilling cycles G83/G87), G96 without S, a zero G50 S limit, milling codes that are not turning codes, a computed T.
; RUN: not %ncc compile %s --machine=%srcroot/examples/machines/lathe.toml --emit=motion 2>&1 | FileCheck %s --implicit-check-not=error:
; CHECK: 3:9: error: X and U in one block (U is the incremental X) [duplicate-word]
; CHECK: 4:5: error: a lathe takes the tool nose radius from the offset of its T word (T0101), not from D [unknown-code]
; CHECK: 5:1: error: G31 needs an axis word [missing-word]
; CHECK: 6:1: error: G43 is not a turning G code (808D G-code system A) [unknown-code]
; CHECK: 7:1: error: G91 is not a turning G code (808D G-code system A) [unknown-code]
; CHECK: 8:1: error: a lathe T word is a constant tool and offset number T<tt><oo> (T0101) [bad-number]
; CHECK: 9:1: error: G83 (face deep-hole drilling cycle (C axis)) is not supported [unsupported-code]
; CHECK: 10:1: error: G87 (side deep-hole drilling cycle (C axis)) is not supported [unsupported-code]
; CHECK: 11:1: error: G96 needs S (the surface speed, m/min or ft/min) [missing-word]
; CHECK: 12:12: error: G10 Q is not supported: the 808D manual's table 1-22 calls it the cutting-edge length, Fanuc the imaginary tool tip; set the edge's tip in the machine file [unsupported-code]
; CHECK: 13:12: error: G10: Z and W in one block (W adds to the offset Z sets) [duplicate-word]
; CHECK: 14:5: error: G50 S (the spindle speed limit) must be greater than 0 [bad-speed]
