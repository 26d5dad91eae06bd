// NC IR -> LLVM IR: variables kept in stack slots across a loop. A loop whose body cannot reach
// its variables through anything but plain reads and writes (no calls, no jumps in or out, no
// computed parameter numbers, no VAR parameters, no modal call that runs NC code after a move)
// gets a private slot per scalar variable it names: loaded before the loop, stored back at its
// one exit. The slots never escape, so LLVM keeps them in registers, across the runtime's command
// calls too (they touch no variable: markRuntimeOnly). The slots hold the same bits as the
// storage, so vacant and unset values behave exactly as in memory.
#include "backends/jit/CodegenImpl.h"

#include "ir/SystemParams.h"
#include "runtime/ncrt.h"

#include <cmath>

namespace ncc::jit {

using namespace llvm;
using ir::Expr, ir::ExprKind, ir::Op, ir::OpKind, ir::VarSpace;

// A number given as a literal index (#100, R5), else false.
static bool literalNumber(const Expr &var, long &n) {
  if (var.args.empty()) {
    n = 0;  // R with no index is R0; a numbered variable always has one
    return var.space == VarSpace::RParam;
  }
  const Expr &i = *var.args[0];
  if (var.args.size() != 1 || (i.kind != ExprKind::Number && i.kind != ExprKind::Bool)) return false;
  n = std::lround(num(i.num));
  return true;
}

// The slot key of a variable a loop may keep (empty: not one): numbered #1..#99999 (frame
// locals and commons), R parameters, undeclared or scalar named locals and globals.
std::string Codegen::cacheKey(const Expr &var) {
  long n;
  switch (var.space) {
  case VarSpace::Numbered:
    if (!literalNumber(var, n) || n < 1 || n >= NCRT_NUMBERED) return {};
    return "#" + std::to_string(n);
  case VarSpace::RParam:
    if (!literalNumber(var, n) || n < 0 || n >= NCRT_RPARAMS) return {};
    return "R" + std::to_string(n);
  case VarSpace::Local:
  case VarSpace::Global: {
    if (!var.args.empty()) return {};
    const VarDecl *d = declOf(var);
    if (d && d->rank) return {};
    if (var.space == VarSpace::Local && cur_->fn->param(var.str) && cur_->fn->param(var.str)->byRef) return {};
    return (var.space == VarSpace::Local ? "l:" : "g:") + var.str;
  }
  default: return {};
  }
}

// Why a loop keeps no slots: an op that leaves or enters it other than through its head and
// exit, or runs other code that could read the variables; a parameter number computed (it may
// name any numbered or R variable); a VAR parameter (its address may be any variable).
bool Codegen::loopVars(const Op &loop, std::vector<const Expr *> &vars) {
  if (modalFn_ || !sectionIds_.empty()) return false;
  bool ok = true;
  auto expr = [&](auto &self, const Expr &e) -> void {
    if (e.kind == ExprKind::Var && cacheKey(e).empty()) {
      ParamMap map;
      bool computed = computedParameterNumber(e, map) ||
                      ((e.space == VarSpace::Numbered || e.space == VarSpace::RParam) && !e.args.empty());
      bool byRef = e.space == VarSpace::Local && cur_->fn->param(e.str) && cur_->fn->param(e.str)->byRef;
      if (computed || byRef) ok = false;
    }
    if (e.kind == ExprKind::Var && !cacheKey(e).empty()) vars.push_back(&e);
    if (e.kind == ExprKind::Var && (e.space == VarSpace::Numbered || e.space == VarSpace::RParam)) return;
    for (auto &a : e.args)
      if (a) self(self, *a);
  };
  auto region = [&](auto &self, const ir::Region &r) -> void {
    for (auto &op : r) {
      switch (op.kind) {
      case OpKind::Goto:
      case OpKind::CallSection:
      case OpKind::Call:
      case OpKind::Return:
      case OpKind::ModalCall:
      case OpKind::ModalTrigger: ok = false; break;
      default: break;
      }
      if (targetBBs_.count(&op)) ok = false;  // a jump from outside lands inside
      for (auto &a : op.args)
        if (a.value) expr(expr, *a.value);
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  for (auto &a : loop.args)
    if (a.value) expr(expr, *a.value);
  for (auto &sub : loop.regions) region(region, sub);
  return ok;
}

// Before the loop: a slot per variable not already kept by an enclosing loop, loaded from where
// the variable lives now (memory, or the enclosing loop's slot).
std::vector<Codegen::KeptVar> Codegen::keepLoopVars(const Op &loop) {
  std::vector<const Expr *> vars;
  std::vector<KeptVar> kept;
  if (!loopVars(loop, vars)) return kept;
  for (const Expr *v : vars) {
    std::string key = cacheKey(*v);
    if (kept_.count(key)) continue;
    Value *home = varPtr(*v, false);
    Value *slot = allocaEntry(dblTy, "kept");
    B.CreateStore(B.CreateLoad(dblTy, home), slot);
    kept_[key] = slot;
    kept.push_back({key, home, slot});
  }
  return kept;
}

// At the loop's exit: the values go home; the slots are forgotten.
void Codegen::releaseLoopVars(const std::vector<KeptVar> &kept) {
  for (auto &k : kept) {
    B.CreateStore(B.CreateLoad(dblTy, k.slot), k.home);
    kept_.erase(k.key);
  }
}

}  // namespace ncc::jit
