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
  post_.push_back(std::move(c));
  return true;
}

}  // namespace ncc::sin
