(arcs with irrational coordinates, inch units, R and IJK, G18/G19)
G20 G90 G17 G94 G54
G0 X1. Y1. Z-0.1
#1 = 1
WHILE [#1 LT 200] DO1
  #2 = 1 + 0.7 * SIN[#1 * 13.7]
  #3 = #1 * 37.3
  #4 = 5 + #2 * COS[#3]
  #5 = 5 + #2 * SIN[#3]
  G1 X[5 + #2] Y5. F[10 + #1 / 7]
  G3 X#4 Y#5 I[-#2] J0 Z[-0.1 - #1 / 3000]
  G2 X[5 + #2] Y5. R[#2 * [1 + #1 / 1000]]
  #1 = #1 + 1
END1
G1 X6. Y5. Z-0.2
G18 G2 X7. I0.5 K0
G19 G3 Y6. J0.5 K0
G17
M30
