// Constant folding: any operator or builtin call whose operands are constants becomes a
// constant, computed with the same operator table as the eval engine.
#include "ir/Builtins.h"
#include "passes/Operators.h"
#include "passes/Pass.h"

#include <cmath>

namespace ncc {
using namespace ir;

static bool constValue(const Expr &e, double &v) {
  if (e.kind == ExprKind::Number || e.kind == ExprKind::Bool) {
    v = e.num;
    return true;
  }
  if (e.kind == ExprKind::Vacant) {
    v = vacantValue();
    return true;
  }
  return false;
}

static void fold(ExprPtr &e) {
  for (auto &a : e->args) fold(a);
  double a, b, r;
  bool isBool = false;
  switch (e->kind) {
  case ExprKind::Unary:
    if (!constValue(*e->args[0], a) || applyUnary(e->op, a, r) != OpStatus::Ok) return;
    isBool = e->op == OpCode::Not;
    break;
  case ExprKind::Binary:
    // Division by zero stays for run time, where it is reported at its location.
    if (!constValue(*e->args[0], a) || !constValue(*e->args[1], b) ||
        applyBinary(e->op, a, b, r) != OpStatus::Ok)
      return;
    isBool = e->op >= OpCode::Eq && e->op <= OpCode::Xor && e->op != OpCode::Concat;
    break;
  case ExprKind::Call: {
    const BuiltinInfo *bi = findBuiltin(e->str);
    if (!bi || !bi->fn || bi->arity != e->args.size() || e->args.size() > 4) return;
    double args[4] = {};
    for (size_t i = 0; i < e->args.size(); ++i)
      if (!constValue(*e->args[i], args[i])) return;
      else args[i] = num(args[i]);
    r = bi->fn(args);
    if (std::isnan(r)) return;  // domain errors are reported at run time
    break;
  }
  default:
    return;
  }
  SourceLoc loc = e->loc;
  Type t = e->type == Type::Unknown ? Type::Real : e->type;
  e = isBool ? Expr::boolean(r != 0, loc) : Expr::number(r, t == Type::Bool ? Type::Real : t, loc);
}

static void foldRegion(Region &r) {
  for (Op &op : r) {
    for (auto &a : op.args)
      if (a.value) fold(a.value);
    for (auto &sub : op.regions) foldRegion(sub);
  }
}

bool runFold(Module &m, Diagnostics &, PassContext &) {
  for (auto &f : m.functions) foldRegion(f.body);
  return true;
}

}  // namespace ncc
