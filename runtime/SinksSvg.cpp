// SVG plot of the toolpath (XY projection): feed solid, rapids dashed, axes and a scale bar.
#include "runtime/Sinks.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
}

void SvgPlot::add(bool rapid, double x, double y, bool first) {
  if (truncated_ || !std::isfinite(x) || !std::isfinite(y)) return;
  if (first || runs_.empty() || runs_.back().rapid != rapid) {
    // A run needs a start point; reuse the previous run when it is the same kind and ends here.
    if (runs_.empty() || runs_.back().rapid != rapid ||
        std::hypot(runs_.back().pts.back()[0] - x, runs_.back().pts.back()[1] - y) > tol_) {
      if (!runs_.empty() && runs_.back().pts.size() < 2) {
        points_ -= runs_.back().pts.size();
        runs_.pop_back();  // a lone point draws nothing
      }
      runs_.push_back(Run{rapid, {{x, y}}});
      ++points_;
    }
  } else {
    auto &last = runs_.back().pts.back();
    if (std::hypot(last[0] - x, last[1] - y) <= tol_) return;
    runs_.back().pts.push_back({x, y});
    ++points_;
  }
  lo_[0] = std::min(lo_[0], x), lo_[1] = std::min(lo_[1], y);
  hi_[0] = std::max(hi_[0], x), hi_[1] = std::max(hi_[1], y);
  // Below a pixel of the plot as it is now, detail is invisible.
  tol_ = std::max(tol_, std::max(hi_[0] - lo_[0], hi_[1] - lo_[1]) / opt_.pixels / 2);
  if (points_ > opt_.maxPoints) simplify();
}

// Doubles the tolerance and thins every polyline until under half the cap.
void SvgPlot::simplify() {
  for (int round = 0; round < 40 && points_ > opt_.maxPoints / 2; ++round) {
    tol_ *= 2;
    points_ = 0;
    std::vector<Run> kept;
    for (auto &r : runs_) {
      std::vector<std::array<double, 2>> pts;
      for (size_t i = 0; i < r.pts.size(); ++i) {
        bool last = i + 1 == r.pts.size();
        if (!pts.empty() && !last && std::hypot(pts.back()[0] - r.pts[i][0], pts.back()[1] - r.pts[i][1]) <= tol_)
          continue;
        pts.push_back(r.pts[i]);
      }
      if (pts.size() < 2) continue;
      points_ += pts.size();
      kept.push_back(Run{r.rapid, std::move(pts)});
    }
    runs_ = std::move(kept);
  }
  if (points_ > opt_.maxPoints) truncated_ = true;
}

void SvgPlot::record(const MotionRecord &r) {
  bool rapid = r.kind == RecordKind::Rapid;
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
  case RecordKind::Probe:
  case RecordKind::Thread:
    // A plunge is invisible in XY: mark it (capped, consecutive duplicates dropped).
    if (!rapid && r.end[2] < r.start[2] && std::hypot(r.end[0] - r.start[0], r.end[1] - r.start[1]) <= tol_ &&
        plunges_.size() < opt_.maxPoints / 4 && std::isfinite(r.end[0]) && std::isfinite(r.end[1]) &&
        (plunges_.empty() || std::hypot(plunges_.back()[0] - r.end[0], plunges_.back()[1] - r.end[1]) > tol_))
      plunges_.push_back({r.end[0], r.end[1]});
    add(rapid, r.start[0], r.start[1], true);
    add(rapid, r.end[0], r.end[1], false);
    return;
  case RecordKind::Arc: {
    ArcGeometry g = arcGeometry(r);
    add(false, r.start[0], r.start[1], true);
    double rm = std::max(0.5 * (g.r0 + g.r1), 1e-9);
    // Chord error below the current tolerance; at most 720 chords per turn.
    double step = 2 * std::acos(std::clamp(1 - tol_ / rm, -1.0, 1.0));
    step = std::max(step, kTwoPi / 720);
    int n = (int)std::min(1e6, std::ceil(std::fabs(g.sweep) / step));
    for (int i = 1; i < n; ++i) {
      AxisVec p = arcPoint(g, r.start, r.end, (double)i / n);
      add(false, p[0], p[1], false);
    }
    add(false, r.end[0], r.end[1], false);
    return;
  }
  case RecordKind::Spline:
    add(false, r.start[0], r.start[1], true);
    SplineCurve(r).flatten(std::max(tol_, kSplineTolerance), [&](const Vec3 &p, double) { add(false, p[0], p[1], false); });
    return;
  default:
    return;
  }
}

// 1, 2 or 5 times a power of ten, near a fifth of the width.
double niceLength(double width) {
  double target = std::max(width / 5, 1e-6);
  double p = std::pow(10, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

std::string xmlEscape(const std::string &text) {
  std::string esc;
  for (char c : text) esc += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return esc;
}

std::string SvgPlot::render() const {
  double x0 = lo_[0], y0 = lo_[1], x1 = hi_[0], y1 = hi_[1];
  if (x0 > x1) x0 = y0 = 0, x1 = y1 = 10;  // empty plot
  double w = std::max(x1 - x0, 1e-3), h = std::max(y1 - y0, 1e-3);
  double size = std::max(w, h);
  w = std::max(w, size / 20), h = std::max(h, size / 20);  // thin parts still get some room
  double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  double margin = 0.08 * size;
  double vx = cx - w / 2 - margin, vw = w + 2 * margin;
  double vy = -(cy + h / 2) - margin, vh = h + 3 * margin;  // extra bottom room for the scale bar
  double scale = opt_.pixels / std::max(vw, vh);
  double font = size / 40;
  std::string s;
  auto out = std::back_inserter(s);
  fmt::format_to(out,
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
                 "viewBox=\"{:.4f} {:.4f} {:.4f} {:.4f}\">\n",
                 vw * scale, vh * scale, vx, vy, vw, vh);
  std::string title = opt_.title.empty() ? "ncc toolpath (XY)" : opt_.title + " (XY)";
  fmt::format_to(out, "<title>{}</title>\n", xmlEscape(title));
  fmt::format_to(out, "<rect x=\"{:.4f}\" y=\"{:.4f}\" width=\"{:.4f}\" height=\"{:.4f}\" fill=\"white\"/>\n", vx, vy,
                 vw, vh);
  // Axes through the origin when it is in view.
  const char *axis = "stroke=\"#999\" stroke-width=\"1\" vector-effect=\"non-scaling-stroke\"";
  if (vx < 0 && vx + vw > 0)
    fmt::format_to(out, "<line x1=\"0\" y1=\"{:.4f}\" x2=\"0\" y2=\"{:.4f}\" {}/>\n", vy, vy + vh, axis);
  if (vy < 0 && vy + vh > 0)
    fmt::format_to(out, "<line x1=\"{:.4f}\" y1=\"0\" x2=\"{:.4f}\" y2=\"0\" {}/>\n", vx, vx + vw, axis);
  fmt::format_to(out, "<text x=\"{:.4f}\" y=\"{:.4f}\" font-size=\"{:.4f}\" fill=\"#666\">X</text>\n",
                 vx + vw - 1.5 * font, std::clamp(0.0, vy + font, vy + vh) - font / 3, font);
  fmt::format_to(out, "<text x=\"{:.4f}\" y=\"{:.4f}\" font-size=\"{:.4f}\" fill=\"#666\">Y</text>\n",
                 std::clamp(0.0, vx, vx + vw - font) + font / 3, vy + font, font);
  for (bool rapid : {true, false}) {
    std::string d;
    for (const Run &r : runs_) {
      if (r.rapid != rapid) continue;
      for (size_t i = 0; i < r.pts.size(); ++i)
        fmt::format_to(std::back_inserter(d), "{}{:.3f},{:.3f}", i == 0 ? (d.empty() ? "M" : " M") : " L",
                       r.pts[i][0] + 0.0, -r.pts[i][1] + 0.0);
    }
    if (d.empty()) continue;
    if (rapid)
      fmt::format_to(out, "<path class=\"rapid\" fill=\"none\" stroke=\"#d33\" stroke-width=\"1\" "
                          "stroke-dasharray=\"4 3\" vector-effect=\"non-scaling-stroke\" d=\"{}\"/>\n", d);
    else
      fmt::format_to(out, "<path class=\"feed\" fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.5\" "
                          "vector-effect=\"non-scaling-stroke\" d=\"{}\"/>\n", d);
  }
  if (!plunges_.empty()) {
    s += "<g class=\"plunge\" fill=\"none\" stroke=\"#2e7d32\" stroke-width=\"1\" "
         "vector-effect=\"non-scaling-stroke\">\n";
    for (auto &p : plunges_)
      fmt::format_to(out, "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\"/>\n", p[0] + 0.0, -p[1] + 0.0, size / 150);
    s += "</g>\n";
  }
  double bar = niceLength(w);
  double bx = vx + margin / 2, by = vy + vh - margin / 2;
  fmt::format_to(out,
                 "<line class=\"scale\" x1=\"{:.4f}\" y1=\"{:.4f}\" x2=\"{:.4f}\" y2=\"{:.4f}\" stroke=\"black\" "
                 "stroke-width=\"2\" vector-effect=\"non-scaling-stroke\"/>\n",
                 bx, by, bx + bar, by);
  fmt::format_to(out, "<text x=\"{:.4f}\" y=\"{:.4f}\" font-size=\"{:.4f}\">{:g} mm</text>\n", bx,
                 by - font / 2, font, bar);
  if (truncated_) fmt::format_to(out, "<!-- point cap reached: later moves are not drawn -->\n");
  s += "</svg>\n";
  return s;
}

}  // namespace ncc
