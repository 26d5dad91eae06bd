// Thread cutting pieces: the pass schedules of runtime/cycles/Thread.h (LinuxCNC's and the 808D's
// G76), one pass's layout, and the lead conversions of a Motion IR thread record.
// FEATURES: ISO-CYT-10
#include "ir/MotionIR.h"
#include "runtime/cycles/Thread.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {

TEST(ThreadDepths, LinuxCncDegressionAndSpringPasses) {
  // J 0.3, K 1.2, R 2 from the drive line (I 1): 1 + 0.3 sqrt(n) while below 2.2, then H + 1 at 2.2.
  auto d = lcncThreadDepths(1, 0.3, 1.2, 2, 2);
  ASSERT_EQ(d.size(), 15u + 3u);
  EXPECT_DOUBLE_EQ(d[0], 1.3);
  EXPECT_DOUBLE_EQ(d[1], 1 + 0.3 * std::sqrt(2.0));
  EXPECT_LT(d[14], 2.2);
  for (size_t i = 15; i < d.size(); ++i) EXPECT_EQ(d[i], 2.2);
}

TEST(ThreadDepths, FanucConstantAreaMinimumCutAllowance) {
  // The seed's example 25: k 3.68, first cut 1.8, min 0.1, allowance 0.2, one finishing pass.
  auto d = fanucThreadDepths(3.68, 1.8, 0.1, 0.2, 1);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_DOUBLE_EQ(d[0], 1.8);
  EXPECT_DOUBLE_EQ(d[1], 1.8 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(d[2], 1.8 * std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(d[3], 3.68 - 0.2);
  EXPECT_DOUBLE_EQ(d[4], 3.68);
  // The minimum cut takes over once the sqrt(n) steps get smaller than it (0.5 sqrt 2 - 0.5 <
  // 0.3 already), and stays: the steps only shrink.
  auto m = fanucThreadDepths(2, 0.5, 0.3, 0, 2);
  ASSERT_EQ(m.size(), 5u + 2u);  // 0.5 0.8 1.1 1.4 1.7, then 2 twice
  EXPECT_DOUBLE_EQ(m[1], 0.8);
  EXPECT_DOUBLE_EQ(m[2], 1.1);
  EXPECT_NEAR(m[4], 1.7, 1e-12);
  EXPECT_EQ(m[5], 2);
  EXPECT_EQ(m[6], 2);
}

TEST(ThreadDepths, RandomSchedulesIncreaseAndEndAtFullDepth) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.01, 1);
  for (int i = 0; i < 500; ++i) {
    double height = 0.2 + 5 * u(rng), first = height * u(rng), minCut = 0.2 * u(rng), allowance = 0.5 * height * u(rng) * 0.5;
    int finish = 1 + i % 3;
    auto d = fanucThreadDepths(height, first, minCut, allowance, finish);
    ASSERT_GE(d.size(), (size_t)finish);
    for (size_t k = 1; k < d.size(); ++k) EXPECT_GE(d[k], d[k - 1]);
    for (size_t k = 1; k + finish + (allowance > 0) < d.size(); ++k) EXPECT_GE(d[k] - d[k - 1], minCut - 1e-12);
    for (size_t k = d.size() - finish; k < d.size(); ++k) EXPECT_EQ(d[k], height);
    for (double x : d) EXPECT_LE(x, height);
  }
}

TEST(ThreadPass, StepsBackInCutOut) {
  ThreadPass p;
  p.retractX = 12, p.startX = 10, p.startZ = 3, p.endX = 10, p.endZ = -20, p.lead = 1.5;
  std::vector<ThreadStep> s;
  threadPass(p, s);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].kind, ThreadStepKind::Rapid);
  EXPECT_EQ(s[1].kind, ThreadStepKind::Rapid);
  EXPECT_EQ(s[2].kind, ThreadStepKind::Start);
  EXPECT_EQ(s[2].z, -20);
  EXPECT_EQ(s[3].x, 12);
  // Both tapers: a synchronised feed in, angled in, the cut, angled out, each chained.
  p.entry = p.exit = true;
  p.entryX = 11, p.entryDz = -1, p.entryLead = 2;
  p.exitX = 11, p.exitDz = -1, p.exitLead = 2;
  s.clear();
  threadPass(p, s);
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(s[1].kind, ThreadStepKind::Start);
  EXPECT_EQ(s[2].kind, ThreadStepKind::Chain);
  EXPECT_EQ(s[2].z, 2);
  EXPECT_EQ(s[3].z, -19);
  EXPECT_EQ(s[4].kind, ThreadStepKind::Chain);
  EXPECT_EQ(s[4].x, 11);
}

TEST(ThreadRecord, LeadAlongAxisAndPath) {
  MotionRecord r;
  r.kind = RecordKind::Thread;
  r.start = {10, 0, 0, 0, 0, 0};
  r.end = {13, 0, -4, 0, 0, 0};  // a 3-4-5 taper
  r.value = 2;
  r.ivalue = (int)ThreadAxis::Z;
  EXPECT_DOUBLE_EQ(threadPathLead(r), 2.5);
  EXPECT_DOUBLE_EQ(threadAxisLead(r, 2), 2);
  EXPECT_DOUBLE_EQ(threadAxisLead(r, 0), 1.5);
  EXPECT_EQ(threadError(r), "");
  r.ivalue = (int)ThreadAxis::Path;
  EXPECT_DOUBLE_EQ(threadAxisLead(r, 2), 1.6);
  r.ivalue = (int)ThreadAxis::Y;
  EXPECT_NE(threadError(r), "");  // no travel along Y
}

}  // namespace
