#include "ir/ContourMath.h"
#include "ir/Value.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace ncc {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Relative tolerance of "on the element" and "parallel" (lengths times this).
constexpr double kRel = 1e-9;

bool isArc(const ContourElement &e) { return e.kind == 2 || e.kind == 3; }
double radius(const ContourElement &e) { return std::hypot(e.xs - e.cx, e.ys - e.cy); }
// The counter-clockwise sweep of an arc, signed (clockwise negative), a full turn when it closes.
double sweep(const ContourElement &e) {
  double a0 = std::atan2(e.ys - e.cy, e.xs - e.cx), a1 = std::atan2(e.ye - e.cy, e.xe - e.cx);
  double s = e.kind == 3 ? a1 - a0 : a0 - a1;
  while (s <= 0) s += 2 * kPi;
  while (s > 2 * kPi) s -= 2 * kPi;
  return e.kind == 3 ? s : -s;
}
// Where point (x, y) (on the element's line or circle) lies along it: 0 at the start, 1 at the end.
double along(const ContourElement &e, double x, double y) {
  if (!isArc(e)) {
    double dx = e.xe - e.xs, dy = e.ye - e.ys, l2 = dx * dx + dy * dy;
    return l2 > 0 ? ((x - e.xs) * dx + (y - e.ys) * dy) / l2 : 0.0;
  }
  double s = sweep(e), a0 = std::atan2(e.ys - e.cy, e.xs - e.cx), a = std::atan2(y - e.cy, x - e.cx);
  double d = s > 0 ? a - a0 : a0 - a;
  while (d < 0) d += 2 * kPi;
  while (d >= 2 * kPi) d -= 2 * kPi;
  double t = d / std::fabs(s);
  // Just before the start (within the tolerance) reads as the start, not the far end.
  if (t > 1 && (2 * kPi - d) * radius(e) <= kRel * std::max(1.0, radius(e))) t = 0;
  return t;
}
double size(const ContourElement &e) {
  return std::max({std::fabs(e.xs), std::fabs(e.ys), std::fabs(e.xe), std::fabs(e.ye), 1.0});
}
bool within(const ContourElement &e, double t) {
  double len = isArc(e) ? std::fabs(sweep(e)) * radius(e) : std::hypot(e.xe - e.xs, e.ye - e.ys);
  double tol = len > 0 ? kRel * size(e) / len : 0;
  return t >= -tol && t <= 1 + tol;
}
// The points of the line through e (a line element) with the circle (c, r), or of two circles.
void lineCircle(const ContourElement &l, double cx, double cy, double r, std::vector<std::array<double, 2>> &out) {
  double dx = l.xe - l.xs, dy = l.ye - l.ys, a = dx * dx + dy * dy;
  if (a == 0) return;
  double fx = l.xs - cx, fy = l.ys - cy;
  double b = 2 * (fx * dx + fy * dy), c = fx * fx + fy * fy - r * r;
  double disc = b * b - 4 * a * c;
  double tol = 4 * a * kRel * size(l) * r;  // a tangent within the tolerance touches
  if (disc < -tol) return;
  if (disc < 0) disc = 0;
  double q = std::sqrt(disc);
  for (double t : {(-b - q) / (2 * a), (-b + q) / (2 * a)}) out.push_back({l.xs + t * dx, l.ys + t * dy});
}
void circleCircle(const ContourElement &a, const ContourElement &b, std::vector<std::array<double, 2>> &out) {
  double ra = radius(a), rb = radius(b), dx = b.cx - a.cx, dy = b.cy - a.cy, d = std::hypot(dx, dy);
  double tol = kRel * std::max(size(a), size(b));
  if (d <= tol || d > ra + rb + tol || d < std::fabs(ra - rb) - tol) return;
  double m = (d * d + ra * ra - rb * rb) / (2 * d), h2 = ra * ra - m * m, h = h2 > 0 ? std::sqrt(h2) : 0;
  double px = a.cx + m * dx / d, py = a.cy + m * dy / d;
  out.push_back({px - h * dy / d, py + h * dx / d});
  out.push_back({px + h * dy / d, py - h * dx / d});
}
}  // namespace

bool intersectElements(const ContourElement &a, const ContourElement &b, double &x, double &y) {
  std::vector<std::array<double, 2>> pts;
  if (!isArc(a) && !isArc(b)) {
    double d1x = a.xe - a.xs, d1y = a.ye - a.ys, d2x = b.xe - b.xs, d2y = b.ye - b.ys;
    double den = d1x * d2y - d1y * d2x;
    if (std::fabs(den) <= kRel * std::hypot(d1x, d1y) * std::hypot(d2x, d2y)) return false;  // parallel
    double t = ((b.xs - a.xs) * d2y - (b.ys - a.ys) * d2x) / den;
    pts.push_back({a.xs + t * d1x, a.ys + t * d1y});
  } else if (!isArc(a)) {
    lineCircle(a, b.cx, b.cy, radius(b), pts);
  } else if (!isArc(b)) {
    lineCircle(b, a.cx, a.cy, radius(a), pts);
  } else {
    circleCircle(a, b, pts);
  }
  double best = std::numeric_limits<double>::infinity();
  for (auto &p : pts) {
    double ta = along(a, p[0], p[1]), tb = along(b, p[0], p[1]);
    if (!within(a, ta) || !within(b, tb) || ta >= best) continue;
    best = ta, x = p[0], y = p[1];
  }
  return best != std::numeric_limits<double>::infinity();
}

bool circleThrough(const double p[3][2], double &cx, double &cy, double &r) {
  double bx = p[1][0] - p[0][0], by = p[1][1] - p[0][1], qx = p[2][0] - p[0][0], qy = p[2][1] - p[0][1];
  double b2 = bx * bx + by * by, q2 = qx * qx + qy * qy, w2 = (qx - bx) * (qx - bx) + (qy - by) * (qy - by);
  double scale = std::max({b2, q2, w2});
  if (scale == 0 || std::min({b2, q2, w2}) <= 1e-24 * scale) return false;  // two points coincide
  double den = 2 * (bx * qy - by * qx);
  if (std::fabs(den) <= 2e-12 * scale) return false;  // on a line
  double ux = (qy * b2 - by * q2) / den, uy = (bx * q2 - qx * b2) / den;
  cx = p[0][0] + ux, cy = p[0][1] + uy, r = std::hypot(ux, uy);
  return true;
}

bool circleOfPoints(const double (*p)[2], int n, double &cx, double &cy, double &r) {
  if (n == 3) return circleThrough(p, cx, cy, r);
  if (n != 4) return false;
  static const int kTriples[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};  // L27638-L27642
  double sx = 0, sy = 0, sr2 = 0;
  for (auto &t : kTriples) {
    double q[3][2], x, y, ri;
    for (int k = 0; k < 3; ++k) q[k][0] = p[t[k]][0], q[k][1] = p[t[k]][1];
    if (!circleThrough(q, x, y, ri)) return false;
    sx += x, sy += y, sr2 += ri * ri;
  }
  cx = sx / 4, cy = sy / 4, r = std::sqrt(sr2) * 0.5;
  return true;
}

extern "C" {
double ncc_builtin_sin_intersec(const double *a) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double mode = num(a[1]);
  if (mode != 0 && mode != 1) return nan;
  ContourElement e[2];
  for (int k = 0; k < 2; ++k) {
    const double *v = a + 2 + 7 * k;
    double code = num(v[0]);
    if (!(code >= 0 && code == std::floor(code) && code < 1e6)) return nan;
    e[k].kind = (int)std::fmod(code, 10.0);
    if (e[k].kind > 3) return nan;
    e[k].xs = num(v[1]), e[k].ys = num(v[2]), e[k].xe = num(v[3]), e[k].ye = num(v[4]);
    e[k].cx = num(v[5]), e[k].cy = num(v[6]);
  }
  double x = 0, y = 0;
  bool found = intersectElements(e[0], e[1], x, y);
  int k = (int)num(a[0]);
  return k == 0 ? (found ? x : 0.0) : k == 1 ? (found ? y : 0.0) : found ? 1.0 : 0.0;
}

double ncc_builtin_sin_calcdat(const double *a) {
  int n = (int)num(a[1]);
  if (n != 3 && n != 4) return std::numeric_limits<double>::quiet_NaN();
  double p[4][2];
  for (int i = 0; i < n; ++i) p[i][0] = num(a[2 + 2 * i]), p[i][1] = num(a[3 + 2 * i]);
  double cx = 0, cy = 0, r = 0;
  bool ok = circleOfPoints(p, n, cx, cy, r);
  int k = (int)num(a[0]);
  return k == 3 ? (ok ? 1.0 : 0.0) : !ok ? 0.0 : k == 0 ? cx : k == 1 ? cy : r;
}
}

}  // namespace ncc
