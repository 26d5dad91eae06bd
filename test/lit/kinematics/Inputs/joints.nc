(Rotary axes as plain joints: A and C move, X Y Z stay as programmed)
G21 G17 G90 G54
G0 X10 Y20 Z5
G0 A30 C90
G1 X20 F500
M30
