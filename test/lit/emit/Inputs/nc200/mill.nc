(NC-200 mill: origins, tool length in the positions, arcs with absolute centres, a full circle, a Z/X arc)
G21 G90 G17 G94
T1 M6
G54 G0 X0 Y0 Z50.
G43 H1 Z5.
S1500 M3 M8
G1 Z-2. F300.
X20. Y10.
G3 X30. Y20. I0 J10.
G2 X50. Y20. R10.
G2 X50. Y20. I-10. J0
G1 X60.
G2 X40. Y20. I-10. J0
G1 Y0
G18 G2 X60. Z-2. I10. K0
G17
G55 G0 X5. Y5.
G1 X30. F300.
G52 X10. Y-5.
G0 X0 Y0
G52 X0 Y0
G49 G0 Z50.
M5 M9
M30
