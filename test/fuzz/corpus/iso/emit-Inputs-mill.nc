%
O0100
(emit round trip: lines, arcs, helices, planes, dwell)
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
G1 X70.
G2 Z-7. I0 J-10.
G3 Z-9. I0 J-10. P2
G18 G2 X80. Z-9. I5. K0
G17
G4 P500
G4 X1.5
M5
M9
(MSG, done)
G0 Z-2.
M30
%
