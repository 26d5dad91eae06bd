#include "runtime/CanonTrace.h"
#include "runtime/Fixed4.h"

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <charconv>
#include <cstring>

namespace ncc {

namespace {
constexpr size_t kFlushAt = 1 << 16;
// The longest prefix ("%5d N%-6lld ") and the longest move line after it: a name, nine numbers
// with their separators, the arc's turns and the parentheses.
constexpr size_t kPrefixMax = 56;
constexpr size_t kMoveMax = 64 + 9 * (kFixed4Max + 2);
// Arc argument order per plane: first and second plane axis, normal axis (rs274's ARC_FEED).
constexpr int kArcAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
constexpr const char *kPlaneNames[] = {"CANON_PLANE_XY", "CANON_PLANE_XZ", "CANON_PLANE_YZ"};

// The straight moves' names, padded so that record() copies them 24 bytes at a time.
constexpr char kStraightNames[2][24] = {"STRAIGHT_FEED(", "STRAIGHT_TRAVERSE("};
constexpr size_t kStraightLen[2] = {14, 18};

// writtenAxes of one straight move's end on the bits: U V W all +0 or -0 is the usual case.
int straightAxes(const AxisVec &v) {
  uint64_t any = 0;
  for (int i = kBaseAxes; i < kAxes; ++i) {
    uint64_t bits;
    std::memcpy(&bits, &v[i], sizeof bits);
    any |= bits << 1;  // the sign bit shifted out: -0 counts as 0, as != 0 does
  }
  return any ? kAxes : kBaseAxes;
}

char *put(char *p, std::string_view s) {
  std::memcpy(p, s.data(), s.size());
  return p + s.size();
}

// ", "-separated %.4f values (room: n * (kFixed4Max + 2)).
char *nums(char *p, const double *v, int n) {
  for (int i = 0; i < n; ++i) {
    if (i) *p++ = ',', *p++ = ' ';
    p = formatFixed4(p, v[i]);
  }
  return p;
}
}  // namespace

CanonTraceWriter::CanonTraceWriter(std::FILE *out) : out_(out), buf_(kFlushAt + 2 * kMoveMax) {
  std::memset(seq_, ' ', sizeof seq_);
  seq_[kSeqEnd - 1] = '0';
}

// After finish() the stream may already be closed by its owner (AtomicFile::commit): no access.
CanonTraceWriter::~CanonTraceWriter() {
  if (!finished_) flush();
}

void CanonTraceWriter::writeOut() {
  if (len_ && out_ && std::fwrite(buf_.data(), 1, len_, out_) != len_) ioError_ = true;
  len_ = 0;
}

bool CanonTraceWriter::flush() {
  if (out_) writeOut();
  if (out_ && std::fflush(out_) != 0) ioError_ = true;
  return !ioError_;
}

char *CanonTraceWriter::room(size_t n) {
  writeOut();
  if (n > buf_.size()) buf_.resize(n);
  return buf_.data();
}

inline char *CanonTraceWriter::axes(char *p, const double *v, int n) {
  for (int i = 0; i < n; ++i) {
    if (i) *p++ = ',', *p++ = ' ';
    uint64_t bits;
    std::memcpy(&bits, &v[i], sizeof bits);
    Column &c = columns_[i];
    if (bits == c.bits) {
      std::memcpy(p, c.text, sizeof c.text);
      p += c.len;
      continue;
    }
    char *e = formatFixed4(p, v[i]);
    if (size_t len = (size_t)(e - p); len <= sizeof c.text) {  // the room after p covers the whole copy
      c.bits = bits, c.len = len;
      std::memcpy(c.text, p, sizeof c.text);
    }
    p = e;
  }
  return p;
}

inline char *CanonTraceWriter::begin(int64_t n, size_t after) {
  // "%5d " then the N column: "N....." + blank, or N and the number left-aligned in 6 columns.
  // The counter counts up in its text; the N column is formatted when the block changes.
  int i = kSeqEnd - 1;
  for (; seq_[i] == '9'; --i) seq_[i] = '0';
  seq_[i] = seq_[i] == ' ' ? '1' : char(seq_[i] + 1);
  if (i < seqFirst_) seqFirst_ = i;
  if (n != lastBlock_ || !blockColLen_) {
    lastBlock_ = n;
    char *q = blockCol_;
    if (n < 0) {
      q = put(q, "N..... ");
    } else {
      *q++ = 'N';
      char *d = std::to_chars(q, q + 24, (long long)n).ptr;
      for (; d - q < 6; ++d) *d = ' ';
      q = d;
    }
    blockColLen_ = (size_t)(q - blockCol_);
  }
  char *p = len_ + kPrefixMax + after + 1 <= buf_.size() ? buf_.data() + len_ : room(kPrefixMax + after + 1);
  // Fixed-size copies (the room reserved covers them; the bytes past the text are overwritten).
  const size_t seqLen = (size_t)(kSeqEnd - seqFirst_);
  if (seqLen <= 16) std::memcpy(p, seq_ + seqFirst_, 16), p += seqLen;
  else p = put(p, std::string_view(seq_ + seqFirst_, seqLen));
  *p++ = ' ';
  std::memcpy(p, blockCol_, 24);
  return p + blockColLen_;
}

inline void CanonTraceWriter::end(char *p) {
  *p++ = '\n';
  len_ = (size_t)(p - buf_.data());
  if (len_ >= kFlushAt && out_) writeOut();
}

void CanonTraceWriter::line(int64_t n, std::string_view text) { end(put(begin(n, text.size()), text)); }

void CanonTraceWriter::numLine(int64_t n, std::string_view name, double v) {
  char *p = put(begin(n, name.size() + kFixed4Max + 1), name);
  p = formatFixed4(p, v);
  *p++ = ')';
  end(p);
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
  char *p = put(begin(n, kMoveMax), r.sync == ThreadSync::TapIn ? "RIGID_TAP(" : "STRAIGHT_FEED(");
  p = axes(p, r.end.data(), r.sync == ThreadSync::TapIn ? 3 : writtenAxes({&r.end}));
  *p++ = ')';
  end(p);
}

// The trace's usual line (every line of a flat program, a loop's every move) without the
// general dispatch below: nothing to stop, start or re-enable before or after it.
void CanonTraceWriter::record(const MotionRecord &r) {
  if (r.kind > RecordKind::Linear || !started_ || finished_ || halted_ || sync_ || enableAfterMove_) return other(r);
  const bool rapid = r.kind == RecordKind::Rapid;
  char *p = begin(r.blockNumber, kMoveMax);  // room for the whole copy
  std::memcpy(p, kStraightNames[rapid], sizeof kStraightNames[rapid]);
  p = axes(p + kStraightLen[rapid], r.end.data(), straightAxes(r.end));
  *p++ = ')';
  end(p);
}

void CanonTraceWriter::other(const MotionRecord &r) {
  if (finished_ || halted_) return;
  if (!started_) preamble();
  const int64_t n = r.blockNumber;
  if (r.kind == RecordKind::Thread) return thread(r);
  stopSync(syncBlock_);
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear: {
    char *p = put(begin(n, kMoveMax), r.kind == RecordKind::Rapid ? "STRAIGHT_TRAVERSE(" : "STRAIGHT_FEED(");
    p = axes(p, r.end.data(), writtenAxes({&r.end}));
    *p++ = ')';
    end(p);
    if (enableAfterMove_) line(n, "ENABLE_FEED_OVERRIDE()");
    enableAfterMove_ = false;
    break;
  }
  case RecordKind::Arc: {
    // After a tilted arc nothing more is written: the trace would no longer be the path.
    if (tilted_.reject(r)) {
      halted_ = true;
      return;
    }
    const int *ax = kArcAxes[(int)r.plane];
    char *p = put(begin(n, kMoveMax + 2 * kFixed4Max), "ARC_FEED(");
    double v[4] = {r.end[ax[0]], r.end[ax[1]], r.center[ax[0]], r.center[ax[1]]};
    p = nums(p, v, 4);
    p = put(p, ", ");
    p = std::to_chars(p, p + 24, r.turns).ptr;
    p = put(p, ", ");
    double w[7] = {r.end[ax[2]], r.end[3], r.end[4], r.end[5], r.end[6], r.end[7], r.end[8]};
    p = nums(p, w, writtenAxes({&r.end}) - 2);
    *p++ = ')';
    end(p);
    break;
  }
  case RecordKind::Probe: {  // rs274's G38.x: the programmed target, bracketed by the probe's switching
    const AxisVec &target = r.probe().target;
    line(n, "TURN_PROBE_ON()");
    char *p = put(begin(n, kMoveMax), "STRAIGHT_PROBE(");
    p = nums(p, target.data(), writtenAxes({&target}));
    *p++ = ')';
    end(p);
    line(n, "TURN_PROBE_OFF()");
    break;
  }
  case RecordKind::Spline:
    // rs274's standalone canon prints only the number of control points (start and end
    // included) for G5, G5.1 and G5.2/G5.3 alike; the curve itself is in the Motion IR.
    line(n, "NURBS_FEED(" + std::to_string(r.spline().count()) + ", ...)");
    break;
  case RecordKind::Dwell:
    numLine(n, "DWELL(", r.value);
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
    numLine(n, "SET_SPINDLE_SPEED(0, ", r.value);
    break;
  case RecordKind::SpindleCW: line(n, "START_SPINDLE_CLOCKWISE(0)"); break;
  case RecordKind::SpindleCCW: line(n, "START_SPINDLE_COUNTERCLOCKWISE(0)"); break;
  case RecordKind::SpindleStop: line(n, "STOP_SPINDLE_TURNING(0)"); break;
  case RecordKind::SpindleOrient: {  // rs274's M19: the orientation, then the wait when Q is given
    char *p = put(begin(n, 64 + kFixed4Max), "ORIENT_SPINDLE(0, ");
    p = put(formatFixed4(p, r.value), ", ");
    p = std::to_chars(p, p + 24, (long long)r.ivalue).ptr;
    *p++ = ')';
    end(p);
    if (r.value2 > 0) numLine(n, "SPINDLE.0.WAIT_ORIENT_COMPLETE(", r.value2);
    break;
  }
  case RecordKind::SpindleMode:
    // rs274 prints the G96 limit (D), 1e30 for none, and 0 for G97; a moved origin is no command.
    if (r.ivalue == 2) break;
    numLine(n, "SET_SPINDLE_MODE(0 ", r.ivalue == 0 ? 0.0 : r.value > 0 ? r.value : 1e30);
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
    numLine(n, "SET_FEED_RATE(", r.value);
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
