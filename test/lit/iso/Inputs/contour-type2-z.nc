(Type II along Z must still run one way: N30 turns back along Z)
G18 G99 S1000 G0 X60. Z5.
G71 U3. R0.5
G71 P10 Q40 U1. W0.5 F0.2
N10 G0 X20. Z2.
N20 G1 Z-10.
N30 X30. Z-5.
N40 Z-20.
M30
