// Output sinks of a run: JSONL trace of the Motion IR, run summary, CSV samples of the planned
// path, SVG plot of the toolpath. RunOutputs (runtime/RunOutputs.h) wires them for the driver.
#pragma once
#include "ir/MotionIR.h"
#include "runtime/Geometry.h"
#include "runtime/Planner.h"

#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace ncc {

// One JSON object per record and line, numbers in shortest round-trip form (full precision),
// non-finite numbers as null. Keys: kind, file, line, col, n, then the kind's fields (see
// docs/PLANNER.md "JSONL trace").
// `work`: the work position of a motion record's end (WorkFrame), written as "work".
std::string motionRecordJson(const MotionRecord &r, const AxisVec *work = nullptr);

class JsonlTraceWriter : public MotionSink {
public:
  explicit JsonlTraceWriter(std::FILE *out) : out_(out) {}
  void record(const MotionRecord &r) override;
  bool finish(Diagnostics &diags) override;

private:
  std::FILE *out_;
  std::string line_;
  WorkFrame frame_;
};

// Counts and measures the record stream for the run summary.
class SummaryCollector : public MotionSink {
public:
  void record(const MotionRecord &r) override;
  void setProgramName(std::string name) { program_ = std::move(name); }
  void setMachineName(std::string name) { machine_ = std::move(name); }
  // Overrides the block count derived from the records (the driver knows the source blocks).
  void setBlockCount(uint64_t n) { blockOverride_ = (int64_t)n; }
  void setTimes(const PlannerStats &s) { times_ = s; }
  std::string text() const;

  uint64_t blocks() const { return blockOverride_ >= 0 ? (uint64_t)blockOverride_ : blocks_; }
  uint64_t rapids = 0, linears = 0, arcs = 0, splines = 0, threads = 0, dwells = 0;
  double feedLength = 0, rapidLength = 0;
  struct Box {
    AxisVec lo, hi;
    bool empty = true;
    void add(const AxisVec &lo, const AxisVec &hi);
  } feedBox, allBox;
  std::set<int64_t> tools;

private:
  std::string program_, machine_;
  int64_t blockOverride_ = -1;
  uint64_t blocks_ = 0;
  SourceLoc lastLoc_{};
  int64_t lastN_ = -2;
  PlannerStats times_;
};

// "h:mm:ss.s", rounded to tenths.
std::string formatDuration(double seconds);

// Samples the planned path every `period` seconds: t,x,y,z,a,b,c,v_path,kind,line (with u,v,w
// after c for a machine that has one of them). Rows at t = k * period for every k with
// t <= total time, and a last row at the total time.
class CsvSampler : public PlanListener {
public:
  // At most maxRows rows are written (a runaway dwell must not fill the disk).
  CsvSampler(std::FILE *out, double period, uint64_t maxRows = 20000000, bool uvw = false);
  void segment(const PlannedSegment &s) override;
  void finished(double totalTime) override;
  uint64_t rows() const { return rows_; }
  bool truncated() const { return truncated_; }

private:
  void row(double t, const AxisVec &p, double v, const char *kind, uint32_t line);
  std::FILE *out_;
  double period_;
  uint64_t k_ = 0, rows_ = 0, maxRows_;
  int axes_;  // columns of positions: kBaseAxes, or kAxes with U V W
  bool truncated_ = false;
  double lastT_ = -1;
  AxisVec lastPos_{};
  const char *lastKind_ = "idle";
  uint32_t lastLine_ = 0;
  std::string buf_;
};

// Toolpath plot, XY projection. Polylines are simplified below a pixel while streaming and the
// number of kept points is capped, so the file stays bounded for any program length.
class SvgPlot : public MotionSink {
public:
  struct Options {
    double pixels = 1000;       // width of the larger side in px
    size_t maxPoints = 100000;  // cap of kept points over all polylines
    std::string title;
  };
  SvgPlot() : SvgPlot(Options{}) {}
  explicit SvgPlot(Options o) : opt_(std::move(o)) {}
  void record(const MotionRecord &r) override;
  std::string render() const;
  size_t points() const { return points_; }
  size_t plunges() const { return plunges_.size(); }

private:
  struct Run {
    bool rapid;
    std::vector<std::array<double, 2>> pts;
  };
  void add(bool rapid, double x, double y, bool first);
  void simplify();
  Options opt_;
  std::vector<Run> runs_;
  std::vector<std::array<double, 2>> plunges_;  // feed moves straight down (holes), as markers
  size_t points_ = 0;
  double tol_ = 1e-3;  // mm: points closer than this to the last kept one are dropped
  double lo_[2] = {1e300, 1e300}, hi_[2] = {-1e300, -1e300};
  bool truncated_ = false;
};

// Path speed (mm/s) and path acceleration (mm/s^2) over time, two stacked panels with a time
// axis in s and a legend (docs/PLANNER.md "Velocity plot"). Samples are kept as the minimum and
// maximum of each time bucket; buckets merge in pairs when there are too many, so memory and
// the file stay bounded for any program length.
class VelocityPlot : public PlanListener {
public:
  struct Options {
    double width = 1000, height = 640;  // px
    size_t maxBuckets = 4000;           // time buckets kept (2 points each per curve)
    std::string title;
  };
  VelocityPlot() : VelocityPlot(Options{}) {}
  explicit VelocityPlot(Options o) : opt_(std::move(o)) {}
  void segment(const PlannedSegment &s) override;
  void finished(double totalTime) override { total_ = totalTime; }
  std::string render() const;
  size_t buckets() const { return buckets_.size(); }

private:
  struct Extreme {
    double lo = 1e300, hi = -1e300, tLo = 0, tHi = 0;
    void add(double t, double x);
    void merge(const Extreme &o);
  };
  struct Bucket {
    Extreme v, a;
  };
  void sample(double t, double v, double a);
  Options opt_;
  std::vector<Bucket> buckets_;
  double width_ = 1e-3;  // s per bucket, doubled when the buckets exceed the cap
  double total_ = 0, vPeak_ = 0, aPeak_ = 0, aLow_ = 0;
  uint64_t segments_ = 0;
};

// Shared by the SVG writers: 1, 2 or 5 times a power of ten near a fifth of width; XML text.
double niceLength(double width);
std::string xmlEscape(const std::string &text);

}  // namespace ncc
