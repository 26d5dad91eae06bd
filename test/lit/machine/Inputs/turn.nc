(A lathe pass in the ZX plane: X in diameters, T0101 applies tool 1's X and Z offsets)
G18 G21 G54 G98
T0101
G0 X50. Z5.
G1 Z-30. F200.
G1 X60.
G0 Z5.
M30
