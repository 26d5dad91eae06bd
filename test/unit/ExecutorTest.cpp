// Executor and canned-cycle tests on hand-built MachineCmds. Expected values come from rs274
// (LinuxCNC 2.9) runs of the equivalent blocks unless stated otherwise.
#include "runtime/Cycles.h"
#include "runtime/Executor.h"
#include "runtime/cycles/Library.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <utility>

using namespace ncc;

namespace {

MachineCmd mode(std::initializer_list<ModeValue> vs) {
  MachineCmd c;
  c.kind = CmdKind::Mode;
  for (ModeValue v : vs) c.modes[c.nmodes++] = v;
  return c;
}

MachineCmd words(CmdKind k, std::initializer_list<std::pair<Word, double>> ws, uint8_t sub = 0) {
  MachineCmd c;
  c.kind = k;
  c.sub = sub;
  for (auto &w : ws) c.set(w.first, w.second);
  return c;
}

MachineCmd move(std::initializer_list<std::pair<Word, double>> ws) { return words(CmdKind::Move, ws); }
MachineCmd feed(double f) { return words(CmdKind::Feed, {{Word::F, f}}); }

struct ExecRun {
  Machine machine;
  SourceManager sm;
  Diagnostics diags{sm};
  MotionBuffer buf;
  Executor ex{machine, buf, diags};
  ExecRun() { diags.setCollect(true); }
  explicit ExecRun(const Machine &m) : machine(m), ex(machine, buf, diags) { diags.setCollect(true); }
  bool operator()(std::initializer_list<MachineCmd> cmds) {
    for (auto &c : cmds)
      if (!ex.exec(c)) return false;
    return true;
  }
  // Motion records only (Rapid, Linear, Arc).
  std::vector<MotionRecord> moves() const {
    std::vector<MotionRecord> out;
    for (auto &r : buf.records)
      if (r.kind == RecordKind::Rapid || r.kind == RecordKind::Linear || r.kind == RecordKind::Arc) out.push_back(r);
    return out;
  }
  bool hasRule(const std::string &rule) const {
    for (auto &d : diags.collected())
      if (d.rule == rule) return true;
    return false;
  }
  int countRule(const std::string &rule) const {
    int n = 0;
    for (auto &d : diags.collected()) n += d.rule == rule;
    return n;
  }
};

void expectPos(const AxisVec &p, double x, double y, double z, double tol = 1e-9) {
  EXPECT_NEAR(p[0], x, tol);
  EXPECT_NEAR(p[1], y, tol);
  EXPECT_NEAR(p[2], z, tol);
}

TEST(Executor, StartsAtMachineZeroInMmAbsolute) {
  ExecRun run;
  const ModalState &st = run.ex.state();
  EXPECT_EQ(st.units, ModeValue::MM);
  EXPECT_EQ(st.distance, ModeValue::Absolute);
  EXPECT_EQ(st.plane, ModeValue::XY);
  EXPECT_EQ(st.workOffset, 1);
  expectPos(st.position, 0, 0, 0);
}

TEST(Executor, RapidAndFeedKeepAbsentAxes) {
  ExecRun run;
  ASSERT_TRUE(run({move({{Word::X, 10}, {Word::Y, 5}}), mode({ModeValue::Linear}), feed(300),
                   move({{Word::Z, -2}})}));
  auto m = run.moves();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].kind, RecordKind::Rapid);
  expectPos(m[0].end, 10, 5, 0);
  EXPECT_EQ(m[1].kind, RecordKind::Linear);
  expectPos(m[1].start, 10, 5, 0);
  expectPos(m[1].end, 10, 5, -2);
  EXPECT_DOUBLE_EQ(m[1].feed, 300);
}

TEST(Executor, ZeroFeedIsAnError) {
  ExecRun run;
  EXPECT_FALSE(run({mode({ModeValue::Linear}), move({{Word::X, 1}})}));
  ASSERT_EQ(run.diags.collected().size(), 1u);
  EXPECT_EQ(run.diags.collected()[0].message, "Cannot do G1 with zero feed rate");
  EXPECT_EQ(run.diags.collected()[0].rule, "motion-without-feed");
}

TEST(Executor, InchConvertsPositionsCentresAndFeed) {
  ExecRun run;
  ASSERT_TRUE(run({mode({ModeValue::Inch, ModeValue::Linear}), feed(10), move({{Word::X, 1}, {Word::Y, 1}}),
                   mode({ModeValue::ArcCW}), move({{Word::X, 2}, {Word::Y, 0}, {Word::I, 0.5}, {Word::J, -0.5}})}));
  auto m = run.moves();
  ASSERT_EQ(m.size(), 2u);
  expectPos(m[0].end, 25.4, 25.4, 0);
  EXPECT_DOUBLE_EQ(m[0].feed, 254);
  EXPECT_EQ(m[1].kind, RecordKind::Arc);
  expectPos(m[1].end, 50.8, 0, 0);
  EXPECT_NEAR(m[1].center[0], 38.1, 1e-9);
  EXPECT_NEAR(m[1].center[1], 12.7, 1e-9);
  EXPECT_EQ(m[1].turns, -1);
}

TEST(Executor, IncrementalMoves) {
  ExecRun run;
  ASSERT_TRUE(run({move({{Word::X, 10}, {Word::Y, 10}}), mode({ModeValue::Incremental}), move({{Word::X, 5}}),
                   move({{Word::Y, -3}, {Word::Z, 1}})}));
  auto m = run.moves();
  expectPos(m[1].end, 15, 10, 0);
  expectPos(m[2].end, 15, 7, 1);
}

TEST(Executor, ArcRadiusFormCentres) {
  // rs274: from (1,0) G2 X10 Y10 R10 -> centre (10.9999, 0.0501).
  ExecRun run;
  ASSERT_TRUE(run({move({{Word::X, 1}}), feed(100), mode({ModeValue::ArcCW}),
                   move({{Word::X, 10}, {Word::Y, 10}, {Word::R, 10}})}));
  auto m = run.moves();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[1].center[0], 10.9999, 1e-4);
  EXPECT_NEAR(m[1].center[1], 0.0501, 1e-4);
  // rs274: from (40,20) G2 X20 Y0 R28.284271 -> centre (12.6795, 27.3205); negative R the other side.
  ExecRun r2;
  ASSERT_TRUE(r2({move({{Word::X, 40}, {Word::Y, 20}}), feed(100), mode({ModeValue::ArcCW}),
                  move({{Word::X, 20}, {Word::Y, 0}, {Word::R, 28.284271}})}));
  EXPECT_NEAR(r2.moves()[1].center[0], 12.6795, 1e-4);
  EXPECT_NEAR(r2.moves()[1].center[1], 27.3205, 1e-4);
  ExecRun r3;
  ASSERT_TRUE(r3({move({{Word::X, 40}, {Word::Y, 20}}), feed(100), mode({ModeValue::ArcCW}),
                  move({{Word::X, 60}, {Word::Y, 20}, {Word::R, -14.142136}})}));
  EXPECT_NEAR(r3.moves()[1].center[0], 50, 1e-4);  // rs274: (50, 30)
  EXPECT_NEAR(r3.moves()[1].center[1], 30, 1e-4);
}

TEST(Executor, ArcRadiusTooSmallAndSamePoint) {
  ExecRun run;
  EXPECT_FALSE(run({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 20}, {Word::R, 9.99}})}));
  EXPECT_TRUE(run.hasRule("arc-radius-too-small"));
  ExecRun ok;  // 0.001 short of the half chord still passes (rs274 too): a half circle
  ASSERT_TRUE(ok({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 20}, {Word::R, 9.999}})}));
  EXPECT_NEAR(ok.moves()[0].center[0], 10, 1e-9);
  EXPECT_NEAR(ok.moves()[0].center[1], 0, 1e-9);
  ExecRun same;
  EXPECT_FALSE(same({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 0}, {Word::R, 5}})}));
  EXPECT_EQ(same.diags.collected()[0].message, "Current point same as end point of arc");
}

TEST(Executor, ArcRadiusMismatchMessageLikeRs274) {
  // rs274 test e02.
  ExecRun run;
  EXPECT_FALSE(run({move({{Word::X, 10}, {Word::Y, 2}}), feed(100), mode({ModeValue::ArcCW}),
                    move({{Word::X, 20}, {Word::Y, 0}, {Word::I, 5}, {Word::J, -5}})}));
  ASSERT_EQ(run.diags.collected().size(), 1u);
  EXPECT_EQ(run.diags.collected()[0].rule, "arc-radius-mismatch");
  EXPECT_EQ(run.diags.collected()[0].message,
            "Radius to end of arc differs from radius to start: start=(X10.0000,Y2.0000) "
            "center=(X15.0000,Y-3.0000) end=(X20.0000,Y0.0000) r1=7.0711 r2=5.8310 abs_err=1.24 "
            "rel_err=17.5379%");
  // Within rs274's tolerance (0.02 mm off, 0.2 %): accepted.
  ExecRun ok;
  EXPECT_TRUE(ok({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 20}, {Word::I, 10.01}})}));
  ExecRun bad;  // 0.03 mm and 0.3 %: rejected
  EXPECT_FALSE(bad({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 20}, {Word::I, 10.015}})}));
}

TEST(Executor, FullCircleHelixAndTurns) {
  ExecRun run;
  ASSERT_TRUE(run({move({{Word::X, 40}, {Word::Y, 20}}), feed(100), mode({ModeValue::ArcCCW}),
                   move({{Word::X, 40}, {Word::Y, 20}, {Word::Z, -5}, {Word::I, -5}, {Word::J, 0}, {Word::P, 3}})}));
  auto a = run.moves()[1];
  EXPECT_EQ(a.turns, 3);
  expectPos(a.end, 40, 20, -5);
  EXPECT_NEAR(a.center[0], 35, 1e-12);
  EXPECT_NEAR(a.center[1], 20, 1e-12);
}

TEST(Executor, ZXPlaneArcUsesKAndI) {
  ExecRun run;
  ASSERT_TRUE(run({feed(300), mode({ModeValue::ZX, ModeValue::ArcCW}),
                   move({{Word::X, 10}, {Word::Z, 10}, {Word::I, 5}, {Word::K, 5}})}));
  auto a = run.moves()[0];
  EXPECT_EQ(a.plane, Plane::ZX);
  EXPECT_NEAR(a.center[0], 5, 1e-12);
  EXPECT_NEAR(a.center[2], 5, 1e-12);
}

TEST(Executor, AbsoluteArcCentres) {
  ExecRun run;
  ASSERT_TRUE(run({feed(300), mode({ModeValue::ArcAbsolute, ModeValue::ArcCW}), move({{Word::X, 20}, {Word::I, 10}, {Word::J, 0}})}));
  EXPECT_NEAR(run.moves()[0].center[0], 10, 1e-12);
}

TEST(Executor, WorkOffsetsG92AndG10) {
  Machine m;
  m.workOffsets[0] = {10, 20, -5, 0, 0, 0};
  ExecRun run(m);
  ASSERT_TRUE(run({move({{Word::X, 0}, {Word::Y, 0}, {Word::Z, 0}})}));
  expectPos(run.moves()[0].end, 10, 20, -5);
  // G10 L2 P2 then G55.
  ASSERT_TRUE(run({words(CmdKind::SetOffset, {{Word::P, 2}, {Word::X, 100}, {Word::Y, 50}}, (uint8_t)SetOffsetKind::G10L2),
                   words(CmdKind::WorkOffset, {}, 2), move({{Word::X, 1}, {Word::Y, 1}})}));
  expectPos(run.moves()[1].end, 101, 51, -5);
  // G92 X0 Y0 here: program 0 0 is the current point.
  ASSERT_TRUE(run({words(CmdKind::SetOffset, {{Word::X, 0}, {Word::Y, 0}}, (uint8_t)SetOffsetKind::G92),
                   move({{Word::X, 2}, {Word::Y, 2}})}));
  expectPos(run.moves()[2].end, 103, 53, -5);
  // G92.1, then G10 L20 P0 X0: the current X becomes program 0 in the active system.
  ASSERT_TRUE(run({words(CmdKind::SetOffset, {}, (uint8_t)SetOffsetKind::G92Cancel), move({{Word::X, 3}}),
                   words(CmdKind::SetOffset, {{Word::P, 0}, {Word::X, 0}}, (uint8_t)SetOffsetKind::G10L20),
                   move({{Word::X, 1}})}));
  EXPECT_NEAR(run.moves()[4].end[0], 104, 1e-12);
  // G53: machine coordinates, one move.
  ASSERT_TRUE(run({words(CmdKind::MachineMove, {{Word::X, 0}, {Word::Y, 0}})}));
  expectPos(run.moves()[5].end, 0, 0, -5);
}

TEST(Executor, ToolLengthFromTable) {
  Machine m;
  m.addTool(1, ToolEdge{25.4, 3});
  ExecRun run(m);
  ASSERT_TRUE(run({words(CmdKind::ToolSelect, {{Word::T, 1}}), words(CmdKind::ToolChange, {}),
                   words(CmdKind::ToolLength, {{Word::H, 1}}), move({{Word::Z, 10}})}));
  expectPos(run.moves()[0].end, 0, 0, 35.4);
  ASSERT_TRUE(run({words(CmdKind::ToolLength, {{Word::H, 0}}), move({{Word::Z, 10}})}));
  expectPos(run.moves()[1].end, 0, 0, 10);
  EXPECT_FALSE(run({words(CmdKind::ToolLength, {{Word::H, 7}})}));
  EXPECT_TRUE(run.hasRule("unknown-tool"));
}

TEST(Executor, HomeThroughIntermediatePoint) {
  Machine m;
  m.home1 = {0, 0, 50, 0, 0, 0};
  m.home2 = {100, 100, 50, 0, 0, 0};
  ExecRun run(m);
  ASSERT_TRUE(run({move({{Word::X, 5}, {Word::Y, 5}}), words(CmdKind::Home, {{Word::Z, 25}}, 1),
                   words(CmdKind::Home, {}, 2)}));
  auto mv = run.moves();
  ASSERT_EQ(mv.size(), 5u);
  expectPos(mv[1].end, 5, 5, 25);   // intermediate
  expectPos(mv[2].end, 5, 5, 50);   // only Z homes
  expectPos(mv[3].end, 5, 5, 50);   // G30 without words: intermediate = here
  expectPos(mv[4].end, 100, 100, 50);
}

TEST(Executor, CutterCompWithoutDKeepsPath) {
  // G41 with no D (and none active): radius 0, the programmed path, a warning.
  ExecRun run;
  ASSERT_TRUE(run({words(CmdKind::CutterComp, {}, 1), feed(100), mode({ModeValue::Linear}), move({{Word::X, 5}}),
                   words(CmdKind::CutterComp, {}, 0)}));
  EXPECT_EQ(run.countRule("cutcomp-without-d"), 1);
  expectPos(run.moves()[0].end, 5, 0, 0);
}

TEST(Executor, CodeAfterEndWarnsOnce) {
  ExecRun run;
  ASSERT_TRUE(run({words(CmdKind::Stop, {}, (uint8_t)StopKind::End), mode({ModeValue::Rapid}), move({{Word::X, 1}}),
                   move({{Word::X, 2}})}));
  EXPECT_EQ(run.countRule("code-after-end"), 1);
  EXPECT_TRUE(run.ex.finish());
  EXPECT_FALSE(run.hasRule("missing-program-end"));
  ExecRun noEnd;
  noEnd.ex.finish();
  EXPECT_TRUE(noEnd.hasRule("missing-program-end"));
}

TEST(Executor, MachineStateRecords) {
  ExecRun run;
  MachineCmd cool;
  cool.kind = CmdKind::Coolant;
  cool.sub = 1;
  cool.sub2 = 1;
  ASSERT_TRUE(run({words(CmdKind::Speed, {{Word::S, 1200}}), words(CmdKind::Spindle, {}, 1), cool,
                   words(CmdKind::Dwell, {{Word::P, 1.5}}), words(CmdKind::Stop, {}, (uint8_t)StopKind::EndRewind)}));
  std::vector<RecordKind> kinds;
  for (auto &r : run.buf.records) kinds.push_back(r.kind);
  std::vector<RecordKind> want = {RecordKind::SpindleSpeed, RecordKind::SpindleCW, RecordKind::CoolantFlood,
                                  RecordKind::Dwell, RecordKind::ProgramEnd};
  EXPECT_EQ(kinds, want);
  EXPECT_EQ(run.buf.records[4].ivalue, 30);
  EXPECT_DOUBLE_EQ(run.buf.records[3].value, 1.5);
}

// --- canned cycles ---------------------------------------------------------------------------

std::string steps(const std::vector<CycleStep> &s) {
  std::string out;
  char b[96];
  for (auto &st : s) {
    switch (st.kind) {
    case CycleStepKind::Rapid:
    case CycleStepKind::Feed:
      std::snprintf(b, sizeof b, "%s%s(%g,%g,%g) ", st.preMove ? "pre" : "", st.kind == CycleStepKind::Rapid ? "R" : "F",
                    st.pos[0], st.pos[1], st.pos[2]);
      break;
    case CycleStepKind::Arc:
      std::snprintf(b, sizeof b, "A%s(%g,%g,%g) ", st.ccw ? "+" : "-", st.pos[0], st.pos[1], st.pos[2]);
      break;
    case CycleStepKind::Dwell: std::snprintf(b, sizeof b, "D%g ", st.seconds); break;
    case CycleStepKind::SpindleStop: std::snprintf(b, sizeof b, "S0 "); break;
    case CycleStepKind::SpindleCW: std::snprintf(b, sizeof b, "CW "); break;
    case CycleStepKind::SpindleCCW: std::snprintf(b, sizeof b, "CCW "); break;
    case CycleStepKind::SpindleOrient: std::snprintf(b, sizeof b, "O%g ", st.angle); break;
    case CycleStepKind::RigidTap: std::snprintf(b, sizeof b, "T%g/%g ", st.pos[2], st.lead); break;
    case CycleStepKind::SpindleSpeed: std::snprintf(b, sizeof b, "S%g ", st.speed); break;
    case CycleStepKind::Coolant: std::snprintf(b, sizeof b, "C%d ", st.coolant); break;
    case CycleStepKind::Thread:
      std::snprintf(b, sizeof b, "%s(%g,%g,%g)/%g ", st.chain ? "TC" : "TS", st.pos[0], st.pos[1], st.pos[2], st.lead);
      break;
    }
    out += b;
  }
  if (!out.empty()) out.pop_back();
  return out;
}

CycleInput hole(ModeValue c, double x, double y, double z, double r) {
  CycleInput in;
  in.cycle = c;
  in.current = {0, 0, 10};
  in.initialLevel = 10;
  in.target = {x, y, 0};
  in.z = z;
  in.r = r;
  return in;
}

std::string expand(const CycleInput &in) {
  std::vector<CycleStep> s;
  std::string err;
  if (!expandCycle(in, s, err)) return "error: " + err;
  return steps(s);
}

TEST(Cycles, DrillG98AndG99) {
  CycleInput in = hole(ModeValue::Drill, 10, 10, -5, 2);
  EXPECT_EQ(expand(in), "R(10,10,10) R(10,10,2) F(10,10,-5) R(10,10,10)");
  in.retractToR = true;
  EXPECT_EQ(expand(in), "R(10,10,10) R(10,10,2) F(10,10,-5) R(10,10,2)");
}

TEST(Cycles, DwellPeckAndChipBreak) {
  CycleInput g82 = hole(ModeValue::DrillDwell, 10, 0, -10, 1);
  g82.p = 1.5;
  EXPECT_EQ(expand(g82), "R(10,0,10) R(10,0,1) F(10,0,-10) D1.5 R(10,0,10)");
  CycleInput g83 = hole(ModeValue::Peck, 0, 0, -4, 1);
  g83.q = 3;
  EXPECT_EQ(expand(g83), "R(0,0,10) R(0,0,1) F(0,0,-2) R(0,0,1) R(0,0,-1.746) F(0,0,-4) R(0,0,10)");
  CycleInput g73 = hole(ModeValue::PeckChipBreak, 5, 0, -5, 1);
  g73.q = 3;
  g73.retractToR = true;
  EXPECT_EQ(expand(g73), "R(5,0,10) R(5,0,1) F(5,0,-2) R(5,0,-1.746) F(5,0,-5) R(5,0,1)");
  g73.q = 0;
  EXPECT_EQ(expand(g73), "error: Negative or zero q value used");
}

TEST(Cycles, TappingAndBoring) {
  CycleInput g84 = hole(ModeValue::Tap, 10, 0, -3, 2);
  EXPECT_EQ(expand(g84), "R(10,0,10) R(10,0,2) F(10,0,-3) S0 CCW D0 F(10,0,10) S0 CW");
  CycleInput g85 = hole(ModeValue::BoreFeed, 20, 0, -3, 2);
  EXPECT_EQ(expand(g85), "R(20,0,10) R(20,0,2) F(20,0,-3) F(20,0,2) R(20,0,10)");
  CycleInput g86 = hole(ModeValue::BoreStop, 30, 0, -3, 2);
  g86.p = 1;
  g86.spindle = 2;
  EXPECT_EQ(expand(g86), "R(30,0,10) R(30,0,2) F(30,0,-3) D1 S0 R(30,0,10) CCW");
  CycleInput g89 = hole(ModeValue::BoreDwell, 40, 0, -3, 2);
  g89.p = 2;
  EXPECT_EQ(expand(g89), "R(40,0,10) R(40,0,2) F(40,0,-3) D2 F(40,0,10)");
}

TEST(Cycles, IncrementalRepeats) {
  // rs274: initial level 1, current Z 2, G99 G91 X5 R-1 Z-5 L3 from X40.
  CycleInput in = hole(ModeValue::Drill, 5, 0, -5, -1);
  in.incremental = true;
  in.retractToR = true;
  in.sameCycle = true;
  in.current = {40, 0, 2};
  in.initialLevel = 1;
  in.repeats = 3;
  EXPECT_EQ(expand(in),
            "R(45,0,2) R(45,0,0) F(45,0,-5) R(45,0,0) R(50,0,0) F(50,0,-5) R(50,0,0) R(55,0,0) F(55,0,-5) R(55,0,0)");
  in.repeats = 0;
  EXPECT_EQ(expand(in), "error: Cannot do zero repeats of cycle");
}

TEST(Cycles, InitialLevelBelowR) {
  // Below R: go up at the current position first (outside the hole bracket).
  CycleInput in = hole(ModeValue::Drill, 0, 0, -4, 5);
  in.current = {0, 0, 2};
  in.initialLevel = 2;
  EXPECT_EQ(expand(in), "preR(0,0,5) R(0,0,5) F(0,0,-4) R(0,0,5)");
  in.z = 6;
  EXPECT_EQ(expand(in), "error: R less than z in cycle in xy plane");
}

TEST(Cycles, OtherPlanesDrillAlongTheirAxis) {
  CycleInput in = hole(ModeValue::Drill, 5, 0, -5, 2);
  in.plane = Plane::ZX;  // drills along Y; the hole is at X5 Z3
  in.target = {5, 0, 3};
  in.current = {0, 0, 0};
  in.initialLevel = 0;
  EXPECT_EQ(expand(in), "preR(0,2,0) R(5,2,3) F(5,-5,3) R(5,2,3)");
}

TEST(Cycles, ExecutorBracketsHolesAndKeepsModalData) {
  ExecRun run;
  ASSERT_TRUE(run({move({{Word::Z, 10}}), feed(100), mode({ModeValue::Drill}),
                   move({{Word::X, 10}, {Word::Z, -5}, {Word::R, 2}}), move({{Word::X, 20}})}));
  auto mv = run.moves();
  ASSERT_EQ(mv.size(), 9u);
  expectPos(mv[8].end, 20, 0, 10);  // second hole reuses Z and R, back to the initial level
  expectPos(mv[7].end, 20, 0, -5);
  EXPECT_TRUE(mv[7].exactStop);
  int exactPath = 0;
  for (auto &r : run.buf.records) exactPath += r.kind == RecordKind::PathMode && r.ivalue == 0;
  EXPECT_EQ(exactPath, 2);
  // A first cycle block without Z is an error (rs274's message).
  ExecRun bad;
  EXPECT_FALSE(bad({feed(100), mode({ModeValue::Drill}), move({{Word::X, 1}, {Word::R, 1}})}));
  EXPECT_EQ(bad.diags.collected()[0].message, "Z value unspecified in xy plane canned cycle");
  // G84 needs the spindle turning clockwise.
  ExecRun tap;
  EXPECT_FALSE(tap({feed(100), mode({ModeValue::Tap}), move({{Word::X, 1}, {Word::Z, -1}, {Word::R, 1}})}));
  EXPECT_TRUE(tap.hasRule("cycle-spindle"));
}

}  // namespace

namespace {

TEST(Executor, Rs274ArcAndFeedMessages) {
  struct Case {
    std::initializer_list<MachineCmd> cmds;
    const char *message;
  };
  auto first = [](std::initializer_list<MachineCmd> cmds) {
    ExecRun run;
    EXPECT_FALSE(run(cmds));
    return run.diags.collected().empty() ? std::string() : run.diags.collected()[0].message;
  };
  EXPECT_EQ(first({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 10}})}), "R i j k words all missing for arc");
  EXPECT_EQ(first({feed(100), mode({ModeValue::ZX, ModeValue::ArcCW}), move({{Word::X, 10}, {Word::J, 5}})}),
            "J word given for arc in xz plane");
  EXPECT_EQ(first({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 10}, {Word::I, 5}, {Word::P, 1.5}})}),
            "P value not an integer with G2 or G3");
  EXPECT_EQ(first({feed(100), mode({ModeValue::ArcCW}), move({{Word::X, 10}, {Word::I, 5}, {Word::P, 0}})}),
            "P value should be 1 or greater with G2 or G3");
  EXPECT_EQ(first({feed(100), mode({ModeValue::CycleOff}), move({{Word::X, 5}})}), "Cannot use axis values with G80");
  {
    // With a tool table, a number outside it (and outside free_tools) is an error; without
    // one, every number is a tool of zero length.
    Machine m;
    m.addTool(1, ToolEdge{10, 1});
    ExecRun table(m);
    EXPECT_FALSE(table({words(CmdKind::ToolLength, {{Word::H, 9}})}));
    EXPECT_EQ(table.diags.collected()[0].message, "Requested tool 9 not found in the tool table");
    ExecRun tsel(m);
    EXPECT_FALSE(tsel({words(CmdKind::ToolSelect, {{Word::T, 2}})}));
    EXPECT_EQ(tsel.diags.collected()[0].message, "Requested tool 2 not found in the tool table");
    m.freeTools = 9;
    ExecRun freeTools(m);
    EXPECT_TRUE(freeTools({words(CmdKind::ToolLength, {{Word::H, 9}})}));
    ExecRun noTable;
    EXPECT_TRUE(noTable({words(CmdKind::ToolLength, {{Word::H, 9}})}));
  }
  // Inverse time: F in the block of each feed move.
  EXPECT_EQ(first({feed(100), mode({ModeValue::InverseTime, ModeValue::Linear}), words(CmdKind::Block, {}),
                   move({{Word::X, 10}})}),
            "F word missing with inverse time G1 move");
  ExecRun ok;
  ASSERT_TRUE(ok({mode({ModeValue::InverseTime, ModeValue::Linear}), words(CmdKind::Block, {}), feed(2),
                  move({{Word::X, 10}})}));
  EXPECT_DOUBLE_EQ(ok.moves()[0].feed, 20);  // 10 mm in 1/2 min (rs274 prints 20.0000)
}

}  // namespace

namespace {

TEST(Executor, BadNumbersAreDiagnosed) {
  ExecRun run;
  EXPECT_FALSE(run({move({{Word::X, std::nan("")}})}));
  EXPECT_TRUE(run.hasRule("bad-number"));
  ExecRun big;
  EXPECT_FALSE(big({words(CmdKind::ToolLength, {{Word::H, 1e300}})}));
  EXPECT_FALSE(big({words(CmdKind::SetOffset, {{Word::P, 1e300}, {Word::X, 1}}, (uint8_t)SetOffsetKind::G10L2)}));
  EXPECT_FALSE(big({words(CmdKind::SetOffset, {{Word::P, -1}, {Word::X, 1}}, (uint8_t)SetOffsetKind::G10L20)}));
  EXPECT_FALSE(big({words(CmdKind::Aux, {{Word::P, 1e300}}, 'M')}));
  EXPECT_FALSE(big({feed(100), mode({ModeValue::Drill}), move({{Word::Z, -1}, {Word::R, 1}, {Word::L, 1e300}})}));
  expectPos(big.ex.state().position, 0, 0, 0);
}

}  // namespace

// A library cycle's arcs go out as Motion IR arcs in the work offset: the centre moves with the
// end points, the turn follows the step, the rate is the step's own.
TEST(Executor, LibraryCycleArcsInTheWorkOffset) {
  Machine m;
  m.workOffsets[0] = {100, 50, 0, 0, 0, 0};
  ExecRun run(m);
  ASSERT_TRUE(run({words(CmdKind::SetOffset, {{Word::P, 1}, {Word::R, 5}}, (uint8_t)SetOffsetKind::ToolSet),
                   words(CmdKind::ToolSelect, {{Word::T, 1}}), words(CmdKind::ToolChange, {}), feed(1000),
                   move({{Word::X, 0}, {Word::Y, 0}, {Word::Z, 20}})}));
  CycleArgs a;
  a.num = {{"Q215", 2}, {"Q223", 30}, {"Q368", 0.5}, {"Q207", 500}, {"Q385", 300}, {"Q201", -5}, {"Q202", 5},
           {"Q206", 150}, {"Q200", 2}, {"Q203", 0}};
  ASSERT_TRUE(run.ex.runCycle(*findCycle("hei.252"), a, nullptr, nullptr, {}));
  std::vector<MotionRecord> arcs;
  for (auto &r : run.moves())
    if (r.kind == RecordKind::Arc) arcs.push_back(r);
  ASSERT_EQ(arcs.size(), 3u);  // onto the wall, the wall, off it
  EXPECT_NEAR(arcs[1].center[0], 100, 1e-9);
  EXPECT_NEAR(arcs[1].center[1], 50, 1e-9);
  expectPos(arcs[1].end, 110, 50, -5);  // the wall path: 15 - 5 from the centre
  EXPECT_EQ(arcs[1].turns, 1);          // climb with M3: counter-clockwise, a full circle
  EXPECT_EQ(arcs[1].plane, Plane::XY);
  EXPECT_DOUBLE_EQ(arcs[1].feed, 300);
  EXPECT_TRUE(arcs[1].exactStop);
  EXPECT_NEAR(arcs[0].center[0], 107.5, 1e-9);  // the quarter arc onto the wall
}

// Under a rotation about the drilling axis (G68 R90 about the origin) the library cycle's arcs
// turn with their end points and keep their sense.
TEST(Executor, LibraryCycleArcsUnderARotation) {
  ExecRun run;
  MachineCmd rot = words(CmdKind::Frame, {{Word::X, 0}, {Word::Y, 0}, {Word::R, 90}}, (uint8_t)FrameSlot::Rotation);
  rot.sub2 = (uint8_t)FrameAction::Set;
  ASSERT_TRUE(run({words(CmdKind::SetOffset, {{Word::P, 1}, {Word::R, 5}}, (uint8_t)SetOffsetKind::ToolSet),
                   words(CmdKind::ToolSelect, {{Word::T, 1}}), words(CmdKind::ToolChange, {}), feed(1000),
                   move({{Word::X, 0}, {Word::Y, 0}, {Word::Z, 20}}), rot}));
  CycleArgs a;
  a.num = {{"Q215", 2}, {"Q223", 30}, {"Q368", 0.5}, {"Q207", 500}, {"Q201", -5}, {"Q202", 5}, {"Q206", 150},
           {"Q200", 2}, {"Q203", 0}};
  ASSERT_TRUE(run.ex.runCycle(*findCycle("hei.252"), a, nullptr, nullptr, {}));
  std::vector<MotionRecord> arcs;
  for (auto &r : run.moves())
    if (r.kind == RecordKind::Arc) arcs.push_back(r);
  ASSERT_EQ(arcs.size(), 3u);
  EXPECT_NEAR(arcs[0].center[0], 0, 1e-9);  // the quarter arc's centre (7.5, 0) turned to (0, 7.5)
  EXPECT_NEAR(arcs[0].center[1], 7.5, 1e-9);
  expectPos(arcs[1].end, 0, 10, -5);
  EXPECT_EQ(arcs[1].turns, 1);
}

// --- constant surface speed (runtime/ExecutorSpindle.cpp) -------------------------------------
// The spindle_mode records, the rpm from the tool's radius with the limits, and feed per
// revolution as the mean path speed (FEATURES ISO-SPD-02 ISO-SPD-03).
namespace {
constexpr uint8_t kRpm = 1, kCss = 2;
std::vector<MotionRecord> recordsOf(const ExecRun &run, RecordKind k) {
  std::vector<MotionRecord> out;
  for (auto &r : run.buf.records)
    if (r.kind == k) out.push_back(r);
  return out;
}
// The mean path speed of a straight feed from radius r0 to r1 (no limit): the time is the
// integral of ds / (f K / r), K = 1000 S / (2 pi).
double meanFeed(double f, double s, double r0, double r1) {
  double k = 1000 * s / (2 * M_PI);
  return f * k / ((r0 + r1) / 2);
}

}  // namespace

TEST(ExecutorSpindle, CssRecordsAndFeedPerRevolution) {
  ExecRun run;
  ASSERT_TRUE(run({mode({ModeValue::ZX, ModeValue::PerRev}), words(CmdKind::Speed, {{Word::S, 150}, {Word::D, 2000}}, kCss),
                   words(CmdKind::Spindle, {}, 1), words(CmdKind::Move, {{Word::X, 40}, {Word::Z, 5}}),
                   words(CmdKind::Feed, {{Word::F, 0.2}}), mode({ModeValue::Linear}),
                   words(CmdKind::Move, {{Word::X, 80}, {Word::Z, -30}}), words(CmdKind::Move, {{Word::X, 10}}),
                   words(CmdKind::Speed, {{Word::S, 600}}, kRpm), words(CmdKind::Move, {{Word::Z, -40}})}))
      << run.diags.collected().front().message;
  auto mode = recordsOf(run, RecordKind::SpindleMode);
  ASSERT_EQ(mode.size(), 2u);
  EXPECT_EQ(mode[0].ivalue, 1);
  EXPECT_EQ(mode[0].value, 2000);
  EXPECT_EQ(mode[0].value2, 0);
  EXPECT_EQ(mode[1].ivalue, 0);
  auto lin = recordsOf(run, RecordKind::Linear);
  ASSERT_EQ(lin.size(), 3u);
  // 1/rpm is linear in the radius while the limit is not reached: the midpoint sum is exact.
  EXPECT_NEAR(lin[0].feed, meanFeed(0.2, 150, 40, 80), 1e-9);
  // From X80 to X10: below r = 1000 * 150 / (2 pi 2000) = 11.94 mm the limit holds (2000 rpm).
  const double rLimit = 150000 / (2 * M_PI * 2000);
  double time = (80 - rLimit) * (80 + rLimit) / 2 / (0.2 * 150000 / (2 * M_PI)) + (rLimit - 10) / (0.2 * 2000);
  EXPECT_NEAR(lin[1].feed, 70 / time, 70 / time * 1e-3);
  EXPECT_NEAR(lin[2].feed, 0.2 * 600, 1e-9);  // G97 S600
}

TEST(ExecutorSpindle, G97WithoutSKeepsTheSpeedReached) {
  ExecRun run;
  ASSERT_TRUE(run({mode({ModeValue::ZX}), words(CmdKind::Speed, {{Word::S, 100}}, kCss), words(CmdKind::Spindle, {}, 1),
                   words(CmdKind::Move, {{Word::X, 25}}), words(CmdKind::Speed, {}, kRpm)}));
  auto speeds = recordsOf(run, RecordKind::SpindleSpeed);
  ASSERT_EQ(speeds.size(), 2u);
  EXPECT_NEAR(speeds[1].value, 100000 / (2 * M_PI * 25), 1e-9);
  EXPECT_FALSE(run.ex.state().css);
}

TEST(ExecutorSpindle, LimitsAndErrors) {
  {  // the machine's top speed bounds CSS at the spindle axis
    ExecRun run;
    run.machine.maxSpindleSpeed = 1000;
    ASSERT_TRUE(run({mode({ModeValue::ZX, ModeValue::PerRev, ModeValue::Linear}), words(CmdKind::Speed, {{Word::S, 100}}, kCss),
                     words(CmdKind::Feed, {{Word::F, 0.1}}), words(CmdKind::Move, {{Word::Z, -5}})}));
    EXPECT_NEAR(recordsOf(run, RecordKind::Linear)[0].feed, 100, 1e-9);
  }
  {  // without any limit, feed per revolution at X0 is an error
    ExecRun run;
    EXPECT_FALSE(run({mode({ModeValue::ZX, ModeValue::PerRev, ModeValue::Linear}), words(CmdKind::Speed, {{Word::S, 100}}, kCss),
                      words(CmdKind::Feed, {{Word::F, 0.1}}), words(CmdKind::Move, {{Word::Z, -5}})}));
    EXPECT_EQ(run.diags.collected().back().rule, "bad-speed");
  }
  {  // G96 needs S; a negative limit is an error
    ExecRun run;
    EXPECT_FALSE(run({words(CmdKind::Speed, {}, kCss)}));
    ExecRun run2;
    EXPECT_FALSE(run2({words(CmdKind::Speed, {{Word::D, -1}})}));
  }
  {  // M2 resets the spindle mode (the machine's reset list names the spindle)
    ExecRun run;
    ASSERT_TRUE(run({words(CmdKind::Speed, {{Word::S, 100}, {Word::D, 900}}, kCss), words(CmdKind::Stop, {}, (uint8_t)StopKind::End)}));
    EXPECT_FALSE(run.ex.state().css);
    EXPECT_EQ(run.ex.state().speedLimit, 0);
  }
}
