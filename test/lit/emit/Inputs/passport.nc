%
O0200
(passport rules: rapid legs, long lines, arcs across quadrants)
G21
G90 G17 G94 G54
T1 M6
S1000 M3
G0 X0 Y0 Z10.
G0 X100. Y50. Z2.
G1 Z-1. F300.
X160.
G2 X170. Y40. I0 J-10.
G3 X150. I-10. J0
G0 X0 Y0 Z20.
M30
%
