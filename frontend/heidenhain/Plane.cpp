// The tilted working plane (docs/HEIDENHAIN.md "Tilted working plane"): PLANE SPATIAL /
// PROJECTED / EULER / VECTOR / POINTS / RELATIV / AXIAL / RESET with SEQ, COORD ROT / TABLE ROT
// and MOVE / TURN / STAY, and cycle 19 WORKING PLANE (19.1 A B C [F ABST], L12974-L13257). Each
// becomes the core's `frame slot=tilt` (ir/FrameTilt.h); the executor computes the rotation, the
// rotary positions and the positioning (runtime/ExecutorPlane.cpp).
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

#include <map>

namespace ncc::hei {

namespace {

struct FormWords {
  const char *form;                   // the PLANE keyword
  const char *tilt;                   // its `tilt=` symbol
  std::vector<std::pair<const char *, const char *>> words;  // Klartext word -> frame word
  bool all;                           // every word is required (else: RELATIV's one, AXIAL's any)
};

// The forms and their words (TNC 640 user manual, "PLANE function"; the cycle manual shows
// only SPATIAL and RESET, L11641, L11673).
const FormWords kForms[] = {
    {"SPATIAL", "spatial", {{"SPA", "A"}, {"SPB", "B"}, {"SPC", "C"}}, true},
    {"PROJECTED", "projected", {{"PROPR", "A"}, {"PROMIN", "B"}, {"PROROT", "C"}}, true},
    {"EULER", "euler", {{"EULPR", "A"}, {"EULNU", "B"}, {"EULROT", "C"}}, true},
    {"VECTOR", "vector", {{"BX", "I"}, {"BY", "J"}, {"BZ", "K"}, {"NX", "X"}, {"NY", "Y"}, {"NZ", "Z"}}, true},
    {"POINTS", "points", {{"P1X", "X"}, {"P1Y", "Y"}, {"P1Z", "Z"}, {"P2X", "I"}, {"P2Y", "J"}, {"P2Z", "K"},
                          {"P3X", "U"}, {"P3Y", "V"}, {"P3Z", "W"}}, true},
    {"RELATIV", "relative", {{"SPA", "A"}, {"SPB", "B"}, {"SPC", "C"}}, false},
    {"AXIAL", "axial", {{"A", "A"}, {"B", "B"}, {"C", "C"}}, false},
};

}  // namespace

Op BlockParser::tiltOp(bool set, const char *form, const char *position) {
  Op o(OpKind::Frame, loc(t_[0]));
  o.set("slot", Expr::symbol("tilt"));
  o.set("action", Expr::symbol(set ? "set" : "cancel"));
  if (form) o.set("tilt", Expr::symbol(form));
  o.set("position", Expr::symbol(position));
  return o;
}

// The word at the cursor as written: letters, with POINTS' P1X read from "P" 1 "X".
std::string BlockParser::planeWord() {
  std::string w = tok().text;
  if (w == "P" && peek().kind == Tok::Number && (peek().text == "1" || peek().text == "2" || peek().text == "3") &&
      peek(2).kind == Tok::Word && peek(2).text.size() == 1) {
    w += peek().text + peek(2).text;
    i_ += 2;
  }
  ++i_;
  return w;
}

// What follows the form's values: SEQ±, COORD ROT / TABLE ROT, then MOVE [DIST n] / TURN [MB n |
// MBMAX] / STAY, with F n / FMAX for MOVE and TURN.
bool BlockParser::planePositioning(Op &o, const Token &kw) {
  std::string position;
  ExprPtr feed;
  bool fmax = false;
  SourceLoc feedAt;
  while (!atEnd()) {
    const Token &w = tok();
    if (w.isWord("SEQ")) {
      ++i_;
      if (!tok().is("+") && !tok().is("-")) return fail(tok(), "SEQ takes + or -");
      o.set("Q", num(tok().is("+") ? 1 : -1));
      ++i_;
    } else if ((w.isWord("COORD") || w.isWord("TABLE")) && peek().isWord("ROT")) {
      if (w.isWord("TABLE")) o.set("E", num(1));
      i_ += 2;
    } else if (w.isWord("MOVE") || w.isWord("TURN") || w.isWord("STAY")) {
      if (!position.empty()) return fail(w, fmt::format("PLANE takes one of MOVE, TURN and STAY ({} given before)", position));
      position = w.text;
      ++i_;
    } else if (w.isWord("DIST") && position == "MOVE") {
      ++i_;
      ExprPtr d = signedValue();
      if (!d) return false;
      o.set("R", std::move(d));
    } else if (w.isWord("MB") && position == "TURN") {
      ++i_;
      ExprPtr d = signedValue();
      if (!d) return false;
      o.set("H", std::move(d));
    } else if (w.isWord("MBMAX") && position == "TURN") {
      o.set("P", num(1));
      ++i_;
    } else if ((w.isWord("F") || w.isWord("FMAX")) && (position == "MOVE" || position == "TURN")) {
      feedAt = loc(w);
      ++i_;
      if (w.isWord("FMAX")) fmax = true;
      else if (!(feed = signedValue())) return false;
    } else {
      return fail(w, fmt::format("unexpected '{}' in PLANE {} (SEQ, COORD ROT / TABLE ROT, MOVE [DIST] / TURN [MB] with "
                                 "F or FMAX, STAY)",
                                 w.text, kw.text));
    }
  }
  if (position.empty()) return fail(kw, fmt::format("PLANE {} needs MOVE, TURN or STAY", kw.text), "missing-word");
  if (feed && !inchFeed(feedAt)) return false;
  if (feed) o.set("F", std::move(feed));
  (void)fmax;  // FMAX: no F word, the rotary move is a rapid
  static const std::map<std::string, const char *> kPosition = {{"MOVE", "move"}, {"TURN", "turn"}, {"STAY", "stay"}};
  o.set("position", Expr::symbol(kPosition.at(position)));
  return true;
}

bool BlockParser::plane() {
  const Token &kw = tok();
  if (kw.kind != Tok::Word) return fail(kw, "PLANE needs its form (SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL or RESET)");
  ++i_;
  if (kw.isWord("RESET")) {
    Op o = tiltOp(false, nullptr, "stay");
    if (!planePositioning(o, kw)) return false;
    out().push_back(std::move(o));
    return true;
  }
  const FormWords *form = nullptr;
  for (auto &f : kForms)
    if (kw.text == f.form) form = &f;
  if (!form) return fail(kw, fmt::format("'{}' is no PLANE form (SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL, RESET)", kw.text));
  Op o = tiltOp(true, form->tilt, "stay");
  std::set<std::string> seen;
  while (!atEnd() && tok().kind == Tok::Word) {
    const Token &at = tok();
    size_t back = i_;
    std::string w = planeWord();
    const char *key = nullptr;
    for (auto &[name, frameWord] : form->words)
      if (w == name) key = frameWord;
    if (w == "ROT" && kw.isWord("PROJECTED")) key = "C";  // the older spelling of PROROT
    if (!key) {
      i_ = back;
      break;
    }
    if (!seen.insert(key).second) return fail(at, fmt::format("PLANE {} gives {} twice", kw.text, w));
    ExprPtr v = signedValue();
    if (!v) return false;
    o.set(key, std::move(v));
  }
  if (form->all && seen.size() != form->words.size()) {
    std::string missing;
    for (auto &[name, frameWord] : form->words)
      if (!seen.count(frameWord)) missing += (missing.empty() ? "" : " ") + std::string(name);
    return fail(tok(), fmt::format("PLANE {} needs {}", kw.text, missing), "missing-word");
  }
  if (kw.isWord("RELATIV") && seen.size() != 1) return fail(tok(), "PLANE RELATIV takes one angle: SPA, SPB or SPC", "missing-word");
  if (kw.isWord("AXIAL") && seen.empty()) return fail(tok(), "PLANE AXIAL needs a rotary axis position (A, B or C)", "missing-word");
  if (!planePositioning(o, kw)) return false;
  out().push_back(std::move(o));
  return true;
}

// CYCL DEF 19.1 A… B… C… [F… ABST…]: spatial angles [model: the machine maker may make them axis
// angles, L13020]; all three 0, or no angle at all (the manual's NO ENT), resets. With F/ABST
// the control positions the rotary axes itself keeping the point ABST above the tip (MOVE DIST,
// L13123-L13154); without them the program positions them from Q120-Q122 (L13085-L13120), which
// the cycle sets in either case (L12999-L13006).
bool BlockParser::workingPlaneCycle(const Token &n) {
  SourceLoc bl = loc(t_[0]);
  Op o = tiltOp(true, "spatial", "stay");
  bool any = false, automatic = false;
  std::set<char> seen;
  while (!atEnd()) {
    const Token &w = tok();
    if (w.kind == Tok::Word && w.text.size() == 1 && std::string_view("ABC").find(w.text[0]) != std::string_view::npos) {
      if (!seen.insert(w.text[0]).second) return fail(w, fmt::format("CYCL DEF 19.1 gives {} twice", w.text));
      ++i_;
      ExprPtr v = signedValue();
      if (!v) return false;
      if (v->kind == ir::ExprKind::Number && (v->num < -360 || v->num > 360))
        return fail(w, "a cycle 19 angle is -360 … 360 (L13046)", "cycle-parameter");
      o.set(w.text, std::move(v));
      any = true;
    } else if (w.isWord("F") || w.isWord("ABST")) {
      ++i_;
      ExprPtr v = signedValue();
      if (!v) return false;
      if (w.isWord("F") && !inchFeed(loc(w))) return false;
      o.set(w.isWord("F") ? "F" : "R", std::move(v));
      automatic = true;
    } else {
      return fail(w, fmt::format("unexpected '{}' in CYCL DEF {} (A, B, C, F, ABST)", w.text, n.text));
    }
  }
  if (!any) o.set("action", Expr::symbol("cancel"));
  if (automatic) o.set("position", Expr::symbol("move"));
  out().push_back(std::move(o));
  static const char *const kPlaneVar[3] = {"_plane_a", "_plane_b", "_plane_c"};
  for (int i = 0; i < 3; ++i)
    out().push_back(assignOp(Expr::var(ir::VarSpace::QParam, "Q", Expr::number(120 + i, ir::Type::Int)),
                             Expr::var(ir::VarSpace::System, kPlaneVar[i], nullptr, bl), bl));
  return true;
}

}  // namespace ncc::hei
