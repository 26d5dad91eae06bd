// Sinumerik spline interpolation ASPLINE, BSPLINE, CSPLINE (manual L10596-L10860) on the core's
// Spline record. Every move block under a spline mode adds a point; at the spline's end:
//  - BSPLINE: one record, the clamped B-spline of degree SD (3, or 2) with the start and the
//    programmed points as its control polygon, weights PW, uniform knots (docs/SINUMERIK.md);
//  - CSPLINE: one cubic record per block, the C2 cubic spline through the points;
//  - ASPLINE: one cubic record per block, the Akima spline through the points;
// A and C splines take one parameter unit per block; their ends follow BNAT/BAUTO/BTAN and
// ENAT/EAUTO (ETAN needs the block after the spline: refused).
#include "runtime/ExecutorImpl.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

namespace {
const char *splineName(ModeValue k) {
  return k == ModeValue::SplineAkima ? "ASPLINE" : k == ModeValue::SplineB ? "BSPLINE" : "CSPLINE";
}
Vec3 at(const AxisVec &p) { return {p[0], p[1], p[2]}; }
Vec3 lin(double a, const Vec3 &x, double b, const Vec3 &y) {
  return {a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2]};
}
double len(const Vec3 &v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The tangents (derivatives per parameter unit) of the C2 cubic spline through p with the
// given end conditions: the tridiagonal system D[i-1] + 4 D[i] + D[i+1] = 3 (p[i+1] - p[i-1]).
std::vector<Vec3> cubicTangents(const std::vector<Vec3> &p, ModeValue start, ModeValue end, const Vec3 &t0) {
  const size_t n = p.size() - 1;
  std::vector<double> a(n + 1), b(n + 1), c(n + 1);
  std::vector<Vec3> r(n + 1);
  for (size_t i = 1; i < n; ++i) a[i] = 1, b[i] = 4, c[i] = 1, r[i] = lin(3, p[i + 1], -3, p[i - 1]);
  // Start: zero curvature 2 D0 + D1 = 3 (p1 - p0); auto: the parabola through the first three
  // points; tangent: the incoming direction with the first chord's length.
  if (start == ModeValue::StartNatural || n == 1) b[0] = 2, c[0] = 1, r[0] = lin(3, p[1], -3, p[0]);
  else if (start == ModeValue::StartAuto) b[0] = 1, r[0] = lin(-1.5, p[0], 2, p[1]), r[0] = lin(1, r[0], -0.5, p[2]);
  else b[0] = 1, r[0] = lin(len(lin(1, p[1], -1, p[0])), t0, 0, t0);
  if (end == ModeValue::EndNatural || n == 1) a[n] = 1, b[n] = 2, r[n] = lin(3, p[n], -3, p[n - 1]);
  else b[n] = 1, r[n] = lin(0.5, p[n - 2], -2, p[n - 1]), r[n] = lin(1, r[n], 1.5, p[n]);
  if (n == 1 && start == ModeValue::StartTangent) b[0] = 1, c[0] = 0, r[0] = lin(len(lin(1, p[1], -1, p[0])), t0, 0, t0);
  // Thomas algorithm (the matrix is diagonally dominant inside; the end rows keep it solvable).
  for (size_t i = 1; i <= n; ++i) {
    double m = a[i] / b[i - 1];
    b[i] -= m * c[i - 1];
    r[i] = lin(1, r[i], -m, r[i - 1]);
  }
  std::vector<Vec3> d(n + 1);
  d[n] = lin(1 / b[n], r[n], 0, r[n]);
  for (size_t i = n; i-- > 0;) d[i] = lin(1 / b[i], lin(1, r[i], -c[i], d[i + 1]), 0, r[i]);
  return d;
}

// The tangents of the Akima spline through p: at each point the mean of the neighbouring
// chords weighted by how much the chords beyond them turn (vector norms, so the curve turns
// with the points), chords beyond the ends extended linearly; natural ends zero curvature.
std::vector<Vec3> akimaTangents(const std::vector<Vec3> &p, ModeValue start, ModeValue end, const Vec3 &t0) {
  const size_t n = p.size() - 1;
  std::vector<Vec3> m(n + 4);  // m[k + 2] is chord k, k = -2 … n + 1
  for (size_t k = 0; k < n; ++k) m[k + 2] = lin(1, p[k + 1], -1, p[k]);
  std::vector<Vec3> d(n + 1);
  if (n == 1) {
    d[0] = d[1] = m[2];
  } else {
    m[1] = lin(2, m[2], -1, m[3]), m[0] = lin(2, m[1], -1, m[2]);
    m[n + 2] = lin(2, m[n + 1], -1, m[n]), m[n + 3] = lin(2, m[n + 2], -1, m[n + 1]);
    for (size_t i = 0; i <= n; ++i) {
      double w1 = len(lin(1, m[i + 3], -1, m[i + 2])), w2 = len(lin(1, m[i + 1], -1, m[i]));
      d[i] = w1 + w2 > 1e-12 * (len(m[i + 1]) + len(m[i + 2])) ? lin(w1 / (w1 + w2), m[i + 1], w2 / (w1 + w2), m[i + 2])
                                                               : lin(0.5, m[i + 1], 0.5, m[i + 2]);
    }
  }
  // Zero curvature at an end of a cubic Hermite segment: D0 = (3 m0 - D1) / 2.
  if (start == ModeValue::StartNatural) d[0] = lin(1.5, m[2], -0.5, d[1]);
  if (start == ModeValue::StartTangent) d[0] = lin(len(m[2]), t0, 0, t0);
  if (end == ModeValue::EndNatural) d[n] = lin(1.5, m[n + 1], -0.5, d[n - 1]);
  return d;
}

// Whether the frame keeps angles (rotation, mirror, uniform scale): the Akima weights are
// computed in machine coordinates and are the program's only then.
bool keepsAngles(const FrameValue &f) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += f.L[k][0] * f.L[k][0];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double g = 0;
      for (int k = 0; k < 3; ++k) g += f.L[k][i] * f.L[k][j];
      if (std::fabs(g - (i == j ? s : 0)) > 1e-12 * s) return false;
    }
  return true;
}
}  // namespace

bool Executor::Impl::sinSplinePoint(const MachineCmd &c) {
  const char *name = splineName(st.motion);
  if (corner.requested) {
    corner.requested = false;
    return error(fmt::format("CHF, CHR or RND at a point of a {} is not simulated", name), "unsupported-code");
  }
  if (c.has(Word::SplineWeight) && st.motion != ModeValue::SplineB)
    return error(fmt::format("PW= (a point's weight) is for BSPLINE, not {}", name), "spline-invalid");
  if (c.has(Word::PolyInterval))
    return error(fmt::format("PL= (knot distances) with {} is not simulated: ncc takes uniform knots", name), "unsupported-code");
  if (c.has(Word::SplineDegree) && st.motion != ModeValue::SplineB)
    return error(fmt::format("SD= (the spline's degree) is for BSPLINE, not {}", name), "spline-invalid");
  if (!(c.mask & kAxisMask)) {
    if (c.mask & (wordBit(Word::SplineWeight) | wordBit(Word::SplineDegree)))
      return error(fmt::format("PW= and SD= belong to a point of the {} (a block with axis positions)", name), "spline-invalid");
    return true;
  }
  if (!compForbids("splines under cutter radius compensation (G41/G42) are not simulated")) return false;
  if (st.feedMode == ModeValue::InverseTime || cssPerRev())
    return error(fmt::format("{} in inverse time (G93) or under constant cutting rate (G96) is not simulated", name),
                 "unsupported-code");
  if (!checkFeed(name)) return false;
  if (st.motion == ModeValue::SplineAkima && !keepsAngles(programmableFrame()))
    return error("ASPLINE under a frame that scales the axes differently is not simulated", "unsupported-code");
  const AxisVec to = target(c);
  for (int i = 3; i < kAxes; ++i)
    if (to[i] != st.position[i])
      return error(fmt::format("{} moves X, Y and Z only; {} is not simulated in a spline", name, kWordKeys[i]),
                   "unsupported-code");
  SinSpline &s = sinSpline;
  // A point on the last one adds no segment (its tangent would be undefined).
  const AxisVec &last = s.open ? s.points.back() : st.position;
  if (to[0] == last[0] && to[1] == last[1] && to[2] == last[2]) return true;
  if (!s.open) {
    s = SinSpline{};
    if (st.splineEnd == ModeValue::EndTangent && st.motion != ModeValue::SplineB)
      return error("ETAN (a tangential end to the block after the spline) is not simulated", "unsupported-code");
    if (st.splineStart == ModeValue::StartTangent && st.motion != ModeValue::SplineB) {
      Vec3 t;
      if (!pathTangent(t))
        return error("BTAN needs a straight or circular move before the spline to be tangent to", "spline-invalid");
      s.startTangent = t, s.hasStartTangent = true;
    }
    s.open = true;
    s.kind = st.motion;
    s.points.push_back(st.position);
    s.weights.push_back(1.0);
  }
  int degree = c.has(Word::SplineDegree) ? (int)c.get(Word::SplineDegree) : s.degree;
  if (c.has(Word::SplineDegree) && c.get(Word::SplineDegree) != 2 && c.get(Word::SplineDegree) != 3)
    return error("SD= takes 2 or 3 (the degree of the B-spline)", "spline-invalid");
  if (degree != s.degree && s.segs.size() > 0)
    return error("SD= changes the degree inside a B-spline: not simulated", "unsupported-code");
  s.degree = degree;
  double w = c.has(Word::SplineWeight) ? c.get(Word::SplineWeight) : 1.0;
  if (!(w > 0 && w <= 3))
    return error(fmt::format("PW={} is not simulated: ncc takes weights above 0 up to 3", w), "spline-invalid");
  s.points.push_back(to);
  s.weights.push_back(w);
  s.segs.push_back({blockNumber, loc, moveFeed(0), st.pathMode == ModeValue::ExactStop});
  st.position = to;
  return true;
}

bool Executor::Impl::sinSplineEnd() {
  SinSpline s = std::move(sinSpline);
  sinSpline = SinSpline{};
  sinSpline.flushing = true;  // emit() passes the records through
  const SourceLoc here = loc;
  auto fail = [&](std::string msg, const char *rule) {
    loc = s.segs.front().loc;
    error(std::move(msg), rule);
    loc = here;
    sinSpline.flushing = false;
    return false;
  };
  size_t nextHeld = 0;
  auto releaseHeld = [&](size_t segsDone) {
    for (; nextHeld < s.held.size() && s.held[nextHeld].first <= segsDone; ++nextHeld) emit(s.held[nextHeld].second);
  };
  auto curve = [&](size_t from, size_t to, SplineData d, const SinSpline::Seg &g) {
    MotionRecord r = record(RecordKind::Spline);
    r.start = s.points[from];
    r.end = s.points[to];
    r.blockNumber = g.blockNumber, r.loc = g.loc;
    r.feed = g.feed;
    r.exactStop = g.exactStop;
    r.setSpline(std::move(d));
    if (std::string why = splineError(r); !why.empty()) return fail(why, "spline-invalid");
    return emitMove(r);
  };
  std::vector<Vec3> p;
  for (auto &q : s.points) p.push_back(at(q));
  bool ok = true;
  if (s.kind == ModeValue::SplineB) {
    // One curve over all points: its feed and block are the last block's; a feed change inside
    // would need the feed along the curve.
    for (auto &g : s.segs)
      if (g.feed != s.segs.front().feed) return fail("a feed change inside a BSPLINE is not simulated", "unsupported-code");
    if (p.size() < (size_t)s.degree + 1)
      return fail(fmt::format("a BSPLINE of degree {} needs at least {} points after its start, not {}", s.degree,
                              s.degree, s.segs.size()),
                  "spline-invalid");
    SplineData d;
    d.degree = s.degree;
    d.points.assign(p.begin() + 1, p.end() - 1);
    bool weighted = false;
    for (double w : s.weights) weighted = weighted || w != 1;
    if (weighted) d.weights = s.weights;
    ok = curve(0, p.size() - 1, std::move(d), s.segs.back());
    releaseHeld(s.segs.size());
  } else {
    const Vec3 t0 = s.startTangent;
    std::vector<Vec3> d = s.kind == ModeValue::SplineC ? cubicTangents(p, st.splineStart, st.splineEnd, t0)
                                                       : akimaTangents(p, st.splineStart, st.splineEnd, t0);
    // Each block's cubic as a Bezier curve: its end points and p ± D/3.
    for (size_t i = 0; ok && i + 1 < p.size(); ++i) {
      releaseHeld(i);
      SplineData b;
      b.degree = 3;
      b.points = {lin(1, p[i], 1.0 / 3, d[i]), lin(1, p[i + 1], -1.0 / 3, d[i + 1])};
      ok = curve(i, i + 1, std::move(b), s.segs[i]);
    }
    if (ok) releaseHeld(s.segs.size());
  }
  sinSpline.flushing = false;
  return ok;
}

}  // namespace ncc

namespace ncc {

// POLY (manual L11043-L11259): per axis f(p) = a0 + a1·p + a2·p² + … + a5·p⁵ on 0 <= p <= PL with
// a0 the start and a1 such that f(PL) is the programmed end; PO[]=(…) a common denominator
// d(p) = 1 + d1·p + d2·p² … (its first value d(PL), d1 from it the same way) that divides the
// geometry axes, the numerator then ending on end · d(PL). The curve is the Bezier curve of the
// polynomials over t = p / PL (rational with the denominator's Bernstein coefficients as weights),
// computed in program coordinates and mapped to the machine point by point.
bool Executor::Impl::polyCoefficients(const MachineCmd &c) {
  if (st.motion != ModeValue::Poly) {  // without POLY the axes move linearly as G1 (L11205)
    poly.outside = true;
    return true;
  }
  const double k = c.get(Word::PolyIndex);
  if (k != std::floor(k) || k < 2 || k > 5) return error("a POLY coefficient index is 2 to 5", "spline-invalid");
  for (int i = 3; i < kAxes; ++i)
    if (c.has((Word)i)) return error(fmt::format("POLY on {} is not simulated (X, Y and Z only)", kWordKeys[i]), "unsupported-code");
  for (int i = 0; i < 3; ++i)
    if (c.has((Word)i)) poly.a[(int)k][i] = c.get((Word)i);
  if (c.has(Word::PolyDenominator)) poly.a[(int)k][3] = c.get(Word::PolyDenominator);
  poly.any = true;
  return true;
}

bool Executor::Impl::polyOutsideMove() {
  poly.outside = false;
  if (st.motion == ModeValue::Linear) return true;
  return error(fmt::format("PO[…] without POLY moves linearly (G1) to its end points (L11205); under {} that is not "
                           "simulated",
                           modeValueInfo(st.motion).name),
               "unsupported-code");
}

bool Executor::Impl::polyMove(const MachineCmd &c) {
  const Poly pc = poly;
  poly = Poly{};
  if (!(c.mask & kAxisMask)) return true;
  const bool den = c.has(Word::PolyDenominator);
  int m = 1;
  for (int k = 2; k <= 5; ++k)
    for (int i = 0; i < 4; ++i)
      if (pc.a[k][i] != 0) m = std::max(m, k);
  if (m == 1 && !den) {  // every axis linear: as G1 (L11108)
    if (!checkFeed("POLY")) return false;
    return moveTo(RecordKind::Linear, target(c));
  }
  if (st.distance == ModeValue::Incremental || c.sub)
    return error("POLY with polynomials under G91 or IC() is not simulated (write absolute end points)", "unsupported-code");
  if (st.units == ModeValue::Inch) return error("POLY with polynomials in inch (G700) is not simulated", "unsupported-code");
  if (!compForbids("POLY under cutter radius compensation (G41/G42) is not simulated")) return false;
  if (st.feedMode == ModeValue::InverseTime) return error("POLY in inverse time (G93) is not simulated", "unsupported-code");
  if (!checkFeed("POLY")) return false;
  const double pl = c.has(Word::PolyInterval) ? c.get(Word::PolyInterval) : 1.0;
  if (!(pl > 0)) return error("PL (the parameter interval of POLY) must be positive", "spline-invalid");
  const AxisVec endMachine = target(c);
  for (int i = 3; i < kAxes; ++i)
    if (endMachine[i] != st.position[i])
      return error(fmt::format("POLY moves X, Y and Z only along its curve; {} is not simulated", kWordKeys[i]),
                   "unsupported-code");
  AxisVec start = programPosition(), end = start;
  {
    AxisVec f = linearFrame() ? frameIn(endMachine) : endMachine;
    for (int i = 0; i < 3; ++i) end[i] = f[i] - frameOffset(i);
  }
  // Power coefficients over t = p / PL: c[k] = a_k · PL^k; index 3 the denominator.
  double cf[6][4] = {};
  const double de = den ? c.get(Word::PolyDenominator) : 1.0;
  for (int i = 0; i < 4; ++i) {
    double a0 = i < 3 ? start[i] : 1.0, ae = i < 3 ? end[i] * de : de, rest = 0;
    for (int k = 2; k <= 5; ++k) cf[k][i] = pc.a[k][i] * std::pow(pl, k), rest += cf[k][i];
    cf[0][i] = a0;
    cf[1][i] = ae - a0 - rest;
  }
  // Bernstein coefficients of degree m: b_j = Σ_{k<=j} C(j,k) / C(m,k) · c_k.
  auto binom = [](int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
  };
  std::vector<std::array<double, 3>> pts;
  std::vector<double> weights;
  for (int j = 0; j <= m; ++j) {
    double b[4] = {};
    for (int k = 0; k <= j; ++k)
      for (int i = 0; i < 4; ++i) b[i] += binom(j, k) / binom(m, k) * cf[k][i];
    if (!(b[3] > 0))
      return error("the POLY denominator gives a Bezier weight that is not positive: not simulated", "unsupported-code");
    AxisVec p = start;
    for (int i = 0; i < 3; ++i) p[i] = b[i] / b[3] + frameOffset(i);
    if (j == m) p = endMachine;  // the end exactly as programmed
    else if (linearFrame()) p = frameOut(p);
    if (j == 0) p = st.position;
    pts.push_back({p[0], p[1], p[2]});
    weights.push_back(b[3]);
  }
  bool weighted = false;
  for (double w : weights) weighted = weighted || w != 1;
  return emitSpline(pts, m + 1, weighted ? weights : std::vector<double>{});
}

}  // namespace ncc
