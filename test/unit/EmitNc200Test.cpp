// FEATURES: NCB-MOT-03 NCB-BLK-01
// The NC-200 writer (docs/EMIT.md "NC-200"): exact text of a small program and a random-arc
// property of the absolute I J centres, read back from the written text as the controller would.
#include "backends/emit/Emitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>

using namespace ncc;
using namespace ncc::emit;

namespace {

constexpr double kTwoPi = 6.283185307179586;

MotionRecord moveRecord(RecordKind k, const AxisVec &from, double x, double y) {
  MotionRecord r;
  r.kind = k;
  r.start = from;
  r.end = from;
  r.end[0] = x, r.end[1] = y;
  r.feed = 100;
  return r;
}

std::string emitNc200(const std::vector<MotionRecord> &recs, bool &ok) {
  SourceManager sm;
  Diagnostics diags{sm};
  diags.setCollect(true);
  Machine machine;
  EmitOptions o;
  o.target = Target::Nc200;
  std::string out;
  ok = emitProgram(machine, o, recs, out, diags);
  return out;
}

// The words of one block ("N7 G2 X1 Y2 I3 J4" -> {N:7, G:2, X:1, …}); comments give none.
std::map<char, double> words(const std::string &line) {
  std::map<char, double> w;
  if (line.empty() || line[0] == ';' || line.find('(') != std::string::npos) return w;
  std::istringstream in(line);
  std::string t;
  while (in >> t) w[t[0]] = std::atof(t.c_str() + 1);
  return w;
}

}  // namespace

TEST(EmitNc200, HeaderBlocksAndWords) {
  std::vector<MotionRecord> recs;
  AxisVec p{};
  recs.push_back(moveRecord(RecordKind::Rapid, p, 10, -0.5));
  MotionRecord f;
  f.kind = RecordKind::FeedRate;
  f.value = 250;
  recs.push_back(f);
  recs.push_back(moveRecord(RecordKind::Linear, recs[0].end, 20, -0.5));
  MotionRecord a = moveRecord(RecordKind::Arc, recs[2].end, 30, 9.5);
  a.center = {20, 9.5, 0};
  a.turns = 1;
  recs.push_back(a);
  bool ok = false;
  EXPECT_EQ(emitNc200(recs, ok),
            "; ncc: NC-200 program (NC-100/110/200/210), UNVERIFIED: ncc has no NC-200 front end to read it back; "
            "metric controller (PGCFIL G70=0); origins (UAO,n) = the machine file's [offsets]\n"
            "N1 G90 G94\nN2 (DPI,X,Y)\nN3 (UAO,1)\n"
            "N4 G0 X10 Y-0.5\n"
            "N5 G1 X20 F250\n"
            "N6 G3 X30 Y9.5 I20 J9.5\n"
            "N7 M30\n");
  EXPECT_TRUE(ok);
}

TEST(EmitNc200, AbsoluteCentresPassTheArcCheck) {
  // Random arcs, full circles among them: the written pieces, read back with I J as the absolute
  // centre, have both ends on one circle within the 0.002 mm arc tolerance, that centre within
  // 0.001 mm of the source's, at most 180 degrees each, and end where the source arc ends.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-300, 300), rad(0.05, 200), ang(0, kTwoPi);
  for (int i = 0; i < 3000; ++i) {
    const double c[2] = {pos(rng), pos(rng)}, r = rad(rng), a0 = ang(rng);
    const double a1 = i % 5 == 0 ? a0 : ang(rng);
    AxisVec start{}, end{};
    start[0] = c[0] + r * std::cos(a0), start[1] = c[1] + r * std::sin(a0);
    end[0] = c[0] + r * std::cos(a1), end[1] = c[1] + r * std::sin(a1);
    if (i % 5 == 0) end = start;
    std::vector<MotionRecord> recs;
    recs.push_back(moveRecord(RecordKind::Rapid, AxisVec{}, start[0], start[1]));
    MotionRecord a = moveRecord(RecordKind::Arc, start, end[0], end[1]);
    a.center = {c[0], c[1], 0};
    a.turns = i % 2 ? 1 : -1;
    recs.push_back(a);
    bool ok = false;
    std::istringstream text(emitNc200(recs, ok));
    ASSERT_TRUE(ok) << i;
    double x = 0, y = 0;
    int arcs = 0;
    for (std::string line; std::getline(text, line);) {
      auto w = words(line);
      if (w.empty() || (!w.count('X') && !w.count('Y') && !w.count('I'))) continue;
      const double px = x, py = y;
      if (w.count('X')) x = w['X'];
      if (w.count('Y')) y = w['Y'];
      if (!w.count('I')) continue;
      ++arcs;
      const double cx = w['I'], cy = w['J'];
      const double rs = std::hypot(px - cx, py - cy), re = std::hypot(x - cx, y - cy);
      ASSERT_LT(std::fabs(rs - re), 0.002) << i << ": " << line;
      ASSERT_LT(std::hypot(cx - c[0], cy - c[1]), 0.001) << i << ": " << line;
      ASSERT_FALSE(px == x && py == y) << i << ": a full circle written as one block";
    }
    ASSERT_GE(arcs, i % 5 == 0 ? 2 : 1) << i;
    ASSERT_LT(std::fabs(x - end[0]), 0.0005 + 1e-9) << i;
    ASSERT_LT(std::fabs(y - end[1]), 0.0005 + 1e-9) << i;
  }
}
