#!/usr/bin/env python3
"""Writes an ADEM CLData listing of N records (default 1,000,000) for the translation benchmark
(bench/cldata.sh, bench/README.md): a header, a tool load, spindle, coolant, then cycles of two
linear moves [181] and two half circles [183] at a feed [23] that changes every 1000 cycles, and
the end [4]. Every record is one the reader lowers (no skipped codes), so the count is the work.

usage: bench/gen_cldata.py OUT.cld [N]"""
import sys

out, n = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 1000000
head = [
    "0[1] PROGRAM/ 'BENCH';",
    "1[35] TOOL/ 1 1 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 5;",
    "1[24] SPINDLE/ 2 3000;",
    "1[26] COOLANT/ 1 1;",
    "1[25] RAPID/;",
    "1[181] LINE/ 0 0 5;",
    "1[23] FEED/ 1 500;",
    "1[181] LINE/ 0 0 -1;",
]
lines = list(head)
k = 0
while len(lines) < n - 1:
    y = (k % 1000) * 0.01
    cycle = [
        f"1[181] LINE/ 0 {y:.2f} -1;",
        f"1[181] LINE/ 10 {y:.2f} -1;",
        f"1[183] ARC/ 20 {y:.2f} -1 15 {y:.2f} -5 1;",  # clockwise half circle (negative radius)
        f"1[183] ARC/ 10 {y:.2f} -1 15 {y:.2f} 5 1;",   # and back counter-clockwise
    ]
    if k % 1000 == 999:
        cycle.append(f"1[23] FEED/ 1 {400 + (k // 1000) % 5 * 100};")
    lines.extend(cycle[: n - 1 - len(lines)])
    k += 1
lines.append("1[4] END/;")
with open(out, "w") as f:
    f.write("\n".join(lines) + "\n")
