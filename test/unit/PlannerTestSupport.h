// Shared by the planner's unit tests: a machine with round limits, straight moves, and a
// listener that checks the planned stream's continuity and keeps the segments.
#pragma once
#include "runtime/Planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ncc::plannertest {

// X/Y/Z with the given acceleration and jerk (0 = none: trapezoids), feed cap 10000 mm/min;
// yAccel > 0 gives Y its own acceleration.
inline Machine planMachine(double accel, double jerk, double tolerance = 0.01, int lookahead = 32, double yAccel = 0) {
  std::string text = "schema = 1\n[machine]\nrapid_feed = 12000\nmax_feed = 10000\nlookahead = " +
                     std::to_string(lookahead) + "\npath_tolerance = " + std::to_string(tolerance) + "\n";
  for (const char *ax : {"X", "Y", "Z"})
    text += std::string("[axes.") + ax + "]\nmax_velocity = 60000\nmax_accel = " +
            std::to_string(ax[0] == 'Y' && yAccel > 0 ? yAccel : accel) + "\nmax_jerk = " + std::to_string(jerk) + "\n";
  Machine m;
  std::string err;
  EXPECT_TRUE(Machine::parse(text, "test.toml", m, err)) << err;
  return m;
}

inline MotionRecord line(AxisVec a, AxisVec b, double feed, bool exact = false) {
  MotionRecord r;
  r.kind = RecordKind::Linear;
  r.start = a;
  r.end = b;
  r.feed = feed;
  r.exactStop = exact;
  return r;
}

inline AxisVec P(double x, double y, double z = 0) {
  AxisVec p{};
  p[0] = x, p[1] = y, p[2] = z;
  return p;
}

// Checks continuity of the planned stream and keeps the segments.
struct Recorder : PlanListener {
  std::vector<PlannedSegment> segs;
  double t = 0;
  bool keep = true;
  uint64_t count = 0;
  void segment(const PlannedSegment &s) override {
    EXPECT_NEAR(s.t0, t, 1e-9);
    if (s.record.kind != RecordKind::Dwell) {
      EXPECT_LE(s.profile.vp, s.vmax * (1 + 1e-9));
      EXPECT_LE(s.profile.v0, s.profile.vp * (1 + 1e-9) + 1e-12);
      double dist, v;
      s.profile.at(s.duration(), dist, v);
      EXPECT_NEAR(dist, s.length(), 1e-6 * std::max(1.0, s.length()));
    }
    t = s.t0 + s.duration();
    ++count;
    if (keep) segs.push_back(s);
  }
};

inline double run(const Machine &m, const std::vector<MotionRecord> &recs, Recorder *rec = nullptr,
                  PlannerStats *stats = nullptr) {
  Planner p(m);
  if (rec) p.addListener(rec);
  for (auto &r : recs) p.record(r);
  SourceManager sm;
  Diagnostics d(sm);
  p.finish(d);
  if (stats) *stats = p.stats();
  return p.totalTime();
}

}  // namespace ncc::plannertest
