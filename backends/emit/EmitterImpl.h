// Private to backends/emit: the emitter engine (Emitter.cpp: blocks, modal memory, moves, arcs,
// splines, the record switch; EmitterSync.cpp: threads and the spindle's modes and orientation;
// EmitterProbe.cpp: probe moves).
#pragma once
#include "backends/emit/ArcGeometry.h"
#include "backends/emit/ControllerTable.h"
#include "backends/emit/Emitter.h"
#include "backends/emit/EmitterFrame.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace ncc {
struct CycleDef;  // runtime/cycles/Library.h
}

namespace ncc::emit::detail {


constexpr double kPi = 3.14159265358979323846;
const char kCenterLetters[] = "IJK";

// Where the text goes: a string (tests, translate) or a stream (bounded memory).
class LineSink {
public:
  explicit LineSink(std::string *s) : str_(s) {}
  explicit LineSink(std::FILE *f) : file_(f) {}
  void line(const std::string &text, const std::string &eol) {
    if (str_) {
      *str_ += text;
      *str_ += eol;
    } else if (file_) {  // the texts hold no NUL (sanitizeText): the same bytes as fputs, no strlen
      std::fwrite(text.data(), 1, text.size(), file_);
      std::fwrite(eol.data(), 1, eol.size(), file_);
    }
  }
  // Bytes as they are (ADEM's binary records).
  void raw(const std::string &bytes) {
    if (str_) *str_ += bytes;
    else if (file_) std::fwrite(bytes.data(), 1, bytes.size(), file_);
  }
  bool failed() const { return file_ && std::ferror(file_); }

private:
  std::string *str_ = nullptr;
  std::FILE *file_ = nullptr;
};

// The coolant codes that take the written state (flood, mist) to the wanted one, and the written
// state after them. The codes share one modal group and one code turns both off, so the two "off"
// records a single M9 produces become one M9 again.
inline std::vector<std::string> coolantCodes(const ControllerStyle &st, bool &flood, bool &mist, bool floodWanted,
                                             bool mistWanted) {
  std::vector<std::string> codes;
  if ((flood && !floodWanted) || (mist && !mistWanted)) {
    codes.push_back(st.codes[(size_t)Code::CoolantOff]);
    flood = mist = false;
  }
  if (mistWanted && !mist) codes.push_back(st.codes[(size_t)Code::MistOn]);
  if (floodWanted && !flood) codes.push_back(st.codes[(size_t)Code::FloodOn]);
  flood = floodWanted;
  mist = mistWanted;
  return codes;
}

// A cycle written as its call: the records of its expansion are skipped (the re-read call makes
// them again); only the position where they end counts.
class SkippedCycle {
public:
  bool active = false;
  // Takes one record of the bracket; true when it closed a bracket that moved, to `end`.
  bool closes(const MotionRecord &r, AxisVec &end) {
    if (isMoveRecord(r.kind)) end_ = r.end, moved_ = true;
    if (r.kind != RecordKind::CycleEnd) return false;
    bool moved = moved_;
    active = moved_ = false;
    end = end_;
    return moved;
  }

private:
  bool moved_ = false;
  AxisVec end_{};
};

// The Klartext writer family (Klartext.cpp): nullptr after reporting when its section is invalid.
std::unique_ptr<ProgramEmitter> makeKlartext(const Machine &m, const EmitOptions &opts, LineSink out,
                                             Diagnostics &diags);

// The CL record writer family (ClRecords.cpp: APT CL text, ADEM CLData listing or binary).
std::unique_ptr<ProgramEmitter> makeClWriter(const Machine &m, const EmitOptions &opts, LineSink out, Diagnostics &diags);

// State words waiting for the next block. A second word of a group already waiting flushes the
// buffer first (the passport's "alternative window" rule, seed 004 §3.5).
enum class PendingGroup : uint8_t { Speed, Spindle, Coolant, Tool, ToolChange, Plane, FeedMode, PathMode, SpindleMode };

class Emitter final : public ProgramEmitter {
public:
  Emitter(const Machine &m, ControllerStyle style, const EmitOptions &opts, LineSink out, Diagnostics &diags)
      : machine_(m), st_(std::move(style)), opts_(opts), out_(out), diags_(diags), nextN_(st_.blockStart) {
    plane_ = st_.setupPlane;
    for (int i = 0; i < kAxes; ++i) axisWords_[i] = axisWordOf(i);
    posValue_.fill(NAN);
  }

  void writeHeader();
  void record(const MotionRecord &r) override;
  bool finish(Diagnostics &diags) override;
  uint64_t blocksWritten() const override { return blocks_; }

private:
  using Words = std::vector<std::string>;
  static constexpr size_t kBlockWords = 8;  // room a move's words take (one allocation, not three)

  const NumberFormat &fmt(WordClass c) const { return st_.formats[(size_t)c]; }
  const std::string &code(Code c) const { return st_.codes[(size_t)c]; }
  bool latheIso() const { return st_.lathe && st_.target == Target::ISO; }  // docs/EMIT.md "Lathes"
  const std::string &axisWord(int axis) const { return axisWords_[axis]; }
  std::string axisWordOf(int axis) const;
  std::array<std::string, kAxes> axisWords_;  // axisWordOf, once per axis
  static WordClass axisClass(int axis) { return isLengthAxis(axis) ? WordClass::Axis : WordClass::Rotary; }
  // Written value of a machine position (a lathe's X as a diameter) and the position the
  // controller reads back from the rounded word.
  double written(int axis, double v) const { return axis == 0 ? v * st_.xScale : v; }
  double readBack(int axis, double v) const {
    return roundTo(written(axis, v), fmt(axisClass(axis)).decimals) / (axis == 0 ? st_.xScale : 1);
  }
  // The position after a block that wrote no axis words for `end` (G5.3, a rigid tap's return).
  void notePosition(const AxisVec &end, int axes);

  bool number(double v, WordClass c, const std::string &letter, const MotionRecord &r, std::string &out);
  void badNumber(double v, const std::string &letter, const MotionRecord &r);
  void push(Words &w, const std::string &word) {
    if (!word.empty()) w.push_back(word);
  }
  void writeBlock(const Words &words, int64_t sourceN);
  void writeLine(const std::string &text) {
    out_.line(text, st_.lineEnding);
    ++blocks_;
  }

  void addPending(PendingGroup g, const std::string &word, const MotionRecord &r);
  void flushPending();

  void ensurePosition(const MotionRecord &r);
  void axisWords(const AxisVec &end, Words &w, const MotionRecord &r);
  void feedWord(const MotionRecord &r, Words &w, double lengthMM);
  void motionCode(Code c, Words &w);
  void move(const MotionRecord &r);
  void moveBlock(const MotionRecord &r);
  // The passport's motion rules (EmitterPassport.cpp, seed 004 §3.3): a rapid in legs, a straight
  // move in equal parts, an arc refused or split at its quadrant boundaries.
  std::vector<MotionRecord> rapidLegs(const MotionRecord &r) const;
  bool incrementParts(const MotionRecord &r, std::vector<MotionRecord> &parts);
  std::string arcRefusal(const MotionRecord &r) const;
  void quadrantArcs(const MotionRecord &r);
  void arc(const MotionRecord &r);
  void arcBlock(const MotionRecord &r, const AxisVec &end, int turns, bool sourceFull);
  void arcPieces(const MotionRecord &r, int turns, bool sourceFull);
  // Why this output cannot write the spline exactly (empty: it can, as LinuxCNC G5.2/G5.3).
  std::string splineRefusal(const MotionRecord &r) const;
  void spindleOrient(const MotionRecord &r);
  void spindleMode(const MotionRecord &r);
  void spline(const MotionRecord &r);
  // Reports `why` (when not empty) as the reason the record cannot be written; true then.
  bool refused(const MotionRecord &r, const char *what, const std::string &why) {
    if (why.empty()) return false;
    diags_.error(r.loc, "the [" + st_.section + "] emitter cannot write this " + what + " (" + why + "): " + printMotionRecord(sourceOf(r)),
                 "unsupported-code");
    errors_ = true;
    return true;
  }
  // Why this output cannot write the thread record exactly (empty: it can).
  std::string threadRefusal(const MotionRecord &r) const;
  void thread(const MotionRecord &r);
  void latheThreadWords(const MotionRecord &r, Words &w);
  // NC-200 G34 (Nc200Thread.cpp).
  std::string nc200ThreadRefusal(const MotionRecord &r) const;
  void nc200Thread(const MotionRecord &r);
  // Probe records (EmitterProbe.cpp): why this output cannot write one (empty: it can).
  std::string probeRefusal(const MotionRecord &r) const;
  void probe(const MotionRecord &r);
  bool probeWarned_ = false;  // the warning that later moves follow the simulated probe, once  // ISO lathe G32/G33: F the lead, Q the start angle
  void latheSpeedLimit(const MotionRecord &r, const std::string &limit);
  void planeWord(Plane p, Words &w);
  void dwell(const MotionRecord &r);
  void comment(const std::string &text);
  void message(const std::string &text, const MotionRecord &r);
  void coolant(const MotionRecord &r, bool flood);
  // Library cycles written back as their calls (EmitterCycle.cpp, Sinumerik).
  bool nativeCycle(const MotionRecord &r);
  bool cycleArguments(const MotionRecord &r, const CycleDef &d, const char *prefix, std::string &out);
  void skipCycleRecord(const MotionRecord &r);
  SkippedCycle skipped_;
  std::vector<std::string> coolantCodes();
  // Work offsets, shifts, tool length and travel (EmitterFrame.cpp). frameRecord notes the
  // records that change them (true: nothing else to write); toWritten gives a record's positions
  // in the written program's coordinates (r itself, or a shifted copy in `scratch`).
  bool frameRecord(const MotionRecord &r);
  const MotionRecord &toWritten(const MotionRecord &r, MotionRecord &scratch);
  void syncFrame(const MotionRecord &r);
  void setWrittenOffset(const AxisVec &offset);
  bool spindleEdgeLength(int d, double &length) const;
  int spindleEdgeWithLength(double length) const;
  void checkTravel(const MotionRecord &r);
  void finishFrame();
  // The record as the stream gave it (machine coordinates), for messages: `r` may be the copy
  // in written coordinates.
  const MotionRecord &sourceOf(const MotionRecord &r) const { return source_ ? *source_ : r; }
  const MotionRecord *source_ = nullptr;
  SourceFrame src_;
  WrittenFrame written_;
  bool frameDirty_ = true, frameInit_ = false;
  uint64_t travelErrors_ = 0;

  const Machine &machine_;
  ControllerStyle st_;
  EmitOptions opts_;
  LineSink out_;
  Diagnostics &diags_;
  int64_t nextN_;
  uint64_t blocks_ = 0, numberedCount_ = 0;
  bool errors_ = false, ended_ = false, finished_ = false;

  Words pending_;
  uint32_t pendingGroups_ = 0;
  int64_t pendingN_ = -1;

  // Modal memory of the written program (what the controller will hold).
  bool posKnown_ = false;
  AxisVec pos_{};                           // rounded, as the controller reads it
  std::array<std::string, kAxes> posText_;  // formatted, for the "unchanged" test
  // The value posText_ was formatted from (NAN: not known). The same value gives the same text,
  // so most axes of most blocks are found unchanged without formatting them (setPosText).
  std::array<double, kAxes> posValue_;
  void setPosText(int axis, double writtenValue) {
    if (writtenValue == posValue_[axis]) return;  // posText_ is its text already
    posValue_[axis] = formatNumber(writtenValue, fmt(axisClass(axis)), posText_[axis]) ? writtenValue : NAN;
  }
  std::string line_;                        // writeBlock's buffer, reused
  std::string motion_;                      // last motion G code written
  Plane plane_ = Plane::XY;                 // the header selects G17
  int64_t feedMode_ = 0;                    // the header selects G94
  int64_t pathMode_ = 2;                    // continuous after reset
  std::string feedText_;                    // last F value written
  bool haveProgrammedFeed_ = false;
  double programmedFeed_ = 0;
  double speedLimit_ = 0;                   // the CSS limit the written program holds (rpm, 0 none)
  bool cssWritten_ = false;                 // G96 in force in the written program
  bool cssNeedsS_ = false;                  // a G96 waits in the block for its S word
  std::string surfaceWord_;                 // the last S written under G96
  bool afterThread_ = false;                // the last motion written was a thread block
  double startAngle_ = NAN;                 // the Sinumerik SF= in force (NAN: none written yet)
  bool spindlePositioned_ = false;          // an oriented stop since the last M3/M4/M5 (Sinumerik G331 needs it)
  bool flood_ = false, mist_ = false;            // written coolant state
  bool floodWanted_ = false, mistWanted_ = false;  // state the records ask for
};

}  // namespace ncc::emit::detail
