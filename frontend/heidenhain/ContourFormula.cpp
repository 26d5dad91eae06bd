// Contour formulas (docs/HEIDENHAIN.md "Contour formulas", manual L11776-L12416), the SL cycles'
// alternatives to cycle 14. `SEL CONTOUR "MODEL"` selects a program whose `DECLARE CONTOUR QCn =
// "program"` lines name the contours and whose `QCm = formula` combines them (| union, &
// intersection, ^ union without the intersection, \ difference, parentheses); `CONTOUR DEF P1 =
// "program" I2 = "program" …` lists pockets and islands. The region is computed by the core when
// a cycle 21-24 runs: each contour is captured (`contour action=begin|end use=subcontour`, the
// end with `P=n`: the contour QCn, always a pocket) and the formula follows in postfix order as
// `contour action=data use=subcontour` steps, `P=n` push QCn, `Q=k` apply operator k (1 | 2 &
// 3 ^ 4 \), `R=n` store into QCn (docs/IR.md §5.6; runtime/cycles/ContourFormula.h).
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

namespace ncc::hei {

namespace {
constexpr int kMaxContours = 128;  // L11788
constexpr int kMaxSimple = 9;      // CONTOUR DEF: nine sub-contours (L12286)

// The formula's operators, by their character (L11973-L12006); the number is the IR's.
int operatorOf(const Token &t) {
  static const char *const kOps = "|&^\\";
  if (t.kind != Tok::Punct || t.text.size() != 1) return 0;
  for (int k = 0; kOps[k]; ++k)
    if (t.text[0] == kOps[k]) return k + 1;
  return 0;
}

Op formulaStep(const char *key, int n, SourceLoc at) {
  Op o(OpKind::Contour, at);
  o.set("action", Expr::symbol("data", at));
  o.set("use", Expr::symbol("subcontour", at));
  o.set(key, Expr::number(n, ir::Type::Int, at));
  return o;
}
}  // namespace

// SEL CONTOUR "MODEL" (L11813-L11835): the program with the contour definitions, loaded now and
// run at each SL cycle's call; it replaces cycle 14 and CONTOUR DEF.
bool BlockParser::selContour() {
  ++i_;
  f_.slBroken = true;  // until it is read
  const Token &name = tok();
  if (name.kind != Tok::String) return fail(name, "SEL CONTOUR needs the contour program's name in quotes");
  ++i_;
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' after SEL CONTOUR", tok().text));
  f_.pp.loadingContourProgram = true;
  std::string callee = f_.pp.program(name.text, f_.file, loc(name));
  f_.pp.loadingContourProgram = false;
  if (callee.empty()) return false;
  f_.slProgram = callee;
  f_.slLabels.clear(), f_.contourDef.clear();
  f_.slBroken = false;
  return true;
}

// A contour's source: "program" (found as CALL PGM's) or LBL n / LBL "name" of this file, then an
// optional DEPTHd: its own depth (FCL 2, L11938-L11966), which ncc does not machine yet (0, the
// cycle 20 depth, is read).
bool BlockParser::contourSource(FileParser::ContourDefEntry &e) {
  const Token &src = tok();
  e.at = loc(src);
  if (src.kind == Tok::String) {
    ++i_;
    if ((e.callee = f_.pp.program(src.text, f_.file, loc(src))).empty()) return false;
  } else if (src.isWord("LBL")) {
    ++i_;
    if (!labelName(e.label)) return false;
  } else {
    return fail(src, "a contour program's name in quotes or LBL n expected");
  }
  if (tok().isWord("DEPTH")) {
    const Token &d = tok();
    ++i_;
    if (tok().is("+") || tok().is("-")) ++i_;
    if (tok().kind != Tok::Number) return fail(tok(), "DEPTH takes a number");
    if (tok().num != 0)
      return fail(d, fmt::format("DEPTH{}: a contour's own depth (FCL 2) is not simulated yet; DEPTH0 takes cycle 20's", tok().text),
                  "unsupported-code");
    ++i_;
  }
  return true;
}

// The captures of one contour: begin, the program's call or the label's section, end with P=n.
void BlockParser::formulaCapture(const FileParser::ContourDefEntry &e, SourceLoc bl) {
  if (!e.label.empty()) {
    subContourCapture("subcontour", e.label, e.at, bl);
  } else {
    Op begin(OpKind::Contour, e.at);
    begin.set("action", Expr::symbol("begin", bl));
    begin.set("use", Expr::symbol("subcontour", bl));
    out().push_back(std::move(begin));
    Op call(OpKind::Call, e.at);
    call.set("callee", Expr::string(e.callee));
    call.set("frame", Expr::symbol("new"));
    out().push_back(std::move(call));
  }
  Op end(OpKind::Contour, e.at);
  end.set("action", Expr::symbol("end", bl));
  end.set("use", Expr::symbol("subcontour", bl));
  end.set("P", Expr::number(e.n, ir::Type::Int, bl));
  out().push_back(std::move(end));
}

// DECLARE CONTOUR QCn = "program" [DEPTHd] (L11886-L11895): the contour is captured where the
// line stands, when SEL CONTOUR's program runs at a cycle's call.
bool BlockParser::declareContour() {
  if (!expectWord("CONTOUR")) return false;
  if (!f_.contourProgram)
    return fail(t_[0], "DECLARE CONTOUR belongs in the contour program that SEL CONTOUR selects", "unsupported-code");
  if (!tok().isWord("QC")) return fail(tok(), "DECLARE CONTOUR needs the contour's number QCn");
  ++i_;
  const Token &n = tok();
  if (n.kind != Tok::Number || !n.isInt || n.num < 1 || n.num > 9999) return fail(n, "QC takes a number 1 … 9999");
  ++i_;
  if (!tok().is("=")) return fail(tok(), "'=' expected after the QC number");
  ++i_;
  FileParser::ContourDefEntry e{false, (int)n.num, {}, {}, {}};
  if (!contourSource(e)) return false;
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in DECLARE CONTOUR", tok().text));
  if (f_.qcKnown.size() >= kMaxContours) return fail(t_[0], "at most 128 contours (L11788)", "cycle-parameter");
  f_.qcKnown.insert(e.n);
  formulaCapture(e, loc(t_[0]));
  return true;
}

// One operand of a formula: QCn or a parenthesised formula, then the operators that follow up to
// `closeWith` (a ')' or the block's end). The manual gives no precedence: one operator repeats
// left to right (`QC1 \ QC2 \ QC3`), different ones need parentheses.
bool BlockParser::formulaOperand(int closeWith, char &op) {
  auto operand = [&]() -> bool {
    const Token &t = tok();
    if (t.is("(")) {
      ++i_;
      char inner = 0;
      if (!formulaOperand(1, inner)) return false;
      if (!tok().is(")")) return fail(tok(), "')' expected in the contour formula");
      ++i_;
      return true;
    }
    if (!t.isWord("QC")) return fail(t, "QCn or '(' expected in the contour formula");
    ++i_;
    const Token &n = tok();
    if (n.kind != Tok::Number || !n.isInt) return fail(n, "QC takes a number");
    if (!f_.qcKnown.count((int)n.num))
      return fail(n, fmt::format("QC{} is not declared (DECLARE CONTOUR) or assigned above", n.text), "missing-block");
    out().push_back(formulaStep("P", (int)n.num, loc(t)));
    ++i_;
    return true;
  };
  if (!operand()) return false;
  while (!atEnd() && !(closeWith && tok().is(")"))) {
    const Token &t = tok();
    const int k = operatorOf(t);
    if (!k) {
      if (t.is("*") || t.is("+"))  // the manual's bracket examples (L11997-L12003): not operators
        return fail(t, fmt::format("'{}' is no contour formula operator: | & ^ \\ combine contours", t.text));
      return fail(t, fmt::format("unexpected '{}' in the contour formula", t.text));
    }
    if (op && op != t.text[0])
      return fail(t, fmt::format("'{}' after '{}': the manual gives the operators no precedence, so ncc needs parentheses", t.text, op));
    op = t.text[0];
    ++i_;
    if (!operand()) return false;
    out().push_back(formulaStep("Q", k, loc(t)));
  }
  return true;
}

// QCn = formula (L11897, L11973-L12006): in SEL CONTOUR's program; the last one is the region.
bool BlockParser::qcFormula() {
  const Token &n = tok();
  if (n.kind != Tok::Number || !n.isInt || n.num < 1 || n.num > 9999) return fail(n, "QC takes a number 1 … 9999");
  if (!f_.contourProgram)
    return fail(t_[0], "a contour formula belongs in the contour program that SEL CONTOUR selects", "unsupported-code");
  ++i_;
  if (!tok().is("=")) return fail(tok(), "'=' expected after the QC number");
  ++i_;
  char op = 0;
  if (!formulaOperand(0, op)) return false;
  f_.qcKnown.insert((int)n.num);
  out().push_back(formulaStep("R", (int)n.num, loc(n)));
  return true;
}

// CONTOUR DEF P1 = "POCK1.H" I2 = "ISLE2.H" DEPTH5 … (L12305-L12313): up to nine contours, the
// first a pocket (the deepest, L12395); the region is the pockets united less the islands.
bool BlockParser::contourDef() {
  f_.slBroken = true;  // until it is read
  if (!expectWord("DEF")) return false;
  std::vector<FileParser::ContourDefEntry> entries;
  while (!atEnd()) {
    const Token &k = tok();
    if (!k.isWord("P") && !k.isWord("I")) return fail(k, "P<n> (a pocket) or I<n> (an island) expected in CONTOUR DEF");
    ++i_;
    const Token &n = tok();
    if (n.kind != Tok::Number || !n.isInt || n.num < 1 || n.num > kMaxSimple)
      return fail(n, fmt::format("{} takes the contour's number 1 … 9", k.text));
    if (n.num != (double)entries.size() + 1)
      return fail(n, fmt::format("CONTOUR DEF numbers its contours 1, 2, 3 … in order: {} expected", entries.size() + 1));
    ++i_;
    if (tok().is("=")) ++i_;
    else  // the manual's own `I3 "ISLE3.H"` (L12312)
      f_.pp.diags.warning(loc(tok()), fmt::format("'=' missing after {}{}", k.text, n.text), "lenient-syntax");
    FileParser::ContourDefEntry e{k.isWord("I"), (int)n.num, {}, {}, {}};
    if (!contourSource(e)) return false;
    if (entries.empty() && e.island) return fail(k, "the first contour of CONTOUR DEF must be a pocket (P1), the deepest (L12395)", "cycle-parameter");
    entries.push_back(std::move(e));
  }
  if (entries.empty()) return fail(tok(), "CONTOUR DEF needs its contours (P1 = \"program\" …)", "missing-word");
  f_.contourDef = std::move(entries);
  f_.slLabels.clear(), f_.slProgram.clear();
  f_.slBroken = false;
  return true;
}

// At an SL cycle's call: SEL CONTOUR's program runs (its declarations and formulas), or CONTOUR
// DEF's contours are captured and combined: P1 | P… then \ I… (pockets united, islands taken
// away, as cycle 14's: docs/HEIDENHAIN.md, the manual gives no order).
bool BlockParser::formulaCaptures(SourceLoc bl) {
  if (!f_.slProgram.empty()) {
    Op call(OpKind::Call, bl);
    call.set("callee", Expr::string(f_.slProgram));
    call.set("frame", Expr::symbol("new"));
    out().push_back(std::move(call));
    out().push_back(blockOp());  // the cycle's moves are this block's again, not the program's last
    return true;
  }
  for (const auto &e : f_.contourDef) formulaCapture(e, bl);
  out().push_back(formulaStep("P", 1, bl));
  for (bool islands : {false, true})
    for (const auto &e : f_.contourDef)
      if (e.n > 1 && e.island == islands) {
        out().push_back(formulaStep("P", e.n, e.at));
        out().push_back(formulaStep("Q", islands ? 4 : 1, e.at));
      }
  out().push_back(formulaStep("R", 0, bl));
  return true;
}

}  // namespace ncc::hei
