// Cutter radius compensation: offset geometry of lines and arcs, corner classification and the
// one-move-lag stage (see CutterComp.h for the rules, measured on LinuxCNC rs274).
#include "runtime/CutterComp.h"

#include <cmath>

namespace ncc {

namespace {

Point2 sub(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
Point2 plus(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
Point2 mul(Point2 a, double k) { return {a.x * k, a.y * k}; }
double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
double len(Point2 a) { return std::hypot(a.x, a.y); }
double dist(Point2 a, Point2 b) { return len(sub(a, b)); }
Point2 unit(Point2 a) {
  double l = len(a);
  return l > 0 ? mul(a, 1 / l) : Point2{};
}
Point2 leftNormal(Point2 t) { return {-t.y, t.x}; }
Point2 xy(const AxisVec &v) { return {v[0], v[1]}; }

// Tangent of an arc at point p: counter-clockwise is the radius vector turned left.
Point2 arcTangent(const PathElem &e, Point2 p) { return mul(unit(leftNormal(sub(p, e.center))), e.dir); }

// The offset of one element as a line (point + direction) or a circle (centre + radius).
struct OffsetCurve {
  bool circle = false;
  Point2 p, d;  // line
  Point2 c;     // circle
  double rho = 0;
};

OffsetCurve offsetCurve(const PathElem &e, bool atEnd, int side, double r) {
  OffsetCurve o;
  if (e.arc) {
    o.circle = true;
    o.c = e.center;
    o.rho = offsetRadius(e, side, r);
  } else {
    o.p = atEnd ? offsetEnd(e, side, r) : offsetStart(e, side, r);
    o.d = startTangent(e);
  }
  return o;
}

// Intersections of a line with a circle or another circle (up to two points).
int intersect(const OffsetCurve &a, const OffsetCurve &b, Point2 out[2]) {
  if (!a.circle && !b.circle) {
    double den = cross(a.d, b.d);
    if (std::fabs(den) < 1e-12) return 0;
    out[0] = plus(a.p, mul(a.d, cross(sub(b.p, a.p), b.d) / den));
    return 1;
  }
  if (a.circle != b.circle) {
    const OffsetCurve &l = a.circle ? b : a, &c = a.circle ? a : b;
    Point2 w = sub(l.p, c.c);
    double half = dot(l.d, w), disc = half * half - (dot(w, w) - c.rho * c.rho);
    if (disc < 0) return 0;
    double s = std::sqrt(disc);
    out[0] = plus(l.p, mul(l.d, -half - s));
    out[1] = plus(l.p, mul(l.d, -half + s));
    return 2;
  }
  double d = dist(a.c, b.c);
  if (d < 1e-12 || d > a.rho + b.rho || d < std::fabs(a.rho - b.rho)) return 0;
  double along = (a.rho * a.rho - b.rho * b.rho + d * d) / (2 * d);
  double h = std::sqrt(std::max(0.0, a.rho * a.rho - along * along));
  Point2 u = unit(sub(b.c, a.c)), m = plus(a.c, mul(u, along)), n = leftNormal(u);
  out[0] = plus(m, mul(n, h));
  out[1] = plus(m, mul(n, -h));
  return 2;
}

// rs274's messages for a concave corner whose offset paths do not meet.
const char *noCrossing(const PathElem &a, const PathElem &b) {
  if (!a.arc) return "Arc move in concave corner cannot be reached by the tool without gouging";
  return b.arc ? "Arc to arc motion makes a corner the compensated tool can't fit in without gouging"
               : "Arc to straight motion makes a corner the compensated tool can't fit in without gouging";
}

// rs274's messages for a move that a concave corner makes run backwards.
const char *backwards(RecordKind k) {
  switch (k) {
  case RecordKind::Arc: return "Arc move in concave corner cannot be reached by the tool without gouging";
  case RecordKind::Rapid: return "Straight traverse in concave corner cannot be reached by the tool without gouging";
  default: return "Straight feed in concave corner cannot be reached by the tool without gouging";
  }
}

// Counter-clockwise angle from a to b in [0, 2 pi).
double ccwAngle(Point2 a, Point2 b) {
  double t = std::atan2(cross(a, b), dot(a, b));
  return t < 0 ? t + 2 * M_PI : t;
}

// True when cutting the move `e` (which the tool starts at `from`) at `cut` would make it run
// backwards: the tool cannot reach the corner without gouging.
bool cutsBehindStart(const PathElem &e, Point2 from, Point2 cut) {
  if (!e.arc) return dot(sub(cut, from), endTangent(e)) < 0;
  // Angles along the arc's direction from its programmed start, in a window centred on the
  // middle of the programmed sweep, so that points cut a little before or after either end
  // keep their order.
  Point2 s0 = sub(e.start, e.center);
  auto along = [&](Point2 p) {
    Point2 v = sub(p, e.center);
    return e.dir > 0 ? ccwAngle(s0, v) : ccwAngle(v, s0);
  };
  double sweep = along(e.end);
  if (sweep < 1e-9) sweep = 2 * M_PI;  // a full circle
  double lo = sweep / 2 - M_PI;
  auto inWindow = [&](double t) { return t >= lo + 2 * M_PI ? t - 2 * M_PI : t; };
  return inWindow(along(cut)) < inWindow(along(from));
}

}  // namespace

Point2 startTangent(const PathElem &e) { return e.arc ? arcTangent(e, e.start) : unit(sub(e.end, e.start)); }
Point2 endTangent(const PathElem &e) { return e.arc ? arcTangent(e, e.end) : unit(sub(e.end, e.start)); }

double offsetRadius(const PathElem &e, int side, double r) {
  // A left-side tool is inside a counter-clockwise arc, outside a clockwise one.
  return dist(e.start, e.center) - side * e.dir * r;
}

Point2 offsetStart(const PathElem &e, int side, double r) {
  return plus(e.start, mul(leftNormal(startTangent(e)), side * r));
}
Point2 offsetEnd(const PathElem &e, int side, double r) {
  return plus(e.end, mul(leftNormal(endTangent(e)), side * r));
}

double turnAngle(Point2 t0, Point2 t1) { return std::atan2(cross(t0, t1), dot(t0, t1)); }

CornerKind cornerKind(double turn, int side, bool outsideArc) {
  if (std::fabs(turn) <= kSmoothTurn) return CornerKind::Smooth;
  double u = side * turn;  // > 0: towards the tool side
  // Near a reversal rs274 goes round the corner, unless the deciding arc has the tool outside:
  // then the concave range runs kSmoothTurn past the reversal.
  double limit = M_PI - kSmoothTurn;
  bool concave = outsideArc ? (u > kSmoothTurn || u < -limit) : (u > kSmoothTurn && u < limit);
  return concave ? CornerKind::Concave : CornerKind::Convex;
}

bool offsetIntersection(const PathElem &a, const PathElem &b, int side, double r, Point2 &out) {
  Point2 pts[2];
  int n = intersect(offsetCurve(a, true, side, r), offsetCurve(b, false, side, r), pts);
  if (n == 0) return false;
  Point2 near = mul(plus(offsetEnd(a, side, r), offsetStart(b, side, r)), 0.5);
  out = pts[0];
  if (n == 2 && dist(pts[1], near) < dist(pts[0], near)) out = pts[1];
  // A line meeting the outside of an arc: rs274 takes where the line enters the circle (line
  // then arc) or leaves it (arc then line), even when the other crossing is nearer (which
  // happens past a reversal). pts[0] is the crossing earlier along the line.
  const PathElem &arcElem = a.arc ? a : b;
  if (n == 2 && a.arc != b.arc && side * arcElem.dir < 0) out = a.arc ? pts[1] : pts[0];
  // Two arcs with the tool outside both: the crossing on the tool side of the line from the
  // first centre to the second (pts[0] is left of it).
  if (n == 2 && a.arc && b.arc && side * a.dir < 0 && side * b.dir < 0) out = side > 0 ? pts[0] : pts[1];
  return true;
}

Point2 noseTipVector(int tip) {
  static const Point2 kTips[10] = {{0, 0},  {1, 1},  {-1, 1}, {-1, -1}, {1, -1},
                                   {1, 0},  {0, 1},  {-1, 0}, {0, -1},  {0, 0}};
  return tip >= 0 && tip <= 9 ? kTips[tip] : Point2{};
}

// --- the stage ---

void CutterComp::start(int side, double r, const AxisVec &tool, bool normalEntry) {
  side_ = side;
  normalEntry_ = normalEntry;
  r_ = r;
  tool_ = tool;
  entry_ = true;
  havePending_ = false;
  afterZ_ = false;
  held_.clear();
}

bool CutterComp::fail(const char *msg, const char *rule) {
  errMsg_ = msg;
  errRule_ = rule;
  return false;
}

void CutterComp::emitPending(Point2 end, bool entryArc) {
  MotionRecord o = pending_;
  o.start = tool_;
  o.end[0] = end.x;
  o.end[1] = end.y;
  if (o.kind == RecordKind::Arc && entryArc) {
    // The entry arc starts off the offset circle: keep the end and move the centre along the
    // end's radius until it is as far from the start as from the end.
    Point2 s = xy(tool_), u = unit(sub(pendingElem_.center, end)), es = sub(end, s);
    double k = dot(es, u);
    if (std::fabs(k) > 1e-12) {
      Point2 c = plus(end, mul(u, -dot(es, es) / (2 * k)));
      o.center[0] = c.x;
      o.center[1] = c.y;
    }
  }
  out_.record(o);
  tool_ = o.end;
  havePending_ = false;
  for (MotionRecord &z : held_) emitAtTool(z);
  held_.clear();
}

void CutterComp::emitAtTool(MotionRecord o) {
  o.start = tool_;
  o.end[0] = tool_[0];
  o.end[1] = tool_[1];
  out_.record(o);
  tool_ = o.end;
}

void CutterComp::emitCornerArc(const PathElem &next, const MotionRecord &nextRec) {
  MotionRecord a = nextRec;
  a.exactStop = false;
  a.start = a.end = tool_;
  Point2 to = offsetStart(next, side_, r_);
  a.end[0] = to.x;
  a.end[1] = to.y;
  if (nextRec.kind != RecordKind::Rapid) {
    a.kind = RecordKind::Arc;
    a.plane = Plane::XY;
    a.center = {next.start.x, next.start.y, tool_[2]};
    a.turns = -side_;  // round a left-side corner clockwise
    a.feed = feed_;
  }  // before a rapid rs274 traverses straight round the corner
  out_.record(a);
  tool_ = a.end;
}

bool CutterComp::hold(const MotionRecord &r) {
  if (!havePending_) return false;
  if (held_.size() < kMaxHeld) {
    held_.push_back(r);
    return true;
  }
  // A long run is let go (the pending move ends normal to its end point): memory stays bounded.
  emitPending(offsetEnd(pendingElem_, side_, r_), pendingEntry_);
  lastElem_ = pendingElem_;
  afterZ_ = true;
  return false;
}

CornerKind CutterComp::corner(const PathElem &a, const PathElem &b) const {
  // The next move decides when it is an arc, else the previous one (measured on rs274).
  const PathElem &decides = b.arc ? b : a;
  bool outside = decides.arc && side_ * decides.dir < 0;
  return cornerKind(turnAngle(endTangent(a), startTangent(b)), side_, outside);
}

bool CutterComp::add(const MotionRecord &rec) {
  PathElem e;
  e.arc = rec.kind == RecordKind::Arc;
  e.start = xy(rec.start);
  e.end = xy(rec.end);
  if (e.arc) {
    e.center = {rec.center[0], rec.center[1]};
    e.dir = rec.turns < 0 ? -1 : 1;
    if (offsetRadius(e, side_, r_) <= 0) return fail("Tool radius not less than arc radius with comp", "cutcomp-arc-too-small");
  }
  if (rec.kind != RecordKind::Rapid) feed_ = rec.feed;
  if (!e.arc && dist(e.start, e.end) < 1e-12) {
    // No XY motion (a Z move): rs274 holds it with the pending move, which still ends where the
    // next XY move says; the tool keeps its compensated XY.
    if (!hold(rec)) emitAtTool(rec);
    return true;
  }
  if (!havePending_) {
    if (entry_ && normalEntry_ && e.arc)
      return fail("the start-up move of tool nose radius compensation must be G00 or G01, not an arc", "cutcomp-entry-arc");
    if (entry_ && !normalEntry_ && dist(xy(tool_), e.end) <= r_)
      return fail("Length of cutter compensation entry move is not greater than the tool radius",
                  "cutcomp-entry-too-short");
    // After a Z move rs274 still goes round a convex corner with the move before it.
    if (afterZ_ && corner(lastElem_, e) == CornerKind::Convex) emitCornerArc(e, rec);
    afterZ_ = false;
    pendingEntry_ = entry_;
    entry_ = false;
  } else if (pendingEntry_ && normalEntry_) {
    emitPending(offsetStart(e, side_, r_), true);  // no corner: the next move starts normal to itself
    pendingEntry_ = false;
  } else {
    CornerKind k = corner(pendingElem_, e);
    Point2 cut = offsetEnd(pendingElem_, side_, r_);
    if (k == CornerKind::Concave && !offsetIntersection(pendingElem_, e, side_, r_, cut))
      return fail(noCrossing(pendingElem_, e), "cutcomp-gouge");
    // The pending move may run backwards: cut before its start here, or started past its end
    // by the previous concave corner. rs274 lets the entry move run backwards.
    if (!pendingEntry_ && (k == CornerKind::Concave || (!pendingElem_.arc && !e.arc)) &&
        cutsBehindStart(pendingElem_, xy(tool_), cut))
      return fail(backwards(pending_.kind), "cutcomp-gouge");
    emitPending(cut, pendingEntry_);
    if (k == CornerKind::Convex) emitCornerArc(e, rec);
    pendingEntry_ = false;
  }
  pending_ = rec;
  pendingElem_ = e;
  havePending_ = true;
  return true;
}

bool CutterComp::stop(bool check) {
  if (havePending_) {
    Point2 end = offsetEnd(pendingElem_, side_, r_);
    // rs274 refuses a G40 after a straight move that a concave corner made run backwards.
    if (check && !pendingElem_.arc && cutsBehindStart(pendingElem_, xy(tool_), end))
      return fail(backwards(pending_.kind), "cutcomp-gouge");
    emitPending(end, pendingEntry_);
  }
  side_ = 0;
  entry_ = false;
  return true;
}

}  // namespace ncc
