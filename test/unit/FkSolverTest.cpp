// The FK solver (frontend/heidenhain/FkSolver.h) against hand-computed cases: intersections, the
// carriers of lines and circles from their data, ends, and the order of the solutions FSELECT
// numbers.
// FEATURES: HEI-MOT-09
#include "frontend/heidenhain/FkSolver.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc::hei::fk;

namespace {
void near(Pt a, Pt b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
}
Hyp at(Pt p, std::optional<Pt> heading = std::nullopt) {
  Hyp h;
  h.at = p;
  h.heading = heading;
  return h;
}
std::vector<Hyp> run(const Hyp &h, const Data &e, bool *undetermined = nullptr) {
  std::string why;
  bool u = false;
  auto r = extend(h, e, 0, why, u);
  if (undetermined) *undetermined = u;
  return r;
}
Data fc(int dr) {
  Data e;
  e.arc = true;
  e.dr = dr;
  return e;
}
const double kS3 = std::sqrt(3.0);
}  // namespace

TEST(FkSolver, Intersections) {
  auto lc = lineCircle({0, 0}, {1, 0}, {5, 0}, 3);  // the one farther along the line first
  ASSERT_EQ(lc.size(), 2u);
  near(lc[0], {8, 0});
  near(lc[1], {2, 0});
  EXPECT_EQ(lineCircle({0, 0}, {1, 0}, {5, 4}, 3).size(), 0u);
  EXPECT_EQ(lineCircle({0, 0}, {1, 0}, {5, 3}, 3).size(), 1u);  // touching: one point
  auto cc = circleCircle({0, 0}, 5, {8, 0}, 5);  // left of c1 -> c2 first
  ASSERT_EQ(cc.size(), 2u);
  near(cc[0], {4, 3});
  near(cc[1], {4, -3});
}

TEST(FkSolver, LineFromAngleAndLength) {
  Data e;
  e.an = 30;
  e.len = 10;
  auto r = run(at({0, 0}), e);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r[0].done.size(), 1u);
  near(r[0].done[0].end, {5 * kS3, 5});
  near(*r[0].heading, {kS3 / 2, 0.5});
}

TEST(FkSolver, TangentArcAndLine) {
  Data e = fc(+1);  // FCT DR+ R10 X+20 Y+10 from X10 Y0 heading +X
  e.tangent = true;
  e.r = 10;
  e.x = 20;
  e.y = 10;
  auto r = run(at({10, 0}, Pt{1, 0}), e);
  ASSERT_EQ(r.size(), 1u);
  near(r[0].done[0].k.c, {10, 10});
  near(*r[0].heading, {0, 1});
  Data l;  // FLT LEN5 goes on up
  l.tangent = true;
  l.len = 5;
  auto r2 = run(r[0], l);
  ASSERT_EQ(r2.size(), 1u);
  near(r2[0].done.back().end, {20, 15});
  // FLT with a direction that is not tangent: no solution.
  l.an = 0;
  EXPECT_TRUE(run(r[0], l).empty());
}

TEST(FkSolver, CircleThroughThreePoints) {
  Data e = fc(-1);  // from X30 Y0 through P1 X20 Y-10 to X10 Y0
  e.through.push_back({20, -10});
  e.x = 10;
  e.y = 0;
  auto r = run(at({30, 0}), e);
  ASSERT_EQ(r.size(), 1u);
  near(r[0].done[0].k.c, {20, 0});
  EXPECT_NEAR(r[0].done[0].k.r, 10, 1e-9);
}

TEST(FkSolver, RadiusAndTwoPointsShorterArcFirst) {
  Data e = fc(+1);  // FC DR+ R5 X+8 Y+0 from X0 Y0: centres X4 Y3 (the short way round) and X4 Y-3
  e.r = 5;
  e.x = 8;
  e.y = 0;
  auto r = run(at({0, 0}), e);
  ASSERT_EQ(r.size(), 2u);
  near(r[0].done[0].k.c, {4, 3});
  near(r[1].done[0].k.c, {4, -3});
}

TEST(FkSolver, OneCoordinateEndInTurnOrder) {
  Data e = fc(-1);  // clockwise about X10 Y0 from X0 Y0 to X=10: Y+10 is reached first
  e.cx = 10;
  e.cy = 0;
  e.x = 10;
  auto r = run(at({0, 0}), e);
  ASSERT_EQ(r.size(), 2u);
  near(r[0].done[0].end, {10, 10});
  near(r[1].done[0].end, {10, -10});
}

TEST(FkSolver, OpenArcMetByLinesAtADistance) {
  Data arc = fc(+1);  // FC DR+ R10 CCX+10 CCY+0 from X0 Y0: its end open
  arc.r = 10;
  arc.cx = 10;
  arc.cy = 0;
  auto r = run(at({0, 0}), arc);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].open.has_value());
  Data line;  // FL AN+90 PDX+10 PDY+0 D5: the lines X15 (PD on its left) and X5
  line.an = 90;
  line.pd = Pt{10, 0};
  line.d = 5;
  std::string why;
  bool u = false;
  auto r2 = extend(r[0], line, 1, why, u);
  ASSERT_EQ(r2.size(), 4u);
  const double h = std::sqrt(75.0);
  Pt expect[] = {{15, h}, {15, -h}, {5, h}, {5, -h}};
  for (int k = 0; k < 4; ++k) {
    ASSERT_EQ(r2[k].done.size(), 1u);  // the arc, now solved; the line is open
    near(r2[k].done[0].end, expect[k]);
    ASSERT_TRUE(r2[k].open.has_value());
    near(r2[k].open->start, expect[k]);
  }
}

TEST(FkSolver, UnsolvableAndUndetermined) {
  Data e = fc(+1);  // the start X0 Y0 is not on the circle R5 about X20 Y0
  e.r = 5;
  e.cx = 20;
  e.cy = 0;
  std::string why;
  bool u = false;
  EXPECT_TRUE(extend(at({0, 0}), e, 0, why, u).empty());
  EXPECT_FALSE(u);
  EXPECT_EQ(why, "its data admit no solution");
  Data open;  // FL AN+0 alone: its end open
  open.an = 0;
  auto r = run(at({0, 0}), open);
  ASSERT_EQ(r.size(), 1u);
  Data next = fc(+1);  // a circle with R only after an open line: not fixed by its own data
  next.r = 5;
  bool undetermined = false;
  EXPECT_TRUE(run(r[0], next, &undetermined).empty());
  EXPECT_TRUE(undetermined);
}
