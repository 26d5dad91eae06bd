// Structure-keeping translation: variables, operators, builtins and comparisons, each written
// only where the target's front end reads it back to the same NC IR meaning (docs/EMIT.md
// "Structure-keeping translation", the mapping tables).
#include "backends/emit/StructuredImpl.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string_view>

namespace ncc::emit::structured {

using ir::ExprKind;
using ir::OpCode;
using ir::VarSpace;

std::string exactNumber(double v, bool point) {
  if (v == 0) v = 0;  // no "-0"
  std::string s;
  for (int d = 0; d <= 40; ++d) {
    s = fmt::format("{:.{}f}", v, d);
    if (std::strtod(s.c_str(), nullptr) == v) break;
  }
  if (s.find('.') == std::string::npos) {
    if (point) s += '.';
  }
  return s;
}

bool Writer::fail(SourceLoc loc, const std::string &what) {
  diags_.error(loc, fmt::format("structure-keeping translation to {}: {}; translate without --keep-structure for a flat program",
                                targetName(o_.target), what),
               "unsupported-code");
  ok_ = false;
  return false;
}

// ---------------------------------------------------------------- operators
// The IR operators both readers give the same meaning; nullptr: the target has no spelling.
struct OpSpelling {
  OpCode op;
  const char *iso, *sinumerik;
};
static const OpSpelling kOps[] = {
    {OpCode::Add, "+", "+"},        {OpCode::Sub, "-", "-"},       {OpCode::Mul, "*", "*"},
    {OpCode::Div, "/", "/"},        {OpCode::Mod, "MOD", "MOD"},   {OpCode::IDiv, nullptr, "DIV"},
    {OpCode::And, "AND", "AND"},    {OpCode::Or, "OR", "OR"},      {OpCode::Xor, "XOR", "XOR"},
    {OpCode::Concat, nullptr, "<<"}, {OpCode::Pow, nullptr, nullptr},
    {OpCode::BAnd, "AND", nullptr}, {OpCode::BOr, "OR", nullptr},  {OpCode::BXor, "XOR", nullptr},
};
// Comparisons: ISO's exact ones, Sinumerik's with the machine's relative tolerance (TOL*).
static const char *const kIsoCmp[] = {"EQ", "NE", "LT", "LE", "GT", "GE"};
static const char *const kSinCmp[] = {"==", "<>", "<", "<=", ">", ">="};
static const char *const kTolNames[] = {"TOLEQ", "TOLNE", "TOLLT", "TOLLE", "TOLGT", "TOLGE"};

// Builtins: the IR name, then the spelling each reader turns back into that IR builtin with the
// same arity; nullptr where the target has none that agrees exactly (docs/EMIT.md).
struct FnSpelling {
  const char *ir, *iso, *sinumerik;
  const char *why;  // why a missing spelling is missing
};
static const FnSpelling kFns[] = {
    {"SIN", "SIN", "SIN", ""},
    {"COS", "COS", "COS", ""},
    {"TAN", "TAN", "TAN", ""},
    {"ASIN", "ASIN", "ASIN", ""},
    {"ACOS", "ACOS", "ACOS", ""},
    {"ATAN", "ATAN", nullptr, "Sinumerik has only the two-argument ATAN2"},
    {"ATAN2", "ATAN", nullptr, "Fanuc's ATAN[a]/[b] is 0..360, Sinumerik's ATAN2 -180..180"},
    {"ATAN2_SIGNED", nullptr, "ATAN2", "Sinumerik's ATAN2 is -180..180, Fanuc's ATAN[a]/[b] 0..360"},
    {"SQRT", "SQRT", "SQRT", ""},
    {"ABS", "ABS", "ABS", ""},
    {"ROUND", "ROUND", "ROUND", ""},
    {"TRUNC", "FIX", "TRUNC", ""},
    {"AWAYFROMZERO", "FUP", nullptr, "Fanuc's FUP rounds away from zero; Sinumerik has no such function"},
    {"ROUNDUP", nullptr, nullptr, "Sinumerik's ROUNDUP rounds up; Fanuc's FUP rounds away from zero"},
    {"FIX", nullptr, nullptr, "LinuxCNC's FIX rounds down; Fanuc's FIX and Sinumerik's TRUNC toward zero"},
    {"FUP", nullptr, nullptr, "LinuxCNC's FUP rounds up; Fanuc's FUP rounds away from zero"},
    {"LN", "LN", "LN", ""},
    {"EXP", "EXP", "EXP", ""},
    {"MINVAL", nullptr, "MINVAL", "Fanuc Macro B has no MIN"},
    {"MAXVAL", nullptr, "MAXVAL", "Fanuc Macro B has no MAX"},
};

// Operators of one level, left-associative in both languages: `a + b - c` needs no brackets
// around its left operand.
static int chainLevel(const Expr &e) {
  if (e.kind != ExprKind::Binary) return 0;
  if (e.op == OpCode::Add || e.op == OpCode::Sub) return 1;
  if (e.op == OpCode::Mul || e.op == OpCode::Div) return 2;
  return 0;
}

bool Writer::wrap(const Expr &e, std::string &out, const Expr *parent) {
  std::string s;
  if (!expr(e, s)) return false;
  if (parent && chainLevel(e) && chainLevel(e) == chainLevel(*parent)) return out += s, true;
  bool tol = e.kind == ExprKind::Call && std::string_view(e.str).substr(0, 3) == "TOL";
  bool atomic = e.kind == ExprKind::Var || (e.kind == ExprKind::Call && !tol) ||
                (e.kind == ExprKind::Number && e.num >= 0);
  out += atomic ? s : (iso_ ? "[" + s + "]" : "(" + s + ")");
  return true;
}

bool Writer::expr(const Expr &e, std::string &out) {
  switch (e.kind) {
  case ExprKind::Number:
    out += exactNumber(e.num, false);
    return true;
  case ExprKind::Bool:
    // A truth value is the number 1 or 0 in both engines (docs/IR.md §2.1).
    out += iso_ ? (e.num != 0 ? "1" : "0") : (e.num != 0 ? "TRUE" : "FALSE");
    return true;
  case ExprKind::String:
    if (iso_) return fail(e.loc, "a string value (Fanuc Macro B has no strings)");
    out += "\"" + e.str + "\"";
    return true;
  case ExprKind::Var:
    return variable(e, out);
  case ExprKind::Vacant:
    return fail(e.loc, "the vacant value #0 (Sinumerik R parameters are never vacant)");
  case ExprKind::Unary: {
    if (e.op == OpCode::Not && !iso_) {
      out += "NOT ";
      return wrap(*e.args[0], out);
    }
    if (e.op == OpCode::Not) return fail(e.loc, "a logical NOT (Fanuc Macro B has none)");
    out += "-";
    return wrap(*e.args[0], out);
  }
  case ExprKind::Binary:
    return binary(e, out);
  case ExprKind::Call:
    return call(e, out);
  case ExprKind::Symbol:
    break;
  }
  return fail(e.loc, "the symbol '" + e.str + "' as a value");
}

bool Writer::binary(const Expr &e, std::string &out) {
  if (e.op >= OpCode::Eq && e.op <= OpCode::Ge) return comparison(e.op, *e.args[0], *e.args[1], e.loc, out);
  for (const OpSpelling &s : kOps) {
    if (s.op != e.op) continue;
    const char *sp = iso_ ? s.iso : s.sinumerik;
    if (!sp) break;
    // ISO reads AND/OR/XOR as logical only between truth values and as bitwise elsewhere: write
    // each only where it reads back the same (frontend/iso/BlockParser.cpp fanucSemantics).
    bool logical = e.op == OpCode::And || e.op == OpCode::Or || e.op == OpCode::Xor;
    auto truth = [](const Expr &a) {
      return (a.kind == ExprKind::Binary && a.op >= OpCode::Eq && a.op <= OpCode::Xor) ||
             (a.kind == ExprKind::Call && std::string_view(a.str).substr(0, 3) == "TOL");
    };
    if (iso_ && logical != (truth(*e.args[0]) && truth(*e.args[1]))) break;
    if (!wrap(*e.args[0], out, &e)) return false;
    out += fmt::format(" {} ", sp);
    return wrap(*e.args[1], out);
  }
  return fail(e.loc, fmt::format("the operator '{}' (no exact equivalent in {})", ir::opCodeName(e.op), targetName(o_.target)));
}

static bool isZero(const Expr &e) { return e.kind == ExprKind::Number && e.num == 0; }

// An exact comparison. Sinumerik compares with a relative tolerance, except against 0, where
// |a| <= tol*|a| only holds for a = 0: so `a > b` is written `a - b > 0` (the difference of two
// doubles is 0 only when they are equal), and `a > 0` as it is.
bool Writer::comparison(OpCode op, const Expr &a, const Expr &b, SourceLoc loc, std::string &out) {
  int k = (int)op - (int)OpCode::Eq;
  if (iso_) {
    if (!wrap(a, out)) return false;
    out += fmt::format(" {} ", kIsoCmp[k]);
    return wrap(b, out);
  }
  if (isZero(b) || isZero(a)) {
    if (!wrap(a, out)) return false;
  } else {
    std::string d;
    if (!wrap(a, d)) return false;
    d += " - ";
    if (!wrap(b, d)) return false;
    out += "(" + d + ")";
  }
  out += fmt::format(" {} ", kSinCmp[k]);
  if (isZero(a) && !isZero(b)) return wrap(b, out);
  out += "0";
  (void)loc;
  return true;
}

// A Sinumerik comparison (TOLxx a b tol) on a target with the same tolerance: as written; on
// ISO against 0 exact as it is, else spelled out: equal means |a-b| <= tol*|a| OR <= tol*|b|.
bool Writer::toleranceComparison(const Expr &e, std::string &out) {
  int k = 0;
  while (e.str != kTolNames[k]) ++k;
  const Expr &a = *e.args[0], &b = *e.args[1], &tol = *e.args[2];
  if (tol.kind != ExprKind::Number || tol.num != o_.realTolerance)
    return fail(e.loc, "a comparison with another tolerance than the machine's");
  if (!iso_ || isZero(a) || isZero(b)) {
    if (!wrap(a, out)) return false;
    out += fmt::format(" {} ", iso_ ? kIsoCmp[k] : kSinCmp[k]);
    return wrap(b, out);
  }
  std::string sa, sb, d;
  if (!wrap(a, sa) || !wrap(b, sb)) return false;
  d = fmt::format("ABS[{} - {}]", sa, sb);
  std::string t = exactNumber(tol.num, false);
  std::string eq = fmt::format("[{} LE [{} * ABS[{}]]] OR [{} LE [{} * ABS[{}]]]", d, t, sa, d, t, sb);
  std::string ne = fmt::format("[{} GT [{} * ABS[{}]]] AND [{} GT [{} * ABS[{}]]]", d, t, sa, d, t, sb);
  std::string lt = fmt::format("[{} {} {}]", sa, k < 4 ? "LT" : "GT", sb);
  static const int kForm[] = {0, 1, 2, 3, 2, 3};  // eq, ne, strict and not equal, or equal
  switch (kForm[k]) {
  case 0: out += eq; break;
  case 1: out += ne; break;
  case 2: out += lt + " AND " + ne; break;
  default: out += lt + " OR " + eq; break;
  }
  return true;
}

bool Writer::call(const Expr &e, std::string &out) {
  if (std::string_view(e.str).substr(0, 3) == "TOL" && e.args.size() == 3) return toleranceComparison(e, out);
  for (const FnSpelling &f : kFns) {
    if (e.str != f.ir) continue;
    const char *sp = iso_ ? f.iso : f.sinumerik;
    if (!sp) return fail(e.loc, fmt::format("the function {} ({})", e.str, f.why));
    // ISO's two-argument arc tangent is written ATAN[a]/[b] (Fanuc).
    if (iso_ && e.str == std::string("ATAN2")) {
      std::string a, b;
      if (!expr(*e.args[0], a) || !expr(*e.args[1], b)) return false;
      out += fmt::format("ATAN[{}]/[{}]", a, b);
      return true;
    }
    out += sp;
    out += iso_ ? "[" : "(";
    for (size_t i = 0; i < e.args.size(); ++i) {
      if (i) out += ", ";
      if (!expr(*e.args[i], out)) return false;
    }
    out += iso_ ? "]" : ")";
    return true;
  }
  // Sinumerik POT(x) is the square: the IR's POT with a literal 2.
  if (e.str == "POT" && !iso_ && e.args.size() == 2 && e.args[1]->kind == ExprKind::Number && e.args[1]->num == 2) {
    out += "POT(";
    if (!expr(*e.args[0], out)) return false;
    out += ")";
    return true;
  }
  return fail(e.loc, fmt::format("the function {} (no exact equivalent in {})", e.str, targetName(o_.target)));
}

// ---------------------------------------------------------------- variables
bool Writer::variable(const Expr &e, std::string &out) {
  const Expr *idx = e.args.empty() ? nullptr : e.args[0].get();
  bool constIdx = idx && idx->kind == ExprKind::Number && idx->num == std::floor(idx->num) && e.args.size() == 1;
  switch (e.space) {
  case VarSpace::Numbered: {
    if (!constIdx) return fail(e.loc, "a computed parameter number #[...]");
    int n = (int)idx->num;
    if (iso_) {
      out += fmt::format("#{}", n);
      return true;
    }
    if (n < 1 || n >= o_.rParams)
      return fail(e.loc, fmt::format("variable #{} has no R parameter (the machine's R0..R{}: #n is written R n)", n,
                                     o_.rParams - 1));
    out += fmt::format("R{}", n);
    return true;
  }
  case VarSpace::RParam: {
    if (!constIdx) return fail(e.loc, "a computed R parameter R[...]");
    int n = (int)idx->num;
    if (!iso_) {
      out += fmt::format("R{}", n);
      return true;
    }
    if (n < 0 || n > 99) return fail(e.loc, fmt::format("R{} has no Fanuc variable (R0..R99 are written #100..#199)", n));
    rUsed_.insert(n);
    out += fmt::format("#{}", 100 + n);
    return true;
  }
  case VarSpace::Local: {
    if (idx) return fail(e.loc, fmt::format("the array element {}[...]", e.str));
    auto it = locals_.find(e.str);
    if (iso_) {
      if (it == locals_.end()) return fail(e.loc, fmt::format("the undeclared variable '{}'", e.str));
      out += fmt::format("#{}", it->second.number);
      return true;
    }
    // LinuxCNC names are case-insensitive and may hold characters Sinumerik names cannot; a
    // Sinumerik name starts with two letters (else `X1` would be an axis word) and is no keyword.
    static const std::set<std::string> kReserved = {
        "AND", "OR", "NOT", "XOR", "MOD", "DIV", "DEF", "REAL", "INT", "BOOL", "CHAR", "STRING", "AXIS", "FRAME",
        "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "TO", "ENDFOR", "LOOP", "ENDLOOP", "REPEAT", "UNTIL",
        "GOTO", "GOTOF", "GOTOB", "GOTOC", "CASE", "OF", "DEFAULT", "CALL", "MCALL", "PROC", "RET", "TRUE", "FALSE",
        "CR", "AR", "AP", "RP", "RND", "RNDM", "CHF", "CHR", "AC", "IC", "DC", "ACP", "ACN", "CIP", "CT", "TURN", "SF",
        "PL", "PW", "SD", "MSG", "SETAL", "STOPRE", "SPOS", "TRANS", "ATRANS", "ROT", "AROT", "SCALE", "ASCALE",
        "MIRROR", "AMIRROR", "LIMS", "SCC", "DISC", "ADIS", "CTOL", "OTOL"};
    std::string up = e.str;
    for (char &c : up) c = (char)std::toupper((unsigned char)c);
    bool ok = up.size() >= 2 && up.size() <= 31 && !kReserved.count(up);
    for (size_t i = 0; i < up.size(); ++i)
      ok &= i < 2 ? (std::isalpha((unsigned char)up[i]) || up[i] == '_') : (std::isalnum((unsigned char)up[i]) || up[i] == '_');
    if (!ok) return fail(e.loc, fmt::format("the variable name '{}' (not a Sinumerik name: two letters first, no keyword)", e.str));
    if (it == locals_.end()) locals_[e.str] = Declared{};
    out += up;
    return true;
  }
  case VarSpace::Global:
    return fail(e.loc, fmt::format("the global variable '{}'", e.str));
  case VarSpace::System:
    return fail(e.loc, fmt::format("the system variable '{}'", e.str));
  case VarSpace::QParam:
    break;
  }
  return fail(e.loc, fmt::format("the Q parameter {}", e.str));
}

bool Writer::storeValue(const Expr &target, const Expr &value, std::string &out) {
  if (iso_ && target.space == VarSpace::Local) {
    auto it = locals_.find(target.str);
    if (it != locals_.end() && it->second.type == ir::Type::Int && value.kind == ExprKind::Number) {
      out += exactNumber(std::round(value.num), false);
      return true;
    }
    if (it != locals_.end() && it->second.type == ir::Type::Bool) {
      // A BOOL stores 1 for any number but 0.
      if (value.kind == ExprKind::Number) return out += value.num != 0 ? "1" : "0", true;
      return condition(value, out);
    }
    if (it != locals_.end() && it->second.type == ir::Type::Int) {
      // A Sinumerik INT rounds what it stores, half away from zero: ROUND does the same.
      out += "ROUND[";
      if (!expr(value, out)) return false;
      out += "]";
      return true;
    }
  }
  return expr(value, out);
}

static bool isTruth(const Expr &e) {
  return e.kind == ExprKind::Bool || (e.kind == ExprKind::Binary && e.op >= OpCode::Eq && e.op <= OpCode::Xor) ||
         (e.kind == ExprKind::Unary && e.op == OpCode::Not) ||
         (e.kind == ExprKind::Call && std::string_view(e.str).substr(0, 3) == "TOL");
}

bool Writer::condition(const Expr &e, std::string &out) {
  if (!iso_ || isTruth(e)) return expr(e, out);
  // A number as a condition is true when it is not 0; Fanuc's IF and WHILE want a comparison.
  if (!wrap(e, out)) return false;
  out += " NE 0";
  return true;
}

bool Writer::word(const Expr &e, std::string &out) {
  if (e.kind == ExprKind::Number) {
    out += exactNumber(e.num, iso_);
    return true;
  }
  std::string s;
  if (!expr(e, s)) return false;
  if (iso_) out += e.kind == ExprKind::Var ? s : "[" + s + "]";
  else out += "=" + (e.kind == ExprKind::Var ? s : "(" + s + ")");
  return true;
}

}  // namespace ncc::emit::structured
