// Executor: the one contour step that inserts a chamfer or a rounding at the corner between two
// moves (ISO `,C` `,R`; Sinumerik CHF/RND and Heidenhain CHF/RND use the same words). The first
// move waits until the second arrives; both are trimmed and the corner element goes between them.
// Chamfers between lines of the active plane; roundings also next to arcs (cornerWithArc).
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"

#include <cmath>

namespace ncc {

namespace {
// One element of the corner in plane coordinates: a line, or an arc about (c1, c2) of radius r
// turning dir (+1 counter-clockwise).
struct Elem {
  bool arc = false;
  double s1 = 0, s2 = 0, e1 = 0, e2 = 0, c1 = 0, c2 = 0, r = 0;
  int dir = 1;
  // The unit tangent at the point (q1, q2) of the element, in the direction of travel.
  void tangent(double q1, double q2, double &t1, double &t2) const {
    if (!arc) {
      double l = std::hypot(e1 - s1, e2 - s2);
      t1 = (e1 - s1) / l, t2 = (e2 - s2) / l;
    } else {
      t1 = -dir * (q2 - c2) / r, t2 = dir * (q1 - c1) / r;
    }
  }
  // Whether (q1, q2), a point on the element's line or circle, lies between its ends.
  bool contains(double q1, double q2) const {
    const double eps = 1e-9;
    if (!arc) {
      double l = std::hypot(e1 - s1, e2 - s2), t = ((q1 - s1) * (e1 - s1) + (q2 - s2) * (e2 - s2)) / l;
      return t >= -eps && t <= l + eps;
    }
    auto sweep = [&](double a1, double a2, double b1, double b2) {  // from a to b in dir, (0, 2 pi]
      double a = std::atan2(a2 - c2, a1 - c1), b = std::atan2(b2 - c2, b1 - c1);
      double s = dir > 0 ? b - a : a - b;
      while (s <= 0) s += 2 * M_PI;
      return s;
    };
    double all = sweep(s1, s2, e1, e2), part = sweep(s1, s2, q1, q2);
    return part <= all + eps / r || std::hypot(q1 - s1, q2 - s2) < eps;
  }
};
}  // namespace

bool Executor::Impl::cornerRequest(const MachineCmd &c) {
  const bool leg = c.has(Word::ChamferLeg);
  if (c.has(Word::Chamfer) + leg + c.has(Word::Round) > 1)
    return error("one chamfer or rounding in a block", "corner-invalid");
  corner.reqNextAxis = -1, corner.reqNextSign = 0;
  if (!c.has(Word::Chamfer) && !leg && !c.has(Word::Round) && !turnCornerRequest(c)) return false;
  double size = c.has(Word::Chamfer) ? c.get(Word::Chamfer) * scale()
                : leg                ? c.get(Word::ChamferLeg) * scale()
                : c.has(Word::Round) ? c.get(Word::Round) * scale()
                                     : corner.reqSize;
  if (!(size > 0)) return error("a chamfer or rounding must be greater than 0", "corner-invalid");
  if (prevBlockFrame || curBlockFrame)  // 808D manual L5950
    return error("a chamfer or rounding must not follow a coordinate-system change or reference-point return",
                 "corner-invalid");
  // Under compensation the corner joins the programmed contour, which is then offset; on the
  // move that leaves compensation (G40) there is no contour to round.
  if (compExit || pf.scaleOn || st.feedMode == ModeValue::InverseTime)
    return error("a chamfer or rounding on the move after G40, with scaling or with inverse-time feed is not supported",
                 "unsupported-code");
  corner.requested = true;
  corner.reqRound = c.has(Word::Round) || (corner.reqNextAxis >= 0 && corner.reqRound);
  corner.reqSize = size;
  corner.reqLeg = leg;
  return true;
}

// Fanuc-T / 808D lathe corners without a comma (the manual's TNRC example, L2483-2484): on a G01
// along X alone, K+-k chamfers k mm towards +-Z; along Z alone, I+-i chamfers i mm (a radius)
// towards +-X; R+-r rounds towards the sign on the other axis. The 45 degree chamfer of legs k is
// the bevel k sqrt2 long. The next block must move along that axis alone, that way (Fanuc alarms
// PS0051-PS0055), which cornerNext checks.
bool Executor::Impl::turnCornerRequest(const MachineCmd &c) {
  if (!machine.controller.lathe())
    return error("I, K or R in a G1 move (a chamfer or corner R without a comma is a lathe's)", "unused-word");
  if (c.has(Word::I) + c.has(Word::K) + c.has(Word::R) > 1)
    return error("one of I, K (chamfer) and R (corner R) in a G1 move", "corner-invalid");
  const AxisVec to = target(c);
  bool alongX = to[0] != st.position[0], alongZ = to[2] != st.position[2];
  for (int i = 0; i < kAxes; ++i)
    if (i != 0 && i != 2 && to[i] != st.position[i]) alongX = alongZ = true;
  if (alongX == alongZ)
    return error("a chamfer (I, K) or corner R without a comma needs a G1 along X or Z alone", "corner-invalid");
  const Word w = c.has(Word::I) ? Word::I : c.has(Word::K) ? Word::K : Word::R;
  if ((w == Word::K && !alongX) || (w == Word::I && !alongZ))
    return error(w == Word::K ? "chamfer K follows a move along X (towards Z); after a move along Z it is I"
                              : "chamfer I follows a move along Z (towards X); after a move along X it is K",
                 "corner-invalid");
  const double v = c.get(w) * scale();
  corner.reqRound = w == Word::R;
  corner.reqSize = std::fabs(v) * (w == Word::R ? 1 : std::sqrt(2.0));
  corner.reqNextAxis = alongX ? 2 : 0;
  corner.reqNextSign = v > 0 ? 1 : -1;
  return true;
}

bool Executor::Impl::cornerRelease(const MotionRecord &first, const MotionRecord *elem) {
  corner.active = false;
  bool ok = pathOut(first) && (!elem || pathOut(*elem));
  for (auto &h : corner.held) emit(h);  // behind the pending compensated move where rs274 queues it
  corner.held.clear();
  return ok;
}

bool Executor::Impl::cornerFlush(const char *why) {
  if (!corner.active) return true;
  diags.warning(corner.move.loc, std::string(corner.round ? "rounding" : "chamfer") + " not inserted: " + why,
                "corner-not-inserted");
  return cornerRelease(corner.move, nullptr);
}

bool Executor::Impl::cornerNext(const MotionRecord &nextIn) {
  MotionRecord first = corner.move, next = nextIn;
  const PlaneAxes ax = planeAxes(first.plane);
  const int a1 = ax.u, a2 = ax.v, d = ax.n;
  for (auto &h : corner.held)
    if (h.kind != RecordKind::Comment && h.kind != RecordKind::Message && h.kind != RecordKind::FeedRate &&
        h.kind != RecordKind::SpindleSpeed)  // these belong to the next block: they go after the corner
      return error("commands between a chamfer or rounding and the next move are not supported", "unsupported-code");
  if (next.kind != RecordKind::Linear && next.kind != RecordKind::Arc)
    return error("a chamfer or rounding needs a G1, G2 or G3 move after it", "unsupported-code");
  if (corner.nextAxis >= 0) {  // the lathe form without a comma: the way its sign gave
    const int along = corner.nextAxis, other = 2 - along;
    if (next.kind != RecordKind::Linear || next.end[other] != next.start[other] ||
        (next.end[along] - next.start[along]) * corner.nextSign <= 0)
      return error(std::string("after a chamfer or corner R without a comma the next move must be a G1 along ") +
                       (along == 0 ? "X" : "Z") + " alone, towards " + (corner.nextSign > 0 ? "+" : "-") +
                       (along == 0 ? "X" : "Z") + " (the sign of its I, K or R)",
                   "corner-invalid");
  }
  // Moves that leave the plane (or turn a rotary axis): the controller does not insert it.
  bool inPlane = true;
  for (int i = 0; i < kAxes; ++i)
    if (i != a1 && i != a2 && (first.end[i] != first.start[i] || next.end[i] != next.start[i])) inPlane = false;
  if (!inPlane) {
    return cornerFlush("a move leaves the plane") && emitMove(next);
  }
  if (first.kind == RecordKind::Arc || next.kind == RecordKind::Arc) return cornerWithArc(first, next);
  double u1 = first.end[a1] - first.start[a1], u2 = first.end[a2] - first.start[a2];
  double v1 = next.end[a1] - next.start[a1], v2 = next.end[a2] - next.start[a2];
  double l1 = std::hypot(u1, u2), l2 = std::hypot(v1, v2);
  if (l1 == 0 || l2 == 0) return error("a chamfer or rounding between zero-length moves", "corner-invalid");
  u1 /= l1, u2 /= l1, v1 /= l2, v2 /= l2;
  double cross = u1 * v2 - u2 * v1, dot = u1 * v1 + u2 * v2;
  if (std::fabs(cross) < 1e-12 && dot > 0) {
    return cornerFlush("the two moves are collinear") && emitMove(next);
  }
  if (std::fabs(cross) < 1e-12) return error("a chamfer or rounding where the path reverses", "corner-invalid");
  // The corner angle between the lines, half of it, and the distance from the corner to the
  // points where the element meets each line.
  double half = std::acos(std::max(-1.0, std::min(1.0, -dot))) / 2;
  double dist = corner.round ? corner.size / std::tan(half) : corner.leg ? corner.size : corner.size / (2 * std::sin(half));
  if (dist > l1 + 1e-9 || dist > l2 + 1e-9) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the %s does not fit: it takes %.4f mm of each move (%.4f and %.4f long)",
                  corner.round ? "rounding" : "chamfer", dist, l1, l2);
    return error(buf, "corner-invalid");
  }
  const AxisVec p = first.end;
  first.end[a1] = p[a1] - u1 * dist, first.end[a2] = p[a2] - u2 * dist;
  next.start[a1] = p[a1] + v1 * dist, next.start[a2] = p[a2] + v2 * dist;
  MotionRecord elem = first;  // the block with the chamfer/rounding: its feed and source
  elem.start = first.end;
  elem.end = next.start;
  if (corner.round) {
    double b1 = v1 - u1, b2 = v2 - u2, bl = std::hypot(b1, b2);  // the bisector, into the corner
    double c = corner.size / std::sin(half);
    elem.kind = RecordKind::Arc;
    elem.center = {p[0], p[1], p[2]};
    elem.center[a1] = p[a1] + b1 / bl * c;
    elem.center[a2] = p[a2] + b2 / bl * c;
    elem.center[d] = p[d];
    elem.turns = cross > 0 ? 1 : -1;  // a left turn runs counter-clockwise
  }
  return cornerRelease(first, &elem) && emitMove(next);  // it may carry a corner request of its own
}

// A rounding where one element (or both) is an arc: the fillet's centre is where the two
// elements, offset by its radius toward the inside of the corner, meet (the solution nearest the
// corner); it touches each element at the foot of that centre. A chamfer next to an arc is an
// error until the bevel's definition on a curve is settled.
bool Executor::Impl::cornerWithArc(MotionRecord first, MotionRecord next) {
  const PlaneAxes ax = planeAxes(first.plane);
  const int a1 = ax.u, a2 = ax.v;
  if (!corner.round) return error("a chamfer next to an arc is not supported yet", "unsupported-code");
  for (const MotionRecord *m : {&first, &next})
    if (m->kind == RecordKind::Arc && (m->tiltedArc() || m->plane != first.plane || std::abs(m->turns) != 1))
      return error("a rounding next to a full-turn or tilted arc is not supported", "unsupported-code");
  auto elem = [&](const MotionRecord &m) {
    Elem e;
    e.arc = m.kind == RecordKind::Arc;
    e.s1 = m.start[a1], e.s2 = m.start[a2], e.e1 = m.end[a1], e.e2 = m.end[a2];
    if (e.arc) {
      e.c1 = m.center[a1], e.c2 = m.center[a2], e.dir = m.turns > 0 ? 1 : -1;
      e.r = std::hypot(e.e1 - e.c1, e.e2 - e.c2);
    }
    return e;
  };
  Elem A = elem(first), B = elem(next);
  const double p1 = A.e1, p2 = A.e2, r = corner.size;
  double ta1, ta2, tb1, tb2;
  A.tangent(p1, p2, ta1, ta2);
  B.tangent(p1, p2, tb1, tb2);
  double cross = ta1 * tb2 - ta2 * tb1, dot = ta1 * tb1 + ta2 * tb2;
  if (std::fabs(cross) < 1e-12 && dot > 0) {
    return cornerFlush("the two moves meet tangentially") && emitMove(next);
  }
  if (std::fabs(cross) < 1e-12) return error("a rounding where the path reverses", "corner-invalid");
  const int side = cross > 0 ? 1 : -1;  // the fillet lies left of both elements in a left turn
  // Each offset element: a line (point o, direction t) or a circle (centre, radius).
  struct Off {
    bool circle;
    double o1, o2, t1, t2, rad;
  };
  auto offset = [&](const Elem &e, double t1, double t2, Off &o) {
    if (!e.arc) {
      o = {false, p1 - side * t2 * r, p2 + side * t1 * r, t1, t2, 0};
      return true;
    }
    o = {true, e.c1, e.c2, 0, 0, side == e.dir ? e.r - r : e.r + r};  // the centre is on the left of a ccw arc
    return o.rad > 1e-12;
  };
  Off oa, ob;
  if (!offset(A, ta1, ta2, oa) || !offset(B, tb1, tb2, ob))
    return error("the rounding does not fit: its radius is not smaller than the arc's", "corner-invalid");
  // Intersections of the two offsets; the fillet centre is the one nearest the corner.
  std::vector<std::array<double, 2>> sols;
  auto lineCircle = [&](const Off &l, const Off &c) {
    double w1 = l.o1 - c.o1, w2 = l.o2 - c.o2, b = w1 * l.t1 + w2 * l.t2, q = w1 * w1 + w2 * w2 - c.rad * c.rad;
    double disc = b * b - q;
    if (disc < 0) return;
    for (double sgn : {-1.0, 1.0}) {
      double lam = -b + sgn * std::sqrt(disc);
      sols.push_back({l.o1 + lam * l.t1, l.o2 + lam * l.t2});
    }
  };
  if (!oa.circle) lineCircle(oa, ob);
  else if (!ob.circle) lineCircle(ob, oa);
  else {
    double dx = ob.o1 - oa.o1, dy = ob.o2 - oa.o2, dd = std::hypot(dx, dy);
    if (dd > 0) {
      double a = (oa.rad * oa.rad - ob.rad * ob.rad + dd * dd) / (2 * dd), h2 = oa.rad * oa.rad - a * a;
      if (h2 >= 0) {
        double h = std::sqrt(h2), m1 = oa.o1 + a * dx / dd, m2 = oa.o2 + a * dy / dd;
        sols.push_back({m1 - h * dy / dd, m2 + h * dx / dd});
        sols.push_back({m1 + h * dy / dd, m2 - h * dx / dd});
      }
    }
  }
  if (sols.empty()) return error("the rounding does not fit between the two moves", "corner-invalid");
  auto best = sols[0];
  for (auto &s : sols)
    if (std::hypot(s[0] - p1, s[1] - p2) < std::hypot(best[0] - p1, best[1] - p2)) best = s;
  // The touching points.
  auto foot = [&](const Elem &e, const Off &o, double &q1, double &q2) {
    if (!e.arc) {
      q1 = best[0] + side * o.t2 * r, q2 = best[1] - side * o.t1 * r;
    } else {
      double l = std::hypot(best[0] - e.c1, best[1] - e.c2);
      q1 = e.c1 + (best[0] - e.c1) * e.r / l, q2 = e.c2 + (best[1] - e.c2) * e.r / l;
    }
  };
  double qa1, qa2, qb1, qb2;
  foot(A, oa, qa1, qa2);
  foot(B, ob, qb1, qb2);
  if (!A.contains(qa1, qa2) || !B.contains(qb1, qb2))
    return error("the rounding does not fit: it would reach past the end of a move", "corner-invalid");
  first.end[a1] = qa1, first.end[a2] = qa2;
  next.start[a1] = qb1, next.start[a2] = qb2;
  MotionRecord elem2 = first;
  elem2.kind = RecordKind::Arc;
  elem2.start = first.end;
  elem2.end = next.start;
  elem2.center = {first.end[0], first.end[1], first.end[2]};
  elem2.center[a1] = best[0], elem2.center[a2] = best[1];
  elem2.turns = side;
  return cornerRelease(first, &elem2) && emitMove(next);
}

}  // namespace ncc
