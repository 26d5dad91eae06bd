#include "runtime/CanonTrace.h"

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <charconv>
#include <cstring>

namespace ncc {

namespace {
constexpr size_t kFlushAt = 1 << 16;
// Arc argument order per plane: first and second plane axis, normal axis (rs274's ARC_FEED).
constexpr int kArcAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
constexpr const char *kPlaneNames[] = {"CANON_PLANE_XY", "CANON_PLANE_XZ", "CANON_PLANE_YZ"};
}  // namespace

CanonTraceWriter::CanonTraceWriter(std::FILE *out) : out_(out) { buf_.reserve(kFlushAt + 4096); }

// After finish() the stream may already be closed by its owner (AtomicFile::commit): no access.
CanonTraceWriter::~CanonTraceWriter() {
  if (!finished_) flush();
}

bool CanonTraceWriter::flush() {
  if (!buf_.empty() && out_) {
    if (std::fwrite(buf_.data(), 1, buf_.size(), out_) != buf_.size()) ioError_ = true;
    buf_.clear();
  }
  if (out_ && std::fflush(out_) != 0) ioError_ = true;
  return !ioError_;
}

void CanonTraceWriter::begin(int64_t n) {
  // "%5d " then the N column: "N....." + blank, or N and the number left-aligned in 6 columns.
  // Built in one stack buffer, appended once.
  char tmp[64];
  char *p = tmp;
  ++seq_;
  char digits[24];
  auto seq = std::to_chars(digits, digits + sizeof digits, (long long)seq_);
  size_t width = (size_t)(seq.ptr - digits);
  for (size_t i = width; i < 5; ++i) *p++ = ' ';
  std::memcpy(p, digits, width);
  p += width;
  *p++ = ' ';
  if (n < 0) {
    std::memcpy(p, "N..... ", 7);
    p += 7;
  } else {
    *p++ = 'N';
    char *q = std::to_chars(p, p + 24, (long long)n).ptr;
    for (size_t i = (size_t)(q - p); i < 6; ++i) *q++ = ' ';
    p = q;
  }
  buf_.append(tmp, (size_t)(p - tmp));
}

void CanonTraceWriter::end() {
  buf_.push_back('\n');
  if (buf_.size() >= kFlushAt && out_) {
    if (std::fwrite(buf_.data(), 1, buf_.size(), out_) != buf_.size()) ioError_ = true;
    buf_.clear();
  }
}

void CanonTraceWriter::line(int64_t n, std::string_view text) {
  begin(n);
  buf_.append(text);
  end();
}

namespace {
// "00".."99": two fraction digits per lookup.
constexpr char kDigitPairs[] =
    "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849"
    "5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";

// Writes v as printf's %.4f at p (room for kMaxNum characters), returns the end.
constexpr size_t kMaxNum = 400;  // %.4f of the largest double takes 315 characters
char *fixed4(char *p, double v) {
  // Fast path: |v| < 1e9 and not near a rounding tie: the scaled value rounds to the same
  // integer as the exact decimal expansion, so printing that integer equals printf's %.4f.
  double scaled = v * 1e4;
  if (std::fabs(v) < 1e9) {
    double r = std::nearbyint(scaled);
    if (std::fabs(scaled - r) < 0.4999) {
      long long q = (long long)r;
      if (q < 0 || (q == 0 && std::signbit(v))) *p++ = '-';  // "-0.0000" like printf
      unsigned long long a = q < 0 ? (unsigned long long)(-q) : (unsigned long long)q;
      p = std::to_chars(p, p + 16, a / 10000).ptr;
      unsigned f = (unsigned)(a % 10000);
      *p = '.';
      std::memcpy(p + 1, kDigitPairs + 2 * (f / 100), 2);
      std::memcpy(p + 3, kDigitPairs + 2 * (f % 100), 2);
      return p + 5;
    }
  }
  // to_chars with a precision rounds exactly like printf's %.4f (including "-0.0000").
  auto res = std::to_chars(p, p + kMaxNum, v, std::chars_format::fixed, 4);
  if (res.ec == std::errc()) return res.ptr;
  int len = std::snprintf(p, kMaxNum, "%.4f", v);
  return p + (len < 0 ? 0 : std::min((size_t)len, kMaxNum - 1));
}
}  // namespace

void CanonTraceWriter::num(double v) {
  char tmp[kMaxNum];
  buf_.append(tmp, (size_t)(fixed4(tmp, v) - tmp));
}

// Formats the values into one stack buffer and appends it once (flushing early only when a
// huge value could overflow it).
void CanonTraceWriter::nums(const double *v, int n) {
  char tmp[1024];
  char *p = tmp;
  for (int i = 0; i < n; ++i) {
    if ((size_t)(tmp + sizeof tmp - p) < kMaxNum + 2) {
      buf_.append(tmp, (size_t)(p - tmp));
      p = tmp;
    }
    if (i) *p++ = ',', *p++ = ' ';
    p = fixed4(p, v[i]);
  }
  buf_.append(tmp, (size_t)(p - tmp));
}

void CanonTraceWriter::preamble() {
  started_ = true;
  line(-1, "USE_LENGTH_UNITS(CANON_UNITS_MM)");
  line(-1, "SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)");
  line(-1, "SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)");
  line(-1, "SET_XY_ROTATION(0.0000)");
  line(-1, "SET_FEED_REFERENCE(CANON_XYZ)");
  line(-1, "ON_RESET()");
}

// What rs274 prints for M2/M30: its reset of the modal state, then PROGRAM_END.
void CanonTraceWriter::epilogue(const MotionRecord &r) {
  int64_t n = r.blockNumber;
  line(n, "SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)");
  line(n, "SET_XY_ROTATION(0.0000)");
  if (plane_ != Plane::XY) line(n, "SELECT_PLANE(CANON_PLANE_XY)");
  plane_ = Plane::XY;
  line(n, "SET_FEED_MODE(0, 0)");
  line(n, "SET_FEED_RATE(0.0000)");
  line(n, "STOP_SPINDLE_TURNING(0)");
  line(n, "SET_SPINDLE_MODE(0 0.0000)");
  if (mist_) line(n, "MIST_OFF()");
  if (flood_) line(n, "FLOOD_OFF()");
  mist_ = flood_ = false;
  if (r.ivalue == 30) line(n, "PALLET_SHUTTLE()");
  line(n, "PROGRAM_END()");
}

void CanonTraceWriter::stopSync(int64_t n) {
  if (!sync_) return;
  sync_ = false;
  line(n, "STOP_SPEED_FEED_SYNCH()");
  enableAfterMove_ = inG76_;
}

// G33 prints START, STRAIGHT_FEED, STOP per block; G33.1 START, RIGID_TAP (down and back, so
// its return record prints nothing), STOP; rs274's G76 changes the lead inside one pass.
void CanonTraceWriter::thread(const MotionRecord &r) {
  if (threadLeadChange(r) != 0) {
    variableLead_ = halted_ = true;
    variableLeadRecord_ = r;
    return;
  }
  const int64_t n = r.blockNumber;
  const bool fresh = r.sync == ThreadSync::Index || r.sync == ThreadSync::TapIn;
  const double lead = threadPathLead(r);
  if (fresh) stopSync(syncBlock_);
  if (fresh && inG76_) line(n, "DISABLE_FEED_OVERRIDE()");
  if (!sync_ || lead != syncLead_) {
    char tmp[64];
    std::snprintf(tmp, sizeof tmp, "START_SPEED_FEED_SYNC(%f,0)", lead);
    line(n, tmp);
  }
  sync_ = true, syncLead_ = lead, syncBlock_ = n;
  if (r.sync == ThreadSync::TapOut) return;
  begin(n);
  buf_.append(r.sync == ThreadSync::TapIn ? "RIGID_TAP(" : "STRAIGHT_FEED(");
  nums(r.end.data(), r.sync == ThreadSync::TapIn ? 3 : writtenAxes({&r.end}));
  buf_.push_back(')');
  end();
}

void CanonTraceWriter::record(const MotionRecord &r) {
  if (finished_ || halted_) return;
  if (!started_) preamble();
  const int64_t n = r.blockNumber;
  if (r.kind == RecordKind::Thread) return thread(r);
  stopSync(syncBlock_);
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
    begin(n);
    buf_.append(r.kind == RecordKind::Rapid ? "STRAIGHT_TRAVERSE(" : "STRAIGHT_FEED(");
    nums(r.end.data(), writtenAxes({&r.end}));
    buf_.push_back(')');
    end();
    if (enableAfterMove_) line(n, "ENABLE_FEED_OVERRIDE()");
    enableAfterMove_ = false;
    break;
  case RecordKind::Arc: {
    // After a tilted arc nothing more is written: the trace would no longer be the path.
    if (tilted_.reject(r)) {
      halted_ = true;
      return;
    }
    const int *ax = kArcAxes[(int)r.plane];
    begin(n);
    buf_.append("ARC_FEED(");
    double v[4] = {r.end[ax[0]], r.end[ax[1]], r.center[ax[0]], r.center[ax[1]]};
    nums(v, 4);
    char tmp[24];
    auto res = std::to_chars(tmp, tmp + sizeof tmp, r.turns);
    buf_.append(", ");
    buf_.append(tmp, (size_t)(res.ptr - tmp));
    buf_.append(", ");
    double w[7] = {r.end[ax[2]], r.end[3], r.end[4], r.end[5], r.end[6], r.end[7], r.end[8]};
    nums(w, writtenAxes({&r.end}) - 2);
    buf_.push_back(')');
    end();
    break;
  }
  case RecordKind::Probe: {  // rs274's G38.x: the programmed target, bracketed by the probe's switching
    const AxisVec &target = r.probe().target;
    line(n, "TURN_PROBE_ON()");
    begin(n);
    buf_.append("STRAIGHT_PROBE(");
    nums(target.data(), writtenAxes({&target}));
    buf_.push_back(')');
    end();
    line(n, "TURN_PROBE_OFF()");
    break;
  }
  case RecordKind::Spline:
    // rs274's standalone canon prints only the number of control points (start and end
    // included) for G5, G5.1 and G5.2/G5.3 alike; the curve itself is in the Motion IR.
    line(n, "NURBS_FEED(" + std::to_string(r.spline().count()) + ", ...)");
    break;
  case RecordKind::Dwell:
    begin(n);
    buf_.append("DWELL(");
    num(r.value);
    buf_.push_back(')');
    end();
    break;
  case RecordKind::ToolSelect:
    line(n, "SELECT_TOOL(" + std::to_string(r.ivalue) + ")");
    break;
  case RecordKind::ToolChange:
    line(n, "START_CHANGE()");
    line(n, "STOP_SPINDLE_TURNING(0)");
    line(n, "CHANGE_TOOL(" + std::to_string(r.ivalue) + ")");
    break;
  case RecordKind::ToolNumber:  // rs274 prints the tool table index; ncc the number (as CHANGE_TOOL)
    line(n, "CHANGE_TOOL_NUMBER(" + std::to_string(r.ivalue) + ")");
    break;
  case RecordKind::DigitalOutput: {  // M62-M65
    static const char *kNames[2][2] = {{"CLEAR_AUX_OUTPUT_BIT(", "SET_AUX_OUTPUT_BIT("},
                                       {"CLEAR_MOTION_OUTPUT_BIT(", "SET_MOTION_OUTPUT_BIT("}};
    line(n, kNames[r.value2 != 0][r.value != 0] + std::to_string(r.ivalue) + ")");
    break;
  }
  case RecordKind::AnalogOutput: {  // M67/M68: rs274 prints "%d,%f"
    char v[64];
    std::snprintf(v, sizeof v, "%lld,%f)", (long long)r.ivalue, r.value);
    line(n, std::string(r.value2 != 0 ? "SET_MOTION_OUTPUT_VALUE(" : "SET_AUX_OUTPUT_VALUE(") + v);
    break;
  }
  case RecordKind::ToolLength:
    // Already applied to the machine positions: printing it would apply it twice.
    break;
  case RecordKind::SpindleSpeed:
    begin(n);
    buf_.append("SET_SPINDLE_SPEED(0, ");
    num(r.value);
    buf_.push_back(')');
    end();
    break;
  case RecordKind::SpindleCW: line(n, "START_SPINDLE_CLOCKWISE(0)"); break;
  case RecordKind::SpindleCCW: line(n, "START_SPINDLE_COUNTERCLOCKWISE(0)"); break;
  case RecordKind::SpindleStop: line(n, "STOP_SPINDLE_TURNING(0)"); break;
  case RecordKind::SpindleOrient:  // rs274's M19: the orientation, then the wait when Q is given
    begin(n);
    buf_.append("ORIENT_SPINDLE(0, ");
    num(r.value);
    buf_.append(", ");
    buf_.append(std::to_string(r.ivalue));
    buf_.push_back(')');
    end();
    if (r.value2 > 0) {
      begin(n);
      buf_.append("SPINDLE.0.WAIT_ORIENT_COMPLETE(");
      num(r.value2);
      buf_.push_back(')');
      end();
    }
    break;
  case RecordKind::SpindleMode:
    // rs274 prints the G96 limit (D), 1e30 for none, and 0 for G97; a moved origin is no command.
    if (r.ivalue == 2) break;
    begin(n);
    buf_.append("SET_SPINDLE_MODE(0 ");
    num(r.ivalue == 0 ? 0.0 : r.value > 0 ? r.value : 1e30);
    buf_.push_back(')');
    end();
    break;
  case RecordKind::CoolantFlood:
    flood_ = r.ivalue != 0;
    line(n, flood_ ? "FLOOD_ON()" : "FLOOD_OFF()");
    break;
  case RecordKind::CoolantMist:
    mist_ = r.ivalue != 0;
    line(n, mist_ ? "MIST_ON()" : "MIST_OFF()");
    break;
  case RecordKind::FeedRate:
    begin(n);
    buf_.append("SET_FEED_RATE(");
    num(r.value);
    buf_.push_back(')');
    end();
    break;
  case RecordKind::FeedMode:
    line(n, r.ivalue == 1 ? "SET_FEED_MODE(0, 1)" : "SET_FEED_MODE(0, 0)");
    break;
  case RecordKind::PathMode:
    if (r.ivalue == 0) {
      line(n, "SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)");
    } else if (r.ivalue == 1) {
      line(n, "SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP)");
    } else {
      char tmp[96];
      std::snprintf(tmp, sizeof tmp, "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, %f)", r.value);
      line(n, tmp);
      std::snprintf(tmp, sizeof tmp, "SET_NAIVECAM_TOLERANCE(%.4f)", r.value2);
      line(n, tmp);
    }
    break;
  case RecordKind::Plane:
    plane_ = (Plane)r.ivalue;
    line(n, std::string("SELECT_PLANE(") + kPlaneNames[(int)plane_ % 3] + ")");
    break;
  case RecordKind::Comment: line(n, "COMMENT(\"" + r.text + "\")"); break;
  case RecordKind::Message: line(n, "MESSAGE(\"" + r.text + "\")"); break;
  case RecordKind::OptionalStop: line(n, "OPTIONAL_PROGRAM_STOP()"); break;
  case RecordKind::ProgramStop: line(n, "PROGRAM_STOP()"); break;
  case RecordKind::ProgramEnd: epilogue(r); break;
  case RecordKind::Aux: break;  // user M codes have no canonical command in rs274's standalone canon
  case RecordKind::CycleBegin:  // the expanded moves are the trace; rs274 has no bracket
  case RecordKind::CycleEnd:
    inG76_ = r.kind == RecordKind::CycleBegin && r.text == "rs274.G76";
    break;
  case RecordKind::FrameChange:  // positions are already machine coordinates
  case RecordKind::Thread:       // thread() above
  case RecordKind::Count: break;
  }
}

bool CanonTraceWriter::finish(Diagnostics &diags) {
  if (finished_) return !ioError_;
  finished_ = true;
  if (!tilted_.report(diags)) {
    flush();
    return false;
  }
  if (variableLead_) {
    diags.error(variableLeadRecord_.loc,
                "the canonical trace (rs274) has no variable-lead thread (G34): " + printMotionRecord(variableLeadRecord_),
                "unsupported-code");
    flush();
    return false;
  }
  if (!started_) preamble();
  stopSync(syncBlock_);
  line(-1, "ON_RESET()");
  line(-1, "ON_RESET()");
  return flush();
}

}  // namespace ncc
