(The engines test runs this on --machine=%S/lathe0.toml)
G18 G98 G0 X50. Z2.
G90 X20. F100.
M30
