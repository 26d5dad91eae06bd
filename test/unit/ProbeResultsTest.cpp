// The probe-results file reader (runtime/ProbeResults.h, docs/PROBING.md) and where a line stops
// a probe move; the probe record's verifier (ir/MotionIR.h probeError).
#include "runtime/ProbeResults.h"

#include <gtest/gtest.h>

using namespace ncc;

namespace {

struct Read {
  SourceManager sm;
  Diagnostics diags{sm};
  ProbeResults results;
  bool ok;
  explicit Read(const char *text) {
    diags.setCollect(true);
    ok = parseProbeResults(sm, sm.addBuffer("p.probe", text), diags, results);
  }
};

TEST(ProbeResults, ReadsTripEndMissAndComments) {
  Read r("# header\n\ntrip X10 y3.5 Z-4.2  # the first\nend\n  miss\ntrip\ntrip A+15\n");
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.results.outcomes.size(), 5u);
  const ProbeOutcome &a = r.results.outcomes[0];
  EXPECT_TRUE(a.tripped);
  EXPECT_TRUE(a.has[0] && a.has[1] && a.has[2] && !a.has[3]);
  EXPECT_EQ(a.at[1], 3.5);
  EXPECT_EQ(a.at[2], -4.2);
  EXPECT_EQ(a.loc.line, 3u);
  EXPECT_TRUE(r.results.outcomes[1].tripped);
  EXPECT_FALSE(r.results.outcomes[2].tripped);
  EXPECT_EQ(r.results.outcomes[2].loc.col, 3u);
  EXPECT_TRUE(r.results.outcomes[4].has[3]);
  EXPECT_EQ(r.results.outcomes[4].at[3], 15);
  EXPECT_EQ(r.results.file, "p.probe");
}

TEST(ProbeResults, ReportsEveryBadLine) {
  Read r("trip Q1\nhit\nmiss X1\ntrip Z1 Z2\ntrip Z\ntrip Z1e999\nend\n");
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.diags.collected().size(), 6u);
  EXPECT_EQ(r.diags.collected()[0].loc.col, 6u);
  EXPECT_EQ(r.diags.collected()[1].loc.line, 2u);
  EXPECT_EQ(r.diags.collected()[3].loc.col, 9u);
  EXPECT_EQ(r.results.outcomes.size(), 1u);  // the good line
}

ProbeOutcome outcome(std::initializer_list<std::pair<int, double>> axes, bool tripped = true) {
  ProbeOutcome o;
  o.tripped = tripped;
  for (auto [a, v] : axes) o.has[a] = true, o.at[a] = v;
  return o;
}

TEST(ProbeResults, StopFractionOnTheMove) {
  const AxisVec start{0, 0, 10}, target{10, 4, 0};
  double t;
  std::string err;
  ASSERT_TRUE(probeStopFraction(outcome({{2, 5}}), start, target, t, err)) << err;
  EXPECT_DOUBLE_EQ(t, 0.5);
  ASSERT_TRUE(probeStopFraction(outcome({{0, 2.5}, {1, 1}, {2, 7.5}}), start, target, t, err)) << err;
  EXPECT_DOUBLE_EQ(t, 0.25);
  ASSERT_TRUE(probeStopFraction(outcome({}), start, target, t, err));  // `end`
  EXPECT_EQ(t, 1);
  ASSERT_TRUE(probeStopFraction(outcome({{0, 3}}, false), start, target, t, err));  // a miss reaches the target
  EXPECT_EQ(t, 1);
  ASSERT_TRUE(probeStopFraction(outcome({{0, 10.00005}}), start, target, t, err));  // the target as printed
  EXPECT_EQ(t, 1);
}

TEST(ProbeResults, StopFractionRefusals) {
  const AxisVec start{0, 0, 10}, target{0, 0, 0};
  double t;
  std::string err;
  EXPECT_FALSE(probeStopFraction(outcome({{0, 1}}), start, target, t, err));  // X does not move
  EXPECT_NE(err.find("does not move"), std::string::npos);
  EXPECT_FALSE(probeStopFraction(outcome({{0, 1}, {2, 5}}), start, target, t, err));  // off the line
  EXPECT_NE(err.find("not on"), std::string::npos);
  EXPECT_FALSE(probeStopFraction(outcome({{2, -1}}), start, target, t, err));  // past the target
  EXPECT_FALSE(probeStopFraction(outcome({{2, 10}}), start, target, t, err));  // at the start
  EXPECT_NE(err.find("between"), std::string::npos);
  EXPECT_TRUE(probeStopFraction(outcome({{2, 10}}), start, start, t, err)) << err;  // no motion: there
  EXPECT_FALSE(probeStopFraction(outcome({{2, 9}}), start, start, t, err));
}

TEST(ProbeRecord, Verifier) {
  MotionRecord r;
  r.kind = RecordKind::Probe;
  r.start = {0, 0, 10};
  r.end = {0, 0, 4};
  r.feed = 100;
  r.exactStop = true;
  r.setProbe(ProbeData{{0, 0, 0}, ProbeSignal::Contact, true, true});
  EXPECT_EQ(probeError(r), "");
  r.end = {1, 0, 4};
  EXPECT_NE(probeError(r), "");  // off the line
  r.end = {0, 0, 4};
  r.exactStop = false;
  EXPECT_NE(probeError(r), "");
  r.exactStop = true;
  r.setProbe(ProbeData{{0, 0, 0}, ProbeSignal::Contact, false, false});
  EXPECT_NE(probeError(r), "");  // a miss ends at the target
  r.end = {0, 0, 0};
  EXPECT_EQ(probeError(r), "");
  r.setProbe(ProbeData{{0, 0, 0}, ProbeSignal::Release, true, false});
  EXPECT_NE(probeError(r), "");  // a miss that is an error never becomes a record
  r.start = r.end = {0, 0, 0};  // G38.3/G38.5 where the machine stands
  r.setProbe(ProbeData{{0, 0, 0}, ProbeSignal::Release, false, true});
  EXPECT_EQ(probeError(r), "");
  r.setProbe(ProbeData{{0, 0, 0}, ProbeSignal::Release, true, true});
  EXPECT_NE(probeError(r), "");
}

}  // namespace
