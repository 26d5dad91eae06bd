(one program that trips every lint rule that lets it run)
G21 G90 G17
G1 X10.
F100
G2 X20. Y5. I5. J0
G41 G1 X30.
G40
#1 = 1
IF [#1 EQ 1] GOTO 20
N10 G0 X0
N20 G0 Y0
M30
G0 X5.
