// One Klartext block: the statement its first word names, lowered to NC IR ops.
#include "frontend/heidenhain/Cycles.h"
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

namespace ncc::hei {

bool BlockParser::fail(const Token &t, std::string msg, const char *rule) {
  return f_.error(loc(t), std::move(msg), rule);
}

bool BlockParser::expectWord(std::string_view w) {
  if (tok().isWord(w)) {
    ++i_;
    return true;
  }
  return fail(tok(), fmt::format("'{}' expected", w));
}

namespace {
// Statements of the Klartext language ncc knows but does not run yet: refused, naming them.
const char *const kNotYet[] = {
    "RPL",
    "FUNCTION", "SPL", "TRANS", "POLARKIN", "TABDATA", "PRESET", "FK",
};

// Text of a block for a comment (BLK FORM is kept that way): the tokens, signs glued to values.
std::string blockText(const std::vector<Token> &t, size_t from) {
  std::string s;
  for (size_t k = from; k + 1 < t.size(); ++k) {
    bool glue = k > from && (t[k - 1].is("+") || t[k - 1].is("-") ||
                                (t[k - 1].kind == Tok::Word && (t[k].kind == Tok::Number || t[k].is("+") || t[k].is("-"))));
    if (!s.empty() && !glue) s += ' ';
    s += t[k].kind == Tok::String ? "\"" + t[k].text + "\"" : t[k].text;
  }
  return s;
}

}  // namespace

// A program name written in a block: a string, or the words and numbers up to `stop`.
std::string nameText(const std::vector<Token> &t, size_t &k, std::string_view stopWord) {
  if (t[k].kind == Tok::String) return t[k++].text;
  std::string s;
  while (t[k].kind != Tok::End && !(t[k].kind == Tok::Word && t[k].text == stopWord && t[k + 1].kind == Tok::End))
    s += t[k++].text;
  return s;
}

Op BlockParser::blockOp() const {
  Op blk(OpKind::Block, {f_.file, b_.line, 1});
  blk.set("n", Expr::number(b_.number, ir::Type::Int));
  return blk;
}

bool BlockParser::parse() {
  SourceLoc bl{f_.file, b_.line, 1};
  const Token &kw = tok();
  if (f_.ended) return fail(kw, "a block after END PGM", "program-frame");
  if (!f_.begun && (b_.star || (!kw.isWord("BEGIN") && !kw.isWord("BEGINN"))))
    return fail(kw, "a Klartext program starts with BEGIN PGM <name> MM|INCH", "program-frame");
  // A label stands before its block (lint: a jump target ends dead code before the block), and
  // END PGM after M2/M30 adds no block (it is no code after the end).
  if (!kw.isWord("LBL") && !kw.isWord("END")) out().push_back(blockOp());
  if (b_.star || atEnd()) {  // `5 * text`, `5 ; text`
    if (!b_.comment.empty()) {
      Op c(OpKind::Comment, bl);
      c.set("text", Expr::string(b_.comment));
      out().push_back(std::move(c));
    }
    return true;
  }
  struct Stmt {
    const char *kw;
    bool (BlockParser::*fn)();
  };
  static const Stmt kStmts[] = {
      {"BEGIN", &BlockParser::beginPgm}, {"BEGINN", &BlockParser::beginPgm}, {"END", &BlockParser::endPgm},
      {"BLK", &BlockParser::blkForm},    {"TOOL", &BlockParser::tool},       {"L", &BlockParser::line},
      {"LP", &BlockParser::linePolar},   {"C", &BlockParser::arc},           {"CP", &BlockParser::arcPolar},
      {"CR", &BlockParser::arcRadius},   {"CT", &BlockParser::arcTangent},   {"CC", &BlockParser::centre},
      {"RND", &BlockParser::corner},     {"CHF", &BlockParser::corner},      {"FN", &BlockParser::fn},
      {"Q", &BlockParser::assign},       {"QL", &BlockParser::assign},       {"QR", &BlockParser::assign},
      {"QS", &BlockParser::assign},
      {"LBL", &BlockParser::label},      {"CALL", &BlockParser::call},       {"CYCL", &BlockParser::cycl},
      {"STOP", &BlockParser::stop},      {"M", &BlockParser::mOnly},
      {"APPR", &BlockParser::approachDepart}, {"DEP", &BlockParser::approachDepart},
      {"PATTERN", &BlockParser::patternDef}, {"SEL", &BlockParser::select}, {"GLOBAL", &BlockParser::globalDef},
      {"TCH", &BlockParser::tchProbe},   {"PLANE", &BlockParser::plane},
      {"DECLARE", &BlockParser::declareContour}, {"CONTOUR", &BlockParser::contourDef}, {"QC", &BlockParser::qcFormula},
      {"FL", &BlockParser::fkElement}, {"FLT", &BlockParser::fkElement}, {"FC", &BlockParser::fkElement},
      {"FCT", &BlockParser::fkElement}, {"FPOL", &BlockParser::fkPole}, {"FSELECT", &BlockParser::fkSelect},
  };
  // M89's calls follow the blocks in file order: control flow or a rounding of the move before
  // would need them at run time.
  bool jump = kw.isWord("FN") && peek().kind == Tok::Number && peek().num >= 9 && peek().num <= 12;
  if (f_.m89 && (jump || kw.isWord("LBL") || kw.isWord("CALL") || kw.isWord("RND") || kw.isWord("CHF")))
    return fail(kw, fmt::format("{} while the modal cycle call M89 is on is not simulated yet", jump ? "a jump" : kw.text),
                "unsupported-code");
  if (kw.kind == Tok::Word) {
    for (auto &s : kStmts)
      if (kw.text == s.kw) {
        if (s.fn != &BlockParser::corner && s.fn != &BlockParser::assign && s.fn != &BlockParser::mOnly) ++i_;
        return (this->*s.fn)();
      }
    for (const char *n : kNotYet)
      if (kw.text == n) return fail(kw, fmt::format("'{}' is not simulated yet (a Klartext function ncc does not run)", kw.text), "unsupported-code");
  }
  return fail(kw, fmt::format("'{}' does not start a Klartext block", kw.text));
}

bool BlockParser::beginPgm() {
  const Token &kw = t_[0];
  if (f_.begun) return fail(kw, "a second BEGIN PGM", "program-frame");
  if (kw.isWord("BEGINN"))
    f_.pp.diags.warning(loc(kw), "BEGINN is the German spelling: the control writes BEGIN PGM", "lenient-syntax");
  if (!expectWord("PGM")) return false;
  size_t k = i_;
  std::string name = nameText(t_, k, t_[t_.size() - 2].text);
  if (name.empty() || t_[k].kind == Tok::End) return fail(t_[k], "BEGIN PGM needs a program name and the unit MM or INCH", "program-frame");
  const Token &unit = t_[k];
  if (!unit.isWord("MM") && !unit.isWord("INCH")) return fail(unit, "the unit is MM or INCH", "program-frame");
  f_.begun = true;
  f_.pgmName = name;
  f_.inch = unit.isWord("INCH");
  f_.beginLoc = loc(kw);
  if (f_.isMain) f_.pp.mainInch = f_.inch;
  else if (f_.inch != f_.pp.mainInch)
    return fail(unit, "a called program in other units than the main program is not simulated", "unsupported-code");
  Op m(OpKind::Mode, loc(kw));
  m.set("units", Expr::symbol(f_.inch ? "inch" : "mm"));
  out().push_back(std::move(m));
  return true;
}

bool BlockParser::endPgm() {
  if (!expectWord("PGM")) return false;
  size_t k = i_;
  const Token &at = tok();
  std::string name = nameText(t_, k, t_[t_.size() - 2].text);
  if (name != f_.pgmName) return fail(at, fmt::format("END PGM {} closes BEGIN PGM {}", name, f_.pgmName), "program-frame");
  const Token &unit = t_[k];
  if (!unit.isWord(f_.inch ? "INCH" : "MM"))
    return fail(unit, fmt::format("END PGM must repeat the unit {} of BEGIN PGM", f_.inch ? "INCH" : "MM"), "program-frame");
  f_.ended = true;
  if (f_.isMain && !f_.sawEnd) {  // without M2/M30, END PGM ends the run; a called program returns
    out().push_back(blockOp());
    Op o(OpKind::Stop, loc(t_[0]));
    o.set("kind", Expr::symbol("end"));
    out().push_back(std::move(o));
  }
  return true;
}

// BLK FORM: the blank, for the graphics only; read, checked and kept as a comment.
bool BlockParser::blkForm() {
  if (!expectWord("FORM")) return false;
  const Token &form = tok();
  std::string text = "BLK FORM " + blockText(t_, i_);
  if (form.kind == Tok::Number && (form.text == "0.1" || form.text == "0.2")) {
    ++i_;
    if (form.text == "0.1") {
      if (!tok().isWord("X") && !tok().isWord("Y") && !tok().isWord("Z"))
        return fail(tok(), "BLK FORM 0.1 names the tool axis (Z) first");
      ++i_;
    }
    std::string seen;
    while (!atEnd()) {
      const Token &w = tok();
      std::string_view a = w.text;
      if (w.kind == Tok::Word && a.size() == 2 && a[0] == 'I' && form.text == "0.2") a.remove_prefix(1);
      if (w.kind != Tok::Word || a.size() != 1 || std::string_view("XYZ").find(a[0]) == std::string_view::npos)
        return fail(w, "BLK FORM takes the coordinates X, Y and Z");
      if (seen.find(a[0]) != std::string::npos)
        f_.pp.diags.warning(loc(w), fmt::format("BLK FORM {} gives {} twice", form.text, a), "blk-form");
      seen += a[0];
      ++i_;
      if (!signedValue()) return false;
    }
    for (char a : {'X', 'Y', 'Z'})
      if (seen.find(a) == std::string::npos)
        f_.pp.diags.warning(loc(form), fmt::format("BLK FORM {} leaves out {}", form.text, a), "blk-form");
  }
  Op c(OpKind::Comment, loc(t_[0]));
  c.set("text", Expr::string(text));
  out().push_back(std::move(c));
  return true;
}

// A tool called by its name (TOOL CALL "name", the SL cycles' QS13 …): the machine's tool table
// gives its number; null after an error at `at`.
ExprPtr BlockParser::toolByName(const std::string &name, SourceLoc at) {
  auto [from, to] = f_.pp.opts.toolNames.equal_range(name);
  if (from == to) {
    f_.error(at, fmt::format("tool \"{}\" is not in the machine's tool table", name), "unknown-tool");
    return nullptr;
  }
  if (std::next(from) != to) {  // sister tools: the TNC picks by tool life, which ncc does not keep
    f_.error(at, fmt::format("tool \"{}\" names {} tools of the machine's table (a replacement tool is chosen by tool "
                             "life, which is not simulated): call the tool by number",
                             name, std::distance(from, to)),
             "unsupported-code");
    return nullptr;
  }
  return Expr::number(from->second, ir::Type::Int, at);
}

// TOOL CALL n Z S F DL DR: select and change the tool (its length and radius from the machine's
// table), the working plane of the tool axis, the spindle speed and the feed (also FAUTO's).
bool BlockParser::tool() {
  SourceLoc bl = loc(t_[0]);
  if (tok().isWord("DEF")) {
    ++i_;
    if (tok().kind != Tok::Number || !tok().isInt) return fail(tok(), "TOOL DEF needs a tool number");
    Op o(OpKind::ToolSelect, bl);
    o.set("value", Expr::number(tok().num, ir::Type::Int));
    ++i_;
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' after TOOL DEF", tok().text));
    out().push_back(std::move(o));
    return true;
  }
  if (!expectWord("CALL")) return false;
  ExprPtr number;
  if (tok().kind == Tok::String) {  // a tool name: the machine's tool table gives its number
    if (!(number = toolByName(tok().text, loc()))) return false;
    ++i_;
  } else if (tok().kind == Tok::Number) {
    if (!tok().isInt) return fail(tok(), "a tool number is a whole number");
    number = Expr::number(tok().num, ir::Type::Int);
    ++i_;
  } else if (tok().isWord("Q") || tok().isWord("QL") || tok().isWord("QR")) {
    number = qParam();
    if (!number) return false;
  }
  const Token &axis = tok();
  if (axis.kind != Tok::Word || (axis.text != "X" && axis.text != "Y" && axis.text != "Z"))
    return fail(axis, "TOOL CALL names the tool axis (Z)", "missing-word");
  if (axis.text != "Z") return fail(axis, fmt::format("tool axis {} is not simulated yet (only Z)", axis.text), "unsupported-code");
  ++i_;
  ExprPtr s, f, dl;
  SourceLoc fl;
  while (!atEnd()) {
    const Token &w = tok();
    ExprPtr *into = w.isWord("S") ? &s : w.isWord("F") ? &f : w.isWord("DL") ? &dl : nullptr;
    if (w.isWord("DR")) {
      ++i_;
      if (tok().kind == Tok::Number && tok().text == "2" && (peek().is("+") || peek().is("-")))
        return fail(w, "DR2 (a turning tool's radius) is not simulated", "unsupported-code");
      ExprPtr v = signedValue();
      if (!v) return false;
      if (v->kind != ir::ExprKind::Number || v->num != 0)
        return fail(w, "a delta radius DR in TOOL CALL is not simulated yet", "unsupported-code");
      continue;
    }
    if (!into) return fail(w, fmt::format("'{}' cannot be used in TOOL CALL", w.text));
    if (*into) return fail(w, fmt::format("{} twice in TOOL CALL", w.text), "duplicate-word");
    if (w.isWord("F")) fl = loc(w);
    ++i_;
    if (!(*into = signedValue())) return false;
  }
  if (number) {
    Op sel(OpKind::ToolSelect, bl);
    sel.set("value", std::move(number));
    out().push_back(std::move(sel));
    out().push_back(Op(OpKind::ToolChange, bl));
    out().push_back(Op(OpKind::ToolLength, bl));
  }
  if (dl) {  // the program's delta length, added to the table's
    Op o(OpKind::ToolLength, bl);
    o.set("form", Expr::symbol("add"));
    o.set("Z", std::move(dl));
    out().push_back(std::move(o));
  }
  Op plane(OpKind::Mode, bl);
  plane.set("plane", Expr::symbol("xy"));
  out().push_back(std::move(plane));
  if (s) {
    Op o(OpKind::Speed, bl);
    o.set("value", std::move(s));
    out().push_back(std::move(o));
  }
  if (f) {
    if (!inchFeed(fl)) return false;
    f_.pp.fauto = true;
    out().push_back(assignOp(hglobal(kFauto, fl), f->clone(), fl));
    Op o(OpKind::Feed, fl);
    o.set("value", std::move(f));
    out().push_back(std::move(o));
  }
  return true;
}

bool BlockParser::assign() {
  SourceLoc l = loc();
  ExprPtr target = qParam();
  if (!target) return false;
  if (!tok().is("=")) return fail(tok(), "'=' expected after the parameter");
  ++i_;
  ExprPtr v = isString(*target) ? stringFormula() : formula();
  if (!v) return false;
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in the formula", tok().text));
  out().push_back(assignOp(std::move(target), std::move(v), l));
  return true;
}

// FN 0-FN 8, FN 13: arithmetic; FN 9-FN 12: conditional jumps to a label; FN 14: an error.
bool BlockParser::fn() {
  const Token &n = tok();
  if (n.kind != Tok::Number || !n.isInt) return fail(n, "FN needs its function number");
  int k = (int)n.num;
  ++i_;
  if (!tok().is(":")) return fail(tok(), fmt::format("':' expected after FN {}", k));
  ++i_;
  SourceLoc l = loc(t_[0]);
  if (k == 14) {
    if (!expectWord("ERROR")) return false;
    if (!tok().is("=")) return fail(tok(), "'=' expected");
    ++i_;
    ExprPtr e = signedValue();
    if (!e) return false;
    Op m(OpKind::Message, l);
    m.set("text", Expr::binary(OpCode::Concat, Expr::string("FN 14: error ", l), Expr::call("TOSTR", [&] {
                                 std::vector<ExprPtr> a;
                                 a.push_back(std::move(e));
                                 return a;
                               }(), l), l));
    m.set("kind", Expr::symbol("abort"));
    out().push_back(std::move(m));
    return atEnd() || fail(tok(), fmt::format("unexpected '{}'", tok().text));
  }
  if (k >= 9 && k <= 12) {
    static const char *kCmp[] = {"EQU", "NE", "GT", "LT"};
    static const OpCode kOp[] = {OpCode::Eq, OpCode::Ne, OpCode::Gt, OpCode::Lt};
    if (!expectWord("IF")) return false;
    ExprPtr a = signedValue();
    if (!a || !expectWord(kCmp[k - 9])) return false;
    ExprPtr b = signedValue();
    if (!b || !expectWord("GOTO") || !expectWord("LBL")) return false;
    std::string name;
    const Token &target = tok();
    if (!labelName(name)) return false;
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}'", tok().text));
    f_.gotos.push_back({name, loc(target)});
    Op g(OpKind::Goto, l);
    g.set("label", Expr::string(name));
    Op c(OpKind::If, l);
    c.set("cond", Expr::binary(kOp[k - 9], std::move(a), std::move(b), l));
    c.regions.emplace_back();
    c.regions[0].push_back(std::move(g));
    out().push_back(std::move(c));
    return true;
  }
  if (k > 14)
    return fail(n, fmt::format("FN {} is not simulated yet", k), "unsupported-code");
  ExprPtr target = qParam();
  if (!target) return false;
  if (!tok().is("=")) return fail(tok(), "'=' expected");
  ++i_;
  ExprPtr v;
  auto binary = [&](const char *word, auto make) -> ExprPtr {
    ExprPtr a = signedValue();
    if (!a || !expectWord(word)) return nullptr;
    ExprPtr b = signedValue();
    return b ? make(std::move(a), std::move(b)) : nullptr;
  };
  auto fn1 = [&](const char *name, const char *builtin) -> ExprPtr {
    if (!expectWord(name)) return nullptr;
    ExprPtr a = signedValue();
    if (!a) return nullptr;
    std::vector<ExprPtr> args;
    args.push_back(std::move(a));
    return Expr::call(builtin, std::move(args), l);
  };
  switch (k) {
  case 0: case 1: case 2: case 3: v = formula(); break;  // `+Q1 - +Q164`: signed operands
  case 4: v = binary("DIV", [&](ExprPtr a, ExprPtr b) { return Expr::binary(OpCode::Div, std::move(a), std::move(b), l); }); break;
  case 5: v = fn1("SQRT", "SQRT"); break;
  case 6: v = fn1("SIN", "SIN"); break;
  case 7: v = fn1("COS", "COS"); break;
  case 8:  // a LEN b: the root of the sum of squares
    v = binary("LEN", [&](ExprPtr a, ExprPtr b) {
      ExprPtr s = Expr::binary(OpCode::Add, Expr::binary(OpCode::Mul, a->clone(), a->clone(), l),
                               Expr::binary(OpCode::Mul, b->clone(), b->clone(), l), l);
      std::vector<ExprPtr> args;
      args.push_back(std::move(s));
      return Expr::call("SQRT", std::move(args), l);
    });
    break;
  case 13:  // a ANG b: the angle of the point (a, b), 0 to 360 degrees
    v = binary("ANG", [&](ExprPtr a, ExprPtr b) {
      std::vector<ExprPtr> args;
      args.push_back(std::move(b));
      args.push_back(std::move(a));
      return Expr::call("ATAN2", std::move(args), l);
    });
    break;
  }
  if (!v) return false;
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in FN {}", tok().text, k));
  out().push_back(assignOp(std::move(target), std::move(v), l));
  return true;
}

std::string labelOf(const Token &t) {
  return t.kind == Tok::String ? "LBL:" + t.text : "LBL" + t.text;
}

bool BlockParser::labelName(std::string &name) {
  const Token &t = tok();
  if (t.kind == Tok::String || (t.kind == Tok::Number && t.isInt)) {
    if (t.kind == Tok::Number && t.num == 0) return fail(t, "LBL 0 ends a subprogram: it cannot be called or jumped to");
    name = labelOf(t);
    ++i_;
    return true;
  }
  if (t.isWord("Q") || t.isWord("QL") || t.isWord("QR") || t.isWord("QS"))
    return fail(t, "a label given by a parameter is not simulated yet", "unsupported-code");
  return fail(t, "a label number or \"name\" was expected");
}

bool BlockParser::label() {
  const Token &t = tok();
  SourceLoc l = loc(t);
  std::string name;
  bool end = t.kind == Tok::Number && t.isInt && t.num == 0;
  if (end) {
    name = fmt::format("LBL0_{}", t.line);
    ++i_;
  } else {
    if (!labelName(name)) return false;
    if (f_.labels.count(name)) return fail(t, fmt::format("LBL {} is defined twice", t.text), "syntax");
  }
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' after LBL", tok().text));
  // Recorded with their op only, so that the sections resolve to labels (Program.cpp).
  if (end) f_.lbl0.push_back(out().size());
  else f_.labels[name] = out().size();
  Op o(OpKind::Label, l);
  o.set("name", Expr::string(name));
  out().push_back(std::move(o));
  out().push_back(blockOp());
  f_.lastMove = SIZE_MAX;
  return true;
}

bool BlockParser::call() {
  SourceLoc l = loc(t_[0]);
  if (tok().isWord("LBL")) {
    ++i_;
    std::string name;
    const Token &at = tok();
    if (!labelName(name)) return false;
    bool rep = false;
    ExprPtr count;
    if (tok().isWord("REP")) {
      ++i_;
      rep = true;
      const Token &n = tok();
      if (n.kind != Tok::Number || !n.isInt) return fail(n, "REP needs the number of repetitions");
      count = Expr::number(n.num, ir::Type::Int);
      ++i_;
      if (tok().is("/")) {  // REP 6/6: the control shows the repetitions left
        ++i_;
        if (tok().kind != Tok::Number) return fail(tok(), "a number expected after '/'");
        ++i_;
      }
    }
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in CALL LBL", tok().text));
    Op o(OpKind::CallSection, l);
    o.set("from", Expr::string(name));
    if (count) o.set("count", std::move(count));
    f_.calls.push_back({out().size(), name, rep, loc(at)});
    out().push_back(std::move(o));
    f_.lastMove = SIZE_MAX;
    return true;
  }
  if (tok().isWord("PGM")) {
    ++i_;
    const Token &at = tok();
    size_t k = i_;
    std::string written = nameText(t_, k, "");
    if (written.empty()) return fail(at, "CALL PGM needs a program name");
    std::string callee = f_.pp.program(written, f_.file, loc(at));
    if (callee.empty()) return false;
    Op o(OpKind::Call, l);
    o.set("callee", Expr::string(callee));
    o.set("frame", Expr::symbol("new"));
    out().push_back(std::move(o));
    f_.lastMove = SIZE_MAX;
    return true;
  }
  return fail(tok(), fmt::format("'CALL {}' is not simulated yet", tok().text), "unsupported-code");
}

bool BlockParser::stop() {
  SourceLoc l = loc(t_[0]);
  PathWords w;
  if (!words(w, kM, "STOP") || !emitBefore(w) || !emitAfter(w)) return false;
  Op o(OpKind::Stop, l);
  o.set("kind", Expr::symbol("program"));
  out().push_back(std::move(o));
  return true;
}

bool BlockParser::mOnly() {
  PathWords w;
  return words(w, kM, "M") && emitBefore(w) && emitAfter(w);
}

}  // namespace ncc::hei
