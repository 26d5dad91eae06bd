// JSONL trace of the Motion IR: one object per record, full precision.
#include "runtime/Sinks.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {

void num(std::string &s, double d) {
  if (std::isfinite(d)) fmt::format_to(std::back_inserter(s), "{}", d);
  else s += "null";
}

void vec(std::string &s, const double *v, int n) {
  s += '[';
  for (int i = 0; i < n; ++i) {
    if (i) s += ',';
    num(s, v[i]);
  }
  s += ']';
}

void str(std::string &s, const std::string &t) {
  s += '"';
  appendJsonEscaped(s, t);
  s += '"';
}

}  // namespace

std::string motionRecordJson(const MotionRecord &r, const AxisVec *work) {
  std::string s = "{\"kind\":\"";
  s += recordKindName(r.kind);
  s += '"';
  if (r.loc.file) fmt::format_to(std::back_inserter(s), ",\"file\":{}", r.loc.file);
  fmt::format_to(std::back_inserter(s), ",\"line\":{},\"col\":{}", r.loc.line, r.loc.col);
  if (r.blockNumber >= 0) fmt::format_to(std::back_inserter(s), ",\"n\":{}", r.blockNumber);
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
  case RecordKind::Arc:
  case RecordKind::Spline:
  case RecordKind::Thread:
  case RecordKind::Probe:
  {
    // Six positions, nine while U V W are in use (writtenAxes).
    const int n = writtenAxes({&r.start, &r.end, work ? work : &r.end});
    s += ",\"start\":";
    vec(s, r.start.data(), n);
    s += ",\"end\":";
    vec(s, r.end.data(), n);
    if (work) {
      s += ",\"work\":";
      vec(s, work->data(), n);
    }
  }
    if (r.kind != RecordKind::Rapid) {
      s += ",\"feed\":";
      num(s, r.feed);
    }
    if (r.kind == RecordKind::Arc) {
      s += ",\"center\":";
      vec(s, r.center.data(), 3);
      fmt::format_to(std::back_inserter(s), ",\"plane\":\"{}\",\"turns\":{}", planeName(r.plane), r.turns);
      if (r.tiltedArc()) {
        s += ",\"normal\":";
        vec(s, r.arcNormal().data(), 3);
      }
    }
    if (r.kind == RecordKind::Thread) {
      s += ",\"lead\":";
      num(s, r.value);
      if (threadLeadChange(r) != 0) s += ",\"dlead\":", num(s, threadLeadChange(r));
      fmt::format_to(std::back_inserter(s), ",\"along\":\"{}\",\"sync\":\"{}\",\"start_angle\":",
                     threadAxisName((ThreadAxis)r.ivalue), threadSyncName(r.sync));
      num(s, r.value2);
    }
    if (r.kind == RecordKind::Probe) {
      const ProbeData &p = r.probe();
      s += ",\"target\":";
      vec(s, p.target.data(), writtenAxes({&r.start, &r.end, &p.target}));
      fmt::format_to(std::back_inserter(s), ",\"signal\":\"{}\",\"miss\":\"{}\",\"tripped\":{}", probeSignalName(p.signal),
                     p.missIsError ? "error" : "ok", p.tripped ? "true" : "false");
    }
    if (r.kind == RecordKind::Spline) {
      const SplineData &sp = r.spline();
      fmt::format_to(std::back_inserter(s), ",\"degree\":{},\"points\":[", sp.degree);
      for (auto &p : sp.points) {
        if (&p != sp.points.data()) s += ',';
        vec(s, p.data(), 3);
      }
      s += ']';
      if (!sp.weights.empty()) s += ",\"weights\":", vec(s, sp.weights.data(), (int)sp.weights.size());
      if (!sp.knots.empty()) s += ",\"knots\":", vec(s, sp.knots.data(), (int)sp.knots.size());
    }
    break;
  case RecordKind::CycleBegin:
  case RecordKind::CycleEnd:
  case RecordKind::FrameChange:
    s += ",\"text\":";
    str(s, r.text);
    s += ",\"params\":{";
    for (auto &p : r.params()) {
      if (&p != &r.params().front()) s += ',';
      s += '"';
      s += p.name();
      s += "\":";
      num(s, p.value);
    }
    s += '}';
    break;
  case RecordKind::Comment:
  case RecordKind::Message:
    s += ",\"text\":";
    str(s, r.text);
    break;
  default:
    s += ",\"value\":";
    num(s, r.value);
    fmt::format_to(std::back_inserter(s), ",\"ivalue\":{}", r.ivalue);
    if (r.kind == RecordKind::SpindleOrient) {  // the wait (s)
      s += ",\"wait\":";
      num(s, r.value2);
    }
    if (r.kind == RecordKind::SpindleMode) {  // the CSS origin: machine X of the spindle axis
      s += ",\"origin\":";
      num(s, r.value2);
    }
    if (r.kind == RecordKind::ToolLength && r.value2 != 0) {  // a lathe tool's X offset
      s += ",\"value2\":";
      num(s, r.value2);
    }
    if (r.kind == RecordKind::Aux) {  // the letter: M, B or H
      s += ",\"text\":";
      str(s, r.text);
    }
    break;
  }
  if (r.exactStop) s += ",\"exact_stop\":true";
  s += '}';
  return s;
}

void JsonlTraceWriter::record(const MotionRecord &r) {
  frame_.note(r);
  AxisVec work = frame_.work(r.end);
  line_ = motionRecordJson(r, &work);
  line_ += '\n';
  std::fwrite(line_.data(), 1, line_.size(), out_);
}

bool JsonlTraceWriter::finish(Diagnostics &diags) {
  if (std::fflush(out_) != 0 || std::ferror(out_)) {
    diags.error(SourceLoc{}, "cannot write the JSONL trace");
    return false;
  }
  return true;
}

}  // namespace ncc
