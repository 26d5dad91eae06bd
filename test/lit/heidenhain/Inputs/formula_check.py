#!/usr/bin/env python3
"""Checks a --trace=jsonl run of an SL cycle on a contour formula: every point of every move below
a level (program Z) lies in the formula's region with the disc of radius KEEP (tool radius + side
allowance) about it, and no move cuts deeper than a floor. The disc is tested at 90 points of its
rim (a crossing of the boundary by more than KEEP * 0.0007 shows). Prints a summary line or the
first violation.

  formula_check.py --below Z --keep D [--floor Z] [--line N] --circle A=cx,cy,r --poly B="x,y x,y ..." --formula "(A | B) \\ C"
The formula takes | & ^ \\ and parentheses, as the Klartext one.
"""
import argparse
import math
import sys

from sl_check import inside, moves_of, samples  # point in polygon, the moves, a move as points


def parse(tokens, shapes):
    """A predicate of the formula: operands left to right, parentheses first."""
    pos = [0]

    def operand():
        t = tokens[pos[0]]
        pos[0] += 1
        if t == "(":
            f = expr()
            pos[0] += 1  # ')'
            return f
        return shapes[t]

    def expr():
        f = operand()
        while pos[0] < len(tokens) and tokens[pos[0]] != ")":
            op = tokens[pos[0]]
            pos[0] += 1
            g = operand()
            f = {"|": lambda a, b: lambda p: a(p) or b(p), "&": lambda a, b: lambda p: a(p) and b(p),
                 "^": lambda a, b: lambda p: a(p) != b(p), "\\": lambda a, b: lambda p: a(p) and not b(p)}[op](f, g)
        return f

    return expr()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--below", type=float, required=True)
    ap.add_argument("--keep", type=float, required=True)
    ap.add_argument("--floor", type=float)
    ap.add_argument("--circle", action="append", default=[])
    ap.add_argument("--poly", action="append", default=[])
    ap.add_argument("--formula", required=True)
    ap.add_argument("--line", type=int, help="only the moves of this source line (one cycle call)")
    a = ap.parse_args()
    shapes = {}
    for c in a.circle:
        name, v = c.split("=")
        cx, cy, rr = (float(x) for x in v.split(","))
        shapes[name] = lambda p, cx=cx, cy=cy, rr=rr: math.hypot(p[0] - cx, p[1] - cy) < rr
    for c in a.poly:
        name, v = c.split("=")
        poly = [tuple(float(x) for x in pt.split(",")) for pt in v.split()]
        shapes[name] = lambda p, poly=poly: inside(p, poly)
    tokens = a.formula.replace("(", " ( ").replace(")", " ) ").split()
    region = parse(tokens, shapes)
    rim = [(math.cos(2 * math.pi * k / 90), math.sin(2 * math.pi * k / 90)) for k in range(90)]
    keep = a.keep - 1e-3
    moves, deepest = 0, math.inf
    for r in moves_of(sys.stdin):
        if min(r["start"][2], r["end"][2]) >= a.below or (a.line is not None and r["line"] != a.line):
            continue
        moves += 1
        for p in samples(r):
            deepest = min(deepest, p[2])
            if p[2] >= a.below:
                continue
            if not region(p) or not all(region((p[0] + keep * u, p[1] + keep * v)) for u, v in rim):
                print(f"VIOLATION: line {r['line']} point {p[0]:.4f},{p[1]:.4f} is nearer than {a.keep} to the region's boundary")
                return 1
    if a.floor is not None and deepest < a.floor - 1e-4:
        print(f"VIOLATION floor: {deepest:.4f} below {a.floor:.4f}")
        return 1
    print(f"OK {moves} moves below; deepest {deepest:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
