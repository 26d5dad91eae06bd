(an arc whose ends are inside the travel and whose bulge is not: X reaches 610 > 600)
G21 G90 G17 G94 G54
G0 X800 Y0 Z50
G3 X800 Y120 I0 J60 F300
M30
