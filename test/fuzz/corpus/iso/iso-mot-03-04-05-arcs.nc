G2 X20 Y5 I5 J0
G3 X10 Y5 R5
G2 X0 Y0 R-5.
G17 G03 X0 Y100. R100 Z90. F10
G18 G2 X60. Z-46.6 I20. K-19.596
G19 G91.1 G2 Y1 Z1 J0.5 K0.5
G90.1
G2 I10
G3 X1 Y1 I1 P2
%
; FEATURES: ISO-MOT-03 ISO-MOT-04 ISO-MOT-05
; Arcs with I J K centre offsets, with R (negative = more than 180 deg), helical (third axis),
; full circle (I only), arc-centre distance modes G90.1/G91.1, LinuxCNC turns P.
; RUN: %ncc compile %s --emit=ir | FileCheck %s
; CHECK: mode motion=arc_cw loc(1:1:1)
; CHECK-NEXT: move X=20 Y=5 I=5 J=0 loc(1:1:1)
; CHECK: mode motion=arc_ccw loc(1:2:1)
; CHECK-NEXT: move X=10 Y=5 R=5 loc(1:2:1)
; CHECK: move X=0 Y=0 R=-5.0 loc(1:3:1)
; CHECK: feed value=10
; CHECK-NEXT: mode plane=xy
; CHECK-NEXT: mode motion=arc_ccw
; CHECK-NEXT: move X=0 Y=100.0 Z=90.0 R=100
; CHECK: mode plane=zx
; CHECK-NEXT: mode motion=arc_cw
; CHECK-NEXT: move X=60.0 Z=-46.6 I=20.0 K=-19.596
; CHECK: mode plane=yz
; CHECK-NEXT: mode arc_distance=arc_incremental
; CHECK-NEXT: mode motion=arc_cw
; CHECK-NEXT: move Y=1 Z=1 J=0.5 K=0.5
; CHECK: mode arc_distance=arc_absolute loc(1:7:1)
; CHECK: move I=10 loc(1:8:1)
; CHECK: move X=1 Y=1 I=1 P=2 loc(1:9:1)
