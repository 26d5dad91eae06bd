// Peck grooving (runtime/cycles/Grooving.h) on random cycles in every direction: no move leaves
// the rectangle between the start and the end point, every feed advances at most one peck past
// the deepest point reached, every retract backs off exactly e (or to the start line), every
// groove reaches the end depth, the shifts are at most the shift and the last groove is at the end,
// and the cycle ends at the start.
// FEATURES: ISO-CYT-08 ISO-CYT-09
#include "runtime/cycles/Grooving.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {

constexpr double kTol = 1e-9;

void checkCycle(const PeckGroove &g) {
  std::vector<ContourElem> moves;
  std::string err;
  ASSERT_TRUE(peckGrooves(g, moves, err)) << err;
  ASSERT_FALSE(moves.empty());
  const double sa = g.end.a > g.start.a ? 1 : -1;
  auto depth = [&](double a) { return sa * (a - g.start.a); };  // 0 at the start line, grows inwards
  const double full = depth(g.end.a);
  Pt2 at = g.start;
  double deepest = 0, grooveB = g.start.b;
  std::vector<double> grooves;
  for (size_t i = 0; i < moves.size(); ++i) {
    const ContourElem &m = moves[i];
    // Inside the rectangle: never beyond the end point, never behind the start.
    EXPECT_GE(depth(m.end.a), -kTol);
    EXPECT_LE(depth(m.end.a), full + kTol);
    EXPECT_GE(m.end.b, std::min(g.start.b, g.end.b) - kTol);
    EXPECT_LE(m.end.b, std::max(g.start.b, g.end.b) + kTol);
    // Each move runs along one axis.
    EXPECT_TRUE(m.end.a == at.a || m.end.b == at.b) << "move " << i;
    if (m.kind == ContourKind::Line) {  // a peck: along a, inwards, at most one peck past the deepest
      EXPECT_EQ(m.end.b, at.b);
      if (grooves.empty() || at.b != grooves.back()) deepest = 0, grooveB = at.b, grooves.push_back(at.b);
      EXPECT_GT(depth(m.end.a), depth(at.a));
      EXPECT_LE(depth(m.end.a) - deepest, g.peck + kTol) << "move " << i;
      deepest = depth(m.end.a);
    } else if (m.end.b == at.b && depth(m.end.a) > kTol && depth(at.a) < full - kTol) {
      // A chip-breaking retract: back by e, or to the start line.
      EXPECT_NEAR(depth(at.a) - depth(m.end.a), std::min(g.retract, depth(at.a)), kTol) << "move " << i;
    }
    if (m.kind == ContourKind::Rapid && m.end.b != at.b && depth(at.a) >= full - kTol) {
      // The relief at the bottom: back towards the start, at most the relief.
      EXPECT_EQ(grooveB, at.b);
      EXPECT_LE(std::fabs(m.end.b - at.b), g.relief + kTol);
      EXPECT_LE(std::fabs(m.end.b - g.start.b), std::fabs(at.b - g.start.b) + kTol);
    }
    at = m.end;
  }
  EXPECT_EQ(at.a, g.start.a);
  EXPECT_EQ(at.b, g.start.b);
  ASSERT_FALSE(grooves.empty());
  EXPECT_EQ(grooves.front(), g.start.b);
  EXPECT_EQ(grooves.back(), g.end.b);
  for (size_t i = 1; i < grooves.size(); ++i) EXPECT_LE(std::fabs(grooves[i] - grooves[i - 1]), g.shift + kTol);
}

}  // namespace

TEST(Grooving, RandomCyclesStayInsideAndPeckAtMostQ) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> len(0.5, 30), amount(0.1, 5), small(0, 2);
  std::uniform_int_distribution<int> coin(0, 1);
  for (int i = 0; i < 400; ++i) {
    PeckGroove g;
    g.start = {len(rng), len(rng)};
    g.end = {g.start.a + (coin(rng) ? 1 : -1) * len(rng), coin(rng) ? g.start.b : g.start.b + (coin(rng) ? 1 : -1) * len(rng)};
    g.peck = amount(rng), g.shift = amount(rng), g.retract = small(rng), g.relief = small(rng);
    SCOPED_TRACE(i);
    checkCycle(g);
  }
}

TEST(Grooving, ExactDrilling) {
  PeckGroove g;
  g.start = {2, 0}, g.end = {-5, 0}, g.peck = 2, g.retract = 0.5;
  std::vector<ContourElem> m;
  std::string err;
  ASSERT_TRUE(peckGrooves(g, m, err));
  const double want[][2] = {{0, 0}, {0.5, 0}, {-2, 0}, {-1.5, 0}, {-4, 0}, {-3.5, 0}, {-5, 0}, {2, 0}};
  ASSERT_EQ(m.size(), std::size(want));
  for (size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].kind, i % 2 == 0 && i < 7 ? ContourKind::Line : ContourKind::Rapid) << i;
    EXPECT_EQ(m[i].end.a, want[i][0]) << i;
    EXPECT_EQ(m[i].end.b, want[i][1]) << i;
  }
}

TEST(Grooving, Errors) {
  std::vector<ContourElem> m;
  std::string err;
  PeckGroove g;
  g.start = {0, 0}, g.end = {-5, 3}, g.peck = 1, g.shift = 1;
  PeckGroove flat = g;
  flat.end.a = 0;
  EXPECT_FALSE(peckGrooves(flat, m, err));
  EXPECT_EQ(err, "the end point has no depth along the pecks (it is the start's)");
  PeckGroove noPeck = g;
  noPeck.peck = 0;
  EXPECT_FALSE(peckGrooves(noPeck, m, err));
  PeckGroove noShift = g;
  noShift.shift = 0;
  EXPECT_FALSE(peckGrooves(noShift, m, err));
  EXPECT_EQ(err, "the shift between grooves must be greater than 0");
  PeckGroove negative = g;
  negative.retract = -1;
  EXPECT_FALSE(peckGrooves(negative, m, err));
  PeckGroove runaway = g;
  runaway.peck = runaway.shift = 1e-4;
  EXPECT_FALSE(peckGrooves(runaway, m, err));
  EXPECT_TRUE(m.empty());
}
