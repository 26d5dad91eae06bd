%
O0200
(Klartext emitter: lines, arcs, helices, tools, M functions, dwell)
G21
G90 G17 G94 G54
T1 M6
S1200 M3
M8
G0 X10. Y10. Z-2.
G1 Z-5. F200.
X40.
G3 X50. Y20. I0 J10.
G2 X60. Y30. R10.
G1 X70. F300.
G2 I0 J-10.
G2 Z-7. I0 J-10.
G3 X80. Y20. Z-9. I0 J-10.
G3 Z-11. I-10. J0 P2
G4 X1.5
M5
M9
(MSG, done)
M1
G0 Z-2.
T2 M6
S800 M4
M7
G0 X0 Y0
G1 X5. F100.
M0
M30
%
