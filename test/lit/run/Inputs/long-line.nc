(one 200 mm G1 at F6000 = 100 mm/s from rest to rest)
G21 G90 G17 G94
G1 X200 F6000
M30
