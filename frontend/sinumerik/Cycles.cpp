// Siemens standard cycles from the cycle library (SIN-CYC-01, -03, docs/SINUMERIK.md "Cycles"):
// a call `CYCLE81(10, 0, 2, -20)` is lowered to the `cycle` op with the entry's parameters by
// position (an empty position is an omitted argument, absent for the entry, not 0);
// `MCALL CYCLE81(…)` makes it modal (it runs after each following block with a position);
// a position pattern `HOLES1(…)` runs the modal cycle at each of its positions, or only
// positions without one. A subprogram of the cycle's name overrides the library (callee()).
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::Op;
using ir::OpKind;

Op BlockParser::cycleCancel(SourceLoc l) const {
  Op o(OpKind::Cycle, l);
  o.set("action", Expr::symbol("cancel", l));
  return o;
}

// Whether `param` is one of an entry's STRING parameters (CycleSignature::strings): 1 a string the
// cycle uses, 2 one for the input screens only ("~_PTAB"), 0 none.
static int stringParam(std::string_view list, std::string_view param) {
  for (size_t i = 0; i < list.size();) {
    size_t j = std::min(list.find(' ', i), list.size());
    std::string_view item = list.substr(i, j - i);
    if (item == param) return 1;
    if (item.size() == param.size() + 1 && item[0] == '~' && item.substr(1) == param) return 2;
    i = j + 1;
  }
  return 0;
}

bool BlockParser::libraryCycle(bool modal, const std::string &name, const CycleSignature &lib, const Token &at) {
  SourceLoc l = loc(at);
  if (modal && lib.contour) return fail(at, fmt::format("MCALL takes a drilling or milling cycle, not {}", name));
  if (modal && lib.pattern)
    return fail(at, fmt::format("MCALL takes a drilling or milling cycle, not the position pattern {}", name));
  std::vector<std::string> params;
  std::string_view ps = lib.params;
  for (size_t i = 0; i < ps.size();) {
    size_t j = std::min(ps.find(' ', i), ps.size());
    if (j > i) params.emplace_back(ps.substr(i, j - i));
    i = j + 1;
  }
  Op c(OpKind::Cycle, l);
  c.set(lib.pattern ? "pattern" : "entry", Expr::string(lib.name, l));
  if (lib.pattern) c.set("action", Expr::symbol("call", l));
  else if (modal) c.set("action", Expr::symbol("modal", l));
  if (!tok().is("(")) return fail(tok(), fmt::format("{} needs its parameters in parentheses", name));
  if (!argumentList(name, params, lib.pattern ? "p." : "a.", c)) return false;
  int strings = 0;  // the command carries one constant string (HOLES1's _HIDE "1,3")
  for (size_t i = 0; i < c.args.size(); ++i) {
    auto &a = c.args[i];
    if (a.key[1] != '.' || !a.value || a.value->kind != ir::ExprKind::String) continue;
    std::string param = a.key.substr(2);
    const int kind = stringParam(lib.strings, param);
    if (kind == 0) return fail(at, fmt::format("{} parameter {} takes a number, not a string", name, param));
    if (kind == 2) {  // for the control's input screens only (thread tables): no effect on the cycle
      c.args.erase(c.args.begin() + (long)i--);
      continue;
    }
    if (++strings > 1)
      return fail(at, fmt::format("{} parameter {}: only one string argument is supported", name, param),
                  "unsupported-code");
  }
  if (!atEnd() && tok().kind == Tok::Name && tok().text[0] == 'P')
    return fail(tok(), fmt::format("{} is a cycle: it takes no repetition count", name));
  if (modal) {
    Op cancel(OpKind::ModalCall, l);  // replaces a subprogram's modal call
    post_.push_back(std::move(cancel));
  }
  if (lib.contour && !contourCapture(name, lib.contour, c, at)) return false;
  post_.push_back(std::move(c));
  return true;
}

// A cycle that works from a named contour (CYCLE95's NPP): the contour's blocks run into a
// capture the cycle then cuts from (docs/IR.md §5.6 `use=keep`), before the cycle op:
//   contour action=begin use=keep
//   call callee="NAME" frame=new          (a subprogram)  |  call_section from="A" to="B" ("A:B")
//   contour action=end use=keep
bool BlockParser::contourCapture(const std::string &name, const char *param, const Op &cycle, const Token &at) {
  SourceLoc l = loc(at);
  const Expr *npp = cycle.get(std::string("a.") + param);
  if (!npp) return fail(at, fmt::format("{} needs the contour's name {}", name, param), "missing-word");
  if (npp->kind != ir::ExprKind::String)
    return fail(at, fmt::format("{} {}: the contour's name must be a constant string", name, param), "unsupported-code");
  std::string text = npp->str;
  for (char &ch : text) ch = (char)std::toupper((unsigned char)ch);
  if (text.empty()) return fail(at, fmt::format("{} {}: the contour's name is empty", name, param), "cycle-invalid");
  Op begin(OpKind::Contour, l);
  begin.set("action", Expr::symbol("begin", l));
  begin.set("use", Expr::symbol("keep", l));
  post_.push_back(std::move(begin));
  if (size_t colon = text.find(':'); colon != std::string::npos) {  // a section of this program
    std::string from = text.substr(0, colon), to = text.substr(colon + 1);
    if (from.empty() || to.empty() || to.find(':') != std::string::npos)
      return fail(at, fmt::format("{} {} \"{}\": a contour section is \"START:END\", two labels", name, param, npp->str),
                  "cycle-invalid");
    Op s(OpKind::CallSection, l);
    s.set("from", Expr::string(from, l));
    s.set("to", Expr::string(to, l));
    post_.push_back(std::move(s));
  } else {  // a subprogram
    std::string type, callee = calledProgram(text, type);
    if (!type.empty()) callee = "_N_" + callee + "_" + type;
    const Signature *sig = f_.pp.callee(callee, l, nullptr, type);
    if (!sig) {
      failed_ = true;
      return false;
    }
    if (!sig->params.empty())
      return fail(at, fmt::format("{} {}: the contour subprogram {} takes parameters", name, param, callee), "cycle-invalid");
    if (sig->retTarget)
      return fail(at, fmt::format("{} {}: the contour subprogram {} returns with RET(target)", name, param, callee),
                  "unsupported-code");
    Op call(OpKind::Call, l);
    call.set("callee", Expr::string(callee, l));
    call.set("frame", Expr::symbol("new", l));
    post_.push_back(std::move(call));
  }
  Op end(OpKind::Contour, l);
  end.set("action", Expr::symbol("end", l));
  end.set("use", Expr::symbol("keep", l));
  post_.push_back(std::move(end));
  return true;
}

}  // namespace ncc::sin
