// Data statements: DEF (types, arrays, SET/REP), assignments, PROC lines.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

ir::Op assignOp(ExprPtr target, ExprPtr value, SourceLoc l) {
  Op a(OpKind::Assign, l);
  a.set("target", std::move(target));
  a.set("value", std::move(value));
  return a;
}

ExprPtr callOf(const char *fn, SourceLoc l, ExprPtr a, ExprPtr b) {
  std::vector<ExprPtr> args;
  args.push_back(std::move(a));
  if (b) args.push_back(std::move(b));
  return Expr::call(fn, std::move(args), l);
}

size_t elementCount(const VarDecl &d) {
  size_t n = 1;
  for (uint32_t x : d.dims) n *= x;
  return n;
}

namespace {
struct TypeName {
  const char *name;
  ir::Type type;
  const char *irName;
};
const TypeName kTypes[] = {
    {"INT", ir::Type::Int, "int"},          {"REAL", ir::Type::Real, "real"},   {"BOOL", ir::Type::Bool, "bool"},
    {"CHAR", ir::Type::String, "char"},       {"STRING", ir::Type::String, "string"},
    {"AXIS", ir::Type::Axis, "axis"},       {"FRAME", ir::Type::Frame, "frame"},
};
const TypeName *findType(std::string_view n) {
  for (auto &t : kTypes)
    if (n == t.name) return &t;
  return nullptr;
}
// The element at row-major position `pos` of an array with dims (last index fastest).
std::vector<ExprPtr> indicesAt(const VarDecl &d, size_t pos, SourceLoc l) {
  std::vector<ExprPtr> idx(d.dims.size());
  for (size_t k = d.dims.size(); k-- > 0;) {
    idx[k] = Expr::number((double)(pos % d.dims[k]), ir::Type::Int, l);
    pos /= d.dims[k];
  }
  return idx;
}
}  // namespace

// SET(a, b, …), (a, b, …) at a definition, REP(v [, n]) into an array from the target element on
// (L2006-L2104): one assignment per element; a gap in SET writes 0.
bool BlockParser::arrayInit(const Expr &target, const VarDecl &d, std::vector<Op> &into, bool atDef) {
  SourceLoc l = loc();
  bool rep = tok().isName("REP");
  if (tok().isName("SET") || rep) ++i_;
  if (!expect("(")) return false;
  std::vector<ExprPtr> vals;
  while (!tok().is(")")) {
    if (tok().is(",")) {
      vals.push_back(Expr::number(0, ir::Type::Int, l));
      ++i_;
      continue;
    }
    ExprPtr v = expr(0);
    if (!v) return false;
    vals.push_back(std::move(v));
    if (tok().is(",")) {
      ++i_;
      if (tok().is(")")) vals.push_back(Expr::number(0, ir::Type::Int, l));
    } else if (!tok().is(")")) {
      return fail(tok(), "expected ',' or ')' in a value list");
    }
  }
  ++i_;
  // The start position: constant indices of the target, else element 0.
  size_t start = 0, total = elementCount(d);
  for (size_t k = 0; k < target.args.size(); ++k) {
    const Expr &ix = *target.args[k];
    if (ix.kind != ir::ExprKind::Number) return fail(t_[i_ - 1], "SET/REP into an element given by a computed index is not supported", "unsupported-code");
    // A constant index outside the array, or one index too many, names no element.
    if (k >= d.dims.size())
      return fail(t_[i_ - 1], fmt::format("SET/REP: array '{}' has {} dimension(s)", target.str, d.dims.size()));
    if (ix.num < 0 || ix.num >= d.dims[k] || ix.num != std::floor(ix.num))
      return fail(t_[i_ - 1], fmt::format("SET/REP: index {} of array '{}' is not a whole number from 0 to {}", ix.num,
                                          target.str, d.dims[k] - 1));
    start = start * d.dims[k] + (size_t)ix.num;
  }
  size_t count;
  ExprPtr value;
  if (rep) {
    if (vals.empty() || vals.size() > 2) return fail(t_[i_ - 1], "REP takes a value and an optional count");
    if (vals.size() == 2 && vals[1]->kind != ir::ExprKind::Number) return fail(t_[i_ - 1], "the count of REP must be a constant");
    double n = vals.size() == 2 ? vals[1]->num : double(total - start);
    if (n < 0 || n > double(total - start) || n != std::floor(n))
      return fail(t_[i_ - 1], fmt::format("the count {} of REP does not fit array '{}' of {} elements from element {}", n,
                                          target.str, total, start));
    count = (size_t)n;
    value = std::move(vals[0]);
  } else {
    count = vals.size();
  }
  if (start + count > total)
    return fail(t_[i_ - 1], fmt::format("{} values from element {} do not fit array '{}' of {} elements", count, start,
                                        target.str, total));
  if (count > 10000) return fail(t_[i_ - 1], "SET/REP of more than 10000 elements is not supported", "unsupported-code");
  (void)atDef;
  for (size_t k = 0; k < count; ++k) {
    auto v = Expr::var(target.space, target.str, nullptr, l);
    v->args = indicesAt(d, start + k, l);
    into.push_back(assignOp(std::move(v), rep ? value->clone() : std::move(vals[k]), l));
  }
  return true;
}

// DEF [NCK|CHAN] [attributes] TYPE [PHU n] [LLI v] [ULI v] name[dims] [= init], … (L734-L741).
bool BlockParser::def() {
  SourceLoc l = loc();
  ++i_;
  bool global = false;
  const TypeName *type = nullptr;
  unsigned len = 200;
  ExprPtr lli, uli;
  while (!type) {
    const Token &t = tok();
    if (t.kind != Tok::Name) return fail(t, "expected a type after DEF (INT REAL BOOL CHAR STRING AXIS FRAME)");
    ++i_;
    if (t.text == "NCK" || t.text == "CHAN") global = true;
    else if (t.text == "SYNR" || t.text == "SYNW" || t.text == "SYNRW") continue;
    else if (t.text == "APR" || t.text == "APW" || t.text == "APRP" || t.text == "APWP" || t.text == "APRB" ||
             t.text == "APWB" || t.text == "PHU") {
      if (!unary()) return false;
    } else if (t.text == "DCM" || t.text == "DCI" || t.text == "DCU") continue;
    else if (!(type = findType(t.text))) return fail(t, fmt::format("unknown type '{}' in DEF", t.text));
  }
  if (f_.definitions && !global) return fail(t_[i_ - 1], "a GUD definition file defines global data: DEF NCK|CHAN");
  if (std::string_view(type->name) == "STRING") {
    if (!expect("[")) return false;
    if (tok().kind != Tok::Number || !tok().isInt || tok().num < 1 || tok().num > 200)
      return fail(tok(), "the length of a STRING is an integer 1..200");
    len = (unsigned)tok().num;
    ++i_;
    if (!expect("]")) return false;
  }
  for (;;) {  // attributes after the type
    const Token &t = tok();
    if (t.isName("PHU") || t.isName("APR") || t.isName("APW") || t.isName("APRP") || t.isName("APWP") ||
        t.isName("APRB") || t.isName("APWB")) {
      ++i_;
      if (!unary()) return false;
    } else if (t.isName("LLI") || t.isName("ULI")) {
      ++i_;
      ExprPtr v = unary();
      if (!v || v->kind != ir::ExprKind::Number) return failed_ ? false : fail(t, "a limit is a number");
      (t.text == "LLI" ? lli : uli) = std::move(v);
    } else {
      break;
    }
  }
  if (lli || uli)
    f_.pp.diags.warning(l, "LLI/ULI limits set the implicit initial value; assignments are not checked against them");
  for (;;) {
    const Token &n = tok();
    if (n.kind != Tok::Name || n.text[0] == '$') return fail(n, "expected a variable name in DEF");
    if (n.text.size() < 2 || n.text.size() > 31 || std::isdigit((unsigned char)n.text[1]))
      return fail(n, fmt::format("'{}' is not a valid variable name (2-31 characters, the first two letters or '_')", n.text));
    if (f_.vars.count(n.text)) return fail(n, fmt::format("variable '{}' is defined twice", n.text));
    if (findAddress(n.text) || findGCode(n.text).code || findFunction(n.text))
      return fail(n, fmt::format("'{}' is a reserved name", n.text));
    ++i_;
    VarDecl d;
    d.type = type->type;
    d.global = global;
    d.isChar = std::string_view(type->name) == "CHAR";
    d.len = type->type == ir::Type::String && !d.isChar ? len : 0;
    if (tok().is("[")) {
      ++i_;
      do {
        if (tok().kind != Tok::Number || !tok().isInt || tok().num < 1 || tok().num > 65535)
          return fail(tok(), "an array dimension is an integer constant 1..65535");
        d.dims.push_back((uint32_t)tok().num);
        ++i_;
      } while (tok().is(",") && (++i_, true));
      if (!expect("]")) return false;
      if (d.dims.size() > 3 || (d.type == ir::Type::String && d.dims.size() > 2))
        return fail(n, "arrays have at most 3 dimensions (STRING arrays 2)");
    }
    auto var = Expr::var(global ? ir::VarSpace::Global : ir::VarSpace::Local, n.text, nullptr, loc(n));
    Op decl(OpKind::Declare, l);
    {
      auto dv = var->clone();
      for (uint32_t x : d.dims) dv->args.push_back(Expr::number(x, ir::Type::Int));
      decl.set("var", std::move(dv));
    }
    decl.set("type", Expr::symbol(type->irName));
    if (d.type == ir::Type::String && !d.isChar) decl.set("len", Expr::number(len, ir::Type::Int));
    f_.vars[n.text] = d;
    std::vector<Op> inits;
    if (tok().is("=")) {
      ++i_;
      if (d.type == ir::Type::Frame) return fail(tok(), "a FRAME takes no initial value in DEF (L2000)");
      if (!d.dims.empty()) {
        if (tok().isName("REP") && (peek(2).is(")"))) {  // REP(v): every element
          i_ += 2;
          ExprPtr v = expr(0);
          if (!v || !expect(")")) return false;
          decl.set("init", std::move(v));
        } else if (!arrayInit(*var, d, inits, true)) {
          return false;
        }
      } else {
        ExprPtr v = expr(0);
        if (!v) return false;
        decl.set("init", std::move(v));
      }
    } else if (lli && lli->num > 0 && d.dims.empty()) {
      decl.set("init", std::move(lli));  // the implicit 0 lies below the limit: the limit (L1401)
    } else if (uli && uli->num < 0 && d.dims.empty()) {
      decl.set("init", std::move(uli));
    }
    pre_.push_back(std::move(decl));
    for (auto &o : inits) pre_.push_back(std::move(o));
    if (!tok().is(",")) break;
    ++i_;
  }
  if (!atEnd()) return fail(tok(), "unexpected text after DEF (one definition per block)");
  return true;
}

// After `=`: a value; frames chain with `:` (L3181, `A : B`), arrays take SET/REP lists.
ExprPtr BlockParser::assignValue(const Expr &target) {
  if (tok().isName("DELDL") && !machineCtx_) return deldlStatus(tok());  // S = DELDL[t, d] (ToolData.cpp)
  if ((tok().isName("CALCDAT") || tok().isName("INTERSEC")) && peek().is("(") && !machineCtx_)
    return contourFunction(tok());  // S = CALCDAT(…) (Contour.cpp)
  ExprPtr v = expr(0);
  if (!v) return nullptr;
  while (tok().is(":")) {
    if (!frameTyped(target) && !frameTyped(*v)) {
      fail(tok(), "':' chains frames only");
      return nullptr;
    }
    SourceLoc l = loc();
    ++i_;
    ExprPtr b = expr(0);
    if (!b) return nullptr;
    v = callOf("FRAME_CHAIN", l, std::move(v), std::move(b));
  }
  return v;
}

bool BlockParser::assignment() {
  const Token &t = tok();
  SourceLoc l = loc(t);
  ++i_;
  ExprPtr target = t.text[0] == '$' ? systemVar(t) : f_.vars.count(t.text) ? variable(t) : nameExpr(t);
  // F[X, TR] = v, $P_PFRAME[X, TR] = v: the frame with one component replaced (FRAME_SET).
  ExprPtr comp;
  if (target && target->kind == ir::ExprKind::Call && (target->str == "FRAME_GET" || target->str == "CHAR_AT")) {
    comp = std::move(target);
    target = std::move(comp->args[0]);
  }
  if (!target) return false;
  if (target->kind != ir::ExprKind::Var) return fail(t, "the left side of '=' must be a variable");
  if (!expect("=")) return false;
  auto it = f_.vars.find(target->str);
  if (it != f_.vars.end() && !it->second.dims.empty() && (tok().isName("SET") || tok().isName("REP")))
    return arrayInit(*target, it->second, pre_, false);
  if (target->space == ir::VarSpace::RParam && (tok().isName("SET") || tok().isName("REP"))) {
    // R10=REP(2.4, 3): R10…R12 (L2236); R parameters are one array of the machine's size.
    if (!target->args.empty() && target->args[0]->kind == ir::ExprKind::Number) {
      VarDecl r;
      r.dims.push_back(65535);
      std::vector<Op> ops;
      auto whole = Expr::var(ir::VarSpace::RParam, "R", nullptr, l);
      whole->args.push_back(target->args[0]->clone());
      if (tok().isName("REP") && !peek(2).is(")") && !arrayInit(*whole, r, ops, false)) return false;
      if (ops.empty()) return fail(tok(), "REP on R parameters needs a count: R10=REP(v, n)");
      for (auto &o : ops) {  // RParam elements have one index
        ir::Expr *t = o.get("target");
        auto idx = std::move(t->args.back());
        t->args.clear();
        t->args.push_back(std::move(idx));
        pre_.push_back(std::move(o));
      }
      return true;
    }
    return fail(tok(), "SET/REP into R parameters needs a constant R number", "unsupported-code");
  }
  ExprPtr v = assignValue(*target);
  if (!v) return false;
  if (comp) {  // F[X, TR] = v: FRAME_SET(F, "X", "TR", v); S[i] = c: CHAR_SET(S, i, c)
    std::vector<ExprPtr> a;
    a.push_back(target->clone());
    for (size_t k = 1; k < comp->args.size(); ++k) a.push_back(std::move(comp->args[k]));
    a.push_back(std::move(v));
    v = Expr::call(comp->str == "CHAR_AT" ? "CHAR_SET" : "FRAME_SET", std::move(a), l);
  }
  pre_.push_back(assignOp(std::move(target), std::move(v), l));
  return true;
}

// PROC NAME[(params)] [SAVE] [SBLOF] [DISPLOF] … : the first line of a subprogram (L7117).
bool BlockParser::proc() {
  const Token &p = tok();
  if (f_.sawStatement)
    return fail(p, "PROC must be the first statement of the program");
  f_.startsWithProc = true;
  ++i_;
  // A name, or (808D macro bodies, seed001 L9816: PROC 0010) the program's number.
  if (tok().kind != Tok::Name && !(tok().kind == Tok::Number && tok().text.find('.') == std::string::npos))
    return fail(tok(), "expected the subprogram name after PROC");
  ++i_;
  std::vector<ir::Param> params;
  if (tok().is("(")) {
    ++i_;
    while (!tok().is(")")) {
      ir::Param pr;
      if (tok().isName("VAR")) {
        pr.byRef = true;
        ++i_;
      }
      const TypeName *ty = tok().kind == Tok::Name ? findType(tok().text) : nullptr;
      if (!ty) return fail(tok(), "expected a parameter type (INT REAL BOOL CHAR STRING AXIS FRAME)");
      ++i_;
      VarDecl d;
      d.type = ty->type;
      d.isChar = std::string_view(ty->name) == "CHAR";
      if (ty->type == ir::Type::String && tok().is("[")) {
        ++i_;
        if (tok().kind != Tok::Number || !tok().isInt || tok().num < 1 || tok().num > 200)
          return fail(tok(), "the length of a STRING is an integer 1..200");
        d.len = (unsigned)tok().num;
        ++i_;
        if (!expect("]")) return false;
      }
      if (tok().kind != Tok::Name) return fail(tok(), "expected a parameter name");
      pr.name = tok().text;
      pr.type = ty->type;
      ++i_;
      if (tok().is("[")) return fail(tok(), "array parameters are not supported", "unsupported-code");
      if (tok().is("=")) {
        ++i_;
        pr.defaultValue = expr(0);
        if (!pr.defaultValue) return false;
      }
      f_.vars[pr.name] = d;
      params.push_back(std::move(pr));
      if (tok().is(",")) ++i_;
      else if (!tok().is(")")) return fail(tok(), "expected ',' or ')' in the parameter list");
    }
    ++i_;
  }
  f_.fn.params = std::move(params);
  f_.fn.loc = loc(p);
  if (!f_.isMain) {  // known before the body: a recursive call passes its arguments by name
    Signature &s = f_.pp.procs[f_.fn.name];
    s.params.clear();
    for (auto &q : f_.fn.params) s.params.push_back({q.name, q.type, q.byRef, nullptr});
    s.ready = true;
  }
  return true;
}

}  // namespace ncc::sin
