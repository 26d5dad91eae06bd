G17 G90 G21 G94 F1000
G0 X10 Y0
G51 X0 Y0 P2000
G1 X20 Y0
G3 X0 Y20 R20
G50
G0 X0 Y0
G51.1 X10
G1 X20 Y5
G2 X25 Y10 I0 J5
G50.1 X0
G0 X0 Y0
G51.1 Y0
T1 M6
G41 D1 G1 X10 Y10
G1 X20
G40 G1 X30 Y30
G50.1
M30
%
; FEATURES: ISO-CS-13 ISO-CS-15
; G51 P scales about the given centre (P2000 = 2 with weighting 0.001): a G3 R20 arc becomes an
; R40 arc. G51.1 X10 mirrors X about X10: a G2 turns the other way on the machine (808D table
; 2-12), and G41 cuts on the other side (the path runs along machine Y-10 in +X and the tool
; is below it, on its right, where G42 would put it on the unmirrored path).
; RUN: %ncc compile %s --emit=ir | FileCheck %s --check-prefix=IR
; IR: frame slot=scale action=set X=0 Y=0 I=2.0 J=2.0 K=2.0 loc(1:3:1)
; IR: frame slot=scale action=cancel loc(1:6:1)
; IR: frame slot=mirror action=set X=10 loc(1:8:1)
; IR: frame slot=mirror action=cancel X=0 loc(1:11:1)
; RUN: %ncc compile %s --emit=motion | FileCheck %s
; CHECK: frame_change "G51" m00=2 m01=0 m02=0 m03=0 m10=0 m11=2 m12=0 m13=0 m20=0 m21=0 m22=2 m23=0 @3:1
; CHECK-NEXT: linear X40 Y0 Z0 {{.*}}@4:1
; CHECK-NEXT: arc X0 Y40 Z0 A0 B0 C0 center({{[0-9.e-]+}}, {{[0-9.e-]+}}, 0) plane=xy turns=1 {{.*}}@5:1
; CHECK-NEXT: frame_change "G50"
; CHECK-NEXT: rapid X0 Y0 Z0 {{.*}}@7:1
; CHECK-NEXT: frame_change "G51.1" m00=-1 m01=0 m02=0 m03=20 {{.*}}@8:1
; CHECK-NEXT: linear X0 Y5 Z0 {{.*}}@9:1
; CHECK-NEXT: arc X-5 Y10 Z0 A0 B0 C0 center(0, 10, 0) plane=xy turns=1 {{.*}}@10:1
; CHECK-NEXT: frame_change "G50.1"
; CHECK-NEXT: rapid X0 Y0 Z0 {{.*}}@12:1
; CHECK: arc X10 Y-15 Z0 A0 B0 C0 center(10, -10, 0) {{.*}}@16:1
; CHECK-NEXT: linear X20 Y-15 Z0 {{.*}}@16:1
