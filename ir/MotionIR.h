// Motion IR: the flat, fully resolved result of running a program. One record per motion or
// machine-state event, all positions in machine coordinates (mm, degrees), all state explicit.
// It is a stream: producers push records into a MotionSink chain (planner, trace writers,
// summary, plot), so a million-move program never has to be held in memory.
#pragma once
#include "ir/Diagnostics.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ncc {

enum class Axis : uint8_t { X, Y, Z, A, B, C, Count };
constexpr int kAxes = (int)Axis::Count;
using AxisVec = std::array<double, kAxes>;

enum class Plane : uint8_t { XY, ZX, YZ };  // G17, G18, G19

enum class RecordKind : uint8_t {
  Rapid,         // straight traverse to `end`
  Linear,        // straight feed to `end` at `feed`
  Arc,           // circular/helical feed: `center`, `plane`, `turns` (+ccw, -cw), to `end`
  Dwell,         // `value` seconds
  ToolSelect,    // `ivalue` tool number (T word)
  ToolChange,    // `ivalue` tool number now in the spindle (M6)
  ToolLength,    // `value` active tool length offset (mm) along the tool axis
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
  Count
};

const char *recordKindName(RecordKind k);

struct MotionRecord {
  RecordKind kind = RecordKind::Rapid;
  Plane plane = Plane::XY;
  bool exactStop = false;   // stop at the end of this move (G9/G61/cycle holes)
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
};

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

// Collects records in memory (tests, --emit=motion of small programs, translate).
class MotionBuffer : public MotionSink {
public:
  void record(const MotionRecord &r) override { records.push_back(r); }
  std::vector<MotionRecord> records;
};

// Textual Motion IR: one record per line, `%.4f`-free full precision (shortest round-trip).
std::string printMotionRecord(const MotionRecord &r);
// Prints records as text to a stream (`ncc compile --emit=motion`).
class MotionTextWriter : public MotionSink {
public:
  explicit MotionTextWriter(std::FILE *out) : out_(out) {}
  void record(const MotionRecord &r) override;

private:
  std::FILE *out_;
};

}  // namespace ncc
