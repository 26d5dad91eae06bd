// The shared cycle pieces (runtime/cycles): hole strategies, pattern walkers, clearing rings,
// and the programmable frame's affine maps (runtime/Frame.h).
#include "runtime/Frame.h"
#include "runtime/cycles/Clearing.h"
#include "runtime/cycles/Hole.h"
#include "runtime/cycles/Library.h"
#include "runtime/cycles/Pattern.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc;

namespace {
// "F-5 R2 …": the drilling-axis levels of the moves (R rapid, F feed, D dwell).
std::string levels(const std::vector<CycleStep> &s) {
  std::string out;
  char b[64];
  for (auto &st : s) {
    if (st.kind == CycleStepKind::Dwell) std::snprintf(b, sizeof b, "D%g ", st.seconds);
    else if (st.kind == CycleStepKind::Rapid || st.kind == CycleStepKind::Feed)
      std::snprintf(b, sizeof b, "%c%g ", st.kind == CycleStepKind::Rapid ? 'R' : 'F', st.pos[2]);
    else std::snprintf(b, sizeof b, "S ");
    out += b;
  }
  return out;
}
}  // namespace

TEST(Hole, PeckFullRetractLikeG83) {
  HoleSpec h;
  h.start = 2, h.bottom = -7, h.retract = 10, h.peck = 3, h.reentry = 0.5;
  std::vector<CycleStep> s;
  holeSteps(h, 0, 1, 2, 0, 0, s);
  EXPECT_EQ(levels(s), "F-1 R2 R-0.5 F-4 R2 R-3.5 F-7 R10 ");
}

TEST(Hole, ChipBreaksThenFullRetractWithDegression) {
  // Heidenhain 203 style: pecks 4, 3, 2 (minimum 2), two chip breaks per full retract.
  HoleSpec h;
  h.start = 2, h.bottom = -12, h.retract = 20, h.peck = 4, h.decrement = 1, h.minPeck = 2;
  h.peckFromSet = true, h.peckFrom = 0, h.breaksPerRetract = 2, h.chipBreak = h.reentry = 0.2;
  h.fullRetractFeed = 500, h.dwellBottom = 1;
  std::vector<CycleStep> s;
  holeSteps(h, 0, 1, 2, 0, 0, s);
  EXPECT_EQ(levels(s), "F-4 R-3.8 F-7 R-6.8 F-9 F2 R-8.8 F-11 R-10.8 F-12 D1 R20 ");
  EXPECT_EQ(s[5].feed, 500);  // the full retract at the retraction feed
}

TEST(Hole, UpwardDrillingAndFeedExit) {
  HoleSpec h;
  h.start = -2, h.bottom = 5, h.retract = -10, h.exit = HoleExit::Feed, h.exitLevel = -2, h.exitFeed = 300;
  std::vector<CycleStep> s;
  holeSteps(h, 0, 1, 2, 0, 0, s);
  EXPECT_EQ(levels(s), "F5 F-2 R-10 ");
}

TEST(Pattern, LineCircleGrid) {
  auto line = linePattern({1, 2}, 90, 10, 5, 3);
  ASSERT_EQ(line.size(), 3u);
  EXPECT_EQ(line[2][0], 1);  // exact at 90 degrees
  EXPECT_EQ(line[2][1], 22);
  auto circle = circlePattern({0, 0}, 10, 0, 90, 4);
  EXPECT_EQ(circle[1][0], 0);
  EXPECT_EQ(circle[3][1], -10);
  auto grid = gridPattern({0, 0}, 0, 10, 5, 3, 2, true, false);  // meander: row 2 runs back
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid[3][0], 20);
  EXPECT_EQ(grid[3][1], 5);
  EXPECT_EQ(gridPattern({0, 0}, 0, 1, 1, 4, 4, false, true).size(), 12u);  // the frame of 4 x 4
}

TEST(Pattern, HidePositions) {
  auto pts = linePattern({0, 0}, 0, 0, 1, 6);
  std::string err;
  ASSERT_TRUE(hidePositions(pts, "1, 3-4", err));
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[0][0], 1);
  EXPECT_EQ(pts[1][0], 4);
  EXPECT_FALSE(hidePositions(pts, "x", err));
}

TEST(Clearing, SquarePocketRings) {
  ClearingSpec s;
  s.contour = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  s.toolRadius = 5, s.stepover = 6;
  std::vector<Polygon> rings;
  std::string err;
  ASSERT_TRUE(clearingRings(s, rings, err)) << err;
  // Offsets 5, 11, 17 from the walls (the 23 one is empty): three rings, innermost first.
  ASSERT_EQ(rings.size(), 3u);
  auto extent = [](const Polygon &p) {
    double lo = 1e9, hi = -1e9;
    for (auto &q : p) lo = std::min(lo, q[0]), hi = std::max(hi, q[0]);
    return std::make_pair(lo, hi);
  };
  EXPECT_NEAR(extent(rings[0]).first, 17, 1e-6);
  EXPECT_NEAR(extent(rings[2]).first, 5, 1e-6);
  EXPECT_NEAR(extent(rings[2]).second, 35, 1e-6);
  s.toolRadius = 25, s.stepover = 10;
  EXPECT_FALSE(clearingRings(s, rings, err));
  EXPECT_EQ(err, "the tool does not fit into the region");
}

TEST(Clearing, IslandStays) {
  ClearingSpec s;
  s.contour = {{0, 0}, {60, 0}, {60, 60}, {0, 60}};
  s.islands = {{{20, 20}, {40, 20}, {40, 40}, {20, 40}}};
  s.toolRadius = 4, s.stepover = 5;
  std::vector<Polygon> rings;
  std::string err;
  ASSERT_TRUE(clearingRings(s, rings, err)) << err;
  ASSERT_GE(rings.size(), 4u);  // rings about the island, not only the outer wall's
  bool nearIsland = false;
  for (auto &r : rings)  // no tool centre comes within the radius of the island
    for (auto &q : r) {
      double dx = std::max({20 - q[0], 0.0, q[0] - 40}), dy = std::max({20 - q[1], 0.0, q[1] - 40});
      EXPECT_GE(std::hypot(dx, dy), 4 - 1e-3);
      nearIsland |= std::hypot(dx, dy) < 4 + 1e-3;  // the first ring about it touches at the radius
    }
  EXPECT_TRUE(nearIsland);
}

TEST(Frame, RotationInverseAndStacking) {
  Affine r = Affine::rotation({0, 0, 1}, 90, {10, 0, 0});
  Vec3 p = r.apply({20, 0, 0});
  EXPECT_EQ(p[0], 10);
  EXPECT_EQ(p[1], 10);
  Vec3 q = r.inverse().apply(p);
  EXPECT_NEAR(q[0], 20, 1e-12);
  EXPECT_NEAR(q[1], 0, 1e-12);
  ProgrammableFrame f;
  f.rotationLevels = 2;
  f.rotation[0] = Affine::rotation({1, 0, 0}, 90, {0, 0, 0});
  f.rotation[1] = Affine::rotation({0, 0, 1}, 90, {0, 0, 0});
  f.update();
  AxisVec m = f.out({10, 0, 0, 0, 0, 0});  // inner about Z (X to Y), then outer about X (Y to Z)
  EXPECT_NEAR(m[2], 10, 1e-12);
  EXPECT_NEAR(f.in(m)[0], 10, 1e-12);
  EXPECT_TRUE(f.linear);
}

TEST(Library, EveryEntryHasParametersAndOneRole) {
  for (auto &d : cycleLibrary()) {
    EXPECT_TRUE((d.expand != nullptr) != (d.positions != nullptr)) << d.name;
    EXPECT_NE(std::string(d.params), "") << d.name;
    EXPECT_EQ(findCycle(d.name), &d);
  }
  CycleArgs a;
  a.num["XYZ"] = 1;
  std::string err;
  EXPECT_FALSE(checkCycleArgs(*findCycle("hei.200"), a, err));
}
