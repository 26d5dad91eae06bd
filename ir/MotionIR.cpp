#include "ir/MotionIR.h"
#include "ir/Mat3.h"
#include "ir/TextQuote.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ncc {

const char *recordKindName(RecordKind k) {
  static const char *names[] = {"rapid",        "linear",        "arc",          "dwell",
                                "tool_select",  "tool_change",   "tool_length",  "spindle_speed",
                                "spindle_cw",   "spindle_ccw",   "spindle_stop", "coolant_flood",
                                "coolant_mist", "feed_rate",     "feed_mode",    "path_mode",
                                "plane",        "comment",       "message",      "optional_stop",
                                "program_stop", "program_end",   "aux",          "cycle_begin",
                                "cycle_end",    "frame_change",  "spline",       "spindle_orient",
                                "spindle_mode", "thread",        "tool_number",
                                "digital_out",  "analog_out",    "probe"};
  static_assert(sizeof(names) / sizeof(names[0]) == (size_t)RecordKind::Count);
  return names[(unsigned)k];
}

const char *threadAxisName(ThreadAxis a) {
  static const char *names[] = {"x", "y", "z", "path"};
  return names[(unsigned)a & 3];
}

const char *threadSyncName(ThreadSync s) {
  static const char *names[] = {"index", "chain", "tap_in", "tap_out"};
  return names[(unsigned)s & 3];
}

const char *probeSignalName(ProbeSignal s) { return s == ProbeSignal::Release ? "release" : "contact"; }

static double moveLength(const MotionRecord &r) {
  return std::sqrt((r.end[0] - r.start[0]) * (r.end[0] - r.start[0]) + (r.end[1] - r.start[1]) * (r.end[1] - r.start[1]) +
                   (r.end[2] - r.start[2]) * (r.end[2] - r.start[2]));
}

// A lead along an axis advances that axis by `lead` per revolution: the path advances by
// lead * length / |axis travel| (the same number of revolutions over the whole move).
double threadPathLead(const MotionRecord &r) {
  if ((ThreadAxis)r.ivalue == ThreadAxis::Path) return r.value;
  double along = std::fabs(r.end[r.ivalue & 3] - r.start[r.ivalue & 3]);
  return along > 0 ? r.value * moveLength(r) / along : 0.0;
}

double threadLeadChange(const MotionRecord &r) {
  const double *d = r.param("dlead");
  return d ? *d : 0.0;
}

static double leadTravel(const MotionRecord &r) {
  return (ThreadAxis)r.ivalue == ThreadAxis::Path ? moveLength(r) : std::fabs(r.end[r.ivalue & 3] - r.start[r.ivalue & 3]);
}

double threadEndLead(const MotionRecord &r) {
  double sq = r.value * r.value + 2 * threadLeadChange(r) * leadTravel(r);
  return sq > 0 ? std::sqrt(sq) : 0.0;
}

double threadAxisLead(const MotionRecord &r, int axis) {
  double len = moveLength(r);
  return len > 0 ? threadPathLead(r) * std::fabs(r.end[axis] - r.start[axis]) / len : 0.0;
}

std::string threadError(const MotionRecord &r) {
  if (!(r.value > 0) || !std::isfinite(r.value)) return fmt::format("a thread lead must be positive, not {}", r.value);
  if (r.ivalue < 0 || r.ivalue > 3) return "a thread lead is measured along x, y, z or the path";
  if (!(r.value2 >= 0 && r.value2 < 360)) return fmt::format("a thread start angle is at least 0 and below 360, not {}", r.value2);
  for (int i = 3; i < kAxes; ++i)
    if (r.start[i] != r.end[i]) return "a thread moves X, Y and Z only, not A, B or C";
  if (threadLeadChange(r) != 0 && !(threadEndLead(r) > 0))
    return fmt::format("the variable lead {} + {} per revolution does not stay positive to the end", r.value,
                       threadLeadChange(r));
  if (!std::isfinite(threadLeadChange(r))) return "a thread's lead change must be finite";
  if (moveLength(r) > 0 && !(threadPathLead(r) > 0))
    return fmt::format("a thread with its lead along {} must move along {}", threadAxisName((ThreadAxis)r.ivalue),
                       threadAxisName((ThreadAxis)r.ivalue));
  return {};
}

const char *planeName(Plane p) {
  static const char *names[] = {"xy", "zx", "yz"};
  return names[(unsigned)p % 3];
}

std::array<double, 3> planeNormal(Plane p) {
  switch (p) {
  case Plane::ZX: return {0, 1, 0};
  case Plane::YZ: return {1, 0, 0};
  default: return {0, 0, 1};
  }
}

bool isNamedNumberKey(std::string_view key) {
  if (key.empty() || key.size() > NamedNumber::kMaxKey) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(key[0])) return false;
  return std::all_of(key.begin(), key.end(), [&](char c) { return alpha(c) || (c >= '0' && c <= '9'); });
}

std::array<double, 3> MotionRecord::arcNormal() const {
  return tiltedArc() ? extra.get()->normal : planeNormal(plane);
}

void MotionRecord::setNormal(const std::array<double, 3> &n) {
  if (n == planeNormal(plane)) {
    if (extra.get()) {
      MotionExtra &e = extra.make();
      e.hasNormal = false;
      e.normal = {};
      if (e.params.empty()) extra.reset();
    }
    return;
  }
  MotionExtra &e = extra.make();
  e.hasNormal = true;
  e.normal = n;
}

const std::vector<NamedNumber> &MotionRecord::params() const {
  static const std::vector<NamedNumber> none;
  return extra.get() ? extra.get()->params : none;
}

bool MotionRecord::setParam(std::string_view key, double value) {
  if (!isNamedNumberKey(key)) return false;
  auto &ps = extra.make().params;
  for (auto &p : ps)
    if (p.name() == key) {
      p.value = value;
      return true;
    }
  NamedNumber n;
  std::copy(key.begin(), key.end(), n.key.begin());
  n.value = value;
  ps.push_back(n);
  return true;
}

const double *MotionRecord::param(std::string_view key) const {
  for (auto &p : params())
    if (p.name() == key) return &p.value;
  return nullptr;
}

std::vector<double> splineDefaultKnots(size_t count, int degree) {
  std::vector<double> k;
  size_t order = (size_t)degree + 1;
  for (size_t i = 0; i < count + order; ++i) k.push_back(i < order ? 0.0 : i < count ? double(i - order + 1) : double(count - order + 1));
  return k;
}

std::string splineError(const MotionRecord &r) {
  const SplineData &s = r.spline();
  size_t n = s.count();
  if (s.degree < 1 || s.degree > 15) return fmt::format("the spline degree {} is not between 1 and 15", s.degree);
  if (n < (size_t)s.degree + 1)
    return fmt::format("a spline of degree {} needs at least {} control points, not {}", s.degree, s.degree + 1, n);
  for (auto &p : s.points)
    for (double v : p)
      if (!std::isfinite(v)) return "a spline control point is not finite";
  if (!s.weights.empty()) {
    if (s.weights.size() != n) return fmt::format("a spline with {} control points needs {} weights, not {}", n, n, s.weights.size());
    for (double w : s.weights)
      if (!(w > 0) || !std::isfinite(w)) return fmt::format("a spline weight must be positive and finite, not {}", w);
  }
  if (!s.knots.empty()) {
    size_t want = n + s.degree + 1;
    if (s.knots.size() != want) return fmt::format("a spline with {} control points of degree {} needs {} knots, not {}", n, s.degree, want, s.knots.size());
    for (size_t i = 0; i < want; ++i) {
      if (!std::isfinite(s.knots[i])) return "a spline knot is not finite";
      if (i && s.knots[i] < s.knots[i - 1]) return "the spline knots must not decrease";
    }
    // Clamped: the curve starts at the first control point and ends at the last, as the record's
    // start and end say.
    for (int i = 1; i <= s.degree; ++i)
      if (s.knots[i] != s.knots[0] || s.knots[want - 1 - i] != s.knots[want - 1])
        return fmt::format("the spline knots must repeat the first and the last value {} times (a clamped curve)", s.degree + 1);
    if (!(s.knots[want - 1] > s.knots[0])) return "the spline knots must span a non-empty interval";
  }
  for (int i = 3; i < kAxes; ++i)
    if (r.start[i] != r.end[i]) return "a spline moves X, Y and Z only, not A, B or C";
  return {};
}

const SplineData &MotionRecord::spline() const {
  static const SplineData none;
  return extra.get() ? extra.get()->spline : none;
}

void MotionRecord::setSpline(SplineData s) {
  if (s.weights.size() == s.count() && std::all_of(s.weights.begin(), s.weights.end(), [](double w) { return w == 1; }))
    s.weights.clear();
  if (!s.knots.empty() && s.knots == splineDefaultKnots(s.count(), s.degree)) s.knots.clear();
  extra.make().spline = std::move(s);
}

const ProbeData &MotionRecord::probe() const {
  static const ProbeData none;
  return extra.get() ? extra.get()->probe : none;
}

std::string probeError(const MotionRecord &r) {
  const ProbeData &p = r.probe();
  if (!(r.feed > 0) || !std::isfinite(r.feed)) return fmt::format("a probe move needs a positive feed, not {}", r.feed);
  if (!r.exactStop) return "a probe move stops at its end (exact_stop)";
  if (p.target == r.start && p.missIsError) return "a probe that must trip (miss=error) cannot have its start as its target";
  for (double v : p.target)
    if (!std::isfinite(v)) return "a probe target is not finite";
  if (!p.tripped) {
    if (p.missIsError) return "a probe that must trip (miss=error) did not";
    if (r.end != p.target) return "a probe that did not trip ends at its target";
    return {};
  }
  if (p.target == r.start) return r.end == r.start ? "" : "a probe to its start stops there";  // G38.3/G38.5
  // The stop lies on the segment: its parameter along the axis that moves most, every axis
  // within 1 nm (1e-6 degree) of that point.
  int k = 0;
  for (int i = 1; i < kAxes; ++i)
    if (std::fabs(p.target[i] - r.start[i]) > std::fabs(p.target[k] - r.start[k])) k = i;
  double t = (r.end[k] - r.start[k]) / (p.target[k] - r.start[k]);
  if (!(t >= 0 && t <= 1)) return "a probe stops between its start and its target";
  for (int i = 0; i < kAxes; ++i)
    if (!(std::fabs(r.start[i] + t * (p.target[i] - r.start[i]) - r.end[i]) <= 1e-6))
      return "a probe stops on the straight line from its start to its target";
  return {};
}

void appendMotionRecord(std::string &s, const MotionRecord &r) {
  auto out = std::back_inserter(s);
  s += recordKindName(r.kind);
  auto axes = [&](const AxisVec &v) {
    for (int i = 0, n = writtenAxes({&v}); i < n; ++i) fmt::format_to(out, " {}{}", kAxisLetters[i], v[i]);
  };
  auto named = [&] {
    if (!r.text.empty()) {
      s += ' ';
      text::appendQuoted(s, r.text);
    }
    for (auto &p : r.params()) fmt::format_to(out, " {}={}", p.name(), p.value);
  };
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
    axes(r.end);
    if (r.kind == RecordKind::Linear) fmt::format_to(out, " F{}", r.feed);
    break;
  case RecordKind::Arc:
    axes(r.end);
    fmt::format_to(out, " center({}, {}, {}) plane={}", r.center[0], r.center[1], r.center[2], planeName(r.plane));
    if (r.tiltedArc()) {
      auto n = r.arcNormal();
      fmt::format_to(out, " normal=({}, {}, {})", n[0], n[1], n[2]);
    }
    fmt::format_to(out, " turns={} F{}", r.turns, r.feed);
    break;
  case RecordKind::Spline: {
    axes(r.end);
    const SplineData &sp = r.spline();
    fmt::format_to(out, " degree={} points=(", sp.degree);
    for (auto &p : sp.points) fmt::format_to(out, "{}({}, {}, {})", &p == sp.points.data() ? "" : ", ", p[0], p[1], p[2]);
    s += ')';
    auto list = [&](const char *key, const std::vector<double> &v) {
      if (v.empty()) return;
      fmt::format_to(out, " {}=(", key);
      for (size_t i = 0; i < v.size(); ++i) fmt::format_to(out, "{}{}", i ? ", " : "", v[i]);
      s += ')';
    };
    list("weights", sp.weights);
    list("knots", sp.knots);
    fmt::format_to(out, " F{}", r.feed);
    break;
  }
  case RecordKind::Thread:
    axes(r.end);
    fmt::format_to(out, " lead={}", r.value);
    if (threadLeadChange(r) != 0) fmt::format_to(out, " dlead={}", threadLeadChange(r));
    fmt::format_to(out, " along={} sync={}", threadAxisName((ThreadAxis)r.ivalue), threadSyncName(r.sync));
    if (r.value2 != 0) fmt::format_to(out, " start={}", r.value2);
    fmt::format_to(out, " F{}", r.feed);
    break;
  case RecordKind::Probe: {
    const ProbeData &p = r.probe();
    axes(r.end);
    s += " target=(";
    for (int i = 0, n = writtenAxes({&r.end, &p.target}); i < n; ++i) fmt::format_to(out, "{}{}", i ? ", " : "", p.target[i]);
    fmt::format_to(out, ") signal={} miss={} tripped={} F{}", probeSignalName(p.signal), p.missIsError ? "error" : "ok",
                   p.tripped ? 1 : 0, r.feed);
    break;
  }
  case RecordKind::Comment:
  case RecordKind::Message:
    s += ' ';
    text::appendQuoted(s, r.text);
    break;
  case RecordKind::Dwell:
  case RecordKind::SpindleSpeed:
  case RecordKind::FeedRate:
    fmt::format_to(out, " {}", r.value);
    break;
  case RecordKind::ToolLength:
    fmt::format_to(out, " {} H{}", r.value, r.ivalue);
    if (r.value2 != 0) fmt::format_to(out, " X{}", r.value2);  // a lathe tool's X offset
    if (const double *y = r.param("Y")) fmt::format_to(out, " Y{}", *y);  // a Sinumerik length on Y
    break;
  case RecordKind::Aux:
    fmt::format_to(out, " {}{}", r.text.empty() ? "M" : r.text, r.ivalue);
    break;
  case RecordKind::PathMode:
    fmt::format_to(out, " {} {}", r.ivalue, r.value);
    if (r.ivalue == 2) fmt::format_to(out, " {}", r.value2);
    break;
  case RecordKind::SpindleOrient:
    fmt::format_to(out, " {} {} {}", r.value, r.ivalue, r.value2);
    break;
  case RecordKind::SpindleMode:
  case RecordKind::DigitalOutput:
  case RecordKind::AnalogOutput:
    fmt::format_to(out, " {} {} {}", r.ivalue, r.value, r.value2);
    break;
  case RecordKind::CycleBegin:
  case RecordKind::FrameChange:
    named();
    break;
  case RecordKind::CycleEnd:
    break;
  default:
    fmt::format_to(out, " {}", r.ivalue);
    break;
  }
  if (r.exactStop) s += " exact_stop";
  if (r.blockNumber >= 0) fmt::format_to(out, " N{}", r.blockNumber);
  if (r.loc.line) fmt::format_to(out, " @{}:{}", r.loc.line, r.loc.col);
}

std::string printMotionRecord(const MotionRecord &r) {
  std::string s;
  appendMotionRecord(s, r);
  return s;
}

static const char *const kFrameKeys[12] = {"m00", "m01", "m02", "m03", "m10", "m11",
                                           "m12", "m13", "m20", "m21", "m22", "m23"};

void setFrameMatrix(MotionRecord &r, const FrameMatrix &m) {
  for (int i = 0; i < 12; ++i) r.setParam(kFrameKeys[i], m[i]);
}

FrameMatrix frameMatrix(const MotionRecord &r) {
  FrameMatrix m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  for (int i = 0; i < 12; ++i)
    if (const double *v = r.param(kFrameKeys[i])) m[i] = *v;
  return m;
}

static const char *const kShiftKeys[kAxes - 3] = {"ma", "mb", "mc", "mu", "mv", "mw"};

void setAxisShift(MotionRecord &r, const AxisShift &s) {
  for (size_t i = 0; i < s.size(); ++i)
    if (s[i] != 0) r.setParam(kShiftKeys[i], s[i]);
}

AxisShift axisShift(const MotionRecord &r) {
  AxisShift s{};
  for (size_t i = 0; i < s.size(); ++i)
    if (const double *v = r.param(kShiftKeys[i])) s[i] = *v;
  return s;
}

void setWorkOffsetSelection(MotionRecord &r, int selection) {
  if (selection != 1) r.setParam("wcs", selection);
}

int workOffsetSelection(const MotionRecord &r) {
  const double *v = r.param("wcs");
  return v ? (int)*v : 1;
}

void WorkFrame::note(const MotionRecord &r) {
  if (r.kind == RecordKind::ToolLength) {
    toolZ_ = r.value, toolX_ = r.value2;
    const double *y = r.param("Y");  // a Sinumerik edge's length on Y
    toolY_ = y ? *y : 0;
    return;
  }
  if (r.kind != RecordKind::FrameChange) return;
  FrameMatrix m = frameMatrix(r);
  double L[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) L[i][j] = m[i * 4 + j];
    origin_[i] = m[i * 4 + 3];
  }
  mat3Inverse(L, inv_);  // frames are never singular
  shift_ = axisShift(r);
}

AxisVec WorkFrame::work(const AxisVec &machine) const {
  double d[3] = {machine[0] - toolX_ - origin_[0], machine[1] - toolY_ - origin_[1], machine[2] - toolZ_ - origin_[2]};
  AxisVec w = machine;
  for (int i = 0; i < 3; ++i) w[i] = inv_[i][0] * d[0] + inv_[i][1] * d[1] + inv_[i][2] * d[2];
  for (size_t i = 0; i < shift_.size(); ++i) w[3 + i] = machine[3 + i] - shift_[i];
  return w;
}

std::string TiltedArcCheck::message(const char *consumer, const MotionRecord &r) {
  return fmt::format("{} cannot handle an arc in a tilted plane (only normals along X, Y or Z): {}", consumer,
                     printMotionRecord(r));
}

bool TiltedArcCheck::report(Diagnostics &diags) const {
  if (!seen_) return true;
  diags.error(first_.loc, message(consumer_, first_), "tilted-arc");
  return false;
}

void MotionTextWriter::record(const MotionRecord &r) {
  if (text_) {
    appendMotionRecord(*text_, r);
    *text_ += '\n';
    return;
  }
  line_.clear();
  appendMotionRecord(line_, r);
  line_ += '\n';
  std::fwrite(line_.data(), 1, line_.size(), out_);
}

}  // namespace ncc
