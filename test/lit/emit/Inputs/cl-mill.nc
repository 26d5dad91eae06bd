%
O0300
(CL writers: lines, arcs both ways, a helix, a ZX arc, tools, spindle, coolant, dwell, stops)
G21
G90 G17 G94 G54
T1 M6
G43 H1
S1200 M3
M8
G0 X10. Y10. Z5.
G1 Z-5. F200.
X40.
G3 X50. Y20. I0 J10.
G2 X60. Y30. R10.
G2 X70. Y20. Z-7. I0 J-10.
G1 X70. Y20. Z-5. F150.
G18 G2 X80. Z-5. I5. K0
G17
G4 X1.5
M5
M9
M1
G0 Z20.
T2 M6
G43 H2
S800 M4
M7
G0 X0 Y0
G95 G1 X5. F0.1
G94 F100.
G1 Y5.
M0
M30
%
