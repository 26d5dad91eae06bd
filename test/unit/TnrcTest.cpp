// Lathe tool nose radius compensation pieces: the imaginary tool tip table and the start-up
// block that ends normal to the next element (the 808D/Fanuc type A start-up). The executor's
// use (tip shift, G41/G42 switch, errors) is tested in test/lit/iso/iso-tool-05-tnrc-*.
#include "runtime/CutterComp.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc;

namespace {

MotionRecord lineRec(double x0, double y0, double x1, double y1, RecordKind k = RecordKind::Linear) {
  MotionRecord r;
  r.kind = k;
  r.start = {x0, y0, 0, 0, 0, 0};
  r.end = {x1, y1, 0, 0, 0, 0};
  r.feed = 100;
  return r;
}

// (Z, X) from the nose centre to the imaginary tip, in nose radii: with +Z right and +X up the
// numbers sit as 2 6 1 / 7 0 5 / 3 8 4 (the Fanuc and Siemens picture).
TEST(NoseTip, VectorTable) {
  const struct {
    int tip;
    double z, x;
  } kCases[] = {{0, 0, 0},  {1, 1, 1}, {2, -1, 1}, {3, -1, -1}, {4, 1, -1}, {5, 1, 0},
                {6, 0, 1},  {7, -1, 0}, {8, 0, -1}, {9, 0, 0},  {10, 0, 0}, {-1, 0, 0}};
  for (auto &c : kCases) {
    Point2 v = noseTipVector(c.tip);
    EXPECT_EQ(v.x, c.z) << "tip " << c.tip;
    EXPECT_EQ(v.y, c.x) << "tip " << c.tip;
  }
}

// The usual outside-diameter tool (tip 3) touches a face with its -Z side and a diameter with
// its -X side: the tip is the corner of the square round the nose.
TEST(NoseTip, OutsideToolTouchesWithItsTip) {
  Point2 v = noseTipVector(3);
  EXPECT_LT(v.x, 0);
  EXPECT_LT(v.y, 0);
  Point2 bore = noseTipVector(2);  // a boring bar in the bore touches the wall above it
  EXPECT_GT(bore.y, 0);
  EXPECT_LT(bore.x, 0);
}

TEST(NoseTip, StartUpEndsNormalToTheNextElement) {
  const double r = 0.4;
  MotionBuffer out;
  CutterComp comp(out);
  // Right-side (G42) compensation in the (Z, X) plane: from (20, 70) to (5, 0), then along -Z.
  comp.start(-1, r, {20, 70, 0, 0, 0, 0}, true);
  ASSERT_TRUE(comp.add(lineRec(20, 70, 5, 0, RecordKind::Rapid)));
  ASSERT_TRUE(comp.add(lineRec(5, 0, 0, 0)));
  ASSERT_EQ(out.records.size(), 1u);  // no corner element after the start-up block
  EXPECT_EQ(out.records[0].kind, RecordKind::Rapid);
  EXPECT_NEAR(out.records[0].end[0], 5, 1e-12);  // normal to the -Z move at its start
  EXPECT_NEAR(out.records[0].end[1], r, 1e-12);
  // rs274's entry would have cut the two offsets at their crossing instead.
  MotionBuffer rs;
  CutterComp rsComp(rs);
  rsComp.start(-1, r, {20, 70, 0, 0, 0, 0});
  ASSERT_TRUE(rsComp.add(lineRec(20, 70, 5, 0, RecordKind::Rapid)));
  ASSERT_TRUE(rsComp.add(lineRec(5, 0, 0, 0)));
  ASSERT_EQ(rs.records.size(), 1u);
  EXPECT_GT(std::fabs(rs.records[0].end[0] - 5), 1e-3);
}

TEST(NoseTip, StartUpMayBeShorterThanTheRadius) {
  MotionBuffer out;
  CutterComp comp(out);
  comp.start(1, 0.8, {0, 0, 0, 0, 0, 0}, true);
  EXPECT_TRUE(comp.add(lineRec(0, 0, 0.5, 0)));  // rs274 refuses this (cutcomp-entry-too-short)
  ASSERT_TRUE(comp.add(lineRec(0.5, 0, 0.5, 10)));
  ASSERT_EQ(out.records.size(), 1u);
  EXPECT_NEAR(out.records[0].end[0], 0.5 - 0.8, 1e-12);  // left of +X travel (second axis up)
  EXPECT_NEAR(out.records[0].end[1], 0, 1e-12);
}

// G41 <-> G42 without G40 (808D manual): the last move on the old side ends normal to its end
// point, and the new side starts from there like a start-up.
TEST(NoseTip, SideSwitchRestartsFromTheCompensatedPoint) {
  const double r = 0.5;
  MotionBuffer out;
  CutterComp comp(out);
  comp.start(-1, r, {10, 10, 0, 0, 0, 0}, true);
  ASSERT_TRUE(comp.add(lineRec(10, 10, 0, 0)));
  ASSERT_TRUE(comp.add(lineRec(0, 0, -10, 0)));
  ASSERT_TRUE(comp.stop(true));
  ASSERT_EQ(out.records.size(), 2u);
  EXPECT_NEAR(out.records[1].end[0], -10, 1e-12);
  EXPECT_NEAR(out.records[1].end[1], r, 1e-12);  // right of -Z travel is +X
  comp.start(1, r, comp.toolPosition(), true);
  ASSERT_TRUE(comp.add(lineRec(-10, 0, -20, 0)));
  ASSERT_TRUE(comp.add(lineRec(-20, 0, -20, -10)));
  ASSERT_EQ(out.records.size(), 3u);
  EXPECT_NEAR(out.records[2].start[1], r, 1e-12);
  EXPECT_NEAR(out.records[2].end[0], -20 + r, 1e-12);  // start-up end: normal to the -X move (left of it is +Z)
  EXPECT_NEAR(out.records[2].end[1], 0, 1e-12);
}

}  // namespace
