#!/usr/bin/env python3
"""Checks the layering of the source tree: each top-level library folder may include only the
folders below it (LLVM-style: ir is the base, runtime knows nothing of passes or front ends).
Run by the build (CMake target check-layering, part of `all`) and by the lit suite.

usage: utils/check-layering.py [ROOT]     exit 1 and one line per violation
"""
import os
import re
import sys

# folder -> folders it may include (besides itself)
ALLOWED = {
    "ir": set(),
    "runtime": {"ir"},
    "frontend": {"ir"},
    "passes": {"ir", "runtime"},
    "backends": {"ir", "runtime", "passes"},
    "utils": {"ir", "runtime", "frontend", "passes", "backends"},
    "test": {"ir", "runtime", "frontend", "passes", "backends", "utils"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')


def violations(root):
    out = []
    for top, allowed in ALLOWED.items():
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for fn in sorted(files):
                if not fn.endswith((".h", ".cpp", ".hpp", ".inc")):
                    continue
                path = os.path.join(dirpath, fn)
                with open(path, encoding="utf-8", errors="replace") as f:
                    for n, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if m and m.group(1) in ALLOWED and m.group(1) != top and m.group(1) not in allowed:
                            rel = os.path.relpath(path, root)
                            out.append(f"{rel}:{n}: {top}/ must not include {m.group(1)}/ (layering, utils/check-layering.py)")
    return out


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    bad = violations(root)
    for b in bad:
        print(b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
