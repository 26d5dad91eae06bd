(G71 type II: the first contour block names X and Z; N40-N45 a pocket down to diameter 30)
G18 G99 S1000 G0 X62. Z2.
G71 U4. R1.
G71 P10 Q50 U0.4 W0.1 F0.2
N10 G0 X20. Z1.
N20 G1 Z-10.
N30 X40. Z-20.
N35 Z-30.
N40 X30. Z-40.
N42 Z-50.
N45 X50. Z-60.
N50 Z-70.
G70 P10 Q50
M30
