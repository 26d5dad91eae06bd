(The engines test runs this on --machine=%S/lathe-b.toml)
G1 U2. F1.
G50 X10.
G31 X10. F1.
M30
