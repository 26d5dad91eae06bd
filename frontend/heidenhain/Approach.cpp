// APPR and DEP: approaching and departing a compensated contour (LT tangential line, LN line
// normal to the contour, CT tangential arc, LCT line and tangential arc). [K] The cycle manual
// only names them (L10081, L10391); the geometry is the TNC 640 user manual's as written in
// docs/HEIDENHAIN.md. The approach elements are compensated contour elements where that gives the
// TNC's path (the core's compensation started with entry=normal: the first move ends normal to
// the element after it); where the TNC's point depends on the tool radius (LN, LCT, all of DEP)
// it is computed when the block runs, from $_tool_diameter.
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::hei {

// The APPR block, waiting for the first contour element (the next block) whose direction it needs.
struct Approach {
  std::string kind;  // LT LN CT LCT
  PathWords w;       // X Y (Z) PA, RL/RR, F, M
  ExprPtr len, cca;
  double radius = 0;  // CT, LCT: R
  SourceLoc loc;
};

namespace {
// Program-wide scratch values of the geometry, declared at the main program's start.
const char *const kAx = "_HEI_AX", *const kAy = "_HEI_AY";    // the contour point PA / PE
const char *const kDx = "_HEI_DX", *const kDy = "_HEI_DY";    // the element's unit direction
const char *const kNx = "_HEI_NX", *const kNy = "_HEI_NY";    // its normal to the tool's side
const char *const kTr = "_HEI_TR";                            // the tool radius
const char *const kMx = "_HEI_MX", *const kMy = "_HEI_MY";    // an arc's centre
const char *const kP0x = "_HEI_P0X", *const kP0y = "_HEI_P0Y";  // where the last L started (DEP)

ExprPtr g(const char *v, SourceLoc l) { return hglobal(v, l); }
ExprPtr bin(OpCode o, ExprPtr a, ExprPtr b, SourceLoc l) { return Expr::binary(o, std::move(a), std::move(b), l); }
ExprPtr fn1(const char *f, ExprPtr a, SourceLoc l) {
  std::vector<ExprPtr> args;
  args.push_back(std::move(a));
  return Expr::call(f, std::move(args), l);
}
ExprPtr sys(const char *n, SourceLoc l) { return Expr::var(ir::VarSpace::System, n, nullptr, l); }
// base + k * vector (vx, vy) component c
ExprPtr along(ExprPtr base, ExprPtr k, ExprPtr v, SourceLoc l) {
  return bin(OpCode::Add, std::move(base), bin(OpCode::Mul, std::move(k), std::move(v), l), l);
}

Op message(const std::string &text, SourceLoc l) {
  Op m(OpKind::Message, l);
  m.set("text", Expr::string(text, l));
  m.set("kind", Expr::symbol("abort"));
  return m;
}
// if cond: stop the run with text
Op abortIf(ExprPtr cond, const std::string &text, SourceLoc l) {
  Op o(OpKind::If, l);
  o.set("cond", std::move(cond));
  o.regions.emplace_back();
  o.regions[0].push_back(message(text, l));
  return o;
}

void linear(ExprPtr x, ExprPtr y, ExprPtr z, SourceLoc l, ir::Region &out) {
  Op mode(OpKind::Mode, l);
  mode.set("motion", Expr::symbol("linear"));
  out.push_back(std::move(mode));
  Op mv(OpKind::Move, l);
  mv.set("X", std::move(x));
  mv.set("Y", std::move(y));
  if (z) mv.set("Z", std::move(z));
  out.push_back(std::move(mv));
}

// An arc about (MX, MY) to (x, y).
void arcTo(ExprPtr x, ExprPtr y, bool ccw, SourceLoc l, ir::Region &out) {
  Op mode(OpKind::Mode, l);
  mode.set("motion", Expr::symbol(ccw ? "arc_ccw" : "arc_cw"));
  out.push_back(std::move(mode));
  Op mv(OpKind::Move, l);
  mv.set("X", std::move(x));
  mv.set("Y", std::move(y));
  mv.set("I", g(kMx, l));
  mv.set("J", g(kMy, l));
  mv.set("ac", Expr::symbol("IJ"));
  out.push_back(std::move(mv));
}

Op compOn(int side, SourceLoc l) {
  Op on(OpKind::CutterComp, l);
  on.set("side", Expr::symbol(side == 1 ? "left" : "right"));
  on.set("d_default", Expr::symbol("tool"));
  on.set("entry", Expr::symbol("normal"));
  return on;
}
Op compOff(SourceLoc l) {
  Op off(OpKind::CutterComp, l);
  off.set("side", Expr::symbol("off"));
  return off;
}

// One component of the vector (vx, vy) turned by `angle` degrees.
ExprPtr turned(ExprPtr vx, ExprPtr vy, ExprPtr angle, bool yComp, SourceLoc l) {
  ExprPtr c = fn1("COS", angle->clone(), l), s = fn1("SIN", std::move(angle), l);
  return yComp ? bin(OpCode::Add, bin(OpCode::Mul, std::move(vx), std::move(s), l), bin(OpCode::Mul, std::move(vy), std::move(c), l), l)
               : bin(OpCode::Sub, bin(OpCode::Mul, std::move(vx), std::move(c), l), bin(OpCode::Mul, std::move(vy), std::move(s), l), l);
}

// M + rot(angle) (from - M) for the point (fx, fy): one component.
ExprPtr rotated(const char *fx, const char *fy, ExprPtr angle, bool yComp, SourceLoc l) {
  ExprPtr vx = bin(OpCode::Sub, g(fx, l), g(kMx, l), l), vy = bin(OpCode::Sub, g(fy, l), g(kMy, l), l);
  return bin(OpCode::Add, g(yComp ? kMy : kMx, l), turned(std::move(vx), std::move(vy), std::move(angle), yComp, l), l);
}

// |(DX, DY)|
ExprPtr lengthD(SourceLoc l) {
  return fn1("SQRT", bin(OpCode::Add, bin(OpCode::Mul, g(kDx, l), g(kDx, l), l), bin(OpCode::Mul, g(kDy, l), g(kDy, l), l), l), l);
}
}  // namespace

// The words APPR and DEP take besides those of `words`: LEN and CCA, taken out of the block.
bool BlockParser::takeWord(const char *w, ExprPtr &out) {
  for (size_t k = i_; k + 1 < t_.size(); ++k)
    if (t_[k].isWord(w)) {
      size_t save = i_;
      i_ = k + 1;
      if (!(out = signedValue())) return false;
      t_.erase(t_.begin() + (long)k, t_.begin() + (long)i_);
      i_ = save;
      return true;
    }
  return true;
}

// R of CT and LCT: a constant (its sign decides the arc's direction when the program is read).
static bool constRadius(const ExprPtr &r, double &out) {
  if (!r || r->kind != ir::ExprKind::Number) return false;
  out = r->num;
  return true;
}

bool BlockParser::approachDepart() {
  const Token &kw = t_[0];
  bool appr = kw.isWord("APPR");
  const Token &k = tok();
  static const char *const kKinds[] = {"LT", "LN", "CT", "LCT"};
  std::string kind;
  for (const char *n : kKinds)
    if (k.isWord(n)) kind = n;
  if (kind.empty()) {
    if (k.isWord("PLT") || k.isWord("PLN") || k.isWord("PCT") || k.isWord("PLCT"))
      return fail(k, fmt::format("{} {} (polar) is not simulated yet", kw.text, k.text), "unsupported-code");
    return fail(k, fmt::format("{} takes LT, LN, CT or LCT", kw.text));
  }
  ++i_;
  auto a = std::make_shared<Approach>();
  a->kind = kind;
  a->loc = loc(kw);
  bool needLen = kind == "LT" || kind == "LN", needArc = kind == "CT" || kind == "LCT";
  if (!takeWord("LEN", a->len) || !takeWord("CCA", a->cca)) return false;
  unsigned allowed = kFeed | kM | kRadius;
  if (appr) allowed |= kCoords | kComp;
  if (!appr && kind == "LCT") allowed |= kCoords;  // DEP LCT's end point
  std::string what = fmt::format("{} {}", kw.text, kind);
  if (!words(a->w, allowed, what.c_str())) return false;
  if (needLen && !a->len) return fail(k, what + " needs LEN", "missing-word");
  if (!needLen && a->len) return fail(k, what + " takes no LEN");
  if (kind == "CT" && !a->cca) return fail(k, what + " needs CCA (the arc's angle)", "missing-word");
  if (kind != "CT" && a->cca) return fail(k, what + " takes no CCA");
  if (needArc && !a->w.radius) return fail(k, what + " needs R", "missing-word");
  if (needArc && !constRadius(a->w.radius, a->radius))
    return f_.error(a->w.radiusLoc, what + " with a computed R is not simulated yet (its sign decides the side)", "unsupported-code");
  if (needArc && a->radius == 0) return f_.error(a->w.radiusLoc, what + ": R must not be 0", "syntax");
  if (kind == "LCT" && a->radius < 0) return f_.error(a->w.radiusLoc, what + " takes a positive R", "syntax");
  if (a->w.fmax) return f_.error(a->w.feedLoc, what + " moves at a feed, not FMAX", "syntax");
  for (auto &c : a->w.coords) {
    if (c.axis != 'X' && c.axis != 'Y' && c.axis != 'Z') return f_.error(c.loc, fmt::format("{} takes X, Y and Z, not {}", what, c.axis));
    if (c.inc) return f_.error(c.loc, "incremental coordinates in " + what + " are not simulated yet", "unsupported-code");
  }
  f_.pp.approach = true;
  if (appr) {
    if (!a->w.find('X') || !a->w.find('Y')) return fail(kw, what + " needs the first contour point X and Y", "missing-word");
    if (a->w.comp <= 0) return fail(kw, what + " needs the radius compensation RL or RR", "missing-word");
    f_.approach = std::move(a);  // lowered with the next block, the first contour element
    f_.compSide = f_.approach->w.comp;
    return true;
  }
  return depart(*a);
}

// The first contour element after APPR: a straight line L or a circle C about the pole CC (dr
// its DR, 0 for L). Its direction at PA places the approach; the approach's moves come first,
// then the element.
bool BlockParser::approachBefore(PathWords &el, int dr) {
  std::shared_ptr<Approach> ap = std::move(f_.approach);
  Approach &a = *ap;
  SourceLoc l = a.loc;
  std::string what = "APPR " + a.kind;
  if (el.comp == 0 || (el.comp > 0 && el.comp != a.w.comp))
    return f_.error(l, what + ": the first contour element must keep its radius compensation", "syntax");
  // The element's `block n=` (pushed last, right after the APPR's) goes after the approach, so
  // the approach's moves are the APPR block's.
  Op elementBlock = std::move(out().back());
  out().pop_back();
  int comp = a.w.comp, side = comp == 1 ? 1 : -1;  // RL: the tool left of the path
  a.w.comp = -1;  // switched on below, with the TNC's normal entry
  ExprPtr z = a.w.find('Z') ? a.w.find('Z')->value->clone() : nullptr;
  if (!emitBefore(a.w)) return false;  // the feed and the M functions at the start
  ir::Region &o = out();
  auto set = [&](const char *v, ExprPtr e) { o.push_back(assignOp(g(v, l), std::move(e), l)); };
  // PA and the element's end P1 (a coordinate left out is PA's; IX from PA).
  set(kAx, a.w.find('X')->value->clone());
  set(kAy, a.w.find('Y')->value->clone());
  if (dr) {
    arcTangent(kAx, kAy, dr, l);
  } else {
    ExprPtr p1[2];
    for (int c = 0; c < 2; ++c) {
      const Coord *k = el.find("XY"[c]);
      const char *base = c ? kAy : kAx;
      p1[c] = !k ? g(base, l) : k->inc ? bin(OpCode::Add, g(base, l), k->value->clone(), l) : k->value->clone();
    }
    set(kDx, bin(OpCode::Sub, std::move(p1[0]), g(kAx, l), l));
    set(kDy, bin(OpCode::Sub, std::move(p1[1]), g(kAy, l), l));
  }
  unitAndNormal(side, what + ": the first contour element has no length", l);
  if (a.kind == "LT") {  // PH = PA - LEN d, on the element's line; both compensated
    o.push_back(compOn(comp, l));
    ExprPtr back = bin(OpCode::Sub, num(0, l), a.len->clone(), l);
    linear(along(g(kAx, l), back->clone(), g(kDx, l), l), along(g(kAy, l), back->clone(), g(kDy, l), l), std::move(z), l, o);
    linear(g(kAx, l), g(kAy, l), nullptr, l, o);
  } else if (a.kind == "LN") {  // the tool centre at PA + (LEN + r) n, then normal onto PA
    ExprPtr k = bin(OpCode::Add, a.len->clone(), g(kTr, l), l);
    linear(along(g(kAx, l), k->clone(), g(kNx, l), l), along(g(kAy, l), k->clone(), g(kNy, l), l), std::move(z), l, o);
    o.push_back(compOn(comp, l));
    linear(g(kAx, l), g(kAy, l), nullptr, l, o);
  } else {  // CT, LCT: an arc of radius R into PA, tangent to the element; its centre PA + R n
    bool ccw = (a.radius > 0) == (side == 1);
    set(kMx, along(g(kAx, l), num(a.radius, l), g(kNx, l), l));
    set(kMy, along(g(kAy, l), num(a.radius, l), g(kNy, l), l));
    ExprPtr hx, hy;
    if (a.kind == "CT") {  // PH: CCA back along the arc
      ExprPtr back = bin(OpCode::Mul, num(ccw ? -1 : 1, l), a.cca->clone(), l);
      hx = rotated(kAx, kAy, back->clone(), false, l);
      hy = rotated(kAx, kAy, std::move(back), true, l);
    } else {  // LCT: PH where the line from the tool's position touches the tool-centre circle
      set(kTr, bin(OpCode::Sub, num(a.radius, l), g(kTr, l), l));  // rho = R - r
      o.push_back(abortIf(bin(OpCode::Le, g(kTr, l), num(0, l), l), "APPR LCT: R is not larger than the tool radius", l));
      set(kDx, bin(OpCode::Sub, sys("_x", l), g(kMx, l), l));  // v = the tool's position - M
      set(kDy, bin(OpCode::Sub, sys("_y", l), g(kMy, l), l));
      tangentPoint(ccw ? 1 : -1, num(a.radius, l), "APPR LCT: the tool starts inside the approach arc", l, hx, hy);
    }
    o.push_back(compOn(comp, l));
    linear(std::move(hx), std::move(hy), std::move(z), l, o);
    arcTo(g(kAx, l), g(kAy, l), ccw, l, o);
  }
  moved_ = true;
  if (!emitAfter(a.w)) return false;
  out().push_back(std::move(elementBlock));
  return true;
}

// DEP after the last contour element, a straight line: its direction from where it started
// (kept before every L of a file with DEP) to the current point PE. The compensation ends
// (the tool stops normal to PE, at PE + r n), then the departure runs uncompensated.
bool BlockParser::depart(Approach &a) {
  SourceLoc l = a.loc;
  std::string what = "DEP " + a.kind;
  if (!f_.lastWasLine && !f_.lastArcDir)
    return f_.error(l, what + " after anything but a straight line L or a circle C (the last contour element) is not simulated yet",
                    "unsupported-code");
  if (f_.compSide <= 0) return f_.error(l, what + " without the radius compensation RL or RR on", "syntax");
  if (a.kind == "LCT" && (!a.w.find('X') || !a.w.find('Y'))) return f_.error(l, what + " needs the end point X and Y", "missing-word");
  int side = f_.compSide == 1 ? 1 : -1;
  ExprPtr z = a.w.find('Z') ? a.w.find('Z')->value->clone() : nullptr;
  if (!emitBefore(a.w)) return false;
  ir::Region &o = out();
  auto set = [&](const char *v, ExprPtr e) { o.push_back(assignOp(g(v, l), std::move(e), l)); };
  set(kAx, sys("_x", l));
  set(kAy, sys("_y", l));
  if (f_.lastArcDir) {  // the circle's tangent at PE
    arcTangent(kAx, kAy, f_.lastArcDir, l);
  } else {
    set(kDx, bin(OpCode::Sub, g(kAx, l), g(kP0x, l), l));
    set(kDy, bin(OpCode::Sub, g(kAy, l), g(kP0y, l), l));
  }
  unitAndNormal(side, what + ": the last contour element has no length", l);
  o.push_back(compOff(l));
  // PE_c = PE + r n: where the tool stands when the compensation ends.
  auto pec = [&](bool y) { return along(g(y ? kAy : kAx, l), g(kTr, l), g(y ? kNy : kNx, l), l); };
  if (a.kind == "LT") {  // on along the element by LEN
    linear(along(pec(false), a.len->clone(), g(kDx, l), l), along(pec(true), a.len->clone(), g(kDy, l), l), nullptr, l, o);
  } else if (a.kind == "LN") {  // normal away to PE + (LEN + r) n
    ExprPtr k = bin(OpCode::Add, a.len->clone(), g(kTr, l), l);
    linear(along(g(kAx, l), k->clone(), g(kNx, l), l), along(g(kAy, l), k->clone(), g(kNy, l), l), nullptr, l, o);
  } else {  // an arc on from PE_c about PE + R n, tangent to the element
    bool ccw = (a.radius > 0) == (side == 1);
    set(kMx, along(g(kAx, l), num(a.radius, l), g(kNx, l), l));
    set(kMy, along(g(kAy, l), num(a.radius, l), g(kNy, l), l));
    set(kAx, pec(false));  // the arc starts at PE_c: the exit move to there has no length but
    set(kAy, pec(true));   // makes the tool's position the programmed one
    linear(g(kAx, l), g(kAy, l), nullptr, l, o);
    if (a.kind == "CT") {
      ExprPtr on = bin(OpCode::Mul, num(ccw ? 1 : -1, l), a.cca->clone(), l);
      ExprPtr ex = rotated(kAx, kAy, on->clone(), false, l), ey = rotated(kAx, kAy, std::move(on), true, l);
      arcTo(std::move(ex), std::move(ey), ccw, l, o);
    } else {  // LCT: the arc to where the line to PN leaves the tool-centre circle, then the line
      set(kTr, bin(OpCode::Sub, num(a.radius, l), g(kTr, l), l));  // rho
      o.push_back(abortIf(bin(OpCode::Le, g(kTr, l), num(0, l), l), "DEP LCT: R is not larger than the tool radius", l));
      set(kDx, bin(OpCode::Sub, a.w.find('X')->value->clone(), g(kMx, l), l));  // v = PN - M
      set(kDy, bin(OpCode::Sub, a.w.find('Y')->value->clone(), g(kMy, l), l));
      ExprPtr tx, ty;
      tangentPoint(ccw ? -1 : 1, g(kTr, l), "DEP LCT: the end point lies inside the departure arc", l, tx, ty);
      arcTo(std::move(tx), std::move(ty), ccw, l, o);
      linear(a.w.find('X')->value->clone(), a.w.find('Y')->value->clone(), std::move(z), l, o);
    }
  }
  f_.compSide = 0;
  f_.lastMove = out().size() - 1;
  moved_ = true;
  return emitAfter(a.w);
}

// (DX, DY) = the direction of a circle about the pole CC at the point (px, py): the radius turned
// a quarter counter-clockwise (DR+) or clockwise (DR-).
void BlockParser::arcTangent(const char *px, const char *py, int dr, SourceLoc l) {
  ir::Region &o = out();
  f_.pp.polar = true;
  ExprPtr rx = bin(OpCode::Sub, g(px, l), hglobal(kCcX, l), l), ry = bin(OpCode::Sub, g(py, l), hglobal(kCcY, l), l);
  o.push_back(assignOp(g(kDx, l), bin(OpCode::Mul, num(-dr, l), std::move(ry), l), l));
  o.push_back(assignOp(g(kDy, l), bin(OpCode::Mul, num(dr, l), std::move(rx), l), l));
}

// (DX, DY) made a unit vector (an abort when it is 0), (NX, NY) its normal to the tool's side
// (1 left), TR the tool radius.
void BlockParser::unitAndNormal(int side, const std::string &zeroLength, SourceLoc l) {
  ir::Region &o = out();
  auto set = [&](const char *v, ExprPtr e) { o.push_back(assignOp(g(v, l), std::move(e), l)); };
  ExprPtr len = lengthD(l);
  o.push_back(abortIf(bin(OpCode::Eq, len->clone(), num(0, l), l), zeroLength, l));
  set(kTr, std::move(len));
  set(kDx, bin(OpCode::Div, g(kDx, l), g(kTr, l), l));
  set(kDy, bin(OpCode::Div, g(kDy, l), g(kTr, l), l));
  set(kNx, bin(OpCode::Mul, num(-side, l), g(kDy, l), l));
  set(kNy, bin(OpCode::Mul, num(side, l), g(kDx, l), l));
  set(kTr, bin(OpCode::Div, sys("_tool_diameter", l), num(2, l), l));
}

// The point where a line through the point M + v (v in DX, DY) touches the circle of radius
// rho (TR) about M, on the side `turn` (1: the line comes in counter-clockwise, -1: the line
// leaves a counter-clockwise arc), scaled out to radius `scale` about M: M + scale rot(turn
// alpha) v / |v|, alpha = ACOS(rho / |v|).
void BlockParser::tangentPoint(int turn, ExprPtr scale, const std::string &inside, SourceLoc l, ExprPtr &x, ExprPtr &y) {
  ir::Region &o = out();
  auto set = [&](const char *v, ExprPtr e) { o.push_back(assignOp(g(v, l), std::move(e), l)); };
  ExprPtr vl = lengthD(l);
  o.push_back(abortIf(bin(OpCode::Le, vl->clone(), g(kTr, l), l), inside, l));
  set(kNx, bin(OpCode::Mul, num(turn, l), fn1("ACOS", bin(OpCode::Div, g(kTr, l), vl->clone(), l), l), l));
  set(kNy, bin(OpCode::Div, std::move(scale), std::move(vl), l));
  auto comp = [&](bool yc) {
    return bin(OpCode::Add, g(yc ? kMy : kMx, l), bin(OpCode::Mul, g(kNy, l), turned(g(kDx, l), g(kDy, l), g(kNx, l), yc, l), l), l);
  };
  x = comp(false);
  y = comp(true);
}

// Before each L of a file with DEP: where it starts, for DEP's direction.
void BlockParser::keepLineStart() {
  if (!f_.usesDep) return;
  SourceLoc l = loc(t_[0]);
  out().push_back(assignOp(g(kP0x, l), sys("_x", l), l));
  out().push_back(assignOp(g(kP0y, l), sys("_y", l), l));
}

const char *const kApproachVars[] = {kAx, kAy, kDx, kDy, kNx, kNy, kTr, kMx, kMy, kP0x, kP0y, nullptr};

}  // namespace ncc::hei
