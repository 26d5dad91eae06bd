#include "ir/MotionIR.h"

#include <fmt/format.h>

namespace ncc {

const char *recordKindName(RecordKind k) {
  static const char *names[] = {"rapid",        "linear",        "arc",          "dwell",
                                "tool_select",  "tool_change",   "tool_length",  "spindle_speed",
                                "spindle_cw",   "spindle_ccw",   "spindle_stop", "coolant_flood",
                                "coolant_mist", "feed_rate",     "feed_mode",    "path_mode",
                                "plane",        "comment",       "message",      "optional_stop",
                                "program_stop", "program_end",   "aux"};
  static_assert(sizeof(names) / sizeof(names[0]) == (size_t)RecordKind::Count);
  return names[(unsigned)k];
}

std::string printMotionRecord(const MotionRecord &r) {
  std::string s = recordKindName(r.kind);
  auto axes = [&](const AxisVec &v) {
    static const char L[] = "XYZABC";
    for (int i = 0; i < kAxes; ++i) s += fmt::format(" {}{}", L[i], v[i]);
  };
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
    axes(r.end);
    if (r.kind == RecordKind::Linear) s += fmt::format(" F{}", r.feed);
    break;
  case RecordKind::Arc:
    axes(r.end);
    s += fmt::format(" center({}, {}, {}) plane={} turns={} F{}", r.center[0], r.center[1], r.center[2],
                     r.plane == Plane::XY ? "xy" : r.plane == Plane::ZX ? "zx" : "yz", r.turns, r.feed);
    break;
  case RecordKind::Comment:
  case RecordKind::Message:
    s += fmt::format(" \"{}\"", r.text);
    break;
  case RecordKind::Dwell:
  case RecordKind::SpindleSpeed:
  case RecordKind::FeedRate:
  case RecordKind::ToolLength:
    s += fmt::format(" {}", r.value);
    break;
  case RecordKind::Aux:
    s += fmt::format(" {}{}", r.text.empty() ? "M" : r.text, r.ivalue);
    break;
  case RecordKind::PathMode:
    s += fmt::format(" {} {}", r.ivalue, r.value);
    if (r.ivalue == 2) s += fmt::format(" {}", r.value2);
    break;
  default:
    s += fmt::format(" {}", r.ivalue);
    break;
  }
  if (r.exactStop) s += " exact_stop";
  if (r.blockNumber >= 0) s += fmt::format(" N{}", r.blockNumber);
  if (r.loc.line) s += fmt::format(" @{}:{}", r.loc.line, r.loc.col);
  return s;
}

void MotionTextWriter::record(const MotionRecord &r) {
  std::string s = printMotionRecord(r);
  s += '\n';
  std::fputs(s.c_str(), out_);
}

}  // namespace ncc
