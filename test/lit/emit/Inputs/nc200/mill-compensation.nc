(NC-200 G41/G42 exit rule: the compensated contour comes out as the offset path, so no G41/G40 is)
(written and the origin change and tool change after it are plain blocks)
G21 G90 G17 G94
T1 M6
G54 G0 X-10. Y-10. Z5.
S1000 M3
G1 Z-1. F200.
G41 D1 G1 X0 Y0
X30.
Y20.
G40 G1 X40. Y30.
G55 G0 Z5.
T3 M6
G0 X0 Y0
M30
