(The engines test runs this on --machine=%S/lathe0.toml)
G18 G99 S1000 G0 X60. Z5.
G71 U3. R0.5
G71 P10 Q20 U1. W0 F0.2
N10 G0 X20.
N20 G1 X40.
M30
