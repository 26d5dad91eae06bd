// The introspection functions, answered when the program is read (ncc knows the program's
// variables, the GUD of the definition files (Gud.cpp), the system variables of Codes.cpp and the
// control's names of the operator table then), so each takes a constant name:
// - ISVAR("name"), ISVAR("name[i, j]") (L2286-L2370): whether the name is a variable the control
//   knows, with its dimensions and indices checked; an unknown user name is FALSE.
// - GETVARTYP("name") (L2645-L2680): the type code 1 BOOL … 7 FRAME, negative for no variable.
// - STRINGIS("name") (L25639-L25770): what the name is in the control's language, yxx.
// - ISAXIS(n) (L25089-L25118): whether geometry axis n (1 abscissa X, 2 ordinate Y, 3 applicate
//   Z) exists on the machine [model: the machine description's X Y Z, as MD20050 assigns them].
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

#include <cstring>

namespace ncc::sin {

namespace {
std::string upperName(std::string s) {
  for (auto &c : s) c = (char)std::toupper((unsigned char)c);
  return s;
}

// "NAME", "NAME[]", "NAME[,]", "NAME[8,]": the name and the index slots (-1 empty); false on a
// syntax error (which ISVAR answers with FALSE).
bool splitName(const std::string &text, std::string &name, std::vector<long> &slots, bool &bracket) {
  size_t b = text.find('[');
  name = upperName(text.substr(0, b));
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

// The one argument of an introspection function: a constant string (or number for ISAXIS), else
// null with an error.
ir::ExprPtr BlockParser::constantArg(const Token &t, ir::ExprKind kind) {
  ++i_;  // (
  ir::ExprPtr arg = expr(0);
  if (!arg || !expect(")")) return nullptr;
  if (arg->kind != kind) {
    bool str = kind == ir::ExprKind::String;
    fail(t, fmt::format("{} with a computed {} is not supported (a constant{} is answered when the program is read)",
                        t.text, str ? "name" : "axis number", str ? " string" : ""),
         "unsupported-code");
    return nullptr;
  }
  return arg;
}

ir::ExprPtr BlockParser::isvar(const Token &t) {
  SourceLoc l = loc(t);
  ir::ExprPtr arg = constantArg(t, ir::ExprKind::String);
  if (!arg) return nullptr;
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

namespace {
// GETVARTYP's codes (L2653-L2660).
int typeCode(const VarDecl &d) {
  if (d.isChar) return 2;
  switch (d.type) {
  case ir::Type::Bool: return 1;
  case ir::Type::Int: return 3;
  case ir::Type::String: return 5;
  case ir::Type::Axis: return 6;
  case ir::Type::Frame: return 7;
  default: return 4;
  }
}

// The type of a system variable ncc provides (Codes.cpp), from the manual's naming: frames end in
// FRAME or FR ($P_UIFR, $P_CHBFR), masks, numbers and the tool's type and cutting position are INT.
int systemTypeCode(std::string_view name) {
  auto ends = [&](std::string_view s) { return name.size() >= s.size() && name.substr(name.size() - s.size()) == s; };
  if (ends("FRAME") || ends("FR")) return 7;
  static const std::string_view kInts[] = {"P_TOOLNO", "P_TOOL", "P_UIFRNUM", "TC_DP1", "TC_DP2"};
  for (auto n : kInts)
    if (name == n) return 3;
  if (ends("MASK") || ends("NUM")) return 3;
  return 4;
}
}  // namespace

ir::ExprPtr BlockParser::getvartyp(const Token &t) {
  SourceLoc l = loc(t);
  ir::ExprPtr arg = constantArg(t, ir::ExprKind::String);
  if (!arg) return nullptr;
  std::string name = upperName(arg->str);
  auto answer = [&](int code) { return ir::Expr::number(code, ir::Type::Int, l); };
  if (name.find_first_of("[ ") != std::string::npos) {
    fail(t, fmt::format("GETVARTYP(\"{}\"): the name of a variable, without indices", arg->str));
    return nullptr;
  }
  if (name == "R") return answer(4);  // the R parameters (the manual's example)
  if (!name.empty() && name[0] == '$') {
    if (!findSystemVar(name.substr(1))) {
      fail(t, fmt::format("GETVARTYP(\"{}\"): ncc does not provide this system variable, the control may", arg->str),
           "unsupported-code");
      return nullptr;
    }
    return answer(systemTypeCode(name.substr(1)));
  }
  if (name.size() > 1 && name[0] == 'R' && name.find_first_not_of("0123456789", 1) == std::string::npos) {
    fail(t, "GETVARTYP of an R parameter depends on the machine's number of R parameters (MD28050), which ncc does not model",
         "unsupported-code");
    return nullptr;
  }
  auto it = f_.vars.find(name);
  return answer(it == f_.vars.end() ? -1 : typeCode(it->second));
}

namespace {
// STRINGIS's answers (L25700-L25726): y = 0 unknown, 2 programmable, 4 a user-defined address;
// xx the kind of a programmable element.
enum StringIs { Unknown = 0, Address = 201, GCodeName = 202, Function = 203, Procedure = 204, Keyword = 205,
                MachineData = 206, SystemVariable = 207, Cycle = 208, Gud = 209, Macro = 210, Lud = 211,
                UserAddress = 400 };
// The NC addresses that take an extension (A1, X2) and those a machine defines (D, M, T …), L25744-L25749.
bool axisLikeAddress(char c) { return std::strchr("ABCEIJKQUVWXYZ", c) != nullptr; }
bool userAddress(char c) { return std::strchr("DFHLMNOPST", c) != nullptr; }
}  // namespace

ir::ExprPtr BlockParser::stringis(const Token &t) {
  SourceLoc l = loc(t);
  ir::ExprPtr arg = constantArg(t, ir::ExprKind::String);
  if (!arg) return nullptr;
  std::string name = upperName(arg->str);
  name.erase(name.find_last_not_of(' ') + 1);  // "GETMDACT " in the manual's example 6
  name.erase(0, name.find_first_not_of(' '));
  auto answer = [&](int code) { return ir::Expr::number(code, ir::Type::Int, l); };
  auto unknown = [&](const char *why) {
    fail(t, fmt::format("STRINGIS(\"{}\"): {}; ncc cannot tell what the control answers", arg->str, why),
         "unsupported-code");
    return nullptr;
  };
  if (name.empty()) return answer(Unknown);
  bool digitsAfter = name.size() > 1 && name.find_first_not_of("0123456789", 1) == std::string::npos;
  if (name.size() == 1 || digitsAfter) {
    if (name[0] == 'R' && digitsAfter)
      return unknown("an R parameter depends on the machine's number of R parameters (MD28050)");
    if (name[0] == 'G' && digitsAfter) {
      if (findGCode(name).code) return answer(GCodeName);
    } else if (axisLikeAddress(name[0])) {
      return answer(Address);
    } else if (userAddress(name[0])) {
      return answer(name.size() == 1 ? UserAddress : Unknown);
    }
  }
  if (name[0] == '$') {
    std::string_view sys = std::string_view(name).substr(name[1] == '$' ? 2 : 1);
    if (findSystemVar(sys)) return answer(SystemVariable);
    return unknown("a system variable or machine datum ncc does not provide");
  }
  if (f_.vars.count(name)) return answer(f_.pp.guds.count(name) ? Gud : Lud);
  if (f_.macros.count(name)) return answer(Macro);
  if (findGCode(name).code) return answer(GCodeName);
  CycleSignature cyc;
  if (f_.pp.opts.cycles && f_.pp.opts.cycles(std::string("sin.") + name, cyc)) return answer(Cycle);
  if (const PredefinedName *p = findPredefined(name)) {
    static const std::pair<std::string_view, int> kKinds[] = {
        {"address", Address}, {"function", Function}, {"procedure", Procedure}, {"keyword", Keyword},
        {"program attribute", Keyword}, {"cycle", Cycle}};
    for (auto &[kind, code] : kKinds)
      if (p->kind == kind) {
        if (code == Cycle) return unknown("a standard cycle the cycle library does not have");
        return answer(code);
      }
  }
  return unknown("not a name of the operator table or of this program");
}

ir::ExprPtr BlockParser::isaxis(const Token &t) {
  SourceLoc l = loc(t);
  ir::ExprPtr arg = constantArg(t, ir::ExprKind::Number);
  if (!arg) return nullptr;
  if (arg->num != 1 && arg->num != 2 && arg->num != 3) {
    fail(t, fmt::format("ISAXIS takes a geometry axis number 1, 2 or 3, not {}", arg->num));
    return nullptr;
  }
  return ir::Expr::boolean((f_.pp.opts.geoAxes >> ((int)arg->num - 1)) & 1u, l);
}

// MODAXVAL(<axis>, <position>) (SIN-AUX-04, manual L25092-L25182): the position reduced to a
// modulo rotary axis's range, unchanged for any other axis. The linear axes X Y Z U V W are
// answered (the position itself); whether A B C are modulo axes and their range (MD30310,
// MD30330, MD30340) the machine description does not say, so they are refused, as is an axis
// only known at run time.
ir::ExprPtr BlockParser::modaxval(const Token &t) {
  ++i_;  // (
  const Token &a = tok();
  const AddrInfo *addr = a.kind == Tok::Name ? findAddress(a.text) : nullptr;
  if (!addr || addr->kind != Addr::Axis) {
    fail(a, "MODAXVAL takes an axis name (X Y Z U V W; a computed axis is not supported)", "unsupported-code");
    return nullptr;
  }
  if (std::string_view("ABC").find(a.text[0]) != std::string_view::npos) {
    fail(a, fmt::format("MODAXVAL of the rotary axis {}: whether it is a modulo axis and its range (MD30310, MD30330, "
                        "MD30340) are not in the machine description",
                        a.text),
         "unsupported-code");
    return nullptr;
  }
  ++i_;
  if (!expect(",")) return nullptr;
  ir::ExprPtr pos = expr(0);
  if (!pos || !expect(")")) return nullptr;
  return pos;  // a linear axis: the position unchanged (L25174-L25182)
}

}  // namespace ncc::sin
