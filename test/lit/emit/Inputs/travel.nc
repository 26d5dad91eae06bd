(moves outside the machine's travel: X 650 > 600 twice)
G21 G90 G17 G94 G54
G0 X0 Y0 Z50
G1 X400 F300
G1 X900
X950
M30
