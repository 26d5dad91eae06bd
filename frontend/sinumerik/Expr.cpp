// Sinumerik expressions with the manual's precedence (L3443-L3467): comparisons bind loosest,
// below << and the logical operators, so `R1<5 AND R2>3` is `R1 < (5 AND R2) > 3`.
#include "frontend/sinumerik/Parser.h"
#include "ir/Builtins.h"
#include "ir/SystemVars.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::OpCode;

namespace {
struct BinOp {
  const char *text;  // punctuation or an upper-case keyword
  int prec;          // higher binds tighter
  OpCode op;
};
// Comparisons are handled apart (tolerance for REALs, bytes for strings).
const BinOp kBinOps[] = {
    {"==", 1, OpCode::Eq},    {"<>", 1, OpCode::Ne},    {"<", 1, OpCode::Lt},       {"<=", 1, OpCode::Le},
    {">", 1, OpCode::Gt},     {">=", 1, OpCode::Ge},    {"<<", 2, OpCode::Concat},  {"OR", 3, OpCode::Or},
    {"XOR", 4, OpCode::Xor},  {"AND", 5, OpCode::And},  {"B_OR", 6, OpCode::BOr},   {"B_XOR", 7, OpCode::BXor},
    {"B_AND", 8, OpCode::BAnd}, {"+", 9, OpCode::Add},  {"-", 9, OpCode::Sub},      {"*", 10, OpCode::Mul},
    {"/", 10, OpCode::Div},   {"DIV", 10, OpCode::IDiv}, {"MOD", 10, OpCode::Mod},
};
const BinOp *binOp(const Token &t) {
  if (t.kind != Tok::Punct && t.kind != Tok::Name) return nullptr;
  for (auto &b : kBinOps)
    if (t.text == b.text) return &b;
  return nullptr;
}
bool isComparison(OpCode op) { return op >= OpCode::Eq && op <= OpCode::Ge; }
}  // namespace

bool BlockParser::stringy(const Expr &e) const {
  if (e.isStringExpr()) return true;
  if (e.kind == ir::ExprKind::Call) {
    const BuiltinInfo *b = findBuiltin(e.str);
    return b && b->result == 's';
  }
  if (e.kind == ir::ExprKind::Var && (e.space == ir::VarSpace::Local || e.space == ir::VarSpace::Global)) {
    auto it = f_.vars.find(e.str);
    return it != f_.vars.end() &&
           (it->second.type == ir::Type::String || it->second.type == ir::Type::Axis);
  }
  return false;
}

bool BlockParser::frameTyped(const Expr &e) const {
  if (e.kind == ir::ExprKind::Call) {
    const BuiltinInfo *b = findBuiltin(e.str);
    return b && b->result == 'f';
  }
  if (e.kind == ir::ExprKind::Var && e.space == ir::VarSpace::System) return sysVarNameIsFrame(e.str);
  if (e.kind == ir::ExprKind::Var) {
    auto it = f_.vars.find(e.str);
    return it != f_.vars.end() && it->second.type == ir::Type::Frame;
  }
  return false;
}

// REAL comparisons use the controller's relative tolerance (TOLEQ …); strings and CHARs compare
// their bytes. CHAR variables hold one-character strings (docs/IR.md §2.2).
ExprPtr BlockParser::comparison(OpCode op, ExprPtr a, ExprPtr b, SourceLoc l) {
  auto isChar = [&](const Expr &e) {
    if (e.kind != ir::ExprKind::Var) return false;
    auto it = f_.vars.find(e.str);
    return it != f_.vars.end() && it->second.isChar;
  };
  if (stringy(*a) || stringy(*b) || isChar(*a) || isChar(*b)) return Expr::binary(op, std::move(a), std::move(b), l);
  static const char *kTol[] = {"TOLEQ", "TOLNE", "TOLLT", "TOLLE", "TOLGT", "TOLGE"};
  std::vector<ExprPtr> args;
  args.push_back(std::move(a));
  args.push_back(std::move(b));
  args.push_back(Expr::number(f_.pp.opts.realTolerance, ir::Type::Real, l));
  return Expr::call(kTol[(int)op - (int)OpCode::Eq], std::move(args), l);
}

ExprPtr BlockParser::expr(int minPrec) {
  ExprPtr lhs = unary();
  while (lhs) {
    const Token &t = tok();
    const BinOp *b = binOp(t);
    if (!b || b->prec < minPrec) break;
    // A name that is an operator keyword only counts with blanks around it (L3249): `R1 AND R2`.
    SourceLoc l = loc(t);
    ++i_;
    ExprPtr rhs = expr(b->prec + 1);
    if (!rhs) return nullptr;
    if (isComparison(b->op))
      lhs = comparison(b->op, std::move(lhs), std::move(rhs), l);
    else
      lhs = Expr::binary(b->op, std::move(lhs), std::move(rhs), l);
  }
  return lhs;
}

ExprPtr BlockParser::unary() {
  const Token &t = tok();
  SourceLoc l = loc(t);
  if (t.is("-") || t.is("+")) {
    bool neg = t.is("-");
    ++i_;
    ExprPtr a = unary();
    if (!a) return nullptr;
    if (!neg) return a;
    if (a->kind == ir::ExprKind::Number) {
      a->num = -a->num;
      return a;
    }
    return Expr::unary(OpCode::Neg, std::move(a), l);
  }
  if (t.isName("NOT")) {
    ++i_;
    ExprPtr a = unary();
    return a ? Expr::unary(OpCode::Not, std::move(a), l) : nullptr;
  }
  if (t.isName("B_NOT")) {
    // Two's complement: B_NOT x = -x - 1 on integers.
    ++i_;
    ExprPtr a = unary();
    if (!a) return nullptr;
    return Expr::binary(OpCode::Sub, Expr::unary(OpCode::Neg, std::move(a), l), Expr::number(1, ir::Type::Int, l), l);
  }
  if (t.is("<<")) {  // unary <<: the text of any value (L3661)
    ++i_;
    ExprPtr a = unary();
    if (!a) return nullptr;
    std::vector<ExprPtr> args;
    args.push_back(std::move(a));
    return Expr::call("TOSTR", std::move(args), l);
  }
  return primary();
}

ExprPtr BlockParser::primary() {
  const Token &t = tok();
  SourceLoc l = loc(t);
  switch (t.kind) {
  case Tok::Number: ++i_; return Expr::number(t.num, t.isInt ? ir::Type::Int : ir::Type::Real, l);
  case Tok::String: ++i_; return Expr::string(t.text, l);
  case Tok::Name: ++i_; return nameExpr(t);
  case Tok::Punct:
    if (t.is("(")) {
      ++i_;
      ExprPtr e = expr(0);
      if (!e || !expect(")")) return nullptr;
      return e;
    }
    break;
  default: break;
  }
  fail(t, atEnd() ? "expected an expression at the end of the block" : fmt::format("expected an expression, found '{}'", t.text));
  return nullptr;
}

// [i, j, k] after a name; axis names (X, Y …) as indices become strings (system variables).
ExprPtr BlockParser::indexList(std::vector<ExprPtr> &out, bool axisOk) {
  if (!expect("[")) return nullptr;
  do {
    const Token &t = tok();
    bool axisName = machineCtx_ || (findAddress(t.text) && findAddress(t.text)->kind == Addr::Axis);
    if ((axisOk || machineCtx_) && t.kind == Tok::Name && axisName && (peek().is(",") || peek().is("]"))) {
      out.push_back(Expr::symbol(t.text, loc(t)));
      ++i_;
      continue;
    }
    ExprPtr e = expr(0);
    if (!e) return nullptr;
    out.push_back(std::move(e));
  } while (tok().is(",") && (++i_, true));
  if (!expect("]")) return nullptr;
  return Expr::boolean(true);  // success marker
}

// 808D macro arguments (seed001 §2.14.2, ISO-MAC-02): G65/G66 and the M-code macros of an ISO
// program pass address X as $C_X; ncc's ISO front end passes them into the Fanuc locals of the
// callee (argument specification I: A #1 … Z #26), so $C_<letter> reads that local and
// $C_<letter>_PROG says whether the call gave it. $C_ALL_PROG, $C_TYP_PROG (ISO-MAC-03) and $C_G
// (the calling G code of a G-code macro, ISO-MAC-06) are named locals the ISO front end passes
// to a callee that reads them (frontend/iso/LowerCalls.cpp). The I/J/K arrays (specification II
// and the _ORDER sets), $C_INC_PROG and the other $C_ variables are not provided.
static ExprPtr macroArgument(const std::string &name, SourceLoc l) {
  if (name == "C_ALL_PROG" || name == "C_TYP_PROG" || name == "C_G") return Expr::var(ir::VarSpace::Local, "_" + name, nullptr, l);
  static const int kNumber[26] = {1, 2, 3, 7, 8, 9, 0, 11, 4, 5, 6, 0, 13, 0, 0, 0, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  bool prog = name.size() == 8 && name.compare(3, 5, "_PROG") == 0;
  if (name.rfind("C_", 0) != 0 || (name.size() != 3 && !prog) || !std::isupper((unsigned char)name[2])) return nullptr;
  char letter = name[2];
  if (letter == 'I' || letter == 'J' || letter == 'K' || !kNumber[letter - 'A']) return nullptr;
  ExprPtr v = Expr::var(ir::VarSpace::Numbered, "", Expr::number(kNumber[letter - 'A'], ir::Type::Int, l), l);
  return prog ? Expr::binary(ir::OpCode::Ne, std::move(v), Expr::vacant(l), l) : std::move(v);
}

ExprPtr BlockParser::systemVar(const Token &t) {
  std::string name = t.text.substr(1);
  if (ExprPtr arg = f_.pp.opts.macroArguments ? macroArgument(name, loc(t)) : nullptr) return arg;
  const SysMap *m = findSystemVar(name);
  SourceLoc l = loc(t);
  SysMap sum{"", "_tool_data", 2, findToolSumVar(name)};
  if (!m && sum.toolField >= 0) m = &sum;
  else if (!m && sum.toolField == -2) {
    fail(t, fmt::format("'${}': ncc keeps the additive offsets of lengths 1-3 and the radius ($TC_SCPx3 … x6)", name),
         "unsupported-code");
    return nullptr;
  }
  if (!m && machineCtx_) return machineValue();
  if (!m && (name == "AA_ETRANS" || name == "P_EXTFR")) {  // SIN-FRM-17, manual L12683-L12748
    fail(t, fmt::format("'${}': the external zero offset takes effect by the PLC signal DB31 DBX3.0, which ncc does "
                        "not simulate (write the system frame $P_EXTFRAME)",
                        name),
         "unsupported-code");
    return nullptr;
  }
  if (!m) {
    fail(t, fmt::format("system variable '${}' is not provided by ncc", name), "unsupported-code");
    return nullptr;
  }
  std::vector<ExprPtr> idx;
  if (tok().is("[") && !indexList(idx, true)) return nullptr;
  SysMap fixed = *m;
  if (m->fixedIndex >= 0) {  // $P_UBFR = $P_CHBFR[0]: the index as if written
    idx.insert(idx.begin(), Expr::number(m->fixedIndex, ir::Type::Int, l));
    fixed.indices = 1;
    m = &fixed;
  }
  if (m->toolField >= 0) {  // $TC_DP3[t, d] -> $_tool_data[t, d, k]
    if (idx.size() != 2) {
      fail(t, fmt::format("'${}' takes two indices [tool, edge]", name));
      return nullptr;
    }
    idx.push_back(Expr::number(m->toolField, ir::Type::Int, l));
  } else if (sysVarNameIsFrame(m->irName) && (int)idx.size() == m->indices + 2) {
    // $P_PFRAME[X, TR], $P_UIFR[n, X, RT]: a component of the frame (FRAME_GET).
    const Expr &ax = *idx[m->indices], &comp = *idx[m->indices + 1];
    if (ax.kind != ir::ExprKind::Symbol || comp.kind != ir::ExprKind::Var) {
      fail(t, fmt::format("a frame component is written ${}[{}axis, TR|FI|RT|SC|MI]", name, m->indices ? "n, " : ""));
      return nullptr;
    }
    std::string axis = ax.str, c = comp.str;
    idx.resize(m->indices);
    auto v = Expr::var(ir::VarSpace::System, m->irName, nullptr, l);
    v->args = std::move(idx);
    std::vector<ExprPtr> a;
    a.push_back(std::move(v));
    a.push_back(Expr::string(axis, l));
    a.push_back(Expr::string(c, l));
    return Expr::call("FRAME_GET", std::move(a), l);
  } else if ((int)idx.size() != m->indices) {
    int n = m->indices - (m->fixedIndex >= 0);
    fail(t, fmt::format("'${}' takes {} ind{}", name, n, n == 1 ? "ex" : "ices"));
    return nullptr;
  }
  auto v = Expr::var(ir::VarSpace::System, m->irName, nullptr, l);
  v->args = std::move(idx);
  return v;
}

ExprPtr BlockParser::function(const Token &t) {
  SourceLoc l = loc(t);
  if (!machineCtx_) {
    if (t.text == "CALCDAT" || t.text == "INTERSEC") {  // their results go to arrays (Contour.cpp)
      fail(t, fmt::format("{} gives its status as the whole value of an assignment only: S = {}(…)", t.text, t.text));
      return nullptr;
    }
    if (t.text == "ISVAR") return isvar(t);
    if (t.text == "GETVARTYP") return getvartyp(t);
    if (t.text == "STRINGIS") return stringis(t);
    if (t.text == "ISAXIS") return isaxis(t);
    if (t.text == "MODAXVAL") return modaxval(t);
  }
  const FnMap *fm = findFunction(t.text);
  if (!fm && machineCtx_) return machineValue();
  if (!fm) {
    fail(t, fmt::format("function '{}' is not supported", t.text), "unsupported-code");
    return nullptr;
  }
  ++i_;  // (
  std::vector<ExprPtr> args;
  if (!tok().is(")")) {
    do {
      const Token &a = tok();
      if (fm->axisArgs && args.size() % 2 == 0 && a.kind == Tok::Name) {
        args.push_back(Expr::string(a.text, loc(a)));
        ++i_;
        continue;
      }
      ExprPtr e = expr(0);
      if (!e) return nullptr;
      args.push_back(std::move(e));
    } while (tok().is(",") && (++i_, true));
  }
  if (!expect(")")) return nullptr;
  if (t.text == "POT") {  // POT(x) is the square (L3100), the IR's POT a power
    if (args.size() != 1) {
      fail(t, "'POT' takes 1 argument");
      return nullptr;
    }
    args.push_back(Expr::number(2, ir::Type::Int, l));
  }
  if (std::string_view(fm->irName).substr(0, 5) == "FILE_")  // ISFILE: the file builtins name their command
    args.insert(args.begin(), Expr::string(t.text, l));
  if (t.text == "CMIRROR")  // CMIRROR(X, Y): only axis names
    for (auto &a : args)
      if (a->kind != ir::ExprKind::String) {
        fail(t, "CMIRROR takes axis names");
        return nullptr;
      }
  const BuiltinInfo *b = findBuiltin(fm->irName);
  if (b && !b->accepts(args.size())) {
    fail(t, fmt::format("'{}' takes {} argument{}, found {}", t.text, builtinArity(*b), b->arity == 1 ? "" : "s",
                        args.size()));
    return nullptr;
  }
  return Expr::call(fm->irName, std::move(args), l);
}

// In a machine-specific construct (MachineOnly.cpp) a system variable, function or name ncc does
// not provide (`$AA_IM[X]`, `CTAB(…)`, an axis or program name) is read for its syntax only: its
// indices or arguments, then a REAL placeholder (the construct is never run).
ExprPtr BlockParser::machineValue() {
  SourceLoc l = loc(t_[i_ - 1]);
  std::vector<ExprPtr> args;
  if (tok().is("[") && !indexList(args, true)) return nullptr;
  if (tok().is("(")) {
    ++i_;
    if (!tok().is(")")) do {
        if (tok().is(",")) continue;
        if (!expr(0)) return nullptr;
      } while (tok().is(",") && (++i_, true));
    if (!expect(")")) return nullptr;
  }
  return Expr::number(0, ir::Type::Real, l);
}

ExprPtr BlockParser::variable(const Token &t) {
  SourceLoc l = loc(t);
  auto it = f_.vars.find(t.text);
  if (it == f_.vars.end()) return nullptr;
  const VarDecl &d = it->second;
  auto v = Expr::var(d.global ? ir::VarSpace::Global : ir::VarSpace::Local, t.text, nullptr, l);
  if (tok().is("[")) {
    std::vector<ExprPtr> idx;
    bool frameComp = d.type == ir::Type::Frame && d.dims.empty();
    if (!indexList(idx, frameComp)) return nullptr;
    if (d.type == ir::Type::String && !d.isChar && idx.size() == d.dims.size() + 1) {
      // S[i], S[k, i]: one character of the string (CHAR_AT; written through CHAR_SET).
      ExprPtr i = std::move(idx.back());
      idx.pop_back();
      v->args = std::move(idx);
      return callOf("CHAR_AT", l, std::move(v), std::move(i));
    }
    if (frameComp) {  // F[X, TR]: a component of a frame variable
      if (idx.size() != 2 || idx[0]->kind != ir::ExprKind::Symbol || idx[1]->kind != ir::ExprKind::Var) {
        fail(t, fmt::format("a frame component is written {}[axis, TR|FI|RT|SC|MI]", t.text));
        return nullptr;
      }
      std::vector<ExprPtr> a;
      a.push_back(std::move(v));
      a.push_back(Expr::string(idx[0]->str, l));
      a.push_back(Expr::string(idx[1]->str, l));
      return Expr::call("FRAME_GET", std::move(a), l);
    }
    v->args = std::move(idx);
  }
  return v;
}

ExprPtr BlockParser::nameExpr(const Token &t) {
  SourceLoc l = loc(t);
  if (t.text == "TRUE" || t.text == "FALSE") return Expr::boolean(t.text == "TRUE", l);
  if (t.text[0] == '$') return systemVar(t);
  if (machineCtx_ && isSyncKeyword(t.text)) {  // WHEN R1 > DO: the operand is missing
    fail(t, fmt::format("expected an expression, found '{}'", t.text));
    return nullptr;
  }
  if (tok().is("(") ) return function(t);
  if (f_.vars.count(t.text)) return variable(t);
  if (t.text == "DELDL" && !machineCtx_) {  // its status only as an assignment's value (ToolData.cpp)
    fail(t, "DELDL gives its status as the whole value of an assignment only: S = DELDL[t, d]");
    return nullptr;
  }
  if (t.text == "R" && tok().is("[")) {
    ++i_;
    ExprPtr e = expr(0);
    if (!e || !expect("]")) return nullptr;
    return Expr::var(ir::VarSpace::RParam, "R", std::move(e), l);
  }
  if (t.text[0] == 'R' && t.digitsAt == 1 && !t.fraction)
    return Expr::var(ir::VarSpace::RParam, "R", Expr::number(t.num, ir::Type::Int, l), l);
  if (t.text == "RG" && tok().is("[")) {  // RG[n]: a global R parameter (SIN-VAR-05), one array for the program
    ++i_;
    ExprPtr e = expr(0);
    if (!e || !expect("]")) return nullptr;
    f_.pp.globalR = true;
    return Expr::var(ir::VarSpace::Global, kGlobalR, std::move(e), l);
  }
  if (machineCtx_) return machineValue();
  // An axis name as a value (`AA = X`, `DEF AXIS AA = (X)`, L1356): its name, what an AXIS holds.
  if (const AddrInfo *a = findAddress(t.text); a && a->kind == Addr::Axis && t.digitsAt == t.text.size())
    return Expr::string(t.text, l);
  // Frame component names read as themselves (F[X, TR]); they are checked by variable().
  static const char *kComponents[] = {"TR", "FI", "RT", "SC", "MI"};
  for (const char *c : kComponents)
    if (t.text == c && tok().is("]")) return Expr::var(ir::VarSpace::Local, c, nullptr, l);
  fail(t, fmt::format("unknown name '{}': not a variable, R parameter or function", t.text));
  return nullptr;
}

}  // namespace ncc::sin
