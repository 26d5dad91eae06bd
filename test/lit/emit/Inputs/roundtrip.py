#!/usr/bin/env python3
"""Translates every test program that runs into another controller's language and reads it back
(`ncc translate --to=TARGET --verify`). Each program must either verify or be refused with a
located error naming the record the target cannot hold ([unsupported-code], [tilted-arc]):
anything else (a path that differs, an output that does not run, a crash) is a MISMATCH.

usage: roundtrip.py NCC SRC_ROOT TARGET[,TARGET...] MACHINE GLOB...
  TARGET: iso, sinumerik, heidenhain, apt or cldata; "sinumerik:structured" translates with
          --keep-structure (docs/EMIT.md "Structure-keeping translation") and ends with the
          refusals by reason. Several, comma-separated, share the source runs; each line then
          names its target (`REFUSED apt: …`) and each gets its own count line
  MACHINE: a machine file for programs whose RUN lines name none ("-": ncc's default machine);
           "=FILE" runs every program on FILE
"""
import glob
import os
import re
import subprocess
import sys

ncc, root, target, machine = sys.argv[1:5]
programs = sorted({p for pat in sys.argv[5:] for p in glob.glob(os.path.join(root, pat), recursive=True)})
# Options the program's own RUN lines give it: its machine, the folders of called programs.
option = re.compile(r"--(machine|include)=(%srcroot|%S|%shared)/(\S+)")
bases = {"%srcroot": root, "%shared": os.path.normpath(os.path.join(root, "..", "shared"))}

targets = target.split(",")
counts = {t: [0, 0, 0] for t in targets}  # verified, refused, mismatches
reasons = {t: {} for t in targets}
for prog in programs:
    with open(prog, errors="replace") as f:
        text = f.read()
    args = {}
    for kind, base, rest in option.findall(text):
        args.setdefault(kind, os.path.join(bases.get(base, os.path.dirname(prog)), rest))
    if machine.startswith("="):
        args["machine"] = machine[1:]
    elif "machine" not in args and machine != "-":
        args["machine"] = machine
    opts = ["--%s=%s" % kv for kv in sorted(args.items())] + ["--max-seconds=20", "--max-loop-iterations=200000"]
    src = subprocess.run([ncc, "run", prog, "-o", os.devnull] + opts, capture_output=True)
    if src.returncode != 0:
        continue  # an error test: the source itself does not run
    name = os.path.relpath(prog, root)
    for t in targets:
        to, _, mode = t.partition(":")
        extra = ["--keep-structure"] if mode == "structured" else []
        out = subprocess.run([ncc, "translate", prog, "--to=" + to, "--verify", "-o", os.devnull] + extra + opts,
                             capture_output=True, text=True)
        tag = " " + t if len(targets) > 1 else ""
        first = next((l for l in out.stderr.splitlines() if "error:" in l), "")
        if out.returncode == 0 and "verified:" in out.stderr:
            counts[t][0] += 1
        elif re.search(r"error: .*\[(unsupported-code|tilted-arc)\]$", first):
            counts[t][1] += 1  # a record at its source line, or the machine (a lathe to Klartext)
            why = (re.search(r"structure-keeping translation to \w+: (.*?); translate", first) or
                   re.search(r"record \((.*)\): ", first) or re.search(r"error: (.*) \[", first))
            print("REFUSED%s %s: %s" % (tag, name, why.group(1)))
            # The reason without the program's own names and numbers, to count refusals by kind.
            reason = re.sub(r"(variable |program |of |\()'[^']*'", r"\1_", why.group(1))
            reason = re.sub(r"\d+(\.\d+)?", "n", reason)
            reasons[t][reason] = reasons[t].get(reason, 0) + 1
        else:
            counts[t][2] += 1
            print("MISMATCH%s %s: %s" % (tag, name, first or out.stderr.strip()[-300:]))
for t in targets:
    if t.endswith(":structured"):
        for reason, n in sorted(reasons[t].items(), key=lambda kv: (-kv[1], kv[0])):
            print("refused %3d: %s" % (n, reason))
    print("%s: %d verified, %d refused, %d mismatches" % (t.partition(":")[0], *counts[t]))
