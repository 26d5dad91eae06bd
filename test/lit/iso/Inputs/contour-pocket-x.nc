(G72 type II: facing layers along X; the first contour block names Z and X; N30-N40 a pocket in Z)
G18 G99 S1000 G0 X82. Z2.
G72 W3. R0.5
G72 P10 Q50 U0.2 W0.2 F0.2
N10 G0 Z-20. X80.
N20 G1 X60.
N30 X50. Z-10.
N35 X40.
N40 X30. Z-15.
N50 X10. Z-5.
M30
