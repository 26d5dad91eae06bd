// One Sinumerik block: block number, label, then statements (keywords, assignments, address
// words, subprogram calls). Keywords and control structures are here; the machine words are
// lowered together at the end of the block (Words.cpp).
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

bool BlockParser::fail(const Token &t, std::string msg, const char *rule) { return failAt(loc(t), std::move(msg), rule); }

bool BlockParser::failAt(SourceLoc l, std::string msg, const char *rule) {
  if (!failed_) f_.pp.error(l, std::move(msg), rule);
  failed_ = true;
  return false;
}

bool BlockParser::expect(std::string_view punct) {
  if (tok().is(punct)) {
    ++i_;
    return true;
  }
  return fail(tok(), atEnd() ? fmt::format("expected '{}' at the end of the block", punct)
                             : fmt::format("expected '{}', found '{}'", punct, tok().text));
}

// Control-structure keywords cannot share a block with machine words (L4970).
static const char *const kControl[] = {"IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "ENDFOR",
                                       "LOOP", "ENDLOOP", "REPEAT", "UNTIL"};

bool BlockParser::parse() {
  // Block number: N10 (auxiliary) or :10 (main block).
  int64_t n = -1;
  // A number past any integer would make the conversion undefined (found by fuzz-sinumerik).
  auto number = [&](const Token &t) {
    if (t.num >= 0 && t.num <= 2147483647.0) return n = (int64_t)t.num, true;
    return fail(t, "block number out of range (0 to 2147483647)");
  };
  if (tok().kind == Tok::Name && tok().text[0] == 'N' && tok().digitsAt == 1 && !tok().fraction) {
    if (!number(tok())) return false;
    ++i_;
  } else if (tok().is(":") && peek().kind == Tok::Number) {
    if (!number(peek())) return false;
    i_ += 2;
  }
  // Label: NAME: (2-32 characters, the first two letters or '_', L4447). It goes before the
  // block op, so a jump or a section repetition to it runs the block's number again.
  if (tok().kind == Tok::Name && peek().is(":") && tok().text[0] != '$') {
    std::string name = tok().text;
    if (name == "ENDLABEL") name = fmt::format("ENDLABEL_{}", line_);
    for (auto &l : f_.labels)
      if (l.first == name) return fail(tok(), fmt::format("label '{}' is defined twice", name));
    f_.labels.push_back({name, line_});
    Op l(OpKind::Label, loc());
    l.set("name", Expr::string(name));
    f_.cur().push_back(std::move(l));
    i_ += 2;
  }
  // A block that only closes a structure (ELSE, ENDIF …) is no block of its own in the IR
  // unless it has a number to jump to.
  static const char *kClosers[] = {"ELSE", "ENDIF", "ENDWHILE", "ENDFOR", "ENDLOOP"};
  bool closer = false;
  for (const char *c : kClosers) closer = closer || (tok().isName(c) && peek().kind == Tok::End);
  if (n >= 0 || !closer) {
    Op b(OpKind::Block, loc(t_[0]));
    if (n >= 0) b.set("n", Expr::number((double)n, ir::Type::Int));
    f_.cur().push_back(std::move(b));
  }
  while (!atEnd() && !failed_)
    if (!statement()) break;
  if (failed_) return false;
  for (auto &o : pre_) f_.cur().push_back(std::move(o));
  if (!lowerWords()) return false;
  for (auto &o : post_) f_.cur().push_back(std::move(o));
  return true;
}

bool BlockParser::statement() {
  const Token &t = tok();
  if (t.kind != Tok::Name) return fail(t, fmt::format("unexpected '{}'", t.text));
  if (f_.endproc.line) return fail(t, fmt::format("statement after ENDPROC (line {}), the program's end line", f_.endproc.line));
  f_.sawStatement = f_.sawStatement || t.text != "PROC";
  if (keyword(t.text)) return !failed_;
  if (failed_) return false;
  // name = value: variables, R parameters, system variables, addresses with an expression.
  if (t.text[0] == '$' || f_.vars.count(t.text) || ((t.text == "R" || t.text == "RG") && peek().is("[")) ||
      (t.text[0] == 'R' && t.digitsAt == 1 && !t.fraction && peek().is("=")))
    return assignment();
  return addressWord();
}

bool BlockParser::keyword(const std::string &kw) {
  const Token &t = tok();
  SourceLoc l = loc(t);
  auto alone = [&]() {
    if (peek().kind != Tok::End) return fail(peek(), fmt::format("'{}' must stand alone in its block", kw));
    ++i_;
    return true;
  };
  for (const char *c : kControl)
    if (kw == c && !(kw == "REPEAT" && peek().kind == Tok::Name) && (!words_.empty() || !gcodes_.empty() || !pre_.empty()))
      return fail(t, fmt::format("'{}' cannot share a block with other statements", kw));
  if (kw == "DEF") return def();
  if (kw == "PROC") return proc();
  if (kw == "TRANSMIT" || kw == "TRACYL" || kw == "TRAFOOF") return transformation(kw);  // Transform.cpp
  if (kw == "IF") return ifStatement();
  if (kw == "ELSE") {
    if (f_.ctl.empty() || f_.ctl.back().kind != Ctl::If) return fail(t, "ELSE without IF", "loop-mismatch");
    CtlFrame &c = f_.ctl.back();
    c.kind = Ctl::Else;
    c.op->regions.emplace_back();
    f_.regions.back() = &c.op->regions[1];
    c.region = f_.regions.back();
    return alone();
  }
  if (kw == "ENDIF") return closeCtl(Ctl::If, "ENDIF", t) && alone();
  if (kw == "ENDWHILE") return closeCtl(Ctl::While, "ENDWHILE", t) && alone();
  if (kw == "ENDFOR") return closeCtl(Ctl::For, "ENDFOR", t) && alone();
  if (kw == "ENDLOOP") return closeCtl(Ctl::Loop, "ENDLOOP", t) && alone();
  if (kw == "WHILE") {
    ++i_;
    ExprPtr c = expr(0);
    if (!c) return false;
    if (!atEnd()) return fail(tok(), "unexpected text after the WHILE condition");
    Op w(OpKind::While, l);
    w.set("cond", std::move(c));
    openCtl(Ctl::While, std::move(w), l);
    return true;
  }
  if (kw == "LOOP") {
    openCtl(Ctl::Loop, Op(OpKind::Loop, l), l);
    return alone();
  }
  if (kw == "FOR") {
    ++i_;
    const Token &v = tok();
    ++i_;
    ExprPtr var = v.kind == Tok::Name ? (f_.vars.count(v.text) ? variable(v) : nameExpr(v)) : nullptr;
    if (!var || var->kind != ir::ExprKind::Var) return failed_ ? false : fail(v, "FOR needs a variable as its counter");
    if (!expect("=")) return false;
    ExprPtr from = expr(0);
    if (!from) return false;
    if (!tok().isName("TO")) return fail(tok(), "expected TO in FOR");
    ++i_;
    ExprPtr to = expr(0);
    if (!to) return false;
    if (!atEnd()) return fail(tok(), "unexpected text after the FOR end value");
    // FOR v = a TO b: v = a; while v <= b { body; v = v + 1 } (the step is always 1, L5103).
    // A REAL counter (an R parameter) counts whole numbers: its start is rounded (L5097-L5101).
    auto vd = f_.vars.find(var->str);
    bool real = var->space == ir::VarSpace::RParam || (vd != f_.vars.end() && vd->second.type == ir::Type::Real);
    if (real) from = callOf("ROUND", l, std::move(from));
    f_.cur().push_back(assignOp(var->clone(), std::move(from), l));
    Op w(OpKind::While, l);
    w.set("cond", Expr::binary(ir::OpCode::Le, var->clone(), std::move(to), l));
    openCtl(Ctl::For, std::move(w), l);
    f_.ctl.back().forVar = std::move(var);
    return true;
  }
  if (kw == "REPEAT" && peek().kind == Tok::End) {  // REPEAT … UNTIL: a loop ending in `if c { break }`
    openCtl(Ctl::Repeat, Op(OpKind::Loop, l), l);
    return alone();
  }
  if (kw == "REPEAT") return repeatStatement(false);
  if (kw == "REPEATB") return repeatStatement(true);
  if (kw == "UNTIL") {
    if (f_.ctl.empty() || f_.ctl.back().kind != Ctl::Repeat)
      return fail(t, "UNTIL without REPEAT", "loop-mismatch");
    ++i_;
    ExprPtr c = expr(0);
    if (!c) return false;
    if (!atEnd()) return fail(tok(), "unexpected text after the UNTIL condition");
    Op iff(OpKind::If, l);
    iff.set("cond", std::move(c));
    iff.regions.emplace_back();
    iff.regions[0].push_back(Op(OpKind::Break, l));
    f_.cur().push_back(std::move(iff));
    return closeCtl(Ctl::Repeat, "UNTIL", t);
  }
  if (kw == "CASE") return caseStatement();
  if (kw == "GOTO" || kw == "GOTOF" || kw == "GOTOB" || kw == "GOTOC" || kw == "GOTOS") {
    if (!words_.empty() || !gcodes_.empty()) return fail(t, "an unconditional jump must stand alone in its block");
    return gotoStatement(kw, post_);
  }
  if (kw == "MSG") {
    ++i_;
    if (!expect("(")) return false;
    ExprPtr e = tok().is(")") ? Expr::string("", l) : expr(0);
    if (!e || !expect(")")) return false;
    Op m(OpKind::Message, l);
    m.set("text", std::move(e));
    pre_.push_back(std::move(m));
    return true;
  }
  if (kw == "STOPRE") {  // a preprocessing stop: nothing to do when the program is simulated
    Op c(OpKind::Comment, l);
    c.set("text", Expr::string("STOPRE"));
    pre_.push_back(std::move(c));
    ++i_;
    return true;
  }
  if (kw == "SETAL" && peek().is("(")) {
    // SETAL(n): a cycle alarm stops the program (its text is the alarm number).
    // SETAL(n, "text"): the text goes with the number.
    i_ += 2;
    ExprPtr n = expr(0);
    if (!n) return false;
    ExprPtr text = Expr::binary(ir::OpCode::Concat, Expr::string("alarm ", l), callOf("TOSTR", l, std::move(n)), l);
    if (tok().is(",")) {
      ++i_;
      ExprPtr s = expr(0);
      if (!s) return false;
      text = Expr::binary(ir::OpCode::Concat, Expr::binary(ir::OpCode::Concat, std::move(text), Expr::string(": ", l), l),
                          callOf("TOSTR", l, std::move(s)), l);
    }
    if (!expect(")")) return false;
    Op m(OpKind::Message, l);
    m.set("text", std::move(text));
    m.set("kind", Expr::symbol("abort"));
    post_.push_back(std::move(m));
    return true;
  }
  if (kw == "MCALL") return callStatement(true);
  if (kw == "CALL") return callStatement(false);
  if (kw == "EXTERN") {  // the signature comes from the subprogram's own PROC line
    ++i_;
    if (tok().kind != Tok::Name) return fail(tok(), "expected a subprogram name after EXTERN");
    if (!f_.pp.callee(tok().text, loc())) return failed_ = true, false;
    i_ = t_.size() - 1;
    return true;
  }
  static const char *kAttrs[] = {"SAVE", "DISPLOF", "DISPLON", "SBLOF", "SBLON", "ACTBLOCNO", "PREPRO"};
  for (const char *a : kAttrs)
    if (kw == a) {  // display and single-block attributes change nothing in a simulation
      if (kw == "SAVE") f_.fn.save = true;
      ++i_;
      return true;
    }
  if (kw == "SPLINEPATH") {
    // SPLINEPATH(1, X, Y, Z): the default spline group (the first three channel axes, L10966),
    // which is what ncc's splines move; any other group is refused.
    std::string text;
    for (size_t j = i_ + 1; j < t_.size() && t_[j].kind != Tok::End; ++j)
      text += t_[j].kind == Tok::Number ? fmt::format("{}", t_[j].num) : t_[j].text;
    if (text != "(1,X,Y,Z)")
      return fail(t, "SPLINEPATH other than SPLINEPATH(1,X,Y,Z) (the default spline group) is not simulated",
                  "unsupported-code");
    while (!atEnd()) ++i_;
    return true;
  }
  if (fileCommand(kw)) return true;       // Files.cpp
  if (contourStatement(kw)) return true;  // Contour.cpp
  if (machineConstruct(kw)) return true;  // MachineOnly.cpp
  if (programCall(kw)) return true;       // Calls.cpp
  // Language constructs ncc does not have yet: refused by name, never silently skipped.
  static const char *kNotYet[] = {"REDEF", "GOTOS", "TRAORI", "G291"};
  for (const char *c : kNotYet)
    if (kw == c)
      return fail(t, fmt::format("'{}' is not simulated (not yet supported construct)", kw), "unsupported-code");
  if (kw == "DELDL") return deleteAdditive(t, false);  // ToolData.cpp
  // The D number management of the tool data (SIN-TOL-20 … -23, L18246-L18371).
  static const struct { const char *name, *what; } kToolData[] = {
      {"DZERO", "invalidating D numbers"},
      {"SETDNO", "renaming a D number"},      {"GETDNO", "reading a D number"},
      {"CHKDNO", "checking D numbers"},       {"GETACTTD", "the T number of a D number"}};
  for (auto &c : kToolData)
    if (kw == c.name) return fail(t, fmt::format("'{}' ({}) is not simulated", kw, c.what), "unsupported-code");
  return false;
}

void BlockParser::openCtl(Ctl kind, Op op, SourceLoc l) {
  op.regions.emplace_back();
  ir::Region &outer = f_.cur();
  outer.push_back(std::move(op));
  Op &o = outer.back();
  f_.ctl.push_back({kind, l, &o.regions[0], &o, nullptr});
  f_.regions.push_back(&o.regions[0]);
  if (f_.ctl.size() > 16) fail(t_[0], "control structures nested deeper than 16 in one subprogram", "loop-mismatch");
}

bool BlockParser::closeCtl(Ctl want, const char *name, const Token &at) {
  bool match = !f_.ctl.empty() && (f_.ctl.back().kind == want || (want == Ctl::If && f_.ctl.back().kind == Ctl::Else));
  if (!match) {
    if (f_.ctl.empty()) return fail(at, fmt::format("{} without an open control structure", name), "loop-mismatch");
    static const char *kOpen[] = {"IF", "IF … ELSE", "WHILE", "FOR", "LOOP", "REPEAT"};
    return fail(at, fmt::format("{} closes {} opened at line {}", name, kOpen[(int)f_.ctl.back().kind],
                                f_.ctl.back().loc.line),
                "loop-mismatch");
  }
  CtlFrame &c = f_.ctl.back();
  if (c.kind == Ctl::For) {
    SourceLoc l = loc(at);
    c.region->push_back(
        assignOp(c.forVar->clone(), Expr::binary(ir::OpCode::Add, c.forVar->clone(), Expr::number(1, ir::Type::Int, l), l), l));
  }
  f_.ctl.pop_back();
  f_.regions.pop_back();
  return true;
}

bool BlockParser::ifStatement() {
  SourceLoc l = loc();
  ++i_;
  ExprPtr c = expr(0);
  if (!c) return false;
  const Token &t = tok();
  if (t.kind == Tok::Name && t.text.rfind("GOTO", 0) == 0) {
    // IF c GOTOF target: a conditional jump without ENDIF (several may share a block).
    Op iff(OpKind::If, l);
    iff.set("cond", std::move(c));
    iff.regions.emplace_back();
    if (!gotoStatement(t.text, iff.regions[0])) return false;
    post_.push_back(std::move(iff));
    return true;
  }
  if (!atEnd()) return fail(t, "unexpected text after the IF condition (a block IF stands alone; use GOTOF/GOTOB for a jump)");
  if (!words_.empty() || !gcodes_.empty() || !pre_.empty() || !post_.empty())
    return fail(t_[0], "'IF' cannot share a block with other statements");
  Op iff(OpKind::If, l);
  iff.set("cond", std::move(c));
  openCtl(Ctl::If, std::move(iff), l);
  return true;
}

// GOTOx target: a label, a block number (N300 or 300) or a string expression (L4420-L4434).
bool BlockParser::gotoStatement(const std::string &kw, std::vector<Op> &into) {
  const Token &k = tok();
  SourceLoc l = loc(k);
  if (kw == "GOTOS") return fail(k, "'GOTOS' is not simulated (the PLC decides whether it jumps)", "unsupported-code");
  ++i_;
  Op g(OpKind::Goto, l);
  g.set("dir", Expr::symbol(kw == "GOTOF" ? "forward" : kw == "GOTOB" ? "backward" : "any"));
  const Token &t = tok();
  if (t.kind == Tok::Name && t.text[0] == 'N' && t.digitsAt == 1 && !t.fraction && peek().kind != Tok::Punct) {
    g.set("n", Expr::number(t.num, ir::Type::Int));
    ++i_;
  } else if (t.kind == Tok::Number && t.isInt) {
    g.set("n", Expr::number(t.num, ir::Type::Int));
    ++i_;
  } else if (t.kind == Tok::Name && !f_.vars.count(t.text) && peek().kind != Tok::Punct &&
             !(t.text[0] == 'R' && t.digitsAt == 1)) {
    g.set("label", Expr::string(t.text == "ENDLABEL" ? "ENDLABEL" : t.text));
    ++i_;
  } else {
    ExprPtr e = expr(0);
    if (!e) return false;
    if (e->kind == ir::ExprKind::String) {  // a constant text: the label or block number it names
      std::string s = e->str;
      for (auto &c : s) c = (char)std::toupper((unsigned char)c);
      bool num = s.size() > 1 && s[0] == 'N' && s.find_first_not_of("0123456789", 1) == std::string::npos;
      if (num)
        g.set("n", Expr::number(std::stod(s.substr(1)), ir::Type::Int));
      else
        g.set("label", Expr::string(s));
    } else {  // names are case-insensitive: labels are kept in upper case
      g.set("label", callOf("TOUPPER", l, callOf("TOSTR", l, std::move(e))));
    }
  }
  if (kw == "GOTOC") {
    // GOTOC goes on when the target is missing; ncc keeps constant targets only (checked later).
    if (!g.get("n") && g.get("label")->kind != ir::ExprKind::String)
      return fail(k, "'GOTOC' with a computed target is not simulated", "unsupported-code");
    g.set("dir", Expr::symbol("any"));
    Op c(OpKind::Comment, l);
    c.set("text", Expr::string("GOTOC"));
    into.push_back(std::move(c));
  }
  into.push_back(std::move(g));
  return true;
}

// CASE (e) OF 1 GOTOF A 2 GOTOF B DEFAULT GOTOF C: one if per constant, in order.
bool BlockParser::caseStatement() {
  SourceLoc l = loc();
  ++i_;
  ExprPtr e = expr(0);
  if (!e) return false;
  if (!tok().isName("OF")) return fail(tok(), "expected OF after the CASE expression");
  ++i_;
  ir::Region *into = &post_;
  while (!atEnd()) {
    if (tok().isName("DEFAULT")) {
      ++i_;
      if (tok().kind != Tok::Name || tok().text.rfind("GOTO", 0) != 0) return fail(tok(), "expected a GOTO after DEFAULT");
      if (!gotoStatement(tok().text, *into)) return false;
      if (!atEnd()) return fail(tok(), "DEFAULT must be the last choice of CASE");
      break;
    }
    ExprPtr c = unary();
    if (!c) return false;
    if (c->kind != ir::ExprKind::Number) return fail(t_[i_ - 1], "a CASE choice is an integer constant");
    if (tok().kind != Tok::Name || tok().text.rfind("GOTO", 0) != 0) return fail(tok(), "expected a GOTO after the CASE choice");
    Op iff(OpKind::If, l);
    iff.set("cond", Expr::binary(ir::OpCode::Eq, e->clone(), std::move(c), l));
    iff.regions.emplace_back();
    if (!gotoStatement(tok().text, iff.regions[0])) return false;
    iff.regions.emplace_back();
    into->push_back(std::move(iff));
    into = &into->back().regions[1];
  }
  return true;
}

// REPEAT A [B] [P=n], REPEATB A [P=n] (L4662-L4711): a section call of this function.
bool BlockParser::repeatStatement(bool single) {
  SourceLoc l = loc();
  ++i_;
  if (tok().kind != Tok::Name) return fail(tok(), "expected a label after REPEAT");
  std::string from = tok().text, to;
  ++i_;
  size_t toAt = i_;
  if (tok().kind == Tok::Name && !(tok().text == "P" && peek().is("="))) {
    to = tok().text;
    ++i_;
  }
  ExprPtr count;
  if (tok().isName("P") && peek().is("=")) {
    i_ += 2;
    count = expr(0);
    if (!count) return false;
  } else if (tok().kind == Tok::Name && tok().text[0] == 'P' && tok().digitsAt == 1) {
    count = Expr::number(tok().num, ir::Type::Int);
    ++i_;
  }
  if (!atEnd()) return fail(tok(), "unexpected text after REPEAT");
  if (single) to = from;
  bool fromBefore = false;  // A stands before the REPEAT (labels are known up to here)
  for (auto &lb : f_.labels) fromBefore = fromBefore || lb.first == from;
  if (!single && fromBefore && !to.empty()) {
    // REPEAT A B with B not reached before the REPEAT: the area ends at the REPEAT (L4692-L4695).
    // `REPEAT A ENDLABEL` names the ENDLABEL mark itself: A's area up to its ENDLABEL (L4697-L4711).
    bool known = false;
    for (auto &lb : f_.labels) known = known || lb.first == to;
    if (!known && to != "ENDLABEL") f_.laterLabels.push_back({to, loc(t_[toAt])});  // it must exist after it
    if (!known) to.clear();
  }
  if (to.empty()) {
    // REPEAT A: from A up to the REPEAT, or to the first ENDLABEL after A (L4806-L4826).
    bool after = false;
    for (auto &lb : f_.labels) {
      if (lb.first == from) after = true;
      else if (after && lb.first.rfind("ENDLABEL_", 0) == 0) {
        to = lb.first;
        break;
      }
    }
  } else if (to == "ENDLABEL") {
    return fail(t_[toAt], fmt::format("REPEAT {} ENDLABEL: label '{}' must stand before the REPEAT, with an ENDLABEL after it", from, from));
  }
  Op s(OpKind::CallSection, l);
  s.set("from", Expr::string(from));
  if (!to.empty()) s.set("to", Expr::string(to));
  if (count) s.set("count", std::move(count));
  post_.push_back(std::move(s));
  return true;
}

}  // namespace ncc::sin
