// comparePaths (ncc translate --verify): equal paths pass, a real difference is reported at the
// right motion, and the short moves an output resolution makes or drops are skipped.
#include "ir/MotionCompare.h"

#include <gtest/gtest.h>

using namespace ncc;

namespace {

// A path of straight feed moves through the given XY points, starting at the origin.
std::vector<MotionRecord> path(std::initializer_list<std::pair<double, double>> points) {
  std::vector<MotionRecord> out;
  AxisVec at{};
  for (auto [x, y] : points) {
    MotionRecord r;
    r.kind = RecordKind::Linear;
    r.feed = 100;
    r.start = at;
    at[0] = x, at[1] = y;
    r.end = at;
    out.push_back(r);
  }
  return out;
}

bool same(const std::vector<MotionRecord> &a, const std::vector<MotionRecord> &b, std::string *why = nullptr) {
  std::string report;
  bool ok = comparePaths(a, b, PathCompareOptions{}, report);
  if (why) *why = report;
  return ok;
}

TEST(MotionCompare, EqualWithinTolerance) {
  EXPECT_TRUE(same(path({{10, 0}, {10, 5}}), path({{10.0004, 0}, {10, 4.9996}})));
}

TEST(MotionCompare, ReportsTheFirstDifference) {
  std::string why;
  EXPECT_FALSE(same(path({{10, 0}, {10, 5}, {0, 5}}), path({{10, 0}, {10, 5.01}, {0, 5}}), &why));
  EXPECT_NE(why.find("paths differ at motion 2: end points differ in Y"), std::string::npos) << why;
}

TEST(MotionCompare, MissingMoveIsADifference) {
  std::string why;
  EXPECT_FALSE(same(path({{10, 0}, {10, 5}}), path({{10, 0}}), &why));
  EXPECT_NE(why.find("differ in length: 2 vs 1"), std::string::npos) << why;
  // A move of a few tolerances is a move: not skipped.
  EXPECT_FALSE(same(path({{10, 0}, {10.003, 0}, {10.003, 5}}), path({{10, 0}, {10.003, 5}})));
}

// Example 09's case (stop 19): a 0.4 µm source move that the 3-decimal output writes as a
// one-unit move, and one the output rounds to nothing.
TEST(MotionCompare, ShortMovesOfRoundingAreSkipped) {
  auto src = path({{55.644209, 62.356365}, {55.644575, 62.355867}, {55.93584, 62.569876}});
  EXPECT_TRUE(same(src, path({{55.644, 62.356}, {55.645, 62.356}, {55.936, 62.57}})));
  EXPECT_TRUE(same(src, path({{55.644, 62.356}, {55.936, 62.57}})));
  // Trailing ones too, on either side.
  EXPECT_TRUE(same(path({{10, 0}}), path({{10, 0}, {10.001, 0}})));
  EXPECT_TRUE(same(path({{10, 0}, {10.001, 0}}), path({{10, 0}})));
}

}  // namespace

// Issue 10: the same tool, spindle and coolant states, in order: each feed move runs in the
// state the commands before it set, wherever between the moves a translator put them.
namespace {
MotionRecord command(RecordKind k, long ivalue = 0, double value = 0) {
  MotionRecord r;
  r.kind = k;
  r.ivalue = ivalue;
  r.value = value;
  return r;
}
std::vector<MotionRecord> withState(std::vector<MotionRecord> prefix, std::vector<MotionRecord> moves) {
  prefix.insert(prefix.end(), moves.begin(), moves.end());
  return prefix;
}
}  // namespace

TEST(MotionCompare, MachineStateAtEachFeedMove) {
  auto moves = path({{10, 0}, {10, 5}});
  auto on = withState({command(RecordKind::ToolChange, 3), command(RecordKind::SpindleSpeed, 0, 1000),
                       command(RecordKind::SpindleCW), command(RecordKind::CoolantFlood, 1)},
                      moves);
  // The same commands in another order before the first move: equal.
  auto reordered = withState({command(RecordKind::CoolantFlood, 1), command(RecordKind::ToolChange, 3),
                              command(RecordKind::SpindleCW), command(RecordKind::SpindleSpeed, 0, 1000)},
                             moves);
  EXPECT_TRUE(same(on, reordered));
  std::string why;
  auto otherTool = on;
  otherTool[0].ivalue = 4;
  EXPECT_FALSE(same(on, otherTool, &why));
  EXPECT_NE(why.find("motion 1: tools differ (T3 vs T4)"), std::string::npos) << why;
  auto ccw = on;
  ccw[2].kind = RecordKind::SpindleCCW;
  EXPECT_FALSE(same(on, ccw, &why));
  EXPECT_NE(why.find("spindle states differ (cw vs ccw)"), std::string::npos) << why;
  auto slower = on;
  slower[1].value = 900;
  EXPECT_FALSE(same(on, slower, &why));
  EXPECT_NE(why.find("spindle speeds differ (S1000 vs S900)"), std::string::npos) << why;
  auto dry = on;
  dry[3].ivalue = 0;
  EXPECT_FALSE(same(on, dry, &why));
  EXPECT_NE(why.find("coolant states differ"), std::string::npos) << why;
  // The coolant switched off between the two moves on one side only: the second move differs.
  auto late = on;
  late.insert(late.end() - 1, command(RecordKind::CoolantFlood, 0));
  EXPECT_FALSE(same(on, late, &why));
  EXPECT_NE(why.find("motion 2: coolant states differ"), std::string::npos) << why;
  // A speed written while the spindle stands still does not count; rapids are not compared.
  auto stopped = withState({command(RecordKind::SpindleSpeed, 0, 500)}, moves);
  EXPECT_TRUE(same(moves, stopped));
}

// A postprocessor passport's split moves (docs/EMIT.md "Passport"): pieces on the source's line,
// forwards, or on its circle adding up to its sweep, pass; anything else is a difference.
namespace {

MotionRecord arcRecord(AxisVec start, AxisVec end, double cx, double cy, int turns) {
  MotionRecord r;
  r.kind = RecordKind::Arc;
  r.feed = 100;
  r.start = start;
  r.end = end;
  r.center = {cx, cy, 0};
  r.turns = turns;
  return r;
}

}  // namespace

TEST(MotionCompare, StraightMoveInParts) {
  EXPECT_TRUE(same(path({{30, 0}}), path({{10, 0}, {20, 0}, {30, 0}})));
  EXPECT_FALSE(same(path({{30, 0}}), path({{10, 0.01}, {30, 0}})));       // off the line
  EXPECT_FALSE(same(path({{30, 0}}), path({{20, 0}, {10, 0}, {30, 0}})));  // backwards on it
}

TEST(MotionCompare, ArcInQuadrants) {
  // A half circle of radius 10 about (10, 0) from (20, 0) counter-clockwise to (0, 0).
  std::vector<MotionRecord> whole = {arcRecord({20, 0, 0}, {0, 0, 0}, 10, 0, 1)};
  std::vector<MotionRecord> parts = {arcRecord({20, 0, 0}, {10, 10, 0}, 10, 0, 1),
                                     arcRecord({10, 10, 0}, {0, 0, 0}, 10, 0, 1)};
  EXPECT_TRUE(same(whole, parts));
  // The same pieces the other way round, and an extra full turn, are not the arc.
  std::vector<MotionRecord> cw = {arcRecord({20, 0, 0}, {10, -10, 0}, 10, 0, -1),
                                  arcRecord({10, -10, 0}, {0, 0, 0}, 10, 0, -1)};
  EXPECT_FALSE(same(whole, cw));
  std::vector<MotionRecord> more = {arcRecord({20, 0, 0}, {10, 10, 0}, 10, 0, 2),
                                    arcRecord({10, 10, 0}, {0, 0, 0}, 10, 0, 1)};
  EXPECT_FALSE(same(whole, more));
}

TEST(MotionCompare, RapidLegsOnlyWhenAsked) {
  auto rapid = [](AxisVec s, AxisVec e) {
    MotionRecord r;
    r.kind = RecordKind::Rapid;
    r.start = s;
    r.end = e;
    return r;
  };
  std::vector<MotionRecord> src = {rapid({0, 0, 10}, {50, 20, 2})};
  std::vector<MotionRecord> legs = {rapid({0, 0, 10}, {50, 20, 10}), rapid({50, 20, 10}, {50, 20, 2})};
  std::vector<MotionRecord> outside = {rapid({0, 0, 10}, {50, 20, 12}), rapid({50, 20, 12}, {50, 20, 2})};
  std::string report;
  PathCompareOptions o;
  EXPECT_FALSE(comparePaths(src, legs, o, report));
  o.rapidLegs = true;
  EXPECT_TRUE(comparePaths(src, legs, o, report)) << report;
  EXPECT_FALSE(comparePaths(src, outside, o, report));
}
