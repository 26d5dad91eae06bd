// The program emitter engine: one block buffer, modal memory and the record -> words mapping.
// Everything controller-specific comes from ControllerStyle.
#include "backends/emit/EmitterImpl.h"

namespace ncc::emit {

namespace detail {

void Emitter::badNumber(double v, const std::string &letter, const MotionRecord &r) {
  diags_.error(r.loc, "cannot write " + letter + " = " + std::to_string(v) + " in the [" + st_.section +
                          "] number format (not finite or too many digits)", "emit");
  errors_ = true;
}

bool Emitter::number(double v, WordClass c, const std::string &letter, const MotionRecord &r, std::string &out) {
  char digits[kNumberMax];
  const char *e = writeNumber(digits, v, fmt(c));
  if (!e) {
    badNumber(v, letter, r);
    return false;
  }
  out.assign(letter).append(digits, size_t(e - digits));
  return true;
}

void Emitter::writeBlock(const Words &words, int64_t sourceN) {
  if (words.empty()) return;
  std::string &line = line_;
  line.clear();
  char n[kIntegerMax + 1] = "N";
  if (st_.numbering == Numbering::Renumber) {
    if (numberedCount_++ % st_.blockEvery == 0) {
      line.assign(n, writeInteger(n + 1, nextN_, st_.blockDigits));
      nextN_ += st_.blockStep;
    }
  } else if (st_.numbering == Numbering::Source && sourceN >= 0) {
    line.assign(n, writeInteger(n + 1, sourceN, st_.blockDigits));
  }
  for (const std::string &w : words) {
    if (!line.empty()) line += st_.separator;
    line += w;
  }
  line += st_.endOfBlock;
  writeLine(line);
}

void Emitter::writeHeader() {
  for (const std::string &l : st_.programHeader) writeLine(l);
  if (!st_.unverifiedNote.empty()) comment(st_.unverifiedNote);
  // The program is named after the file: "1234.nc" becomes O1234, other names a comment.
  std::string name = opts_.programName;
  if (size_t slash = name.find_last_of("/\\"); slash != std::string::npos) name = name.substr(slash + 1);
  std::string stem = name.substr(0, name.find('.'));
  bool numeric = !stem.empty() && stem.size() <= (size_t)st_.programNumberDigits;
  for (char c : stem) numeric &= std::isdigit((unsigned char)c) != 0;
  if (st_.programNumber) {
    std::string line = "O" + formatInteger(numeric ? std::stoll(stem) : 1, st_.programNumberDigits);
    if (!numeric && !name.empty()) line += " (" + sanitizeText(name, "()", "[]") + ")";
    writeLine(line);
  } else if (!name.empty()) {
    comment(name);
  }
  for (const std::string &blk : st_.setup) writeBlock({blk}, -1);
}

void Emitter::addPending(PendingGroup g, const std::string &word, const MotionRecord &r) {
  uint32_t bit = 1u << (unsigned)g;
  if (pendingGroups_ & bit) flushPending();
  if (pending_.empty()) pendingN_ = r.blockNumber;
  pendingGroups_ |= bit;
  push(pending_, word);
}

void Emitter::flushPending() {
  // A G96 for a new limit alone (no S record follows): the surface speed again, as G96 needs S.
  if (cssNeedsS_ && !(pendingGroups_ & (1u << (unsigned)PendingGroup::Speed))) pending_.push_back(surfaceWord_);
  cssNeedsS_ = false;
  if (pendingGroups_ & (1u << (unsigned)PendingGroup::Coolant)) {
    // Coolant codes share one modal group: the first joins the block, others get their own.
    std::vector<std::string> codes = coolantCodes();
    if (!codes.empty()) pending_.push_back(codes[0]);
    writeBlock(pending_, pendingN_);
    for (size_t i = 1; i < codes.size(); ++i) writeBlock({codes[i]}, pendingN_);
    pending_.clear();
    pendingGroups_ = 0;
    pendingN_ = -1;
    return;
  }
  writeBlock(pending_, pendingN_);
  pending_.clear();
  pendingGroups_ = 0;
  pendingN_ = -1;
}

void Emitter::ensurePosition(const MotionRecord &r) {
  if (posKnown_) return;
  // The controller running the emitted program starts where the source program started.
  notePosition(r.start, kAxes);
  posKnown_ = true;
}

void Emitter::notePosition(const AxisVec &end, int axes) {
  for (int i = 0; i < axes; ++i) {
    setPosText(i, written(i, end[i]));
    pos_[i] = readBack(i, end[i]);
  }
}

void Emitter::axisWords(const AxisVec &end, Words &w, const MotionRecord &r) {
  for (int i = 0; i < kAxes; ++i) {
    const WordClass c = axisClass(i);
    const double v = written(i, end[i]);
    // A non-modal class (the passport's modal flag off) restates every axis the machine has.
    const bool modal = fmt(c).modal || !machine_.axes[i].present;
    if (modal && v == posValue_[i]) continue;  // the value of the written text: the same text
    char digits[kNumberMax];
    const char *e = writeNumber(digits, v, fmt(c));
    if (!e) {
      badNumber(v, std::string(1, kAxisLetters[i]), r);
      continue;
    }
    const std::string_view text(digits, size_t(e - digits));
    if (modal && text == posText_[i]) {
      posValue_[i] = v;  // formats to the written text too
      continue;
    }
    posText_[i].assign(text);
    posValue_[i] = v;
    pos_[i] = readBack(i, end[i]);
    w.push_back(axisWord(i) + posText_[i]);
  }
}

// Sinumerik writes the controller's axis names (a name of more than one letter with '=':
// Q1=3); ISO addresses are the letters.
std::string Emitter::axisWordOf(int axis) const {
  if (st_.target != Target::Sinumerik) return std::string(1, kAxisLetters[axis]);
  std::string name = machine_.axisName(axis);
  return name.size() > 1 ? name + "=" : name;
}

void Emitter::motionCode(Code c, Words &w) {
  const std::string &g = code(c);
  if (g == motion_ && st_.motionModal) return;
  motion_ = g;
  push(w, g);
}

void Emitter::feedWord(const MotionRecord &r, Words &w, double lengthMM) {
  // The programmed F (per minute or per revolution) when the stream carried one, the move's
  // effective feed otherwise. Inverse time: the stream's rates are mm/min, so F = 1/minutes is
  // rebuilt from the move's length the way the executor measures it.
  double f = haveProgrammedFeed_ ? programmedFeed_ : r.feed;
  if (feedMode_ == 2) f = lengthMM > 1e-9 ? r.feed / lengthMM : 1;
  std::string word;
  if (!number(f, WordClass::Feed, "F", r, word)) return;
  bool everyBlock = feedMode_ == 2 || !fmt(WordClass::Feed).modal;  // inverse time: F belongs to each block
  if (!everyBlock && word == feedText_) return;
  feedText_ = word;
  w.push_back(word);
}

void Emitter::planeWord(Plane p, Words &w) {
  if (p == plane_) return;
  plane_ = p;
  static const Code codes[] = {Code::PlaneXY, Code::PlaneZX, Code::PlaneYZ};
  push(w, code(codes[(unsigned)p]));
}

void Emitter::move(const MotionRecord &r) {
  std::vector<MotionRecord> parts;
  for (const MotionRecord &leg : rapidLegs(r)) {
    if (!incrementParts(leg, parts)) return;
    for (const MotionRecord &p : parts) moveBlock(p);
  }
}

void Emitter::moveBlock(const MotionRecord &r) {
  flushPending();
  ensurePosition(r);
  Words w;
  w.reserve(kBlockWords);
  if (r.exactStop && pathMode_ != 1) push(w, code(Code::ExactStopOnce));
  bool rapid = r.kind == RecordKind::Rapid;
  motionCode(rapid ? Code::Rapid : Code::Linear, w);
  size_t before = w.size();
  axisWords(r.end, w, r);
  if (w.size() == before) {
    // A zero-length move still is a record: restate one coordinate so it is not lost.
    int i = 0;
    while (i < kAxes - 1 && !machine_.axes[i].present) ++i;
    if (!machine_.axes[i].present) i = 0;
    w.push_back(axisWord(i) + posText_[i]);
  }
  if (!rapid) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) d2 += (r.end[i] - r.start[i]) * (r.end[i] - r.start[i]);
    feedWord(r, w, std::sqrt(d2));
  }
  writeBlock(w, r.blockNumber);
}

void Emitter::arc(const MotionRecord &r) {
  flushPending();
  ensurePosition(r);
  if (st_.arcQuadrants) return quadrantArcs(r);
  int n = r.turns == 0 ? 1 : std::abs(r.turns);
  PlaneAxes pa = planeAxes(r.plane);
  double s[2] = {r.start[pa.a], r.start[pa.b]}, e[2] = {r.end[pa.a], r.end[pa.b]};
  double c[2] = {r.center[pa.a], r.center[pa.b]};
  bool sourceFull = std::hypot(e[0] - s[0], e[1] - s[1]) < 1e-9;
  if (!st_.helixAllowed && r.end[pa.normal] != r.start[pa.normal] &&
      refused(r, "helix", "the target has no helical interpolation: an arc moves two axes of its plane only"))
    return;
  if (st_.maxArcSweep > 0) {
    arcPieces(r, n, sourceFull);
    return;
  }
  if (n == 1 || st_.helixTurns == HelixTurns::Word) {
    arcBlock(r, r.end, n, sourceFull);
    return;
  }
  // Split: n-1 full circles back to the start point, then the last arc. Axes off the plane move
  // in proportion to the angle, as on the original helix.
  double last = sourceFull ? 2 * kPi : sweepAngle(s, e, c, r.turns > 0);
  double total = (n - 1) * 2 * kPi + last;
  for (int k = 1; k < n; ++k) {
    AxisVec mid = r.end;
    double t = k * 2 * kPi / total;
    for (int i = 0; i < kAxes; ++i) mid[i] = r.start[i] + (r.end[i] - r.start[i]) * t;
    mid[pa.a] = r.start[pa.a];
    mid[pa.b] = r.start[pa.b];
    arcBlock(r, mid, 1, true);
  }
  arcBlock(r, r.end, 1, sourceFull);
}

// Equal pieces of at most maxArcSweep degrees on the source's circle (the start's radius), the
// last ending at the record's end: the same path, for targets whose arc words cannot say more
// (NC-200: a full circle, the sign of R beyond a half circle).
void Emitter::arcPieces(const MotionRecord &r, int turns, bool sourceFull) {
  PlaneAxes pa = planeAxes(r.plane);
  double s[2] = {r.start[pa.a], r.start[pa.b]}, e[2] = {r.end[pa.a], r.end[pa.b]};
  double c[2] = {r.center[pa.a], r.center[pa.b]};
  const bool ccw = r.turns >= 0;
  const double total = (turns - 1) * 2 * kPi + (sourceFull ? 2 * kPi : sweepAngle(s, e, c, ccw));
  const int pieces = std::max(1, (int)std::ceil(total / (st_.maxArcSweep * kPi / 180) - 1e-9));
  const double radius = std::hypot(s[0] - c[0], s[1] - c[1]), a0 = std::atan2(s[1] - c[1], s[0] - c[0]);
  for (int k = 1; k < pieces; ++k) {
    AxisVec mid = r.end;
    for (int i = 0; i < kAxes; ++i) mid[i] = r.start[i] + (r.end[i] - r.start[i]) * k / pieces;  // a helix's rise
    double a = a0 + (ccw ? 1 : -1) * total * k / pieces;
    mid[pa.a] = c[0] + radius * std::cos(a);
    mid[pa.b] = c[1] + radius * std::sin(a);
    arcBlock(r, mid, 1, false);
  }
  arcBlock(r, r.end, 1, pieces == 1 && sourceFull);
}

void Emitter::arcBlock(const MotionRecord &r, const AxisVec &end, int turns, bool sourceFull) {
  PlaneAxes pa = planeAxes(r.plane);
  double s[2] = {pos_[pa.a], pos_[pa.b]};
  double e[2] = {readBack(pa.a, end[pa.a]), readBack(pa.b, end[pa.b])};
  double c[2] = {r.center[pa.a], r.center[pa.b]};
  bool ccw = r.turns >= 0;
  bool full = s[0] == e[0] && s[1] == e[1];
  if (full && !sourceFull && turns == 1) {
    // The arc is shorter than the output resolution: a full circle would be wrong, a line is
    // within rounding of the original.
    double os[2] = {r.start[pa.a], r.start[pa.b]}, oe[2] = {r.end[pa.a], r.end[pa.b]};
    if (sweepAngle(os, oe, c, ccw) < kPi) {
      MotionRecord line = r;
      line.kind = RecordKind::Linear;
      line.end = end;
      move(line);
      return;
    }
  }
  Words w;
  w.reserve(kBlockWords);
  double startNormal = pos_[pa.normal];
  if (st_.planeOwnBlock) {  // a three-letter plane code stands alone, before the arc
    planeWord(r.plane, w);
    writeBlock(w, r.blockNumber);
    w.clear();
  }
  bool preferR = st_.arcStyle == ArcStyle::R && turns == 1;
  ArcWords aw = planArc(s, e, c, ccw, full, preferR, fmt(WordClass::Center), machine_.arcTolerance);
  // NC-200 lathes with diameters have only the R form (whether J is a diameter is not known).
  if (!aw.useRadius && st_.centerStyle == CenterStyle::AbsolutePlane && st_.xScale != 1 &&
      refused(r, "arc", preferR ? "its R form does not give the centre back within the arc tolerance after rounding"
                                : "the centre's J on a diameter axis is not known: set arc_style = r"))
    return;
  if (r.exactStop && pathMode_ != 1) push(w, code(Code::ExactStopOnce));
  planeWord(r.plane, w);
  motionCode(ccw ? Code::ArcCCW : Code::ArcCW, w);
  axisWords(end, w, r);
  std::string word;
  if (aw.useRadius) {
    if (number(aw.radius, WordClass::Center, st_.radiusWord, r, word)) w.push_back(word);
  } else if (st_.centerStyle == CenterStyle::AbsolutePlane) {
    // I on the abscissa, J on the ordinate: the centre's absolute position (rounded start plus
    // the chosen offset, both on the centre format's grid).
    for (int i = 0; i < 2; ++i)
      if (number(s[i] + aw.offset[i], WordClass::Center, i ? "J" : "I", r, word)) w.push_back(word);
  } else {
    for (int i = 0; i < 3; ++i) {
      if (i == pa.normal) continue;
      double off = i == pa.a ? aw.offset[0] : aw.offset[1];
      if (number(off, WordClass::Center, std::string(1, kCenterLetters[i]), r, word)) w.push_back(word);
    }
  }
  if (turns > 1) w.push_back(st_.turnsWord + std::to_string(turns - st_.turnsOffset));
  // Length of this piece for inverse time: every piece starts at the source arc's start.
  double os[2] = {r.start[pa.a], r.start[pa.b]}, oe[2] = {end[pa.a], end[pa.b]};
  bool pieceFull = os[0] == oe[0] && os[1] == oe[1];
  double sweep = (turns - 1) * 2 * kPi + (pieceFull ? 2 * kPi : sweepAngle(os, oe, c, ccw));
  double radius = std::hypot(os[0] - c[0], os[1] - c[1]);
  feedWord(r, w, std::hypot(sweep * radius, end[pa.normal] - startNormal));
  writeBlock(w, r.blockNumber);
}

std::string Emitter::splineRefusal(const MotionRecord &r) const {
  const SplineData &s = r.spline();
  if (st_.target != Target::ISO || machine_.controller.family != "linuxcnc")
    return "only LinuxCNC G5.2 NURBS are written: an ISO target on a machine of [controller] family \"linuxcnc\"";
  if (!s.knots.empty()) return "G5.2 has rs274's uniform knots only";
  if (s.degree < 2 || s.degree > 15) return "G5.2 has orders L 3 to 16 only";
  for (auto &p : s.points)
    if (p[2] != r.start[2]) return "G5.2 moves in X and Y only";
  if (r.end[2] != r.start[2]) return "G5.2 moves in X and Y only";
  if (feedMode_ == 2) return "rs274 gives a spline no feed rate in inverse time";
  return {};
}

void Emitter::spline(const MotionRecord &r) {
  // G5.2 X Y P<weight> [L<order>] ... G5.3; a start weight other than 1 is a G5.2 P block of its
  // own (rs274's first-point form). Both X and Y in every block (rs274 requires them).
  flushPending();
  ensurePosition(r);
  const SplineData &s = r.spline();
  NumberFormat wf = fmt(WordClass::Center);
  wf.decimals = 9;  // weights: no unit, more digits than lengths
  auto weight = [&](size_t i, Words &w) {
    std::string digits;
    double v = s.weights.empty() ? 1.0 : s.weights[i];
    if (formatNumber(v, wf, digits)) w.push_back("P" + digits);
    else badNumber(v, "P", r);
  };
  auto point = [&](const std::array<double, 3> &p, Words &w) {
    std::string word;
    for (int i = 0; i < 2; ++i)
      if (number(p[i], WordClass::Axis, std::string(1, kAxisLetters[i]), r, word)) w.push_back(word);
  };
  Words w;
  planeWord(Plane::XY, w);
  w.push_back("G5.2");
  if (!s.weights.empty() && s.weights[0] != 1) {
    weight(0, w);
    writeBlock(w, r.blockNumber);
    w.clear();
  }
  std::vector<std::array<double, 3>> pts = s.points;
  pts.push_back({r.end[0], r.end[1], r.end[2]});
  for (size_t i = 0; i < pts.size(); ++i) {
    point(pts[i], w);
    weight(i + 1, w);
    if (i == 0) {
      if (s.degree + 1 > 3) w.push_back("L" + std::to_string(s.degree + 1));
      feedWord(r, w, 0);  // the length matters in inverse time only, which splineRefusal refuses
    }
    writeBlock(w, -1);
    w.clear();
  }
  if (r.exactStop && pathMode_ != 1) push(w, code(Code::ExactStopOnce));
  w.push_back("G5.3");
  writeBlock(w, -1);
  motion_.clear();  // rs274 has no motion mode after G5.3
  notePosition(r.end, 2);
}


void Emitter::dwell(const MotionRecord &r) {
  if (code(Code::Dwell).empty() || st_.dwellWord.empty()) {
    refused(r, "dwell", "no dwell code and word are known for it: set code_dwell and dwell_word in [" + st_.section + "]");
    return;
  }
  flushPending();
  NumberFormat f = fmt(WordClass::Dwell);
  if (st_.dwellScale != 1) {  // milliseconds and the like: an integer count, never a point
    f.decimals = 0;
    f.pointOnInteger = false;
  }
  std::string digits;
  if (!formatNumber(r.value * st_.dwellScale, f, digits)) {
    badNumber(r.value, st_.dwellWord, r);
    return;
  }
  // Dwell stands alone in its block (seed 001 §2.10).
  writeBlock({code(Code::Dwell), st_.dwellWord + digits}, r.blockNumber);
}

void Emitter::comment(const std::string &text) {
  if (st_.commentStyle == CommentStyle::Paren) {
    std::string t = sanitizeText(text, "()", "[]");
    // "(MSG, ...)" would be read back as a message.
    if (t.size() >= 4 && std::toupper((unsigned char)t[0]) == 'M' && std::toupper((unsigned char)t[1]) == 'S' &&
        std::toupper((unsigned char)t[2]) == 'G' && t[3] == ',')
      t.insert(3, " ");
    writeLine("(" + t + ")");
  } else
    writeLine("; " + sanitizeText(text, "", ""));
}

void Emitter::message(const std::string &text, const MotionRecord &r) {
  if (st_.messageStyle == MessageStyle::Comment)  // no message code: the text is kept as a comment
    comment("MSG " + text);
  else if (st_.messageStyle == MessageStyle::ParenMsg)
    writeBlock({"(MSG, " + sanitizeText(text, "()", "[]") + ")"}, r.blockNumber);
  else
    writeBlock({"MSG(\"" + sanitizeText(text, "\"", "'") + "\")"}, r.blockNumber);
}

void Emitter::coolant(const MotionRecord &r, bool flood) {
  // Only the wanted state is noted here; flushPending() writes the codes, so the two "off"
  // records a single M9 produces become one M9 again.
  (flood ? floodWanted_ : mistWanted_) = r.ivalue != 0;
  if (pending_.empty() && !pendingGroups_) pendingN_ = r.blockNumber;
  pendingGroups_ |= 1u << (unsigned)PendingGroup::Coolant;
}

std::vector<std::string> Emitter::coolantCodes() { return detail::coolantCodes(st_, flood_, mist_, floodWanted_, mistWanted_); }

void Emitter::record(const MotionRecord &source) {
  if (finished_) return;
  if (!skipped_.active && frameRecord(source)) return;
  MotionRecord shifted;
  const MotionRecord &r = toWritten(source, shifted);
  source_ = &source;
  struct ForgetSource {  // the pointer is valid during this call only
    const MotionRecord *&p;
    ~ForgetSource() { p = nullptr; }
  } forgetSource{source_};
  struct AfterThread {  // the record is a thread or another motion: noted once it is written
    bool &flag;
    const MotionRecord &r;
    ~AfterThread() {
      if (isMoveRecord(r.kind)) flag = r.kind == RecordKind::Thread;
    }
  } afterThread{afterThread_, r};
  if (skipped_.active) return skipCycleRecord(r);
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear: move(r); break;
  case RecordKind::Arc:
    if (r.tiltedArc()) {
      diags_.error(r.loc, TiltedArcCheck::message(("the [" + st_.section + "] emitter").c_str(), source),
                   "tilted-arc");
      errors_ = true;
      break;
    }
    if (!refused(r, "arc", arcRefusal(r))) arc(r);
    break;
  case RecordKind::Spline:
    // Written exactly (LinuxCNC G5.2/G5.3) or refused, never as chords: those would be a silent
    // approximation.
    if (!refused(r, "spline", splineRefusal(r))) spline(r);
    break;
  case RecordKind::Thread:
    if (!refused(r, "thread", threadRefusal(r))) thread(r);
    break;
  case RecordKind::Probe:
    if (!refused(r, "probe move", probeRefusal(r))) probe(r);
    break;
  case RecordKind::Dwell: dwell(r); break;
  case RecordKind::ToolSelect:
    // An ISO lathe's T<tt><oo>: offset 00, the positions already hold the tool's offsets.
    if (latheIso() && (r.ivalue < 0 || r.ivalue > 99)) {
      diags_.error(r.loc, "the [" + st_.section + "] emitter writes lathe tools 0 to 99 (T<tt>00): " + printMotionRecord(r),
                   "unsupported-code");
      errors_ = true;
      break;
    }
    addPending(PendingGroup::Tool, "T" + formatInteger(r.ivalue, latheIso() ? 2 : st_.toolDigits) + (latheIso() ? "00" : st_.toolSuffix), r);
    break;
  case RecordKind::ToolChange:
    // The change is a block of its own, together with the T word that prepared it.
    if (pendingGroups_ & ~(1u << (unsigned)PendingGroup::Tool)) flushPending();
    addPending(PendingGroup::ToolChange, st_.toolOffsetWord, r);
    push(pending_, code(Code::ToolChange));
    flushPending();
    break;
  case RecordKind::ToolLength:  // frameRecord
  case RecordKind::ToolNumber:
    break;
  case RecordKind::SpindleSpeed: {
    std::string w;
    if (!number(r.value, WordClass::Speed, "S", r, w)) break;
    addPending(PendingGroup::Speed, w, r);
    if (cssWritten_) surfaceWord_ = w, cssNeedsS_ = false;
    break;
  }
  case RecordKind::SpindleCW: addPending(PendingGroup::Spindle, code(Code::SpindleCW), r), spindlePositioned_ = false; break;
  case RecordKind::SpindleCCW: addPending(PendingGroup::Spindle, code(Code::SpindleCCW), r), spindlePositioned_ = false; break;
  case RecordKind::SpindleStop: addPending(PendingGroup::Spindle, code(Code::SpindleStop), r), spindlePositioned_ = false; break;
  case RecordKind::SpindleOrient: spindleOrient(r); break;
  case RecordKind::SpindleMode: spindleMode(r); break;
  case RecordKind::CoolantFlood: coolant(r, true); break;
  case RecordKind::CoolantMist: coolant(r, false); break;
  case RecordKind::FeedRate:
    programmedFeed_ = r.value;
    haveProgrammedFeed_ = true;
    break;
  case RecordKind::DigitalOutput:
  case RecordKind::AnalogOutput:  // no emitter writes LinuxCNC's I/O codes yet: refused, not dropped
    diags_.error(r.loc, "the [" + st_.section + "] emitter has no code for LinuxCNC's digital/analog outputs: " +
                            printMotionRecord(r),
                 "unsupported-code");
    errors_ = true;
    break;
  case RecordKind::FeedMode: {
    static const Code codes[] = {Code::PerMinute, Code::PerRev, Code::InverseTime};
    if (r.ivalue < 0 || r.ivalue > 2 || r.ivalue == feedMode_) break;
    if (code(codes[r.ivalue]).empty()) {  // a lathe (and the NC-200) has no inverse time
      diags_.error(r.loc, "the [" + st_.section + "] emitter has no code for this feed mode" +
                              (st_.target == Target::Nc200 ? std::string(" (set its code_ key in [emit.nc200])") : " on a lathe") +
                              ": " + printMotionRecord(r),
                   "unsupported-code");
      errors_ = true;
      break;
    }
    feedMode_ = r.ivalue;
    feedText_.clear();  // a new feed mode needs a new F
    addPending(PendingGroup::FeedMode, code(codes[r.ivalue]), r);
    break;
  }
  case RecordKind::PathMode: {
    static const Code codes[] = {Code::ExactPath, Code::ExactStop, Code::Continuous};
    if (r.ivalue < 0 || r.ivalue > 2 || r.ivalue == pathMode_) break;
    pathMode_ = r.ivalue;
    addPending(PendingGroup::PathMode, code(codes[r.ivalue]), r);
    break;
  }
  case RecordKind::Plane: {
    if (r.ivalue < 0 || r.ivalue > 2) break;
    if (src_.planeXY != (r.ivalue == (int)Plane::XY)) {
      src_.planeXY = r.ivalue == (int)Plane::XY;
      frameDirty_ |= st_.target == Target::Sinumerik;
    }
    Words w;
    planeWord((Plane)r.ivalue, w);
    if (!w.empty() && st_.planeOwnBlock) flushPending(), writeBlock(w, r.blockNumber);
    else if (!w.empty()) addPending(PendingGroup::Plane, w[0], r);
    break;
  }
  case RecordKind::Comment:
    if (!opts_.comments) break;
    flushPending();
    comment(r.text);
    break;
  case RecordKind::Message:
    flushPending();
    message(r.text, r);
    break;
  case RecordKind::OptionalStop:
    flushPending();
    writeBlock({code(Code::OptionalStop)}, r.blockNumber);
    break;
  case RecordKind::ProgramStop:
    flushPending();
    writeBlock({code(Code::ProgramStop)}, r.blockNumber);
    break;
  case RecordKind::ProgramEnd:
    flushPending();
    writeBlock({code(r.ivalue == 2 ? Code::EndM2 : Code::EndM30)}, r.blockNumber);
    ended_ = true;
    break;
  case RecordKind::Aux: {
    flushPending();
    std::string letter = r.text.empty() ? "M" : r.text;
    // B is also an axis address: on a machine with a B axis the word would move it.
    if (letter == "B" && machine_.axes[(int)Axis::B].present) {
      diags_.error(r.loc, "cannot write the auxiliary function B" + std::to_string(r.ivalue) +
                              ": B is an axis of this machine", "emit");
      errors_ = true;
      break;
    }
    writeBlock({letter + std::to_string(r.ivalue)}, r.blockNumber);
    break;
  }
  case RecordKind::CycleBegin: nativeCycle(r); break;  // else the expanded moves are written
  case RecordKind::CycleEnd:
  case RecordKind::FrameChange:  // frameRecord
  case RecordKind::Count: break;
  }
}

bool Emitter::finish(Diagnostics &diags) {
  if (finished_) return !errors_;
  finished_ = true;
  flushPending();
  finishFrame();
  // A footer line repeating the end code ("M30") is not written twice; a program without an
  // end (the executor warned about it) gets one.
  auto isEnd = [&](const std::string &l) { return l == code(Code::EndM30) || l == code(Code::EndM2); };
  bool footerEnds = false;
  for (const std::string &l : st_.programFooter) footerEnds |= isEnd(l);
  if (!ended_ && !footerEnds) writeBlock({code(Code::EndM30)}, -1);
  for (const std::string &l : st_.programFooter)
    if (!(ended_ && isEnd(l))) writeLine(l);
  if (out_.failed()) {
    diags.error(SourceLoc{}, "error writing the emitted program", "emit");
    errors_ = true;
  }
  return !errors_;
}

}  // namespace detail

namespace {

using detail::Emitter;
using detail::LineSink;

std::unique_ptr<ProgramEmitter> makeEmitter(const Machine &m, const EmitOptions &opts, LineSink out,
                                            Diagnostics &diags) {
  if (opts.target == Target::Heidenhain) return detail::makeKlartext(m, opts, out, diags);
  if (opts.target == Target::Apt || opts.target == Target::Adem) return detail::makeClWriter(m, opts, out, diags);
  ControllerStyle style = defaultStyle(opts.target);
  if (!applyLathe(m, style, diags) || !applyMachineSection(m, style, diags)) return nullptr;
  auto e = std::make_unique<Emitter>(m, std::move(style), opts, out, diags);
  e->writeHeader();
  return e;
}

}  // namespace

bool targetFromName(std::string_view name, Target &out) {
  std::string l;
  for (char c : name) l += (char)std::tolower((unsigned char)c);
  if (l == "iso" || l == "fanuc") return out = Target::ISO, true;
  if (l == "sinumerik" || l == "siemens") return out = Target::Sinumerik, true;
  if (l == "heidenhain" || l == "klartext" || l == "tnc") return out = Target::Heidenhain, true;
  if (l == "apt") return out = Target::Apt, true;
  if (l == "cldata" || l == "adem") return out = Target::Adem, true;
  // Seed 003 documents the NC-100, NC-110, NC-200 and NC-210 together: one language, whose
  // features differ by software version only (docs/EMIT.md "NC-200").
  for (const char *n : {"nc200", "nc210", "nc110", "nc100", "nc-200", "nc-210", "nc-110", "nc-100"})
    if (l == n) return out = Target::Nc200, true;
  return false;
}

const char *targetName(Target t) {
  static const char *const kNames[] = {"iso", "sinumerik", "heidenhain", "apt", "adem", "nc200"};
  return kNames[(size_t)t];
}

std::unique_ptr<ProgramEmitter> ProgramEmitter::create(const Machine &m, const EmitOptions &opts,
                                                       std::string &out, Diagnostics &diags) {
  return makeEmitter(m, opts, LineSink(&out), diags);
}

std::unique_ptr<ProgramEmitter> ProgramEmitter::create(const Machine &m, const EmitOptions &opts,
                                                       std::FILE *out, Diagnostics &diags) {
  return makeEmitter(m, opts, LineSink(out), diags);
}

bool emitProgram(const Machine &machine, const EmitOptions &opts, const std::vector<MotionRecord> &records,
                 std::string &out, Diagnostics &diags) {
  auto e = ProgramEmitter::create(machine, opts, out, diags);
  if (!e) return false;
  for (const MotionRecord &r : records) e->record(r);
  return e->finish(diags);
}

}  // namespace ncc::emit
