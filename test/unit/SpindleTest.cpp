// Constant surface speed in the executor (runtime/ExecutorSpindle.cpp): the spindle_mode records,
// the rpm from the tool's radius with the limits, and feed per revolution as the mean path speed.
// FEATURES: ISO-SPD-02 ISO-SPD-03
#include "runtime/Executor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

using namespace ncc;

namespace {

MachineCmd cmd(CmdKind k, std::initializer_list<std::pair<Word, double>> ws, uint16_t sub = 0) {
  MachineCmd c;
  c.kind = k;
  c.sub = sub;
  for (auto &w : ws) c.set(w.first, w.second);
  return c;
}
MachineCmd modes(std::initializer_list<ModeValue> vs) {
  MachineCmd c;
  c.kind = CmdKind::Mode;
  for (ModeValue v : vs) c.modes[c.nmodes++] = v;
  return c;
}
constexpr uint16_t kRpm = 1, kCss = 2;

struct SpindleRun {
  Machine machine;
  SourceManager sm;
  Diagnostics diags{sm};
  MotionBuffer buf;
  Executor ex{machine, buf, diags};
  SpindleRun() { diags.setCollect(true); }
  bool operator()(std::initializer_list<MachineCmd> cmds) {
    for (auto &c : cmds)
      if (!ex.exec(c)) return false;
    return true;
  }
  std::vector<MotionRecord> of(RecordKind k) const {
    std::vector<MotionRecord> out;
    for (auto &r : buf.records)
      if (r.kind == k) out.push_back(r);
    return out;
  }
};

// The mean path speed of a straight feed from radius r0 to r1 (no limit): the time is the
// integral of ds / (f K / r), K = 1000 S / (2 pi).
double meanFeed(double f, double s, double r0, double r1) {
  double k = 1000 * s / (2 * M_PI);
  return f * k / ((r0 + r1) / 2);
}

}  // namespace

TEST(Spindle, CssRecordsAndFeedPerRevolution) {
  SpindleRun run;
  ASSERT_TRUE(run({modes({ModeValue::ZX, ModeValue::PerRev}), cmd(CmdKind::Speed, {{Word::S, 150}, {Word::D, 2000}}, kCss),
                   cmd(CmdKind::Spindle, {}, 1), cmd(CmdKind::Move, {{Word::X, 40}, {Word::Z, 5}}),
                   cmd(CmdKind::Feed, {{Word::F, 0.2}}), modes({ModeValue::Linear}),
                   cmd(CmdKind::Move, {{Word::X, 80}, {Word::Z, -30}}), cmd(CmdKind::Move, {{Word::X, 10}}),
                   cmd(CmdKind::Speed, {{Word::S, 600}}, kRpm), cmd(CmdKind::Move, {{Word::Z, -40}})}))
      << run.diags.collected().front().message;
  auto mode = run.of(RecordKind::SpindleMode);
  ASSERT_EQ(mode.size(), 2u);
  EXPECT_EQ(mode[0].ivalue, 1);
  EXPECT_EQ(mode[0].value, 2000);
  EXPECT_EQ(mode[0].value2, 0);
  EXPECT_EQ(mode[1].ivalue, 0);
  auto lin = run.of(RecordKind::Linear);
  ASSERT_EQ(lin.size(), 3u);
  // 1/rpm is linear in the radius while the limit is not reached: the midpoint sum is exact.
  EXPECT_NEAR(lin[0].feed, meanFeed(0.2, 150, 40, 80), 1e-9);
  // From X80 to X10: below r = 1000 * 150 / (2 pi 2000) = 11.94 mm the limit holds (2000 rpm).
  const double rLimit = 150000 / (2 * M_PI * 2000);
  double time = (80 - rLimit) * (80 + rLimit) / 2 / (0.2 * 150000 / (2 * M_PI)) + (rLimit - 10) / (0.2 * 2000);
  EXPECT_NEAR(lin[1].feed, 70 / time, 70 / time * 1e-3);
  EXPECT_NEAR(lin[2].feed, 0.2 * 600, 1e-9);  // G97 S600
}

TEST(Spindle, G97WithoutSKeepsTheSpeedReached) {
  SpindleRun run;
  ASSERT_TRUE(run({modes({ModeValue::ZX}), cmd(CmdKind::Speed, {{Word::S, 100}}, kCss), cmd(CmdKind::Spindle, {}, 1),
                   cmd(CmdKind::Move, {{Word::X, 25}}), cmd(CmdKind::Speed, {}, kRpm)}));
  auto speeds = run.of(RecordKind::SpindleSpeed);
  ASSERT_EQ(speeds.size(), 2u);
  EXPECT_NEAR(speeds[1].value, 100000 / (2 * M_PI * 25), 1e-9);
  EXPECT_FALSE(run.ex.state().css);
}

TEST(Spindle, LimitsAndErrors) {
  {  // the machine's top speed bounds CSS at the spindle axis
    SpindleRun run;
    run.machine.maxSpindleSpeed = 1000;
    ASSERT_TRUE(run({modes({ModeValue::ZX, ModeValue::PerRev, ModeValue::Linear}), cmd(CmdKind::Speed, {{Word::S, 100}}, kCss),
                     cmd(CmdKind::Feed, {{Word::F, 0.1}}), cmd(CmdKind::Move, {{Word::Z, -5}})}));
    EXPECT_NEAR(run.of(RecordKind::Linear)[0].feed, 100, 1e-9);
  }
  {  // without any limit, feed per revolution at X0 is an error
    SpindleRun run;
    EXPECT_FALSE(run({modes({ModeValue::ZX, ModeValue::PerRev, ModeValue::Linear}), cmd(CmdKind::Speed, {{Word::S, 100}}, kCss),
                      cmd(CmdKind::Feed, {{Word::F, 0.1}}), cmd(CmdKind::Move, {{Word::Z, -5}})}));
    EXPECT_EQ(run.diags.collected().back().rule, "bad-speed");
  }
  {  // G96 needs S; a negative limit is an error
    SpindleRun run;
    EXPECT_FALSE(run({cmd(CmdKind::Speed, {}, kCss)}));
    SpindleRun run2;
    EXPECT_FALSE(run2({cmd(CmdKind::Speed, {{Word::D, -1}})}));
  }
  {  // M2 resets the spindle mode (the machine's reset list names the spindle)
    SpindleRun run;
    ASSERT_TRUE(run({cmd(CmdKind::Speed, {{Word::S, 100}, {Word::D, 900}}, kCss), cmd(CmdKind::Stop, {}, (uint16_t)StopKind::End)}));
    EXPECT_FALSE(run.ex.state().css);
    EXPECT_EQ(run.ex.state().speedLimit, 0);
  }
}
