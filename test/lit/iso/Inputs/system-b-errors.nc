(The engines test runs this on --machine=%S/lathe-b.toml)
G1 U2. F1.
G50 X10.
G12.1
M30
