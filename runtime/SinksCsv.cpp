// CSV samples of the planned path at a fixed period, interpolated inside each planned segment.
#include "runtime/Sinks.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

CsvSampler::CsvSampler(std::FILE *out, double period, uint64_t maxRows, bool uvw)
    : out_(out), period_(std::isfinite(period) && period > 0 ? period : 0.01), maxRows_(maxRows),
      axes_(uvw ? kAxes : kBaseAxes) {
  std::fputs(uvw ? "t,x,y,z,a,b,c,u,v,w,v_path,kind,line\n" : "t,x,y,z,a,b,c,v_path,kind,line\n", out_);
}

void CsvSampler::row(double t, const AxisVec &p, double v, const char *kind, uint32_t line) {
  if (rows_ >= maxRows_) {
    truncated_ = true;
    return;
  }
  buf_.clear();
  auto out = std::back_inserter(buf_);
  fmt::format_to(out, "{:.6f}", t);
  for (int i = 0; i < axes_; ++i) fmt::format_to(out, ",{:.4f}", p[i] + 0.0);
  fmt::format_to(out, ",{:.3f},{},{}\n", v * 60, kind, line);
  std::fwrite(buf_.data(), 1, buf_.size(), out_);
  lastT_ = t;
  ++rows_;
}

void CsvSampler::segment(const PlannedSegment &s) {
  const char *kind = recordKindName(s.record.kind);
  double d = s.duration(), end = s.t0 + d;
  // Sample times are k * period (no accumulated drift); a sample on a boundary belongs to the
  // segment that starts there.
  if (!std::isfinite(end)) end = s.t0;
  for (double t = k_ * period_; t < end && !truncated_; t = ++k_ * period_) {
    double local = std::max(0.0, t - s.t0);
    double dist, v;
    s.profile.at(local, dist, v);
    row(t, s.positionAt(local), s.record.kind == RecordKind::Dwell ? 0 : v, kind, s.record.loc.line);
  }
  lastPos_ = s.record.end;
  lastKind_ = kind;
  lastLine_ = s.record.loc.line;
}

void CsvSampler::finished(double total) {
  if (!std::isfinite(total)) total = lastT_ > 0 ? lastT_ : 0;
  for (double t = k_ * period_; t <= total + 1e-9 * std::max(1.0, total) && !truncated_; t = ++k_ * period_)
    row(t, lastPos_, 0, lastKind_, lastLine_);
  if (!truncated_ && lastT_ < total - 1e-9) row(total, lastPos_, 0, lastKind_, lastLine_);
  std::fflush(out_);
}

}  // namespace ncc
