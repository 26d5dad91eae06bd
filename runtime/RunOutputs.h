// The facade `ncc run` uses: plans the record stream and produces the summary text, the CSV
// samples and the SVG plot. Files are written atomically at finish().
#pragma once
#include "ir/MotionIR.h"
#include "runtime/Machine.h"
#include "runtime/Planner.h"
#include "runtime/Sinks.h"

#include <memory>
#include <string>

namespace ncc {

struct RunOutputOptions {
  std::string svgPath, csvPath;  // empty = not written
  std::string velocityPath;      // --plot-velocity: speed/acceleration over time (SVG)
  double samplePeriod = 0.01;    // s, CSV sample period
  std::string programName;       // shown in the summary and the plot title
  size_t svgMaxPoints = 100000;
};

class RunOutputs : public MotionSink {
public:
  RunOutputs(const Machine &machine, const RunOutputOptions &options);
  ~RunOutputs() override;
  void record(const MotionRecord &r) override;
  // Plans the rest of the path and writes the files; errors go to diags.
  bool finish(Diagnostics &diags) override;
  std::string summaryText() const;

  void setBlockCount(uint64_t n) { summary_.setBlockCount(n); }
  void setProgramName(const std::string &name);
  double cycleTime() const { return planner_.totalTime(); }
  const Planner &planner() const { return planner_; }
  Planner &planner() { return planner_; }
  const SummaryCollector &summary() const { return summary_; }

private:
  RunOutputOptions opt_;
  Planner planner_;
  SummaryCollector summary_;
  std::unique_ptr<AtomicFile> csvFile_;
  std::unique_ptr<CsvSampler> csv_;
  std::unique_ptr<SvgPlot> svg_;
  std::unique_ptr<VelocityPlot> velocity_;
  bool finished_ = false;
};

}  // namespace ncc
