#include "frontend/iso/LowerBlock.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>

namespace ncc::iso {

static const char kAxes[] = "XYZABCUVW";
static const char kMoveWords[] = "XYZABCUVW@^";  // words that make a block a move

// G codes that mean something else in RS274NGC than in the Fanuc table and are not lowered yet.
static const char *rs274Meaning(int32_t code10) {
  switch (code10) {
  case 870: return "RS274NGC back boring with I J K";
  case 160: case 500: case 510: case 511: case 660: case 680: case 2910: return "not an RS274NGC code";
  default: return nullptr;
  }
}

std::string gName(int32_t code10) {
  return code10 % 10 ? fmt::format("G{}.{}", code10 / 10, code10 % 10) : fmt::format("G{}", code10 / 10);
}

BlockLowerer::BlockLowerer(const IsoOptions &opts, Flavour flavour, Diagnostics &diags)
    : codeCalls_(opts.codeCalls), diags_(&diags), flavour_(flavour), axesScaleEnable_(opts.axesScaleEnable),
      lathe_(opts.lathe && flavour == Flavour::Fanuc), auxiliaryB_(opts.auxiliaryB && flavour == Flavour::Fanuc), system_(opts.latheSystem), scaleWeighting_(opts.scaleWeighting) {
  if (opts.decimalMode == "calculator") decimal_ = 0;
  else if (opts.decimalMode == "is-b") decimal_ = 1;
  else if (opts.decimalMode == "is-c") decimal_ = 2;
  else decimal_ = -1;
  for (ModeValue m : opts.startup) {
    ModeGroup g = modeValueInfo(m).group;
    if (g == ModeGroup::Units) units_ = m;
    else if (g == ModeGroup::FeedMode) feedMode_ = m;
    else if (g == ModeGroup::Motion) motion_ = m;
  }
  if (isPathMotion(motion_)) pathMotion_ = motion_;
}

Op BlockLowerer::blockOp(const ParsedBlock &b) const {
  Op op(OpKind::Block, b.loc);
  if (b.n >= 0) op.set("n", Expr::number((double)b.n, ir::Type::Int, b.loc));
  if (b.skip >= 0) op.set("skip", Expr::number(b.skip, ir::Type::Int, b.loc));
  return op;
}

// LinuxCNC's parameter substitution in DEBUG/PRINT/ABORT texts: `#123` and `#<name>` become
// the parameter's value (a `concat` the engines format at run time); the rest stays text.
static ExprPtr substituted(const std::string &text, SourceLoc loc, Flavour flavour, Diagnostics &diags) {
  ExprPtr out;
  std::string lit;
  auto append = [&](ExprPtr e) { out = out ? Expr::binary(ir::OpCode::Concat, std::move(out), std::move(e), loc) : std::move(e); };
  auto flush = [&] {
    if (!lit.empty()) append(Expr::string(lit, loc));
    lit.clear();
  };
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '#' && i + 1 < text.size() && std::isdigit((unsigned char)text[i + 1])) {
      size_t j = i + 1;
      while (j < text.size() && std::isdigit((unsigned char)text[j])) ++j;
      flush();
      std::string err;
      double n = std::stod(text.substr(i + 1, j - i - 1));
      ExprPtr p = n == 0 ? Expr::vacant(loc) : numberedParameter(paramMapFor(flavour, OffsetMemory::None, false), n > 1e9 ? 1000000000L : (long)n, loc, err);  // rs274 texts
      if (!p) {
        diags.error(loc, err, "unsupported-code");
        p = Expr::string("", loc);
      }
      append(std::move(p));
      i = j - 1;
    } else if (text[i] == '#' && i + 1 < text.size() && text[i + 1] == '<' && text.find('>', i) != std::string::npos) {
      size_t close = text.find('>', i);
      if (ExprPtr p = namedParameter(std::string_view(text).substr(i + 2, close - i - 2), loc)) {
        flush();
        append(std::move(p));
      } else {
        lit += "######";  // rs274 prints an empty name as an unknown parameter
      }
      i = close;
    } else {
      lit.push_back(text[i]);
    }
  }
  flush();
  return out ? std::move(out) : Expr::string("", loc);
}

void BlockLowerer::lowerComments(const ParsedBlock &b, Region &out) {
  for (auto &c : b.comments) {
    Op op(c.message ? OpKind::Message : OpKind::Comment, c.loc);
    bool substitutes = c.message && std::string_view(c.kind) != "msg";
    op.set("text", substitutes ? substituted(c.text, c.loc, flavour_, *diags_) : Expr::string(c.text, c.loc));
    if (substitutes) op.set("kind", Expr::symbol(c.kind, c.loc));
    out.push_back(std::move(op));
  }
}

// The table entry of a constant G word (the flavour's tables, the lathe's system); null when an
// error was reported: unknown, unsupported, or a code whose LinuxCNC meaning ncc does not lower.
const GCodeInfo *BlockLowerer::Block::lookupG(const IsoWord &w) {
  const GCodeInfo *gi = nullptr;
  if (w.value >= 0 && w.value < 100000) {  // range first: llround of huge values is undefined
    double t = w.value * 10;
    long long c10 = std::llround(t);
    if (std::fabs(t - (double)c10) < 1e-6) gi = L.lathe_ ? findTurningGCode((int32_t)c10, L.system_) : findGCode((int32_t)c10);
    if (!gi && L.lathe_ && std::fabs(t - (double)c10) < 1e-6 && findGCode((int32_t)c10)) {
      L.diags_->error(w.loc, fmt::format("{} is not a turning G code (808D G-code system {})", gName((int32_t)c10), L.system_),
                     "unknown-code");
      return nullptr;
    }
  }
  if (gi && L.flavour_ != Flavour::RS274 && (gi->code10 == 70 || gi->code10 == 80))
    gi = nullptr;  // LinuxCNC's lathe diameter/radius modes; no such code in the 808D table
  if (L.flavour_ == Flavour::RS274 && w.value >= 0 && w.value < 100000)  // also codes only rs274 has (G33.1)
    if (const GCodeInfo *r = findRs274GCode((int32_t)std::llround(w.value * 10));
        r && std::fabs(w.value * 10 - r->code10) < 1e-6)
      gi = r;
  if (!gi) {
    L.diags_->error(w.loc, fmt::format("unknown G code G{}", w.value), "unknown-code");
    return nullptr;
  }
  // Codes whose LinuxCNC meaning differs from Fanuc's and that are not lowered: G76 threading.
  if (const char *what = L.flavour_ == Flavour::RS274 ? rs274Meaning(gi->code10) : nullptr) {
    L.diags_->error(w.loc, fmt::format("{} ({}) is not supported", gName(gi->code10), what),
                   "unsupported-code");
    return nullptr;
  }
  if (gi->kind == GKind::Unsupported) {
    L.diags_->error(w.loc, fmt::format("{} ({}) is not supported", gName(gi->code10), gi->what),
                 "unsupported-code");
    return nullptr;
  }
  return gi;
}

bool BlockLowerer::Block::classify() {
  bool ok = true;
  macroCall = false;  // G65, G66: every other address is an argument (M too)
  for (auto &w : b.words)
    if (w.letter == 'G' && !w.expr && (w.value == 65 || w.value == 66)) macroCall = true;

  for (auto &w : b.words) {
    if (w.letter == 'G') {
      if (w.expr) {
        L.diags_->error(w.loc, "a G code must be a number", "unknown-code");
        ok = false;
        continue;
      }
      const GCodeInfo *gi = L.cachedGCode(w.value);
      if (!gi && !(gi = lookupG(w))) {
        ok = false;
        continue;
      }
      L.cacheGCode(w.value, gi);
      GUse &slot = gs[(size_t)gi->group];
      if (!(groups & (1u << (unsigned)gi->group))) slot = {};  // not cleared per block (LowerBlock.h)
      // Fanuc/808D keep the canned cycles in their own group (09), so `G80 G0` is legal there:
      // the group-01 code ends the cycle anyway. A cycle with a group-01 code is not
      // (ISO-CYM-15); RS274NGC has both in one group and rejects either pair.
      if (slot.info && L.flavour_ != Flavour::RS274 && gi->group == GGroup::Motion) {
        auto plainMotion = [](const GCodeInfo *g) { return !isCycleMotion(g->mode) && g->code10 != 800; };
        if (slot.info->code10 == 800 && plainMotion(gi)) {
          slot = {gi, &w};
          groups |= 1u << (unsigned)gi->group;
          continue;
        }
        if (gi->code10 == 800 && plainMotion(slot.info)) continue;
        if (plainMotion(gi) != plainMotion(slot.info)) {
          L.diags_->error(w.loc,
                         fmt::format("{} cannot be programmed in a canned cycle block with {}", gName(gi->code10),
                                     gName(slot.info->code10)),
                         "modal-group-conflict");
          ok = false;
          continue;
        }
      }
      if (slot.info) {
        L.diags_->error(w.loc,
                     fmt::format("two G codes from the same modal group: {} and {}", gName(slot.info->code10),
                                 gName(gi->code10)),
                     "modal-group-conflict");
        ok = false;
        continue;
      }
      slot = {gi, &w};
      groups |= 1u << (unsigned)gi->group;
      continue;
    }
    if (w.letter == 'M' && !macroCall) {
      if (w.expr || w.value < 0 || w.value != std::floor(w.value) || w.value > 99999999) {
        L.diags_->error(w.loc, "an M code must be an integer 0..99999999", "unknown-code");
        ok = false;
        continue;
      }
      MCodeInfo mi = findMCode((int32_t)w.value, L.flavour_ == Flavour::RS274);
      if (mi.kind == MKind::Unsupported) {
        L.diags_->error(w.loc, fmt::format("M{} ({}) is not supported", mi.code, mi.what), "unsupported-code");
        ok = false;
        continue;
      }
      if (nm == 5) {
        L.diags_->error(w.loc, "more than 5 M codes in one block", "too-many-m-codes");
        ok = false;
        continue;
      }
      for (int i = 0; i < nm; ++i) {
        bool coolantPair = mi.group == MGroup::Coolant && ms[i].info.group == MGroup::Coolant &&
                           mi.arg != 9 && ms[i].info.arg != 9 && mi.arg != ms[i].info.arg;  // M7 M8
        if (mi.group != MGroup::None && ms[i].info.group == mi.group && !coolantPair) {
          L.diags_->error(w.loc,
                       fmt::format("two M codes from the same modal group: M{} and M{}", ms[i].info.code, mi.code),
                       "modal-group-conflict");
          ok = false;
        }
      }
      ms[nm++] = {mi, &w};
      continue;
    }
    if ((w.letter < 'A' || w.letter > 'Z') && w.letter != '@' && w.letter != '^') continue;
    bool argSetII = macroCall && (w.letter == 'I' || w.letter == 'J' || w.letter == 'K');
    if (bw.get(w.letter) && !argSetII) {
      L.diags_->error(w.loc, fmt::format("two {} words in one block", w.letter), "duplicate-word");
      ok = false;
      continue;
    }
    if (!bw.get(w.letter)) bw.w[Words::slot(w.letter)] = &w;
    bw.present |= Words::bit(w.letter);
  }
  return ok;
}

// Feed mode, F, S, T, M6, spindle, coolant, dwell, plane, units, compensation, work offset,
// path mode, distance, return level (the first part of the rs274 order).
// LinuxCNC M19 R<angle 0..360> P<0 cw, 1 ccw, 2 shortest> Q<seconds to wait>. rs274 orients only
// when R or P is given (a bare M19 or M19 Q issues no orientation): an error here, not a no-op.
bool BlockLowerer::Block::orientWords(Op &op, SourceLoc loc) {
  if (!bw.has('R') && !bw.has('P')) {
    L.diags_->error(loc, "M19 needs R (the angle) or P (the direction): LinuxCNC does not orient the spindle without them",
                   "missing-word");
    return false;
  }
  struct Check {
    char letter;
    const char *key;
    double lo, hi;
    bool integer, open;  // open: lo excluded
    const char *msg;
  };
  static const Check kChecks[] = {{'R', "angle", 0, 360, false, false, "R value must be within 0..360 with M19"},
                                  {'P', "way", 0, 2, true, false, "P value must be 0,1,or 2 with M19"},
                                  {'Q', "wait", 0, 1e9, false, true, "Q word with M19 requires a value > 0"}};
  for (const Check &c : kChecks) {
    if (!bw.has(c.letter)) continue;
    IsoWord *w = bw.get(c.letter);
    double v = w->value;
    if (!w->expr && (v < c.lo || v > c.hi || (c.open && v == c.lo) || (c.integer && v != std::floor(v)))) {
      L.diags_->error(w->loc, c.msg, "bad-command");
      return false;
    }
    if (c.letter == 'P') {
      if (w->expr) {
        L.diags_->error(w->loc, "M19 P (the direction) must be a constant 0, 1 or 2", "bad-command");
        return false;
      }
      static const char *ways[] = {"cw", "ccw", "shortest"};
      bw.used |= Words::bit('P');
      op.set(c.key, Expr::symbol(ways[(int)v], w->loc));
    } else
      op.set(c.key, take(c.letter, Scale::None));
  }
  return true;
}

// The block's own units and feed mode apply to its words.
void BlockLowerer::Block::trackModes() {
  if (auto *gi = G(GGroup::Units)) L.units_ = gi->mode;
  if (auto *gi = G(GGroup::FeedMode)) L.feedMode_ = gi->mode;
  if (auto *gi = G(GGroup::Plane)) L.plane_ = gi->mode;
  if (auto *gi = G(GGroup::Distance)) L.distance_ = gi->mode;
  if (auto *gi = G(GGroup::Polar)) L.polar_ = gi->code10 == 160;
  if (auto *gi = G(GGroup::Motion)) {
    motionBefore = L.motion_;
    L.motion_ = gi->mode;
    if (isPathMotion(L.motion_)) L.pathMotion_ = L.motion_;
    if (L.motion_ == ModeValue::CycleOff && L.flavour_ == Flavour::Fanuc) L.motion_ = L.pathMotion_;  // as the executor
  }
  if (auto *gi = G(GGroup::NonModal); gi && gi->code10 == 310) {  // G31: a skip move in this block only
    motionBefore = L.motion_;
    L.motion_ = ModeValue::Skip;
  }
}

void BlockLowerer::Block::checkFeed(const IsoWord &f) {
  if (!f.expr && f.value <= 0 && L.flavour_ == Flavour::Fanuc)  // 808D alarm 14800
    L.diags_->warning(f.loc, "path feed F must be greater than zero (808D alarm 14800)", "zero-feed");
}

// 808D ISO (ISO-LEX-11, manual L1466): G13.1 is programmed in a block of its own (block number
// and comments only). G04 (dwell-with-motion) and G68/G69 (frameOps) have their own checks, G07.1
// and G12.1 are refused as codes. G20/G21 are not held to it: the manual's own example (spec
// example 60, `G21 X100`) breaks its rule of L2063, and ncc applies a block's unit to its words.
bool BlockLowerer::Block::standAloneOk() {
  const GCodeInfo *gi = G(GGroup::Polar);
  if (L.flavour_ != Flavour::Fanuc || !gi || gi->code10 != 131) return true;
  if (!nm && !bw.present && (groups & (groups - 1)) == 0) return true;
  L.diags_->error(gs[(size_t)GGroup::Polar].word->loc,
                  fmt::format("{} must be programmed in a block of its own (no other codes or words)", gName(131)),
                  "syntax");
  return false;
}

// 808D mills (ISO-MOT-06, ISO-CS-10; L5804-5818, L6349-6378): U V W in a plane-selection block
// choose a plane with that parallel axis, and in an arc block they make the arc in such a plane.
// ncc's planes are XY, ZX and YZ only: both are errors, never an XY arc with U moving along.
bool BlockLowerer::Block::parallelAxesOk() {
  if (L.flavour_ != Flavour::Fanuc || L.lathe_ || !bw.hasAny("UVW")) return true;
  const char *what = G(GGroup::Plane) ? "a plane with a parallel axis U, V or W (G17-G19 with U V W)"
                     : L.motion_ == ModeValue::ArcCW || L.motion_ == ModeValue::ArcCCW ? "an arc in a plane with a parallel axis U, V or W"
                                        : nullptr;
  if (!what) return true;
  const IsoWord *w = bw.w[Words::slot(bw.has('U') ? 'U' : bw.has('V') ? 'V' : 'W')];
  L.diags_->error(w->loc, fmt::format("{} is not supported", what), "unsupported-code");
  return false;
}

bool BlockLowerer::Block::setup() {
  if (!standAloneOk()) return false;
  trackModes();
  if (!parallelAxesOk()) return false;
  nonModal = G(GGroup::NonModal);
  if (nonModal && nonModal->kind == GKind::MacroCall && !macroCall) nonModal = nullptr;
  // 808D: where B names no axis it is an auxiliary function, a PLC output as H1=<n> (manual
  // L2752-2760): not an axis word of the block's move.
  if (L.auxiliaryB_ && !macroCall && bw.has('B')) {
    auxB = take('B', Scale::None);
    bw.present &= ~Words::bit('B');
  }
  // In G16 X and Y are a radius and an angle; G28/G30/G92/G53/G10/G52/G04 X... would read them
  // as coordinates: an error rather than a guess (ISO-MOT-11).
  if (L.polar_ && nonModal && !macroCall && bw.hasAny("XY")) {
    L.diags_->error(gloc(GGroup::NonModal), fmt::format("{} with X or Y in G16 polar coordinates is not supported",
                                                      gName(nonModal->code10)), "unsupported-code");
    return false;
  }

  if (macroCall) {
    // G65/G66 P<program> L<count> <arguments>: other G/M codes of the block are not allowed.
    for (size_t g = 0; g < (size_t)GGroup::Count; ++g)
      if (G((GGroup)g) && gs[g].info->kind != GKind::MacroCall && gs[g].info->kind != GKind::ModalMacro) {
        L.diags_->error(gs[g].word->loc, fmt::format("{} must not share its block with other G codes", macroName()),
                       "syntax");
        return false;
      }
  }

  modeOp(GGroup::FeedMode, "feed_mode");
  if (!macroCall) {
    if (bw.has('F')) {
      IsoWord *f = bw.get('F');
      checkFeed(*f);
      emit(OpKind::Feed, f->loc).set("value", take('F', Scale::Feed));
    }
    if (!speedOp()) return false;
    if (bw.has('T') && L.lathe_) {
      if (!latheTool()) return false;
    } else if (bw.has('T')) {
      emit(OpKind::ToolSelect, bw.get('T')->loc).set("value", take('T', Scale::None));
    }
  }
  if (auto *m = findM(MKind::Io); m && !ioCode(*m)) return false;  // rs274: after T, before M6
  if (auto *m = findM(MKind::ToolChange)) {
    emit(OpKind::ToolChange, m->word->loc);
  }
  if (auto *m = findM(MKind::ToolNumber)) {  // LinuxCNC M61 Q<tool>: declares the tool in the spindle
    if (!bw.has('Q')) {
      L.diags_->error(m->word->loc, "Need non-negative Q-word to specify tool number with M61", "missing-word");
      return false;
    }
    emit(OpKind::ToolChange, m->word->loc).set("number", take('Q', Scale::None));
  }
  if (auto *m = findM(MKind::Spindle)) {
    static const char *dirs[] = {"stop", "cw", "ccw", "orient"};
    Op &op = emit(OpKind::Spindle, m->word->loc);
    op.set("dir", Expr::symbol(dirs[m->info.arg], m->word->loc));
    if (m->info.arg == 3) {
      // 808D M19 takes no words: the angle is the machine's (SD43240), reached the shortest way.
      if (L.flavour_ == Flavour::Fanuc) op.set("way", Expr::symbol("shortest", m->word->loc));
      else if (!orientWords(op, m->word->loc)) return false;
    }
  }
  if (auto *m = findM(MKind::Coolant)) {
    Op &op = emit(OpKind::Coolant, m->word->loc);
    for (int i = 0; i < nm; ++i) {
      if (ms[i].info.kind != MKind::Coolant) continue;
      int a = ms[i].info.arg;
      if (a == 7 || a == 9) op.set("mist", Expr::symbol(a == 7 ? "on" : "off", ms[i].word->loc));
      if (a == 8 || a == 9) op.set("flood", Expr::symbol(a == 8 ? "on" : "off", ms[i].word->loc));
    }
  }
  if (nonModal && nonModal->kind == GKind::Dwell) {
    SourceLoc loc = gloc(GGroup::NonModal);
    ExprPtr secs;
    if (bw.has('P')) {
      // Fanuc: P is in milliseconds unless written with a point; RS274NGC: P is seconds.
      IsoWord *p = bw.get('P');
      bw.used |= 1u << ('P' - 'A');
      if (L.flavour_ == Flavour::RS274 || (p->hasPoint && !p->expr)) secs = literal(*p, 1.0);
      else if (p->expr) secs = Expr::binary(ir::OpCode::Div, p->expr->clone(), Expr::number(1000, ir::Type::Int, p->loc), p->loc);
      else secs = Expr::number(p->value / 1000.0, ir::Type::Real, p->loc);
    } else if (L.flavour_ == Flavour::Fanuc && (bw.has('X') || bw.has('U'))) {
      // Fanuc G4 X<seconds>: the word is the dwell time, not an axis.
      secs = take(bw.has('X') ? 'X' : 'U', Scale::DwellX);
      dwellTookAxis = true;
    } else {
      L.diags_->error(loc, "G4 needs a dwell time: P (milliseconds) or X (seconds)", "missing-word");
      return false;
    }
    // 808D ISO (spec ISO-LEX-11, manual L2111): a dwell is programmed in a block of its own.
    // rs274 runs a dwell and the block's motion, the dwell first.
    if (L.flavour_ == Flavour::Fanuc && (G(GGroup::Motion) || (bw.present & ~bw.used & Words::bits(kAxes)))) {
      L.diags_->error(loc, "G4 must be programmed in a block of its own (no motion in a dwell block)",
                     "dwell-with-motion");
      return false;
    }
    emit(OpKind::Dwell, loc).set("seconds", std::move(secs));
  }
  modeOp(GGroup::Plane, "plane");
  modeOp(GGroup::Units, "units");
  if (auto *gi = G(GGroup::CutterComp)) {
    static const char *sides[] = {"off", "left", "right", "left", "right"};
    const SourceLoc gl = gloc(GGroup::CutterComp);
    if (gi->arg >= 3 && !bw.has('D')) {  // rs274 G41.1/G42.1: D is the cutter's diameter
      L.diags_->error(gl, fmt::format("G{}.1 with no D word", gi->arg == 3 ? 41 : 42), "missing-word");
      return false;
    }
    Op &op = emit(OpKind::CutterComp, gl);
    op.set("side", Expr::symbol(sides[gi->arg], gl));
    if (gi->arg >= 3) {
      op.set("radius", Expr::binary(ir::OpCode::Div, take('D', Scale::Linear), Expr::number(2, ir::Type::Int, gl), gl));
      if (bw.has('L')) op.set("orientation", take('L', Scale::None));
    } else if (gi->arg != 0 && bw.has('D') && L.lathe_) {  // the radius and tip are the T word's offset
      L.diags_->error(bw.get('D')->loc, "a lathe takes the tool nose radius from the offset of its T word (T0101), not from D",
                     "unknown-code");
      return false;
    } else if (gi->arg != 0 && bw.has('D')) {
      op.set("d", take('D', Scale::None));
    } else if (gi->arg != 0 && L.flavour_ == Flavour::RS274) {  // rs274: the loaded tool's radius
      op.set("d_default", Expr::symbol("tool", gl));
    }
  }
  if (auto *gi = G(GGroup::ToolLength)) {
    SourceLoc loc = gloc(GGroup::ToolLength);
    if (gi->arg >= 2 && !offsetToolLength(gi->arg == 3, loc)) return false;
    ExprPtr h;
    if (gi->arg >= 2) {
    } else if (gi->arg == 0) h = Expr::number(0, ir::Type::Int, loc);
    else if (bw.has('H') && L.flavour_ == Flavour::RS274 && !bw.get('H')->expr && bw.get('H')->value == 0)
      bw.used |= Words::bit('H');  // rs274 G43 H0: the tool in the spindle, as G43 alone
    else if (bw.has('H')) h = take('H', Scale::None);
    if (!h && L.flavour_ != Flavour::RS274) {
      L.diags_->error(loc, "G43 needs an H word (tool length offset number)", "missing-word");
      return false;
    }
    if (gi->arg < 2) {
      Op &op = emit(OpKind::ToolLength, loc);
      if (h) op.set("h", std::move(h));  // none: the tool in the spindle (rs274 G43 without H)
    }
  }
  int workOffset = G(GGroup::WorkOffset) ? G(GGroup::WorkOffset)->arg : 0;
  if (workOffset == 1 && L.flavour_ == Flavour::Fanuc && !nonModal && bw.has('P') && !extendedWorkOffset(workOffset))
    return false;
  if (workOffset)
    emit(OpKind::WorkOffset, gloc(GGroup::WorkOffset))
        .set("index", Expr::number(workOffset, ir::Type::Int, gloc(GGroup::WorkOffset)));
  modeOp(GGroup::PathMode, "path_mode");
  if (G(GGroup::PathMode) && G(GGroup::PathMode)->mode == ModeValue::Continuous) {
    // G64 P<path tolerance> Q<naive-CAM tolerance>; rs274: Q defaults to P.
    Op &op = out.back();
    if (bw.has('P')) op.set("tolerance", take('P', Scale::Linear));
    if (bw.has('Q')) op.set("naive_tolerance", take('Q', Scale::Linear));
  }
  modeOp(GGroup::Distance, "distance");
  modeOp(GGroup::ArcDistance, "arc_distance");
  modeOp(GGroup::Retract, "retract");
  return true;
}

// The motion mode and the move (axis words, arc or cycle words).
bool BlockLowerer::Block::motion() {
  modeOp(GGroup::Motion, "motion");
  // LinuxCNC G5/G5.1 do not change rs274's motion mode: the next block moves as before them.
  const ModeValue m = L.motion_;
  const bool bezier = m == ModeValue::SplineCubic || m == ModeValue::SplineQuadratic;
  const bool turnOneShot = m == ModeValue::ThreadMulti || isPeckMotion(m);  // G76, G74/G75
  if (bezier || turnOneShot) L.motion_ = motionBefore;  // one-shot
  if (m == ModeValue::Skip) return skipMove();
  if (m == ModeValue::NurbsEnd && G(GGroup::Motion) && bw.hasAny(kMoveWords)) {
    for (const char *c = kMoveWords; *c; ++c)
      if (bw.has(*c)) {
        L.diags_->error(bw.get(*c)->loc, "G5.3 takes no axis words (rs274 ignores them)", "unused-word");
        return false;
      }
  }
  // rs274 refuses a probe block without a target (a bare G1 is accepted).
  if (isProbeMotion(m) && G(GGroup::Motion) && !bw.hasAny(kMoveWords)) {
    L.diags_->error(gloc(GGroup::Motion), "All axes missing with motion code", "missing-word");
    return false;
  }
  if (!axesTaken) {
    bool cycle = isCycleMotion(m);
    bool arc = m == ModeValue::ArcCW || m == ModeValue::ArcCCW;
    // G5/G5.1 always move (the executor reports missing axes as rs274 does); a G5.2 block
    // may give the first point's weight alone (P).
    bool moves = bw.hasAny(kMoveWords) || (arc && bw.hasAny("IJKR")) || (cycle && bw.has('R')) ||
                 (turnOneShot && G(GGroup::Motion)) ||
                 (bezier && G(GGroup::Motion)) || (m == ModeValue::Nurbs && (G(GGroup::Motion) || bw.hasAny("PL")));
    if (moves) {
      const bool rs274 = L.flavour_ == Flavour::RS274;
      std::string_view params = cycle ? cycleParamWords(m, rs274) : "";
      if (cycle && bw.has('K') && bw.has('L')) {
        L.diags_->error(bw.get('K')->loc, "K and L both give the cycle repeat count", "duplicate-word");
        return false;
      }
      SourceLoc loc = G(GGroup::Motion) ? gloc(GGroup::Motion) : b.loc;
      Op op(OpKind::Move, loc);
      op.args.reserve((size_t)__builtin_popcount(bw.present));
      if (L.polar_) {
        if (!polarWords(op, m, loc)) return false;
      } else {
        axisWords(op, L.lathe_ ? "XYZABCV" : kAxes);
      }
      if (L.lathe_ && !latheAxisWords(op)) return false;
      // RS274NGC polar coordinates: @ radius (a length), ^ angle in degrees, about the origin.
      if (bw.has('@')) add(op, "polar_r", take('@', Scale::Linear));
      if (bw.has('^')) add(op, "polar_a", take('^', Scale::None));
      // Arcs read I J K R; cycles read R (the clearance plane) only; G5/G5.1 I J (the first
      // control point, relative to the start).
      // A lathe's G01 reads the Fanuc-T chamfer I/K and corner R without a comma (the executor's).
      const bool turnCorner = L.lathe_ && m == ModeValue::Linear && b.corner.empty();
      for (char c : std::string_view(arc                                ? "IJKR"
                                     : cycle || isTurnCycleMotion(m)    ? "R"
                                     : bezier                           ? "IJ"
                                     : turnCorner                       ? "IKR"
                                                                        : "")) {
        if (!bw.has(c)) continue;
        add(op, c, take(c, Scale::Linear));
      }
      // G5 P Q: the second control point relative to the end (lengths); G5.2 P: a weight.
      if (m == ModeValue::SplineCubic && bw.has('P')) op.set("P", take('P', Scale::Linear));
      if (bw.has('P') && (arc || m == ModeValue::Nurbs || params.find('P') != std::string_view::npos)) {
        IsoWord *p = bw.get('P');
        bw.used |= 1u << ('P' - 'A');
        // Cycle dwell: seconds (Fanuc P without a point is milliseconds); arc P = turns.
        bool ms = cycle && L.flavour_ == Flavour::Fanuc && !p->hasPoint;
        if (ms && p->expr)
          op.set("P", Expr::binary(ir::OpCode::Div, p->expr->clone(), Expr::number(1000, ir::Type::Int, p->loc), p->loc));
        else if (ms) op.set("P", Expr::number(p->value / 1000.0, ir::Type::Real, p->loc));
        else op.set("P", literal(*p, 1.0));
      }
      // Fanuc/808D G86 has no dwell word (spec table 2-22: G86 X Y Z R F K); the executor
      // follows rs274, whose G86 needs P, so the dialect's "no dwell" is written out here.
      if (m == ModeValue::BoreStop && L.flavour_ == Flavour::Fanuc && !bw.has('P') &&
          G(GGroup::Motion))
        op.set("P", Expr::number(0.0, ir::Type::Real, loc));
      if (bw.has('Q') && (m == ModeValue::SplineCubic || params.find('Q') != std::string_view::npos))
        op.set("Q", take('Q', Scale::Linear));
      if (m == ModeValue::Nurbs && bw.has('L')) op.set("L", take('L', Scale::None));  // the order
      if (isThreadMotion(m) && !threadWords(op, m)) return false;
      if (isPeckMotion(m)) peckWords(op);
      // The repeat count: K (Fanuc/808D) or L; rs274 has L only.
      if (cycle && (bw.has('L') || (bw.has('K') && !rs274))) op.set("L", take(bw.has('L') ? 'L' : 'K', Scale::None));
      // The 808D's G73 and G84/G74 steps differ from rs274's (docs/CYCLES.md "808D drilling").
      if (!rs274 && (m == ModeValue::PeckChipBreak || m == ModeValue::Tap || m == ModeValue::TapLeft))
        op.set("fanuc_cycle", Expr::number(1, ir::Type::Int, loc));
      if (!b.corner.empty() && (arc || m == ModeValue::Linear)) {
        const IsoWord &w = b.corner.front();
        op.set(w.letter == 'C' ? "chamfer" : "round", literal(w, factor(Scale::Linear)));
        cornerTaken = true;
      }
      out.push_back(std::move(op));
    }
  }
  if (!b.corner.empty() && !cornerTaken) {
    L.diags_->error(b.corner.front().loc, "a chamfer ,C or rounding ,R needs a G1, G2 or G3 move in its block",
                   "unused-word");
    return false;
  }
  return true;
}

// G31 skip (808D L4468-4523, L9398-9501; ISO-MEAS-01): one linear move at F toward X Y Z...
// that stops where the measuring input switches (the probe-results file, docs/PROBING.md) and
// latches that point (#5061-#5069); the group-01 mode of the program comes back after the block.
// The executor's probe checks apply (G40, F, feed per minute). G31 with a group-01 code, or in a
// mode other than G0-G3 (a canned cycle, a thread), is an error rather than a guess at its end.
bool BlockLowerer::Block::skipMove() {
  const SourceLoc loc = gloc(GGroup::NonModal);
  L.motion_ = motionBefore;
  auto refuse = [&](std::string msg, const char *rule) {
    L.diags_->error(loc, msg, rule);
    return false;
  };
  if (G(GGroup::Motion)) return refuse("G31 must not share its block with a group-01 code", "modal-group-conflict");
  if (!isPathMotion(motionBefore))
    return refuse(fmt::format("G31 in motion mode {} is not supported (G0-G3 only)", modeValueInfo(motionBefore).name),
                  "unsupported-code");
  if (!bw.hasAny(kMoveWords)) return refuse("G31 needs an axis word", "missing-word");
  auto mode = [&](ModeValue v) { add(emit(OpKind::Mode, loc), "motion", Expr::symbol(modeValueInfo(v).name, loc)); };
  mode(ModeValue::Skip);
  Op &op = emit(OpKind::Move, loc);
  if (L.polar_) {
    if (!polarWords(op, ModeValue::Skip, loc)) return false;
  } else {
    axisWords(op, L.lathe_ ? "XYZABCV" : kAxes);
    if (L.lathe_ && !latheAxisWords(op)) return false;
  }
  mode(motionBefore);
  return true;
}

// G16 polar coordinates (808D L9346-9395, ISO-MOT-11): in G17 the first plane axis word X is the
// radius, the second Y the angle in degrees, about the workpiece zero under G90 (a missing word
// keeps the current point's radius or angle, as the manual's N20 example computes the radius).
// They become the core's polar words (the executor's polarStep, shared with RS274NGC @ ^). What
// ncc cannot honour exactly is an error: G91 (the pole moves to the current position), the ZX
// and YZ planes, and arcs or cycles in G16 (docs/ISO-WORDS.md).
bool BlockLowerer::Block::polarWords(Op &op, ModeValue m, SourceLoc loc) {
  auto refuse = [&](const char *what) {
    L.diags_->error(loc, fmt::format("{} in G16 polar coordinates is not supported", what), "unsupported-code");
    return false;
  };
  if (L.plane_ != ModeValue::XY) return refuse(L.plane_ == ModeValue::ZX ? "the ZX plane (G18)" : "the YZ plane (G19)");
  if (L.distance_ == ModeValue::Incremental) return refuse("G91 (pole at the current position)");
  if (m != ModeValue::Rapid && m != ModeValue::Linear) return refuse(modeValueInfo(m).name);
  axisWords(op, "ZABCUVW");
  if (bw.has('X')) add(op, "polar_r", take('X', Scale::Linear));
  if (bw.has('Y')) add(op, "polar_a", take('Y', Scale::Rotary));
  return true;
}

// The words of the thread codes (docs/ISO-WORDS.md): LinuxCNC G33/G33.1 K the lead, G76 P I J
// K R Q H E L; the 808D's G32/G33 Q the start angle, G92/G78 R the taper and Q, G76 P Q R (the
// data block: P the digits m r a, Q and R lengths; with X/Z: R taper, P height, Q first cut; its
// P and Q lengths without a decimal point are least input increments, 0.001 mm, whatever the
// decimal mode: L3842-3843).
bool BlockLowerer::Block::threadWords(Op &op, ModeValue m) {
  struct W { char c; Scale s; };
  auto words = [&](std::initializer_list<W> list) {
    for (const W &w : list)
      if (bw.has(w.c)) add(op, w.c, take(w.c, w.s));
  };
  const bool rs274 = L.flavour_ == Flavour::RS274;
  switch (m) {
  case ModeValue::Thread:
  case ModeValue::RigidTap:
    if (!rs274) return words({{'Q', Scale::Rotary}}), true;
    if (!bw.has('K')) {
      L.diags_->error(b.loc, fmt::format("{} needs K (the lead per revolution)", m == ModeValue::Thread ? "G33" : "G33.1"),
                     "missing-word");
      return false;
    }
    words({{'K', Scale::Linear}});
    return true;
  case ModeValue::ThreadCycle:
    words({{'P', Scale::Linear}, {'I', Scale::Linear}, {'J', Scale::Linear}, {'K', Scale::Linear}, {'R', Scale::None},
           {'Q', Scale::None}, {'H', Scale::None}, {'E', Scale::Linear}, {'L', Scale::None}});
    return true;
  case ModeValue::ThreadSingle: words({{'R', Scale::Linear}, {'Q', Scale::Rotary}}); return true;
  case ModeValue::ThreadVariable: words({{'K', Scale::Linear}}); return true;  // G34 K the lead change
  case ModeValue::ThreadMulti:  // P and Q lengths in least increments without a point (L3842-3843)
    if (bw.hasAny("XZUW")) words({{'R', Scale::Linear}, {'P', Scale::Increment}, {'Q', Scale::Increment}});
    else words({{'P', Scale::None}, {'Q', Scale::Increment}, {'R', Scale::Linear}});
    return true;
  default: return true;
  }
}

// Stops and other M codes.
bool BlockLowerer::Block::stops() {
  if (auto *m = findM(MKind::Stop)) {
    static const char *kinds[] = {"program", "optional", "end", "end_rewind"};
    emit(OpKind::Stop, m->word->loc).set("kind", Expr::symbol(kinds[m->info.arg], m->word->loc));
  }
  for (int i = 0; i < nm; ++i)
    if (ms[i].info.kind == MKind::Aux)
      emit(OpKind::Aux, ms[i].word->loc).set("m", Expr::number(ms[i].info.code, ir::Type::Int, ms[i].word->loc));
  if (auxB) {
    SourceLoc loc = auxB->loc;
    emit(OpKind::Aux, loc).set("b", std::move(auxB));
  }
  return true;
}

// LinuxCNC M62/M63 (M64/M65) P<output>: a digital output on/off synchronized with the next move
// (immediately); M67 (M68) E<output> Q<value>: an analog output; M66 P<digital>|E<analog input>
// L0: reads an input at once (its result #5399 is not provided). All are `aux m=` with the
// channel `index` (and `value`, `input`). M66 L1-L4 wait for an input edge or level, which a
// simulation cannot know: an error, not a wait of unknown length.
bool BlockLowerer::Block::ioCode(const MUse &m) {
  const int code = m.info.code;
  const SourceLoc loc = m.word->loc;
  auto fail = [&](const std::string &msg, const char *rule) {
    L.diags_->error(loc, msg, rule);
    return false;
  };
  Op &op = emit(OpKind::Aux, loc);
  op.set("m", Expr::number(code, ir::Type::Int, loc));
  if (code <= 65) {
    if (!bw.has('P')) return fail(fmt::format("No valid P word with M{}", code), "missing-word");
    op.set("index", take('P', Scale::None));
  } else if (code == 66) {
    if (bw.has('P') == bw.has('E')) return fail("Need to have either a valid P or a valid E word with M66", "missing-word");
    if (IsoWord *l = bw.get('L')) {
      if (l->expr || l->value != 0)
        return fail("M66 L1-L4 (wait for an input) is not supported: a simulation cannot know when the input changes; "
                    "L0 reads it at once",
                    "unsupported-code");
      bw.used |= Words::bit('L');
    }
    bw.used |= Words::bit('Q') & bw.present;  // the timeout, unused by L0
    op.set("input", Expr::symbol(bw.has('P') ? "digital" : "analog", loc));
    op.set("index", take(bw.has('P') ? 'P' : 'E', Scale::None));
  } else {
    if (!bw.has('E')) return fail(fmt::format("Invalid analog index with M{}", code), "missing-word");
    if (!bw.has('Q')) return fail(fmt::format("M{} needs Q (the output value)", code), "missing-word");
    op.set("index", take('E', Scale::None));
    op.set("value", take('Q', Scale::None));
  }
  return true;
}

// Subprogram and macro calls, M99.
bool BlockLowerer::Block::callsAndReturn() {
  if (auto *m = findM(MKind::Call)) {
    SourceLoc loc = m->word->loc;
    if (!callAllowed(loc, "M98")) return false;
    if (IsoWord *p = bw.get('P'); p && p->expr) {
      // M98 P#1 / P[expr]: a computed program number, found when the call runs (a number n
      // calls O<n>; the count comes from L only).
      bw.used |= Words::bit('P');
      Op &op = emit(OpKind::Call, loc);
      op.set("callee", p->expr->clone());
      op.set("count", bw.has('L') ? take('L', Scale::None) : Expr::number(1, ir::Type::Int, loc));
      op.set("frame", Expr::symbol("shared", loc));
      return true;
    }
    long long prog;
    if (!programNumber(loc, "M98", prog)) return false;
    ExprPtr count;
    if (bw.has('L')) {
      count = take('L', Scale::None);
    } else if (prog > 9999) {  // M98 P<count 4 digits><program 4 digits>
      count = Expr::number((double)(prog / 10000), ir::Type::Int, bw.get('P')->loc);
      prog %= 10000;
    } else {
      count = Expr::number(1, ir::Type::Int, loc);
    }
    callOp(loc, prog, std::move(count), "shared");
  }
  if (nonModal && nonModal->kind == GKind::SubCall) {
    // 808D G05 P<program> L<count> calls like M98; without P, or with P0/P01, it is ignored.
    SourceLoc loc = gloc(GGroup::NonModal);
    IsoWord *p = bw.get('P');
    if (p && !(p->expr == nullptr && p->value <= 1)) {
      if (!callAllowed(loc, "G05")) return false;
      long long prog;
      if (!programNumber(loc, "G05", prog)) return false;
      callOp(loc, prog, bw.has('L') ? take('L', Scale::None) : Expr::number(1, ir::Type::Int, loc), "shared");
    } else {
      bw.used |= (1u << ('P' - 'A')) | (1u << ('L' - 'A'));
    }
  }
  if (nonModal && nonModal->kind == GKind::ContourCopy && !contourCopy()) return false;
  if (auto *g67 = G(GGroup::MacroModal); g67 && g67->arg == 1) emit(OpKind::ModalCall, gloc(GGroup::MacroModal));
  if (macroCall) {
    bool modal = !G(GGroup::NonModal);  // G66: a modal_call, after each following move (docs/IR.md §5.5)
    SourceLoc loc = gloc(modal ? GGroup::MacroModal : GGroup::NonModal);
    if (!callAllowed(loc, macroName())) return false;
    long long prog;
    if (!programNumber(loc, macroName(), prog)) return false;
    ExprPtr count = bw.has('L') ? take('L', Scale::None) : Expr::number(1, ir::Type::Int, loc);
    Op &op = modal ? modalCallOp(loc, prog, std::move(count)) : callOp(loc, prog, std::move(count), "new");
    if (!macroArguments(b.words, "GPL", op, *L.diags_)) return false;
    bw.used |= bw.present;
  }
  if (auto *m = findM(MKind::Return)) return returnOp(m->word->loc);
  return true;
}

bool BlockLowerer::Block::finish() {
  for (auto &a : b.assigns) {
    if (a.alarm) {
      // Fanuc #3000 = n: alarm 3000 + n, the run stops; #3006 = n: a stop with a message, the
      // program goes on at cycle start (M0). The block's comment is the operator text.
      SourceLoc loc = a.loc;
      ExprPtr text = Expr::binary(ir::OpCode::Concat, Expr::string(a.alarm == 3000 ? "macro alarm #3000 = " : "#3006 = ", loc),
                                  std::move(a.value), loc);
      if (!b.comments.empty())
        text = Expr::binary(ir::OpCode::Concat, std::move(text), Expr::string(" (" + b.comments.front().text + ")", loc), loc);
      Op &m = emit(OpKind::Message, loc);
      m.set("text", std::move(text));
      if (a.alarm == 3000) m.set("kind", Expr::symbol("abort", loc));
      else emit(OpKind::Stop, loc).set("kind", Expr::symbol("program", loc));
      continue;
    }
    Op &op = emit(OpKind::Assign, a.loc);
    op.set("target", std::move(a.target));
    op.set("value", std::move(a.value));
  }

  // A word no code of the block uses is an error, as in rs274: it usually means a code ncc
  // does not model (or a typo), and running without it would be silently wrong.
  bool ok = true;
  for (uint32_t unused = bw.present & ~bw.used; unused; unused &= unused - 1)
    if (int c = __builtin_ctz(unused); bw.w[c]) {
      L.diags_->error(bw.w[c]->loc, fmt::format("{} word is not used by any code of this block", Words::letter(c)),
                     "unused-word");
      ok = false;
    }
  return ok;
}

bool BlockLowerer::lowerActions(ParsedBlock &b, Region &out) {
  if (!codeCalls_.empty()) {
    const CodeCall *call;
    const IsoWord *word;
    if (!codeCallOf(b, call, word)) return false;
    if (call) return lowerCodeCall(b, *call, *word, out);
  }
  return lowerPlain(b, out);
}

bool BlockLowerer::lowerPlain(ParsedBlock &b, Region &out) {
  Block blk(*this, b, out);
  return blk.classify() && blk.setup() && blk.coordinateOps() && blk.transformOp() && blk.turnCycle() && blk.motion() && blk.stops() &&
         blk.callsAndReturn() && blk.finish();
}

}  // namespace ncc::iso
