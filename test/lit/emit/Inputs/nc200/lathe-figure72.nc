(seed 003 figure 7.2 as an ISO lathe program: the convex corner from the face to the cylinder is G3)
G98
G0 X100. Z30.
X0 Z10.
G1 Z0 F100.
X20.
G3 X60. Z-20. R20.
G1 Z-50.
G0 X100. Z30.
M30
