#!/usr/bin/env python3
"""Runs every test program of the suite (and the examples) through both engines and checks they
give identical Motion IR, or fail with the same exit code and the same first error.

usage: equiv.py NCC SRC_ROOT
"""
import glob
import os
import re
import subprocess
import sys

ncc, root = sys.argv[1], sys.argv[2]
patterns = ["test/lit/**/*.nc", "test/lit/**/*.ngc", "test/lit/**/*.ncir", "test/lit/**/*.h", "test/lit/**/*.apt", "test/lit/**/*.cld", "examples/*.nc"]
programs = sorted({p for pat in patterns for p in glob.glob(os.path.join(root, pat), recursive=True)})


def run(prog, engine):
    # Runaway programs stop at the loop limit in both engines, well before the time limit, also
    # in the sanitizer build on a loaded machine (10M eval iterations there take over 20 s).
    args = [ncc, "compile", prog, "--emit=motion", "--engine=" + engine, "--max-seconds=20",
            "--max-loop-iterations=200000"]
    with open(prog, errors="replace") as f:  # an ISO subprogram file run alone: its M99 restarts it
        text = f.read()
    if prog.endswith(".nc") and re.search(r"M0*99\b", text) and not re.search(r"M0*(2|30)\b", text):
        args[-1] = "--max-loop-iterations=1000"
    oracle = os.path.join(os.path.dirname(prog), "Inputs", "oracle.toml")
    if os.path.exists(oracle):
        args.append("--machine=" + oracle)
    else:  # a program whose RUN lines name a machine (the lathes) runs on it
        with open(prog, errors="replace") as f:
            m = re.search(r"--machine=(%srcroot|%S)/(\S+)", f.read())
        if m:
            base = root if m.group(1) == "%srcroot" else os.path.dirname(prog)
            args.append("--machine=" + os.path.join(base, m.group(2)))
    with open(prog, errors="replace") as f:  # called programs on the search path (Heidenhain CALL PGM)
        m = re.search(r"--include=%S/(\S+)", f.read())
    if m:
        args.append("--include=" + os.path.join(os.path.dirname(prog), m.group(1)))
    with open(prog, errors="replace") as f:  # a probing program runs against its probe results
        m = re.search(r"--probe-results=(%srcroot|%S)/(\S+)", f.read())
    if m:
        base = root if m.group(1) == "%srcroot" else os.path.dirname(prog)
        args.append("--probe-results=" + os.path.join(base, m.group(2)))
    p = subprocess.run(args, capture_output=True, text=True, timeout=120)
    first_error = next((l for l in p.stderr.splitlines() if ": error: " in l), "")
    return p.returncode, p.stdout, first_error


failures = 0
compared = 0
for prog in programs:
    e = run(prog, "eval")
    j = run(prog, "jit")
    compared += 1
    rel = os.path.relpath(prog, root)
    if e[0] != j[0]:
        print("MISMATCH exit code %s: eval %d, jit %d\n  eval: %s\n  jit:  %s" % (rel, e[0], j[0], e[2], j[2]))
        failures += 1
    elif e[1] != j[1]:
        el, jl = e[1].splitlines(), j[1].splitlines()
        i = next((k for k in range(min(len(el), len(jl))) if el[k] != jl[k]), min(len(el), len(jl)))
        print("MISMATCH motion %s at record %d:\n  eval: %s\n  jit:  %s" %
              (rel, i + 1, el[i] if i < len(el) else "<end>", jl[i] if i < len(jl) else "<end>"))
        failures += 1
    elif e[2] != j[2]:
        print("MISMATCH first error %s:\n  eval: %s\n  jit:  %s" % (rel, e[2], j[2]))
        failures += 1
print("engines compared on %d programs, %d mismatches" % (compared, failures))
sys.exit(1 if failures else 0)
