import sys
L = ['G21 G90 G17 G94 F1000']
rows = ['G1 X{a} Y{b} (cut {i})', '#1 = {c}', 'G1 X1 Y2', 'G2 X1 Y2 I-1 J0', 'G91 G0 X0.5 Z0.1',
        'G90 G20 X0.1 Y0.2', 'G21 G3 X1 Y1 R5', 'M8', 'N{i} G1 X2.5 Y-1 F500', 'S1000 M3 G1 X3',
        'G18 G1 X1 Z-1', 'G17 G64 G0 X0 Y0', 'G1 Z-#1']
for i in range(9000):
    L.append(rows[i % len(rows)].format(a=i % 10, b=i % 7, c=i % 5, i=i))
L.append('M2')
open(sys.argv[1], 'w').write(chr(10).join(L) + chr(10))
