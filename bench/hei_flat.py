#!/usr/bin/env python3
"""Writes the same N random moves as a Klartext program (OUT.h) and as ISO G1 blocks (OUT.ngc),
for timing the Heidenhain front end against the ISO one (bench/README.md).

usage: bench/hei_flat.py OUT [N]"""
import random
import sys

out, n = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 100000
random.seed(1)
h = ["0 BEGIN PGM BIG MM", "1 TOOL CALL 3 Z S1000", "2 L X+0 Y+0 Z+0 R0 FMAX", "3 L Z-1 F500"]
g = ["G21 G17 G90", "T3 M6", "S1000", "G0 X0 Y0 Z0", "G1 Z-1 F500"]
for i in range(n):
    x, y = round(random.uniform(0, 100), 3), round(random.uniform(0, 100), 3)
    h.append(f"{i + 4} L X{x:+} Y{y:+}")
    g.append(f"G1 X{x} Y{y}")
h.append(f"{n + 4} END PGM BIG MM")
g.append("M30")
open(out + ".h", "w").write("\n".join(h) + "\n")
open(out + ".ngc", "w").write("\n".join(g) + "\n")
