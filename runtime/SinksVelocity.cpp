// Velocity plot: path speed and path acceleration over time in two stacked SVG panels
// (`ncc run --plot-velocity`, docs/PLANNER.md "Velocity plot").
#include "runtime/Sinks.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

void VelocityPlot::Extreme::add(double t, double x) {
  if (x < lo) lo = x, tLo = t;
  if (x > hi) hi = x, tHi = t;
}

void VelocityPlot::Extreme::merge(const Extreme &o) {
  if (o.lo < lo) lo = o.lo, tLo = o.tLo;
  if (o.hi > hi) hi = o.hi, tHi = o.tHi;
}

void VelocityPlot::sample(double t, double v, double a) {
  if (!std::isfinite(t) || !std::isfinite(v) || !std::isfinite(a) || t < 0) return;
  size_t k;
  while ((k = (size_t)(t / width_)) >= opt_.maxBuckets) {
    // Too long for the buckets: pairs merge and each bucket covers twice the time.
    for (size_t i = 0; i < buckets_.size(); ++i) {
      Bucket &dst = buckets_[i / 2];
      if (i % 2 == 0) dst = buckets_[i];
      else dst.v.merge(buckets_[i].v), dst.a.merge(buckets_[i].a);
    }
    buckets_.resize((buckets_.size() + 1) / 2);
    width_ *= 2;
  }
  if (buckets_.size() <= k) buckets_.resize(k + 1);
  buckets_[k].v.add(t, v);
  buckets_[k].a.add(t, a);
  aPeak_ = std::max(aPeak_, a);
  aLow_ = std::min(aLow_, a);
}

void VelocityPlot::segment(const PlannedSegment &s) {
  ++segments_;
  const double d = s.duration();
  if (s.record.kind == RecordKind::Dwell) {
    sample(s.t0, 0, 0);
    sample(s.t0 + d, 0, 0);
    return;
  }
  vPeak_ = std::max(vPeak_, s.profile.vp);
  // Two samples per bucket at least, so every bucket a segment crosses sees its extremes closely.
  double steps = std::ceil(d / (0.5 * width_));
  int n = (int)std::clamp(std::isfinite(steps) ? steps : 1.0, 1.0, 4.0 * (double)opt_.maxBuckets);
  for (int i = 0; i <= n; ++i) {
    double t = d * i / n, dist, v, a;
    s.profile.at(t, dist, v, a);
    sample(s.t0 + t, v, a);
  }
}

namespace {

struct Panel {
  double top, height, lo, hi;  // px, px, value range
  double y(double value) const { return top + height * (1 - (value - lo) / (hi - lo)); }
};

// A value range from lo to hi extended to whole ticks (step from niceLength).
void tickRange(double lo, double hi, double &from, double &to, double &step) {
  if (!(hi > lo)) hi = lo + 1;
  step = niceLength((hi - lo) * 5 / 4);  // about four or five ticks
  from = std::floor(lo / step + 1e-9) * step;
  to = std::ceil(hi / step - 1e-9) * step;
  if (to <= from) to = from + step;
}

}  // namespace

std::string VelocityPlot::render() const {
  const double W = opt_.width, H = opt_.height, left = 80, right = 24, top = 56, gap = 56, bottom = 48;
  const double plotW = W - left - right, panelH = (H - top - gap - bottom) / 2;
  double T = total_ > 0 && std::isfinite(total_) ? total_ : 1;
  double tFrom, tTo, tStep;
  tickRange(0, T, tFrom, tTo, tStep);
  auto x = [&](double t) { return left + plotW * t / tTo; };
  double vFrom, vTo, vStep, aFrom, aTo, aStep;
  tickRange(0, vPeak_ * 1.05, vFrom, vTo, vStep);  // headroom: the plateau clear of the frame
  tickRange(std::min(aLow_ * 1.05, 0.0), std::max(aPeak_ * 1.05, 0.0), aFrom, aTo, aStep);
  const Panel speed{top, panelH, vFrom, vTo}, accel{top + panelH + gap, panelH, aFrom, aTo};

  std::string s;
  auto out = std::back_inserter(s);
  fmt::format_to(out,
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} "
                 "{:.0f}\" font-family=\"sans-serif\" font-size=\"12\" data-duration=\"{:.6f}\" "
                 "data-peak-speed=\"{:.6f}\" data-peak-accel=\"{:.6f}\" data-segments=\"{}\">\n",
                 W, H, W, H, total_, vPeak_, aPeak_, segments_);
  std::string title = (opt_.title.empty() ? "ncc" : opt_.title) + ": path speed and acceleration";
  fmt::format_to(out, "<title>{}</title>\n<rect width=\"{:.0f}\" height=\"{:.0f}\" fill=\"white\"/>\n",
                 xmlEscape(title), W, H);
  fmt::format_to(out, "<text class=\"title\" x=\"{:.1f}\" y=\"22\" font-size=\"15\">{}</text>\n", left,
                 xmlEscape(title));
  auto panel = [&](const Panel &p, const char *cls, double from, double to, double step, const char *unit) {
    fmt::format_to(out, "<g class=\"panel {}\">\n", cls);
    fmt::format_to(out, "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"#444\"/>\n",
                   left, p.top, plotW, p.height);
    for (double v = from; v <= to + step * 1e-6; v += step) {
      double y = p.y(v), label = std::fabs(v) < step * 1e-9 ? 0.0 : v;
      fmt::format_to(out, "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", left, y,
                     left + plotW, y);
      fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}</text>\n", left - 6, y + 4, label);
    }
    for (double t = tFrom; t <= tTo + tStep * 1e-6; t += tStep)
      fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}</text>\n", x(t),
                     p.top + p.height + 16, t);
    fmt::format_to(out, "<text x=\"16\" y=\"{:.1f}\" transform=\"rotate(-90 16 {:.1f})\" text-anchor=\"middle\">{}</text>\n",
                   p.top + p.height / 2, p.top + p.height / 2, unit);
    s += "</g>\n";
  };
  panel(speed, "speed", vFrom, vTo, vStep, "path speed (mm/s)");
  panel(accel, "accel", aFrom, aTo, aStep, "path acceleration (mm/s²)");
  fmt::format_to(out, "<text class=\"time-axis\" x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">time (s)</text>\n",
                 left + plotW / 2, H - 8);
  auto curve = [&](const Panel &p, const char *cls, const char *color, Extreme Bucket::*which) {
    std::string pts;
    for (const Bucket &b : buckets_) {
      const Extreme &e = b.*which;
      if (e.lo > e.hi) continue;
      bool loFirst = e.tLo <= e.tHi;
      for (int k = 0; k < (e.tLo == e.tHi ? 1 : 2); ++k) {
        bool lo = (k == 0) == loFirst;
        fmt::format_to(std::back_inserter(pts), "{}{:.2f},{:.2f}", pts.empty() ? "" : " ", x(lo ? e.tLo : e.tHi),
                       p.y(lo ? e.lo : e.hi));
      }
    }
    fmt::format_to(out, "<polyline class=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.2\" points=\"{}\"/>\n",
                   cls, color, pts);
  };
  curve(speed, "speed", "#1565c0", &Bucket::v);
  curve(accel, "accel", "#e65100", &Bucket::a);
  // Legend and the peaks, top right.
  double lx = left + plotW - 260;
  s += "<g class=\"legend\">\n";
  fmt::format_to(out, "<line x1=\"{:.1f}\" y1=\"34\" x2=\"{:.1f}\" y2=\"34\" stroke=\"#1565c0\" stroke-width=\"2\"/>"
                      "<text x=\"{:.1f}\" y=\"38\">path speed (mm/s)</text>\n", lx, lx + 24, lx + 30);
  fmt::format_to(out, "<line x1=\"{:.1f}\" y1=\"48\" x2=\"{:.1f}\" y2=\"48\" stroke=\"#e65100\" stroke-width=\"2\"/>"
                      "<text x=\"{:.1f}\" y=\"52\">path acceleration (mm/s²)</text>\n", lx, lx + 24, lx + 30);
  s += "</g>\n";
  fmt::format_to(out, "<text class=\"peak-speed\" x=\"{:.1f}\" y=\"{:.1f}\">peak speed {:.3f} mm/s</text>\n",
                 left + 6, speed.top + 16, vPeak_);
  fmt::format_to(out, "<text class=\"peak-accel\" x=\"{:.1f}\" y=\"{:.1f}\">peak acceleration {:.3f} mm/s²</text>\n",
                 left + 6, accel.top + 16, aPeak_);
  fmt::format_to(out, "<text class=\"duration\" x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">cycle time {:.3f} s</text>\n",
                 left + plotW - 6, speed.top + 16, total_);
  s += "</svg>\n";
  return s;
}

}  // namespace ncc
