#!/usr/bin/env python3
"""Compiles a one-block program for every G code of GCodeTable.inc and counts what the front end
does with it: runs (executed or the group's initial setting), refused as not simulated, needs
words of its block (G4 F, G53 X …), or any other error (printed: there must be none).

usage: each-gcode.py NCC GCodeTable.inc TMPDIR"""
import os
import re
import subprocess
import sys

ncc, table, tmp = sys.argv[1:4]
os.makedirs(tmp, exist_ok=True)
names = re.findall(r'^\{"([^"]+)", (\d+)', open(table).read(), re.M)
counts = {"runs": 0, "not simulated": 0, "needs": 0, "other": 0}
groups = set()
for name, group in names:
    groups.add(group)
    path = os.path.join(tmp, "g.mpf")
    with open(path, "w") as f:
        f.write(name + "\nM30\n")
    p = subprocess.run([ncc, "compile", "--emit=ir", path], capture_output=True, text=True)
    if p.returncode == 0:
        counts["runs"] += 1
    elif "is not simulated" in p.stderr:
        counts["not simulated"] += 1
    elif " needs " in p.stderr:  # G4 without its time, G53 without positions
        counts["needs"] += 1
    else:
        counts["other"] += 1
        print("OTHER %s: %s" % (name, p.stderr.splitlines()[0] if p.stderr else p.returncode))
print("%d codes in %d groups: %d run, %d not simulated, %d need words of their block, %d other" %
      (len(names), len(groups), counts["runs"], counts["not simulated"], counts["needs"], counts["other"]))
