G0 X0 Y0 (Überfahrt, фреза) G1 X1 F100 G9999
M2
