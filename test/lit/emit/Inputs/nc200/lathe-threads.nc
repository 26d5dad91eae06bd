(NC-200 threads: three starts by spindle angle, face, taper, cylinder then taper, variable pitch)
G0 X40. Z5.
S300 M3
(three-start thread: the same start point, Q the angle)
X20.
G32 Z-30. F6. Q0
G0 X30.
Z5.
X20.
G32 Z-30. Q120.
G0 X30.
Z5.
X20.
G32 Z-30. Q240.
G0 X30.
(face thread, pitch along X)
Z-32.
G32 X10. F5.
G0 Z5.
(taper thread, pitch along Z)
X20. Z0
G32 X30. Z-50. F5.
G0 X40.
Z5.
(cylinder then taper: one thread)
X20. Z0
G32 Z-20. F2.
X26. Z-30.
G0 X40.
Z5.
(variable pitch, growing)
X20. Z0
G34 Z-40. F2. K0.05
G0 X40.
Z5.
M5
M30
