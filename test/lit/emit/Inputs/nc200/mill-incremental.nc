(NC-200 G91 after an origin change, seed 003 figure 18.1 in ISO: the output is absolute, so the)
(first incremental block after the change means the same on every software version)
G21 G17 G94
G54 G0 G90 X0 Y0
G55
G0 G91 X10. Y15.
G1 X30. Y15. F100.
G90 G0 X10. Y15.
G1 G91 X30. Y15.
G90
M30
