(NC-200: records the target cannot write exactly)
G21 G90 G17 G94 G54
S1000 M3
G0 X10. Y10. Z-1.
G4 X1.5
G1 X20. F100.
G2 X20. Y10. Z-3. I5. J0
G93
G1 X30. F2.
M30
