(The engines test runs this on --machine=%S/lathe0.toml)
G18 G98
G10 P100 X20.
M30
