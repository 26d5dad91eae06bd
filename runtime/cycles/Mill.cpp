#include "runtime/cycles/Mill.h"

#include "runtime/Geometry.h"

#include <cmath>

namespace ncc {

Contour roundedRect(double a, double b, double rc) {
  Contour c;
  c.start = {a, 0};
  // Corners counter-clockwise from the upper right: the side to the corner, then its arc.
  static const double kSign[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  PlanePoint at = c.start;
  auto line = [&](PlanePoint to) {
    if (std::hypot(to[0] - at[0], to[1] - at[1]) > 1e-12) c.segs.push_back({to, false, {}, true});
    at = to;
  };
  for (int k = 0; k < 4; ++k) {
    double sx = kSign[k][0], sy = kSign[k][1];
    // Entering corner k along x (k odd) or along y (k even).
    PlanePoint from = k % 2 == 0 ? PlanePoint{sx * a, sy * (b - rc)} : PlanePoint{sx * (a - rc), sy * b};
    PlanePoint to = k % 2 == 0 ? PlanePoint{sx * (a - rc), sy * b} : PlanePoint{sx * a, sy * (b - rc)};
    line(from);
    if (rc > 0) c.segs.push_back({to, true, {sx * (a - rc), sy * (b - rc)}, true});
    at = to;
  }
  line(c.start);
  return c;
}

Contour circleContour(double r) {
  Contour c;
  c.start = {r, 0};
  c.segs.push_back({c.start, true, {0, 0}, true});
  return c;
}

Contour halfTurn(Contour c) {
  auto turn = [](PlanePoint &p) { p = {-p[0], -p[1]}; };
  turn(c.start);
  for (PathSeg &s : c.segs) turn(s.end), turn(s.centre);
  return c;
}

double arcSweep(PlanePoint from, const PathSeg &s) {
  double a0 = std::atan2(from[1] - s.centre[1], from[0] - s.centre[0]);
  double a1 = std::atan2(s.end[1] - s.centre[1], s.end[0] - s.centre[0]);
  double sweep = s.ccw ? a1 - a0 : a0 - a1;
  if (sweep <= 1e-12) sweep += 2 * M_PI;
  return sweep;
}

Polygon contourPolygon(const Contour &c, double tol) {
  Polygon out;
  PlanePoint at = c.start;
  for (const PathSeg &s : c.segs) {
    if (s.arc) {
      double r = std::hypot(at[0] - s.centre[0], at[1] - s.centre[1]);
      double a0 = std::atan2(at[1] - s.centre[1], at[0] - s.centre[0]);
      double sweep = arcSweep(at, s);
      // The region lies left of the contour: inside a counter-clockwise arc, whose chords (corners
      // on it, half-angle h) sag r (1 - cos h) <= tol inward; outside a clockwise one, which gets
      // tangents instead (corners r / cos h out), so the polygon never takes in material.
      const double dirSign = s.ccw ? 1 : -1;
      double h = r > tol ? (s.ccw ? std::acos(1 - tol / r) : std::acos(r / (r + tol))) : M_PI / 2;
      int n = std::max(1, (int)std::ceil(sweep / (2 * h)));
      out.push_back(at);
      for (int i = s.ccw ? 1 : 0; i < n; ++i) {
        double t = a0 + dirSign * sweep * (s.ccw ? i : i + 0.5) / n;
        double rr = s.ccw ? r : r / std::cos(sweep / (2 * n));
        out.push_back({s.centre[0] + rr * std::cos(t), s.centre[1] + rr * std::sin(t)});
      }
    } else {
      out.push_back(at);
    }
    at = s.end;
  }
  return out;
}

Mill::Mill(std::vector<CycleStep> &out, int plane, PlanePoint origin, double degrees, double dir,
           std::array<double, 3> at)
    : out_(out), origin_(origin), dir_(dir) {
  PlaneAxes ax = planeAxes((Plane)plane);
  u_ = ax.u, v_ = ax.v, n_ = ax.n;
  sinCosDegrees(degrees, s_, c_);
  double du = at[u_] - origin[0], dv = at[v_] - origin[1];
  here_ = {c_ * du + s_ * dv, -s_ * du + c_ * dv};
  level_ = at[n_];
}

std::array<double, 3> Mill::place(PlanePoint p, double level) const {
  // Rounded to 1e-9 mm: levels like 9.8 - 2 print as 7.8, not 7.800000000000001.
  auto tidy = [](double x) { return std::round(x * 1e9) / 1e9; };
  std::array<double, 3> q{};
  q[u_] = tidy(origin_[0] + c_ * p[0] - s_ * p[1]);
  q[v_] = tidy(origin_[1] + s_ * p[0] + c_ * p[1]);
  q[n_] = tidy(level);
  return q;
}

void Mill::step(CycleStepKind k, PlanePoint p, double level, double f) {
  CycleStep st;
  st.kind = k;
  st.pos = place(p, level);
  st.feed = f;
  out_.push_back(st);
  here_ = p, level_ = level;
}

void Mill::rapid(PlanePoint p, double level) { step(CycleStepKind::Rapid, p, level, 0); }
void Mill::feed(PlanePoint p, double level, double f) { step(CycleStepKind::Feed, p, level, f); }

void Mill::arc(PlanePoint end, PlanePoint centre, bool ccw, double level, double f, int turns) {
  step(CycleStepKind::Arc, end, level, f);
  out_.back().centre = place(centre, level);
  out_.back().ccw = ccw;  // a rotation keeps the turning sense
  out_.back().turns = turns;
}

void Mill::go(PlanePoint p, double level) {
  if ((level - level_) * dir_ < 0) up(level);
  if (p != here_) rapid(p, level_);
  up(level);
}

void Mill::goProgram(const std::array<double, 3> &p) {
  double du = p[u_] - origin_[0], dv = p[v_] - origin_[1];
  size_t before = out_.size();
  go({c_ * du + s_ * dv, -s_ * du + c_ * dv}, p[n_]);
  if (out_.size() > before) out_.back().pos = p;  // exactly where the cycle started, free of rounding
}

void Mill::run(const Contour &c, bool ccw, double level, double f) {
  if (ccw) {
    for (const PathSeg &s : c.segs)
      s.arc ? arc(s.end, s.centre, s.ccw, level, f) : feed(s.end, level, f);
    return;
  }
  for (size_t i = c.segs.size(); i-- > 0;) {
    const PathSeg &s = c.segs[i];
    PlanePoint to = i > 0 ? c.segs[i - 1].end : c.start;
    s.arc ? arc(to, s.centre, !s.ccw, level, f) : feed(to, level, f);
  }
}

namespace {
size_t nearestCorner(const Polygon &p, PlanePoint at, double &best) {
  size_t first = 0;
  best = 1e300;
  for (size_t i = 0; i < p.size(); ++i) {
    double d = std::hypot(p[i][0] - at[0], p[i][1] - at[1]);
    if (d < best) best = d, first = i;
  }
  return first;
}
}  // namespace

PlanePoint Mill::ringStart(const Polygon &p) const {
  double best;
  return p[nearestCorner(p, here_, best)];
}

void Mill::ring(const Polygon &p, bool ccw, double level, double f) {
  double best;
  const size_t first = nearestCorner(p, here_, best), n = p.size();
  if (best > 0) feed(p[first], level, f);
  for (size_t k = 1; k <= n; ++k) feed(p[ccw ? (first + k) % n : (first + n - k) % n], level, f);
}

}  // namespace ncc
