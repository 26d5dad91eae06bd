// Run summary: counts, path lengths, cycle time, bounds, tools (format: docs/PLANNER.md).
#include "runtime/Sinks.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

void SummaryCollector::Box::add(const AxisVec &l, const AxisVec &h) {
  if (empty) {
    lo = l;
    hi = h;
    empty = false;
    return;
  }
  for (int i = 0; i < kAxes; ++i) {
    lo[i] = std::min(lo[i], l[i]);
    hi[i] = std::max(hi[i], h[i]);
  }
}

void SummaryCollector::record(const MotionRecord &r) {
  // A block is counted when the source position changes: consecutive records of one block
  // (a move and its feed/tool state records) count once, a loop body counts per execution.
  // Columns are not compared: the records of one block point at its different words.
  bool hasPlace = r.loc.line != 0 || r.blockNumber >= 0;
  if (hasPlace && (r.loc.file != lastLoc_.file || r.loc.line != lastLoc_.line || r.blockNumber != lastN_)) {
    ++blocks_;
    lastLoc_ = r.loc;
    lastN_ = r.blockNumber;
  }
  AxisVec lo, hi;
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
  case RecordKind::Probe:  // a straight feed (counted with the linear moves)
  case RecordKind::Thread: {
    for (int i = 0; i < kAxes; ++i) {
      lo[i] = std::min(r.start[i], r.end[i]);
      hi[i] = std::max(r.start[i], r.end[i]);
    }
    double len = linearLength(r.start, r.end);
    if (r.kind == RecordKind::Rapid) ++rapids, rapidLength += len;
    else ++(r.kind == RecordKind::Thread ? threads : linears), feedLength += len;
    break;
  }
  case RecordKind::Arc: {
    ArcGeometry g = arcGeometry(r);
    Vec3 l3, h3;
    arcBounds(g, r.start, r.end, l3, h3);
    for (int i = 0; i < kAxes; ++i) {
      lo[i] = i < 3 ? l3[i] : std::min(r.start[i], r.end[i]);  // arcs move X Y Z; the rest straight
      hi[i] = i < 3 ? h3[i] : std::max(r.start[i], r.end[i]);
    }
    ++arcs;
    feedLength += g.length;
    break;
  }
  case RecordKind::Spline: {
    Vec3 l3, h3;
    splineBounds(r, l3, h3);
    for (int i = 0; i < kAxes; ++i) {
      lo[i] = i < 3 ? l3[i] : r.start[i];
      hi[i] = i < 3 ? h3[i] : r.start[i];
    }
    ++splines;
    feedLength += splineLength(r);
    break;
  }
  case RecordKind::Dwell:
    ++dwells;
    return;
  case RecordKind::ToolChange:
    tools.insert(r.ivalue);
    return;
  default:
    return;
  }
  allBox.add(lo, hi);
  if (r.kind != RecordKind::Rapid) feedBox.add(lo, hi);
}

std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
  long long tenths = std::llround(seconds * 10);
  long long h = tenths / 36000, m = tenths / 600 % 60, s = tenths / 10 % 60, t = tenths % 10;
  return fmt::format("{}:{:02}:{:02}.{}", h, m, s, t);
}

namespace {
std::string boxText(const SummaryCollector::Box &b) {
  if (b.empty) return "none";
  std::string s;
  for (int i = 0; i < kAxes; ++i) {
    // A B C U V W only when they move or sit away from zero.
    if (i >= 3 && b.lo[i] == 0 && b.hi[i] == 0) continue;
    if (!s.empty()) s += "  ";
    s += fmt::format("{} {:.3f}..{:.3f}", kAxisLetters[i], b.lo[i] + 0.0, b.hi[i] + 0.0);
  }
  return s;
}
}  // namespace

std::string SummaryCollector::text() const {
  std::string s;
  auto line = [&](const char *label, const std::string &value) {
    s += fmt::format("{:<14}{}\n", std::string(label) + ":", value);
  };
  if (!program_.empty()) line("program", program_);
  if (!machine_.empty()) line("machine", machine_);
  line("blocks", std::to_string(blocks()));
  // Splines only when there are some: the summary of every other program stays as it was.
  line("moves", fmt::format("{} (rapid {}, linear {}, arc {}{}{}), dwells {}", rapids + linears + arcs + splines + threads,
                            rapids, linears, arcs, splines ? fmt::format(", spline {}", splines) : "",
                            threads ? fmt::format(", thread {}", threads) : "", dwells));
  line("path length", fmt::format("{:.3f} mm (feed {:.3f}, rapid {:.3f})", feedLength + rapidLength, feedLength,
                                  rapidLength));
  line("cycle time", fmt::format("{} ({:.3f} s)", formatDuration(times_.totalTime), times_.totalTime));
  line("time split", fmt::format("feed {:.3f} s, rapid {:.3f} s, dwell {:.3f} s", times_.feedTime,
                                 times_.rapidTime, times_.dwellTime));
  line("bounds", boxText(feedBox));
  line("bounds all", boxText(allBox));
  std::string t;
  for (int64_t n : tools) t += (t.empty() ? "T" : " T") + std::to_string(n);
  line("tools", t.empty() ? "none" : t);
  return s;
}

}  // namespace ncc
