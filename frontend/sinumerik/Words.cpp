// Address words (X10, X=AC(5), CR=20, G1, M3, T1 D1 …), subprogram calls and the frame
// statements, and the lowering of one block's machine words to ops in execution order.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

// The value of an address: `X10` (digits in the name), `X-10` / `X 10`, `X=expr`, `X=AC(e)`.
bool BlockParser::addressWord() {
  const Token &t = tok();
  SourceLoc l = loc(t);
  const AddrInfo *full = findAddress(t.text);
  std::string letters = t.text.substr(0, t.digitsAt);
  const AddrInfo *pre = t.digitsAt < t.text.size() ? findAddress(letters) : nullptr;
  if (t.isName("SPOS")) return spindlePosition();
  GInfo g = findGCode(t.text);
  if (g.code && !(full && peek().is("="))) {
    ++i_;
    return gcode(t.text, t);
  }
  Word w;
  w.loc = l;
  if (full && full->kind == Addr::Axis && peek().is("=") && peek(2).isName("PO")) {  // X=PO(…)
    i_ += 3;
    return polyTerm(t.text, t);
  }
  if (full && peek().is("=")) {  // X=…, CR=…, I1=…
    w.addr = t.text;
    i_ += 2;
    const Token &m = tok();
    if ((m.isName("AC") || m.isName("IC")) && peek().is("(")) {
      w.mode = m.text[0];
      i_ += 2;
      w.value = expr(0);
      if (!w.value || !expect(")")) return false;
    } else if ((m.isName("DC") || m.isName("ACP") || m.isName("ACN") || m.isName("CAC") || m.isName("CIC")) &&
               peek().is("(")) {
      return fail(m, fmt::format("{}=({}) positioning is not simulated", w.addr, m.text), "unsupported-code");
    } else {
      w.value = expr(0);
      if (!w.value) return false;
    }
  } else if (pre && !t.fraction && t.digitsAt == 1 && (letters == "L")) {
    // L123: a program call; leading zeros count (L8331), so the name is kept as written.
    return callStatement(false);
  } else if (pre) {  // X10, G1, M30
    w.addr = letters;
    w.value = Expr::number(t.num, t.isInt ? ir::Type::Int : ir::Type::Real, l);
    ++i_;
    if (letters == "G") {  // G01 is G1
      if (!t.isInt) return fail(t, fmt::format("unknown G function {}", t.text), "unknown-code");
      return gcode(fmt::format("G{}", t.num), t);  // a double: G99999999999999999999 has no long
    }
  } else if (full && (peek().kind == Tok::Number || ((peek().is("-") || peek().is("+")) && peek(2).kind == Tok::Number))) {
    w.addr = t.text;  // X-10, X 10
    ++i_;
    bool neg = tok().is("-");
    if (tok().kind == Tok::Punct) ++i_;
    w.value = Expr::number(neg ? -tok().num : tok().num, tok().isInt ? ir::Type::Int : ir::Type::Real, l);
    ++i_;
  } else if (pre && peek().is("=")) {
    // S1=300, M2=19, X1=5: an address with an extension (spindle or channel axis number).
    return fail(t, fmt::format("the address extension {}= (a spindle or axis number) is not simulated", t.text),
                "unsupported-code");
  } else if (t.isName("PO") && peek().is("[")) {  // PO[X]=(…), PO[]=(…)
    i_ += 2;
    std::string axis;
    if (!tok().is("]")) {
      const AddrInfo *a = tok().kind == Tok::Name ? findAddress(tok().text) : nullptr;
      if (!a || a->kind != Addr::Axis) return fail(tok(), "PO[…] takes an axis name (or nothing: the denominator)");
      axis = tok().text;
      ++i_;
    }
    if (!expect("]") || !expect("=")) return false;
    return polyTerm(axis, t);
  } else if (t.isName("PO") && peek().is("(")) {  // PO(…): the denominator
    ++i_;
    return polyTerm("", t);
  } else if (t.isName("AX") && peek().is("[")) {  // AX[X]=10, AX[AXNAME("X")]=10 (SIN-IND-02)
    i_ += 2;
    ExprPtr ax = expr(0);
    if (!ax || !expect("]") || !expect("=")) return false;
    if (ax->kind == ir::ExprKind::Call && ax->str == "AXNAME" && ax->args.size() == 1 &&
        ax->args[0]->kind == ir::ExprKind::String)
      ax = std::move(ax->args[0]);
    std::string name = ax->kind == ir::ExprKind::String ? ax->str : "";
    for (auto &c : name) c = (char)std::toupper((unsigned char)c);
    const AddrInfo *axis = findAddress(name);
    if (ax->kind != ir::ExprKind::String)
      return fail(t, "AX[…] with an axis known only at run time (an AXIS variable) is not simulated", "unsupported-code");
    if (!axis || axis->kind != Addr::Axis)
      return fail(t, fmt::format("AX[\"{}\"]: not an axis (X Y Z A B C U V W)", ax->str));
    w.addr = name;
    w.value = expr(0);
    if (!w.value) return false;
  } else if (peek().is("[")) {
    // G[8]=2, S[SPINU]=300: indirect addresses (SIN-IND-01, -03).
    return fail(t, fmt::format("the indexed address {}[…] is not simulated", t.text), "unsupported-code");
  } else {
    return callStatement(false);  // a subprogram called by its name
  }
  const AddrInfo *a = findAddress(w.addr);
  if (a->kind == Addr::Refused) return fail(t, fmt::format("{} ({}) is not simulated", w.addr, a->why), "unsupported-code");
  if (a->kind == Addr::Misc) {
    if (w.value->kind != ir::ExprKind::Number || w.value->num != std::floor(w.value->num) || w.value->num < 0 ||
        w.value->num > INT32_MAX)
      return fail(t, "an M function is a constant integer from 0 to 2147483647 (M=expressions are not simulated)",
                  "unsupported-code");
    mcodes_.push_back({(int)w.value->num, l});
    return true;
  }
  for (auto &o : words_)
    if (o.addr == w.addr) return fail(t, fmt::format("address {} is programmed twice in the block", w.addr), "duplicate-word");
  words_.push_back(std::move(w));
  return true;
}

// SPOS=<degrees>: the spindle stops at the angle in position control (what G331/G332 need),
// the shortest way (as DC); SPOS=DC(a) / ACP(a) / ACN(a) the shortest way, turning positive (M3's
// way) or negative. SPOS=IC(…) and SPOS[n] (other spindles) are not simulated.
bool BlockParser::spindlePosition() {
  const Token &t = tok();
  if (!peek().is("="))
    return fail(t, "SPOS takes =<angle> (SPOS[n] and the other spindles are not simulated)", "unsupported-code");
  i_ += 2;
  static const char *kWays[][2] = {{"DC", "shortest"}, {"ACP", "cw"}, {"ACN", "ccw"}};
  const char *way = "shortest";
  bool wrapped = false;
  if (tok().kind == Tok::Name && peek().is("(")) {
    const char *found = nullptr;
    for (auto &w : kWays)
      if (tok().isName(w[0])) found = w[1];
    if (!found)
      return fail(tok(), fmt::format("SPOS={}(…) is not simulated (SPOS=<angle>, DC, ACP and ACN are)", tok().text),
                  "unsupported-code");
    way = found, wrapped = true;
    i_ += 2;
  }
  ExprPtr a = expr(0);
  if (!a || (wrapped && !expect(")"))) return false;
  Op o(OpKind::Spindle, loc(t));
  o.set("dir", Expr::symbol("orient"));
  o.set("angle", std::move(a));
  o.set("way", Expr::symbol(way));
  pre_.push_back(std::move(o));
  return true;
}

bool BlockParser::gcode(const std::string &name, const Token &at) {
  GInfo g = findGCode(name);
  if (!g.code) return fail(at, fmt::format("unknown G function {}", name), "unknown-code");
  if (g.act == GAct::Frame) return frameStatement(g, at);
  for (auto &o : gcodes_)
    if (o.first.code->group == g.code->group && o.first.code->group != 2 && o.first.code->group != 3)
      return fail(at, fmt::format("{} and {} are both of G group {}", o.first.code->name, name, g.code->group),
                  "modal-group-conflict");
  if (g.act == GAct::Unsupported && machineGCode(g, at)) return true;  // MachineOnly.cpp
  if (g.act == GAct::Unsupported)
    return fail(at, fmt::format("{} ({}) is not simulated", name, g.code->meaning), "unsupported-code");
  if (g.act == GAct::Units && g.arg == 2)
    return fail(at, "G70 (inch for geometry, feed stays metric) is not simulated: use G700", "unsupported-code");
  gcodes_.push_back({g, loc(at)});
  return true;
}

// TRANS X10, ATRANS, ROT Z45 / ROT RPL=30, SCALE X2, MIRROR X0 … as assignments to $P_PFRAME
// (docs/IR.md §2.4): the absolute form replaces the programmable frame, the additive one chains.
bool BlockParser::frameStatement(const GInfo &g, const Token &at) {
  SourceLoc l = loc(at);
  static const char *kBuiltin[] = {"CTRANS", "CROT", "CSCALE", "CMIRROR", "CROTS"};
  FrameKind k = (FrameKind)g.arg;
  std::vector<ExprPtr> args;
  while (!atEnd()) {
    const Token &t = tok();
    if (k == FrameKind::Rot && t.isName("RPL") && peek().is("=")) {
      i_ += 2;
      static const char *kNormal[] = {"Z", "Y", "X"};  // G17, G18, G19
      int p = f_.plane == ModeValue::XY ? 0 : f_.plane == ModeValue::ZX ? 1 : 2;
      ExprPtr v = expr(0);
      if (!v) return false;
      args.push_back(Expr::string(kNormal[p], l));
      args.push_back(std::move(v));
      continue;
    }
    const AddrInfo *a = t.kind == Tok::Name ? findAddress(t.text.substr(0, t.digitsAt)) : nullptr;
    if (!a || a->kind != Addr::Axis || (t.text.size() > 1 && t.digitsAt != 1))
      return fail(t, fmt::format("{} takes axis words only (and must stand alone in its block)", g.code->name));
    std::string axis = t.text.substr(0, 1);
    ExprPtr v;
    if (t.digitsAt == 1 && t.text.size() > 1) {  // Z45; Z alone is followed by =, a sign or a value
      v = Expr::number(t.num, t.isInt ? ir::Type::Int : ir::Type::Real, loc(t));
      ++i_;
    } else if (peek().is("=")) {
      i_ += 2;
      v = expr(0);
    } else {
      ++i_;
      v = unary();
    }
    if (!v) return false;
    args.push_back(Expr::string(axis, l));
    if (k != FrameKind::Mirror) args.push_back(std::move(v));  // MIRROR X0: the value does not count
  }
  if (!words_.empty() || !gcodes_.empty()) return fail(at, fmt::format("{} must stand alone in its block", g.code->name));
  ExprPtr f = Expr::call(kBuiltin[(int)k], std::move(args), l);
  auto pf = Expr::var(ir::VarSpace::System, "_pframe", nullptr, l);
  if (g.additive) f = callOf("FRAME_CHAIN", l, pf->clone(), std::move(f));
  pre_.push_back(assignOp(std::move(pf), std::move(f), l));
  return true;
}

// NAME, NAME(args), NAME P3, L10 P=2, CALL "NAME", MCALL NAME(args), MCALL. A Siemens standard
// cycle the program has no subprogram for runs from the cycle library (Cycles.cpp).
bool BlockParser::callStatement(bool modal) {
  const Token &first = tok();
  SourceLoc l = loc(first);
  bool viaCall = first.isName("CALL");
  if (modal || viaCall) ++i_;
  Op c(modal ? OpKind::ModalCall : OpKind::Call, l);
  if (modal && atEnd()) {  // MCALL alone: cancel (a subprogram's or a cycle's)
    post_.push_back(std::move(c));
    post_.push_back(cycleCancel(l));
    return true;
  }
  const Token &t = tok();
  std::string name, type;
  if (viaCall && t.isName("BLOCK")) return sectionCall(nullptr, l);  // CALL BLOCK A TO B: this program's section
  if (viaCall && t.kind == Tok::Name && f_.vars.count(t.text) && peek().is("("))  // CALL PROGNAME(1)
    return fail(peek(), "an indirect CALL takes no arguments and stands alone in its block (L8554)");
  if (viaCall) {
    ExprPtr e = expr(0);
    if (!e) return false;
    if (tok().isName("BLOCK")) return sectionCall(std::move(e), l);
    if (e->kind != ir::ExprKind::String) return computedCall(std::move(e), t, l);
    name = calledProgram(e->str, type);
  } else {
    if (t.kind != Tok::Name) return fail(t, "expected a subprogram name");
    name = t.text[0] == '_' ? calledProgram(t.text, type) : t.text;
    ++i_;
  }
  if (!type.empty()) name = "_N_" + name + "_" + type;  // the key of a call that named its file type
  if (name.size() < 2 || name[0] == '$')
    return fail(t, fmt::format("unknown address or name '{}'", name), "unknown-code");
  CycleSignature lib;
  const Signature *sig = f_.pp.callee(name, loc(t), &lib, type);
  if (!sig && lib.name) return libraryCycle(modal, name, lib, t);
  if (!sig) {
    failed_ = true;
    return false;
  }
  c.set("callee", Expr::string(name));
  if (!modal) c.set("frame", Expr::symbol("new"));
  std::vector<std::string> params;
  for (auto &p : sig->params) params.push_back(p.name);
  if (!argumentList(name, params, "a.", c)) return false;
  if (tok().kind == Tok::Name && tok().text[0] == 'P' && (tok().digitsAt == 1 || (tok().text == "P" && peek().is("=")))) {
    if (tok().digitsAt == 1) {
      c.set("count", Expr::number(tok().num, ir::Type::Int));
      ++i_;
    } else {
      i_ += 2;
      ExprPtr n = expr(0);
      if (!n) return false;
      c.set("count", std::move(n));
    }
  }
  if (modal && sig->retTarget)
    return fail(t, fmt::format("MCALL of {}, which returns with RET(target), is not simulated", name), "unsupported-code");
  if (modal) post_.push_back(cycleCancel(l));  // the last modal call replaces a modal cycle
  post_.push_back(std::move(c));
  if (sig->retTarget) resumeAfterCall(l);
  return true;
}

// `(a, , c)` after a called name, if there: argument i to key prefix + params[i]; an empty
// position is an omitted argument.
bool BlockParser::argumentList(const std::string &name, const std::vector<std::string> &params, const char *prefix,
                               Op &c) {
  if (!tok().is("(")) return true;
  ++i_;
  size_t pos = 0;
  while (!tok().is(")")) {
    if (tok().is(",")) {  // an omitted argument: the default
      ++pos;
      ++i_;
      continue;
    }
    if (pos >= params.size())
      return fail(tok(), fmt::format("too many arguments for {} ({} parameter{})", name, params.size(),
                                     params.size() == 1 ? "" : "s"));
    ExprPtr e = expr(0);
    if (!e) return false;
    c.set(prefix + params[pos], std::move(e));
    ++pos;
    if (tok().is(",")) {
      ++i_;
      if (tok().is(")")) break;
    } else if (!tok().is(")")) {
      return fail(tok(), "expected ',' or ')' in the argument list");
    }
  }
  ++i_;
  return true;
}

}  // namespace ncc::sin

namespace ncc::sin {

// The list of a polynomial, `(end, a2, …, a5)`, at the current token.
bool BlockParser::polyTerm(std::string axis, const Token &at) {
  if (tok().isName("IC") || tok().isName("AC"))
    return fail(tok(), "PO with IC()/AC() is not simulated (write absolute end points)", "unsupported-code");
  if (!expect("(")) return false;
  PolyTerm p{std::move(axis), {}};
  do {
    ExprPtr v = expr(0);
    if (!v) return false;
    p.values.push_back(std::move(v));
  } while (tok().is(",") && (++i_, true));
  if (!expect(")")) return false;
  if (p.values.size() > 5) return fail(at, "a polynomial has its end value and at most the coefficients a2 … a5");
  for (auto &o : poly_)
    if (o.axis == p.axis) return fail(at, "a polynomial is programmed twice for the same axis in the block", "duplicate-word");
  poly_.push_back(std::move(p));
  return true;
}

// The block's polynomials: the end values become the axis words (the denominator's: `denominator`),
// the coefficients a_k one move op each with `poly_index` k before the block's move.
bool BlockParser::lowerPoly(ir::Region &out, ExprPtr &denominator) {
  SourceLoc bl = loc(t_[0]);
  for (int k = 2; k <= 5; ++k) {
    Op o(OpKind::Move, bl);
    for (auto &p : poly_)
      if (p.values.size() >= (size_t)k) o.set(p.axis.empty() ? "denominator" : p.axis, std::move(p.values[k - 1]));
    if (o.args.empty() && k > 2) continue;  // a2 always: it tells the executor the block has polynomials
    o.set("poly_index", Expr::number(k, ir::Type::Int));
    out.push_back(std::move(o));
  }
  for (auto &p : poly_) {
    if (p.axis.empty()) {
      denominator = std::move(p.values[0]);
      continue;
    }
    for (auto &o : words_)
      if (o.addr == p.axis) return fail(t_[0], fmt::format("address {} is programmed twice in the block", p.axis), "duplicate-word");
    words_.push_back(Word{p.axis, std::move(p.values[0]), 0, bl});
  }
  return true;
}

}  // namespace ncc::sin
