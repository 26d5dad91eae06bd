// The CL record writer family (issue 10): a Motion IR stream as APT CL text (ISO 4343 style, as
// NX, CATIA and Mastercam write it) or as ADEM CLData (its listing, or the binary file of 8-byte
// cells). Each writes what frontend/cldata reads back, with the tables the readers use
// (ir/AptWords.h, ir/AdemRecords.h): one table, two directions. The positions are tool-tip points
// in the machine's G54 work coordinates, the frame both readers run in (docs/EMIT.md "CL records").
#include "backends/emit/EmitterImpl.h"
#include "ir/AdemRecords.h"
#include "ir/AptWords.h"
#include "runtime/cycles/Library.h"

#include <fmt/format.h>

#include <set>

namespace ncc::emit::detail {

namespace {

using namespace ncc::cld;
using Vec3 = std::array<double, 3>;

// The readers' arc check: both ends within this of the radius (mm). The centre is chosen so
// that the two ends' radii differ by at most 0.9 of twice of it; the radius is their mean.
constexpr double kArcCheck = 0.001;

// The coolant words in the word-address writers' coolant rule (coolantCodes): what the written
// state needs, one "off" for both.
const ControllerStyle &coolantWords() {
  static const ControllerStyle s = [] {
    ControllerStyle c;
    c.codes[(size_t)Code::CoolantOff] = "off";
    c.codes[(size_t)Code::FloodOn] = "flood";
    c.codes[(size_t)Code::MistOn] = "mist";
    return c;
  }();
  return s;
}

// A number with at least minDec and at most maxDec decimals (trailing zeros beyond minDec
// stripped): `10.0000`, `0.5`, `3000`.
std::string clNumber(double v, int minDec, int maxDec) {
  NumberFormat f;
  f.decimals = maxDec;
  f.trailingZeros = true;
  std::string s;
  if (!formatNumber(v, f, s)) return "nan";
  size_t dot = s.find('.');
  if (dot == std::string::npos) return s;
  while (s.size() - dot - 1 > (size_t)minDec && s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

// The format-neutral half: Motion IR records become CL events (a tool load, a feed, a rapid or
// feed move, an arc about an axis, spindle, coolant, dwell, stops, comments) in written
// coordinates; APT and ADEM spell them.
class ClWriter : public ProgramEmitter {
public:
  ClWriter(const Machine &m, const EmitOptions &o, LineSink out, Diagnostics &d)
      : machine_(m), opts_(o), out_(out), diags_(d) {
    const AxisVec start = startFrame(m);  // the readers select nothing: the machine's start frame
    for (int i = 0; i < 3; ++i) origin_[i] = start[i];
  }
  void start();
  void record(const MotionRecord &r) override;
  bool finish(Diagnostics &diags) override;
  uint64_t blocksWritten() const override { return lines_; }

protected:
  virtual const char *format() const = 0;  // "APT CL", "ADEM CLData"
  // Format-specific refusals (empty: the format can hold the record).
  virtual std::string refusal(const MotionRecord &r) const = 0;
  virtual void header(const std::string &name, const std::string &note) = 0;
  virtual void comment(const std::string &text) = 0;
  virtual void toolLoad(int n, double radius) = 0;
  virtual void feed(double value, bool perRev) = 0;
  virtual void rapidMove(const Vec3 &p) = 0;
  virtual void feedMove(const Vec3 &p) = 0;
  // An arc from the written position to `end` about `centre`, counter-clockwise about `axis`.
  virtual void arc(const Vec3 &centre, const Vec3 &axis, double radius, const Vec3 &end) = 0;
  virtual void spindleOn(double rpm, bool ccw) = 0;
  virtual void spindleOff() = 0;
  virtual void coolant(const char *which) = 0;  // "flood", "mist"; null: every coolant off
  virtual void dwell(double seconds) = 0;
  virtual void stop(bool optional) = 0;
  virtual void end() = 0;
  virtual void fini() {}
  // Switches the loaded tool's length offset off / on again (ADEM [709] / [705]); false when the
  // format has no record for it (APT: LOADTL switches it on, nothing switches it off).
  virtual bool lengthOff() { return false; }
  virtual bool lengthOn() { return false; }
  // A canned cycle's bracket written as the format's cycle (true: its records are skipped).
  virtual bool nativeCycle(const MotionRecord &) { return false; }
  virtual void closeCycle() {}
  // What the reader reads back of a written coordinate (APT: rounded to its decimals).
  virtual double readBack(double v) const { return v; }
  // ADEM's rapid mode [25] lasts until the next feed [23]; APT's RAPID is for one GOTO.
  virtual bool rapidIsModal() const = 0;
  virtual int centreDecimals() const = 0;

  void line(const std::string &text) {
    out_.line(text, "\n");
    ++lines_;
  }
  void raw(const std::string &bytes) {
    out_.raw(bytes);
    ++lines_;
  }
  bool refuse(const MotionRecord &r, const std::string &why) {
    diags_.error(r.loc, fmt::format("the {} writer cannot write this record ({}): {}", format(), why, printMotionRecord(r)),
                 "unsupported-code");
    errors_ = true;
    return false;
  }
  Vec3 written(const AxisVec &machine) const {
    return {readBack(machine[0] - origin_[0]), readBack(machine[1] - origin_[1]), readBack(machine[2] - origin_[2] - toolLength_)};
  }

  const Machine &machine_;
  EmitOptions opts_;
  LineSink out_;
  Diagnostics &diags_;
  uint64_t lines_ = 0;
  bool errors_ = false, ended_ = false, finished_ = false;
  Vec3 origin_{};          // the machine's G54 after its stored base frames: both readers run in it
  double toolLength_ = 0;  // what the reader's tool length offset adds on Z
  double loadedLength_ = 0;  // the length the last tool load switched on
  double sourceLength_ = 0;  // the source's tool length in force (ToolLength records)
  bool posKnown_ = false;  // the reader knows the position (a move was written since the last tool load)
  Vec3 pos_{};             // the written position as the reader reads it back
  Plane plane_ = Plane::XY;
  // Feeds: the programmed value and mode, and what was written.
  bool haveProgrammedFeed_ = false;
  double programmedFeed_ = 0;
  int64_t feedMode_ = 0;
  std::string feedText_;
  bool inRapid_ = false;
  SkippedCycle skipped_;

private:
  void flushState();
  bool threeAxis(const MotionRecord &r);
  void ensureFeed(const MotionRecord &r);
  void move(const MotionRecord &r);
  void arcRecord(const MotionRecord &r);
  void toolChange(const MotionRecord &r);
  void followLength();

  // Spindle and coolant wait for the next event that needs them (the readers switch at once).
  double speed_ = 0;
  bool speedPending_ = false;
  int dirWanted_ = 0, dirWritten_ = 0;  // 0 stopped, 1 cw, 2 ccw
  bool spindlePending_ = false;
  bool flood_ = false, mist_ = false, floodWanted_ = false, mistWanted_ = false, coolantPending_ = false;
  MotionRecord spindleAt_;  // the record that asked for the waiting spindle state (for messages)
};

void ClWriter::start() {
  std::string name = opts_.programName;
  if (size_t slash = name.find_last_of("/\\"); slash != std::string::npos) name = name.substr(slash + 1);
  name = name.substr(0, name.find('.'));
  for (char &c : name) c = (char)std::toupper((unsigned char)c);
  header(name.empty() ? "NCC" : name,
         fmt::format("ncc: tool-tip positions in the G54 work coordinates{} of machine '{}' (mm); a tool load switches the "
                     "tool's length offset on; other work offsets, shifts and frames of the source are in the positions",
                     storedBaseFrames(machine_, false) != AxisVec{} ? " (after its stored base frames)" : "", machine_.name));
}

// The reader's tool length follows the source's where the format can switch it (ADEM [709],
// [705]: then the positions are the source's work coordinates); otherwise it stays in the
// positions. The reader's last point is then in the other length's terms: an arc writes its start.
void ClWriter::followLength() {
  auto same = [](double a, double b) { return std::fabs(a - b) < 1e-9; };
  if (same(sourceLength_, toolLength_)) return;
  if (same(sourceLength_, 0) ? lengthOff() : same(sourceLength_, loadedLength_) && lengthOn()) {
    toolLength_ = sourceLength_;
    posKnown_ = false;
  }
}

void ClWriter::flushState() {
  followLength();
  if (spindlePending_ || speedPending_) {
    if (dirWanted_ == 0) {
      if (dirWritten_ != 0) spindleOff();
      dirWritten_ = 0;
    } else if (spindlePending_ || (speedPending_ && dirWanted_ == dirWritten_)) {
      if (speed_ > 0) spindleOn(speed_, dirWanted_ == 2), dirWritten_ = dirWanted_;
      else refuse(spindleAt_, "the spindle turns without a speed; the reader needs a positive speed");
    }
    spindlePending_ = speedPending_ = false;
  }
  if (coolantPending_)
    for (const std::string &c : coolantCodes(coolantWords(), flood_, mist_, floodWanted_, mistWanted_))
      coolant(c == "off" ? nullptr : c.c_str());
  coolantPending_ = false;
}

bool ClWriter::threeAxis(const MotionRecord &r) {
  for (int i = 3; i < kAxes; ++i)
    if (r.end[i] != r.start[i])
      return refuse(r, fmt::format("the CL data written is 3-axis, and {} moves", kAxisLetters[i]));
  return true;
}

// The programmed F in its mode; under inverse time (which neither reader has) the move's
// effective feed per minute, the same path feed.
void ClWriter::ensureFeed(const MotionRecord &r) {
  bool perRev = feedMode_ == 1 && haveProgrammedFeed_;
  double v = haveProgrammedFeed_ && feedMode_ != 2 ? programmedFeed_ : r.feed;
  std::string key = clNumber(v, 4, 8) + (perRev ? "/rev" : "/min");
  if (key != feedText_ || (rapidIsModal() && inRapid_)) feed(v, perRev);
  feedText_ = key;
  inRapid_ = false;
}

void ClWriter::move(const MotionRecord &r) {
  if (!threeAxis(r)) return;
  flushState();
  Vec3 p = written(r.end);
  if (r.kind == RecordKind::Rapid) {
    rapidMove(p);
    inRapid_ = true;
  } else {
    ensureFeed(r);
    feedMove(p);
  }
  pos_ = p;
  posKnown_ = true;
}

void ClWriter::arcRecord(const MotionRecord &r) {
  if (r.tiltedArc()) {
    diags_.error(r.loc, TiltedArcCheck::message(fmt::format("the {} writer", format()).c_str(), r), "tilted-arc");
    errors_ = true;
    return;
  }
  if (std::abs(r.turns) > 1) return (void)refuse(r, "a CL arc turns once at most; a multi-turn helix has no record");
  if (!threeAxis(r)) return;
  const PlaneAxes pa = planeAxes(r.plane);
  // A CL circle has one radius: a source arc whose ends lie further apart in radius than the
  // readers' check allows (rs274 takes up to 0.5 mm) would need its centre moved.
  double rs = std::hypot(r.start[pa.a] - r.center[pa.a], r.start[pa.b] - r.center[pa.b]);
  double re = std::hypot(r.end[pa.a] - r.center[pa.a], r.end[pa.b] - r.center[pa.b]);
  if (std::fabs(rs - re) > kArcCheck)
    return (void)refuse(r, fmt::format("a CL circle has one radius; this arc starts {:.4f} and ends {:.4f} from its centre", rs, re));
  flushState();
  if (!posKnown_) {  // the readers check the arc's start: the start first (a move of length 0)
    MotionRecord to = r;
    to.kind = RecordKind::Rapid;
    to.end = r.start;
    move(to);
  }
  const bool ccw = r.turns >= 0;
  Vec3 e = written(r.end);
  Vec3 c = {r.center[0] - origin_[0], r.center[1] - origin_[1], r.center[2] - origin_[2] - toolLength_};
  double s2[2] = {pos_[pa.a], pos_[pa.b]}, e2[2] = {e[pa.a], e[pa.b]}, c2[2] = {c[pa.a], c[pa.b]};
  bool full = s2[0] == e2[0] && s2[1] == e2[1];
  if (full) {
    // Shorter than the output resolution: a full circle would be wrong, a line is within rounding.
    double os[2] = {r.start[pa.a], r.start[pa.b]}, oe[2] = {r.end[pa.a], r.end[pa.b]}, oc[2] = {r.center[pa.a], r.center[pa.b]};
    if (std::hypot(oe[0] - os[0], oe[1] - os[1]) > 1e-9 && sweepAngle(os, oe, oc, ccw) < kPi) {
      MotionRecord l = r;
      l.kind = RecordKind::Linear;
      return move(l);
    }
  }
  NumberFormat cf;
  cf.decimals = centreDecimals();
  ArcWords aw = planArc(s2, e2, c2, ccw, full, false, cf, 2 * kArcCheck * 0.9);
  double cc[2] = {s2[0] + aw.offset[0], s2[1] + aw.offset[1]};
  double radius = (std::hypot(cc[0] - s2[0], cc[1] - s2[1]) + std::hypot(cc[0] - e2[0], cc[1] - e2[1])) / 2;
  Vec3 centre = pos_;  // along the axis: the start's height
  centre[pa.a] = readBack(cc[0]);
  centre[pa.b] = readBack(cc[1]);
  Vec3 axis{};
  axis[pa.normal] = ccw ? 1 : -1;
  ensureFeed(r);
  arc(centre, axis, radius, e);
  pos_ = e;
}

void ClWriter::toolChange(const MotionRecord &r) {
  flushState();
  double length = 0;
  if (!offsetNumberLength(machine_, (int)r.ivalue, length))
    return (void)refuse(r, fmt::format("a tool load switches the length offset of tool {} on, which machine '{}' does not have", r.ivalue,
                                       machine_.name));
  const ToolData *t = machine_.findTool((int)r.ivalue);
  toolLoad((int)r.ivalue, t ? t->radius : 0);
  toolLength_ = loadedLength_ = length;
  posKnown_ = false;  // the reader's position is the last written point, in the old tool's terms
}

void ClWriter::record(const MotionRecord &r) {
  if (finished_ || ended_) return;
  if (AxisVec end; skipped_.active) {
    if (skipped_.closes(r, end)) pos_ = written(end), posKnown_ = true;
    return;
  }
  switch (r.kind) {  // an open cycle stays open over rapid moves and records that write nothing
  case RecordKind::Rapid:
  case RecordKind::CycleBegin:
  case RecordKind::CycleEnd:
  case RecordKind::Comment:
  case RecordKind::FeedRate:
  case RecordKind::FeedMode:
  case RecordKind::PathMode:
  case RecordKind::Plane:
  case RecordKind::ToolLength:
  case RecordKind::ToolSelect:
  case RecordKind::FrameChange: break;
  default: closeCycle();
  }
  if (std::string why = refusal(r); !why.empty()) return (void)refuse(r, why);
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear: move(r); break;
  case RecordKind::Arc: arcRecord(r); break;
  case RecordKind::Dwell: flushState(), dwell(r.value); break;
  case RecordKind::ToolChange: toolChange(r); break;
  case RecordKind::SpindleSpeed:
    speed_ = r.value, speedPending_ = true;
    break;
  case RecordKind::SpindleCW:
  case RecordKind::SpindleCCW:
  case RecordKind::SpindleStop:
    dirWanted_ = r.kind == RecordKind::SpindleCW ? 1 : r.kind == RecordKind::SpindleCCW ? 2 : 0;
    spindlePending_ = true;
    spindleAt_ = r;
    break;
  case RecordKind::CoolantFlood: floodWanted_ = r.ivalue != 0, coolantPending_ = true; break;
  case RecordKind::CoolantMist: mistWanted_ = r.ivalue != 0, coolantPending_ = true; break;
  case RecordKind::FeedRate: programmedFeed_ = r.value, haveProgrammedFeed_ = true; break;
  case RecordKind::FeedMode: feedMode_ = r.ivalue; break;
  case RecordKind::ToolLength: sourceLength_ = r.value; break;
  case RecordKind::Plane: plane_ = (Plane)r.ivalue; break;
  case RecordKind::Comment:
    if (opts_.comments) flushState(), comment(r.text);
    break;
  case RecordKind::Message: flushState(), comment("MSG " + r.text); break;
  case RecordKind::OptionalStop:
  case RecordKind::ProgramStop: flushState(), stop(r.kind == RecordKind::OptionalStop); break;
  case RecordKind::ProgramEnd:
    flushState();
    end();
    ended_ = true;
    break;
  case RecordKind::CycleBegin: nativeCycle(r); break;  // else the expanded moves are written
  case RecordKind::Spline: refuse(r, "the readers have no spline or curve record"); break;
  case RecordKind::Thread: refuse(r, "the readers have no thread move"); break;
  case RecordKind::Probe: refuse(r, "the readers have no probe move"); break;
  case RecordKind::SpindleOrient: refuse(r, "an oriented stop at a given angle is not read"); break;
  case RecordKind::SpindleMode:
    if (r.ivalue != 0) refuse(r, "constant surface speed is not read");
    break;
  case RecordKind::Aux: refuse(r, fmt::format("the readers have no record for {}{}", r.text.empty() ? "M" : r.text, r.ivalue)); break;
  case RecordKind::DigitalOutput:
  case RecordKind::AnalogOutput: refuse(r, "the readers have no record for LinuxCNC's digital/analog outputs"); break;
  // Nothing to write: a preselection, timing (path modes), or already in the positions (tool
  // lengths, frames; the plane goes with each arc).
  case RecordKind::ToolSelect:
  case RecordKind::ToolNumber:
  case RecordKind::PathMode:
  case RecordKind::CycleEnd:
  case RecordKind::FrameChange:
  case RecordKind::Count: break;
  }
}

bool ClWriter::finish(Diagnostics &diags) {
  if (finished_) return !errors_;
  closeCycle();
  flushState();
  if (!ended_) end();
  fini();
  finished_ = true;
  if (out_.failed()) {
    diags.error(SourceLoc{}, "error writing the emitted program", "emit");
    errors_ = true;
  }
  return !errors_;
}

// ---- APT CL text ----

class AptWriter final : public ClWriter {
public:
  using ClWriter::ClWriter;

private:
  static constexpr int kDecimals = 4;  // NX's CLSF: GOTO/10.0000,…
  const char *format() const override { return "APT CL"; }
  std::string refusal(const MotionRecord &) const override { return {}; }
  double readBack(double v) const override { return roundTo(v, kDecimals); }
  bool rapidIsModal() const override { return false; }
  int centreDecimals() const override { return kDecimals; }
  static std::string xyz(const Vec3 &p) {
    return clNumber(p[0], kDecimals, kDecimals) + "," + clNumber(p[1], kDecimals, kDecimals) + "," + clNumber(p[2], kDecimals, kDecimals);
  }
  // `$` continues a record and `$$` starts a comment; a leading `/` would make parameters.
  static std::string text(const std::string &t) {
    std::string s = sanitizeText(t, "$", "-");
    if (!s.empty() && s[0] == '/') s[0] = '-';
    return s;
  }
  void header(const std::string &name, const std::string &note) override {
    line("$$ " + text(note));
    line("PARTNO " + text(name));
    line("UNITS/MM");
  }
  void comment(const std::string &t) override { line("PPRINT " + text(t)); }
  void toolLoad(int n, double radius) override {
    line(fmt::format("LOADTL/{}", n));
    if (radius > 0) line("CUTTER/" + clNumber(2 * radius, kDecimals, 6));
  }
  void feed(double v, bool perRev) override {
    const AptFeedUnit *u = aptFind(kAptFeedUnits, [&](auto &k) { return !k.inch && k.perRev == perRev; });
    line(fmt::format("FEDRAT/{},{}", u->word, clNumber(v, kDecimals, 8)));
  }
  void rapidMove(const Vec3 &p) override {
    line("RAPID");
    line("GOTO/" + xyz(p));
  }
  void feedMove(const Vec3 &p) override { line("GOTO/" + xyz(p)); }
  void arc(const Vec3 &c, const Vec3 &axis, double radius, const Vec3 &end) override {
    line(fmt::format("CIRCLE/{},{},{},{},{}", xyz(c), clNumber(axis[0], 6, 6), clNumber(axis[1], 6, 6), clNumber(axis[2], 6, 6),
                     clNumber(radius, kDecimals, 6)));
    line("GOTO/" + xyz(end));
  }
  void spindleOn(double rpm, bool ccw) override {
    const AptSpindleWord *d = aptFind(kAptSpindleDirs, [&](auto &k) { return std::string_view(k.dir) == (ccw ? "ccw" : "cw"); });
    line(fmt::format("SPINDL/RPM,{},{}", clNumber(rpm, 0, 4), d->word));
  }
  void spindleOff() override { line("SPINDL/OFF"); }
  void coolant(const char *which) override {
    const AptCoolantWord *w = aptFind(kAptCoolants, [&](auto &k) {
      return which ? k.coolant && std::string_view(k.coolant) == which : !k.coolant;
    });
    line(std::string("COOLNT/") + w->word);
  }
  void dwell(double s) override { line("DELAY/" + clNumber(s, 1, 6)); }
  void stop(bool optional) override { line(optional ? "OPSTOP" : "STOP"); }
  void end() override { line("END"); }
  void fini() override { line("FINI"); }
  bool nativeCycle(const MotionRecord &r) override;
  void closeCycle() override {
    if (cycleOpen_.empty()) return;
    line("CYCLE/OFF");
    cycleOpen_.clear();
  }

  std::string cycleOpen_;  // the CYCLE/ record in force (empty: none)
};

// A library cycle the APT reader makes of CYCLE/DRILL or BORE (ir/AptWords.h) written back as
// that record and the GOTO to the hole's top, when its parameters are exactly what the reader
// gives: RTP = RFP + SDIS, DP below RFP, for BORE both feeds equal, in the XY plane, not under a
// rotated frame, at a feed per minute. Otherwise the expanded moves are written.
bool AptWriter::nativeCycle(const MotionRecord &r) {
  const AptCycleWord *k = aptFind(kAptCycles, [&](auto &c) { return c.entry && r.text == c.entry; });
  if (!k || !posKnown_ || plane_ != Plane::XY || (r.param("frame") && *r.param("frame") != 0)) return false;
  static const std::set<std::string_view> kAllowed = {"RTP", "RFP", "SDIS", "DP", "FFR", "RFF", "mx", "my", "mz", "frame", "wcs"};
  for (const NamedNumber &n : r.params())
    if (!kAllowed.count(n.name())) return false;
  const double *rtp = r.param("RTP"), *rfp = r.param("RFP"), *sdis = r.param("SDIS"), *dp = r.param("DP");
  const double *ffr = r.param("FFR"), *rff = r.param("RFF"), *mz = r.param("mz");
  if (!rtp || !rfp || !sdis || !dp || std::fabs(*rtp - *rfp - *sdis) > 1e-9 || *sdis < 0 || !(*rfp > *dp)) return false;
  const bool bore = std::string_view(k->word) == "BORE";
  double feed = programmedFeed_;
  if (bore) {
    if (!ffr || !rff || *ffr != *rff || !(*ffr > 0)) return false;
    feed = *ffr;
  } else if (ffr || rff || feedMode_ != 0 || !haveProgrammedFeed_ || !(feed > 0)) {
    return false;
  }
  double top = readBack(*rfp + (mz ? *mz : 0) - origin_[2] - toolLength_);
  std::string def = fmt::format("CYCLE/{},{},MMPM,{},{}", k->word, clNumber(*rfp - *dp, kDecimals, 6), clNumber(feed, kDecimals, 8),
                                clNumber(*sdis, kDecimals, 6));
  if (def != cycleOpen_) {
    closeCycle();
    line(def);
    cycleOpen_ = def;
  }
  line("GOTO/" + xyz({pos_[0], pos_[1], top}));
  skipped_.active = true;
  return true;
}

// ---- ADEM CLData: the listing, or the binary record file ----

class AdemWriter final : public ClWriter {
public:
  AdemWriter(const Machine &m, const EmitOptions &o, LineSink out, Diagnostics &d) : ClWriter(m, o, out, d) {}

private:
  const char *format() const override { return "ADEM CLData"; }
  std::string refusal(const MotionRecord &r) const override {
    if (r.kind == RecordKind::SpindleCCW) return "the spindle record [24] has no direction: the reader turns it clockwise";
    if (r.kind == RecordKind::CoolantMist && r.ivalue != 0) return "the coolant record [26] carries line 1 (flood) only";
    if (r.kind == RecordKind::Arc && r.plane != Plane::XY && !r.tiltedArc())
      return "the arc record [183] is read in the XY plane only (the manual does not say which coordinates its centre has in YZ and ZX)";
    return {};
  }
  bool rapidIsModal() const override { return true; }
  int centreDecimals() const override { return 9; }

  using Fields = std::initializer_list<std::pair<int, double>>;
  void put(int code, Fields nums, int textAt = 0, const std::string &text = {}) {
    AdemRecord rec;
    rec.code = code;
    rec.obj = obj_;
    for (auto [i, v] : nums) rec.fr[i] = AdemField{false, v, {}, {}};
    if (textAt) rec.fr[textAt] = AdemField{true, 0, text, {}};
    write(rec);
  }
  // One record, with the codec the readers use (ir/AdemRecords.h).
  void write(const AdemRecord &rec) {
    if (opts_.binary) return raw(writeAdemBinary({rec}));
    std::string l = writeAdemListing({rec});
    if (!l.empty() && l.back() == '\n') l.pop_back();
    line(l);
  }
  void header(const std::string &name, const std::string &note) override {
    put(1, {}, 3, name);
    put(582, {}, 10, note);
  }
  void comment(const std::string &t) override { put(582, {}, 10, t); }
  void toolLoad(int n, double radius) override {
    ++obj_;  // a new route object
    AdemRecord rec;
    rec.code = 35;
    rec.obj = obj_;
    for (int i = 3; i <= 18; ++i) rec.fr[i] = AdemField{false, 0, {}, {}};
    rec.fr[3].num = 1;  // a mill
    rec.fr[4].num = n;  // the pocket (ncc's reading: docs/CLDATA.md)
    if (radius > 0) rec.fr[19] = AdemField{false, 1, {}, {}}, rec.fr[20] = AdemField{false, radius, {}, {}};
    write(rec);
  }
  void feed(double v, bool perRev) override { put(23, {{3, perRev ? 2 : 1}, {4, v}}); }
  void rapidMove(const Vec3 &p) override {
    if (!inRapid_) put(25, {});
    put(181, {{3, p[0]}, {4, p[1]}, {5, p[2]}});
  }
  void feedMove(const Vec3 &p) override { put(181, {{3, p[0]}, {4, p[1]}, {5, p[2]}}); }
  void arc(const Vec3 &c, const Vec3 &axis, double radius, const Vec3 &e) override {
    put(183, {{3, e[0]}, {4, e[1]}, {5, e[2]}, {6, c[0]}, {7, c[1]}, {8, axis[2] > 0 ? radius : -radius}, {9, 1}});
  }
  void spindleOn(double rpm, bool) override { put(24, {{3, 2}, {4, rpm}}); }
  void spindleOff() override { put(701, {}); }
  void coolant(const char *which) override {
    if (which) put(26, {{3, 1}, {4, 1}});
    else put(700, {});
  }
  void dwell(double s) override { put(27, {{3, 0}, {4, s}}); }
  void stop(bool optional) override { put(optional ? 33 : 22, {}); }
  void end() override { put(4, {}); }
  bool lengthOff() override { return put(709, {}), true; }
  bool lengthOn() override { return put(705, {}), true; }

  int obj_ = 0;
};

}  // namespace

std::unique_ptr<ProgramEmitter> makeClWriter(const Machine &m, const EmitOptions &opts, LineSink out, Diagnostics &diags) {
  const char *what = opts.target == Target::Apt ? "APT CL" : "ADEM CLData";
  if (m.controller.lathe()) {
    diags.error(SourceLoc{}, fmt::format("machine '{}': the {} writer writes milling programs only", m.name, what), "unsupported-code");
    return nullptr;
  }
  if (opts.binary && opts.target != Target::Adem) {
    diags.error(SourceLoc{}, "--binary: only ADEM CLData (--to=cldata) has a binary form", "emit");
    return nullptr;
  }
  std::unique_ptr<ClWriter> w;
  if (opts.target == Target::Apt) w = std::make_unique<AptWriter>(m, opts, out, diags);
  else w = std::make_unique<AdemWriter>(m, opts, out, diags);
  w->start();
  return w;
}

}  // namespace ncc::emit::detail
