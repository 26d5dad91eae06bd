// ISVAR("name"), ISVAR("name[i, j]") (L2286-L2370): whether the name is a variable the control
// knows, with its dimensions and indices checked. ncc knows the program's variables and the
// system variables of Codes.cpp when it reads the program, so a constant name is answered
// there; the program's variables include the GUD of the definition files (Gud.cpp), so an
// unknown user name is FALSE.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

namespace {
// "NAME", "NAME[]", "NAME[,]", "NAME[8,]": the name and the index slots (-1 empty); false on a
// syntax error (which ISVAR answers with FALSE).
bool splitName(const std::string &text, std::string &name, std::vector<long> &slots, bool &bracket) {
  size_t b = text.find('[');
  name = text.substr(0, b);
  for (auto &c : name) c = (char)std::toupper((unsigned char)c);
  bracket = b != std::string::npos;
  if (name.empty()) return false;
  if (!bracket) return true;
  if (text.back() != ']') return false;
  std::string inner = text.substr(b + 1, text.size() - b - 2);
  size_t a = 0;
  while (true) {
    size_t c = inner.find(',', a);
    std::string part = inner.substr(a, c == std::string::npos ? std::string::npos : c - a);
    part.erase(0, part.find_first_not_of(' '));
    part.erase(part.find_last_not_of(' ') + 1);
    if (part.empty()) slots.push_back(-1);
    else if (part.find_first_not_of("0123456789") != std::string::npos) slots.push_back(-2);  // an axis name
    else slots.push_back(part.size() > 9 ? 1000000000L : std::stol(part));  // past any dimension (<= 65535)
    if (c == std::string::npos) break;
    a = c + 1;
  }
  return true;
}
}  // namespace

ir::ExprPtr BlockParser::isvar(const Token &t) {
  SourceLoc l = loc(t);
  ++i_;  // (
  ir::ExprPtr arg = expr(0);
  if (!arg || !expect(")")) return nullptr;
  if (arg->kind != ir::ExprKind::String) {
    fail(t, "ISVAR with a computed name is not supported (a constant string is answered when the program is read)",
         "unsupported-code");
    return nullptr;
  }
  std::string name;
  std::vector<long> slots;
  bool bracket = false;
  if (!splitName(arg->str, name, slots, bracket)) return ir::Expr::boolean(false, l);
  if (name[0] == '$') {
    const SysMap *m = findSystemVar(name.substr(1));
    if (!m) {
      fail(t, fmt::format("ISVAR(\"{}\"): ncc does not provide this system variable, the control may", arg->str),
           "unsupported-code");
      return nullptr;
    }
    return ir::Expr::boolean(!bracket || (int)slots.size() == m->indices, l);
  }
  if ((name[0] == 'R' && name.size() > 1 && name.find_first_not_of("0123456789", 1) == std::string::npos)) {
    fail(t, "ISVAR of an R parameter depends on the machine's number of R parameters (MD28050), which ncc does not model",
         "unsupported-code");
    return nullptr;
  }
  auto it = f_.vars.find(name);
  if (it == f_.vars.end()) return ir::Expr::boolean(false, l);
  const VarDecl &d = it->second;
  if (!bracket) return ir::Expr::boolean(true, l);
  // NAME[] for a one-dimensional array: the brackets with one empty slot.
  if (slots.size() != d.dims.size()) return ir::Expr::boolean(false, l);
  for (size_t k = 0; k < slots.size(); ++k)
    if (slots[k] == -2 || (slots[k] >= 0 && (unsigned long)slots[k] >= d.dims[k])) return ir::Expr::boolean(false, l);
  return ir::Expr::boolean(true, l);
}

}  // namespace ncc::sin
