(The engines test runs this on --machine=%S/lathe0.toml)
G18 G98 G0 X60. Z5.
G70 P10 Q20
N10 G1 X20. F100.
N20 M98 P9001
M30
O9001
M30
