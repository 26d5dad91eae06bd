// Motion IR: the flat, fully resolved result of running a program. One record per motion or
// machine-state event, all positions in machine coordinates (mm, degrees), all state explicit.
// It is a stream: producers push records into a MotionSink chain (planner, trace writers,
// summary, plot), so a million-move program never has to be held in memory.
#pragma once
#include "ir/Diagnostics.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

// The machine axes a record positions: the Cartesian X Y Z, the rotary A B C (about X Y Z) and
// the further linear axes U V W (parallel to X Y Z: LinuxCNC, Heidenhain, Sinumerik channel
// axes; a machine names them as its controller does, docs/MACHINE.md). A machine describes
// which of them it has.
enum class Axis : uint8_t { X, Y, Z, A, B, C, U, V, W, Count };
constexpr int kAxes = (int)Axis::Count;
constexpr char kAxisLetters[kAxes + 1] = "XYZABCUVW";
// X Y Z A B C: what a position is written with while U V W stay at 0 (text form, JSONL,
// canonical trace), so programs of machines without U V W keep rs274's six-axis form.
constexpr int kBaseAxes = 6;
using AxisVec = std::array<double, kAxes>;
// X Y Z and U V W are lengths (scaled by the program's unit), A B C angles.
constexpr bool isLengthAxis(int i) { return i < 3 || i >= kBaseAxes; }
// How many leading axes of the positions to write: kBaseAxes while U V W of all are 0, else kAxes.
inline int writtenAxes(std::initializer_list<const AxisVec *> vs) {
  for (const AxisVec *v : vs)
    for (int i = kBaseAxes; i < kAxes; ++i)
      if ((*v)[i] != 0) return kAxes;
  return kBaseAxes;
}

enum class Plane : uint8_t { XY, ZX, YZ };  // G17, G18, G19

enum class RecordKind : uint8_t {
  Rapid,         // straight traverse to `end`
  Linear,        // straight feed to `end` at `feed`
  Arc,           // circular/helical feed: `center`, `plane`, `turns` (+ccw, -cw), to `end`;
                 // arcNormal() (a tilted plane when set, see MotionExtra)
  Dwell,         // `value` seconds
  ToolSelect,    // `ivalue` tool number (T word)
  ToolChange,    // `ivalue` tool number now in the spindle (M6)
  ToolLength,    // `value` active tool length offset (mm) along the tool axis, `ivalue` the H number,
                 // `value2` a lathe tool's X offset (mm, machine X; printed `X..` when not 0)
  SpindleSpeed,  // `value` rpm (or m/min with CSS)
  SpindleCW,
  SpindleCCW,
  SpindleStop,
  CoolantFlood,  // ivalue 1 = on, 0 = off
  CoolantMist,
  FeedRate,      // `value` mm/min (or mm/rev, see feedMode)
  FeedMode,      // ivalue 0 per minute, 1 per revolution, 2 inverse time
  PathMode,      // ivalue 0 exact path, 1 exact stop, 2 continuous (value = tolerance)
  Plane,         // ivalue = Plane
  Comment,       // text
  Message,       // text (MSG)
  OptionalStop,  // M1
  ProgramStop,   // M0
  ProgramEnd,    // M2/M30 (ivalue 30 for M30)
  Aux,           // other M code, B or H auxiliary function: text the letter, ivalue the number
  CycleBegin,    // a canned cycle's expansion follows: text the cycle (`iso.G81`), params its words
  CycleEnd,      // closes the innermost CycleBegin
  FrameChange,   // the work->machine transform changed: params m00..m23, text what changed (`G54`)
  Spline,        // polynomial or NURBS curve fed to `end` at `feed`: spline() (SplineData)
  SpindleOrient, // oriented spindle stop: `value` angle (degrees), `ivalue` way (0 cw, 1 ccw,
                 // 2 shortest), `value2` seconds to wait for it (0: no wait)
  SpindleMode,   // G96/G97: `ivalue` 0 constant rpm, 1 constant surface speed (CSS; the
                 // SpindleSpeed records that follow are m/min, the rpm follows the tool's
                 // radius, see docs/IR.md), 2 CSS goes on about a moved origin (no code);
                 // `value` the CSS spindle-speed limit (rpm, 0: none), `value2` the origin:
                 // the machine X of the spindle axis
  Thread,        // spindle-synchronised straight feed to `end` (thread cutting, rigid tapping):
                 // `value` the lead (mm per spindle revolution) measured along `ivalue`
                 // (ThreadAxis), `value2` the start angle (degrees after the spindle's index),
                 // `sync` (ThreadSync), `feed` the path feed it gives at the programmed speed
  ToolNumber,    // LinuxCNC M61: `ivalue` the tool now declared in the spindle (no change, no motion)
  DigitalOutput, // LinuxCNC M62-M65: `ivalue` the output, `value` 1 on / 0 off, `value2` 1 synchronized
                 // with the next move (M62/M63), 0 at once (M64/M65)
  AnalogOutput,  // LinuxCNC M67/M68: `ivalue` the output, `value` its value, `value2` as DigitalOutput
  Probe,         // straight feed at `feed` toward a programmed target that stops where a probe's
                 // signal came (LinuxCNC G38.2-G38.5; later ISO G31, Sinumerik MEAS/MEAW):
                 // `end` is where the machine stopped, probe() (ProbeData) the target and mode
  Count
};

const char *recordKindName(RecordKind k);

// Thread records: what the lead is measured along. LinuxCNC's K is per unit of path length;
// Fanuc/808D and Sinumerik give it along the thread's main axis (Z, or X for a face thread).
enum class ThreadAxis : uint8_t { X, Y, Z, Path };
// How a thread record joins the motion before it: `Index` waits for the spindle's index
// (plus the start angle) and starts a new synchronisation; `Chain` continues the thread record
// before it without waiting (chained threads, a lead change inside one pass); `TapIn` is a
// rigid tap into the hole (waits like Index), `TapOut` its return with the spindle reversed.
enum class ThreadSync : uint8_t { Index, Chain, TapIn, TapOut };
const char *threadAxisName(ThreadAxis a);  // "x" "y" "z" "path"
const char *threadSyncName(ThreadSync s);  // "index" "chain" "tap_in" "tap_out"

// Probe records: what stops the move and what a miss means. `Contact` stops on the signal's
// coming (G38.2/G38.3, G31, MEAS=1), `Release` on its going (G38.4/G38.5, MEAS=-1). `tripped`
// says the signal came: `end` is where (on the segment start..target); otherwise the move
// reached `target` (= end) without it, which is an error when `missIsError` (G38.2, G38.4), so
// such a record never exists.
enum class ProbeSignal : uint8_t { Contact, Release };
struct ProbeData {
  AxisVec target{};  // the programmed end, machine coordinates
  ProbeSignal signal = ProbeSignal::Contact;
  bool missIsError = true;
  bool tripped = true;
};
const char *probeSignalName(ProbeSignal s);  // "contact" "release"

// One named number of a CycleBegin or FrameChange record, `key=value` in the text form.
// Keys are 1..7 characters [A-Za-z_][A-Za-z0-9_]*, stored inline (no allocation per key).
struct NamedNumber {
  static constexpr size_t kMaxKey = 7;
  std::array<char, kMaxKey + 1> key{};
  double value = 0;
  std::string_view name() const { return std::string_view(key.data()); }
};
bool isNamedNumberKey(std::string_view key);

// The curve of a Spline record: a clamped B-spline (rational when weighted) of `degree` whose
// control points are the record's start, `points`, then its end (machine XYZ, as every record's
// positions). Every dialect's spline maps onto it: LinuxCNC G5 (cubic Bezier: degree 3, two inner
// points), G5.1 (quadratic, one), G5.2 (NURBS of order L, weights P), Sinumerik BSPLINE (degree
// SD, weights PW, knots PL), Heidenhain SPL and CLData NURBS (explicit knots and weights).
struct SplineData {
  int degree = 3;
  std::vector<std::array<double, 3>> points;  // the inner control points, in order
  std::vector<double> weights;  // empty: all 1; else one per control point, the start's first
  std::vector<double> knots;    // empty: splineDefaultKnots; else count + degree + 1 values
  size_t count() const { return points.size() + 2; }  // control points with start and end
};
// The clamped uniform knot vector rs274 uses (knot_vector_creator): degree + 1 zeros, then
// 1, 2, ..., then degree + 1 copies of count - degree.
std::vector<double> splineDefaultKnots(size_t count, int degree);
// Why the record's spline is not a valid curve (empty when it is): degree >= 1, enough points,
// finite positive weights, a non-decreasing clamped knot vector of the right length, no motion
// of A, B or C (a spline moves the tool point only).
struct MotionRecord;
std::string splineError(const MotionRecord &r);

// The rarely used content of a record, kept out of line so that ordinary records (every move
// of a program) stay small and copy as before: a tilted arc's normal, the named numbers.
struct MotionExtra {
  bool hasNormal = false;
  std::array<double, 3> normal{};  // unit normal of a tilted arc (see MotionRecord::arcNormal)
  std::vector<NamedNumber> params;
  SplineData spline;  // Spline records
  ProbeData probe;    // Probe records
};

// A copyable owning pointer (deep copy), null by default: keeps the rarely used part of a hot,
// often copied structure out of line (MotionRecord::extra, ArcGeometry's tilted frame).
template <class T>
class CopyPtr {
public:
  CopyPtr() = default;
  CopyPtr(const CopyPtr &o) : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
  CopyPtr(CopyPtr &&) noexcept = default;
  // Both null (the common case) costs two tests.
  CopyPtr &operator=(const CopyPtr &o) {
    if ((p_ || o.p_) && this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
    return *this;
  }
  CopyPtr &operator=(CopyPtr &&o) noexcept {
    if (p_ || o.p_) p_ = std::move(o.p_);
    return *this;
  }
  const T *get() const { return p_.get(); }
  const T &operator*() const { return *p_; }
  const T *operator->() const { return p_.get(); }
  explicit operator bool() const { return p_ != nullptr; }
  T &make() {
    if (!p_) p_ = std::make_unique<T>();
    return *p_;
  }
  void reset() { p_.reset(); }

private:
  std::unique_ptr<T> p_;
};
using MotionExtraPtr = CopyPtr<MotionExtra>;

struct MotionRecord {
  RecordKind kind = RecordKind::Rapid;
  Plane plane = Plane::XY;
  bool exactStop = false;   // stop at the end of this move (G9/G61/cycle holes)
  ThreadSync sync = ThreadSync::Index;  // Thread records only
  int32_t turns = 0;        // arcs: +n counter-clockwise, -n clockwise (n full turns + 1)
  int64_t ivalue = 0;
  int64_t blockNumber = -1; // N word of the source block, -1 when none
  SourceLoc loc;
  AxisVec start{};          // position before the record (motion records)
  AxisVec end{};            // position after the record
  std::array<double, 3> center{};  // arc centre, machine X Y Z
  double feed = 0;          // mm/min effective for this move (0 = rapid)
  double value = 0;
  double value2 = 0;        // PathMode continuous: naive-CAM tolerance (G64 Q), mm
  std::string text;
  MotionExtraPtr extra;     // null unless tiltedArc(), params() or a spline (see MotionExtra)

  // Arcs: the unit normal of the arc's plane; `turns` > 0 is counter-clockwise seen from its
  // tip (a right-handed rotation about it). Unless set, the plane's own axis: +Z for XY (G17),
  // +Y for ZX (G18, from Z towards X), +X for YZ (G19, from Y towards Z), as rs274's ARC_FEED.
  std::array<double, 3> arcNormal() const;
  // True when an arc's normal was set and is not its plane's axis: it lies in a tilted plane.
  bool tiltedArc() const { return extra.get() && extra.get()->hasNormal; }
  // Sets the normal; the plane's own axis (exactly) clears it, so a record has one spelling.
  void setNormal(const std::array<double, 3> &n);
  // Spline records: the curve (an empty degree-3 curve, a straight line, when never set).
  const SplineData &spline() const;
  // Sets the curve; unit weights and the default knot vector are dropped, so one curve has one
  // spelling (as the text form prints it).
  void setSpline(SplineData s);
  // Probe records: the target and the mode (a probe toward the record's end when never set).
  const ProbeData &probe() const;
  void setProbe(const ProbeData &p) { extra.make().probe = p; }
  // CycleBegin / FrameChange: the named numbers in order.
  const std::vector<NamedNumber> &params() const;
  // Appends (or replaces) a named number; false when the key is not a valid key.
  bool setParam(std::string_view key, double value);
  // The value of a named number, or nullptr.
  const double *param(std::string_view key) const;
};

// Thread records: the lead per revolution along the path (LinuxCNC's K) and along machine axis
// `axis` (0..2) of the straight move from start to end; 0 when the record does not move there.
double threadPathLead(const MotionRecord &r);
// A variable lead (808D G34): the change of the lead per revolution (mm/rev^2, along the same
// axis as the lead; the named number `dlead`, 0 when absent), and the lead at the end:
// sqrt(lead^2 + 2 dlead travel) (the lead grows linearly with the revolutions).
double threadLeadChange(const MotionRecord &r);
double threadEndLead(const MotionRecord &r);
double threadAxisLead(const MotionRecord &r, int axis);
// Why a thread record is not a valid one (empty when it is): a lead > 0 and finite, a move
// along the lead's axis, a start angle in [0, 360), no A B C motion.
std::string threadError(const MotionRecord &r);

// Why a probe record is not a valid one (empty when it is): a positive finite feed, a target
// other than the start, the end on the segment start..target (the target itself when it did not
// trip), not a miss that is an error, and a stop at its end (exact_stop).
std::string probeError(const MotionRecord &r);
// The records that move the machine from `start` to `end` (the text form's and the stream's
// position follows them).
inline bool isMoveRecord(RecordKind k) {
  return k <= RecordKind::Arc || k == RecordKind::Spline || k == RecordKind::Thread || k == RecordKind::Probe;
}

// FrameChange's transform: the 3x4 matrix that maps program XYZ to machine XYZ, row-major
// (machine_i = m_i0 x + m_i1 y + m_i2 z + m_i3), as the named numbers m00..m23.
using FrameMatrix = std::array<double, 12>;
void setFrameMatrix(MotionRecord &r, const FrameMatrix &m);
// Reads m00..m23; an entry the record lacks is the identity's.
FrameMatrix frameMatrix(const MotionRecord &r);
// Its axes after X Y Z: machine A B C U V W = work + shift, named numbers ma mb mc mu mv mw
// (written when not 0).
using AxisShift = std::array<double, kAxes - 3>;
void setAxisShift(MotionRecord &r, const AxisShift &s);
AxisShift axisShift(const MotionRecord &r);
// The work offset selected when the frame changed: 1..9 the machine's [offsets] g54…"g59.3" (ISO
// G54…G59.3, Sinumerik G54…G57, G505…G509), 7..99 also the 808D's G54 P1…P93 ([offsets] g54p), 0 none
// (Sinumerik G500, an assigned $P_IFRAME, or G510…G599: the transform carries their offsets).
// The named number `wcs`, written when not 1 (G54, the selection at the start). Emitters select
// the same offset on their target (docs/EMIT.md "Work offsets").
void setWorkOffsetSelection(MotionRecord &r, int selection);
int workOffsetSelection(const MotionRecord &r);

// Work coordinates beside machine coordinates: follows a stream's FrameChange and ToolLength
// records and gives the work (program) position of a machine position, in mm (a diameter-
// programmed X as a radius) and degrees: machine XYZ = M · work + the tool offset, A B C U V W =
// work + shift. Emitters, lint and the JSONL trace read positions through it.
class WorkFrame {
public:
  void note(const MotionRecord &r);  // FrameChange and ToolLength records; others are ignored
  AxisVec work(const AxisVec &machine) const;

private:
  double inv_[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::array<double, 3> origin_{};  // M's translation
  AxisShift shift_{};
  double toolZ_ = 0, toolX_ = 0, toolY_ = 0;
};

// The plane's own unit normal (+Z, +Y, +X for XY, ZX, YZ).
std::array<double, 3> planeNormal(Plane p);
const char *planeName(Plane p);  // "xy", "zx", "yz"

// Receives the record stream. Sinks are chained: a sink may forward to `next`.
class MotionSink {
public:
  virtual ~MotionSink() = default;
  virtual void record(const MotionRecord &r) = 0;
  // Called once after the last record (flush planners, write files). Returns false on failure.
  virtual bool finish(Diagnostics &diags) { return true; }
};

// Fans one stream out to several sinks.
class MotionTee : public MotionSink {
public:
  void add(MotionSink *s) { sinks_.push_back(s); }
  // The one sink when there is only one (records then skip the tee's call), else null.
  MotionSink *single() const { return sinks_.size() == 1 ? sinks_[0] : nullptr; }
  void record(const MotionRecord &r) override {
    for (auto *s : sinks_) s->record(r);
  }
  bool finish(Diagnostics &diags) override {
    bool ok = true;
    for (auto *s : sinks_) ok &= s->finish(diags);
    return ok;
  }

private:
  std::vector<MotionSink *> sinks_;
};

// For sinks whose output has only the three principal planes (the canonical trace; the emitters
// use message()): remembers the first arc in a tilted plane and reports it at finish(), where
// diagnostics are at hand. The sink writes nothing wrong meanwhile: it skips the record.
class TiltedArcCheck {
public:
  explicit TiltedArcCheck(const char *consumer) : consumer_(consumer) {}
  // True (and noted) when r is a tilted arc the sink must not write.
  bool reject(const MotionRecord &r) {
    if (!r.tiltedArc()) return false;
    if (!seen_) first_ = r, seen_ = true;
    return true;
  }
  bool seen() const { return seen_; }
  // Reports the first rejected arc as an error; false when there was one.
  bool report(Diagnostics &diags) const;
  // The message (also used directly by sinks that have diagnostics at hand).
  static std::string message(const char *consumer, const MotionRecord &r);

private:
  const char *consumer_;
  bool seen_ = false;
  MotionRecord first_;
};

// Collects records in memory (tests, --emit=motion of small programs, translate).
class MotionBuffer : public MotionSink {
public:
  void record(const MotionRecord &r) override { records.push_back(r); }
  std::vector<MotionRecord> records;
};

// Textual Motion IR (docs/IR.md "Motion IR text"): one record per line, numbers in shortest
// round-trip form, strings quoted and escaped. The one printer; parseMotionText reads it back.
std::string printMotionRecord(const MotionRecord &r);
void appendMotionRecord(std::string &out, const MotionRecord &r);
// Prints records as text, one line each, to a stream or into a string (`ncc compile
// --emit=motion`, the lower-motion pass).
class MotionTextWriter : public MotionSink {
public:
  explicit MotionTextWriter(std::FILE *out) : out_(out) {}
  explicit MotionTextWriter(std::string &text) : text_(&text) {}
  void record(const MotionRecord &r) override;

private:
  std::FILE *out_ = nullptr;
  std::string *text_ = nullptr;
  std::string line_;
};

// Parses Motion IR text (file `file` of sm) into records pushed to `sink`, in order. Starts
// at the machine origin in the XY plane; each record's start is the previous record's end, its
// plane the last plane record's. Records keep the source positions written in them (`@l:c`,
// file 0: they point into the program the text came from). Errors are reported at their place
// in the text; returns false after an error (records before it have been pushed).
bool parseMotionText(const SourceManager &sm, uint32_t file, MotionSink &sink, Diagnostics &diags);

}  // namespace ncc
