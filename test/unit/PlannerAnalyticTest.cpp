// Planner v2 against closed forms (docs/PLANNER.md): a long line, a square at a corner
// tolerance, a circle at the centripetal limit, and a chain of tiny collinear moves that must
// reach the same cruise speed as one line (acceleration carried across move boundaries).
#include "runtime/Planner.h"
#include "PlannerTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc;

using namespace ncc::plannertest;

namespace {

Machine machine(double accel, double jerk, double tolerance, int lookahead, double yAccel = 0) {
  return planMachine(accel, jerk, tolerance, lookahead, yAccel);
}

// Independent closed forms of one symmetric jerk-limited change of dv (a trapezoid when j = 0).
double changeTime(double dv, double a, double j) {
  if (dv <= 0) return 0;
  if (j <= 0) return dv / a;
  return dv >= a * a / j ? dv / a + a / j : 2 * std::sqrt(dv / j);
}
double changeDist(double v0, double v1, double a, double j) { return 0.5 * (v0 + v1) * changeTime(std::fabs(v1 - v0), a, j); }

// Time of a straight stretch of length len from v0 to v1 that cruises at v (it must be long enough).
double stretchTime(double len, double v0, double v, double v1, double a, double j) {
  double ramps = changeDist(v0, v, a, j) + changeDist(v, v1, a, j);
  EXPECT_LT(ramps, len);
  return changeTime(v - v0, a, j) + changeTime(v - v1, a, j) + (len - ramps) / v;
}

}  // namespace

TEST(PlannerAnalytic, LongLineTrapezoidAndSCurve) {
  // 200 mm at F6000 = 100 mm/s, a = 1000: trapezoid 2 * 0.1 s + 190 mm / 100.
  EXPECT_NEAR(run(machine(1000, 0, 0.01, 64), {line(P(0, 0), P(200, 0), 6000)}), 0.2 + 1.9, 1e-9);
  // j = 20000: each change 100/1000 + 1000/20000 = 0.15 s over 7.5 mm.
  double t = run(machine(1000, 20000, 0.01, 64), {line(P(0, 0), P(200, 0), 6000)});
  EXPECT_NEAR(t, stretchTime(200, 0, 100, 0, 1000, 20000), 1e-6 * t);
  EXPECT_NEAR(t, 0.3 + 185.0 / 100, 1e-9);
}

TEST(PlannerAnalytic, SquareCornersAtJunctionDeviationSpeed) {
  const double side = 50, delta = 0.05, s = std::sqrt(0.5);
  const double radius = delta * s / (1 - s);  // the virtual corner circle of a right angle
  std::vector<MotionRecord> sq = {line(P(0, 0), P(side, 0), 6000), line(P(side, 0), P(side, side), 6000),
                                  line(P(side, side), P(0, side), 6000), line(P(0, side), P(0, 0), 6000)};
  for (double j : {0.0, 20000.0}) {
    Machine m = machine(1000, j, delta, 64);
    // On the corner arc each axis takes the whole centripetal acceleration at one end of it
    // (and the whole jerk v^3/R^2): v = min(sqrt(a R), cbrt(j R^2)).
    double vc = std::sqrt(1000 * radius);
    if (j > 0) vc = std::min(vc, std::cbrt(j * radius * radius));
    Recorder c;
    double t = run(m, sq, &c);
    ASSERT_EQ(c.segs.size(), 4u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(c.segs[k].profile.v1, vc, 1e-9 * vc) << "j=" << j << " corner " << k;
      EXPECT_NEAR(c.segs[k + 1].profile.v0, vc, 1e-9 * vc);
    }
    double closed = stretchTime(side, 0, 100, vc, 1000, j) + 2 * stretchTime(side, vc, 100, vc, 1000, j) +
                    stretchTime(side, vc, 100, 0, 1000, j);
    EXPECT_NEAR(t, closed, 0.01 * closed) << "j=" << j;
    EXPECT_NEAR(t, closed, 1e-6 * closed) << "j=" << j;
  }
}

TEST(PlannerAnalytic, CornerFollowsTheSlowestAxis) {
  // Y takes a quarter of X's acceleration: the X->Y corner runs at sqrt(250 R), not sqrt(1000 R).
  const double delta = 0.05, s = std::sqrt(0.5), radius = delta * s / (1 - s);
  Recorder c;
  run(machine(1000, 0, delta, 64, 250), {line(P(0, 0), P(50, 0), 6000), line(P(50, 0), P(50, 50), 6000)}, &c);
  ASSERT_EQ(c.segs.size(), 2u);
  EXPECT_NEAR(c.segs[0].profile.v1, std::sqrt(250 * radius), 1e-9);
}

TEST(PlannerAnalytic, FullCircleAtCentripetalLimit) {
  MotionRecord arc;
  arc.kind = RecordKind::Arc;
  arc.start = arc.end = P(2, 0);  // r = 2 mm, F6000 = 100 mm/s is above the limits
  arc.center = {0, 0, 0};
  arc.turns = 1;
  arc.feed = 6000;
  const double r = 2, len = 2 * M_PI * r;
  for (double j : {0.0, 20000.0}) {
    double v = std::sqrt(1000 * r);                 // v^2 / r <= a
    if (j > 0) v = std::min(v, std::cbrt(j * r * r));  // v^3 / r^2 <= j
    Recorder c;
    double t = run(machine(1000, j, 0.01, 64), {arc}, &c);
    ASSERT_EQ(c.segs.size(), 1u);
    EXPECT_NEAR(c.segs[0].profile.vp, v, 1e-9 * v) << "j=" << j;
    double closed = stretchTime(len, 0, v, 0, 1000, j);
    EXPECT_NEAR(t, closed, 0.01 * closed) << "j=" << j;
    EXPECT_NEAR(t, closed, 1e-6 * closed) << "j=" << j;
  }
}

TEST(PlannerAnalytic, TinyCollinearMovesCruiseLikeOneLine) {
  // 10,000 moves of 0.01 mm: the S-curve ramp to 100 mm/s needs 7.5 mm (750 moves); a planner
  // that brings acceleration to zero at every move could not get above ~1.7 mm/s.
  Machine m = machine(1000, 20000, 0.01, 4096);
  std::vector<MotionRecord> chain;
  for (int i = 0; i < 10000; ++i) chain.push_back(line(P(i * 0.01, 0), P((i + 1) * 0.01, 0), 6000));
  Recorder one, many;
  PlannerStats st;
  double tOne = run(m, {line(P(0, 0), P(100, 0), 6000)}, &one);
  double tMany = run(m, chain, &many, &st);
  double peak = 0;
  for (const auto &s : many.segs) peak = std::max(peak, s.profile.vp);
  EXPECT_NEAR(peak, one.segs[0].profile.vp, 0.01 * peak);
  EXPECT_NEAR(peak, 100, 1e-9);
  EXPECT_NEAR(tMany, tOne, 0.01 * tOne);
  EXPECT_LE(st.runs, 10u);  // runs of half the window, not one ramp per move
  EXPECT_LE(st.maxQueued, 4097u);
  // Speed and acceleration are continuous across boundaries, and acceleration is carried:
  // inside the first ramp a boundary is passed at full path acceleration.
  double maxBoundaryAccel = 0;
  for (size_t k = 0; k + 1 < many.segs.size(); ++k) {
    const VelocityProfile &a = many.segs[k].profile, &b = many.segs[k + 1].profile;
    double s0, v0, a0, s1, v1, a1;
    a.at(a.duration(), s0, v0, a0);
    b.at(0, s1, v1, a1);
    ASSERT_NEAR(v0, v1, 1e-9) << k;
    ASSERT_NEAR(a0, a1, 1e-6) << k;
    maxBoundaryAccel = std::max(maxBoundaryAccel, a1);
  }
  EXPECT_NEAR(maxBoundaryAccel, 1000, 1);
}

TEST(PlannerAnalytic, SlicesCoverTheRampExactly) {
  // Uneven moves in one run: the slices' lengths are the moves', their times add up to the ramp.
  Machine m = machine(1000, 20000, 0.01, 64);
  std::vector<MotionRecord> recs;
  double x = 0;
  for (double len : {0.3, 2.0, 0.01, 5.0, 0.7, 9.0, 0.05}) {
    recs.push_back(line(P(x, 0), P(x + len, 0), 6000));
    x += len;
  }
  Recorder c;
  double t = run(m, recs, &c);
  double one = run(m, {line(P(0, 0), P(x, 0), 6000)});
  EXPECT_NEAR(t, one, 1e-9);
  ASSERT_EQ(c.segs.size(), recs.size());
  for (size_t k = 0; k < recs.size(); ++k) {
    EXPECT_NEAR(c.segs[k].length(), recs[k].end[0] - recs[k].start[0], 1e-12);
    AxisVec e = c.segs[k].positionAt(c.segs[k].duration());
    EXPECT_NEAR(e[0], recs[k].end[0], 1e-9);
    AxisVec mid = c.segs[k].positionAt(c.segs[k].duration() / 2);
    EXPECT_GT(mid[0], recs[k].start[0]);
    EXPECT_LT(mid[0], recs[k].end[0]);
  }
}

TEST(PlannerAnalytic, RandomPathsStayFeasibleAndContinuous) {
  // Random polylines with arcs, feed changes, exact stops and zero-length moves, over several
  // window sizes: every slice ends at its move's length (Recorder), speed is continuous from
  // move to move, and no slice exceeds its cap or its ramp's acceleration.
  uint64_t seed = 12345;
  auto rnd = [&] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(seed >> 11) / 9007199254740992.0;
  };
  for (int lookahead : {1, 2, 5, 16, 64}) {
    Machine m = machine(1000, 20000, 0.02, lookahead, 400);
    std::vector<MotionRecord> recs;
    AxisVec pos = P(0, 0);
    for (int i = 0; i < 600; ++i) {
      double u = rnd(), feed = u < 0.3 ? 3000 : u < 0.6 ? 6000 : 1200;
      AxisVec next = pos;
      if (rnd() < 0.05) {
        recs.push_back(line(pos, pos, feed));  // zero length
        continue;
      }
      if (rnd() < 0.15) {  // a half circle to the side
        MotionRecord arc;
        arc.kind = RecordKind::Arc;
        arc.start = pos;
        double r = 0.5 + 3 * rnd();
        next[0] += 2 * r;
        arc.end = next;
        arc.center = {pos[0] + r, pos[1], 0};
        arc.turns = rnd() < 0.5 ? 1 : -1;
        arc.feed = feed;
        recs.push_back(arc);
      } else {
        double len = rnd() < 0.5 ? 0.05 * rnd() : 5 * rnd(), ang = (rnd() < 0.7 ? 0.2 : 3.0) * (rnd() - 0.5);
        next[0] += len * std::cos(ang);
        next[1] += len * std::sin(ang);
        recs.push_back(line(pos, next, feed, rnd() < 0.03));
      }
      pos = next;
    }
    Recorder rec;
    PlannerStats st;
    run(m, recs, &rec, &st);
    ASSERT_EQ(rec.segs.size(), recs.size());
    EXPECT_LE(st.maxQueued, (size_t)lookahead + 1);
    for (size_t k = 0; k < rec.segs.size(); ++k) {
      const VelocityProfile &p = rec.segs[k].profile;
      if (k > 0) EXPECT_NEAR(rec.segs[k - 1].profile.v1, p.v0, 1e-6) << "lookahead " << lookahead << " move " << k;
      for (int i = 0; i <= 8; ++i) {
        double s, v, a;
        p.at(p.duration() * i / 8, s, v, a);
        EXPECT_LE(v, rec.segs[k].vmax * (1 + 1e-9) + 1e-9) << k;
        EXPECT_LE(std::fabs(a), p.accel * (1 + 1e-6) + 1e-6) << k;
        EXPECT_GE(v, -1e-9) << k;
      }
    }
    EXPECT_NEAR(rec.segs.back().profile.v1, 0, 1e-9);
  }
}

TEST(PlannerAnalytic, CarriedAccelerationTurnsWithinTheJerk) {
  // a = 1000, j = 2000, F6000 = 100 mm/s, delta = 0.01. A corner with a virtual radius R does not
  // limit speed once R >= max(v^2/a, sqrt(v^3/j)) = 22.4 mm, but turning the carried
  // acceleration needs a v / R <= j, R >= 50 mm: at R = 30 the moves are two runs, at R = 100 one.
  Machine m = machine(1000, 2000, 0.01, 64);
  for (double radius : {30.0, 100.0}) {
    double k = radius / 0.01, s = k / (1 + k), c = 2 * s * s - 1, th = std::acos(c);  // R = delta s / (1 - s)
    Recorder rec;
    PlannerStats st;
    run(m, {line(P(0, 0), P(50, 0), 6000), line(P(50, 0), P(50 + 50 * std::cos(th), 50 * std::sin(th)), 6000)}, &rec, &st);
    EXPECT_EQ(st.runs, radius < 50 ? 2u : 1u) << radius;
    EXPECT_NEAR(rec.segs[0].profile.v1, 100, 1e-9) << radius;  // the corner itself keeps the feed
  }
}
