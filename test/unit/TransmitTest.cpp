// The kinematic transformations' math (runtime/Transmit.h): the axis maps, the split of a path
// into straight machine moves within the tolerance, the pole rules.
#include "runtime/Transmit.h"

#include "ir/Diagnostics.h"
#include "runtime/Geometry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc;

namespace {

AxisVec P(double x, double y, double z, double c = 0) { return AxisVec{x, y, z, 0, 0, c}; }

TransformSetup face(double tol = 0.01) {
  TransformSetup s;
  s.kind = TransformKind::Face;
  s.tolerance = tol;
  return s;
}

struct Collect : MotionSink {
  std::vector<MotionRecord> recs;
  void record(const MotionRecord &r) override { recs.push_back(r); }
};

// The largest distance between the machine-axis straight pieces (mapped back to the BCS) and the
// exact segment a-b, sampled finely.
double worstLineDeviation(const TransformSetup &s, const AxisVec &a, const AxisVec &b, const AxisVec &m0,
                          const std::vector<AxisVec> &pts) {
  double worst = 0;
  AxisVec prev = m0;
  for (const AxisVec &m : pts) {
    for (int k = 0; k <= 16; ++k) {
      AxisVec q;
      for (int i = 0; i < kAxes; ++i) q[i] = prev[i] + (m[i] - prev[i]) * k / 16.0;
      AxisVec p = transformToBcs(s, q);
      double dx = b[0] - a[0], dy = b[1] - a[1];
      double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      worst = std::max(worst, std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy));
    }
    prev = m;
  }
  return worst;
}

// A face transformation's sink started at machine X10 C0, and an arc record in G17 from (10, 0).
struct FaceSink {
  Collect out;
  SourceManager sm;
  Diagnostics diags{sm};
  TransformSink sink{out, diags};
  FaceSink() { sink.begin(face(), P(10, 0, 0, 0)); }
  void arc(const AxisVec &end, std::array<double, 3> center, int turns) {
    MotionRecord r;
    r.kind = RecordKind::Arc;
    r.plane = Plane::XY;
    r.start = P(10, 0, 0);
    r.end = end;
    r.center = center;
    r.turns = turns;
    sink.record(r);
  }
};

}  // namespace

TEST(Transmit, FaceMapsAndKeepsCContinuous) {
  TransformSetup s = face();
  FaceState fs;
  AxisVec m = transformToMachine(s, P(20, -20, 5), P(0, 0, 0), fs);
  EXPECT_NEAR(m[0], std::sqrt(800.0), 1e-9);
  EXPECT_NEAR(m[5], -45, 1e-9);
  EXPECT_EQ(m[2], 5);
  // Near C 700 the same point is C 675 (continuous, not modulo 360).
  m = transformToMachine(s, P(20, -20, 5), P(0, 0, 0, 700), fs);
  EXPECT_NEAR(m[5], 675, 1e-9);
  // Past the pole: X negative, C half a turn from the point's angle.
  fs.side = -1;
  m = transformToMachine(s, P(0, 10, 0), P(0, 0, 0, 0), fs);
  EXPECT_NEAR(m[0], -10, 1e-9);
  EXPECT_NEAR(m[5], -90, 1e-9);
  AxisVec b = transformToBcs(s, m);
  EXPECT_NEAR(b[0], 0, 1e-9);
  EXPECT_NEAR(b[1], 10, 1e-9);
  // At the pole C keeps its value.
  m = transformToMachine(s, P(0, 0, 0), P(7, 0, 0, 33), fs);
  EXPECT_EQ(m[0], 0);
  EXPECT_EQ(m[5], 33);
}

TEST(Transmit, CylinderMapsArcLengthToDegrees) {
  TransformSetup s;
  s.kind = TransformKind::Cylinder;
  s.radius = 20;
  FaceState fs;
  AxisVec m = transformToMachine(s, P(17, 20 * M_PI / 2, -10), P(0, 0, 0), fs);
  EXPECT_NEAR(m[5], 90, 1e-9);
  EXPECT_EQ(m[0], 17);
  EXPECT_EQ(m[1], 0);
  AxisVec b = transformToBcs(s, P(17, 0, -10, 450));
  EXPECT_NEAR(b[1], 20 * M_PI * 2.5, 1e-9);
}

TEST(Transmit, LineSplitStaysWithinTolerance) {
  for (double tol : {0.1, 0.01, 0.001}) {
    TransformSetup s = face(tol);
    FaceState fs;
    AxisVec a = P(20, -20, 0), b = P(20, 20, 0);
    AxisVec m0 = transformToMachine(s, a, P(0, 0, 0), fs);
    std::vector<AxisVec> pts;
    std::string err;
    ASSERT_TRUE(splitTransformed(
        s, fs, m0, [&](double t) { AxisVec p = a; p[1] += 40 * t; return p; },
        [&](const AxisVec &p, double, double) { return std::fabs(p[0] - 20); }, 1, pts, err))
        << err;
    EXPECT_LE(worstLineDeviation(s, a, b, m0, pts), tol * 1.0001) << tol;
    EXPECT_NEAR(pts.back()[5], 45, 1e-9);
    EXPECT_GT(pts.size(), 4u);
    for (size_t i = 1; i < pts.size(); ++i) EXPECT_GT(pts[i][5], pts[i - 1][5]);  // C turns one way
  }
}

TEST(Transmit, SinkRunsThroughThePoleExactly) {
  Collect out;
  SourceManager sm;
  Diagnostics diags(sm);
  TransformSink sink(out, diags);
  AxisVec bcs = sink.begin(face(), P(30, 0, 0, 0));
  EXPECT_NEAR(bcs[0], 30, 1e-12);
  MotionRecord r;
  r.kind = RecordKind::Linear;
  r.start = P(30, 20, 0);
  r.end = P(-30, -20, 0);
  // Put the machine where the start is first (a radial move from (30,0) would not be it).
  MotionRecord first = r;
  first.start = P(30, 0, 0);
  first.end = P(30, 20, 0);
  sink.record(first);
  size_t n = out.recs.size();
  sink.record(r);
  ASSERT_EQ(out.recs.size(), n + 1);  // one exact move: C stays, X passes zero
  EXPECT_NEAR(out.recs.back().end[0], -std::sqrt(1300.0), 1e-9);
  EXPECT_NEAR(out.recs.back().end[5], out.recs.back().start[5], 1e-12);
  EXPECT_FALSE(sink.failed);
}

TEST(Transmit, ArcThroughThePoleIsRefused) {
  FaceSink f;
  f.arc(P(0, 10, 0), {5, 5, 0}, -1);  // clockwise: the long way, through (0, 0)
  EXPECT_TRUE(f.sink.failed);
  EXPECT_EQ(f.diags.errorCount(), 1u);
}

TEST(Transmit, ArcAboutThePoleIsCAlone) {
  FaceSink f;
  f.arc(P(10, 0, 0), {0, 0, 0}, 1);  // a full circle, counter-clockwise
  ASSERT_EQ(f.out.recs.size(), 4u);
  for (auto &o : f.out.recs) EXPECT_NEAR(o.end[0], 10, 1e-9);
  EXPECT_NEAR(f.out.recs.back().end[5], 360, 1e-9);
}
