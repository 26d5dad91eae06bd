// FK free contour programming (HEI-MOT-09): FPOL, FL, FLT, FC, FCT and FSELECT. The FK words are
// read into the solver's data (numbers only: the contour is solved when the program is read);
// the rest of the block (X Y, PR PA, R, DR, RL/RR, F, M) is read as in L and C. An element is
// lowered, as an L or C move with its block's feed, M functions and compensation, once one
// solution is left; a non-FK block (or the end of the file) needs the chain solved.
#include "frontend/heidenhain/Fk.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace ncc::hei {

namespace {
// Data words of FK blocks ncc solves, and those it reads but does not solve yet.
const char *const kFkWords[] = {"LEN", "AN", "CCX", "CCY", "CCPR", "CCPA", "PDX", "PDY", "D"};
const char *const kFkNotYet[] = {"IAN", "ICCX", "ICCY", "ICCPR", "ICCPA", "IPDX", "IPDY", "RX",  "RY",
                                 "RAN", "RLEN", "RCCX", "RCCY",  "RPR",   "RPA",  "CLSD", "CCA", "ILEN"};
const char *const kFkComputed = "FK data from a Q parameter are not simulated (the contour is solved when the program is read)";
constexpr double kDeg = 3.14159265358979323846 / 180;

bool listed(const char *const *b, const char *const *e, const std::string &w) {
  for (; b != e; ++b)
    if (w == *b) return true;
  return false;
}
fk::Pt aboutPole(fk::Pt pole, double pr, double pa) {
  return {pole.x + pr * std::cos(pa * kDeg), pole.y + pr * std::sin(pa * kDeg)};
}
std::string elementName(const FkPending &p) {
  return fmt::format("{} (block {})", p.block->toks[0].text, p.block->number);
}
// A solved coordinate as a number: rounded to 1e-10 mm, so that 57.49999999999999 is 57.5.
ExprPtr solved(double v) { return num(std::round(v * 1e10) / 1e10); }
}  // namespace

FkChain &FileParser::fkChain() {
  if (!fk) fk = std::make_shared<FkChain>();
  return *fk;
}

bool FileParser::fkLower() {
  FkChain &c = *fk;
  if (c.hyps.size() != 1) return true;
  bool ok = true;
  for (const fk::Element &el : c.hyps[0].done) {
    FkPending &p = *c.elems[el.index];
    BlockParser bp(*this, *p.block);
    ok = bp.fkLowerElement(el, p.words) && ok;
    c.lowered = el.index + 1;
  }
  c.hyps[0].done.clear();
  return ok;
}

bool FileParser::fkFinish(SourceLoc at, const std::string &what) {
  if (!fk || fk->hyps.empty()) return true;
  FkChain &c = *fk;
  bool ok = true;
  auto where = [&](const FkPending &p) { return SourceLoc{file, p.block->toks[0].line, p.block->toks[0].col}; };
  if (c.hyps.size() > 1) {
    const FkPending &p = *c.elems[c.lowered];
    ok = error(where(p), fmt::format("{} is ambiguous: the FK contour has {} solutions where it continues with {} (line {}); "
                                     "FSELECT 1 … {} picks one",
                                     elementName(p), c.hyps.size(), what, at.line, c.hyps.size()),
               "contour-invalid");
  } else if (c.hyps[0].open) {
    const FkPending &p = *c.elems[c.hyps[0].open->index];
    ok = error(where(p), fmt::format("{} is not determined: its end is still open where the contour continues with {} (line {})",
                                     elementName(p), what, at.line),
               "contour-invalid");
  } else {
    ok = fkLower();
  }
  c.here = ok ? std::optional<fk::Pt>(c.hyps[0].at) : std::nullopt;
  c.heading = ok ? c.hyps[0].heading : std::nullopt;
  c.hyps.clear();
  c.elems.clear();
  c.lowered = 0;
  return ok;
}

bool BlockParser::fkElement() {
  const std::string kw = t_[0].text;
  bool arc = kw == "FC" || kw == "FCT";
  if (f_.m89) return fail(t_[0], "M89 with FK programming: the TNC does not allow it (L905-L907)", "unsupported-code");
  // The FK data words (LEN AN CCX … D, P1X … P3Y) are taken out; the rest is read as in L and C.
  std::map<std::string, std::pair<double, SourceLoc>> data;
  std::vector<Token> rest{t_[0]};
  while (!atEnd()) {
    const Token &t = tok();
    std::string name = t.kind == Tok::Word ? t.text : "";
    size_t skip = 1;
    if (name == "P" && peek().kind == Tok::Number && peek().isInt && peek().num >= 1 && peek().num <= 3 &&
        (peek(2).isWord("X") || peek(2).isWord("Y"))) {
      name = fmt::format("P{}{}", (int)peek().num, peek(2).text);
      skip = 3;
    } else if (!listed(std::begin(kFkWords), std::end(kFkWords), name)) {
      if (listed(std::begin(kFkNotYet), std::end(kFkNotYet), name))
        return fail(t, fmt::format("the FK word {} is not simulated yet", name), "unsupported-code");
      rest.push_back(t);
      ++i_;
      continue;
    }
    SourceLoc l = loc(t);
    if (data.count(name)) return fail(t, fmt::format("{} twice in one block", name), "duplicate-word");
    i_ += skip;
    ExprPtr v = signedValue();
    if (!v) return false;
    if (v->kind != ir::ExprKind::Number)
      return f_.error(l, kFkComputed, "unsupported-code");
    data[name] = {v->num, l};
  }
  rest.push_back(tok());
  b_.toks = std::move(rest);
  i_ = 1;
  PathWords w;
  if (!words(w, kCoords | kPolar | kComp | kFeed | kM | (arc ? kDir | kRadius : 0), kw.c_str())) return false;

  fk::Data e;
  e.arc = arc;
  e.tangent = kw.back() == 'T';
  e.dr = w.dr;
  auto has = [&](const char *n) { return data.count(n) > 0; };
  auto val = [&](const char *n) { return data.at(n).first; };
  auto refuse = [&](const char *n, const std::string &why, const char *rule = "syntax") {
    return f_.error(data.at(n).second, why, rule);
  };
  FkChain &c = f_.fkChain();
  auto needPole = [&](const char *n) {
    return c.pole || refuse(n, fmt::format("{} is polar about the FK pole: FPOL must come first", n), "missing-word");
  };
  for (const char *n : {"CCX", "CCY", "CCPR", "CCPA"})
    if (has(n) && !arc) return refuse(n, fmt::format("{} gives a circle's centre: not in {}", n, kw));
  for (const char *n : {"LEN", "AN"})
    if (has(n) && arc)
      return refuse(n, fmt::format("{} in {} (the chord length, the entry tangent's angle) is not simulated yet", n, kw), "unsupported-code");
  for (auto &co : w.coords) {
    if (co.axis != 'X' && co.axis != 'Y') return f_.error(co.loc, fmt::format("{} lies in the working plane (X, Y)", kw));
    if (co.inc) return f_.error(co.loc, "incremental FK data (IX, IY) are not simulated yet", "unsupported-code");
    if (co.value->kind != ir::ExprKind::Number)
      return f_.error(co.loc, kFkComputed,
                      "unsupported-code");
    (co.axis == 'X' ? e.x : e.y) = co.value->num;
  }
  if (w.pr || w.pa) {
    SourceLoc l = w.pr ? w.prLoc : w.paLoc;
    if (!w.pr || !w.pa) return f_.error(l, "an FK end point in polar coordinates needs PR and PA", "unsupported-code");
    if (w.prInc || w.paInc) return f_.error(l, "incremental FK data (IPR, IPA) are not simulated yet", "unsupported-code");
    if (w.pr->kind != ir::ExprKind::Number || w.pa->kind != ir::ExprKind::Number)
      return f_.error(l, kFkComputed, "unsupported-code");
    if (e.x || e.y) return f_.error(l, "an FK end point in X/Y and in PR/PA", "syntax");
    if (!c.pole) return f_.error(l, "PR/PA in FK are polar about the FK pole: FPOL must come first", "missing-word");
    fk::Pt p = aboutPole(*c.pole, w.pr->num, w.pa->num);
    e.x = p.x;
    e.y = p.y;
  }
  if (w.radius) {
    if (w.radius->kind != ir::ExprKind::Number || w.radius->num <= 0)
      return f_.error(w.radiusLoc, "R in FK is a positive number", "unsupported-code");
    e.r = w.radius->num;
  }
  if (arc && !w.dr) return fail(t_[0], fmt::format("{} needs the direction DR+ or DR-", kw), "missing-word");
  if (arc && w.fmax) return f_.error(w.feedLoc, "FMAX on an arc: the TNC moves arcs at a feed", "syntax");
  if (has("LEN")) e.len = val("LEN");
  if (has("AN")) e.an = val("AN");
  if (has("CCX")) e.cx = val("CCX");
  if (has("CCY")) e.cy = val("CCY");
  if (has("CCPR") || has("CCPA")) {
    const char *one = has("CCPR") ? "CCPR" : "CCPA";
    if (!has("CCPR") || !has("CCPA")) return refuse(one, "a polar circle centre needs CCPR and CCPA", "missing-word");
    if (e.cx || e.cy) return refuse(one, "a circle centre in CCX/CCY and in CCPR/CCPA");
    if (!needPole(one)) return false;
    fk::Pt cc = aboutPole(*c.pole, val("CCPR"), val("CCPA"));
    e.cx = cc.x;
    e.cy = cc.y;
  }
  if (has("PDX") || has("PDY") || has("D")) {
    const char *one = has("PDX") ? "PDX" : has("PDY") ? "PDY" : "D";
    if (!has("PDX") || !has("PDY") || !has("D")) return refuse(one, "a distance from a point needs PDX, PDY and D", "missing-word");
    if (val("D") < 0) return refuse("D", "D is a distance (not negative)");
    e.pd = fk::Pt{val("PDX"), val("PDY")};
    e.d = val("D");
  }
  for (int k = 1; k <= 3; ++k) {
    std::string px = fmt::format("P{}X", k), py = fmt::format("P{}Y", k);
    if (has(px.c_str()) != has(py.c_str()))
      return refuse(has(px.c_str()) ? px.c_str() : py.c_str(), fmt::format("P{} needs P{}X and P{}Y", k, k, k), "missing-word");
    if (has(px.c_str())) e.through.push_back({val(px.c_str()), val(py.c_str())});
  }
  if (e.through.size() > (arc ? 3u : 2u)) return fail(t_[0], fmt::format("{} takes at most {} points P1…", kw, arc ? 3 : 2));

  // Extend every way the contour may go by this element.
  if (c.hyps.empty()) {
    if (!c.here)
      return fail(t_[0], fmt::format("{} starts an FK contour where the position is not known when the program is read "
                                     "(the block before must reach absolute X and Y)", kw), "unsupported-code");
    c.hyps.push_back({{}, std::nullopt, *c.here, c.heading});
  }
  size_t index = c.elems.size();
  c.elems.push_back(std::make_unique<FkPending>(FkPending{&b_, std::move(w), arc}));
  std::vector<fk::Hyp> next;
  std::string why;
  bool undetermined = false;
  for (const fk::Hyp &h : c.hyps) {
    bool u = false;
    for (fk::Hyp &n : fk::extend(h, e, index, why, u)) next.push_back(std::move(n));
    undetermined = undetermined || u;
  }
  std::string name = elementName(*c.elems.back());
  if (undetermined || next.empty()) {
    c.hyps.clear();
    c.elems.clear();
    c.here.reset();
    if (undetermined)
      return fail(t_[0], fmt::format("{} is not simulated: {} (ncc solves an FK element whose own data and start fix it)", name, why),
                  "unsupported-code");
    return fail(t_[0], fmt::format("{} cannot be solved: {}", name, why), "contour-invalid");
  }
  c.hyps = std::move(next);
  return f_.fkLower();
}

bool BlockParser::fkPole() {
  PathWords w;
  if (!words(w, kCoords, "FPOL")) return false;
  fk::Pt p;
  for (char a : {'X', 'Y'}) {
    const Coord *co = w.find(a);
    if (!co) return fail(t_[0], "FPOL needs X and Y", "missing-word");
    if (co->inc || co->value->kind != ir::ExprKind::Number)
      return f_.error(co->loc, "FPOL takes absolute numbers (the contour is solved when the program is read)", "unsupported-code");
    (a == 'X' ? p.x : p.y) = co->value->num;
  }
  if (w.coords.size() != 2) return f_.error(w.coords.back().loc, "FPOL takes X and Y only");
  f_.fkChain().pole = p;
  return true;
}

bool BlockParser::fkSelect() {
  const Token &n = tok();
  if (n.kind != Tok::Number || !n.isInt || peek().kind != Tok::End) return fail(n, "FSELECT takes the number of a solution");
  FkChain &c = f_.fkChain();
  if (c.hyps.empty()) return fail(t_[0], "FSELECT without an FK element before it", "contour-invalid");
  if (n.num < 1 || n.num > c.hyps.size())
    return fail(n, fmt::format("FSELECT {}: the FK contour has {} solution{} here", (int)n.num, c.hyps.size(),
                               c.hyps.size() == 1 ? "" : "s"), "contour-invalid");
  fk::Hyp pick = std::move(c.hyps[(size_t)n.num - 1]);
  c.hyps.clear();
  c.hyps.push_back(std::move(pick));
  return f_.fkLower();
}

// A solved element: an L or a C about its centre, with its block's words.
// An element solved at a later block gets its own block's `block` op again first, so that the
// trace and the diagnostics name its block.
bool BlockParser::fkLowerElement(const fk::Element &e, PathWords &w) {
  for (size_t k = out().size(); k-- > 0;)
    if (out()[k].kind == OpKind::Block) {
      if (out()[k].loc.line != b_.line) out().push_back(blockOp());
      break;
    }
  if (!emitBefore(w)) return false;
  Op mv(OpKind::Move);
  mv.set("X", solved(e.end.x));
  mv.set("Y", solved(e.end.y));
  if (e.k.arc) {
    mv.set("I", solved(e.k.c.x));
    mv.set("J", solved(e.k.c.y));
    mv.set("ac", Expr::symbol("IJ"));
  }
  w.coords.clear();
  const char *motion = !e.k.arc ? "linear" : e.k.dr > 0 ? "arc_ccw" : "arc_cw";
  return emitMove(std::move(mv), w, motion) && emitAfter(w);
}

// Where an L leaves the contour when its words are numbers (FK starts there), and its direction.
void BlockParser::fkFollowLine(const PathWords &w) {
  FkChain &c = f_.fkChain();
  std::optional<fk::Pt> from = c.here;
  double xy[2];
  bool known = true, moved = false;
  for (int k = 0; k < 2; ++k) {
    const Coord *co = w.find(k == 0 ? 'X' : 'Y');
    double before = from ? (k == 0 ? from->x : from->y) : 0;
    if (!co) {
      known = known && from.has_value();
      xy[k] = before;
    } else if (co->value->kind != ir::ExprKind::Number || (co->inc && !from)) {
      known = false;
    } else {
      xy[k] = co->inc ? before + co->value->num : co->value->num;
      moved = true;
    }
  }
  if (!known) {
    c.here.reset();
    c.heading.reset();
    return;
  }
  fk::Pt to{xy[0], xy[1]};
  if (moved) {
    double len = from ? std::hypot(to.x - from->x, to.y - from->y) : 0;
    c.heading = len > 1e-9 ? std::optional<fk::Pt>(fk::Pt{(to.x - from->x) / len, (to.y - from->y) / len}) : c.heading;
    if (!from) c.heading.reset();
  }
  c.here = to;
}

}  // namespace ncc::hei
