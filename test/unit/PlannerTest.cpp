#include "runtime/Planner.h"
#include "PlannerTestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

using namespace ncc;

using namespace ncc::plannertest;

namespace {

Machine testMachine(double jerk, double tolerance = 0.01, int lookahead = 32) {
  return planMachine(1000, jerk, tolerance, lookahead);
}

}  // namespace

TEST(Planner, SingleMoveTrapezoidClosedForm) {
  Machine m = testMachine(0);
  // 100 mm at 100 mm/s, a = 1000: 0.1 s up (5 mm), 0.9 s cruise, 0.1 s down.
  EXPECT_NEAR(run(m, {line(P(0, 0), P(100, 0), 6000)}), 1.1, 1e-9);
  // 1 mm never reaches the feed: triangle, t = 2 sqrt(L / a).
  EXPECT_NEAR(run(m, {line(P(0, 0), P(1, 0), 6000)}), 2 * std::sqrt(0.001), 1e-9);
  // At 45 degrees each axis carries 1/sqrt2 of the path acceleration: a_path = 1000 sqrt2.
  double a = 1000 * std::sqrt(2.0);
  EXPECT_NEAR(run(m, {line(P(0, 0), P(10, 10), 6000)}), 2 * 100 / a + (std::sqrt(200.0) - 100 * 100 / a) / 100,
              1e-9);
}

TEST(Planner, SingleMoveSCurveClosedForm) {
  Machine m = testMachine(20000);
  // a^2/j = 50 mm/s < 100: each change takes v/a + a/j = 0.15 s over 7.5 mm.
  EXPECT_NEAR(run(m, {line(P(0, 0), P(100, 0), 6000)}), 0.3 + 85.0 / 100, 1e-9);
  // 10 mm/s < a^2/j: triangular acceleration, 2 sqrt(v / j) per change.
  double tc = 2 * std::sqrt(10.0 / 20000);
  EXPECT_NEAR(run(m, {line(P(0, 0), P(100, 0), 600)}), 2 * tc + (100 - 10 * tc) / 10, 1e-9);
  EXPECT_NEAR(velocityChangeTime(100, 1000, 20000), 0.15, 1e-12);
  EXPECT_NEAR(velocityChangeDistance(0, 100, 1000, 20000), 7.5, 1e-12);
}

TEST(Planner, ReachableSpeedInvertsDistance) {
  for (double j : {0.0, 5000.0, 50000.0}) {
    double jj = j > 0 ? j : INFINITY;
    for (double v : {0.0, 3.0, 40.0, 200.0})
      for (double len : {1e-4, 0.01, 0.5, 3.0, 100.0}) {
        double w = maxReachableSpeed(v, len, 1000, jj);
        EXPECT_NEAR(velocityChangeDistance(v, w, 1000, jj), len, 1e-9 * std::max(1.0, len))
            << "v=" << v << " len=" << len << " j=" << j;
      }
  }
}

TEST(Planner, ProfileReachesItsLengthAndSpeeds) {
  for (double j : {(double)INFINITY, 20000.0}) {
    VelocityProfile p = planProfile(2.0, 10, 5, 100, 1000, j);
    EXPECT_LT(p.vp, 100);
    double s, v;
    p.at(p.duration(), s, v);
    EXPECT_NEAR(s, 2.0, 1e-9);
    EXPECT_NEAR(v, 5, 1e-9);
    p.at(0, s, v);
    EXPECT_NEAR(v, 10, 1e-12);
    p.at(p.tAcc, s, v);
    EXPECT_NEAR(v, p.vp, 1e-9);
  }
}

TEST(Planner, RightAngleCornerIsSlowerThanStraight) {
  Machine m = testMachine(0, 0.01);
  Recorder rec;
  double straight = run(m, {line(P(0, 0), P(10, 0), 6000), line(P(10, 0), P(20, 0), 6000)});
  double corner = run(m, {line(P(0, 0), P(10, 0), 6000), line(P(10, 0), P(10, 10), 6000)}, &rec);
  EXPECT_NEAR(straight, 0.3, 1e-9);  // one 20 mm trapezoid
  EXPECT_GT(corner, straight + 0.05);
  // Junction-deviation speed at 90 degrees: sqrt(a * d * s / (1 - s)), s = sin 45.
  double s = std::sqrt(0.5);
  double vj = std::sqrt(1000 * 0.01 * s / (1 - s));
  ASSERT_EQ(rec.segs.size(), 2u);
  EXPECT_NEAR(rec.segs[0].profile.v1, vj, 1e-9);
  EXPECT_NEAR(rec.segs[1].profile.v0, vj, 1e-9);
  // A larger tolerance lets the corner go faster.
  EXPECT_LT(run(testMachine(0, 0.5), {line(P(0, 0), P(10, 0), 6000), line(P(10, 0), P(10, 10), 6000)}), corner);
  // A reversal stops.
  Recorder back;
  run(m, {line(P(0, 0), P(10, 0), 6000), line(P(10, 0), P(0, 0), 6000)}, &back);
  EXPECT_NEAR(back.segs[0].profile.v1, 0, 1e-12);
}

TEST(Planner, ExactStopAddsTime) {
  Machine m = testMachine(20000);
  double single = run(m, {line(P(0, 0), P(10, 0), 3000)});
  double blended = run(m, {line(P(0, 0), P(10, 0), 3000), line(P(10, 0), P(20, 0), 3000)});
  double stopped = run(m, {line(P(0, 0), P(10, 0), 3000, true), line(P(10, 0), P(20, 0), 3000)});
  EXPECT_LT(blended, stopped);
  EXPECT_NEAR(stopped, 2 * single, 1e-9);
  // G61.1 (path mode exact stop) does the same for every move.
  MotionRecord pm;
  pm.kind = RecordKind::PathMode;
  pm.ivalue = 1;
  EXPECT_NEAR(run(m, {pm, line(P(0, 0), P(10, 0), 3000), line(P(10, 0), P(20, 0), 3000)}), stopped, 1e-9);
  // So do stopping records between moves.
  MotionRecord m0;
  m0.kind = RecordKind::ProgramStop;
  EXPECT_NEAR(run(m, {line(P(0, 0), P(10, 0), 3000), m0, line(P(10, 0), P(20, 0), 3000)}), stopped, 1e-9);
}

TEST(Planner, DwellAddsItsTime) {
  Machine m = testMachine(20000);
  double base = run(m, {line(P(0, 0), P(10, 0), 3000, true), line(P(10, 0), P(20, 0), 3000)});
  MotionRecord dw;
  dw.kind = RecordKind::Dwell;
  dw.value = 2.5;
  dw.end = P(10, 0);
  Recorder rec;
  double t = run(m, {line(P(0, 0), P(10, 0), 3000), dw, line(P(10, 0), P(20, 0), 3000)}, &rec);
  EXPECT_NEAR(t, base + 2.5, 1e-9);
  ASSERT_EQ(rec.segs.size(), 3u);
  EXPECT_EQ(rec.segs[1].record.kind, RecordKind::Dwell);
  EXPECT_NEAR(rec.segs[1].duration(), 2.5, 1e-12);
}

TEST(Planner, ArcSpeedLimitedByCentripetalAcceleration) {
  Machine m = testMachine(0);
  MotionRecord arc;
  arc.kind = RecordKind::Arc;
  arc.start = arc.end = P(1, 0);  // full circle, r = 1 mm
  arc.center = {0, 0, 0};
  arc.turns = 1;
  arc.feed = 6000;
  Recorder rec;
  double t = run(m, {arc}, &rec);
  ASSERT_EQ(rec.segs.size(), 1u);
  double vmax = std::sqrt(1000 * 1.0);  // v^2 / r <= a
  EXPECT_NEAR(rec.segs[0].vmax, vmax, 1e-9);
  EXPECT_GT(t, 2 * M_PI / vmax);
  // A large radius is feed-limited instead.
  arc.start = arc.end = P(100, 0);
  Recorder big;
  run(m, {arc}, &big);
  EXPECT_NEAR(big.segs[0].vmax, 100, 1e-9);
  // Position along the arc stays on the circle.
  AxisVec q = big.segs[0].positionAt(big.segs[0].duration() / 2);
  EXPECT_NEAR(std::hypot(q[0], q[1]), 100, 1e-9);
}

TEST(Planner, FeedIsCappedByMachineAndRapidUsesRapidFeed) {
  Machine m = testMachine(0);
  Recorder rec;
  MotionRecord rapid = line(P(0, 0), P(1000, 0), 0);
  rapid.kind = RecordKind::Rapid;
  run(m, {line(P(0, 0), P(1000, 0), 99999), rapid}, &rec);
  EXPECT_NEAR(rec.segs[0].vmax, 10000.0 / 60, 1e-9);
  EXPECT_NEAR(rec.segs[1].vmax, 12000.0 / 60, 1e-9);
}

TEST(Planner, LookaheadWindowAllowsSpeedOverManyShortMoves) {
  // 100 moves of 0.1 mm in a line: with look-ahead over all of them the speed builds up over
  // the whole run.
  Machine m = testMachine(0, 0.01, 128);
  std::vector<MotionRecord> recs;
  for (int i = 0; i < 100; ++i) recs.push_back(line(P(i * 0.1, 0), P((i + 1) * 0.1, 0), 6000));
  double t = run(m, recs);
  EXPECT_NEAR(t, 0.2, 1e-9);  // 10 mm: 5 up at 1000, 5 down, peak exactly 100 mm/s
  // A window of 32 moves (3.2 mm) must be able to stop within the window: peak sqrt(2 a 3.2).
  double t32 = run(testMachine(0, 0.01, 32), recs);
  EXPECT_GT(t32, t);
  EXPECT_LT(t32, t * 1.1);
  // A window of 2 moves must stop within two moves: far slower.
  EXPECT_GT(run(testMachine(0, 0.01, 2), recs), 2 * t);
}

TEST(Planner, MillionMovesInConstantMemory) {
  Machine m = testMachine(50000, 0.01, 64);
  Planner p(m);
  Recorder rec;
  rec.keep = false;
  p.addListener(&rec);
  const int n = 1000000;
  auto t0 = std::chrono::steady_clock::now();
  MotionRecord r = line(P(0, 0), P(0, 0), 3000);
  for (int i = 0; i < n; ++i) {
    r.start = r.end;
    r.end = P((i + 1) * 0.5, (i % 2) * 0.2);  // zig-zag with small corners
    p.record(r);
  }
  SourceManager sm;
  Diagnostics d(sm);
  p.finish(d);
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(rec.count, (uint64_t)n);
  EXPECT_LE(p.stats().maxQueued, 65u);
  EXPECT_GT(p.totalTime(), 0);
  std::printf("planner: %d moves in %.3f s (%.2f M moves/s)\n", n, secs, n / secs / 1e6);
}

// The S-curve evaluation is consistent: speed is the derivative of distance, and acceleration and
// jerk stay within the limits the profile was planned with.
TEST(Planner, ProfileRespectsAccelAndJerk) {
  Machine m = testMachine(20000, 0.05);
  Recorder rec;
  std::vector<MotionRecord> recs = {line(P(0, 0), P(30, 0), 6000), line(P(30, 0), P(30, 0.7), 6000),
                                    line(P(30, 0.7), P(0, 3), 6000), line(P(0, 3), P(0, 40), 9000, true)};
  run(m, recs, &rec);
  ASSERT_EQ(rec.segs.size(), recs.size());
  for (const auto &seg : rec.segs) {
    const VelocityProfile &p = seg.profile;
    const double h = 1e-5;
    double prevV = p.v0, prevA = 0;
    for (double t = h; t < p.duration(); t += h) {
      double s0, v0, s1, v1;
      p.at(t - h, s0, v0);
      p.at(t, s1, v1);
      EXPECT_NEAR((s1 - s0) / h, 0.5 * (v0 + v1), 1e-3 * std::max(1.0, v1));
      double acc = (v1 - prevV) / h;
      EXPECT_LE(std::fabs(acc), p.accel * (1 + 1e-6) + 1e-6);
      EXPECT_LE(std::fabs(acc - prevA) / h, p.jerk * 1.01 + 1e-3);
      prevV = v1;
      prevA = acc;
    }
  }
}

TEST(Planner, SplineQuarterCircleTimesLikeTheArc) {
  // One move along the curve: the same length, curvature limits and so the same time as the
  // G3 it draws (docs/PLANNER.md, "Splines").
  Machine m = testMachine(0);
  MotionRecord arc;
  arc.kind = RecordKind::Arc;
  arc.start = P(10, 0);
  arc.end = P(0, 10);
  arc.center = {0, 0, 0};
  arc.turns = 1;
  arc.feed = 6000;
  MotionRecord spl = arc;
  spl.kind = RecordKind::Spline;
  SplineData s;
  s.degree = 2;
  s.points = {{10, 10, 0}};
  s.weights = {1, std::sqrt(0.5), 1};
  spl.setSpline(s);
  Recorder rec;
  double ta = run(m, {line(P(0, 0), P(10, 0), 6000), arc}, nullptr);
  double ts = run(m, {line(P(0, 0), P(10, 0), 6000), spl}, &rec);
  EXPECT_NEAR(ts, ta, 1e-3 * ta);
  ASSERT_EQ(rec.segs.size(), 2u);
  const PlannedSegment &g = rec.segs[1];
  EXPECT_EQ(g.record.kind, RecordKind::Spline);
  EXPECT_NEAR(g.length(), 5 * M_PI, 1e-5);
  for (double f : {0.2, 0.5, 0.8}) {
    AxisVec p = g.positionAt(f * g.duration());
    EXPECT_NEAR(std::hypot(p[0], p[1]), 10, 2e-3) << f;
  }
  AxisVec e = g.positionAt(g.duration());
  EXPECT_EQ(e[0], 0);
  EXPECT_EQ(e[1], 10);
}
