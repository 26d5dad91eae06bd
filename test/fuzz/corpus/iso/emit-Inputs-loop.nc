(drilling pattern in a Macro B loop, then a G81 cycle)
G21 G90 G17 G94 G54
T3 M6
S2000 M3
G0 X20. Y20. Z-2.
#1 = 0
WHILE [#1 LT 3] DO1
  G1 X[20 + #1 * 15] F300.
  G1 Z-10.
  G0 Z-2.
  #1 = #1 + 1
END1
G98 G81 X100. Y50. Z-12. R-2. F150.
X120.
G80
M30
