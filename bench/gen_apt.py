#!/usr/bin/env python3
"""Writes an APT CL file of N records (default 1,000,000) for the translation benchmark and the
streaming test (bench/cldata.sh --apt, test/lit/apt/stream.test): a header, a tool load, spindle,
coolant, then cycles of two GOTO moves and two half circles (CIRCLE and the GOTO that ends it)
at a feed that changes every 1000 cycles, then END and FINI. Every record is one the reader
lowers, so the count is the work.

usage: bench/gen_apt.py OUT.apt [N]"""
import sys

out, n = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 1000000
head = [
    "PARTNO BENCH",
    "UNITS/MM",
    "LOADTL/1",
    "SPINDL/RPM,3000,CLW",
    "COOLNT/ON",
    "RAPID",
    "GOTO/0.0000,0.0000,5.0000",
    "FEDRAT/MMPM,500.0000",
    "GOTO/0.0000,0.0000,-1.0000",
]
lines = list(head)
k = 0
while len(lines) < n - 2:
    y = (k % 1000) * 0.01
    cycle = [
        f"GOTO/0.0000,{y:.4f},-1.0000",
        f"GOTO/10.0000,{y:.4f},-1.0000",
        f"CIRCLE/15.0000,{y:.4f},-1.0000,0.000000,0.000000,-1.000000,5.0000",  # clockwise half circle
        f"GOTO/20.0000,{y:.4f},-1.0000",
        f"CIRCLE/15.0000,{y:.4f},-1.0000,0.000000,0.000000,1.000000,5.0000",  # and back
        f"GOTO/10.0000,{y:.4f},-1.0000",
    ]
    if k % 1000 == 999:
        cycle.append(f"FEDRAT/MMPM,{400 + (k // 1000) % 5 * 100:.4f}")
    lines.extend(cycle[: n - 2 - len(lines)])
    k += 1
if lines[-1].startswith("CIRCLE"):  # a circle needs its GOTO
    lines.pop()
lines += ["END", "FINI"]
with open(out, "w") as f:
    f.write("\n".join(lines) + "\n")
