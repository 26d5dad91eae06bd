#include "runtime/RunOutputs.h"

namespace ncc {

RunOutputs::RunOutputs(const Machine &machine, const RunOutputOptions &options)
    : opt_(options), planner_(machine) {
  summary_.setMachineName(machine.name);
  summary_.setProgramName(opt_.programName);
  if (!opt_.csvPath.empty()) {
    csvFile_ = std::make_unique<AtomicFile>(opt_.csvPath);
    // An unopenable file is reported at finish(), where diagnostics are at hand.
    if (csvFile_->ok()) {
      csv_ = std::make_unique<CsvSampler>(csvFile_->stream(), opt_.samplePeriod, 20000000,
                                          machine.axes[6].present || machine.axes[7].present || machine.axes[8].present);
      planner_.addListener(csv_.get());
    }
  }
  if (!opt_.svgPath.empty()) {
    SvgPlot::Options so;
    so.title = opt_.programName;
    so.maxPoints = opt_.svgMaxPoints;
    svg_ = std::make_unique<SvgPlot>(so);
  }
  if (!opt_.velocityPath.empty()) {
    VelocityPlot::Options vo;
    vo.title = opt_.programName;
    velocity_ = std::make_unique<VelocityPlot>(vo);
    planner_.addListener(velocity_.get());
  }
}

RunOutputs::~RunOutputs() = default;

void RunOutputs::setProgramName(const std::string &name) {
  opt_.programName = name;
  summary_.setProgramName(name);
}

void RunOutputs::record(const MotionRecord &r) {
  summary_.record(r);
  planner_.record(r);
  if (svg_) svg_->record(r);
}

bool RunOutputs::finish(Diagnostics &diags) {
  if (finished_) return true;
  finished_ = true;
  bool ok = planner_.finish(diags);
  summary_.setTimes(planner_.stats());
  std::string err;
  if (csvFile_) {
    if (!csvFile_->ok()) {
      diags.error(SourceLoc{}, "cannot write samples to '" + opt_.csvPath + "'");
      ok = false;
    } else if (csv_->truncated()) {
      diags.warning(SourceLoc{}, "samples in '" + opt_.csvPath + "' stop after " + std::to_string(csv_->rows()) +
                                     " rows (use a longer --sample-period)");
    }
    if (csvFile_->ok() && !csvFile_->commit(err)) {
      diags.error(SourceLoc{}, "cannot write samples to '" + opt_.csvPath + "': " + err);
      ok = false;
    }
  }
  if (svg_ && !writeFileAtomic(opt_.svgPath, svg_->render(), err)) {
    diags.error(SourceLoc{}, "cannot write plot to '" + opt_.svgPath + "': " + err);
    ok = false;
  }
  if (velocity_ && !writeFileAtomic(opt_.velocityPath, velocity_->render(), err)) {
    diags.error(SourceLoc{}, "cannot write velocity plot to '" + opt_.velocityPath + "': " + err);
    ok = false;
  }
  return ok;
}

std::string RunOutputs::summaryText() const { return summary_.text(); }

}  // namespace ncc
