// NC IR -> LLVM IR: expressions and variables, with the value rules of ir/Value.h and
// ir/Arith.h. Vacant checks are emitted only for values that can be vacant (variable reads).
#include "backends/jit/CodegenImpl.h"

#include "ir/Arith.h"
#include "ir/Builtins.h"
#include "runtime/ncrt.h"

#include <llvm/IR/Intrinsics.h>

#include <cstdlib>

namespace ncc::jit {

using namespace llvm;
using ir::Expr;
using ir::ExprKind;
using ir::OpCode;
using ir::VarSpace;

void Codegen::badExpr(const Expr &e, const std::string &msg) {
  diags_.error(e.loc, msg);
  failed_ = true;
}

Value *Codegen::isVacant(Value *v) {
  return B.CreateICmpEQ(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, kVacantBits));
}

Value *Codegen::numOf(Val v) {
  if (!v.mayVacant) return v.v;
  return B.CreateSelect(isVacant(v.v), ConstantFP::get(dblTy, 0.0), v.v);
}

// truthy = not vacant and != 0 (a NaN is true, as `v != 0.0` is in C++).
Value *Codegen::truthy(Val v) {
  Value *nz = B.CreateFCmpUNE(v.v, ConstantFP::get(dblTy, 0.0));
  if (!v.mayVacant) return nz;
  return B.CreateAnd(nz, B.CreateNot(isVacant(v.v)));
}

Value *Codegen::toDouble(Value *i1) {
  return B.CreateSelect(i1, ConstantFP::get(dblTy, 1.0), ConstantFP::get(dblTy, 0.0));
}

Value *Codegen::roundIndex(Val v) { return B.CreateUnaryIntrinsic(Intrinsic::round, numOf(v)); }

// The index of a variable when it is a literal: args[0] if a number, else the digits of the
// name (`#12` may be stored as name "12").
static bool literalIndex(const Expr &var, double &out) {
  if (!var.args.empty()) {
    const Expr &i = *var.args[0];
    if (i.kind != ExprKind::Number && i.kind != ExprKind::Bool) return false;
    out = i.num;
    return true;
  }
  size_t p = 0;
  while (p < var.str.size() && !std::isdigit((unsigned char)var.str[p]) && var.str[p] != '-') ++p;
  if (p == var.str.size()) return false;
  out = std::strtod(var.str.c_str() + p, nullptr);
  return true;
}

Value *Codegen::numberedPtr(const Expr &var, bool write) {
  double lit;
  if (literalIndex(var, lit)) {
    int64_t slot;
    switch (numberedSlot(lit, write, slot)) {
    case VarSlot::Local: return B.CreateConstGEP1_64(dblTy, frameArg, slot);
    case VarSlot::Global: return B.CreateConstGEP1_64(dblTy, numberedBase, slot);
    case VarSlot::OutOfRange: failIf(B.getTrue(), var.loc, "parameter number out of range"); return scratch;
    }
  }
  if (var.args.empty()) {
    badExpr(var, "numbered variable without an index");
    return scratch;
  }
  Value *r = roundIndex(expr(*var.args[0]));
  Value *ok = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 0.0)),
                          B.CreateFCmpOLT(r, ConstantFP::get(dblTy, (double)kNumberedVars)));
  if (write) ok = B.CreateAnd(ok, B.CreateFCmpONE(r, ConstantFP::get(dblTy, 0.0)));
  failIf(B.CreateNot(ok), var.loc, "parameter number out of range");
  Value *slot = B.CreateFPToSI(r, i64Ty);
  Value *local = B.CreateICmpULT(B.CreateSub(slot, B.getInt64(1)), B.getInt64(kFrameLocals));
  return B.CreateSelect(local, B.CreateGEP(dblTy, frameArg, slot), B.CreateGEP(dblTy, numberedBase, slot));
}

Value *Codegen::paramPtr(const Expr &var, Value *base, int64_t count) {
  double lit;
  if (literalIndex(var, lit)) {
    int64_t slot;
    if (paramSlot(lit, count, slot)) return B.CreateConstGEP1_64(dblTy, base, slot);
    failIf(B.getTrue(), var.loc, "parameter number out of range");
    return scratch;
  }
  if (var.args.empty()) {
    badExpr(var, "parameter without an index");
    return scratch;
  }
  Value *r = roundIndex(expr(*var.args[0]));
  Value *ok = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 0.0)),
                          B.CreateFCmpOLT(r, ConstantFP::get(dblTy, (double)count)));
  failIf(B.CreateNot(ok), var.loc, "parameter number out of range");
  return B.CreateGEP(dblTy, base, B.CreateFPToSI(r, i64Ty));
}

Value *Codegen::varPtr(const Expr &var, bool write) {
  switch (var.space) {
  case VarSpace::Numbered: return numberedPtr(var, write);
  case VarSpace::RParam: return paramPtr(var, rBase, kRParams);
  case VarSpace::QParam: {
    Value *base = B.CreateConstGEP1_64(dblTy, qBase, (uint64_t)qSpaces_.at(var.str) * kQParams);
    if (var.args.empty()) {
      badExpr(var, "Q parameter without an index");
      return scratch;
    }
    return paramPtr(var, base, kQParams);
  }
  case VarSpace::Local: return B.CreateConstGEP1_64(dblTy, frameArg, kFrameLocals + 1 + localNames_.at(var.str));
  case VarSpace::Global: return B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.at(var.str));
  case VarSpace::System: break;
  }
  return scratch;
}

Val Codegen::loadVar(const Expr &var) {
  if (var.space == VarSpace::System) return {ConstantFP::get(dblTy, vacantValue()), true};
  Value *v = B.CreateLoad(dblTy, varPtr(var, false));
  if (var.space == VarSpace::Local || var.space == VarSpace::Global) {
    Value *unset = B.CreateICmpEQ(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS));
    faultIf(unset, var.loc, NCRT_FAULT_UNSET_VAR, var.str, nullptr);
  }
  return {v, true};
}

void Codegen::storeVar(const Expr &var, Value *value) {
  if (var.space == VarSpace::System) {
    faultIf(B.getTrue(), var.loc, NCRT_FAULT_SYSTEM_WRITE, var.str, nullptr);
    return;
  }
  B.CreateStore(value, varPtr(var, true));
}

Val Codegen::expr(const Expr &e) {
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Bool: return {ConstantFP::get(dblTy, e.num), false};
  case ExprKind::Vacant: return {ConstantFP::get(dblTy, vacantValue()), true};
  case ExprKind::String:
  case ExprKind::Symbol: badExpr(e, "'" + e.str + "' is not a number"); break;
  case ExprKind::Var: return loadVar(e);
  case ExprKind::Unary: {
    if (e.args.size() != 1) break;
    Val a = expr(*e.args[0]);
    if (e.op == OpCode::Neg) return {B.CreateFNeg(numOf(a)), false};
    if (e.op == OpCode::Not) return {toDouble(B.CreateNot(truthy(a))), false};
    badExpr(e, std::string("invalid unary operator ") + ir::opCodeName(e.op));
    break;
  }
  case ExprKind::Binary:
    if (e.args.size() == 2) return binary(e);
    break;
  case ExprKind::Call: return callBuiltin(e);
  }
  if (!failed_) badExpr(e, "malformed expression");
  return {ConstantFP::get(dblTy, 0.0), false};
}

Val Codegen::binary(const Expr &e) {
  Val a = expr(*e.args[0]), b = expr(*e.args[1]);
  auto divisor = [&]() {
    Value *nb = numOf(b);
    failIf(B.CreateFCmpOEQ(nb, ConstantFP::get(dblTy, 0.0)), e.loc, "division by zero");
    return nb;
  };
  switch (e.op) {
  case OpCode::Add: return {B.CreateFAdd(numOf(a), numOf(b)), false};
  case OpCode::Sub: return {B.CreateFSub(numOf(a), numOf(b)), false};
  case OpCode::Mul: return {B.CreateFMul(numOf(a), numOf(b)), false};
  case OpCode::Div: {
    Value *nb = divisor();
    return {B.CreateFDiv(numOf(a), nb), false};
  }
  case OpCode::Mod: {
    Value *nb = divisor();
    return {B.CreateCall(fMod, {numOf(a), nb}), false};
  }
  case OpCode::IDiv: {
    Value *nb = divisor();
    return {B.CreateCall(fIDiv, {numOf(a), nb}), false};
  }
  case OpCode::Pow: return {B.CreateCall(fPow, {numOf(a), numOf(b)}), false};
  case OpCode::Eq:
  case OpCode::Ne: {
    // valueEq: vacant equals only vacant.
    Value *eq = B.CreateFCmpOEQ(a.v, b.v);
    if (a.mayVacant || b.mayVacant) {
      Value *va = a.mayVacant ? isVacant(a.v) : B.getFalse();
      Value *vb = b.mayVacant ? isVacant(b.v) : B.getFalse();
      eq = B.CreateSelect(B.CreateOr(va, vb), B.CreateAnd(va, vb), eq);
    }
    return {toDouble(e.op == OpCode::Eq ? eq : B.CreateNot(eq)), false};
  }
  case OpCode::Lt: return {toDouble(B.CreateFCmpOLT(numOf(a), numOf(b))), false};
  case OpCode::Le: return {toDouble(B.CreateFCmpOLE(numOf(a), numOf(b))), false};
  case OpCode::Gt: return {toDouble(B.CreateFCmpOGT(numOf(a), numOf(b))), false};
  case OpCode::Ge: return {toDouble(B.CreateFCmpOGE(numOf(a), numOf(b))), false};
  case OpCode::And: return {toDouble(B.CreateAnd(truthy(a), truthy(b))), false};
  case OpCode::Or: return {toDouble(B.CreateOr(truthy(a), truthy(b))), false};
  case OpCode::Xor: return {toDouble(B.CreateXor(truthy(a), truthy(b))), false};
  default: badExpr(e, std::string("operator ") + ir::opCodeName(e.op) + " is not supported on numbers"); break;
  }
  return {ConstantFP::get(dblTy, 0.0), false};
}

Val Codegen::callBuiltin(const Expr &e) {
  const BuiltinInfo *bi = findBuiltin(e.str);
  if (!bi) {
    badExpr(e, "unknown function '" + e.str + "'");
    return {ConstantFP::get(dblTy, 0.0), false};
  }
  if (e.args.size() != bi->arity) {
    badExpr(e, std::string(bi->name) + " takes " + std::to_string(bi->arity) + " argument(s)");
    return {ConstantFP::get(dblTy, 0.0), false};
  }
  std::vector<Value *> vals;
  for (auto &a : e.args) vals.push_back(expr(*a).v);  // raw: the builtin applies num()
  if (!argSlot) argSlot = allocaEntry(ArrayType::get(dblTy, 4), "args");
  for (unsigned i = 0; i < vals.size(); ++i) B.CreateStore(vals[i], B.CreateConstGEP1_32(dblTy, argSlot, i));
  return {B.CreateCall(builtins_.at(bi->name), {argSlot}), false};
}

}  // namespace ncc::jit
