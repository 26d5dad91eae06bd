(The engines test runs this on --machine=%S/lathe-b.toml)
G1 U2. F1.
G50 X10.
G34 X10. Z-5. F1. K0.1
M30
