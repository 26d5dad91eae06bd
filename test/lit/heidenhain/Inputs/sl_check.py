#!/usr/bin/env python3
"""Checks a --trace=jsonl run of an SL cycle: every move below a level (program Z) keeps at
least KEEP (tool radius + side allowance) off each island polygon and stays that far inside the
outline polygons (when given), and cuts no deeper than a floor. Prints a summary line or the
first violation.

  sl_check.py --below Z --keep D [--floor Z] [--outline "x,y x,y ..."]... [--island "x,y ..."]... < run.jsonl
  --circle-outline "cx,cy,r" (repeatable: their union) and --circle-island "cx,cy,r" take circles.
"""
import argparse
import json
import math
import sys


def seg_dist(p, a, b):
    ux, uy = b[0] - a[0], b[1] - a[1]
    l2 = ux * ux + uy * uy
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / l2))
    return math.hypot(a[0] + t * ux - p[0], a[1] + t * uy - p[1])


def inside(p, poly):
    c = False
    n = len(poly)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                c = not c
    return c


def boundary_dist(p, poly):
    return min(seg_dist(p, poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly)))


def samples(r):
    s, e = r["start"], r["end"]
    if r["kind"] == "arc":
        c = r["center"]
        a0 = math.atan2(s[1] - c[1], s[0] - c[0])
        a1 = math.atan2(e[1] - c[1], e[0] - c[0])
        rad = math.hypot(s[0] - c[0], s[1] - c[1])
        ccw = r["turns"] > 0
        sweep = (a1 - a0) % (2 * math.pi) if ccw else -((a0 - a1) % (2 * math.pi))
        if abs(sweep) < 1e-12:
            sweep = 2 * math.pi if ccw else -2 * math.pi
        n = 128
        return [(c[0] + rad * math.cos(a0 + sweep * k / n), c[1] + rad * math.sin(a0 + sweep * k / n),
                 s[2] + (e[2] - s[2]) * k / n) for k in range(n + 1)]
    n = max(1, int(math.hypot(e[0] - s[0], e[1] - s[1]) / 0.05))
    return [tuple(s[i] + (e[i] - s[i]) * k / n for i in range(3)) for k in range(n + 1)]


def in_circle(q, c, strict=1e-9):
    return math.hypot(q[0] - c[0], q[1] - c[1]) < c[2] - strict


def circle_union_depth(p, circles):
    """Signed distance of p inside the union of circles to its boundary (exact: the nearest
    point is the radial projection onto an uncovered arc or a corner of the union)."""
    if not any(in_circle(p, c, 0) for c in circles):
        return -min(math.hypot(p[0] - c[0], p[1] - c[1]) - c[2] for c in circles)
    cands = []
    for i, c in enumerate(circles):
        d = math.hypot(p[0] - c[0], p[1] - c[1])
        if d > 0:
            q = (c[0] + c[2] * (p[0] - c[0]) / d, c[1] + c[2] * (p[1] - c[1]) / d)
            if not any(in_circle(q, o) for j, o in enumerate(circles) if j != i):
                cands.append(abs(c[2] - d))
        for j in range(i + 1, len(circles)):
            o = circles[j]
            dx, dy = o[0] - c[0], o[1] - c[1]
            dd = math.hypot(dx, dy)
            if dd == 0 or dd > c[2] + o[2] or dd < abs(c[2] - o[2]):
                continue
            a = (c[2] ** 2 - o[2] ** 2 + dd ** 2) / (2 * dd)
            h = math.sqrt(max(0.0, c[2] ** 2 - a * a))
            mx, my = c[0] + a * dx / dd, c[1] + a * dy / dd
            for sgn in (1, -1):
                s = (mx - sgn * h * dy / dd, my + sgn * h * dx / dd)
                if not any(in_circle(s, k) for k in circles):
                    cands.append(math.hypot(p[0] - s[0], p[1] - s[1]))
    return min(cands)


def poly_arg(text):
    return [tuple(float(v) for v in pt.split(",")) for pt in text.split()]


def moves_of(stream):
    """The rapid, linear and arc records of a JSONL motion stream, in program coordinates (a
    record with "work" has its start, end and centre shifted by work - end)."""
    for line in stream:
        r = json.loads(line)
        if r["kind"] not in ("rapid", "linear", "arc"):
            continue
        if "work" in r:
            d = [w - e for w, e in zip(r["work"], r["end"])]
            r["start"] = [v + dv for v, dv in zip(r["start"], d)]
            r["end"] = list(r["work"])
            if "center" in r:
                r["center"] = [v + dv for v, dv in zip(r["center"], d)]
        yield r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--below", type=float, required=True)
    ap.add_argument("--keep", type=float, required=True)
    ap.add_argument("--floor", type=float)
    ap.add_argument("--outline", action="append", default=[])
    ap.add_argument("--circle-outline", action="append", default=[])
    ap.add_argument("--island", action="append", default=[])
    ap.add_argument("--circle-island", action="append", default=[])
    a = ap.parse_args()
    outlines = [poly_arg(o) for o in a.outline]
    circles = [tuple(float(v) for v in c.split(",")) for c in a.circle_outline]
    islands = [poly_arg(i) for i in a.island]
    circle_islands = [tuple(float(v) for v in c.split(",")) for c in a.circle_island]
    tol = 1e-4
    moves = 0
    min_island = min_wall = math.inf
    deepest = math.inf
    for r in moves_of(sys.stdin):
        if min(r["start"][2], r["end"][2]) >= a.below:
            continue
        moves += 1
        for p in samples(r):
            deepest = min(deepest, p[2])
            if p[2] >= a.below:
                continue
            for isl in islands:
                d = -boundary_dist(p, isl) if inside(p, isl) else boundary_dist(p, isl)
                min_island = min(min_island, d)
                if d < a.keep - tol:
                    print(f"VIOLATION island: line {r['line']} point {p[0]:.4f},{p[1]:.4f} is {d:.4f} off")
                    return 1
            for cx, cy, rr in circle_islands:
                d = math.hypot(p[0] - cx, p[1] - cy) - rr
                min_island = min(min_island, d)
                if d < a.keep - tol:
                    print(f"VIOLATION island: line {r['line']} point {p[0]:.4f},{p[1]:.4f} is {d:.4f} off")
                    return 1
            if outlines or circles:
                # inside some outline (a union), at least keep from its boundary
                best = -math.inf
                for o in outlines:
                    best = max(best, boundary_dist(p, o) if inside(p, o) else -boundary_dist(p, o))
                if circles:
                    best = max(best, circle_union_depth(p, circles))
                min_wall = min(min_wall, best)
                if best < a.keep - tol:
                    print(f"VIOLATION wall: line {r['line']} point {p[0]:.4f},{p[1]:.4f} is {best:.4f} inside")
                    return 1
    if a.floor is not None and deepest < a.floor - tol:
        print(f"VIOLATION floor: {deepest:.4f} below {a.floor:.4f}")
        return 1
    print(f"OK {moves} moves below; island clearance {min_island:.3f}; wall clearance {min_wall:.3f}; deepest {deepest:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
