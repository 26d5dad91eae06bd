G17 G90 G21 G94 F1000
G0 X0 Y0
G1 X10 ,C2
Y10 ,R3
X0
G91 Y-10 ,C1.41421356237
X10
G90 G18
G1 Z-10 ,R2
X20
G17
G1 X30 Y0 ,C1
X40
G1 X40 Y10 ,R2
Z5
X50
M30
%
; FEATURES: ISO-MOT-07
; ,C (chamfer: the length of the bevel, as the 808D manual's figure 2-9 labels it) and ,R
; (rounding radius) between two lines in the active plane (rounding also next to arcs, below): the first line is trimmed, the bevel
; or the tangent arc follows, the second line starts where it ends; G18 too. The controller does
; not insert one when the moves are collinear or a move leaves the plane (a warning says so).
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: move X=10 chamfer=2 loc(1:3:1)
; IR: move Y=10 round=3 loc(1:4:1)
; RUN: %ncc compile %s --emit=motion 2>%t.err | FileCheck %s
; RUN: FileCheck %s --check-prefix=WARN --input-file=%t.err
; 90 degrees, bevel 2: 2 / (2 sin 45) = 1.4142 of each line.
; CHECK: linear X8.585786437626904 Y0 Z0 {{.*}}@3:1
; CHECK-NEXT: linear X10 Y1.4142135623730951 Z0 {{.*}}@3:1
; CHECK-NEXT: linear X10 Y7 Z0 {{.*}}@4:1
; CHECK-NEXT: arc X7 Y10 Z0 A0 B0 C0 center(7, 7, 0) plane=xy turns=1 F1000 @4:1
; CHECK-NEXT: linear X0 Y10 Z0 {{.*}}@5:1
; CHECK-NEXT: linear X0 Y0.99999999999{{[0-9]*}} Z0 {{.*}}@6:
; CHECK-NEXT: linear X0.99999999999{{[0-9]*}} Y0 Z0 {{.*}}@6:
; CHECK-NEXT: linear X10 Y0 Z0 {{.*}}@7:1
; G18 (Z then X): a right turn seen from +Y runs clockwise.
; CHECK: linear X10 Y0 Z-8 {{.*}}@9:1
; CHECK-NEXT: arc X12 Y0 Z-10 A0 B0 C0 center(12, 0, -8) plane=zx turns=-1 F1000 @9:1
; CHECK-NEXT: linear X20 Y0 Z-10 {{.*}}@10:1
; Collinear: nothing to insert; leaving the plane: not inserted.
; CHECK: linear X30 Y0 Z-10 {{.*}}@12:1
; CHECK-NEXT: linear X40 Y0 Z-10 {{.*}}@13:1
; WARN: iso-mot-07-chamfer-rounding.nc:12:1: warning: chamfer not inserted: the two moves are collinear [corner-not-inserted]
; WARN: iso-mot-07-chamfer-rounding.nc:14:1: warning: rounding not inserted: a move leaves the plane [corner-not-inserted]
; Errors: too large for the moves, a rapid or an arc next to it, two in a block, ,A, a chamfer
; right after a coordinate change, a chamfer in a block without a move.
; RUN: printf 'G1 X10 Y0 F100 ,C30\nY10\nM30\n' > %t.big.nc
; RUN: not %ncc run %t.big.nc 2>&1 | FileCheck %s --check-prefix=BIG
; BIG: :2:1: error: the chamfer does not fit: it takes 21.2132 mm of each move (10.0000 and 10.0000 long) [corner-invalid]
; RUN: printf 'G1 X10 Y0 F100 ,C2\nG2 X20 Y0 R5\nM30\n' > %t.arc.nc
; RUN: not %ncc run %t.arc.nc 2>&1 | FileCheck %s --check-prefix=ARC
; ARC: :2:1: error: a chamfer next to an arc is not supported yet [unsupported-code]
; Rounding next to arcs: the fillet's centre is where both elements, offset by its radius toward
; the inside of the corner, meet. Line into a G2 over the top of (20,0) R10: centre (8.168, 2),
; touching the line at X8.168 and the arc at (10.140, 1.667); a G2 into a line; G3 into G3.
; RUN: printf 'G17 G90 G21 G94 F1000\nG0 X0 Y0\nG1 X10 ,R2\nG2 X30 Y0 I10 J0 ,R2\nG1 X40 Y0\nG0 X0 Y0\nG3 X10 Y10 I10 J0 ,R1\nG3 X20 Y0 I10 J0\nM30\n' > %t.ra.nc
; RUN: %ncc compile %t.ra.nc --emit=motion | FileCheck %s --check-prefix=RA
; RA: linear X8.16784043380076{{[0-9]*}} Y0 Z0 {{.*}}@3:1
; RA-NEXT: arc X10.13986702816730{{[0-9]*}} Y1.666666666666666{{[0-9]*}} Z0 A0 B0 C0 center(8.16784043380076{{[0-9]*}}, 2, 0) plane=xy turns=1 F1000 @3:1
; RA-NEXT: arc X29.8601329718326{{[0-9]*}} Y1.66666666666666{{[0-9]*}} Z0 A0 B0 C0 center(20, 0, 0) plane=xy turns=-1 F1000 @4:1
; RA-NEXT: arc X31.8321595661992{{[0-9]*}} Y0 Z0 A0 B0 C0 center(31.8321595661992{{[0-9]*}}, 2, 0) plane=xy turns=1 F1000 @4:1
; RA-NEXT: linear X40 Y0 Z0 {{.*}}@5:1
; RA: arc X11.18110673666010{{[0-9]*}} Y9.93000437445100{{[0-9]*}} Z0 A0 B0 C0 center(10, 0, 0) plane=xy turns=1 F1000 @7:1
; RA-NEXT: arc X10.06999562554899{{[0-9]*}} Y8.81889326333989{{[0-9]*}} Z0 A0 B0 C0 center(11.06299606299409{{[0-9]*}}, 8.93700393700590{{[0-9]*}}, 0) plane=xy turns=1 F1000 @7:1
; RA-NEXT: arc X20 Y0 Z0 A0 B0 C0 center(20, 10, 0) plane=xy turns=1 F1000 @8:1
; RUN: printf 'G0 X9\nG1 X10 Y0 F100 ,R5\nG3 X12 Y0 I1 J0\nM30\n' > %t.rbig.nc
; RUN: not %ncc run %t.rbig.nc 2>&1 | FileCheck %s --check-prefix=RBIG
; RBIG: :3:1: error: the rounding does not fit: it would reach past the end of a move [corner-invalid]
; RUN: printf 'G92 X0 Y0\nG1 X10 F100 ,C1\nY10\nM30\n' > %t.g92.nc
; RUN: not %ncc run %t.g92.nc 2>&1 | FileCheck %s --check-prefix=G92
; G92: :2:1: error: a chamfer or rounding must not follow a coordinate-system change or reference-point return [corner-invalid]
; RUN: printf 'G1 X10 F100 ,C1 ,R2\nM1 ,C1\nG1 X1 ,A30\n' > %t.syn.nc
; RUN: not %ncc compile %t.syn.nc --emit=ir 2>&1 | FileCheck %s --check-prefix=SYN
; SYN: :1:17: error: one chamfer or rounding per block [duplicate-word]
; SYN: :2:4: error: a chamfer ,C or rounding ,R needs a G1, G2 or G3 move in its block [unused-word]
; SYN: :3:7: error: ,A (a line given by its angle) is not supported yet [unsupported-code]
; RUN: printf 'G1 X10 F100 ,C1\nM30\n' > %t.end.nc
; RUN: %ncc run %t.end.nc 2>&1 | FileCheck %s --check-prefix=END
; END: :1:1: warning: chamfer not inserted: no move follows [corner-not-inserted]
