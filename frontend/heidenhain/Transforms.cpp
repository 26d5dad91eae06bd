// The coordinate transformation cycles on the core's programmable frame (docs/HEIDENHAIN.md
// "Transformations"): 7 DATUM SHIFT (local shift), 10 ROTATION, 8 MIRROR IMAGE, 11 SCALING and
// 26 AXIS-SPECIFIC SCALING. The TNC keeps one value of each (digest §4), kept in program-wide
// variables; every definition takes the active rotation, scaling and mirror off, changes its
// value and puts them back, because the core refuses a shift under them. The slots combine in the
// digest's order (combine=ordered: 26 and 11, then 8, then 10, all about the datum).
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

namespace ncc::hei {

const char *const kScl = "_HEI_SCL";  // cycle 11's factor (1: off)
const char *const kAxisScl[3] = {"_HEI_SCLX", "_HEI_SCLY", "_HEI_SCLZ"};  // cycle 26's factors
const char *const kAxisCc[3] = {"_HEI_CCSX", "_HEI_CCSY", "_HEI_CCSZ"};   // … and centres
const char *const kMirror[2] = {"_HEI_MIRX", "_HEI_MIRY"};                // cycle 8: 1 = mirrored

namespace {
const char *const kAxis[3] = {"X", "Y", "Z"};

ExprPtr bin(OpCode op, ExprPtr a, ExprPtr b, SourceLoc l) { return Expr::binary(op, std::move(a), std::move(b), l); }
ExprPtr g(const char *v, SourceLoc l) { return hglobal(v, l); }

ExprPtr rotated(SourceLoc l) { return bin(OpCode::Ne, g(kRot, l), num(0), l); }
ExprPtr scaled(SourceLoc l) {
  ExprPtr e = bin(OpCode::Ne, g(kScl, l), num(1), l);
  for (const char *k : kAxisScl) e = bin(OpCode::Or, std::move(e), bin(OpCode::Ne, g(k, l), num(1), l), l);
  return e;
}
ExprPtr mirrored(SourceLoc l) {
  return bin(OpCode::Or, bin(OpCode::Ne, g(kMirror[0], l), num(0), l), bin(OpCode::Ne, g(kMirror[1], l), num(0), l), l);
}

Op when(ExprPtr cond, Op inner, SourceLoc l) {
  Op c(OpKind::If, l);
  c.set("cond", std::move(cond));
  c.regions.emplace_back();
  c.regions[0].push_back(std::move(inner));
  return c;
}

Op slotOp(const char *slot, bool set, SourceLoc l) {
  Op o(OpKind::Frame, l);
  o.set("slot", Expr::symbol(slot));
  o.set("action", Expr::symbol(set ? "set" : "cancel"));
  if (set) o.set("combine", Expr::symbol("ordered"));
  return o;
}

Op abortOp(const char *text, SourceLoc l) {
  Op m(OpKind::Message, l);
  m.set("text", Expr::string(text, l));
  m.set("kind", Expr::symbol("abort"));
  return m;
}
}  // namespace

void frameTakeOff(ir::Region &out, SourceLoc l) {
  out.push_back(when(rotated(l), slotOp("rotation", false, l), l));
  out.push_back(when(scaled(l), slotOp("scale", false, l), l));
  out.push_back(when(mirrored(l), slotOp("mirror", false, l), l));
}

// Puts the active scaling, mirror and rotation back. Cycle 11 scales about the datum, cycle 26
// about its centre: together they are one scaling only when 26's centre is the datum on its
// scaled axes (a centre on an axis of factor 1 does nothing and is dropped at its definition).
void framePutOn(ir::Region &out, SourceLoc l) {
  ExprPtr offCentre = bin(OpCode::Ne, g(kAxisCc[0], l), num(0), l);
  for (int i = 1; i < 3; ++i) offCentre = bin(OpCode::Or, std::move(offCentre), bin(OpCode::Ne, g(kAxisCc[i], l), num(0), l), l);
  out.push_back(when(bin(OpCode::And, bin(OpCode::Ne, g(kScl, l), num(1), l), std::move(offCentre), l),
                     abortOp("cycle 11 together with cycle 26 about a centre off the datum is not supported", l), l));
  Op rot = slotOp("rotation", true, l);
  rot.set("form", Expr::symbol("plane"));
  rot.set("X", num(0));
  rot.set("Y", num(0));
  rot.set("R", g(kRot, l));
  out.push_back(when(rotated(l), std::move(rot), l));
  Op sc = slotOp("scale", true, l);
  static const char *const kFactor[3] = {"I", "J", "K"};
  for (int i = 0; i < 3; ++i) {
    sc.set(kFactor[i], bin(OpCode::Mul, g(kScl, l), g(kAxisScl[i], l), l));
    sc.set(kAxis[i], g(kAxisCc[i], l));
  }
  out.push_back(when(scaled(l), std::move(sc), l));
  for (int i = 0; i < 2; ++i) {
    Op m = slotOp("mirror", true, l);
    m.set(kAxis[i], num(0));
    out.push_back(when(bin(OpCode::Ne, g(kMirror[i], l), num(0), l), std::move(m), l));
  }
}

// CYCL DEF 8.1 X Y (mirrored axes; none: off), 11.1 SCL f, 26.1 X f Y f [CCX c CCY c].
bool BlockParser::transformBlock(int number, const Token &n) {
  SourceLoc bl = loc(t_[0]);
  f_.pp.frames = true;
  ir::Region set;  // the state changes, between taking the frame off and putting it back
  auto inRange = [&](const char *var) {  // a factor from a Q parameter, checked when it runs
    ExprPtr bad = bin(OpCode::Or, bin(OpCode::Lt, g(var, bl), num(0.000001), bl), bin(OpCode::Gt, g(var, bl), num(99.999999), bl), bl);
    set.push_back(when(std::move(bad), abortOp("a scaling factor is 0.000001 … 99.999999", bl), bl));
  };
  auto end = [&]() {
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in CYCL DEF {}", tok().text, n.text));
    frameTakeOff(out(), bl);
    for (Op &o : set) out().push_back(std::move(o));
    framePutOn(out(), bl);
    return true;
  };
  if (number == 8) {
    bool axes[2] = {false, false};
    for (; !atEnd() && tok().kind == Tok::Word; ++i_) {
      const std::string &w = tok().text;
      if (w == "Z") return fail(tok(), "cycle 8 cannot mirror the spindle axis Z (L12815)", "frame-invalid");
      if (w != "X" && w != "Y") return fail(tok(), fmt::format("mirroring the {} axis is not simulated yet", w), "unsupported-code");
      axes[w == "Y"] = true;
    }
    for (int i = 0; i < 2; ++i) set.push_back(assignOp(g(kMirror[i], bl), num(axes[i] ? 1 : 0), bl));
    return end();
  }
  auto factor = [&](const Token &at) -> ExprPtr {  // 0.000001 … 99.999999 (L12891)
    ExprPtr v = signedValue();
    if (!v) return nullptr;
    if (v->kind == ir::ExprKind::Number && !(v->num >= 0.000001 && v->num <= 99.999999)) {
      fail(at, "a scaling factor is 0.000001 … 99.999999", "frame-invalid");
      return nullptr;
    }
    return v;
  };
  if (number == 11) {
    if (!tok().isWord("SCL")) return fail(tok(), "CYCL DEF 11.1 takes SCL");
    const Token &at = tok();
    ++i_;
    ExprPtr v = factor(at);
    if (!v) return false;
    set.push_back(assignOp(g(kScl, bl), std::move(v), bl));
    inRange(kScl);
    return end();
  }
  // Cycle 26: the named axes get their factor and centre; the others keep theirs [model].
  bool seen[3] = {false, false, false};
  ExprPtr centre[3];
  while (!atEnd()) {
    const Token &w = tok();
    bool cc = w.kind == Tok::Word && w.text.size() == 3 && w.text.rfind("CC", 0) == 0;
    std::string_view a = cc ? std::string_view(w.text).substr(2) : std::string_view(w.text);
    size_t i = std::string_view("XYZ").find(a);
    if (w.kind != Tok::Word || a.size() != 1 || i == std::string_view::npos)
      return fail(w, "CYCL DEF 26.1 takes X Y Z factors and CCX CCY CCZ centres");
    ++i_;
    if (cc) {
      if (!(centre[i] = signedValue())) return false;
      continue;
    }
    ExprPtr v = factor(w);
    if (!v) return false;
    seen[i] = true;
    set.push_back(assignOp(g(kAxisScl[i], bl), std::move(v), bl));
    inRange(kAxisScl[i]);
  }
  for (int i = 0; i < 3; ++i) {
    if (centre[i] && !seen[i]) return fail(n, fmt::format("CC{} without a factor for {}", kAxis[i], kAxis[i]));
    if (!seen[i]) continue;
    set.push_back(assignOp(g(kAxisCc[i], bl), centre[i] ? std::move(centre[i]) : num(0), bl));
    set.push_back(when(bin(OpCode::Eq, g(kAxisScl[i], bl), num(1), bl), assignOp(g(kAxisCc[i], bl), num(0), bl), bl));
  }
  return end();
}

}  // namespace ncc::hei
