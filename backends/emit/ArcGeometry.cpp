#include "backends/emit/ArcGeometry.h"

#include <cmath>

namespace ncc::emit {

static constexpr double kTwoPi = 6.283185307179586476925;

PlaneAxes planeAxes(Plane p) {
  switch (p) {
  case Plane::ZX: return {2, 0, 1};
  case Plane::YZ: return {1, 2, 0};
  case Plane::XY: break;
  }
  return {0, 1, 2};
}

double sweepAngle(const double s[2], const double e[2], const double c[2], bool ccw) {
  double as = std::atan2(s[1] - c[1], s[0] - c[0]);
  double ae = std::atan2(e[1] - c[1], e[0] - c[0]);
  double d = ccw ? ae - as : as - ae;
  while (d <= 1e-12) d += kTwoPi;
  while (d > kTwoPi + 1e-12) d -= kTwoPi;
  return d;
}

// Centre rebuilt from a signed radius the way a controller does it; false when the radius is
// shorter than half the chord.
static bool centerFromRadius(const double s[2], const double e[2], double r, bool ccw, double out[2]) {
  double mx = (s[0] + e[0]) / 2, my = (s[1] + e[1]) / 2;
  double dx = e[0] - s[0], dy = e[1] - s[1];
  double chord = std::hypot(dx, dy);
  if (chord == 0) return false;
  double h2 = r * r - chord * chord / 4;
  if (h2 < 0) return false;
  double h = std::sqrt(h2);
  double ux = -dy / chord, uy = dx / chord;
  for (int side : {1, -1}) {
    double c[2] = {mx + side * ux * h, my + side * uy * h};
    bool small = sweepAngle(s, e, c, ccw) <= kTwoPi / 2 + 1e-12;
    if (small == (r > 0)) {
      out[0] = c[0];
      out[1] = c[1];
      return true;
    }
  }
  return false;
}

static double radiusMismatch(const double s[2], const double e[2], const double off[2]) {
  double c[2] = {s[0] + off[0], s[1] + off[1]};
  return std::fabs(std::hypot(c[0] - s[0], c[1] - s[1]) - std::hypot(c[0] - e[0], c[1] - e[1]));
}

// Of the four output-grid points around the centre: the nearest whose radii to the rounded ends
// agree within `limit`, else the one that agrees best (rounding alone can add 0.7 units of the
// last digit to the mismatch).
static void pickOffsets(const double s[2], const double e[2], const double cc[2], int decimals, double limit,
                        double out[2]) {
  double unit = std::pow(10.0, -decimals);
  double fx = std::floor((cc[0] - s[0]) / unit), fy = std::floor((cc[1] - s[1]) / unit);
  double bestMismatch = INFINITY, bestDist = INFINITY;
  bool bestOk = false;
  for (int i = 0; i < 4; ++i) {
    double off[2] = {roundTo((fx + (i & 1)) * unit, decimals), roundTo((fy + (i >> 1)) * unit, decimals)};
    double m = radiusMismatch(s, e, off);
    double d = std::hypot(s[0] + off[0] - cc[0], s[1] + off[1] - cc[1]);
    bool ok = m <= limit;
    bool better = ok ? (!bestOk || d < bestDist) : (!bestOk && m < bestMismatch);
    if (better) {
      bestOk = ok;
      bestMismatch = m;
      bestDist = d;
      out[0] = off[0];
      out[1] = off[1];
    }
  }
}

ArcWords planArc(const double s[2], const double e[2], const double c[2], bool ccw, bool fullCircle,
                 bool preferRadius, const NumberFormat &centerFormat, double tolerance) {
  ArcWords w;
  double cc[2] = {c[0], c[1]};
  double dx = e[0] - s[0], dy = e[1] - s[1];
  double chord = std::hypot(dx, dy);
  double onBisector[2] = {c[0], c[1]};
  if (!fullCircle && chord > 0) {
    double mx = (s[0] + e[0]) / 2, my = (s[1] + e[1]) / 2;
    double ux = -dy / chord, uy = dx / chord;
    double t = (c[0] - mx) * ux + (c[1] - my) * uy;
    onBisector[0] = mx + ux * t;
    onBisector[1] = my + uy * t;
    // Rounded end points may sit at different distances from the exact centre. Within 3/4 of the
    // tolerance the centre stays (it is the better path); beyond, it moves towards the bisector
    // just enough, because moving it far shifts a long arc.
    double mismatch = std::fabs(std::hypot(c[0] - s[0], c[1] - s[1]) - std::hypot(c[0] - e[0], c[1] - e[1]));
    double budget = 0.75 * tolerance;
    if (mismatch > budget) {
      double k = 1 - budget / mismatch;
      cc[0] = c[0] + k * (onBisector[0] - c[0]);
      cc[1] = c[1] + k * (onBisector[1] - c[1]);
    }
  }
  double limit = 0.9 * tolerance;
  pickOffsets(s, e, cc, centerFormat.decimals, limit, w.offset);
  if (!fullCircle && chord > 0 && radiusMismatch(s, e, w.offset) > limit) {
    // Coarse centre format: only the centre on the bisector leaves room for its rounding.
    pickOffsets(s, e, onBisector, centerFormat.decimals, limit, w.offset);
  }
  if (!preferRadius || fullCircle || chord == 0) return w;

  // R form: the controller puts the centre on the bisector; use it only when that centre,
  // rebuilt from the rounded R, is close to the exact one (not near half circles).
  double r = std::hypot(onBisector[0] - s[0], onBisector[1] - s[1]);
  if (sweepAngle(s, e, onBisector, ccw) > kTwoPi / 2 + 1e-9) r = -r;
  double rr = roundTo(r, centerFormat.decimals);
  double rebuilt[2];
  if (!centerFromRadius(s, e, rr, ccw, rebuilt)) return w;
  if (std::hypot(rebuilt[0] - c[0], rebuilt[1] - c[1]) > tolerance / 4) return w;
  w.useRadius = true;
  w.radius = rr;
  return w;
}

}  // namespace ncc::emit
