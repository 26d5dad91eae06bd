// Run outputs: summary numbers, CSV samples, SVG plot, JSONL trace.
#include "runtime/RunOutputs.h"
#include "runtime/Sinks.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace ncc;

namespace {

Machine trapezoidMachine() {
  std::string text = "schema = 1\n[machine]\nrapid_feed = 12000\nmax_feed = 10000\n";
  for (const char *ax : {"X", "Y", "Z"})
    text += std::string("[axes.") + ax + "]\nmax_velocity = 60000\nmax_accel = 1000\n";
  Machine m;
  std::string err;
  EXPECT_TRUE(Machine::parse(text, "t.toml", m, err)) << err;
  return m;
}

AxisVec P(double x, double y, double z = 0) { return AxisVec{x, y, z, 0, 0, 0}; }

MotionRecord move(RecordKind k, AxisVec a, AxisVec b, double feed = 0, uint32_t line = 0) {
  MotionRecord r;
  r.kind = k;
  r.start = a;
  r.end = b;
  r.feed = feed;
  r.loc = {1, line, 1};
  return r;
}

MotionRecord event(RecordKind k, int64_t iv = 0, double v = 0, uint32_t line = 0) {
  MotionRecord r;
  r.kind = k;
  r.ivalue = iv;
  r.value = v;
  r.loc = {1, line, 1};
  return r;
}

std::string slurp(const std::string &path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::vector<std::string> lines(const std::string &s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Tag balance of an XML document: every <tag> closed by </tag> in order, or self-closed.
bool wellFormed(const std::string &x) {
  std::vector<std::string> stack;
  for (size_t i = x.find('<'); i != std::string::npos; i = x.find('<', i + 1)) {
    size_t e = x.find('>', i);
    if (e == std::string::npos) return false;
    std::string tag = x.substr(i + 1, e - i - 1);
    if (tag.rfind("!--", 0) == 0) continue;
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != tag.substr(1)) return false;
      stack.pop_back();
    } else if (tag.back() != '/') {
      stack.push_back(tag.substr(0, tag.find(' ')));
    }
  }
  return stack.empty();
}

}  // namespace

TEST(RunSummary, CountsLengthsTimeBoundsTools) {
  Machine m = trapezoidMachine();
  RunOutputOptions opt;
  opt.programName = "prog.nc";
  RunOutputs out(m, opt);
  out.record(event(RecordKind::ToolChange, 2, 0, 1));
  out.record(move(RecordKind::Rapid, P(0, 0, 0), P(0, 0, 10), 0, 2));
  out.record(move(RecordKind::Linear, P(0, 0, 10), P(100, 0, 10), 6000, 3));
  out.record(event(RecordKind::Dwell, 0, 0.5, 4));
  MotionRecord arc = move(RecordKind::Arc, P(100, 0, 10), P(100, 0, 10), 6000, 5);
  arc.center = {90, 0, 10};  // full circle r = 10: reaches x 80..100, y -10..10
  arc.turns = 1;
  out.record(arc);
  out.record(event(RecordKind::ToolChange, 1, 0, 6));
  out.record(move(RecordKind::Rapid, P(100, 0, 10), P(100, 0, 50), 0, 6));
  out.record(event(RecordKind::ProgramEnd, 30, 0, 7));
  SourceManager sm;
  Diagnostics d(sm);
  ASSERT_TRUE(out.finish(d));
  const SummaryCollector &s = out.summary();
  EXPECT_EQ(s.blocks(), 7u);
  EXPECT_EQ(s.rapids, 2u);
  EXPECT_EQ(s.linears, 1u);
  EXPECT_EQ(s.arcs, 1u);
  EXPECT_EQ(s.dwells, 1u);
  EXPECT_NEAR(s.feedLength, 100 + 20 * M_PI, 1e-9);
  EXPECT_NEAR(s.rapidLength, 50, 1e-12);
  // 100 mm at 100 mm/s (1.1 s) + dwell + arc + two 10/40 mm rapids.
  double t = out.cycleTime();
  EXPECT_GT(t, 1.1 + 0.5 + 20 * M_PI / 100);
  std::string text = out.summaryText();
  EXPECT_NE(text.find("program:      prog.nc\n"), std::string::npos) << text;
  EXPECT_NE(text.find("blocks:       7\n"), std::string::npos) << text;
  EXPECT_NE(text.find("moves:        4 (rapid 2, linear 1, arc 1), dwells 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("path length:  212.832 mm (feed 162.832, rapid 50.000)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("bounds:       X 0.000..100.000  Y -10.000..10.000  Z 10.000..10.000\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("bounds all:   X 0.000..100.000  Y -10.000..10.000  Z 0.000..50.000\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("tools:        T1 T2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("cycle time:   " + formatDuration(t) + " ("), std::string::npos) << text;
  out.setBlockCount(123);
  EXPECT_NE(out.summaryText().find("blocks:       123\n"), std::string::npos);
}

TEST(RunSummary, DurationFormat) {
  EXPECT_EQ(formatDuration(83.412), "0:01:23.4");
  EXPECT_EQ(formatDuration(3600 * 2 + 59.96), "2:01:00.0");
  EXPECT_EQ(formatDuration(0), "0:00:00.0");
  EXPECT_EQ(formatDuration(-1), "0:00:00.0");
}

TEST(RunCsv, SampleCountAndTimes) {
  Machine m = trapezoidMachine();
  std::string path = ::testing::TempDir() + "ncc-samples.csv";
  RunOutputOptions opt;
  opt.csvPath = path;
  opt.samplePeriod = 0.01;
  {
    RunOutputs out(m, opt);
    out.record(move(RecordKind::Linear, P(0, 0), P(100, 0), 6000, 9));  // 1.1 s trapezoid
    SourceManager sm;
    Diagnostics d(sm);
    ASSERT_TRUE(out.finish(d));
    EXPECT_NEAR(out.cycleTime(), 1.1, 1e-12);
  }
  auto rows = lines(slurp(path));
  ASSERT_EQ(rows.size(), 1u + 111u);  // header + t = 0.00 .. 1.10
  EXPECT_EQ(rows[0], "t,x,y,z,a,b,c,v_path,kind,line");
  EXPECT_EQ(rows[1], "0.000000,0.0000,0.0000,0.0000,0.0000,0.0000,0.0000,0.000,linear,9");
  // Half way, by symmetry, at full speed (6000 mm/min).
  EXPECT_EQ(rows[56], "0.550000,50.0000,0.0000,0.0000,0.0000,0.0000,0.0000,6000.000,linear,9");
  // During acceleration: s = a t^2 / 2 at t = 0.05 -> 1.25 mm.
  EXPECT_EQ(rows[6].substr(0, 16), "0.050000,1.2500,");
  EXPECT_EQ(rows.back().substr(0, 17), "1.100000,100.0000");
  double prev = -1;
  for (size_t i = 1; i < rows.size(); ++i) {
    double t = std::stod(rows[i]);
    EXPECT_NEAR(t, (i - 1) * 0.01, 1e-9);
    EXPECT_GT(t, prev);
    prev = t;
  }
  std::remove(path.c_str());
}

TEST(RunCsv, LastRowAtTotalTimeAndDwells) {
  Machine m = trapezoidMachine();
  std::string buf;
  std::FILE *f = std::tmpfile();
  ASSERT_TRUE(f);
  Planner p(m);
  CsvSampler csv(f, 0.3);
  p.addListener(&csv);
  p.record(move(RecordKind::Linear, P(0, 0), P(100, 0), 6000, 1));
  p.record(event(RecordKind::Dwell, 0, 1.0, 2));  // no position: dwells where the move ended
  SourceManager sm;
  Diagnostics d(sm);
  p.finish(d);
  EXPECT_NEAR(p.totalTime(), 2.1, 1e-12);
  // t = 0, .3, ..., 2.1 (2.1 = 7 * 0.3 up to rounding) -> 8 rows.
  EXPECT_EQ(csv.rows(), 8u);
  std::rewind(f);
  char line[256];
  std::vector<std::string> rows;
  while (std::fgets(line, sizeof line, f)) rows.push_back(line);
  std::fclose(f);
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_EQ(rows[5].substr(0, 8), "1.200000");
  EXPECT_EQ(rows[5], "1.200000,100.0000,0.0000,0.0000,0.0000,0.0000,0.0000,0.000,dwell,2\n");
}

TEST(RunSvg, WellFormedWithFeedAndRapidPaths) {
  Machine m = trapezoidMachine();
  std::string path = ::testing::TempDir() + "ncc-plot.svg";
  RunOutputOptions opt;
  opt.svgPath = path;
  opt.programName = "a<b>.nc";
  RunOutputs out(m, opt);
  out.record(move(RecordKind::Rapid, P(0, 0), P(10, 10)));
  out.record(move(RecordKind::Linear, P(10, 10), P(60, 10), 1000));
  MotionRecord arc = move(RecordKind::Arc, P(60, 10), P(60, 30), 1000);
  arc.center = {60, 20, 0};
  arc.turns = 1;
  out.record(arc);
  out.record(move(RecordKind::Linear, P(60, 30, 0), P(60, 30, -5), 100));  // plunge: a marker
  SourceManager sm;
  Diagnostics d(sm);
  ASSERT_TRUE(out.finish(d));
  std::string svg = slurp(path);
  EXPECT_NE(svg.find("<circle cx=\"60.000\" cy=\"-30.000\""), std::string::npos);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("class=\"feed\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"rapid\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("a&lt;b&gt;.nc"), std::string::npos);
  EXPECT_NE(svg.find(" mm</text>"), std::string::npos);  // scale bar
  EXPECT_TRUE(wellFormed(svg)) << svg;
  // The arc is drawn as a polyline reaching its far side (x = 70) within the chord tolerance.
  size_t at = svg.find("class=\"feed\"");
  std::string pathData = svg.substr(svg.find(" d=\"", at) + 4);
  pathData = pathData.substr(0, pathData.find('"'));
  double maxX = -1e9;
  int points = 0;
  for (size_t i = 0; (i = pathData.find_first_of("ML", i)) != std::string::npos; ++i, ++points)
    maxX = std::max(maxX, std::stod(pathData.substr(i + 1)));
  EXPECT_GT(points, 8);
  EXPECT_NEAR(maxX, 70, 0.05);
  EXPECT_LE(maxX, 70.0005);
  std::remove(path.c_str());
}

TEST(RunSvg, SizeStaysBoundedForHugePrograms) {
  SvgPlot::Options o;
  o.maxPoints = 20000;
  SvgPlot plot(o);
  MotionRecord r = move(RecordKind::Linear, P(0, 0), P(0, 0), 1000);
  for (int i = 0; i < 500000; ++i) {
    r.start = r.end;
    r.end = P(std::fmod(i * 0.37, 300), std::fmod(i * 0.61, 200));
    r.kind = i % 50 == 0 ? RecordKind::Rapid : RecordKind::Linear;
    plot.record(r);
  }
  EXPECT_LE(plot.points(), o.maxPoints);
  std::string svg = plot.render();
  EXPECT_LT(svg.size(), 40u * o.maxPoints);
  EXPECT_TRUE(wellFormed(svg));
}

TEST(RunVelocityPlot, BoundedAndKeepsPeaksForLongPrograms) {
  // 200,000 planned moves and a long dwell: the buckets merge instead of growing, the extremes
  // survive the merges, and the document stays small and well formed.
  Machine m = trapezoidMachine();
  VelocityPlot::Options o;
  o.maxBuckets = 500;
  VelocityPlot plot(o);
  Planner planner(m);
  planner.addListener(&plot);
  MotionRecord r = move(RecordKind::Linear, P(0, 0), P(0, 0), 6000);
  for (int i = 0; i < 200000; ++i) {
    r.start = r.end;
    r.end = P((i + 1) * 0.5, (i % 2) * 0.5);  // zig-zag: a speed dip at every corner
    planner.record(r);
  }
  planner.record(event(RecordKind::Dwell, 0, 5000));
  SourceManager sm;
  Diagnostics d(sm);
  planner.finish(d);
  EXPECT_LE(plot.buckets(), o.maxBuckets);
  std::string svg = plot.render();
  EXPECT_TRUE(wellFormed(svg));
  EXPECT_LT(svg.size(), 200000u);
  // Each 45-degree move may use 1000 mm/s^2 per axis: sqrt(2) * 1000 along the path.
  EXPECT_NE(svg.find(fmt::format("data-peak-accel=\"{:.6f}\"", 1000 * std::sqrt(2.0))), std::string::npos)
      << svg.substr(0, 400);
  EXPECT_NE(svg.find(fmt::format("data-duration=\"{:.6f}\"", planner.totalTime())), std::string::npos);
  EXPECT_NE(svg.find("data-segments=\"200001\""), std::string::npos);
}

TEST(RunOutputs, UnwritablePathIsADiagnostic) {
  Machine m = trapezoidMachine();
  RunOutputOptions opt;
  opt.svgPath = "/nonexistent-dir/x.svg";
  opt.csvPath = "/nonexistent-dir/x.csv";
  opt.velocityPath = "/nonexistent-dir/v.svg";
  RunOutputs out(m, opt);
  out.record(move(RecordKind::Linear, P(0, 0), P(1, 0), 1000));
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  EXPECT_FALSE(out.finish(d));
  EXPECT_EQ(d.errorCount(), 3u);
}

TEST(JsonlTrace, OneObjectPerRecordFullPrecision) {
  std::FILE *f = std::tmpfile();
  ASSERT_TRUE(f);
  JsonlTraceWriter w(f);
  MotionRecord l = move(RecordKind::Linear, P(0, 0), P(0.1 + 0.2, 1.0 / 3), 1234.5, 12);
  l.loc.col = 4;
  l.blockNumber = 5;
  l.exactStop = true;
  w.record(l);
  MotionRecord c = event(RecordKind::Comment, 0, 0, 13);
  c.text = "say \"hi\"\\\n";
  w.record(c);
  MotionRecord arc = move(RecordKind::Arc, P(1, 0), P(0, 1), 100, 14);
  arc.plane = Plane::ZX;
  arc.turns = -2;
  w.record(arc);
  w.record(event(RecordKind::Dwell, 0, NAN, 15));
  SourceManager sm;
  Diagnostics d(sm);
  ASSERT_TRUE(w.finish(d));
  std::rewind(f);
  char buf[1024];
  std::vector<std::string> rows;
  while (std::fgets(buf, sizeof buf, f)) rows.push_back(buf);
  std::fclose(f);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0],
            "{\"kind\":\"linear\",\"file\":1,\"line\":12,\"col\":4,\"n\":5,\"start\":[0,0,0,0,0,0],"
            "\"end\":[0.30000000000000004,0.3333333333333333,0,0,0,0],"
            "\"work\":[0.30000000000000004,0.3333333333333333,0,0,0,0],\"feed\":1234.5,\"exact_stop\":true}\n");
  EXPECT_EQ(rows[1], "{\"kind\":\"comment\",\"file\":1,\"line\":13,\"col\":1,\"text\":\"say \\\"hi\\\"\\\\\\n\"}\n");
  EXPECT_NE(rows[2].find("\"plane\":\"zx\",\"turns\":-2"), std::string::npos) << rows[2];
  EXPECT_NE(rows[3].find("\"value\":null"), std::string::npos) << rows[3];
}

TEST(RunOutputs, AbsurdInputDoesNotHangOrCrash) {
  Machine m = trapezoidMachine();
  std::string path = ::testing::TempDir() + "ncc-absurd.csv";
  RunOutputOptions opt;
  opt.csvPath = path;
  opt.svgPath = ::testing::TempDir() + "ncc-absurd.svg";
  RunOutputs out(m, opt);
  out.record(move(RecordKind::Linear, P(0, 0), P(NAN, 0), 1000));
  out.record(move(RecordKind::Linear, P(0, 0), P(1e308, 1e308), 1000));
  out.record(move(RecordKind::Rapid, P(0, 0), P(INFINITY, 0)));
  MotionRecord arc = move(RecordKind::Arc, P(0, 0), P(0, 0), NAN);
  arc.center = {NAN, 0, 0};
  out.record(arc);
  out.record(move(RecordKind::Linear, P(0, 0), P(1, 0), 1000));
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  EXPECT_TRUE(out.finish(d));
  EXPECT_TRUE(std::isfinite(out.cycleTime()));
  EXPECT_GT(out.cycleTime(), 0);
  std::remove(path.c_str());
  std::remove(opt.svgPath.c_str());
}

TEST(RunCsv, RowCapStopsRunawaySampling) {
  Machine m = trapezoidMachine();
  std::FILE *f = std::tmpfile();
  ASSERT_TRUE(f);
  Planner p(m);
  CsvSampler csv(f, 0.01, 1000);
  p.addListener(&csv);
  p.record(event(RecordKind::Dwell, 0, 1e12, 1));  // clamped to 1e9 s, sampled up to the cap
  SourceManager sm;
  Diagnostics d(sm);
  p.finish(d);
  std::fclose(f);
  EXPECT_EQ(csv.rows(), 1000u);
  EXPECT_TRUE(csv.truncated());
}
