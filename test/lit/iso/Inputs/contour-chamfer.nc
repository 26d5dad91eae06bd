(The engines test runs this on --machine=%S/lathe0.toml)
G18 G99 S1000 G0 X60. Z5.
G70 P10 Q20
N10 G1 X20. F0.1
N20 Z-10. ,C1.
M30
