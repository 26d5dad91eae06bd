(NC-200 dwell set by the machine file)
G21 G90 G17 G94 G54
G0 X10. Y10.
G4 X1.5
G1 X20.5 F100.
M30
