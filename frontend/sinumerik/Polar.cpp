// Polar coordinates: the pole (G110 relative to the last programmed position, G111 to the
// workpiece origin, G112 to the last pole) and moves given by AP= (angle, degrees) and RP=
// (radius) about it. The pole, AP and RP live in program-wide variables (%%_SIN_POLE1/2, %%_SIN_AP,
// %%_SIN_RP, declared in the main program when some file uses them); a move becomes the plane's
// axis words (and for G2/G3 the centre words, the pole) as absolute values (`ac=`).
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpCode;

namespace {
// The plane's axes (abscissa, ordinate) and their centre words.
struct PlaneAxes {
  const char *a1, *a2, *c1, *c2;
};
const PlaneAxes kPlanes[] = {{"X", "Y", "I", "J"}, {"Z", "X", "K", "I"}, {"Y", "Z", "J", "K"}};
const PlaneAxes &planeAxes(ModeValue p) { return kPlanes[p == ModeValue::XY ? 0 : p == ModeValue::ZX ? 1 : 2]; }

const char *const kPole[] = {"_SIN_POLE1", "_SIN_POLE2"};
constexpr const char *kAp = "_SIN_AP", *kRp = "_SIN_RP";

ExprPtr global(const char *name, SourceLoc l) { return Expr::var(ir::VarSpace::Global, name, nullptr, l); }

// base + r cos(a) (k = 0) or base + r sin(a) (k = 1).
ExprPtr polarPoint(int k, ExprPtr base, ExprPtr r, ExprPtr a, SourceLoc l) {
  ExprPtr trig = callOf(k ? "SIN" : "COS", l, std::move(a));
  return Expr::binary(OpCode::Add, std::move(base), Expr::binary(OpCode::Mul, std::move(r), std::move(trig), l), l);
}
}  // namespace

void declarePolarState(ir::Region &mainBody) {
  std::vector<Op> decls;
  for (const char *n : {kPole[0], kPole[1], kAp, kRp}) {
    Op d(ir::OpKind::Declare, {});
    d.set("var", global(n, {}));
    d.set("type", Expr::symbol("real"));
    d.set("init", Expr::number(0, ir::Type::Real));
    decls.push_back(std::move(d));
  }
  mainBody.insert(mainBody.begin(), std::make_move_iterator(decls.begin()), std::make_move_iterator(decls.end()));
}

BlockParser::Word *BlockParser::findWord(std::string_view addr) {
  for (auto &w : words_)
    if (w.addr == addr) return &w;
  return nullptr;
}

ExprPtr BlockParser::takeWord(std::string_view addr, char *mode) {
  Word *w = findWord(addr);
  if (!w) return nullptr;
  w->addr.clear();
  if (mode) *mode = w->mode;
  return std::move(w->value);
}

// G110/G111/G112 with the plane's axes or AP= RP=, alone in its block (the pole is set at run time).
bool BlockParser::lowerPole(const GInfo &g, ir::Region &out) {
  const PlaneAxes &p = planeAxes(f_.plane);
  const char *name = g.code->name;
  SourceLoc l = loc(t_[0]);
  if (gcodes_.size() > 1 || !mcodes_.empty())
    return fail(t_[0], fmt::format("{} (a pole) must stand alone in its block", name));
  if (g.arg == 2 && !f_.poleKnown)
    return fail(t_[0], fmt::format("{} after a plane change: set the pole with G110 or G111 first (the pole of the "
                                   "old plane is not carried over)", name), "unsupported-code");
  char m1 = 0, m2 = 0, ma = 0, mr = 0;
  ExprPtr v[2] = {takeWord(p.a1, &m1), takeWord(p.a2, &m2)};
  ExprPtr ap = takeWord("AP", &ma), rp = takeWord("RP", &mr);
  for (auto &w : words_)
    if (!w.addr.empty())
      return fail(t_[0], fmt::format("{} takes the plane's axes {} {} or AP= RP= only, found {}", name, p.a1, p.a2, w.addr));
  if (m1 || m2 || ma || mr) return fail(t_[0], fmt::format("AC()/IC() in a pole definition ({}) is not simulated", name), "unsupported-code");
  bool polar = ap || rp;
  if (polar && (v[0] || v[1])) return fail(t_[0], fmt::format("{} takes either axis positions or AP= RP=", name));
  if (polar && !(ap && rp)) return fail(t_[0], fmt::format("a pole in polar coordinates needs both AP= and RP= ({})", name), "missing-word");
  if (!polar && !v[0] && !v[1]) return fail(t_[0], fmt::format("{} needs the pole's position", name), "missing-word");
  static const char *const kPos[] = {"_x", "_y", "_z"};
  for (int k = 0; k < 2; ++k) {
    const char *axis = k ? p.a2 : p.a1;
    ExprPtr base = g.arg == 0   ? Expr::var(ir::VarSpace::System, kPos[axis[0] == 'X' ? 0 : axis[0] == 'Y' ? 1 : 2], nullptr, l)
                   : g.arg == 1 ? Expr::number(0, ir::Type::Real, l)
                                : global(kPole[k], l);
    ExprPtr value = polar ? polarPoint(k, std::move(base), rp->clone(), ap->clone(), l)
                    : v[k] ? Expr::binary(OpCode::Add, std::move(base), std::move(v[k]), l)
                           : std::move(base);
    out.push_back(assignOp(global(kPole[k], l), std::move(value), l));
  }
  f_.poleKnown = true;
  f_.apKnown = false;  // the angle is kept until a new pole (PGsl "AP")
  f_.pp.polar = true;
  return true;
}

// A G0/G1/G2/G3 move with AP= and/or RP=: the end point about the pole; G2/G3 turn about it.
bool BlockParser::lowerPolarMove(ir::Op &mv, std::string &ac, ir::Region &out) {
  const PlaneAxes &p = planeAxes(f_.plane);
  SourceLoc l = loc(t_[0]);
  if (f_.motion == ModeValue::ArcThrough || f_.motion == ModeValue::ArcTangent)
    return fail(t_[0], "AP=/RP= with CIP or CT is not simulated", "unsupported-code");
  if (!f_.poleKnown)
    return fail(t_[0], "AP=/RP= after a plane change: set the pole with G110 or G111 first", "unsupported-code");
  if (findWord(p.a1) || findWord(p.a2))
    return fail(t_[0], fmt::format("AP=/RP= give the end point in the plane: {} and {} cannot be programmed with them", p.a1, p.a2));
  bool arc = f_.motion == ModeValue::ArcCW || f_.motion == ModeValue::ArcCCW;
  if (arc && (findWord(p.c1) || findWord(p.c2) || findWord("CR") || findWord("AR")))
    return fail(t_[0], fmt::format("a G2/G3 in polar coordinates turns about the pole: {} {}, CR= and AR= are not taken with AP=/RP=", p.c1, p.c2));
  char ma = 0, mr = 0;
  ExprPtr ap = takeWord("AP", &ma), rp = takeWord("RP", &mr);
  if (ap) {
    if (ma == 'I' && !f_.apKnown)
      return fail(t_[0], "AP=IC() needs the angle programmed before it (since the last pole or plane change, in this program)", "missing-word");
    if (!ma && f_.distance != ModeValue::Absolute)
      return fail(t_[0], "AP= under G91 (or before G90 in a subprogram): write AP=AC(…) or AP=IC(…)", "unsupported-code");
    if (ma == 'I') ap = Expr::binary(OpCode::Add, global(kAp, l), std::move(ap), l);
    out.push_back(assignOp(global(kAp, l), std::move(ap), l));
    f_.apKnown = true;
  } else if (!f_.apKnown) {
    return fail(t_[0], "AP= must be programmed after a pole definition or plane change (and in each program)", "missing-word");
  }
  if (rp) {
    if (mr) return fail(t_[0], "RP= is always an absolute radius: AC()/IC() are not taken", "unsupported-code");
    if (rp->kind == ir::ExprKind::Number && rp->num < 0) return fail(t_[0], "RP= (the polar radius) must not be negative", "arc-invalid");
    out.push_back(assignOp(global(kRp, l), std::move(rp), l));
  }
  for (int k = 0; k < 2; ++k) mv.set(k ? p.a2 : p.a1, polarPoint(k, global(kPole[k], l), global(kRp, l), global(kAp, l), l));
  ac += std::string(p.a1) + p.a2;
  if (arc) {
    mv.set(p.c1, global(kPole[0], l));
    mv.set(p.c2, global(kPole[1], l));
    ac += std::string(p.c1) + p.c2;
  }
  f_.pp.polar = true;
  return true;
}

}  // namespace ncc::sin
