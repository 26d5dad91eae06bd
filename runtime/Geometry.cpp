#include "runtime/Geometry.h"

#include <algorithm>
#include <cmath>

namespace ncc {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kFullCircleChord = 1e-9;  // mm: end this close to start means a full circle
}  // namespace

void sinCosDegrees(double degrees, double &s, double &c) {
  double q = degrees / 90;
  if (q == std::floor(q)) {
    static const double kS[] = {0, 1, 0, -1}, kC[] = {1, 0, -1, 0};
    int k = (int)std::fmod(std::fmod(q, 4) + 4, 4);
    s = kS[k], c = kC[k];
    return;
  }
  double r = degrees * M_PI / 180;
  s = std::sin(r), c = std::cos(r);
}

PlaneAxes planeAxes(Plane p) {
  static const PlaneAxes table[] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};  // XY, ZX, YZ
  return table[(unsigned)p];
}

namespace {
// The sweep and length from the start and end in plane coordinates relative to the centre.
[[gnu::always_inline]] inline void finishArc(ArcGeometry &g, double su, double sv, double eu, double ev, double helix, int turns) {
  g.r0 = std::hypot(su, sv);
  g.r1 = std::hypot(eu, ev);
  g.startAngle = std::atan2(sv, su);
  bool ccw = turns >= 0;
  double d;
  if (std::hypot(eu - su, ev - sv) < kFullCircleChord) {
    d = ccw ? kTwoPi : -kTwoPi;
  } else {
    // Angle from the start to the end vector, robust for tiny arcs (no difference of atan2s).
    d = std::atan2(su * ev - sv * eu, su * eu + sv * ev);
    if (ccw && d <= 0) d += kTwoPi;
    if (!ccw && d >= 0) d -= kTwoPi;
  }
  int extra = std::abs(turns) > 1 ? std::abs(turns) - 1 : 0;
  g.sweep = d + (ccw ? 1 : -1) * extra * kTwoPi;
  g.helix = helix;
  double planar = 0.5 * (g.r0 + g.r1) * std::fabs(g.sweep);
  g.length = std::hypot(planar, g.helix);
}

}  // namespace

double dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3 &a, const Vec3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

ArcGeometry arcGeometry(const AxisVec &start, const AxisVec &end, const Vec3 &center, Plane plane,
                        int turns) {
  ArcGeometry g;
  g.ax = planeAxes(plane);
  g.cu = center[g.ax.u];
  g.cv = center[g.ax.v];
  finishArc(g, start[g.ax.u] - g.cu, start[g.ax.v] - g.cv, end[g.ax.u] - g.cu, end[g.ax.v] - g.cv,
            end[g.ax.n] - start[g.ax.n], turns);
  return g;
}

ArcGeometry tiltedArcGeometry(const AxisVec &start, const AxisVec &end, const Vec3 &center, const Vec3 &normal,
                              int turns) {
  ArcGeometry g;
  TiltedFrame &f = g.tilted.make();
  f.c = center;
  f.n = normal;
  Vec3 s{start[0] - center[0], start[1] - center[1], start[2] - center[2]};
  Vec3 e{end[0] - center[0], end[1] - center[1], end[2] - center[2]};
  f.n0 = dot(s, f.n);
  Vec3 sp{s[0] - f.n0 * f.n[0], s[1] - f.n0 * f.n[1], s[2] - f.n0 * f.n[2]};
  double r0 = std::sqrt(dot(sp, sp));
  if (r0 > 0) {
    f.u = {sp[0] / r0, sp[1] / r0, sp[2] / r0};
  } else {  // start on the axis: any direction in the plane
    int k = std::fabs(f.n[0]) < 0.9 ? 0 : 1;
    Vec3 a{};
    a[k] = 1;
    f.u = cross(cross(f.n, a), f.n);
    double l = std::sqrt(dot(f.u, f.u));
    for (double &x : f.u) x /= l;
  }
  f.v = cross(f.n, f.u);
  finishArc(g, r0, 0, dot(e, f.u), dot(e, f.v), dot(e, f.n) - f.n0, turns);
  return g;
}

ArcGeometry arcGeometry(const MotionRecord &r) {
  if (r.tiltedArc()) return tiltedArcGeometry(r.start, r.end, r.center, r.arcNormal(), r.turns);
  return arcGeometry(r.start, r.end, r.center, r.plane, r.turns);
}

Vec3 arcAxisShare(const ArcGeometry &g) {
  Vec3 share{};
  if (g.length <= 0) return share;
  double planar = 0.5 * (g.r0 + g.r1) * std::fabs(g.sweep) / g.length;
  double helix = std::fabs(g.helix) / g.length;
  if (!g.tilted) {
    share[g.ax.u] = share[g.ax.v] = planar;
    share[g.ax.n] = helix;
    return share;
  }
  // The planar velocity turns through the plane: on axis i it peaks at |(u_i, v_i)|.
  const TiltedFrame &f = *g.tilted;
  for (int i = 0; i < 3; ++i) share[i] = planar * std::hypot(f.u[i], f.v[i]) + helix * std::fabs(f.n[i]);
  return share;
}

// The length of a straight move as rs274 measures it: X Y Z, else U V W (parallel linear
// axes), else A B C (degrees).
double linearLength(const AxisVec &a, const AxisVec &b) {
  for (int first : {0, 6, 3}) {
    double l = std::sqrt((b[first] - a[first]) * (b[first] - a[first]) + (b[first + 1] - a[first + 1]) * (b[first + 1] - a[first + 1]) +
                         (b[first + 2] - a[first + 2]) * (b[first + 2] - a[first + 2]));
    if (l > 1e-12 || first == 3) return l;
  }
  return 0;
}

AxisVec unitDirection(const AxisVec &start, const AxisVec &end, double length) {
  AxisVec u{};
  if (length <= 0) return u;
  for (int i = 0; i < kAxes; ++i) u[i] = (end[i] - start[i]) / length;
  return u;
}

AxisVec arcPoint(const ArcGeometry &g, const AxisVec &start, const AxisVec &end, double s) {
  if (s <= 0) return start;
  if (s >= 1) return end;
  AxisVec p;
  for (int i = 0; i < kAxes; ++i) p[i] = start[i] + (end[i] - start[i]) * s;
  double a = g.startAngle + g.sweep * s;
  double r = g.r0 + (g.r1 - g.r0) * s;
  if (g.tilted) {
    const TiltedFrame &f = *g.tilted;
    double pu = r * std::cos(a), pv = r * std::sin(a), pn = f.n0 + g.helix * s;
    for (int i = 0; i < 3; ++i) p[i] = f.c[i] + pu * f.u[i] + pv * f.v[i] + pn * f.n[i];
    return p;
  }
  p[g.ax.u] = g.cu + r * std::cos(a);
  p[g.ax.v] = g.cv + r * std::sin(a);
  return p;
}

Vec3 arcTangent(const ArcGeometry &g, double s) {
  double a = g.startAngle + g.sweep * s;
  double r = g.r0 + (g.r1 - g.r0) * s;
  double c = std::cos(a), sn = std::sin(a);
  double dr = g.r1 - g.r0;
  Vec3 t{};
  double tu = dr * c - r * sn * g.sweep, tv = dr * sn + r * c * g.sweep;
  if (g.tilted) {
    const TiltedFrame &f = *g.tilted;
    for (int i = 0; i < 3; ++i) t[i] = tu * f.u[i] + tv * f.v[i] + g.helix * f.n[i];
  } else {
    t[g.ax.u] = tu;
    t[g.ax.v] = tv;
    t[g.ax.n] = g.helix;
  }
  double l = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  if (l <= 0) return Vec3{};
  for (double &x : t) x /= l;
  return t;
}

double arcCurvature(const ArcGeometry &g) {
  double rm = 0.5 * (g.r0 + g.r1);
  if (rm <= 0 || g.sweep == 0) return 0;
  double c = g.helix / g.sweep;
  return rm / (rm * rm + c * c);
}

void arcBounds(const ArcGeometry &g, const AxisVec &start, const AxisVec &end, Vec3 &lo, Vec3 &hi) {
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::fmin(start[i], end[i]);
    hi[i] = std::fmax(start[i], end[i]);
  }
  double span = std::fabs(g.sweep);
  if (g.tilted) {
    // Axis i is extreme where the circle's direction is across it: angle atan2(v_i, u_i) (+ pi).
    for (int k = 0; k < 6; ++k) {
      double a = std::atan2(g.tilted->v[k / 2], g.tilted->u[k / 2]) + (k % 2) * (kTwoPi / 2);
      double delta = std::fmod(g.sweep >= 0 ? a - g.startAngle : g.startAngle - a, kTwoPi);
      if (delta < 0) delta += kTwoPi;
      if (delta > span || span <= 0) continue;
      AxisVec p = arcPoint(g, start, end, delta / span);
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::fmin(lo[i], p[i]);
        hi[i] = std::fmax(hi[i], p[i]);
      }
    }
    return;
  }
  for (int k = 0; k < 4; ++k) {
    double a = k * (kTwoPi / 4);
    // Angular distance from the start to this extreme, in the direction of travel.
    double delta = g.sweep >= 0 ? a - g.startAngle : g.startAngle - a;
    delta = std::fmod(delta, kTwoPi);
    if (delta < 0) delta += kTwoPi;
    if (delta > span) continue;
    double s = span > 0 ? delta / span : 0;
    double r = g.r0 + (g.r1 - g.r0) * s;
    double pu = g.cu + r * std::cos(a), pv = g.cv + r * std::sin(a);
    lo[g.ax.u] = std::fmin(lo[g.ax.u], pu);
    hi[g.ax.u] = std::fmax(hi[g.ax.u], pu);
    lo[g.ax.v] = std::fmin(lo[g.ax.v], pv);
    hi[g.ax.v] = std::fmax(hi[g.ax.v], pv);
  }
}

void polarStep(double &x, double &y, bool incremental, bool hasRadius, double radius, bool hasAngle,
               double degrees) {
  double r = std::hypot(x, y), a = std::atan2(y, x);
  double da = degrees * M_PI / 180;
  if (incremental) {
    r += hasRadius ? radius : 0;
    a += hasAngle ? da : 0;
  } else {
    r = hasRadius ? radius : r;
    a = hasAngle ? da : a;
  }
  x = r * std::cos(a);
  y = r * std::sin(a);
}

SplineCurve::SplineCurve(const MotionRecord &r) : degree_(r.spline().degree) {
  const SplineData &s = r.spline();
  size_t n = s.count();
  knots_ = s.knots.empty() ? splineDefaultKnots(n, degree_) : s.knots;
  end_ = {r.end[0], r.end[1], r.end[2]};
  cp_.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    Vec3 p = i == 0 ? Vec3{r.start[0], r.start[1], r.start[2]} : i + 1 == n ? end_ : s.points[i - 1];
    double w = s.weights.empty() ? 1 : s.weights[i];
    cp_.push_back({p[0] * w, p[1] * w, p[2] * w, w});
  }
  size_t spans = 0;
  for (size_t k = 0; k + 1 < knots_.size(); ++k) spans += knots_[k + 1] > knots_[k];
  while (maxDepth_ > 0 && (spans << (maxDepth_ + 2)) > (size_t{1} << 16)) --maxDepth_;
}

Vec3 SplineCurve::at(double u) const {
  const int p = degree_;
  // The span [k_s, k_s+1) holding u; u at (or past) the end uses the last non-empty span.
  size_t s = (size_t)p;
  size_t last = cp_.size() - 1;
  if (u >= knots_[last + 1]) s = last;
  else
    while (s < last && knots_[s + 1] <= u) ++s;
  std::array<std::array<double, 4>, 16> d;
  for (int j = 0; j <= p; ++j) d[j] = cp_[s - p + j];
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      double a0 = knots_[s - p + j], a1 = knots_[s + 1 + j - r];
      double alpha = a1 > a0 ? (u - a0) / (a1 - a0) : 0;
      for (int c = 0; c < 4; ++c) d[j][c] = (1 - alpha) * d[j - 1][c] + alpha * d[j][c];
    }
  return {d[p][0] / d[p][3], d[p][1] / d[p][3], d[p][2] / d[p][3]};
}

double SplineCurve::chordError(double ua, const Vec3 &pa, double ub, const Vec3 &pb) const {
  Vec3 ch{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
  double len2 = ch[0] * ch[0] + ch[1] * ch[1] + ch[2] * ch[2], worst = 0;
  for (double f : {0.25, 0.5, 0.75}) {
    Vec3 q = at(ua + (ub - ua) * f);
    Vec3 d{q[0] - pa[0], q[1] - pa[1], q[2] - pa[2]};
    double t = len2 > 0 ? std::clamp((d[0] * ch[0] + d[1] * ch[1] + d[2] * ch[2]) / len2, 0.0, 1.0) : 0;
    double e = std::hypot(d[0] - t * ch[0], d[1] - t * ch[1], d[2] - t * ch[2]);
    worst = std::max(worst, e);
  }
  return worst;
}

double splineLength(const MotionRecord &r) { return splinePath(r).length(); }

void splineBounds(const MotionRecord &r, Vec3 &lo, Vec3 &hi) {
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = r.start[i];
  SplineCurve(r).flatten(kSplineTolerance, [&](const Vec3 &q, double) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], q[i]), hi[i] = std::max(hi[i], q[i]);
  });
}

static Vec3 unitOf(const Vec3 &a, const Vec3 &b) {
  Vec3 d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  double l = std::hypot(d[0], d[1], d[2]);
  if (l > 0)
    for (double &v : d) v /= l;
  return d;
}

SplinePath splinePath(const MotionRecord &r) {
  SplinePath p;
  p.pts.push_back({r.start[0], r.start[1], r.start[2]});
  p.cum.push_back(0);
  SplineCurve curve(r);
  double ua = curve.u0();
  auto dist = [](const Vec3 &a, const Vec3 &b) { return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]); };
  curve.flatten(kSplineTolerance, [&](const Vec3 &q, double u) {
    const Vec3 &a = p.pts.back();
    double l = dist(a, q);
    Vec3 m = curve.at(0.5 * (ua + u));
    double arc = (4 * (dist(a, m) + dist(m, q)) - l) / 3;  // Richardson: the chord's error is O(h^2)
    ua = u;
    if (l > 0)
      for (int i = 0; i < 3; ++i) p.share[i] = std::max(p.share[i], std::fabs(q[i] - a[i]) / l);
    if (p.pts.size() >= 2 && l > 0) {
      const Vec3 &z = p.pts[p.pts.size() - 2];
      double l0 = p.cum.back() - p.cum[p.cum.size() - 2];
      Vec3 u = unitOf(z, a), v = unitOf(a, q);
      double c = std::clamp(u[0] * v[0] + u[1] * v[1] + u[2] * v[2], -1.0, 1.0);
      if (l0 > 0) p.maxCurvature = std::max(p.maxCurvature, 2 * std::sqrt(0.5 * (1 - c)) / (0.5 * (l0 + l)));
    }
    p.pts.push_back(q);
    p.cum.push_back(p.cum.back() + std::max(arc, l));
  });
  return p;
}

Vec3 SplinePath::at(double s) const {
  if (!(s > 0)) return pts.front();
  if (s >= cum.back()) return pts.back();
  size_t i = (size_t)(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());  // cum[i-1] <= s < cum[i]
  double f = (s - cum[i - 1]) / (cum[i] - cum[i - 1]);
  const Vec3 &a = pts[i - 1], &b = pts[i];
  return {a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f};
}

Vec3 SplinePath::startTangent() const {
  for (size_t i = 1; i < pts.size(); ++i)
    if (cum[i] > 0) return unitOf(pts[0], pts[i]);
  return {};
}

Vec3 SplinePath::endTangent() const {
  for (size_t i = pts.size() - 1; i-- > 0;)
    if (cum.back() > cum[i]) return unitOf(pts[i], pts.back());
  return {};
}

}  // namespace ncc
