"""Independent check of the 808D manual's turning TNRC example (seed file 12, G42, tip 3, nose
radius 0.4): builds the contour by hand (the R3 rounding and the 3 mm chamfer inserted here),
offsets it to the right by the radius (convex corners: an arc round the corner; concave ones: the
offsets' crossing; the start-up block ends normal to the next element, the cancel block leaves from
the last element's end normal), adds the tip vector and compares every motion record ncc printed
(stdin: `ncc compile --emit=motion`) with it, to 1e-9 mm. Coordinates here are (Z, X) in program
radii; machine = program + (-20, -70) after G50 X140 Z20 from the machine zero."""
import math
import re
import sys

R = 0.4
TIP = (-1.0, -1.0)  # tip 3: the imaginary tip is -Z -X of the nose centre
SHIFT = (-20.0, -70.0)


def line(a, b, kind="linear"):
    return {"arc": False, "s": a, "e": b, "kind": kind}


def arc(a, b, c, d):
    return {"arc": True, "s": a, "e": b, "c": c, "dir": d, "kind": "arc"}


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def unit(v):
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def tangent(el, at_end):
    if not el["arc"]:
        return unit(sub(el["e"], el["s"]))
    rv = sub(el["e"] if at_end else el["s"], el["c"])
    t = (-rv[1], rv[0]) if el["dir"] > 0 else (rv[1], -rv[0])
    return unit(t)


def right(t):
    return (t[1], -t[0])


def off_point(el, at_end):
    p = el["e"] if at_end else el["s"]
    n = right(tangent(el, at_end))
    return (p[0] + R * n[0], p[1] + R * n[1])


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def line_line(p, d, q, e):
    den = cross(d, e)
    k = cross(sub(q, p), e) / den
    return (p[0] + k * d[0], p[1] + k * d[1])


# The contour as the program describes it (the tip's path), corners inserted by hand.
P = [(5, 0), (0, 0), (0, 10), (-20, 10), (-35, 15)]
contour = [line(P[i], P[i + 1]) for i in range(len(P) - 1)]
contour += [line((-35, 15), (-52, 15)), arc((-52, 15), (-55, 18), (-52, 18), -1),  # N8 and its R3
            line((-55, 18), (-55, 22)), line((-55, 22), (-58, 25)),              # N9 and the chamfer
            line((-58, 25), (-70, 25)), arc((-70, 25), (-90, 45), (-70, 45), -1),  # N10, N11 G02 R20
            line((-90, 45), (-90, 55)), "dwell", line((-90, 55), (-110, 55)), line((-110, 55), (-110, 60))]

out = []  # (kind, end, centre) of the nose centre
start = (20 - TIP[0] * R, 70 - TIP[1] * R)  # the nose centre before the start-up block
els = [e for e in contour if e != "dwell"]
# Start-up block N3 (rapid): to the first element's offset start point, normal to it.
out.append(("rapid", off_point(els[0], False), None))
pending_dwell = False
for i, el in enumerate(els):
    nxt = els[i + 1] if i + 1 < len(els) else None
    end = off_point(el, True)
    join = None
    if nxt is not None:
        turn = cross(tangent(el, True), tangent(nxt, False))
        if turn < -1e-9:  # towards the tool (right): concave, cut at the crossing of the offsets
            assert not el["arc"] and not nxt["arc"]
            end = line_line(off_point(el, True), tangent(el, True), off_point(nxt, False), tangent(nxt, False))
        elif turn > 1e-9:  # convex: round the corner point, counter-clockwise
            join = ("arc", off_point(nxt, False), el["e"])
    centre = el["c"] if el["arc"] else None
    out.append((el["kind"], end, centre))
    if contour[contour.index(el) + 1:contour.index(el) + 2] == ["dwell"]:
        out.append(("dwell", end, None))
    if join:
        out.append(join)
out.append(("rapid", None, None))  # N16 G40: straight to the programmed point, uncompensated


def machine(p, shifted=True):
    return (p[0] + (TIP[0] * R if shifted else 0) + SHIFT[0], p[1] + (TIP[1] * R if shifted else 0) + SHIFT[1])


expect = []
for kind, end, centre in out:
    e = machine(end) if end is not None else (20 + SHIFT[0], 70 + SHIFT[1])
    c = machine(centre) if centre is not None else None
    expect.append((kind, e, c))

got = []
for text in sys.stdin:
    m = re.match(r"(rapid|linear|arc|dwell) ", text)
    if not m or " N3 " not in text and not got:
        continue
    if m.group(1) == "dwell":
        got.append(("dwell", None, None))
        continue
    x = float(re.search(r" X(\S+)", text).group(1))
    z = float(re.search(r" Z(\S+)", text).group(1))
    c = re.search(r"center\((\S+), \S+, (\S+)\)", text)
    got.append((m.group(1), (z, x), (float(c.group(2)), float(c.group(1))) if c else None))

if len(got) != len(expect):
    sys.exit("expected %d records, ncc printed %d" % (len(expect), len(got)))
for i, (g, e) in enumerate(zip(got, expect)):
    if g[0] != e[0]:
        sys.exit("record %d: expected %s, got %s" % (i, e[0], g[0]))
    if e[0] == "dwell":
        continue
    for a, b in ((g[1], e[1]), (g[2], e[2])):
        if (a is None) != (b is None) or (a and math.hypot(a[0] - b[0], a[1] - b[1]) > 1e-9):
            sys.exit("record %d (%s): expected %s, got %s" % (i, e[0], e, g))
print("OK %d records" % len(got))
