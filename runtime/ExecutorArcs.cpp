// Arcs defined by something other than a centre or radius: through an intermediate point
// (Sinumerik CIP) and tangent to the path so far (Sinumerik and Heidenhain CT). The circle is
// found in machine coordinates, where a similarity frame keeps circles circles, and the arc
// then goes out like any other: in a principal plane when its normal is an axis, else as a
// tilted arc (Motion IR `normal=`, which the planner follows and the trace refuses).
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"

#include <cmath>

namespace ncc {

namespace {
Vec3 sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 xyz(const AxisVec &p) { return {p[0], p[1], p[2]}; }
double norm(const Vec3 &a) { return std::sqrt(dot(a, a)); }
Vec3 scaled(const Vec3 &a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }
// Points closer than this (mm) to a line count as on it: no circle.
constexpr double kCollinearMM = 1e-9;
}  // namespace

// The last path move (programmed, before corners and compensation): what the next CT continues.
// A move that does not change XYZ (rotary only) keeps the one before.
void Executor::Impl::notePath(const MotionRecord &r) {
  bool line = r.kind == RecordKind::Linear || r.kind == RecordKind::Rapid;
  if (r.kind != RecordKind::Arc && !(line && (r.end[0] != r.start[0] || r.end[1] != r.start[1] || r.end[2] != r.start[2])))
    return;
  lastPath.kind = r.kind, lastPath.start = r.start, lastPath.end = r.end;
  lastPathPlain = false;
  if (r.kind != RecordKind::Arc) return;
  lastPath.center = r.center, lastPath.turns = r.turns, lastPath.plane = r.plane, lastPath.normal = r.arcNormal();
}

// The unit direction the path leaves its last point with (machine XYZ); false before any.
bool Executor::Impl::pathTangent(Vec3 &t) const {
  const LastPath p = lastPathNow();
  if (p.kind == RecordKind::Arc) {
    t = ncc::arcTangent(tiltedArcGeometry(p.start, p.end, p.center, p.normal, p.turns), 1.0);
    return true;
  }
  if (p.kind != RecordKind::Linear && p.kind != RecordKind::Rapid) return false;
  t = sub(xyz(p.end), xyz(p.start));
  t = scaled(t, 1 / norm(t));
  return true;
}

bool Executor::Impl::emitArc(const AxisVec &end, const Vec3 &centre, const Vec3 &normal, int turns, double feed,
                             bool exactStop) {
  MotionRecord r = record(RecordKind::Arc);
  r.plane = plane();
  for (Plane p : {Plane::XY, Plane::ZX, Plane::YZ}) {  // a principal plane when the normal is an axis
    double d = dot(normal, planeNormal(p));
    if (std::fabs(std::fabs(d) - 1) < 1e-12) {
      r.plane = p;
      turns = d > 0 ? turns : -turns;
    }
  }
  if (std::fabs(std::fabs(dot(normal, planeNormal(r.plane))) - 1) >= 1e-12) {
    if (comp.active()) return error("an arc outside the principal planes with cutter compensation on", "unsupported-code");
    r.setNormal(normal);
  }
  r.end = end;
  r.center = centre;
  r.turns = turns;
  r.exactStop = exactStop || st.pathMode == ModeValue::ExactStop;
  r.feed = feed > 0 ? feed : cssPerRev() ? cssFeed(r) : moveFeed(arcGeometry(r).length);
  if (feed <= 0) inverseTimeRate(r.feed);
  st.position = end;
  return emitMove(r);
}

// CIP: start, intermediate and end point fix the circle and its plane; the arc runs from the
// start through the intermediate point, so it turns counter-clockwise about
// (via - start) x (end - start).
bool Executor::Impl::arcThrough(const MachineCmd &c) {
  if (!checkFeed("CIP")) return false;
  if (pf.linear && !pf.similar())
    return error("an arc under a frame that scales its axes unequally is not supported", "unsupported-code");
  if (!c.has(Word::ViaX) && !c.has(Word::ViaY) && !c.has(Word::ViaZ))
    return error("an arc through an intermediate point needs it (via_x via_y via_z: CIP I1 J1 K1)", "arc-invalid");
  if (c.mask & (wordBit(Word::I) | wordBit(Word::J) | wordBit(Word::K) | wordBit(Word::R)))
    return error("an arc through an intermediate point takes no centre or radius", "arc-invalid");
  MachineCmd via;  // the intermediate point reads like an end point (G90/G91, units, frames)
  via.kind = CmdKind::Move;
  for (int i = 0; i < 3; ++i)
    if (c.has((Word)((int)Word::ViaX + i))) via.set((Word)i, c.get((Word)((int)Word::ViaX + i)));
  const AxisVec end = target(c);
  const Vec3 p0 = xyz(st.position), a = sub(xyz(target(via)), p0), b = sub(xyz(end), p0);
  const Vec3 n = cross(a, b);
  double nn = dot(n, n);
  if (norm(a) < kCollinearMM || norm(b) < kCollinearMM || norm(sub(b, a)) < kCollinearMM)
    return error("the start, intermediate and end points of the arc must differ", "arc-invalid");
  if (std::sqrt(nn) / std::max(norm(a), norm(b)) < kCollinearMM)
    return error("the start, intermediate and end points of the arc lie on a line", "arc-invalid");
  // Circumcentre: p0 + (|a|^2 (b x n) + |b|^2 (n x a)) / (2 |n|^2).
  Vec3 off = scaled(cross(b, n), dot(a, a));
  Vec3 off2 = scaled(cross(n, a), dot(b, b));
  Vec3 centre{};
  for (int i = 0; i < 3; ++i) centre[i] = p0[i] + (off[i] + off2[i]) / (2 * nn);
  return emitArc(end, centre, scaled(n, 1 / std::sqrt(nn)), 1);
}

// CT: the arc in the active plane that leaves the start along the path's last direction and
// ends at the end point; the normal axis moves linearly (a helix), as with G2/G3.
bool Executor::Impl::arcTangent(const MachineCmd &c) {
  if (!checkFeed("CT")) return false;
  if (Vec3 tn; pf.tiltOn && !tiltedNormal(tn, &c)) return false;  // an arc turning the chain
  if (pf.linear && !pf.similar())
    return error("an arc under a frame that scales its axes unequally is not supported", "unsupported-code");
  if (c.mask & (wordBit(Word::I) | wordBit(Word::J) | wordBit(Word::K) | wordBit(Word::R)))
    return error("a tangential arc takes no centre or radius", "arc-invalid");
  if (!(c.mask & kAxisMask)) return true;
  const Vec3 nrm = pf.linear ? outLinear().applyLinear(planeNormal(plane())) : planeNormal(plane());
  const Vec3 n = scaled(nrm, 1 / norm(nrm));
  // The tangent and the chord in the plane (their parts along the normal dropped).
  Vec3 t{};
  bool have = pathTangent(t);
  t = sub(t, scaled(n, dot(t, n)));
  if (!have || norm(t) < 1e-9)
    return error("a tangential arc needs a path direction in its plane before it (a G1, G2 or G3 move)", "arc-invalid");
  t = scaled(t, 1 / norm(t));
  const AxisVec end = target(c);
  const Vec3 p0 = xyz(st.position);
  Vec3 d = sub(xyz(end), p0);
  d = sub(d, scaled(n, dot(d, n)));
  const Vec3 left = cross(n, t);  // the centre lies on this side for a counter-clockwise arc
  double across = dot(d, left);
  if (norm(d) < kCollinearMM) return error("a tangential arc needs an end point away from its start", "arc-invalid");
  if (std::fabs(across) < kCollinearMM * norm(d))
    return error("the end point lies on the tangent: no tangential arc reaches it (program a straight line)",
                 "arc-invalid");
  double h = dot(d, d) / (2 * across);  // signed distance of the centre along `left`
  Vec3 centre = p0;
  for (int i = 0; i < 3; ++i) centre[i] += h * left[i];
  return emitArc(end, centre, n, h > 0 ? 1 : -1);
}

}  // namespace ncc
