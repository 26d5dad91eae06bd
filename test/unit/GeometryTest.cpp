#include "runtime/Geometry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc;

namespace {
constexpr double kPi = 3.14159265358979323846;
AxisVec P(double x, double y, double z) { return AxisVec{x, y, z, 0, 0, 0}; }
}  // namespace

TEST(Geometry, QuarterCircleCcwAndCw) {
  // G17 G3 from (10,0) to (0,10) around the origin: a quarter circle.
  ArcGeometry g = arcGeometry(P(10, 0, 0), P(0, 10, 0), {0, 0, 0}, Plane::XY, 1);
  EXPECT_NEAR(g.sweep, kPi / 2, 1e-12);
  EXPECT_NEAR(g.length, 10 * kPi / 2, 1e-12);
  EXPECT_NEAR(arcCurvature(g), 0.1, 1e-12);
  AxisVec mid = arcPoint(g, P(10, 0, 0), P(0, 10, 0), 0.5);
  EXPECT_NEAR(mid[0], 10 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(mid[1], 10 / std::sqrt(2.0), 1e-12);
  Vec3 t0 = arcTangent(g, 0), t1 = arcTangent(g, 1);
  EXPECT_NEAR(t0[0], 0, 1e-12);
  EXPECT_NEAR(t0[1], 1, 1e-12);
  EXPECT_NEAR(t1[0], -1, 1e-12);
  EXPECT_NEAR(t1[1], 0, 1e-12);
  // G2 the same way round is the long way: three quarters, clockwise.
  ArcGeometry c = arcGeometry(P(10, 0, 0), P(0, 10, 0), {0, 0, 0}, Plane::XY, -1);
  EXPECT_NEAR(c.sweep, -3 * kPi / 2, 1e-12);
  EXPECT_NEAR(c.length, 10 * 3 * kPi / 2, 1e-12);
  AxisVec q = arcPoint(c, P(10, 0, 0), P(0, 10, 0), 1.0 / 3);
  EXPECT_NEAR(q[0], 0, 1e-12);
  EXPECT_NEAR(q[1], -10, 1e-12);
}

TEST(Geometry, FullCirclesAndExtraTurns) {
  ArcGeometry g = arcGeometry(P(5, 0, 0), P(5, 0, 0), {0, 0, 0}, Plane::XY, 1);
  EXPECT_NEAR(g.sweep, 2 * kPi, 1e-12);
  EXPECT_NEAR(g.length, 10 * kPi, 1e-12);
  ArcGeometry cw = arcGeometry(P(5, 0, 0), P(5, 0, 0), {0, 0, 0}, Plane::XY, -1);
  EXPECT_NEAR(cw.sweep, -2 * kPi, 1e-12);
  // turns = 3: the partial arc plus two full turns.
  ArcGeometry t = arcGeometry(P(5, 0, 0), P(0, 5, 0), {0, 0, 0}, Plane::XY, 3);
  EXPECT_NEAR(t.sweep, kPi / 2 + 4 * kPi, 1e-12);
  // turns = 0 is read as one counter-clockwise pass.
  EXPECT_NEAR(arcGeometry(P(5, 0, 0), P(0, 5, 0), {0, 0, 0}, Plane::XY, 0).sweep, kPi / 2, 1e-12);
}

TEST(Geometry, HelixLengthAndCurvature) {
  // One full turn of radius 10 rising 5 mm.
  ArcGeometry g = arcGeometry(P(10, 0, 0), P(10, 0, 5), {0, 0, 0}, Plane::XY, 1);
  EXPECT_NEAR(g.helix, 5, 1e-12);
  EXPECT_NEAR(g.length, std::hypot(20 * kPi, 5), 1e-9);
  double c = 5 / (2 * kPi);
  EXPECT_NEAR(arcCurvature(g), 10 / (100 + c * c), 1e-12);
  AxisVec half = arcPoint(g, P(10, 0, 0), P(10, 0, 5), 0.5);
  EXPECT_NEAR(half[0], -10, 1e-12);
  EXPECT_NEAR(half[2], 2.5, 1e-12);
  Vec3 t = arcTangent(g, 0);
  EXPECT_NEAR(t[2], 5 / g.length, 1e-12);
}

TEST(Geometry, EachPlaneIsRightHanded) {
  // G18 (ZX): counter-clockwise seen from +Y turns Z towards X.
  ArcGeometry zx = arcGeometry(P(0, 0, 10), P(10, 0, 0), {0, 0, 0}, Plane::ZX, 1);
  EXPECT_NEAR(zx.sweep, kPi / 2, 1e-12);
  EXPECT_EQ(zx.ax.n, 1);
  // G19 (YZ): counter-clockwise seen from +X turns Y towards Z.
  ArcGeometry yz = arcGeometry(P(0, 10, 0), P(0, 0, 10), {0, 0, 0}, Plane::YZ, 1);
  EXPECT_NEAR(yz.sweep, kPi / 2, 1e-12);
  EXPECT_EQ(yz.ax.n, 0);
  AxisVec m = arcPoint(yz, P(0, 10, 0), P(0, 0, 10), 0.5);
  EXPECT_NEAR(m[1], 10 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m[2], 10 / std::sqrt(2.0), 1e-12);
  // Helix along Y in G18.
  ArcGeometry h = arcGeometry(P(0, 0, 10), P(10, 3, 0), {0, 0, 0}, Plane::ZX, 1);
  EXPECT_NEAR(h.helix, 3, 1e-12);
}

TEST(Geometry, TinyArcIsNotAFullCircle) {
  double a = 1e-6;  // radians
  AxisVec s = P(100, 0, 0), e = P(100 * std::cos(a), 100 * std::sin(a), 0);
  ArcGeometry g = arcGeometry(s, e, {0, 0, 0}, Plane::XY, 1);
  EXPECT_NEAR(g.sweep, a, 1e-15);
  EXPECT_NEAR(g.length, 100 * a, 1e-12);
  ArcGeometry cw = arcGeometry(s, e, {0, 0, 0}, Plane::XY, -1);
  EXPECT_NEAR(cw.sweep, a - 2 * kPi, 1e-12);
}

TEST(Geometry, RadiusMismatchSpirals) {
  ArcGeometry g = arcGeometry(P(10, 0, 0), P(-10.002, 0, 0), {0, 0, 0}, Plane::XY, 1);
  EXPECT_NEAR(g.r0, 10, 1e-12);
  EXPECT_NEAR(g.r1, 10.002, 1e-12);
  AxisVec e = arcPoint(g, P(10, 0, 0), P(-10.002, 0, 0), 1);
  EXPECT_DOUBLE_EQ(e[0], -10.002);
  AxisVec m = arcPoint(g, P(10, 0, 0), P(-10.002, 0, 0), 0.5);
  EXPECT_NEAR(m[1], 10.001, 1e-12);
}

TEST(Geometry, ArcBoundsIncludeQuadrantCrossings) {
  Vec3 lo, hi;
  // Quarter from (10,0) ccw to (0,10): no crossing inside, the bounds are the endpoints.
  ArcGeometry q = arcGeometry(P(10, 0, 0), P(0, 10, 0), {0, 0, 0}, Plane::XY, 1);
  arcBounds(q, P(10, 0, 0), P(0, 10, 0), lo, hi);
  EXPECT_NEAR(lo[0], 0, 1e-12);
  EXPECT_NEAR(hi[1], 10, 1e-12);
  // Half circle from (0,10) ccw to (0,-10) passes x = -10.
  ArcGeometry h = arcGeometry(P(0, 10, 0), P(0, -10, 0), {0, 0, 0}, Plane::XY, 1);
  arcBounds(h, P(0, 10, 0), P(0, -10, 0), lo, hi);
  EXPECT_NEAR(lo[0], -10, 1e-12);
  EXPECT_NEAR(hi[0], 0, 1e-12);
  // Clockwise the same endpoints pass x = +10.
  ArcGeometry c = arcGeometry(P(0, 10, 0), P(0, -10, 0), {0, 0, 0}, Plane::XY, -1);
  arcBounds(c, P(0, 10, 0), P(0, -10, 0), lo, hi);
  EXPECT_NEAR(hi[0], 10, 1e-12);
  EXPECT_NEAR(lo[0], 0, 1e-12);
}

TEST(Geometry, LinearLengthFallsBackToRotary) {
  EXPECT_DOUBLE_EQ(linearLength(P(0, 0, 0), P(3, 4, 0)), 5);
  AxisVec a{0, 0, 0, 0, 0, 0}, b{0, 0, 0, 90, 0, 0};
  EXPECT_DOUBLE_EQ(linearLength(a, b), 90);
  AxisVec u = unitDirection(P(0, 0, 0), P(3, 4, 0), 5);
  EXPECT_DOUBLE_EQ(u[0], 0.6);
  EXPECT_DOUBLE_EQ(u[1], 0.8);
}

// A tilted arc follows the same rules about its own normal: about +Y/+X/+Z it is exactly the
// principal plane's arc, and a tilted helix stays on its cylinder with tangents across the normal.
TEST(Geometry, TiltedArcMatchesPrincipalPlanesAndStaysOnItsCircle) {
  struct Case {
    Plane plane;
    Vec3 normal;
  } cases[] = {{Plane::XY, {0, 0, 1}}, {Plane::ZX, {0, 1, 0}}, {Plane::YZ, {1, 0, 0}}};
  for (auto &c : cases) {
    for (int turns : {1, -1, 2}) {
      AxisVec s = P(3, 4, 5), e = P(5, 3, 4);
      Vec3 center{4, 4, 4};
      ArcGeometry a = arcGeometry(s, e, center, c.plane, turns);
      ArcGeometry t = tiltedArcGeometry(s, e, center, c.normal, turns);
      EXPECT_NEAR(a.sweep, t.sweep, 1e-12);
      EXPECT_NEAR(a.length, t.length, 1e-12);
      for (double f : {0.25, 0.5, 0.75}) {
        AxisVec pa = arcPoint(a, s, e, f), pt = arcPoint(t, s, e, f);
        Vec3 ta = arcTangent(a, f), tt = arcTangent(t, f);
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(pa[i], pt[i], 1e-12) << (int)c.plane << " " << turns << " " << f;
          EXPECT_NEAR(ta[i], tt[i], 1e-12);
        }
      }
    }
  }
  // Normal (0, 0.6, 0.8), centre (5, 0, 0), from the origin with 2 mm of helix, counter-clockwise.
  Vec3 n{0, 0.6, 0.8};
  AxisVec s = P(0, 0, 0), e = P(10, 1.2, 1.6);
  ArcGeometry g = tiltedArcGeometry(s, e, {5, 0, 0}, n, 1);
  EXPECT_NEAR(g.sweep, kPi, 1e-12);
  EXPECT_NEAR(g.helix, 2, 1e-12);
  EXPECT_NEAR(g.length, std::hypot(5 * kPi, 2), 1e-12);
  for (double f = 0; f <= 1; f += 0.125) {
    AxisVec p = arcPoint(g, s, e, f);
    Vec3 d{p[0] - 5, p[1], p[2]};
    double h = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    EXPECT_NEAR(h, 2 * f, 1e-12);
    EXPECT_NEAR(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - h * h), 5, 1e-12);
  }
  // Half way round, at the far side: v = n x u = (0, -0.8, 0.6) with u = (-1, 0, 0).
  AxisVec mid = arcPoint(g, s, e, 0.5);
  EXPECT_NEAR(mid[0], 5, 1e-12);
  EXPECT_NEAR(mid[1], -4 + 0.6, 1e-12);
  EXPECT_NEAR(mid[2], 3 + 0.8, 1e-12);
  Vec3 lo, hi;
  ArcGeometry flat = tiltedArcGeometry(s, P(10, 0, 0), {5, 0, 0}, n, 1);
  arcBounds(flat, s, P(10, 0, 0), lo, hi);
  EXPECT_NEAR(lo[1], -4, 1e-12);
  EXPECT_NEAR(hi[2], 3, 1e-12);
  EXPECT_NEAR(hi[0], 10, 1e-12);
  Vec3 share = arcAxisShare(flat);
  EXPECT_NEAR(share[0], 1, 1e-12);
  EXPECT_NEAR(share[1], 0.8, 1e-12);
  EXPECT_NEAR(share[2], 0.6, 1e-12);
}

namespace {
MotionRecord splineRec(AxisVec a, AxisVec b, int degree, std::vector<std::array<double, 3>> inner,
                       std::vector<double> weights = {}, std::vector<double> knots = {}) {
  MotionRecord r;
  r.kind = RecordKind::Spline;
  r.start = a;
  r.end = b;
  r.feed = 100;
  SplineData s;
  s.degree = degree;
  s.points = std::move(inner);
  s.weights = std::move(weights);
  s.knots = std::move(knots);
  r.setSpline(std::move(s));
  return r;
}
}  // namespace

TEST(Geometry, SplineBezierAndRationalCircle) {
  // rs274's knot vector: degree + 1 zeros, 1 .. count - degree - 1, degree + 1 copies of the last.
  EXPECT_EQ(splineDefaultKnots(4, 3), (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(splineDefaultKnots(5, 2), (std::vector<double>{0, 0, 0, 1, 2, 3, 3, 3}));
  // G5 from (0,0) with handles (1,0) and (2,2) to (3,2): the cubic Bezier, at t = 0.3.
  MotionRecord b = splineRec(P(0, 0, 0), P(3, 2, 0), 3, {{1, 0, 0}, {2, 2, 0}});
  SplineCurve c(b);
  double t = 0.3, u = 1 - t;
  auto bez = [&](double p0, double p1, double p2, double p3) {
    return u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3;
  };
  Vec3 q = c.at(c.u0() + t * (c.u1() - c.u0()));
  EXPECT_NEAR(q[0], bez(0, 1, 2, 3), 1e-12);
  EXPECT_NEAR(q[1], bez(0, 0, 2, 2), 1e-12);
  Vec3 e = c.at(c.u1());
  EXPECT_EQ(e[0], 3);
  EXPECT_EQ(e[1], 2);
  // The rational quadratic with middle weight sqrt(2)/2 is a quarter circle: every point of the
  // curve is on it, the flattened length is 5 pi within the chord tolerance.
  MotionRecord circle = splineRec(P(10, 0, 0), P(0, 10, 0), 2, {{10, 10, 0}}, {1, std::sqrt(0.5), 1});
  SplineCurve cc(circle);
  for (double f : {0.1, 0.37, 0.5, 0.9}) {
    Vec3 p = cc.at(f);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 10, 1e-12) << f;
  }
  EXPECT_NEAR(splineLength(circle), 5 * kPi, 1e-5);
  SplinePath path = splinePath(circle);
  EXPECT_NEAR(path.maxCurvature, 0.1, 1e-3);
  Vec3 mid = path.at(path.length() / 2);
  EXPECT_NEAR(mid[0], 10 / std::sqrt(2.0), 1e-3);
  EXPECT_NEAR(mid[1], 10 / std::sqrt(2.0), 1e-3);
  Vec3 t0 = path.startTangent();
  EXPECT_NEAR(t0[1], 1, 1e-4);
  // Two spans with an inner knot: the curve passes the spans' joint continuously and the bounds
  // hold the control polygon's hull.
  MotionRecord two = splineRec(P(0, 0, 0), P(4, 0, 0), 2, {{1, 2, 0}, {3, -2, 0}}, {}, {0, 0, 0, 0.5, 1, 1, 1});
  SplineCurve ct(two);
  Vec3 l = ct.at(0.5 - 1e-12), r = ct.at(0.5);
  EXPECT_NEAR(l[0], r[0], 1e-9);
  EXPECT_NEAR(l[1], r[1], 1e-9);
  Vec3 lo, hi;
  splineBounds(two, lo, hi);
  EXPECT_GT(hi[1], 0.5);
  EXPECT_LT(lo[1], -0.5);
  EXPECT_LE(hi[1], 2);
}
