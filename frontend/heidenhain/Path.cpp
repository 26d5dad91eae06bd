// Path blocks: L, C, CR, CT, LP, CP, the pole CC and the corners RND and CHF, lowered to `mode
// motion=` + `move` in the order the TNC applies a block: feed, the M functions that act at
// the block start, radius compensation, the move, the M functions that act at its end.
// Circles are about the pole CC (program-wide variables, so Q parameters and incremental
// poles work); polar end points are computed from it (docs/HEIDENHAIN.md).
#include "frontend/heidenhain/Cycles.h"
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::hei {

const char *const kCcX = "_HEI_CCX";
const char *const kCcY = "_HEI_CCY";
const char *const kPr = "_HEI_PR";
const char *const kPa = "_HEI_PA";
const char *const kFauto = "_HEI_FAUTO";
const char *const kShiftX = "_HEI_SHIFTX";
const char *const kShiftY = "_HEI_SHIFTY";
const char *const kShiftZ = "_HEI_SHIFTZ";
const char *const kRot = "_HEI_ROT";

ExprPtr hglobal(const char *name, SourceLoc l) { return Expr::var(ir::VarSpace::Global, name, nullptr, l); }

Op assignOp(ExprPtr target, ExprPtr value, SourceLoc l) {
  Op o(OpKind::Assign, l);
  o.set("target", std::move(target));
  o.set("value", std::move(value));
  return o;
}

namespace {
// M functions (the TNC 640's list): when in the block they act and what they are.
enum class MAct : uint8_t { Spindle, Coolant, SpindleCoolant, Stop, End, CycleCall, Aux, Refused };
enum class When : uint8_t { Start, End };
struct MRow {
  int code;
  MAct act;
  When when;
  const char *arg;
};
const MRow kMTable[] = {
    {0, MAct::Stop, When::End, "program"},   {1, MAct::Stop, When::End, "optional"},
    {2, MAct::End, When::End, "end"},        {30, MAct::End, When::End, "end_rewind"},
    {3, MAct::Spindle, When::Start, "cw"},   {4, MAct::Spindle, When::Start, "ccw"},
    {5, MAct::Spindle, When::End, "stop"},   {6, MAct::Spindle, When::End, "stop"},  // M6: spindle stop, then the machine's tool change (aux)
    {7, MAct::Coolant, When::Start, "mist"}, {8, MAct::Coolant, When::Start, "flood"},
    {9, MAct::Coolant, When::End, "off"},    {13, MAct::SpindleCoolant, When::Start, "cw"},
    {14, MAct::SpindleCoolant, When::Start, "ccw"}, {99, MAct::CycleCall, When::End, "M99"},
    {89, MAct::CycleCall, When::End, "M89"},
};
MRow mRow(int code) {
  for (auto &m : kMTable)
    if (m.code == code) return m;
  // M89 and above are the control's own functions (M91/M92 machine positions, M94, M97, M98,
  // M101…M150): they change the path, so they are refused. The rest are the machine maker's.
  return {code, code >= 89 ? MAct::Refused : MAct::Aux, When::Start, ""};
}

Op spindleOp(const char *dir, SourceLoc l) {
  Op o(OpKind::Spindle, l);
  o.set("dir", Expr::symbol(dir));
  return o;
}
Op coolantOp(const char *what, SourceLoc l) {
  Op o(OpKind::Coolant, l);
  if (std::string_view(what) == "off") {
    o.set("flood", Expr::symbol("off"));
    o.set("mist", Expr::symbol("off"));
  } else {
    o.set(what, Expr::symbol("on"));
  }
  return o;
}
Op auxOp(int code, SourceLoc l) {
  Op o(OpKind::Aux, l);
  o.set("m", Expr::number(code, ir::Type::Int));
  return o;
}

ExprPtr sysvar(const char *name, SourceLoc l) { return Expr::var(ir::VarSpace::System, name, nullptr, l); }
ExprPtr call1(const char *fn, ExprPtr a, SourceLoc l) {
  std::vector<ExprPtr> args;
  args.push_back(std::move(a));
  return Expr::call(fn, std::move(args), l);
}
ExprPtr sub(ExprPtr a, ExprPtr b, SourceLoc l) { return Expr::binary(OpCode::Sub, std::move(a), std::move(b), l); }
ExprPtr add(ExprPtr a, ExprPtr b, SourceLoc l) { return Expr::binary(OpCode::Add, std::move(a), std::move(b), l); }
ExprPtr mul(ExprPtr a, ExprPtr b, SourceLoc l) { return Expr::binary(OpCode::Mul, std::move(a), std::move(b), l); }
// The current position relative to the pole, in the plane.
ExprPtr dx(SourceLoc l) { return sub(sysvar("_x", l), hglobal(kCcX, l), l); }
ExprPtr dy(SourceLoc l) { return sub(sysvar("_y", l), hglobal(kCcY, l), l); }
}  // namespace

bool BlockParser::words(PathWords &w, unsigned allowed, const char *stmt) {
  auto refuse = [&](const Token &t) { return fail(t, fmt::format("'{}' cannot be used in a {} block", t.text, stmt)); };
  while (!atEnd()) {
    const Token &t = tok();
    SourceLoc l = loc(t);
    if (t.kind != Tok::Word) return fail(t, fmt::format("unexpected '{}' in a {} block", t.text, stmt));
    const std::string &s = t.text;
    bool inc = s.size() == 2 && s[0] == 'I';
    std::string_view ax = inc ? std::string_view(s).substr(1) : std::string_view(s);
    if (ax.size() == 1 && std::string_view("XYZABCUVW").find(ax[0]) != std::string_view::npos) {
      if (!(allowed & kCoords)) return refuse(t);
      if (w.find(ax[0])) return fail(t, fmt::format("axis {} twice in one block", ax[0]), "duplicate-word");
      ++i_;
      ExprPtr v = signedValue();
      if (!v) return false;
      w.coords.push_back({ax[0], inc, std::move(v), l});
    } else if (s == "PA" || s == "PR" || s == "IPA" || s == "IPR") {
      if (!(allowed & kPolar))
        return fail(t, fmt::format("polar coordinates ({}) need LP or CP, not {}", s, stmt), "syntax");
      bool angle = s.back() == 'A';
      if (angle ? w.pa != nullptr : w.pr != nullptr) return fail(t, fmt::format("{} twice in one block", s), "duplicate-word");
      ++i_;
      ExprPtr v = signedValue();
      if (!v) return false;
      (angle ? w.pa : w.pr) = std::move(v);
      (angle ? w.paInc : w.prInc) = s[0] == 'I';
      (angle ? w.paLoc : w.prLoc) = l;
    } else if (s == "RL" || s == "RR" || (s == "R" && peek().kind == Tok::Number && peek().text == "0")) {
      if (!(allowed & kComp)) return refuse(t);
      if (w.comp >= 0) return fail(t, "two radius compensations in one block", "duplicate-word");
      w.comp = s == "RL" ? 1 : s == "RR" ? 2 : 0;
      i_ += s == "R" ? 2 : 1;
    } else if (s == "R" && (allowed & kRadius)) {
      if (w.radius) return fail(t, "R twice in one block", "duplicate-word");
      ++i_;
      w.radius = signedValue();
      w.radiusLoc = l;
      if (!w.radius) return false;
    } else if (s == "F" || s == "FMAX" || s == "FAUTO" || s == "FQ" || s == "FQL" || s == "FQR") {
      if (!(allowed & kFeed)) return refuse(t);
      if (w.feed || w.fmax || w.fauto) return fail(t, "two feeds in one block", "duplicate-word");
      w.feedLoc = l;
      if (s == "FMAX" || s == "FAUTO") {
        (s == "FMAX" ? w.fmax : w.fauto) = true;
        ++i_;
      } else if (s == "F") {
        ++i_;
        if (!(w.feed = signedValue())) return false;
      } else {  // FQ5: the feed in a Q parameter
        Token q = t;
        q.text = s.substr(1);
        t_[i_] = q;
        if (!(w.feed = qParam())) return false;
      }
    } else if (s == "FU" || s == "FZ") {
      return fail(t, fmt::format("{} (feed per {}) is not simulated yet", s, s == "FU" ? "revolution" : "tooth"), "unsupported-code");
    } else if (s == "M") {
      if (!(allowed & kM)) return refuse(t);
      const Token &n = peek();
      if (n.kind != Tok::Number || !n.isInt) return fail(n, "M needs a whole number");
      w.ms.push_back({(int)n.num, l});
      i_ += 2;
    } else if (s == "DR" && (allowed & kDir)) {
      const Token &d = peek();
      if (!d.is("+") && !d.is("-")) return fail(d, "DR+ (counter-clockwise) or DR- (clockwise) expected");
      if (w.dr) return fail(t, "DR twice in one block", "duplicate-word");
      w.dr = d.is("+") ? 1 : -1;
      w.drLoc = l;
      i_ += 2;
    } else {
      return refuse(t);
    }
  }
  for (auto &[m, ml] : w.ms) {
    MRow r = mRow(m);
    if (r.act == MAct::Refused)
      return f_.error(ml, fmt::format("M{} is a TNC function ncc does not simulate", m), "unsupported-code");
    if (r.act == MAct::End && !f_.isMain)
      return f_.error(ml, fmt::format("M{} in a program called by CALL PGM (the called program must not end the run)", m),
                      "program-frame");
    if (r.act == MAct::CycleCall) {
      if (f_.cycle < 0) return f_.error(ml, fmt::format("{} without a cycle definition (CYCL DEF) before it", r.arg), "cycle-invalid");
      if (slCycle(f_.cycle))
        return f_.error(ml, fmt::format("SL cycle {} by {} is not simulated: call it by CYCL CALL", f_.cycle, r.arg), "unsupported-code");
      if (!f_.cycleRuns) return f_.error(ml, fmt::format("cycle {} is not simulated yet ({})", f_.cycle, r.arg), "unsupported-code");
    }
  }
  return true;
}

// Whether an INCH program's F is in inch/min or 0.1 inch/min depends on the control's
// generation; neither the manual nor the digests say, so it is refused rather than guessed.
bool BlockParser::inchFeed(SourceLoc at) {
  return !f_.inch || f_.error(at, "a feed in an INCH program is not simulated (its unit is not settled)", "unsupported-code");
}

bool BlockParser::emitBefore(PathWords &w) {
  SourceLoc bl = loc(t_[0]);
  if ((w.feed || w.fauto) && !inchFeed(w.feedLoc)) return false;
  if (w.feed) {
    Op o(OpKind::Feed, w.feedLoc);
    o.set("value", std::move(w.feed));
    out().push_back(std::move(o));
  } else if (w.fauto) {  // the feed of the last TOOL CALL
    f_.pp.fauto = true;
    Op o(OpKind::Feed, w.feedLoc);
    o.set("value", hglobal(kFauto, w.feedLoc));
    out().push_back(std::move(o));
  }
  for (auto &[m, l] : w.ms) {
    MRow r = mRow(m);
    if (r.when != When::Start) continue;
    if (r.act == MAct::Spindle || r.act == MAct::SpindleCoolant) out().push_back(spindleOp(r.arg, l));
    if (r.act == MAct::Coolant) out().push_back(coolantOp(r.arg, l));
    if (r.act == MAct::SpindleCoolant) out().push_back(coolantOp("flood", l));
    if (r.act == MAct::Aux) out().push_back(auxOp(m, l));
  }
  if (w.comp >= 0) f_.compSide = w.comp;
  if (w.comp == 0) {
    Op o(OpKind::CutterComp, bl);
    o.set("side", Expr::symbol("off"));
    out().push_back(std::move(o));
  } else if (w.comp > 0) {
    // RL/RR may stand in every block of a compensated contour: switch on only when off or on
    // the other side ($_ccomp is 400 off, 410 left, 420 right).
    Op on(OpKind::CutterComp, bl);
    on.set("side", Expr::symbol(w.comp == 1 ? "left" : "right"));
    on.set("d_default", Expr::symbol("tool"));
    on.set("entry", Expr::symbol("normal"));  // the TNC starts normal to the first element
    Op cond(OpKind::If, bl);
    cond.set("cond", Expr::binary(OpCode::Ne, sysvar("_ccomp", bl), num(400 + 10 * w.comp), bl));
    cond.regions.emplace_back();
    cond.regions[0].push_back(std::move(on));
    out().push_back(std::move(cond));
  }
  return true;
}

bool BlockParser::emitMove(Op mv, PathWords &w, const char *motion) {
  SourceLoc bl = loc(t_[0]);
  std::string ic;
  for (auto &c : w.coords) {
    if (c.inc) ic += c.axis;
    mv.set(std::string(1, c.axis), std::move(c.value));
  }
  if (!ic.empty()) mv.set("ic", Expr::symbol(ic));
  if (mv.args.empty()) return true;  // a block with words but no position (`L R0 FMAX M3`)
  Op mode(OpKind::Mode, bl);
  mode.set("motion", Expr::symbol(w.fmax ? "rapid" : motion));
  out().push_back(std::move(mode));
  mv.loc = bl;
  out().push_back(std::move(mv));
  f_.lastMove = out().size() - 1;
  moved_ = true;
  return true;
}

// M99 calls the cycle once after the block's move; M89 does and keeps calling it after every
// positioning block (L889-L907) until an M99 block (its call the last) or a new CYCL DEF.
bool BlockParser::emitAfter(PathWords &w) {
  bool called = false;
  for (auto &[m, l] : w.ms)
    if (mRow(m).act == MAct::CycleCall) {
      if (!called) out().push_back(f_.storedCall(l));
      called = true;
      f_.m89 = m == 89 || (f_.m89 && m != 99);
    }
  if (!called && moved_ && f_.m89) out().push_back(f_.storedCall(loc(t_[0])));
  for (auto &[m, l] : w.ms) {
    MRow r = mRow(m);
    if (r.when != When::End) continue;
    if (r.act == MAct::Spindle) out().push_back(spindleOp(r.arg, l));
    if (m == 6) out().push_back(auxOp(6, l));  // the machine's tool change program
    if (r.act == MAct::Coolant) out().push_back(coolantOp(r.arg, l));
    if (r.act == MAct::End) f_.sawEnd = true;
    if (r.act == MAct::Stop || r.act == MAct::End) {
      Op o(OpKind::Stop, l);
      o.set("kind", Expr::symbol(r.arg));
      out().push_back(std::move(o));
    }
  }
  return true;
}

bool BlockParser::line() {
  PathWords w;
  if (!words(w, kCoords | kComp | kFeed | kM, "L")) return false;
  if (f_.approach && !approachBefore(w, 0)) return false;
  keepLineStart();
  fkFollowLine(w);
  if (!emitBefore(w)) return false;
  return emitMove(Op(OpKind::Move), w, "linear") && emitAfter(w);
}

// Circles lie in the working plane of TOOL CALL Z: X and Y (and Z for a helix with CP).
static bool planeOnly(const PathWords &w, bool helix, const Coord *&bad) {
  for (auto &c : w.coords)
    if (c.axis != 'X' && c.axis != 'Y' && !(helix && c.axis == 'Z')) {
      bad = &c;
      return false;
    }
  return true;
}

bool BlockParser::arc() {
  PathWords w;
  if (!words(w, kCoords | kComp | kFeed | kM | kDir, "C")) return false;
  const Coord *bad = nullptr;
  if (!planeOnly(w, false, bad)) return f_.error(bad->loc, "C moves in the working plane (X, Y) only");
  if (w.coords.empty()) return fail(t_[0], "C needs its end point (X, Y)", "missing-word");
  if (!w.dr) return fail(t_[0], "C needs the direction DR+ or DR-", "missing-word");
  if (w.fmax) return f_.error(w.feedLoc, "FMAX on an arc: the TNC moves arcs at a feed", "syntax");
  f_.pp.polar = true;
  arcDir_ = w.dr;
  if (f_.approach && !approachBefore(w, w.dr)) return false;
  if (!emitBefore(w)) return false;
  Op mv(OpKind::Move);
  mv.set("I", hglobal(kCcX));
  mv.set("J", hglobal(kCcY));
  mv.set("ac", Expr::symbol("IJ"));
  return emitMove(std::move(mv), w, w.dr > 0 ? "arc_ccw" : "arc_cw") && emitAfter(w);
}

bool BlockParser::arcRadius() {
  PathWords w;
  if (!words(w, kCoords | kComp | kFeed | kM | kDir | kRadius, "CR")) return false;
  const Coord *bad = nullptr;
  if (!planeOnly(w, false, bad)) return f_.error(bad->loc, "CR moves in the working plane (X, Y) only");
  if (w.coords.empty()) return fail(t_[0], "CR needs its end point (X, Y)", "missing-word");
  if (!w.dr) return fail(t_[0], "CR needs the direction DR+ or DR-", "missing-word");
  if (!w.radius) return fail(t_[0], "CR needs the radius R (negative: more than 180 degrees)", "missing-word");
  if (w.fmax) return f_.error(w.feedLoc, "FMAX on an arc: the TNC moves arcs at a feed", "syntax");
  if (!emitBefore(w)) return false;
  Op mv(OpKind::Move);
  mv.set("R", std::move(w.radius));
  return emitMove(std::move(mv), w, w.dr > 0 ? "arc_ccw" : "arc_cw") && emitAfter(w);
}

bool BlockParser::arcTangent() {
  PathWords w;
  if (!words(w, kCoords | kComp | kFeed | kM, "CT")) return false;
  const Coord *bad = nullptr;
  if (!planeOnly(w, false, bad)) return f_.error(bad->loc, "CT moves in the working plane (X, Y) only");
  if (w.coords.empty()) return fail(t_[0], "CT needs its end point (X, Y)", "missing-word");
  if (w.fmax) return f_.error(w.feedLoc, "FMAX on an arc: the TNC moves arcs at a feed", "syntax");
  if (!emitBefore(w)) return false;
  return emitMove(Op(OpKind::Move), w, "arc_tangent") && emitAfter(w);
}

// CC: the pole. Coordinates left out are the current position's; IX IY add to it.
bool BlockParser::centre() {
  PathWords w;
  if (!words(w, kCoords, "CC")) return false;
  const Coord *bad = nullptr;
  if (!planeOnly(w, false, bad)) return f_.error(bad->loc, "CC takes the working plane's coordinates (X, Y)");
  f_.pp.polar = true;
  SourceLoc bl = loc(t_[0]);
  std::vector<Op> sets;
  for (char a : {'X', 'Y'}) {
    const Coord *c = w.find(a);
    ExprPtr here = sysvar(a == 'X' ? "_x" : "_y", bl);
    ExprPtr v = !c ? std::move(here) : c->inc ? add(std::move(here), c->value->clone(), c->loc) : c->value->clone();
    sets.push_back(assignOp(hglobal(a == 'X' ? kCcX : kCcY, bl), std::move(v), bl));
  }
  for (auto &s : sets) out().push_back(std::move(s));  // both from the position before
  return true;
}

// The polar end point about the pole: PR and PA, each absolute, incremental (IPR, IPA) to the
// current position's polar coordinates, or that value when left out.
bool BlockParser::polarEnd(PathWords &w, Op &mv, bool arc) {
  SourceLoc bl = loc(t_[0]);
  f_.pp.polar = true;
  auto radiusNow = [&] {
    return call1("SQRT", add(mul(dx(bl), dx(bl), bl), mul(dy(bl), dy(bl), bl), bl), bl);
  };
  auto angleNow = [&] {
    std::vector<ExprPtr> a;
    a.push_back(dy(bl));
    a.push_back(dx(bl));
    return Expr::call("ATAN2", std::move(a), bl);
  };
  ExprPtr pr = arc ? radiusNow() : !w.pr ? radiusNow() : w.prInc ? add(radiusNow(), std::move(w.pr), bl) : std::move(w.pr);
  ExprPtr pa = !w.pa ? angleNow() : w.paInc ? add(angleNow(), std::move(w.pa), bl) : std::move(w.pa);
  out().push_back(assignOp(hglobal(kPr, bl), std::move(pr), bl));
  out().push_back(assignOp(hglobal(kPa, bl), std::move(pa), bl));
  mv.set("X", add(hglobal(kCcX, bl), mul(hglobal(kPr, bl), call1("COS", hglobal(kPa, bl), bl), bl), bl));
  mv.set("Y", add(hglobal(kCcY, bl), mul(hglobal(kPr, bl), call1("SIN", hglobal(kPa, bl), bl), bl), bl));
  return true;
}

bool BlockParser::linePolar() {
  PathWords w;
  if (!words(w, kCoords | kPolar | kComp | kFeed | kM, "LP")) return false;
  const Coord *bad = nullptr;
  for (auto &c : w.coords)
    if (c.axis == 'X' || c.axis == 'Y') bad = &c;
  if (bad) return f_.error(bad->loc, "LP takes PR and PA in the working plane, not X or Y", "polar-with-xy");
  if (!w.pr && !w.pa) return fail(t_[0], "LP needs PR or PA", "missing-word");
  if (!emitBefore(w)) return false;
  Op mv(OpKind::Move);
  if (!polarEnd(w, mv, false)) return false;
  return emitMove(std::move(mv), w, "linear") && emitAfter(w);
}

bool BlockParser::arcPolar() {
  PathWords w;
  if (!words(w, kCoords | kPolar | kComp | kFeed | kM | kDir, "CP")) return false;
  const Coord *bad = nullptr;
  if (!planeOnly(w, true, bad) || w.find('X') || w.find('Y'))
    return f_.error((bad ? bad : w.find('X') ? w.find('X') : w.find('Y'))->loc, "CP takes PA (and Z for a helix), not X or Y",
                    "polar-with-xy");
  if (w.pr) return f_.error(w.prLoc, "CP keeps the radius: PR cannot be given", "syntax");
  if (!w.pa) return fail(t_[0], "CP needs PA or IPA", "missing-word");
  if (!w.dr) return fail(t_[0], "CP needs the direction DR+ or DR-", "missing-word");
  if (w.fmax) return f_.error(w.feedLoc, "FMAX on an arc: the TNC moves arcs at a feed", "syntax");
  Op mv(OpKind::Move);
  if (w.paInc) {
    // An incremental angle may pass full turns: the core's turn count (1 = less than one turn).
    if (w.pa->kind != ir::ExprKind::Number)
      return f_.error(w.paLoc, "CP with a computed IPA is not simulated (its number of turns must be known)", "unsupported-code");
    double a = w.pa->num;
    if (a == 0) return f_.error(w.paLoc, "CP with IPA+0 does not move", "arc-invalid");
    if ((a > 0) != (w.dr > 0))
      return f_.error(w.drLoc, fmt::format("IPA{:+g} turns the other way than DR{}", a, w.dr > 0 ? "+" : "-"), "arc-invalid");
    double turns = std::ceil(std::fabs(a) / 360.0 - 1e-12);
    if (turns > 1) mv.set("P", num(turns));
  }
  if (!emitBefore(w)) return false;
  if (!polarEnd(w, mv, true)) return false;
  mv.set("I", hglobal(kCcX));
  mv.set("J", hglobal(kCcY));
  mv.set("ac", Expr::symbol("IJ"));
  return emitMove(std::move(mv), w, w.dr > 0 ? "arc_ccw" : "arc_cw") && emitAfter(w);
}

// RND R5 / CHF 5: the corner between the contour element before and the one after, inserted by
// the core's contour step (runtime/ExecutorCorner.cpp) from the move before.
bool BlockParser::corner() {
  bool round = t_[0].isWord("RND");
  ++i_;
  if (round && !expectWord("R")) return false;
  ExprPtr v = signedValue();
  if (!v) return false;
  if (!atEnd()) {
    if (tok().kind == Tok::Word && (tok().text == "F" || tok().text.rfind("F", 0) == 0))
      return fail(tok(), fmt::format("a feed on {} is not simulated yet", t_[0].text), "unsupported-code");
    return fail(tok(), fmt::format("unexpected '{}' after {}", tok().text, t_[0].text));
  }
  ir::Region &r = out();
  size_t k = r.size();
  while (k > 0 && (r[k - 1].kind == OpKind::Block || r[k - 1].kind == OpKind::Comment)) --k;
  if (k == 0 || k - 1 != f_.lastMove || r[k - 1].kind != OpKind::Move)
    return fail(t_[0], fmt::format("{} must follow a contour element (L, C, CR, CT, LP, CP)", t_[0].text), "corner-invalid");
  if (r[k - 1].get("chamfer") || r[k - 1].get("round"))
    return fail(t_[0], "two corners after one contour element", "corner-invalid");
  r[k - 1].set(round ? "round" : "chamfer", std::move(v));
  return true;
}

}  // namespace ncc::hei
