// The calls of a program named in other ways than by its name in a block of its own: CALL with a
// STRING expression (SIN-CAL-05), a section CALL … BLOCK … TO … (SIN-CAL-06), ISOCALL (SIN-CAL-07),
// PCALL (SIN-CAL-08), CALLPATH (SIN-CAL-09) and EXTCALL (SIN-CAL-10), the returns RET/RETB with a
// target (SIN-SUB-13, -14) and EXECSTRING of a constant (SIN-IND-05). docs/SINUMERIK.md "Program
// memory" says how calls map onto the search path.
#include "frontend/SubprogramFiles.h"
#include "frontend/sinumerik/Parser.h"
#include "ir/FileCommands.h"

#include <fmt/format.h>

#include <filesystem>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

// CALL <STRING expression> (SIN-CAL-05, L8554-L8598): the program is named when the call runs,
// so every subprogram of the search path is read now and the call finds its function by the
// name SIN_PROGNAME makes of the string (folders and type dropped).
bool BlockParser::computedCall(ExprPtr e, const Token &at, SourceLoc l) {
  if (!stringy(*e)) return fail(at, "CALL takes a program name: a STRING constant, variable or expression");
  if (!atEnd()) return fail(tok(), "an indirect CALL takes no arguments and stands alone in its block (L8554)");
  if (!f_.pp.loadSearchPath(l)) {
    failed_ = true;
    return false;
  }
  Op c(OpKind::Call, l);
  c.set("callee", callOf("SIN_PROGNAME", l, std::move(e)));
  c.set("frame", Expr::symbol("new"));
  post_.push_back(std::move(c));
  for (auto &[n, sig] : f_.pp.procs)
    if (sig.retTarget) return resumeAfterCall(l), true;  // the program called may be one of them
  return true;
}

// CALL [P] BLOCK A TO B (SIN-CAL-06, L8600-L8665): the section from label A through B's block, of
// this program (a section call here) or of program P (a call of P's section function). Labels in
// STRING variables (example 87) go to P's section function for labels named at run time.
bool BlockParser::sectionCall(ExprPtr program, SourceLoc l) {
  ++i_;  // BLOCK
  std::string labels[2];
  ExprPtr named[2];  // a label held in a STRING variable
  for (int k = 0; k < 2; ++k) {
    if (k == 1) {
      if (!tok().isName("TO")) return fail(tok(), "expected TO and the end label (CALL … BLOCK start TO end)");
      ++i_;
    }
    const Token &t = tok();
    if (t.kind != Tok::Name) return fail(t, k ? "expected the end label after TO" : "expected the start label after BLOCK");
    ++i_;
    if (f_.vars.count(t.text)) {
      named[k] = variable(t);
      if (!named[k]) return false;
      if (!stringy(*named[k])) return fail(t, fmt::format("'{}' is no STRING: a section label is a name or a STRING", t.text));
    }
    labels[k] = t.text;
  }
  if (!atEnd()) return fail(tok(), "unexpected text after CALL … BLOCK … TO …");
  if (program && program->kind != ir::ExprKind::String)
    return failAt(l, "CALL … BLOCK of a program named at run time is not simulated", "unsupported-code");
  std::string type, name = program ? calledProgram(program->str, type) : "";
  if (named[0] || named[1]) {
    if (!program)
      return failAt(l, "CALL BLOCK with a label in a STRING variable is simulated for a named program only "
                       "(CALL \"P\" BLOCK …)", "unsupported-code");
    const char *keys[] = {kSectionFrom, kSectionTo};
    for (int k = 0; k < 2; ++k) {
      ExprPtr v = named[k] ? callOf("TOUPPER", l, callOf("TOSTR", l, std::move(named[k]))) : Expr::string(labels[k], l);
      post_.push_back(assignOp(Expr::var(ir::VarSpace::Global, keys[k], nullptr, l), std::move(v), l));
    }
    f_.pp.namedSections = true;
    return sectionFunctionCall(name, type, "", "", l);
  }
  if (!program) {
    Op s(OpKind::CallSection, l);
    s.set("from", Expr::string(labels[0]));
    s.set("to", Expr::string(labels[1]));
    post_.push_back(std::move(s));
    return true;
  }
  return sectionFunctionCall(name, type, labels[0], labels[1], l);
}

bool BlockParser::sectionFunctionCall(const std::string &name, const std::string &type, const std::string &from,
                                      const std::string &to, SourceLoc l) {
  const std::string *fn = f_.pp.sectionFunction(name, type, from, to, l);
  return plainCall(fn, l, fn && f_.pp.sections[*fn]);
}

// The section function of labels named at run time: it keeps the end label the caller left in
// %%_SIN_SEC_TO, stops when it is none of its labels, jumps to %%_SIN_SEC_FROM, and returns after
// the block of each label when that label is the end (a block ends before the next block or label
// op of its region, as a section call's, docs/IR.md §5.3).
void namedSectionFunction(ir::Function &fn, SourceLoc l) {
  std::vector<std::string> labels;
  auto place = [&](auto &self, ir::Region &r) -> void {
    std::string open;  // the label whose block is being read
    bool skipBlock = false;
    auto endCheck = [&](size_t at) {
      Op iff(OpKind::If, l);
      iff.set("cond", Expr::binary(ir::OpCode::Eq, Expr::var(ir::VarSpace::Local, kSectionEnd, nullptr, l),
                                   Expr::string(open, l), l));
      iff.regions.emplace_back();
      iff.regions[0].push_back(Op(OpKind::Return, l));
      r.insert(r.begin() + (long)at, std::move(iff));
      open.clear();
    };
    for (size_t i = 0; i < r.size(); ++i) {
      for (auto &sub : r[i].regions) self(self, sub);
      bool label = r[i].kind == OpKind::Label && r[i].get("name")->str.find('@') == std::string::npos;
      if (r[i].kind == OpKind::Block && skipBlock) {
        skipBlock = false;
        continue;
      }
      if (!open.empty() && (label || r[i].kind == OpKind::Block)) endCheck(i++);
      if (label) {
        open = r[i].get("name")->str;
        labels.push_back(open);
        skipBlock = true;
      }
    }
    if (!open.empty()) endCheck(r.size());
  };
  place(place, fn.body);
  std::vector<Op> pro;
  Op d(OpKind::Declare, l);
  d.set("var", Expr::var(ir::VarSpace::Local, kSectionEnd, nullptr, l));
  d.set("type", Expr::symbol("string"));
  d.set("len", Expr::number(200, ir::Type::Int));
  pro.push_back(std::move(d));
  pro.push_back(assignOp(Expr::var(ir::VarSpace::Local, kSectionEnd, nullptr, l),
                         Expr::var(ir::VarSpace::Global, kSectionTo, nullptr, l), l));
  ExprPtr missing = Expr::boolean(true, l);
  for (auto &name : labels)
    missing = Expr::binary(ir::OpCode::And, std::move(missing),
                           Expr::binary(ir::OpCode::Ne, Expr::var(ir::VarSpace::Local, kSectionEnd, nullptr, l),
                                        Expr::string(name, l), l), l);
  Op stop(OpKind::If, l);
  stop.set("cond", std::move(missing));
  stop.regions.emplace_back();
  Op m(OpKind::Message, l);
  m.set("kind", Expr::symbol("abort"));
  m.set("text", Expr::binary(ir::OpCode::Concat, Expr::string("CALL BLOCK: end label '", l),
                             Expr::binary(ir::OpCode::Concat, Expr::var(ir::VarSpace::Local, kSectionEnd, nullptr, l),
                                          Expr::string("' is not in the program", l), l), l));
  stop.regions[0].push_back(std::move(m));
  pro.push_back(std::move(stop));
  Op go(OpKind::Goto, l);
  go.set("label", Expr::var(ir::VarSpace::Global, kSectionFrom, nullptr, l));
  go.set("dir", Expr::symbol("any"));
  pro.push_back(std::move(go));
  fn.body.insert(fn.body.begin(), std::make_move_iterator(pro.begin()), std::make_move_iterator(pro.end()));
  // (the "@text" label after the prologue: sectionFunction)
}

void declareNamedSections(ir::Region &mainBody) {
  for (const char *n : {kSectionFrom, kSectionTo}) {
    Op d(ir::OpKind::Declare, {});
    d.set("var", Expr::var(ir::VarSpace::Global, n, nullptr, {}));
    d.set("type", Expr::symbol("string"));
    d.set("len", Expr::number(200, ir::Type::Int));
    mainBody.insert(mainBody.begin(), std::move(d));
  }
}

// A call of function `fn` without arguments (null: not found, reported), with the jump to a
// RET target after it when `resume`.
bool BlockParser::plainCall(const std::string *fn, SourceLoc l, bool resume) {
  if (!fn) {
    failed_ = true;
    return false;
  }
  Op c(OpKind::Call, l);
  c.set("callee", Expr::string(*fn));
  c.set("frame", Expr::symbol("new"));
  post_.push_back(std::move(c));
  if (resume) resumeAfterCall(l);
  return true;
}

// A call of the program a constant names (`"SP_1"`, `"USB:WKS.DIR/WST1.WPD/SP_2.SPF"`): as `CALL`.
bool BlockParser::namedCall(const std::string &written, SourceLoc l) {
  std::string type, name = calledProgram(written, type);
  if (name.size() < 2) return failAt(l, fmt::format("\"{}\" names no program", written), "syntax");
  if (!type.empty()) name = "_N_" + name + "_" + type;
  const Signature *sig = f_.pp.callee(name, l, nullptr, type);
  return plainCall(sig ? &name : nullptr, l, sig && sig->retTarget);
}

// `(expr)` after a keyword, alone in the block; null with an error reported. `empty`: `()` and
// no parentheses at all give "" (CALLPATH resets).
ExprPtr BlockParser::stringArgument(const char *kw, bool empty) {
  ++i_;
  SourceLoc l = loc();
  if (empty && (atEnd() || (tok().is("(") && peek().is(")")))) {
    i_ += atEnd() ? 0 : 2;
    return atEnd() ? Expr::string("", l) : (fail(tok(), fmt::format("{} stands alone in its block", kw)), nullptr);
  }
  if (!expect("(")) return nullptr;
  ExprPtr e = expr(0);
  if (!e || !expect(")")) return nullptr;
  if (!stringy(*e)) return fail(t_[i_ - 2], fmt::format("{} takes a STRING (a path and program name)", kw)), nullptr;
  if (!atEnd()) return fail(tok(), fmt::format("{} stands alone in its block", kw)), nullptr;
  return e;
}

// EXTCALL("[device:][path/]name") (SIN-CAL-10, L8809-L9152): a program of external memory, which
// for ncc is the search path (the device and folders are left out, docs/SINUMERIK.md).
bool BlockParser::extcall() {
  SourceLoc l = loc();
  ExprPtr e = stringArgument("EXTCALL", false);
  if (!e) return false;
  if (e->kind != ir::ExprKind::String) return computedCall(std::move(e), t_[i_ - 1], l);
  return namedCall(e->str, l);
}

// PCALL /_N_WKS_DIR/_N_W_WPD/W(1, 2) (SIN-CAL-08, L8706-L8736): the program named by the path's
// last component, with its arguments, as a plain call.
bool BlockParser::pcall() {
  ++i_;
  while (tok().is("/")) {
    ++i_;
    if (tok().kind != Tok::Name) return fail(tok(), "expected a folder or program name in the PCALL path");
    if (!peek().is("/")) break;
    ++i_;
  }
  if (tok().kind != Tok::Name) return fail(tok(), "expected a program name after PCALL");
  return callStatement(false);
}

// CALLPATH("/_N_WKS_DIR/_N_X_WPD") (SIN-CAL-09, L8738-L8807): the folder joins the search path
// (after --include) for the calls read after it; CALLPATH alone, CALLPATH() and CALLPATH("")
// take it out again.
bool BlockParser::callpath() {
  SourceLoc l = loc();
  if (!f_.ctl.empty())
    return fail(tok(), "CALLPATH inside a control structure is not simulated (ncc finds called programs when it "
                       "reads them: write it outside IF, WHILE …)", "unsupported-code");
  ExprPtr e = stringArgument("CALLPATH", true);
  if (!e) return false;
  if (e->kind != ir::ExprKind::String)
    return failAt(l, "CALLPATH with a computed path is not simulated (write the folder)", "unsupported-code");
  std::string path = e->str;
  size_t b = path.find_first_not_of(' ');
  if (b == std::string::npos) {
    f_.pp.callPath.clear();
    return true;
  }
  std::string dir = f_.pp.programFolder(path.substr(b));
  if (dir.empty())
    return failAt(l, fmt::format("CALLPATH: folder \"{}\" not found in {} (alarm 14009)", path,
                                 folderList(f_.pp.opts.searchDirs)), "missing-subprogram");
  f_.pp.callPath = dir;
  return true;
}

// ISOCALL "NAME" (SIN-CAL-07, L8666-L8704): a program in the ISO dialect, read by the ISO front
// end into a function of its own (frontend/ModeSwitch.h); back in Siemens mode after it.
bool BlockParser::isocall() {
  SourceLoc l = loc();
  ++i_;
  ExprPtr e = expr(0);
  if (!e) return false;
  if (!atEnd()) return fail(tok(), "ISOCALL takes a program name and stands alone in its block");
  if (e->kind != ir::ExprKind::String)
    return failAt(l, "ISOCALL with a name known only at run time is not simulated (write the name)", "unsupported-code");
  return plainCall(f_.pp.isoProgram(e->str, l), l, false);
}

// RET("target" [, after [, levels [, to-start]]]) and RETB(…) (SIN-SUB-13, -14, L7816-L8291): the
// callee leaves the target in the global %%_SIN_RET (RETB: %%_SIN_RETB true) and returns; each call
// of a program with such a RET is followed by the jump to it (resumeAfterCall), a goto whose label
// is the target's text: a label, else a block number `N…` (docs/IR.md §5.2).
bool BlockParser::retStatement(bool backward) {
  SourceLoc l = loc();
  const char *kw = backward ? "RETB" : "RET";
  ++i_;
  std::vector<ExprPtr> args;
  if (tok().is("(")) {
    ++i_;
    while (!tok().is(")")) {
      if (tok().is(",")) {
        args.emplace_back();
        ++i_;
        continue;
      }
      ExprPtr e = expr(0);
      if (!e) return false;
      args.push_back(std::move(e));
      if (tok().is(",")) {
        ++i_;
        if (tok().is(")")) args.emplace_back();
      } else if (!tok().is(")")) {
        return fail(tok(), fmt::format("expected ',' or ')' in {}(…)", kw));
      }
    }
    ++i_;
  }
  if (args.size() > 4) return failAt(l, fmt::format("{} takes at most 4 parameters (target, after, levels, to-start)", kw), "syntax");
  // after 0, one level, no restart: the only forms ncc runs (a block after the target, several
  // levels, the restart of an ISO main program are refused).
  static const char *kWhat[] = {"", "continuing after the target block", "returning more than one level",
                                "restarting the main program"};
  for (size_t k = 1; k < args.size(); ++k) {
    if (!args[k]) continue;
    bool plain = args[k]->kind == ir::ExprKind::Number && args[k]->num == (k == 2 ? 1 : 0);
    plain = plain || (k == 3 && args[k]->kind == ir::ExprKind::Bool && !args[k]->num);
    if (!plain) return failAt(args[k]->loc, fmt::format("{} {} is not simulated", kw, kWhat[k]), "unsupported-code");
  }
  if (args.empty() || !args[0]) {  // RET, RET(), RET( , , 1): back to the caller
    post_.push_back(Op(OpKind::Return, l));
    return true;
  }
  if (f_.isMain) return failAt(l, fmt::format("{} with a jump target in the main program (no caller to go back to)", kw), "syntax");
  f_.retTarget = true;
  f_.pp.retTargets = true;
  post_.push_back(assignOp(Expr::var(ir::VarSpace::Global, kRetTarget, nullptr, l),
                           callOf("TOUPPER", l, callOf("TOSTR", l, std::move(args[0]))), l));
  post_.push_back(assignOp(Expr::var(ir::VarSpace::Global, kRetBackward, nullptr, l), Expr::boolean(backward, l), l));
  post_.push_back(Op(OpKind::Return, l));
  return true;
}

// ENDPROC (operator table, L36769): the end line of a program that starts with PROC, a return
// to the caller like M17; nothing may follow it.
bool BlockParser::endproc() {
  const Token &t = tok();
  if (!f_.startsWithProc) return fail(t, "ENDPROC ends a program whose first statement is PROC");
  if (peek().kind != Tok::End) return fail(peek(), "'ENDPROC' must stand alone in its block");
  ++i_;
  f_.endproc = loc(t);
  post_.push_back(Op(OpKind::Return, f_.endproc));
  return true;
}

// After a call of a program with RET(target): if it left a target, the jump there.
void BlockParser::resumeAfterCall(SourceLoc l) {
  auto ret = [&] { return Expr::var(ir::VarSpace::Global, kRetTarget, nullptr, l); };
  Op iff(OpKind::If, l);
  iff.set("cond", Expr::binary(ir::OpCode::Ne, ret(), Expr::string("", l), l));
  iff.regions.emplace_back();
  ir::Region &r = iff.regions[0];
  r.push_back(assignOp(Expr::var(ir::VarSpace::Global, kRetJump, nullptr, l), ret(), l));
  r.push_back(assignOp(ret(), Expr::string("", l), l));
  for (bool back : {true, false}) {  // RETB searches towards the start (only: docs/SINUMERIK.md)
    Op g(OpKind::Goto, l);
    g.set("label", Expr::var(ir::VarSpace::Global, kRetJump, nullptr, l));
    g.set("dir", Expr::symbol(back ? "backward" : "any"));
    if (!back) {
      r.push_back(std::move(g));
      continue;
    }
    Op b(OpKind::If, l);
    b.set("cond", Expr::var(ir::VarSpace::Global, kRetBackward, nullptr, l));
    b.regions.emplace_back();
    b.regions[0].push_back(std::move(g));
    r.push_back(std::move(b));
  }
  post_.push_back(std::move(iff));
}

void declareReturnTargets(ir::Region &mainBody) {
  std::vector<Op> decls;
  for (const char *n : {kRetTarget, kRetJump, kRetBackward}) {
    Op d(ir::OpKind::Declare, {});
    d.set("var", Expr::var(ir::VarSpace::Global, n, nullptr, {}));
    bool flag = n == kRetBackward;
    d.set("type", Expr::symbol(flag ? "bool" : "string"));
    if (!flag) d.set("len", Expr::number(200, ir::Type::Int));
    decls.push_back(std::move(d));
  }
  mainBody.insert(mainBody.begin(), std::make_move_iterator(decls.begin()), std::make_move_iterator(decls.end()));
}

// EXECSTRING("M7 M4711") (SIN-IND-05, L3018-L3069): the string is a block of its own, read by the
// block parser where the EXECSTRING stands; its tokens keep their columns inside the string, so an
// error in it points into the string's text. Only a constant string: a string computed when the
// program runs would need the engines to parse it then (docs/SINUMERIK.md).
bool BlockParser::execString() {
  const Token &kw = tok();
  SourceLoc l = loc();
  if (!words_.empty() || !gcodes_.empty() || !mcodes_.empty() || !pre_.empty() || !post_.empty())
    return fail(kw, "EXECSTRING stands alone in its block (L3024)");
  ++i_;
  if (!expect("(")) return false;
  uint32_t quote = tok().col;
  bool literal = tok().kind == Tok::String && peek().is(")");
  ExprPtr e = expr(0);
  if (!e || !expect(")")) return false;
  if (!atEnd()) return fail(tok(), "EXECSTRING stands alone in its block (L3024)");
  if (!literal)
    return failAt(l, "EXECSTRING of a string computed when the program runs is not simulated (ncc compiles the "
                     "program before it runs; write the string as a constant or the block itself)", "unsupported-code");
  std::vector<Token> toks;
  std::string err;
  uint32_t errCol = 0;
  if (!lexLine(e->str, toks, err, errCol))
    return failAt({f_.file, line_, quote + errCol}, fmt::format("EXECSTRING \"{}\": {}", e->str, err), "syntax");
  for (auto &t : toks) t.col += quote;
  // Not allowed in the string (L3038-L3043): control structures, PROC, DEF (and EXECSTRING itself).
  static const char *kRefused[] = {"IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "ENDFOR", "LOOP", "ENDLOOP",
                                   "REPEAT", "REPEATB", "UNTIL", "CASE", "PROC", "DEF", "EXECSTRING", "DEFINE"};
  for (auto &t : toks)
    for (const char *r : kRefused)
      if (t.isName(r)) return failAt(loc(t), fmt::format("EXECSTRING \"{}\": {} cannot be executed from a string (L3040)", e->str, r), "syntax");
  if (toks.size() < 2) return true;  // an empty string: nothing to run
  BlockParser inner(f_, toks, line_);
  if (!inner.parse()) failed_ = true;
  return !failed_;
}

bool BlockParser::programCall(const std::string &kw) {
  if (kw == "PCALL") pcall();
  else if (kw == "EXTCALL") extcall();
  else if (kw == "CALLPATH") callpath();
  else if (kw == "ISOCALL") isocall();
  else if (kw == "RET" || kw == "RETB") retStatement(kw == "RETB");
  else if (kw == "ENDPROC") endproc();
  else if (kw == "EXECSTRING") execString();
  else return false;
  return true;
}

}  // namespace ncc::sin
