(feed modes: inverse time lines and arcs, per revolution, back to per minute)
G21 G90 G17 G94 G54
S1000 M3
G0 X10. Y10. Z-1.
G93
G1 X20. Y15. F2.
G3 X25. Y20. R5. F4.
G2 X25. Y20. Z-3. I5. J0 F0.5
G95
G1 X40. F0.125
G94
G1 Y40. F800.
M30
