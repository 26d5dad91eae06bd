// The face-end and cylinder-surface transformations (runtime/Transmit.h): the axis maps, the
// split of a path into straight machine-axis pieces within the chordal tolerance, and the sink.
#include "runtime/Transmit.h"

#include "ir/Diagnostics.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/Library.h"

#include <cmath>
#include <cstring>
#include <fmt/format.h>

namespace ncc {

namespace {

constexpr double kDeg = 180.0 / M_PI;
constexpr int kMaxDepth = 40;          // bisections of one path (2^-40 of it: never reached on a real path)
constexpr size_t kMaxPieces = 1000000;  // pieces of one record

// Machine positions are kept to 1e-9 (mm, degrees), far below any tolerance: a C60 that went
// through the arc length comes back as 60, not 59.99999999999999.
double snap(double v) { return std::round(v * 1e9) / 1e9; }

// The angle equivalent to `a` (degrees) nearest `ref`.
double nearestAngle(double a, double ref) { return a + 360.0 * std::round((ref - a) / 360.0); }

AxisVec lerp(const AxisVec &a, const AxisVec &b, double t) {
  AxisVec r;
  for (int i = 0; i < kAxes; ++i) r[i] = a[i] + (b[i] - a[i]) * t;
  return r;
}

double dist3(const AxisVec &a, const AxisVec &b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Distance of p from the segment a-b (XYZ).
double segmentDistance(const AxisVec &p, const AxisVec &a, const AxisVec &b) {
  double d[3], w[3], dd = 0, dw = 0;
  for (int i = 0; i < 3; ++i) d[i] = b[i] - a[i], w[i] = p[i] - a[i], dd += d[i] * d[i], dw += d[i] * w[i];
  double t = dd > 0 ? std::clamp(dw / dd, 0.0, 1.0) : 0.0;
  return std::hypot(w[0] - t * d[0], w[1] - t * d[1], w[2] - t * d[2]);
}

}  // namespace

AxisVec transformToMachine(const TransformSetup &s, const AxisVec &bcs, const AxisVec &prev, const FaceState &fs) {
  AxisVec m = bcs;
  m[1] = 0;  // the BCS Y is virtual: the machine's Y (if any) stays at 0
  if (s.kind == TransformKind::Cylinder) {
    m[s.rotary] = snap(bcs[1] / s.radius * kDeg);  // unrolled: one turn is 2 pi r
    return m;
  }
  double r = std::hypot(bcs[0], bcs[1]);
  if (r < kPoleEps) {  // at the pole the angle is free: C stays
    m[0] = 0, m[s.rotary] = prev[s.rotary];
    return m;
  }
  double a = std::atan2(bcs[1], bcs[0]) * kDeg;
  if (fs.side < 0) a += 180, r = -r;
  m[0] = snap(r), m[s.rotary] = snap(nearestAngle(a, prev[s.rotary]));
  return m;
}

AxisVec transformToBcs(const TransformSetup &s, const AxisVec &m) {
  AxisVec b = m;
  if (s.kind == TransformKind::Cylinder) {
    b[1] = m[s.rotary] / kDeg * s.radius;
    return b;
  }
  double sn, cs;
  sinCosDegrees(m[s.rotary], sn, cs);
  b[0] = m[0] * cs, b[1] = m[0] * sn;
  return b;
}

bool splitTransformed(const TransformSetup &s, const FaceState &fs, const AxisVec &startMachine,
                      const TransformCurve &curve, const TransformDeviation &deviation, int pieces,
                      std::vector<AxisVec> &out, std::string &err) {
  out.clear();
  // One piece t0..t1 from machine m0 to m1: straight in machine axes when its quarter points
  // lie within the tolerance of the exact path (and C turns by less than 90 degrees, so that the
  // nearest-angle choice of the next point is the path's own); else its halves.
  auto piece = [&](auto &self, double t0, const AxisVec &m0, double t1, const AxisVec &m1, int depth) -> bool {
    bool fits = std::fabs(m1[s.rotary] - m0[s.rotary]) <= 90 + 1e-9;
    for (double k : {0.25, 0.5, 0.75})
      if (fits && deviation(transformToBcs(s, lerp(m0, m1, k)), t0, t1) > s.tolerance) fits = false;
    if (fits) {
      if (out.size() >= kMaxPieces) {
        err = fmt::format("the path needs more than {} pieces within the transformation's tolerance {} mm", kMaxPieces,
                          s.tolerance);
        return false;
      }
      out.push_back(m1);
      return true;
    }
    if (depth >= kMaxDepth) {
      err = "the path cannot be followed within the transformation's tolerance (it passes too close to the pole)";
      return false;
    }
    double tm = (t0 + t1) / 2;
    AxisVec mm = transformToMachine(s, curve(tm), m0, fs);
    return self(self, t0, m0, tm, mm, depth + 1) && self(self, tm, mm, t1, transformToMachine(s, curve(t1), mm, fs), depth + 1);
  };
  // `pieces` equal parts first (an arc about the pole: each under a quarter turn of C), so that
  // the nearest-angle choice at each part's end follows the path.
  AxisVec m0 = startMachine;
  for (int i = 1; i <= pieces; ++i) {
    double t0 = double(i - 1) / pieces, t1 = double(i) / pieces;
    AxisVec m1 = transformToMachine(s, curve(t1), m0, fs);
    if (!piece(piece, t0, m0, t1, m1, 0)) return false;
    m0 = m1;
  }
  return true;
}

AxisVec TransformSink::begin(const TransformSetup &s, const AxisVec &machine) {
  s_ = s;
  fs_ = {};
  pos_ = machine;
  if (s.kind == TransformKind::Face && machine[0] < 0) fs_.side = -1;  // already past the centre
  return transformToBcs(s, machine);
}

bool TransformSink::fail(const MotionRecord &r, std::string msg) {
  if (!failed) diags_.error(r.loc, std::move(msg), "transform");
  failed = true;
  return false;
}

void TransformSink::emitPieces(const MotionRecord &r, const std::vector<AxisVec> &pts) {
  for (size_t i = 0; i < pts.size(); ++i) {
    MotionRecord o;
    o.kind = r.kind == RecordKind::Rapid ? RecordKind::Rapid : RecordKind::Linear;
    o.plane = r.plane;
    o.exactStop = r.exactStop && i + 1 == pts.size();
    o.blockNumber = r.blockNumber;
    o.loc = r.loc;
    o.feed = r.feed;
    o.start = pos_;
    o.end = pts[i];
    pos_ = pts[i];
    out_.record(o);
  }
}

void TransformSink::record(const MotionRecord &r) {
  if (failed) return;
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear: line(r); return;
  case RecordKind::Arc: arc(r); return;
  default: break;
  }
  if (isMoveRecord(r.kind)) {
    fail(r, fmt::format("a {} move is not simulated while a kinematic transformation (TRANSMIT, TRACYL, G12.1, "
                        "G07.1) is active",
                        r.kind == RecordKind::Thread ? "thread" : r.kind == RecordKind::Spline ? "spline" : "probe"));
    return;
  }
  MotionRecord o = r;
  o.start = o.end = pos_;
  out_.record(o);
}

// Leaving the face's pole towards BCS point `toward`: C turns on the spot to the nearer of the
// direction's two angles (X then moves out on the positive or the negative side).
static bool leavePole(const TransformSetup &s, FaceState &fs, const AxisVec &pos, const AxisVec &toward,
                      AxisVec &turned) {
  double a = std::atan2(toward[1], toward[0]) * kDeg;
  double plus = nearestAngle(a, pos[s.rotary]), minus = nearestAngle(a + 180, pos[s.rotary]);
  bool neg = std::fabs(minus - pos[s.rotary]) < std::fabs(plus - pos[s.rotary]);
  fs.side = neg ? -1 : 1;
  turned = pos;
  turned[s.rotary] = neg ? minus : plus;
  return std::fabs(turned[s.rotary] - pos[s.rotary]) > 1e-9;
}

bool TransformSink::line(const MotionRecord &r) {
  const AxisVec &a = r.start, &b = r.end;
  std::vector<AxisVec> pts;
  if (s_.kind == TransformKind::Face) {
    double r0 = std::hypot(a[0], a[1]), r1 = std::hypot(b[0], b[1]);
    double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (r0 < kPoleEps && r1 >= kPoleEps) {
      AxisVec turned;
      if (leavePole(s_, fs_, pos_, b, turned)) emitPieces(r, {turned});
    } else if (r0 >= kPoleEps && r1 >= kPoleEps && len > 0 &&
               std::fabs(a[0] * b[1] - a[1] * b[0]) / len < kPoleEps && a[0] * b[0] + a[1] * b[1] < 0) {
      // Through the pole: the rotary axis stays, X passes the centre to the other side (exact).
      fs_.side = -fs_.side;
      AxisVec m = transformToMachine(s_, b, pos_, fs_);
      m[s_.rotary] = pos_[s_.rotary];
      emitPieces(r, {m});
      return true;
    }
  }
  std::string err;
  auto curve = [&](double t) { return lerp(a, b, t); };
  auto dev = [&](const AxisVec &p, double, double) { return segmentDistance(p, a, b); };
  if (!splitTransformed(s_, fs_, pos_, curve, dev, 1, pts, err)) return fail(r, err);
  emitPieces(r, pts);
  return true;
}

bool TransformSink::arc(const MotionRecord &r) {
  if (r.tiltedArc()) return fail(r, "an arc in a tilted plane is not simulated while a kinematic transformation is active");
  ArcGeometry g = arcGeometry(r);
  auto curve = [&](double t) { return arcPoint(g, r.start, r.end, t); };
  if (s_.kind == TransformKind::Face) {
    // The pole inside the arc: the angle turns half a turn at once there, which no machine path
    // follows (the manual's pole rules are for straight lines).
    for (int i = 1; i < 256; ++i) {
      AxisVec p = curve(i / 256.0);
      if (std::hypot(p[0], p[1]) < std::max(s_.tolerance, kPoleEps) &&
          std::hypot(r.end[0], r.end[1]) >= kPoleEps && std::hypot(r.start[0], r.start[1]) >= kPoleEps)
        return fail(r, "the arc passes through the pole (the centre of the face) of the face-end transformation: "
                       "not simulated; split it there or keep it off the centre");
    }
    if (std::hypot(r.start[0], r.start[1]) < kPoleEps) {
      AxisVec turned;
      if (leavePole(s_, fs_, pos_, curve(1.0 / 4096), turned)) emitPieces(r, {turned});
    }
  }
  auto dev = [&](const AxisVec &p, double t0, double t1) {
    // The nearest point of the arc between t0 and t1, found by its angle about the centre.
    double t = (t0 + t1) / 2;
    if (g.sweep != 0 && !g.tilted) {
      double ang = std::atan2(p[g.ax.v] - g.cv, p[g.ax.u] - g.cu);
      double want = g.startAngle + g.sweep * t;
      ang += 2 * M_PI * std::round((want - ang) / (2 * M_PI));
      t = std::clamp((ang - g.startAngle) / g.sweep, t0, t1);
    }
    return dist3(p, curve(t));
  };
  std::vector<AxisVec> pts;
  std::string err;
  if (!splitTransformed(s_, fs_, pos_, curve, dev, std::max(1, (int)std::ceil(std::fabs(g.sweep) / (M_PI / 2) - 1e-9)), pts, err))
    return fail(r, err);
  emitPieces(r, pts);
  return true;
}

// ---- library entries ------------------------------------------------------------------------

static bool runsInExecutor(const CycleArgs &, const CycleContext &, std::vector<CycleStep> &, std::string &err) {
  err = "a transformation entry runs in the executor";
  return false;
}

void addTransformEntries(std::vector<CycleDef> &out) {
  // ISO = 1: the ISO rules (G12.1, G07.1): the rotary axis word names the surface coordinate and
  // the plane is the transformation's until it ends. AXIS: the rotary axis the program named
  // (3 A, 4 B, 5 C; G07.1 A/B/C), absent: the machine's.
  out.push_back({"trf.TRANSMIT", "N ISO", "face-end (polar) transformation on (Sinumerik TRANSMIT, ISO G12.1)",
                 runsInExecutor, nullptr});
  out.push_back({"trf.TRACYL", "D N K ISO AXIS",
                 "cylinder-surface transformation on, reference diameter D (Sinumerik TRACYL, ISO G07.1)",
                 runsInExecutor, nullptr});
  out.push_back({"trf.TRAFOOF", "ISO", "kinematic transformation off (Sinumerik TRAFOOF, ISO G13.1, G07.1 C0)",
                 runsInExecutor, nullptr});
}

bool isTransformEntry(const CycleDef &def) { return std::strncmp(def.name, "trf.", 4) == 0; }

}  // namespace ncc
