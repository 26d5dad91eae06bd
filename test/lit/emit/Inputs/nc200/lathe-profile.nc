(NC-200 lathe profile: seed 003 figure 7.2 written in ISO; arcs by R, the half circle in two 90 degree pieces)
G98
T0101
G0 X100. Z30.
S800 M3
X0 Z10.
G1 Z0 F100.
X20.
G2 X60. Z-20. R20.
G1 Z-50.
G3 X80. Z-60. R10.
G1 X90.
Z-70.
G2 Z-90. R10.
G0 X100. Z30.
M5
M30
