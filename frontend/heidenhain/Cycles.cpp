// CYCL DEF n with its parameter lines (`Q200=2 ;SET-UP CLEARANCE`), CYCL CALL and the table of
// the cycles' parameters.
#include "frontend/heidenhain/Cycles.h"
#include "frontend/heidenhain/Parser.h"
#include "ir/WordList.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

namespace ncc::hei {

namespace {
// Act at their definition (digest §3.0): transformations 7 8 10 11 19 26 247, dwell 9, SL data
// 14 20 270, tolerance 32, patterns 220 221, and the touch-probe cycles.
bool defActiveNumber(int n) {
  static const std::set<int> k = {7, 8, 9, 10, 11, 14, 19, 20, 26, 32, 220, 221, 247, 270};
  return k.count(n) || (n >= 400 && n < 500) || (n >= 1400 && n < 1500);
}

}  // namespace

bool defActiveCycle(int number) { return defActiveNumber(number); }

Op cycleCall(SourceLoc l) {
  Op o(OpKind::Cycle, l);
  o.set("action", Expr::symbol("call", l));
  return o;
}

// Cycle 12 PGM CALL (seed002b §3.2, L13391-L13446) runs its program as CALL PGM does (Q
// parameters global, QL fresh); the others are the library's `cycle action=call`.
Op FileParser::storedCall(SourceLoc l) const {
  if (cycle != 12) return cycleCall(l);
  Op o(OpKind::Call, l);
  o.set("callee", Expr::string(cycleProgram));
  o.set("frame", Expr::symbol("new"));
  return o;
}

// The old-style cycles ncc runs, DEF-active: 7 DATUM SHIFT, 8 MIRROR IMAGE, 9 DWELL TIME,
// 10 ROTATION, 11 SCALING, 19 WORKING PLANE (Plane.cpp), 26 AXIS-SPECIFIC SCALING.
bool oldCycleRuns(int number) {
  return number == 7 || number == 8 || number == 9 || number == 10 || number == 11 || number == 19 || number == 26 ||
         number == 32;
}

// One sub-block of cycle 7, 9 or 10 (8, 11, 26: Transforms.cpp). The TNC keeps one datum shift
// and one rotation angle (digest §4.1): each definition replaces it (IX, IROT add to it), kept in
// program-wide variables. The core's chain applies the rotation before the local shift, as the
// TNC does (rotation about the shifted datum).
bool BlockParser::oldCycleBlock(int number, const Token &n) {
  SourceLoc bl = loc(t_[0]);
  if (number == 32) return toleranceBlock(n);
  if (number == 19) return workingPlaneCycle(n);
  if (number != 7 && number != 9 && number != 10) return transformBlock(number, n);
  f_.pp.frames = true;
  if (number == 9) {  // CYCL DEF 9.1 DWELL 1.5: the time is the block's number
    while (!atEnd() && tok().kind == Tok::Word) ++i_;
    ExprPtr t = signedValue();
    if (!t) return false;
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in CYCL DEF {}", tok().text, n.text));
    Op d(OpKind::Dwell, bl);
    d.set("seconds", std::move(t));
    out().push_back(std::move(d));
    return true;
  }
  if (number == 10) {  // CYCL DEF 10.1 ROT+35 / IROT+45
    bool inc = tok().isWord("IROT");
    if (!inc && !tok().isWord("ROT")) return fail(tok(), "CYCL DEF 10.1 takes ROT or IROT");
    ++i_;
    ExprPtr a = signedValue();
    if (!a) return false;
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in CYCL DEF {}", tok().text, n.text));
    Op off(OpKind::CutterComp, bl);  // cycle 10 cancels radius compensation (L12850)
    off.set("side", Expr::symbol("off"));
    out().push_back(std::move(off));
    ExprPtr angle = inc ? Expr::binary(ir::OpCode::Add, hglobal(kRot, bl), std::move(a), bl) : std::move(a);
    frameTakeOff(out(), bl);
    out().push_back(assignOp(hglobal(kRot, bl), std::move(angle), bl));
    framePutOn(out(), bl);
    return true;
  }
  // Cycle 7: one axis per sub-block; absolute from the preset, IX from the last shift.
  if (tok().is("#")) return fail(tok(), "datum tables (CYCL DEF 7.1 #n) are not simulated yet", "unsupported-code");
  const Token &w = tok();
  std::string_view a = w.text;
  bool inc = w.kind == Tok::Word && a.size() == 2 && a[0] == 'I';
  if (inc) a.remove_prefix(1);
  if (w.kind != Tok::Word || a.size() != 1 || std::string_view("XYZ").find(a[0]) == std::string_view::npos)
    return fail(w, "CYCL DEF 7 shifts X, Y or Z (one axis per block)");
  ++i_;
  ExprPtr v = signedValue();
  if (!v) return false;
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in CYCL DEF {}", tok().text, n.text));
  const char *var = a[0] == 'X' ? kShiftX : a[0] == 'Y' ? kShiftY : kShiftZ;
  ExprPtr shift = inc ? Expr::binary(ir::OpCode::Add, hglobal(var, bl), std::move(v), bl) : std::move(v);
  out().push_back(assignOp(hglobal(var, bl), std::move(shift), bl));
  Op f(OpKind::Frame, bl);
  f.set("slot", Expr::symbol("local"));
  f.set("action", Expr::symbol("set"));
  f.set(std::string(1, a[0]), hglobal(var, bl));
  frameTakeOff(out(), bl);
  out().push_back(std::move(f));
  framePutOn(out(), bl);
  return true;
}

// CYCL DEF 12.1 PGM name: the program (looked up as CALL PGM looks) becomes the stored cycle.
bool BlockParser::programCycle(const Token &n) {
  if (!expectWord("PGM")) return false;
  const Token &at = tok();
  std::string written = nameText(t_, i_, "");
  if (written.empty()) return fail(at, "CYCL DEF 12.1 needs the program's name");
  std::string ext = written.size() > 2 ? written.substr(written.size() - 2) : "";
  if (ext == ".I" || ext == ".i")
    return fail(at, "an ISO program as cycle 12 is not simulated yet", "unsupported-code");
  std::string callee = f_.pp.program(written, f_.file, loc(at));
  if (callee.empty()) return false;
  f_.cycleProgram = callee;
  f_.cycleRuns = true;
  Op note(OpKind::Comment, loc(t_[0]));
  note.set("text", Expr::string(fmt::format("CYCL DEF {} PGM {}", n.text, written)));
  out().push_back(std::move(note));
  return true;
}

// Cycle 32 TOLERANCE (seed002b §3.4, L13490-L13685): 32.1 T<tol> is the path tolerance of the
// core's continuous path mode (the blending of the planner, docs/PLANNER.md); 32.1 without T, or
// T0, is the machine's default again, which in ncc is the continuous mode without a tolerance,
// as at the program's start. 32.2 HSC-MODE:0|1 TA<deg> is read: the filter shapes the motion
// inside the tolerance band, which ncc does not model, and TA acts only with M128/TCPM, which ncc
// refuses.
bool BlockParser::toleranceBlock(const Token &n) {
  SourceLoc bl = loc(t_[0]);
  int sub = (int)std::lround((n.num - 32) * 10);
  if (sub == 1) {
    ExprPtr tol;
    if (tok().isWord("T")) {
      ++i_;
      if (!(tol = signedValue())) return false;
      if (tol->kind == ir::ExprKind::Number && (tol->num < 0 || tol->num > 10))
        return fail(t_[0], "CYCL DEF 32.1: the tolerance T must be 0 to 10 (L13617)", "cycle-parameter");
    }
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in CYCL DEF {}", tok().text, n.text));
    Op m(OpKind::Mode, bl);
    m.set("path_mode", Expr::symbol("continuous"));
    if (tol && !(tol->kind == ir::ExprKind::Number && tol->num == 0)) m.set("tolerance", std::move(tol));
    out().push_back(std::move(m));
    return true;
  }
  if (sub != 2) return fail(n, fmt::format("CYCL DEF {}: cycle 32 has the sub-blocks 32.1 and 32.2", n.text), "cycle-invalid");
  while (!atEnd()) {  // HSC-MODE:0|1 TA<deg>
    if (tok().isWord("HSC") && peek().is("-") && peek(2).isWord("MODE")) {
      i_ += 3;
      if (tok().is(":")) ++i_;
      if (tok().kind != Tok::Number || (tok().num != 0 && tok().num != 1))
        return fail(tok(), "HSC-MODE takes 0 or 1", "cycle-parameter");
      ++i_;
    } else if (tok().isWord("TA")) {
      ++i_;
      if (!signedValue()) return false;
    } else {
      return fail(tok(), fmt::format("unexpected '{}' in CYCL DEF {} (HSC-MODE, TA)", tok().text, n.text));
    }
  }
  return true;
}

const char *const kSurface = "_HEI_Q203";
const char *const kModalFeed = "_HEI_FEED";

// CYCL CALL POS X Y Z [FMAX] [M] (L851-L888): the tool moves to X Y in the plane, then the stored
// cycle runs there with Z as an extra datum shift in the tool axis (its Q203 counts from Z). The
// manual's positioning logic moves in the plane first when the tool is above the surface Q203 (+Z)
// and otherwise retracts "to the clearance height" first: that height it does not give, so a call
// from below the surface stops the run. A feed of its own is for the approach only (L883).
bool BlockParser::cyclCallPos() {
  SourceLoc bl = loc(t_[0]);
  ++i_;  // POS
  PathWords w;
  if (!words(w, kCoords | kFeed | kM, "CYCL CALL POS")) return false;
  for (auto &c : w.coords) {
    if (c.axis != 'X' && c.axis != 'Y' && c.axis != 'Z')
      return f_.error(c.loc, fmt::format("CYCL CALL POS takes X, Y and Z, not {}", c.axis));
    if (c.inc) return f_.error(c.loc, "incremental coordinates in CYCL CALL POS are not simulated yet", "unsupported-code");
  }
  if (!w.find('X') || !w.find('Y') || !w.find('Z'))
    return fail(t_[0], "CYCL CALL POS needs all three coordinates X, Y and Z (L869)", "missing-word");
  // Its feed is the approach's only (L883): the modal feed comes back after the move.
  ExprPtr feed = w.fauto ? hglobal(kFauto, w.feedLoc) : std::move(w.feed);
  if (feed && !inchFeed(w.feedLoc)) return false;
  if (w.fauto) f_.pp.fauto = true;
  w.fauto = false;
  if (!f_.cycleSurface)
    return fail(t_[0], fmt::format("CYCL CALL POS needs the surface Q203 in the definition of cycle {}", f_.cycle), "cycle-invalid");
  if (!emitBefore(w)) return false;
  ExprPtr z = w.find('Z')->value->clone();
  ExprPtr surface = Expr::binary(ir::OpCode::Add, hglobal(kSurface, bl), z->clone(), bl);
  Op below(OpKind::If, bl);
  below.set("cond", Expr::binary(ir::OpCode::Le, Expr::var(ir::VarSpace::System, "_z", nullptr, bl), std::move(surface), bl));
  below.regions.emplace_back();
  Op stop(OpKind::Message, bl);
  stop.set("text", Expr::string("CYCL CALL POS with the tool at or below the surface (Q203 + Z): the retract to the "
                                "clearance height first is not simulated yet", bl));
  stop.set("kind", Expr::symbol("abort"));
  below.regions[0].push_back(std::move(stop));
  out().push_back(std::move(below));
  PathWords plane;  // the move in the plane at the current height
  plane.fmax = w.fmax;
  for (auto &c : w.coords)
    if (c.axis != 'Z') plane.coords.push_back({c.axis, false, std::move(c.value), c.loc});
  auto setFeed = [&](ExprPtr v) {
    Op o(OpKind::Feed, bl);
    o.set("value", std::move(v));
    out().push_back(std::move(o));
  };
  const bool ownFeed = feed != nullptr;
  if (ownFeed) {
    f_.pp.callFeed = true;
    out().push_back(assignOp(hglobal(kModalFeed, bl), Expr::var(ir::VarSpace::System, "_feed", nullptr, bl), bl));
    setFeed(std::move(feed));
  }
  if (!emitMove(Op(OpKind::Move), plane, "linear")) return false;
  if (ownFeed) setFeed(hglobal(kModalFeed, bl));
  bool shift = !(z->kind == ir::ExprKind::Number && z->num == 0);
  auto shiftZ = [&](ExprPtr by) {  // the local shift in Z, with the frame's other parts kept
    f_.pp.frames = true;
    Op f(OpKind::Frame, bl);
    f.set("slot", Expr::symbol("local"));
    f.set("action", Expr::symbol("set"));
    f.set("Z", by ? Expr::binary(ir::OpCode::Add, hglobal(kShiftZ, bl), std::move(by), bl) : hglobal(kShiftZ, bl));
    frameTakeOff(out(), bl);
    out().push_back(std::move(f));
    framePutOn(out(), bl);
  };
  if (shift) shiftZ(std::move(z));
  out().push_back(cycleCall(bl));
  if (shift) shiftZ(nullptr);
  moved_ = false;  // its call is the block's: M89 adds none
  return emitAfter(w);
}

bool BlockParser::cycl() {
  SourceLoc bl = loc(t_[0]);
  if (tok().isWord("CALL")) {
    ++i_;
    std::string how = tok().isWord("POS") ? " POS" : tok().isWord("PAT") ? " PAT" : "";
    if (f_.cycle < 0) return fail(t_[0], fmt::format("CYCL CALL{} without a cycle definition (CYCL DEF) before it", how), "cycle-invalid");
    if (f_.cycle == 12 && f_.cycleRuns && !how.empty())
      return fail(t_[0], fmt::format("cycle 12 (PGM CALL) by CYCL CALL{} is not simulated yet", how), "unsupported-code");
    if (slCycle(f_.cycle)) return slCall(how);
    if (f_.cycleRuns && how == " POS") return cyclCallPos();
    if (f_.cycleRuns && how == " PAT") return cyclCallPat();
    if (!f_.cycleRuns || !how.empty())
      return fail(t_[0], fmt::format("cycle {} is not simulated yet (CYCL CALL{})", f_.cycle, how), "unsupported-code");
    PathWords w;  // CYCL CALL M3: the M functions around the call
    if (!words(w, kM, "CYCL CALL") || !emitBefore(w)) return false;
    out().push_back(f_.storedCall(bl));
    return emitAfter(w);
  }
  if (!expectWord("DEF")) return false;
  const Token &n = tok();
  if (n.kind != Tok::Number) return fail(n, "CYCL DEF needs the cycle number");
  int number = (int)std::floor(n.num);
  int sub = n.isInt ? -1 : (int)std::lround((n.num - number) * 10);  // 7.0, 7.1 …: the old sub-blocks
  ++i_;
  if (sub > 0 && number == f_.oldCycle && oldCycleRuns(number)) return oldCycleBlock(number, n);
  if (number == 14 && sub == 1 && f_.oldCycle == 14) return contourLabels(n);
  if (number == 14 && sub == 0) {  // CYCL DEF 14.0 <title>: its labels follow in 14.1
    while (!atEnd() && tok().line == n.line) ++i_;
    if (!atEnd()) return fail(tok(), "CYCL DEF 14.0 takes no parameter lines: the labels follow in CYCL DEF 14.1", "cycle-parameter");
    f_.oldCycle = 14;
    f_.slLabels.clear();
    Op note(OpKind::Comment, loc(t_[0]));
    note.set("text", Expr::string(fmt::format("CYCL DEF {} CONTOUR", n.text)));
    out().push_back(std::move(note));
    return true;
  }
  if (sub < 0 && slCycle(number)) return slDefinition(number, n);
  if (number == 12 && sub == 1 && f_.oldCycle == 12) return programCycle(n);
  while (!atEnd() && tok().line == n.line) ++i_;  // the title: free text
  // The parameter lines: Qn=value, each at most once, each one the cycle takes. A cycle of the
  // library (`ncc cycle --list`) becomes the `cycle` op: a CALL-active one is stored (define)
  // for CYCL CALL and M99, a pattern (220, 221) runs the stored one at its positions at once.
  CycleSignature lib;
  bool inLib = sub < 0 && f_.pp.opts.cycles && f_.pp.opts.cycles(fmt::format("hei.{}", number), lib);
  bool defActive = defActiveCycle(number);
  if (sub <= 0 && !defActive) {  // a new definition replaces the last, also when it is wrong
    f_.cycle = number;
    f_.cycleRuns = inLib;
    f_.cycleSurface = false;
    f_.cycleProgram.clear();
    f_.m89 = false;  // a new definition ends M89 (L903)
  }
  Op c(OpKind::Cycle, bl);
  if (inLib) {
    c.set(lib.pattern ? "pattern" : "entry", Expr::string(lib.name, bl));
    c.set("action", Expr::symbol(lib.pattern ? "call" : "define", bl));
  }
  std::set<std::string> seen;
  while (!atEnd()) {
    const Token &q = tok();
    std::string name;
    if (!cycleParamName(number, seen, name)) return false;
    if (inLib && !inWordList(lib.params, name)) return fail(q, fmt::format("{} is not a parameter of cycle {}", name, number), "cycle-parameter");
    // FAUTO, FMAX, FU, FZ and PREDEF are the library's as numbers (FMAX, FU, FZ: the codes the
    // executor resolves at the call, ir/CycleFeed.h); a cycle ncc does not run has them read only.
    CycleValue cv;
    if (!cycleValue(number, name, cv, inLib)) return false;
    if (!inLib) continue;
    if (cv.kind == CycleValue::Text)
      return f_.error(cv.at, fmt::format("{} of cycle {} takes a number, not a string", name, number), "cycle-parameter");
    ExprPtr v = std::move(cv.value);
    if (!lib.pattern && name == "Q203") {  // CYCL CALL POS compares the tool with it
      f_.pp.surface = f_.cycleSurface = true;
      out().push_back(assignOp(hglobal(kSurface, bl), v->clone(), bl));
    }
    c.set((lib.pattern ? "p." : "a.") + name, std::move(v));
  }
  Op note(OpKind::Comment, bl);
  note.set("text", Expr::string(fmt::format("CYCL DEF {}", n.text)));
  out().push_back(std::move(note));
  if (sub > 0) {  // a sub-block of an old-style cycle: its n.0 block was refused already
    if (f_.cycleLoc.line == 0 || f_.oldCycle != number)
      return fail(n, fmt::format("CYCL DEF {} without CYCL DEF {}.0 before it", n.text, number), "cycle-invalid");
    return true;
  }
  if (sub == 0) f_.oldCycle = number;
  if (sub == 0 && oldCycleRuns(number)) return true;  // its sub-blocks act
  f_.cycleLoc = bl;
  if (inLib && lib.pattern) {
    if (f_.cycle < 0) return fail(n, fmt::format("cycle {} runs the machining cycle defined before it: there is none", number), "cycle-invalid");
    if (!f_.cycleRuns)
      return fail(n, fmt::format("cycle {} is not simulated yet (called by cycle {})", f_.cycle, number), "unsupported-code");
  } else if (defActive) {
    return fail(n, fmt::format("cycle {} (active at its definition) is not simulated yet", number), "unsupported-code");
  }
  if (inLib) out().push_back(std::move(c));
  return true;
}

bool BlockParser::cycleParamName(int number, std::set<std::string> &seen, std::string &name, const char *block) {
  const Token &q = tok();
  if (!(q.isWord("Q") || q.isWord("QS")) || peek().kind != Tok::Number || !peek().isInt)
    return fail(q, fmt::format("a cycle parameter line Qn=value was expected, not '{}'", q.text));
  name = q.text + peek().text;
  i_ += 2;
  if (!tok().is("=")) return fail(tok(), fmt::format("'=' expected after {}", name));
  ++i_;
  if (!seen.insert(name).second) return fail(q, fmt::format("{} twice in {} {}", name, block, number), "cycle-parameter");
  return true;
}

}  // namespace ncc::hei
