// Cutter radius compensation: offset geometry, corner classification, the one-move-lag stage
// and its use by the executor. Expected numbers were checked against LinuxCNC rs274 runs of the
// equivalent programs (test/lit/oracle/comp_*.ngc hold the recorded ones).
#include "runtime/CutterComp.h"
#include "runtime/Executor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

using namespace ncc;

namespace {

constexpr double kR = 3.175;

PathElem line(double x0, double y0, double x1, double y1) {
  PathElem e;
  e.start = {x0, y0};
  e.end = {x1, y1};
  return e;
}

PathElem arc(double x0, double y0, double x1, double y1, double cx, double cy, int dir) {
  PathElem e = line(x0, y0, x1, y1);
  e.arc = true;
  e.center = {cx, cy};
  e.dir = dir;
  return e;
}

void expectPt(Point2 p, double x, double y, double tol = 1e-4) {
  EXPECT_NEAR(p.x, x, tol);
  EXPECT_NEAR(p.y, y, tol);
}

MotionRecord lineRec(double x0, double y0, double x1, double y1, double z = 0) {
  MotionRecord r;
  r.kind = RecordKind::Linear;
  r.start = {x0, y0, z, 0, 0, 0};
  r.end = {x1, y1, z, 0, 0, 0};
  r.feed = 100;
  return r;
}

MotionRecord arcRec(double x0, double y0, double x1, double y1, double cx, double cy, int turns) {
  MotionRecord r = lineRec(x0, y0, x1, y1);
  r.kind = RecordKind::Arc;
  r.center = {cx, cy, 0};
  r.turns = turns;
  return r;
}

TEST(CutterCompGeometry, TangentsOfLinesAndArcs) {
  expectPt(startTangent(line(0, 0, 10, 0)), 1, 0);
  expectPt(endTangent(line(0, 0, 0, -5)), 0, -1);
  // Counter-clockwise around (0,0) from (10,0): heading +Y; clockwise: -Y.
  expectPt(startTangent(arc(10, 0, 0, 10, 0, 0, 1)), 0, 1);
  expectPt(endTangent(arc(10, 0, 0, 10, 0, 0, 1)), -1, 0);
  expectPt(startTangent(arc(10, 0, 0, -10, 0, 0, -1)), 0, -1);
}

TEST(CutterCompGeometry, OffsetPointsAndArcRadius) {
  PathElem l = line(0, 0, 10, 0);
  expectPt(offsetStart(l, 1, kR), 0, kR);    // left of +X is +Y
  expectPt(offsetEnd(l, -1, kR), 10, -kR);   // right is -Y
  PathElem ccw = arc(10, 0, 0, 10, 0, 0, 1);
  EXPECT_NEAR(offsetRadius(ccw, 1, kR), 10 - kR, 1e-12);   // left of a CCW arc: inside
  EXPECT_NEAR(offsetRadius(ccw, -1, kR), 10 + kR, 1e-12);  // right: outside
  expectPt(offsetEnd(ccw, 1, kR), 0, 10 - kR);
  PathElem cw = arc(10, 0, 0, -10, 0, 0, -1);
  EXPECT_NEAR(offsetRadius(cw, 1, kR), 10 + kR, 1e-12);
  expectPt(offsetStart(cw, 1, kR), 10 + kR, 0);
}

TEST(CutterCompGeometry, CornerKinds) {
  double right = turnAngle({1, 0}, {0, -1}), left = turnAngle({1, 0}, {0, 1});
  EXPECT_NEAR(right, -M_PI / 2, 1e-12);
  EXPECT_NEAR(left, M_PI / 2, 1e-12);
  EXPECT_EQ(cornerKind(right, 1, false), CornerKind::Convex);   // left tool, right turn: outside
  EXPECT_EQ(cornerKind(left, 1, false), CornerKind::Concave);
  EXPECT_EQ(cornerKind(right, -1, false), CornerKind::Concave);
  EXPECT_EQ(cornerKind(left, -1, false), CornerKind::Convex);
  // rs274's smooth limit: 0.0499 rad no corner treatment, 0.0501 a corner.
  EXPECT_EQ(cornerKind(-0.0499, 1, false), CornerKind::Smooth);
  EXPECT_EQ(cornerKind(-0.0501, 1, false), CornerKind::Convex);
  EXPECT_EQ(cornerKind(0.0501, 1, false), CornerKind::Concave);
  // Near a reversal rs274 goes round the corner (177.1 degrees left with G41 is a cut, 177.2
  // goes round) unless the deciding arc has the tool outside: then the cut range runs 0.05 rad
  // past the reversal (177.2 right is a cut, 177 right goes round).
  double d177_1 = 177.1 * M_PI / 180, d177_2 = 177.2 * M_PI / 180, d177 = 177 * M_PI / 180;
  EXPECT_EQ(cornerKind(turnAngle({1, 0}, {-1, 0}), 1, false), CornerKind::Convex);
  EXPECT_EQ(cornerKind(turnAngle({1, 0}, {-1, 0}), -1, false), CornerKind::Convex);
  EXPECT_EQ(cornerKind(d177_1, 1, false), CornerKind::Concave);
  EXPECT_EQ(cornerKind(d177_2, 1, false), CornerKind::Convex);
  EXPECT_EQ(cornerKind(d177_2, 1, true), CornerKind::Concave);
  EXPECT_EQ(cornerKind(-d177_2, 1, true), CornerKind::Concave);
  EXPECT_EQ(cornerKind(-d177, 1, true), CornerKind::Convex);
  EXPECT_EQ(cornerKind(d177_2, -1, true), CornerKind::Concave);  // mirrored for a right tool
}

TEST(CutterCompGeometry, OffsetIntersections) {
  Point2 p;
  // Line-line: pocket corner, tool right of a clockwise path.
  ASSERT_TRUE(offsetIntersection(line(25, 30, 50, 30), line(50, 30, 50, 0), -1, 1.5875, p));
  expectPt(p, 48.4125, 28.4125);
  // Entry move cut by the next line (rs274: -3.1750, 1.3151).
  ASSERT_TRUE(offsetIntersection(line(-20, -20, 0, 0), line(0, 0, 0, 30), 1, kR, p));
  expectPt(p, -3.1750, 1.3151);
  // Line into the outside of a clockwise half circle and out again (rs274: 7.7038 / 18.2962).
  ASSERT_TRUE(offsetIntersection(line(0, 0, 10, 0), arc(10, 0, 16, 0, 13, 0, -1), 1, kR, p));
  expectPt(p, 7.7038, kR);
  ASSERT_TRUE(offsetIntersection(arc(10, 0, 16, 0, 13, 0, -1), line(16, 0, 20, 0), 1, kR, p));
  expectPt(p, 18.2962, kR);
  // Arc-arc: the outside offsets of two clockwise arcs (R10 and R15) meeting at (20, 20).
  double cy = 20 - std::sqrt(125.0);
  ASSERT_TRUE(offsetIntersection(arc(0, 20, 20, 20, 10, 20, -1), arc(20, 20, 40, 20, 30, cy, -1), 1, kR, p));
  EXPECT_NEAR(std::hypot(p.x - 10, p.y - 20), 10 + kR, 1e-9);
  EXPECT_NEAR(std::hypot(p.x - 30, p.y - cy), 15 + kR, 1e-9);
  EXPECT_LT(std::hypot(p.x - 20, p.y - 20), 2 * kR);  // the crossing near the corner
  // Inside a small counter-clockwise arc the offset line never meets the offset circle.
  EXPECT_FALSE(offsetIntersection(line(0, 0, 10, 0), arc(10, 0, 0, 0, 5, 0, 1), 1, kR, p));
}

TEST(CutterCompStage, ConvexCornerArcAndLag) {
  MotionBuffer out;
  CutterComp comp(out);
  comp.start(1, kR, {0, -20, 0, 0, 0, 0});
  ASSERT_TRUE(comp.add(lineRec(0, -20, 0, 0)));  // entry
  EXPECT_TRUE(out.records.empty());               // waits for the next move
  ASSERT_TRUE(comp.add(lineRec(0, 0, 10, 0)));   // right turn: convex for a left tool
  ASSERT_EQ(out.records.size(), 2u);
  EXPECT_NEAR(out.records[0].end[0], -kR, 1e-9);
  EXPECT_NEAR(out.records[0].end[1], 0, 1e-9);
  const MotionRecord &corner = out.records[1];
  EXPECT_EQ(corner.kind, RecordKind::Arc);
  EXPECT_EQ(corner.turns, -1);  // clockwise round the corner
  EXPECT_NEAR(corner.center[0], 0, 1e-9);
  EXPECT_NEAR(corner.center[1], 0, 1e-9);
  EXPECT_NEAR(corner.end[0], 0, 1e-9);
  EXPECT_NEAR(corner.end[1], kR, 1e-9);
  EXPECT_NEAR(corner.feed, 100, 1e-9);
  comp.stop();  // G40: the last line ends normal to its end point
  ASSERT_EQ(out.records.size(), 3u);
  EXPECT_NEAR(out.records[2].start[1], kR, 1e-9);
  EXPECT_NEAR(out.records[2].end[0], 10, 1e-9);
  EXPECT_NEAR(out.records[2].end[1], kR, 1e-9);
  EXPECT_FALSE(comp.active());
  EXPECT_NEAR(comp.toolPosition()[1], kR, 1e-9);
}

TEST(CutterCompStage, ZMovesWaitWithThePendingMove) {
  MotionBuffer out;
  CutterComp comp(out);
  comp.start(-1, kR, {-20, -20, 0, 0, 0, 0});
  ASSERT_TRUE(comp.add(lineRec(-20, -20, 0, 0)));  // entry
  ASSERT_TRUE(comp.add(lineRec(0, 0, 0, 0, -5)));   // plunge: held with the entry
  EXPECT_TRUE(out.records.empty());
  // The next XY move turns right: concave for a right-side tool, so the entry is cut at the
  // crossing and the plunge happens there (rs274: both wait for this move).
  ASSERT_TRUE(comp.add(lineRec(0, 0, 0, -30, -5)));
  ASSERT_EQ(out.records.size(), 2u);
  Point2 cut;
  ASSERT_TRUE(offsetIntersection(line(-20, -20, 0, 0), line(0, 0, 0, -30), -1, kR, cut));
  EXPECT_NEAR(out.records[0].end[0], cut.x, 1e-9);
  EXPECT_NEAR(out.records[0].end[1], cut.y, 1e-9);
  EXPECT_NEAR(out.records[1].end[0], cut.x, 1e-9);
  EXPECT_NEAR(out.records[1].end[1], cut.y, 1e-9);
  EXPECT_NEAR(out.records[1].end[2], -5, 1e-9);
}

TEST(CutterCompStage, CornerBeforeARapidIsStraight) {
  MotionBuffer out;
  CutterComp comp(out);
  comp.start(1, kR, {0, -20, 0, 0, 0, 0});
  ASSERT_TRUE(comp.add(lineRec(0, -20, 0, 0)));
  MotionRecord rapid = lineRec(0, 0, 10, 0);
  rapid.kind = RecordKind::Rapid;
  ASSERT_TRUE(comp.add(rapid));  // convex corner: rs274 traverses straight round it
  ASSERT_EQ(out.records.size(), 2u);
  EXPECT_EQ(out.records[1].kind, RecordKind::Rapid);
  EXPECT_NEAR(out.records[1].end[0], 0, 1e-9);
  EXPECT_NEAR(out.records[1].end[1], kR, 1e-9);
}

TEST(CutterCompStage, Errors) {
  MotionBuffer out;
  CutterComp comp(out);
  comp.start(1, kR, {0, 0, 0, 0, 0, 0});
  EXPECT_FALSE(comp.add(lineRec(0, 0, 3, 0)));
  EXPECT_EQ(comp.rule(), "cutcomp-entry-too-short");
  ASSERT_TRUE(comp.add(lineRec(0, 0, 10, 0)));
  EXPECT_FALSE(comp.add(arcRec(10, 0, 13, 0, 11.5, 0, 1)));  // R1.5 inside
  EXPECT_EQ(comp.rule(), "cutcomp-arc-too-small");
  EXPECT_FALSE(comp.add(arcRec(10, 0, 0, 0, 5, 0, 1)));
  EXPECT_EQ(comp.rule(), "cutcomp-gouge");
  EXPECT_TRUE(out.records.empty());  // nothing emitted by the failed moves
  // A 170 degree left turn: the cut lies behind the start of the line (rs274 refuses it; it
  // lets the entry move run backwards, so this needs a second line).
  ASSERT_TRUE(comp.add(lineRec(10, 0, 20, 0)));
  size_t emitted = out.records.size();
  double a = 170 * M_PI / 180;
  EXPECT_FALSE(comp.add(lineRec(20, 0, 20 + 10 * std::cos(a), 10 * std::sin(a))));
  EXPECT_EQ(comp.error(), "Straight feed in concave corner cannot be reached by the tool without gouging");
  EXPECT_EQ(out.records.size(), emitted);
}

// --- through the executor ---

MachineCmd cmd(CmdKind k, std::initializer_list<std::pair<Word, double>> ws, uint8_t sub = 0) {
  MachineCmd c;
  c.kind = k;
  c.sub = sub;
  for (auto &w : ws) c.set(w.first, w.second);
  return c;
}
MachineCmd linear() {
  MachineCmd c;
  c.kind = CmdKind::Mode;
  c.modes[c.nmodes++] = ModeValue::Linear;
  return c;
}

struct CompRun {
  Machine machine;
  SourceManager sm;
  Diagnostics diags{sm};
  MotionBuffer buf;
  Executor ex{machine, buf, diags};
  CompRun() {
    diags.setCollect(true);
    machine.addTool(1, ToolEdge{0, kR});
  }
  bool operator()(std::initializer_list<MachineCmd> cmds) {
    for (auto &c : cmds)
      if (!ex.exec(c)) return false;
    return true;
  }
  std::vector<MotionRecord> moves() const {
    std::vector<MotionRecord> v;
    for (auto &r : buf.records)
      if (r.kind == RecordKind::Linear || r.kind == RecordKind::Rapid || r.kind == RecordKind::Arc) v.push_back(r);
    return v;
  }
  bool hasRule(const std::string &rule) const {
    for (auto &d : diags.collected())
      if (d.rule == rule) return true;
    return false;
  }
};

TEST(CutterCompExecutor, PocketCornerAndExit) {
  CompRun run;
  ASSERT_TRUE(run({cmd(CmdKind::Feed, {{Word::F, 100}}), linear(), cmd(CmdKind::Move, {{Word::X, 20}, {Word::Y, 10}}),
                   cmd(CmdKind::CutterComp, {{Word::D, 1}}, 2), cmd(CmdKind::Move, {{Word::Y, 30}}),
                   cmd(CmdKind::Move, {{Word::X, 50}}), cmd(CmdKind::Move, {{Word::Y, 0}}),
                   cmd(CmdKind::CutterComp, {}, 0), cmd(CmdKind::Move, {{Word::X, 20}, {Word::Y, 10}})}));
  auto mv = run.moves();
  ASSERT_EQ(mv.size(), 5u);
  // Right of a clockwise path: concave corners cut at the offset intersections.
  EXPECT_NEAR(mv[1].end[0], 20 + kR, 1e-9);
  EXPECT_NEAR(mv[1].end[1], 30 - kR, 1e-9);
  EXPECT_NEAR(mv[2].end[0], 50 - kR, 1e-9);
  EXPECT_NEAR(mv[2].end[1], 30 - kR, 1e-9);
  EXPECT_NEAR(mv[3].end[1], 0, 1e-9);  // last compensated move: normal to its end point
  // The exit move starts where the tool is and goes to the programmed point.
  EXPECT_NEAR(mv[4].start[0], 50 - kR, 1e-9);
  EXPECT_NEAR(mv[4].end[0], 20, 1e-9);
  EXPECT_NEAR(mv[4].end[1], 10, 1e-9);
  // The programmed position is what the executor reports.
  EXPECT_NEAR(run.ex.state().position[0], 20, 1e-9);
  EXPECT_FALSE(run.hasRule("cutcomp-unsupported"));
}

TEST(CutterCompExecutor, ProgramEndFlushesAndRulesHold) {
  CompRun run;
  ASSERT_TRUE(run({cmd(CmdKind::Feed, {{Word::F, 100}}), linear(), cmd(CmdKind::CutterComp, {{Word::D, 1}}, 1),
                   cmd(CmdKind::Move, {{Word::X, 10}}), cmd(CmdKind::Stop, {}, (uint8_t)StopKind::End)}));
  auto mv = run.moves();
  ASSERT_EQ(mv.size(), 1u);
  EXPECT_NEAR(mv[0].end[1], kR, 1e-9);
  EXPECT_EQ(run.buf.records.back().kind, RecordKind::ProgramEnd);

  CompRun twice;
  EXPECT_FALSE(twice({cmd(CmdKind::CutterComp, {{Word::D, 1}}, 1), cmd(CmdKind::CutterComp, {{Word::D, 1}}, 2)}));
  EXPECT_TRUE(twice.hasRule("cutcomp-already-on"));
  CompRun missing;
  EXPECT_FALSE(missing({cmd(CmdKind::CutterComp, {{Word::D, 7}}, 1)}));
  EXPECT_TRUE(missing.hasRule("unknown-tool"));
  CompRun negative;
  EXPECT_FALSE(negative({cmd(CmdKind::CutterComp, {{Word::D, -1}}, 2)}));
  EXPECT_TRUE(negative.hasRule("unknown-tool"));
  CompRun xz;  // G18 compensates (the path reaches the XY computation with its axes turned)
  MachineCmd g18 = linear();
  g18.modes[0] = ModeValue::ZX;
  EXPECT_TRUE(xz({g18, cmd(CmdKind::CutterComp, {{Word::D, 1}}, 1)}));
  EXPECT_FALSE(xz.hasRule("cutcomp-plane"));
}

}  // namespace
