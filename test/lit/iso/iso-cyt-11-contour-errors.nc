G18 G0 X60. Z5.
G71 U3. R0.5
G71 P10 Q30 U1. W0.5 F0.2
N10 G0 X20.
N20 G28 X100.
N25 G20
N30 G1 Z-10. F0.1
G70 P10
G70 P10 Q99
G71 P30 Q10
G71 G1 P10 Q30
G72 W5.
N40 G73 U1. W1. R2
G70 P40 Q40
G70 P50 Q50
N50 M2
M30
%
; FEATURES: ISO-CYT-11
; What the 808D forbids in the contour blocks of G70-G73 (one-shot G codes but G04, group 06,
; other cycles), and malformed cycle blocks, are located errors.
; RUN: not %ncc compile %s --machine=%S/Inputs/lathe0.toml --emit=ir 2>&1 | FileCheck %s --implicit-check-not=error:
; Lowering errors come first, then the checks of the contour ranges.
; CHECK: 8:1: error: G70 needs P and Q (the first and last contour block) [missing-word]
; CHECK: 11:5: error: G71 must not share its block with G1 [modal-group-conflict]
; CHECK: 12:1: error: G72 WR needs R (the cycle data block) [missing-word]
; CHECK: 5:5: error: a reference point return (G28/G30) is not allowed in the contour blocks of G70-G73 [contour-invalid]
; CHECK: 6:5: error: G20/G21 is not allowed in the contour blocks of G70-G73 [contour-invalid]
; CHECK: 9:1: error: there is no block N99 in this program (outside control structures) [missing-block]
; CHECK: 10:1: error: the contour block N30 comes after N10 [contour-invalid]
; CHECK: 13:5: error: a contour cycle (G70-G73) is not allowed in the contour blocks of G70-G73 [contour-invalid]
; CHECK: 16:5: error: a program end (M2/M30) is not allowed in the contour blocks of G70-G73 [contour-invalid]
