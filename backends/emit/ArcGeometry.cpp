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
  w.offset[0] = roundTo(cc[0] - s[0], centerFormat.decimals);
  w.offset[1] = roundTo(cc[1] - s[1], centerFormat.decimals);
  if (!preferRadius || fullCircle || chord == 0) return w;

  // R form: the controller puts the centre on the bisector; use it only when that centre,
  // rebuilt from the rounded R, is close to the exact one (not near half circles).
  double r = std::hypot(onBisector[0] - s[0], onBisector[1] - s[1]);
  if (sweepAngle(s, e, onBisector, ccw) > kTwoPi / 2 + 1e-9) r = -r;
  double rr = roundTo(r, centerFormat.decimals);
  double rebuilt[2];
  if (!centerFromRadius(s, e, rr, ccw, rebuilt)) return w;
  if (std::hypot(rebuilt[0] - c[0], rebuilt[1] - c[1]) > tolerance / 2) return w;
  w.useRadius = true;
  w.radius = rr;
  return w;
}

}  // namespace ncc::emit
