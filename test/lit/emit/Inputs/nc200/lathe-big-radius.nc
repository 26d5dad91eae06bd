(NC-200 diameter lathe: an arc whose R form misses its centre after rounding)
G98
G0 X20. Z5.
G1 Z0 F100.
G2 X20.0213 Z-10.0007 R9000.
M30
