// The Klartext writer family (Heidenhain TNC conversational programs): a Motion IR stream as
// numbered blocks `L X+10 Y-5 R0 F200`, circles about a pole `CC` + `C … DR±` (helices as polar
// `CP IPA… Z… DR±`), TOOL CALL, M functions, dwell as cycle 9, `;` comments, and the Heidenhain
// hole cycles of the source written back as CYCL DEF with their Q lines + CYCL CALL. It shares the
// word formats (WordFormat), the arc-centre choice after rounding (ArcGeometry), the controller
// table and its [emit.heidenhain] keys with the word-address writer (Emitter.cpp); what it writes
// is read back by frontend/heidenhain (docs/EMIT.md "Klartext").
#include "backends/emit/EmitterImpl.h"
#include "ir/CycleFeed.h"
#include "runtime/cycles/Library.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <set>

namespace ncc::emit::detail {

namespace {

// Hole cycles written back as CYCL DEF: their only absolute parameter is the surface Q203 (the
// others are depths and clearances relative to it, feeds, times), so the call moves into the
// output's machine coordinates by shifting Q203 alone. Titles as a TNC 640 writes them.
struct KlartextCycle {
  int number;
  const char *title;
};
const KlartextCycle kCycles[] = {
    {200, "DRILLING"},        {201, "REAMING"},      {202, "BORING"},
    {203, "UNIVERSAL DRILLING"}, {206, "TAPPING"},   {207, "RIGID TAPPING"},
    {208, "BORE MILLING"},    {209, "TAPPING W/ CHIP BRKG"}, {240, "CENTERING"},
    {204, "BACK BORING"},     {205, "UNIVERSAL PECKING"}, {241, "SINGLE-LIP D.H.DRLNG"},
    {262, "THREAD MILLING"},  {263, "THREAD MLLNG/CNTSNKG"}, {264, "THREAD DRILLNG/MLLNG"},
    {265, "HEL. THREAD DRLG/MLG"}, {267, "OUTSIDE THREAD MLLNG"},
};

// The parameter comments of the TNC's cycle forms (the line reads without them too).
const std::pair<const char *, const char *> kQComments[] = {
    {"Q200", "SET-UP CLEARANCE"}, {"Q201", "DEPTH"},          {"Q206", "FEED RATE FOR PLNGNG"},
    {"Q202", "PLUNGING DEPTH"},   {"Q210", "DWELL TIME AT TOP"}, {"Q203", "SURFACE COORDINATE"},
    {"Q204", "2ND SET-UP CLEARANCE"}, {"Q211", "DWELL TIME AT DEPTH"}, {"Q395", "DEPTH REFERENCE"},
    {"Q208", "RETRACTION FEED RATE"}, {"Q212", "DECREMENT"},  {"Q213", "BREAKS"},
    {"Q205", "MIN. PLUNGING DEPTH"}, {"Q256", "DIST FOR CHIP BRKNG"}, {"Q214", "DISENGAGING DIRECTN"},
    {"Q336", "ANGLE OF SPINDLE"},  {"Q239", "THREAD PITCH"},  {"Q343", "SELECT DIA./DEPTH"},
    {"Q344", "DIAMETER"},         {"Q334", "FEED PER REVOLUTION"}, {"Q335", "NOMINAL DIAMETER"},
    {"Q342", "ROUGHING DIAMETER"}, {"Q351", "CLIMB OR UP-CUT"}, {"Q257", "DEPTH FOR CHIP BRKNG"},
    {"Q403", "RPM FACTOR"},
    {"Q249", "DEPTH OF COUNTERBORE"}, {"Q250", "MATERIAL THICKNESS"}, {"Q251", "OFF-CENTER DISTANCE"},
    {"Q252", "TOOL EDGE HEIGHT"}, {"Q253", "F PRE-POSITIONING"}, {"Q254", "F COUNTERSINKING"},
    {"Q255", "DWELL TIME"},       {"Q258", "UPPER ADV STOP DIST"}, {"Q259", "LOWER ADV STOP DIST"},
    {"Q379", "STARTING POINT"},   {"Q355", "THREADS PER STEP"},
    {"Q207", "FEED RATE FOR MILLING"}, {"Q512", "FEED FOR APPROACH"}, {"Q356", "COUNTERSINKING DEPTH"},
    {"Q357", "CLEARANCE TO SIDE"}, {"Q358", "DEPTH AT FRONT"}, {"Q359", "OFFSET AT FRONT"},
    {"Q360", "COUNTERSINK PROCESS"}, {"Q426", "DIR. OF SPINDLE ROT."}, {"Q427", "ROT.SPEED INFEED/OUT"},
    {"Q428", "ROT. SPEED DRILLING"}, {"Q429", "COOLANT ON"},      {"Q430", "COOLANT OFF"},
    {"Q435", "DWELL DEPTH"},      {"Q401", "FEED RATE FACTOR"},
};

// M functions the Heidenhain front end reads as something else than an auxiliary function
// (spindle, coolant, stops, the end, cycle calls; M89 and above are the TNC's own): an Aux record
// with one of these numbers cannot be written as `M<n>`.
bool mHasMeaning(int64_t m) {
  static const std::set<int64_t> kMeaning = {0, 1, 2, 3, 4, 5, 7, 8, 9, 13, 14, 30};
  return m >= 89 || kMeaning.count(m) != 0;
}

// Keys of the [emit.*] table that Klartext output honours (besides the number-format keys).
const std::set<std::string> kHonoured = {
    "block_start", "block_step", "line_ending", "code_spindle_cw", "code_spindle_ccw", "code_spindle_stop",
    "code_flood_on", "code_mist_on", "code_coolant_off", "code_program_stop", "code_optional_stop",
    "code_end_m2", "code_end_m30"};
bool formatKey(const std::string &k) {
  for (const char *p : {"decimals", "trailing_zeros", "point_on_integer", "leading_zero", "plus_sign", "max_digits"})
    if (k.size() >= std::strlen(p) && k.compare(k.size() - std::strlen(p), std::string::npos, p) == 0) return true;
  return k.rfind("format.", 0) == 0;
}

constexpr double kDeg = 180 / kPi;

// Klartext signs every coordinate and parameter, zero too (formatNumber leaves 0 unsigned).
void signDigits(std::string &d) {
  if (d.empty() || (d[0] != '-' && d[0] != '+')) d.insert(d.begin(), '+');
}

}  // namespace

class Klartext final : public ProgramEmitter {
public:
  Klartext(const Machine &m, ControllerStyle style, const EmitOptions &opts, LineSink out, Diagnostics &diags)
      : machine_(m), st_(std::move(style)), opts_(opts), out_(out), diags_(diags), nextN_(st_.blockStart) {}

  void writeHeader();
  void record(const MotionRecord &r) override;
  bool finish(Diagnostics &diags) override;
  uint64_t blocksWritten() const override { return lines_; }

private:
  const NumberFormat &fmt(WordClass c) const { return st_.formats[(size_t)c]; }
  const std::string &code(Code c) const { return st_.codes[(size_t)c]; }

  void line(const std::string &text) {
    out_.line(text, st_.lineEnding);
    ++lines_;
  }
  void block(const std::string &text) {
    char n[kIntegerMax];
    block_.assign(n, writeInteger(n, nextN_, 0));
    block_ += ' ';
    block_ += text;
    line(block_);
    nextN_ += st_.blockStep;
  }
  std::string block_;  // block's buffer, reused
  // A signed Klartext number (`+0`, `+12.5`, `-3`) of class c, or false (reported).
  bool number(double v, WordClass c, const std::string &letter, const MotionRecord &r, std::string &out);
  bool refuse(const MotionRecord &r, const std::string &why);

  void flushState();
  void ensurePosition(const MotionRecord &r);
  void notePosition(const AxisVec &end);
  std::string axisWords(const AxisVec &end, const MotionRecord &r);
  std::string feedWord(const MotionRecord &r);
  void move(const MotionRecord &r);
  void arc(const MotionRecord &r);
  void dwell(const MotionRecord &r);
  void comment(const std::string &text);
  void mBlock(const std::string &m) { if (!m.empty()) block(m); }
  void aux(const MotionRecord &r);
  bool nativeCycle(const MotionRecord &r);

  const Machine &machine_;
  ControllerStyle st_;
  EmitOptions opts_;
  LineSink out_;
  Diagnostics &diags_;
  int64_t nextN_;
  uint64_t lines_ = 0;
  bool errors_ = false, ended_ = false, finished_ = false;
  std::string name_;

  // Waiting state: a TOOL CALL (number, DL) and its S, a preselected tool, the M functions.
  int64_t toolCall_ = -1, toolDef_ = -1;
  std::string speed_;
  std::vector<std::string> ms_;
  bool coolantPending_ = false;

  // Modal memory of the written program.
  bool posKnown_ = false;
  AxisVec pos_{};
  std::array<std::string, kAxes> posText_;
  // The value posText_ was formatted from (NAN: not known): an unchanged value is an unchanged
  // text, found without formatting it (as in the word-address Emitter).
  std::array<double, kAxes> posValue_ = nanAxes();
  // Whether v formats to the written text of axis i (formatted only when the value differs).
  bool writtenText(int i, double v) const {
    if (v == posValue_[i]) return true;
    char digits[kNumberMax];
    const char *e = writeNumber(digits, v, fmt(isLengthAxis(i) ? WordClass::Axis : WordClass::Rotary));
    return e ? std::string_view(digits, size_t(e - digits)) == posText_[i] : posText_[i].empty();
  }
  static AxisVec nanAxes() {
    AxisVec v;
    v.fill(NAN);
    return v;
  }
  std::string feedText_, poleText_;
  bool haveProgrammedFeed_ = false;
  double programmedFeed_ = 0;
  bool spindleOn_ = false;
  bool flood_ = false, mist_ = false, floodWanted_ = false, mistWanted_ = false;
  SkippedCycle skipped_;
  std::string cycleDef_;  // the stored cycle definition of the written program
};

bool Klartext::number(double v, WordClass c, const std::string &letter, const MotionRecord &r, std::string &out) {
  char buf[kNumberMax + 1];
  char *b = buf + 1, *e = writeNumber(b, v, fmt(c));  // room in front for signDigits's '+'
  if (!e) {
    diags_.error(r.loc, "cannot write " + letter + " = " + std::to_string(v) + " in the [" + st_.section +
                            "] number format (not finite or too many digits)", "emit");
    errors_ = true;
    return false;
  }
  if (fmt(c).plusSign && (e == b || (*b != '-' && *b != '+'))) *--b = '+';  // as signDigits
  out.assign(letter).append(b, size_t(e - b));
  return true;
}

bool Klartext::refuse(const MotionRecord &r, const std::string &why) {
  diags_.error(r.loc, "the [" + st_.section + "] emitter cannot write this record (" + why + "): " + printMotionRecord(r),
               "unsupported-code");
  errors_ = true;
  return false;
}

void Klartext::writeHeader() {
  // The program's name: the file's stem, in the characters a TNC file name takes.
  std::string name = opts_.programName;
  if (size_t slash = name.find_last_of("/\\"); slash != std::string::npos) name = name.substr(slash + 1);
  name = name.substr(0, name.find('.'));
  for (char &c : name)
    if (!std::isalnum((unsigned char)c) && c != '_' && c != '-') c = '_';
  name_ = name.empty() ? "NCC" : name;
  block("BEGIN PGM " + name_ + " MM");
  // Motion IR is in machine coordinates with the tool lengths in them (docs/EMIT.md "Klartext").
  block("; ncc: machine coordinates, tool lengths included (TOOL CALL DL cancels the table's)");
  // The TNC runs the program in its preset (the machine's G54) and, on a machine with stored
  // Sinumerik base frames, after them (startFrame): cycle 7 moves the datum back to machine zero,
  // so the coordinates below are the machine's. Cycle 7 shifts X Y Z only.
  const AxisVec preset = startFrame(machine_);
  for (int i = 3; i < kAxes; ++i)
    if (preset[i] != 0 && machine_.axes[i].present) {
      diags_.error({}, fmt::format("machine '{}' starts a program with axis {} shifted by {} (its G54 and base frames): "
                                   "cycle 7 cannot take it back, so the Klartext positions would run shifted",
                                   machine_.name, machine_.axisName(i), preset[i]),
                   "unsupported-code");
      errors_ = true;
    }
  if (preset[0] == 0 && preset[1] == 0 && preset[2] == 0) return;
  const bool base = storedBaseFrames(machine_, false) != AxisVec{};
  block("; the datum shift cancels the preset" + std::string(base ? " and the base frames" : "") + " of machine '" +
        machine_.name + "'");
  block("CYCL DEF 7.0 DATUM SHIFT");
  MotionRecord at;
  for (int i = 0; i < 3; ++i) {
    std::string w;
    if (number(-preset[i], WordClass::Axis, std::string(1, kAxisLetters[i]), at, w))
      block("CYCL DEF 7." + std::to_string(i + 1) + " " + w);
  }
}

void Klartext::ensurePosition(const MotionRecord &r) {
  if (posKnown_) return;
  notePosition(r.start);  // the target starts where the source started
  posKnown_ = true;
}

void Klartext::notePosition(const AxisVec &end) {
  for (int i = 0; i < kAxes; ++i) {
    WordClass c = isLengthAxis(i) ? WordClass::Axis : WordClass::Rotary;
    if (end[i] != posValue_[i]) posValue_[i] = formatNumber(end[i], fmt(c), posText_[i]) ? end[i] : NAN;
    pos_[i] = roundTo(end[i], fmt(c).decimals);
  }
}

std::string Klartext::axisWords(const AxisVec &end, const MotionRecord &r) {
  std::string words;
  for (int i = 0; i < kAxes; ++i) {
    if (end[i] == posValue_[i]) continue;  // the value of the written text: the same text
    WordClass c = isLengthAxis(i) ? WordClass::Axis : WordClass::Rotary;
    char digits[kNumberMax];
    const char *e = writeNumber(digits, end[i], fmt(c));
    if (!e) {
      std::string w;
      number(end[i], c, std::string(1, kAxisLetters[i]), r, w);  // reports it
      continue;
    }
    const std::string_view text(digits, size_t(e - digits));
    posValue_[i] = end[i];
    if (text == posText_[i]) continue;
    posText_[i].assign(text);
    pos_[i] = roundTo(end[i], fmt(c).decimals);
    words += ' ';
    words += kAxisLetters[i];
    if (fmt(c).plusSign && text[0] != '-' && text[0] != '+') words += '+';  // as number() signs it
    words += text;
  }
  return words;
}

// F is modal in Klartext (FMAX is for its block only): written when it changes. The programmed F
// when the stream carried one, else the move's effective feed.
std::string Klartext::feedWord(const MotionRecord &r) {
  std::string w;
  if (!number(haveProgrammedFeed_ ? programmedFeed_ : r.feed, WordClass::Feed, "F", r, w) || w == feedText_) return {};
  feedText_ = w;
  return " " + w;
}

// State waiting for the next block: TOOL CALL with its S (or TOOL CALL Z S for a new speed), a
// preselected tool (TOOL DEF), then the M functions of spindle and coolant in one block.
void Klartext::flushState() {
  if (toolCall_ >= 0) {
    std::string text = "TOOL CALL " + std::to_string(toolCall_) + " Z";
    if (!speed_.empty()) text += " " + speed_;
    // The front end adds the tool table's length; the positions hold it already.
    const ToolData *t = machine_.findTool((int)toolCall_);
    if (t && t->length != 0) {
      std::string dl;
      MotionRecord at;
      if (number(-t->length, WordClass::Axis, "DL", at, dl)) text += " " + dl;
    }
    block(text);
  } else if (!speed_.empty()) {
    block("TOOL CALL Z " + speed_);
  }
  if (toolDef_ >= 0) block("TOOL DEF " + std::to_string(toolDef_));
  if (coolantPending_)
    for (const std::string &c : coolantCodes(st_, flood_, mist_, floodWanted_, mistWanted_)) ms_.push_back(c);
  std::string m;
  for (const std::string &c : ms_) m += (m.empty() ? "" : " ") + c;
  mBlock(m);
  toolCall_ = toolDef_ = -1;
  speed_.clear();
  ms_.clear();
  coolantPending_ = false;
}

void Klartext::move(const MotionRecord &r) {
  flushState();
  ensurePosition(r);
  std::string text = "L" + axisWords(r.end, r);
  if (text == "L") {  // a zero-length move is still a record: restate one coordinate
    int i = 0;
    while (i < kAxes - 1 && !machine_.axes[i].present) ++i;
    std::string w;
    if (number(pos_[i], isLengthAxis(i) ? WordClass::Axis : WordClass::Rotary, std::string(1, kAxisLetters[i]), r, w))
      text += " " + w;
  }
  text += " R0";  // the stream's path is the tool centre's: no radius compensation
  text += r.kind == RecordKind::Rapid ? " FMAX" : feedWord(r);
  block(text);
}

void Klartext::arc(const MotionRecord &r) {
  if (r.tiltedArc()) {
    diags_.error(r.loc, TiltedArcCheck::message(("the [" + st_.section + "] emitter").c_str(), r), "tilted-arc");
    errors_ = true;
    return;
  }
  // The front end reads circles in the working plane of TOOL CALL Z only, helices (CP) along Z.
  if (r.plane != Plane::XY)
    return (void)refuse(r, "Klartext circles lie in the X/Y plane of TOOL CALL Z; G18/G19 arcs are not written");
  for (int i = 3; i < kAxes; ++i)
    if (r.end[i] != r.start[i]) return (void)refuse(r, "a circle moves X, Y and Z only");
  flushState();
  ensurePosition(r);
  const bool ccw = r.turns >= 0;
  const int turns = r.turns == 0 ? 1 : std::abs(r.turns);
  double s[2] = {pos_[0], pos_[1]};
  double e[2] = {roundTo(r.end[0], fmt(WordClass::Axis).decimals), roundTo(r.end[1], fmt(WordClass::Axis).decimals)};
  double c[2] = {r.center[0], r.center[1]};
  bool full = s[0] == e[0] && s[1] == e[1];
  const bool helix = turns > 1 || !writtenText(2, r.end[2]);
  if (full && turns == 1 && !helix) {
    // Shorter than the output resolution: a full circle would be wrong, a line is within rounding.
    double os[2] = {r.start[0], r.start[1]}, oe[2] = {r.end[0], r.end[1]};
    if (std::hypot(oe[0] - os[0], oe[1] - os[1]) > 1e-9 && sweepAngle(os, oe, c, ccw) < kPi) {
      MotionRecord l = r;
      l.kind = RecordKind::Linear;
      return move(l);
    }
  }
  // A polar CP's end is rebuilt from the start's radius about the pole: the centre must then be
  // (nearly) equally far from both rounded ends, closer than the arc check asks for C.
  double tolerance = helix ? std::min(machine_.arcTolerance, 4e-4) : machine_.arcTolerance;
  ArcWords aw = planArc(s, e, c, ccw, full, false, fmt(WordClass::Center), tolerance);
  double pole[2] = {roundTo(s[0] + aw.offset[0], fmt(WordClass::Center).decimals),
                    roundTo(s[1] + aw.offset[1], fmt(WordClass::Center).decimals)};
  std::string cx, cy;
  if (!number(pole[0], WordClass::Center, "X", r, cx) || !number(pole[1], WordClass::Center, "Y", r, cy)) return;
  if (poleText_ != cx + " " + cy) block("CC " + cx + " " + cy);
  poleText_ = cx + " " + cy;
  std::string text;
  if (!helix) {
    std::string x, y;
    number(e[0], WordClass::Axis, "X", r, x);
    number(e[1], WordClass::Axis, "Y", r, y);
    text = "C " + x + " " + y;
    notePosition(r.end);
  } else {
    // CP IPA: the incremental angle counts the full turns too (the front end's P).
    double sweep = (full ? 2 * kPi : sweepAngle(s, e, pole, ccw)) + (turns - 1) * 2 * kPi;
    std::string ipa, zw;
    NumberFormat angle = fmt(WordClass::Center);
    angle.decimals = std::max(angle.decimals, 6);  // 1e-6 degrees: below 1e-5 mm at 500 mm radius
    std::string digits;
    if (!formatNumber((ccw ? 1 : -1) * sweep * kDeg, angle, digits)) return (void)refuse(r, "the angle cannot be written");
    signDigits(digits);
    number(r.end[2], WordClass::Axis, "Z", r, zw);
    text = "CP IPA" + digits + " " + zw;
    // The controller's end point lies on the start's circle about the pole: the next block
    // restates X and Y rather than trusting the rounded source end.
    double rad = std::hypot(s[0] - pole[0], s[1] - pole[1]);
    double a = std::atan2(s[1] - pole[1], s[0] - pole[0]) + (ccw ? 1 : -1) * sweep;
    notePosition(r.end);
    pos_[0] = pole[0] + rad * std::cos(a);
    pos_[1] = pole[1] + rad * std::sin(a);
    posText_[0].clear(), posValue_[0] = NAN;
    posText_[1].clear(), posValue_[1] = NAN;
  }
  text += ccw ? " DR+" : " DR-";
  text += feedWord(r);
  block(text);
}

void Klartext::dwell(const MotionRecord &r) {
  flushState();
  std::string t;
  if (!formatNumber(r.value, fmt(WordClass::Dwell), t)) {
    number(r.value, WordClass::Dwell, "", r, t);  // reports it
    return;
  }
  block("CYCL DEF 9.0 DWELL TIME");
  block("CYCL DEF 9.1 DWELL " + t);
}

void Klartext::comment(const std::string &text) {
  // `;` runs to the line's end; a trailing `~` would join the next line to the block.
  std::string t = sanitizeText(text, "~", "-");
  block(t.empty() ? ";" : "; " + t);
}

void Klartext::aux(const MotionRecord &r) {
  std::string letter = r.text.empty() ? "M" : r.text;
  if (letter != "M") return (void)refuse(r, "Klartext has no " + letter + " functions");
  // The TNC's M6 stops the spindle before the machine's tool change: only where it already stands.
  if (r.ivalue == 6 ? spindleOn_ : mHasMeaning(r.ivalue))
    return (void)refuse(r, "the TNC reads M" + std::to_string(r.ivalue) + " as a function of its own");
  flushState();
  block("M" + std::to_string(r.ivalue));
}

// A Heidenhain hole cycle's bracket (cycle_begin "hei.200" …, the front end's CYCL CALL or M99)
// written back as CYCL DEF + CYCL CALL at the current position; its records are skipped, the
// re-read call makes them again. Not under a rotation, scaling or mirror (frame=1), not for
// patterns, not before the position is known.
bool Klartext::nativeCycle(const MotionRecord &r) {
  if (r.param("frame") || !posKnown_ || r.text.find_first_of("+|") != std::string::npos) return false;
  if (r.text.rfind("hei.", 0) != 0) return false;
  const KlartextCycle *kc = nullptr;
  for (const KlartextCycle &k : kCycles)
    if (r.text == "hei." + std::to_string(k.number)) kc = &k;
  const CycleDef *d = kc ? findCycle(r.text) : nullptr;
  if (!d) return false;
  std::vector<std::string> lines;
  NumberFormat f = fmt(WordClass::Center);
  f.decimals = 6;  // parameters keep more digits than the axes: depths, angles, feeds
  for (std::string_view name : cycleParamNames(*d)) {
    const double *v = r.param(std::string(name));
    if (!v) continue;  // the library defaults it, as on the re-read
    double value = *v;
    if (name == "Q203") {  // the surface: into machine coordinates
      const double *mz = r.param("mz");
      value += mz ? *mz : 0;
    }
    std::string digits = "FMAX";  // a feed of FMAX (ir/CycleFeed.h) is written as the keyword
    if (value != cyclefeed::kRapid) {
      if (!formatNumber(value, f, digits)) return false;
      signDigits(digits);
    }
    std::string l = "  " + std::string(name) + "=" + digits;
    for (auto &[q, what] : kQComments)
      if (name == q) l += " ;" + std::string(what);
    lines.push_back(l);
  }
  flushState();
  // The definition stays stored (cycles 7 and 9, DEF-active, do not replace it): written again
  // only when it changes.
  std::string def = std::to_string(kc->number);
  for (const std::string &l : lines) def += l;
  if (def != cycleDef_) {
    block("CYCL DEF " + std::to_string(kc->number) + " " + kc->title + (lines.empty() ? "" : " ~"));
    for (size_t i = 0; i < lines.size(); ++i) line(lines[i] + (i + 1 < lines.size() ? " ~" : ""));
    cycleDef_ = def;
  }
  block("CYCL CALL");
  skipped_.active = true;
  return true;
}

void Klartext::record(const MotionRecord &r) {
  if (finished_) return;
  if (AxisVec end; skipped_.active) {
    if (skipped_.closes(r, end)) notePosition(end);
    return;
  }
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear: move(r); break;
  case RecordKind::Arc: arc(r); break;
  case RecordKind::Spline: refuse(r, "Klartext splines (SPL) are not read by ncc; chords would approximate"); break;
  case RecordKind::Thread: refuse(r, "Klartext has no thread move (threads are cycles)"); break;
  case RecordKind::Probe: refuse(r, "touch-probe cycles are not written"); break;
  case RecordKind::SpindleOrient: refuse(r, "oriented spindle stops are not written"); break;
  case RecordKind::SpindleMode:
    if (r.ivalue != 0) refuse(r, "constant surface speed is not written");
    break;
  case RecordKind::DigitalOutput:
  case RecordKind::AnalogOutput: refuse(r, "Klartext has no code for LinuxCNC's digital/analog outputs"); break;
  case RecordKind::FeedMode:
    if (r.ivalue != 0) refuse(r, "the front end reads feeds per minute only (FU/FZ are not read)");
    break;
  case RecordKind::Dwell: dwell(r); break;
  case RecordKind::ToolSelect:
    if (toolDef_ >= 0 || toolCall_ >= 0) flushState();
    toolDef_ = r.ivalue;
    break;
  case RecordKind::ToolChange:
    if (toolCall_ >= 0 || !speed_.empty() || !ms_.empty() || coolantPending_) flushState();
    toolCall_ = r.ivalue;
    toolDef_ = -1;
    break;
  case RecordKind::SpindleSpeed: {
    if (!speed_.empty()) flushState();
    std::string w;
    if (formatNumber(r.value, fmt(WordClass::Speed), w)) speed_ = "S" + w;
    else number(r.value, WordClass::Speed, "S", r, w);  // reports it
    break;
  }
  case RecordKind::SpindleCW:
  case RecordKind::SpindleCCW:
    // The TNC runs M3/M4 at the start of a block and M5 at its end: a stop before a start (a
    // boring cycle's reversal) gets a block of its own, or the spindle would end up stopped.
    if (std::find(ms_.begin(), ms_.end(), code(Code::SpindleStop)) != ms_.end()) flushState();
    ms_.push_back(code(r.kind == RecordKind::SpindleCW ? Code::SpindleCW : Code::SpindleCCW)), spindleOn_ = true;
    break;
  case RecordKind::SpindleStop: ms_.push_back(code(Code::SpindleStop)), spindleOn_ = false; break;
  case RecordKind::CoolantFlood: floodWanted_ = r.ivalue != 0, coolantPending_ = true; break;
  case RecordKind::CoolantMist: mistWanted_ = r.ivalue != 0, coolantPending_ = true; break;
  case RecordKind::FeedRate:
    programmedFeed_ = r.value;
    haveProgrammedFeed_ = true;
    break;
  case RecordKind::Comment:
    if (!opts_.comments) break;
    flushState();
    comment(r.text);
    break;
  case RecordKind::Message:  // Klartext has no message block ncc reads: kept as a comment
    flushState();
    comment("MSG " + r.text);
    break;
  case RecordKind::OptionalStop: flushState(), mBlock(code(Code::OptionalStop)); break;
  case RecordKind::ProgramStop: flushState(), mBlock(code(Code::ProgramStop)); break;
  case RecordKind::ProgramEnd:
    flushState();
    mBlock(code(r.ivalue == 2 ? Code::EndM2 : Code::EndM30));
    ended_ = true;
    break;
  case RecordKind::Aux: aux(r); break;
  case RecordKind::CycleBegin: nativeCycle(r); break;  // else the expanded moves are written
  // Not written: timing only (path modes, exact stops), no motion (planes: arcs check theirs),
  // or already in the positions (tool lengths, frames).
  case RecordKind::PathMode:
  case RecordKind::Plane:
  case RecordKind::ToolLength:
  case RecordKind::ToolNumber:
  case RecordKind::CycleEnd:
  case RecordKind::FrameChange:
  case RecordKind::Count: break;
  }
}

bool Klartext::finish(Diagnostics &diags) {
  if (finished_) return !errors_;
  finished_ = true;
  flushState();
  block("END PGM " + name_ + " MM");  // reaching END PGM ends the run as M2 does
  if (out_.failed()) {
    diags.error(SourceLoc{}, "error writing the emitted program", "emit");
    errors_ = true;
  }
  return !errors_;
}

std::unique_ptr<ProgramEmitter> makeKlartext(const Machine &m, const EmitOptions &opts, LineSink out,
                                             Diagnostics &diags) {
  ControllerStyle style = defaultStyle(Target::Heidenhain);
  if (m.controller.lathe()) {
    diags.error(SourceLoc{}, "machine '" + m.name + "': the [emit.heidenhain] emitter writes milling programs only", "unsupported-code");
    return nullptr;
  }
  if (!applyMachineSection(m, style, diags)) return nullptr;
  for (NumberFormat &f : style.formats) f.discrete = false, f.modal = true;  // not Klartext's: warned below
  if (auto sec = m.sections.find(style.section); sec != m.sections.end())
    for (const auto &kv : sec->second)
      if (!kHonoured.count(kv.first) && !formatKey(kv.first))
        diags.warning(SourceLoc{}, "machine '" + m.name + "' [" + style.section + "] " + kv.first +
                                       ": has no effect on Klartext output");
  auto e = std::make_unique<Klartext>(m, std::move(style), opts, out, diags);
  e->writeHeader();
  return e;
}

}  // namespace ncc::emit::detail
