(A lathe pass in the ZX plane; X is a radius until the front end reads diameter_programming)
G18 G21 G90 G54
T1 M6
G0 X25. Z5.
G1 Z-30. F200.
G1 X30.
G0 Z5.
M30
