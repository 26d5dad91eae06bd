G17 G90 G21 G94 F1000
G0 X0 Y0
G52 X100 Y50
G0 X10 Y0
G68 X0 Y0 R90
G1 X10 Y0
G3 X0 Y10 R10
G69
G52 X0 Y0
G0 X20 Y10
G68 R45
G91 G1 X10
G90
G69
G0 X0 Y0 Z0
G68 X0 Y0 Z0 I1 J0 K0 R90
G1 X10 Y10 Z0
G68 X0 Y0 Z0 I0 J0 K1 R90
G1 X10 Y0 Z0
G69
G1 X10 Y0 Z0
G18
G68 X0 Z0 R90
G1 X0 Y0 Z10
G69
M30
%
; FEATURES: ISO-CS-06 ISO-CS-11 ISO-CS-12
; G52 shifts (machine = program + local); G68 rotates about the given centre, in the active
; plane (G17: about Z, G18: about Y, counter-clockwise seen from the axis tip); without X Y the
; centre is the current position; a 3-D G68 turns about I J K; a second G68 stacks in the rotated
; system (808D manual 2.4.1.6, 2.4.1.9-10). Arcs stay arcs in the rotated frame.
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: frame slot=local action=set X=100 Y=50 loc(1:3:1)
; IR: frame slot=rotation action=set form=plane X=0 Y=0 R=90 loc(1:5:1)
; IR: frame slot=rotation action=cancel loc(1:8:1)
; IR: frame slot=rotation action=set form=axis X=0 Y=0 Z=0 I=1 J=0 K=0 R=90 loc(1:16:1)
; RUN: %ncc compile %s --emit=motion | FileCheck %s
; Each change of the program -> machine transform is a frame_change record with its matrix.
; CHECK: frame_change "G52" m00=1 m01=0 m02=0 m03=100 m10=0 m11=1 m12=0 m13=50 m20=0 m21=0 m22=1 m23=0 @3:1
; CHECK-NEXT: rapid X110 Y50 Z0 {{.*}}@4:1
; CHECK-NEXT: frame_change "G68" m00=0 m01=-1 m02=0 m03=100 m10=1 m11=0 m12=0 m13=50 {{.*}}@5:1
; CHECK-NEXT: linear X100 Y60 Z0 {{.*}}@6:1
; CHECK-NEXT: arc X90 Y50 Z0 A0 B0 C0 center(100, 50, 0) plane=xy turns=1 {{.*}}@7:1
; CHECK-NEXT: frame_change "G69" m00=1 m01=0 m02=0 m03=100 {{.*}}@8:1
; CHECK-NEXT: frame_change "G52" m00=1 m01=0 m02=0 m03=0 {{.*}}@9:1
; CHECK-NEXT: rapid X20 Y10 Z0 {{.*}}@10:1
; 45 degrees about the current position (20, 10): X+10 incremental goes along the diagonal.
; CHECK-NEXT: frame_change "G68" m00=0.70710678118654{{[0-9]*}} m01=-0.70710678118654{{[0-9]*}} {{.*}}@11:1
; CHECK-NEXT: linear X27.07106781186{{[0-9]*}} Y17.07106781186{{[0-9]*}} Z0 {{.*}}@12:
; CHECK-NEXT: frame_change "G69"
; CHECK-NEXT: rapid X0 Y0 Z0 {{.*}}@15:1
; About X by 90: Y goes to Z.
; CHECK-NEXT: frame_change "G68" m00=1 m01=0 m02=0 m03=0 m10=0 m11=0 m12=-1 m13=0 m20=0 m21=1 m22=0 m23=0 @16:1
; CHECK-NEXT: linear X10 Y0 Z10 {{.*}}@17:1
; Stacked: about Z of the rotated system, X turns to its Y, which the first rotation turned to Z.
; CHECK-NEXT: frame_change "G68" m00=0 m01=-1 m02=0 m03=0 m10=0 m11=0 m12=-1 m13=0 m20=1 m21=0 m22=0 m23=0 @18:1
; CHECK-NEXT: linear X0 Y0 Z10 {{.*}}@19:1
; CHECK-NEXT: frame_change "G69"
; CHECK-NEXT: linear X10 Y0 Z0 {{.*}}@21:1
; G18: about Y, Z turns toward X.
; CHECK-NEXT: plane 1
; CHECK-NEXT: frame_change "G68" m00=0 m01=0 m02=1 {{.*}} m20=-1 m21=0 m22=0 m23=0 @23:1
; CHECK-NEXT: linear X10 Y0 Z0 {{.*}}@24:1
; An arc under a 3-D rotation: about X by 90 the G17 arc lies in machine ZX and turns the other
; way (the mapped normal is -Y); at 45 degrees its plane is tilted and the record says its normal.
; RUN: printf 'G17 G90 G21 G94 F1000\nG0 X10 Y0 Z0\nG68 X0 Y0 Z0 I1 J0 K0 R90\nG3 X0 Y10 R10\nG69\nG0 X10 Y0 Z0\nG68 X0 Y0 Z0 I1 J0 K0 R45\nG3 X0 Y10 R10\nG69\nM30\n' > %t.nc
; RUN: %ncc compile %t.nc --emit=motion | FileCheck %s --check-prefix=TILT
; TILT: arc X0 Y0 Z10 A0 B0 C0 center({{[-0-9.e]+}}, 0, {{[-0-9.e]+}}) plane=zx turns=-1 F1000 @4:1
; TILT: arc X0 Y7.07106781186547{{[0-9]*}} Z7.07106781186547{{[0-9]*}} {{.*}} plane=xy normal=(0, -0.70710678118654{{[0-9]*}}, 0.70710678118654{{[0-9]*}}) turns=1 F1000 @8:1
; The canonical trace cannot say a tilted arc: an error, no file.
; RUN: not %ncc run %t.nc --trace=canon -o %t.canon 2>&1 | FileCheck %s --check-prefix=CANON
; CANON: error: {{.*}}tilted plane
; A drilling cycle under a rotation about its drilling axis: the hole is rotated, the levels not.
; RUN: printf 'G17 G90 G21 G94 F100\nG0 X0 Y0 Z10\nG68 X0 Y0 R90\nG81 X10 Y0 Z-2 R1\nG80\nG69\nM30\n' > %t.cyc.nc
; RUN: %ncc compile %t.cyc.nc --emit=motion | FileCheck %s --check-prefix=CYC
; CYC: cycle_begin "iso.G81" X=10 Y=0 Z=-2 R=1 L=1 @4:1
; CYC: rapid X0 Y10 Z10 {{.*}}exact_stop @4:1
; CYC-NEXT: rapid X0 Y10 Z1
; CYC-NEXT: linear X0 Y10 Z-2
; CYC-NEXT: rapid X0 Y10 Z10
