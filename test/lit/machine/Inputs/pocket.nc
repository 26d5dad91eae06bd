(A square with one rounded corner, written with decimal points so IS-B machines read it in mm)
G21 G17 G90 G54
T1 M6
G43 H1
S3000 M3
G0 X0. Y0. Z5.
G1 Z-2. F300.
G1 X40. F800.
G1 Y30.
G3 X30. Y40. R10.
G1 X0.
G1 Y0.
G0 Z5.
M5
M30
