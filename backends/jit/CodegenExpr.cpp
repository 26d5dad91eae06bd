// NC IR -> LLVM IR: expressions and variables, with the value rules of ir/Value.h and
// ir/Arith.h. Vacant checks are emitted only for values that can be vacant (variable reads).
#include "backends/jit/CodegenImpl.h"

#include "ir/Value.h"
#include "ir/Builtins.h"
#include "ir/SystemVars.h"
#include "runtime/ncrt.h"

#include <llvm/IR/Intrinsics.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace ncc::jit {

using namespace llvm;
using ir::Expr;
using ir::ExprKind;
using ir::OpCode;
using ir::VarSpace;


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

Value *Codegen::roundOf(Value *v) { return B.CreateUnaryIntrinsic(Intrinsic::round, v); }

// A literal index: args[0] when it is a number (the IR parser always gives #n an index
// expression); a front end may also spell the number in the name.
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

// #n: 1..33 the frame's locals, 0 always vacant (not assignable), else the global array.
Value *Codegen::numberedPtr(const Expr &var, bool write) {
  double lit;
  if (literalIndex(var, lit)) {
    long n = std::lround(num(lit));
    if (n >= 1 && n <= 33) return B.CreateConstGEP1_64(dblTy, frameArg, n);
    if (n == 0 && write) {
      fail(var.loc, "#0 is always vacant and cannot be assigned");
      return scratch;
    }
    if (n < 0 || n >= NCRT_NUMBERED) {
      faultIf(B.getTrue(), var.loc, NCRT_FAULT_NUMBERED, "", ConstantFP::get(dblTy, num(lit)));
      return scratch;
    }
    return B.CreateConstGEP1_64(dblTy, numberedBase, n);  // numbered[0] stays vacant
  }
  if (var.args.empty()) {
    fail(var.loc, "bad variable");
    return scratch;
  }
  Value *x = numOf(expr(*var.args[0]));
  Value *r = roundOf(x);
  Value *inRange = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 0.0)),
                               B.CreateFCmpOLT(r, ConstantFP::get(dblTy, (double)NCRT_NUMBERED)));
  Value *local = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 1.0)),
                             B.CreateFCmpOLE(r, ConstantFP::get(dblTy, 33.0)));
  if (write) failIf(B.CreateFCmpOEQ(r, ConstantFP::get(dblTy, 0.0)), var.loc, "#0 is always vacant and cannot be assigned");
  faultIf(B.CreateNot(B.CreateOr(local, inRange)), var.loc, NCRT_FAULT_NUMBERED, "", x);
  Value *slot = B.CreateFPToSI(r, i64Ty);
  return B.CreateSelect(local, B.CreateGEP(dblTy, frameArg, slot), B.CreateGEP(dblTy, numberedBase, slot));
}

// R and Q parameters: index rounded like #n (no index = 0).
Value *Codegen::paramPtr(const Expr &var, Value *base, int64_t count, unsigned fault) {
  if (var.args.empty()) return base;
  double lit;
  if (literalIndex(var, lit)) {
    long n = std::lround(num(lit));
    if (n >= 0 && n < count) return B.CreateConstGEP1_64(dblTy, base, n);
    faultIf(B.getTrue(), var.loc, fault, "", ConstantFP::get(dblTy, num(lit)));
    return scratch;
  }
  Value *x = numOf(expr(*var.args[0]));
  Value *r = roundOf(x);
  Value *ok = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 0.0)),
                          B.CreateFCmpOLT(r, ConstantFP::get(dblTy, (double)count)));
  faultIf(B.CreateNot(ok), var.loc, fault, "", x);
  return B.CreateGEP(dblTy, base, B.CreateFPToSI(r, i64Ty));
}

// Element of a named array (ir/Value.h arrayIndex): an integer index in 0..kArrayElements-1.
Value *Codegen::elemPtr(const Expr &var, Value *base) {
  Value *x = numOf(expr(*var.args[0]));
  Value *ok = B.CreateAnd(B.CreateAnd(B.CreateFCmpOGE(x, ConstantFP::get(dblTy, 0.0)),
                                      B.CreateFCmpOLT(x, ConstantFP::get(dblTy, (double)kArrayElements))),
                          B.CreateFCmpOEQ(x, B.CreateUnaryIntrinsic(Intrinsic::trunc, x)));
  faultIf(B.CreateNot(ok), var.loc, NCRT_FAULT_INDEX, var.str, x);
  lastIndex = x;
  return B.CreateGEP(dblTy, base, B.CreateFPToSI(x, i64Ty));
}

Value *Codegen::varPtr(const Expr &var, bool write) {
  if (!var.args.empty() && var.space == VarSpace::Local)
    return elemPtr(var, B.CreateConstGEP1_64(dblTy, localArrays, (uint64_t)cur_->arrays.at(var.str) * kArrayElements));
  if (!var.args.empty() && var.space == VarSpace::Global)
    return elemPtr(var, B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.size() + (uint64_t)globalArrays_.at(var.str) *
                                                                                   kArrayElements));
  switch (var.space) {
  case VarSpace::Numbered: return numberedPtr(var, write);
  case VarSpace::RParam: return paramPtr(var, rBase, NCRT_RPARAMS, NCRT_FAULT_RPARAM);
  case VarSpace::QParam: {
    int q = qPrefixIndex(var.str);
    if (q < 0) {
      fail(var.loc, fmt::format("unknown Q parameter prefix '{}'", var.str));
      return scratch;
    }
    Value *base = B.CreateConstGEP1_64(dblTy, qBase, (uint64_t)q * NCRT_QPARAMS);
    return paramPtr(var, base, NCRT_QPARAMS, NCRT_FAULT_QPARAM);
  }
  case VarSpace::Local: return B.CreateConstGEP1_64(dblTy, frameArg, kFrameLocals + 1 + cur_->locals.at(var.str));
  case VarSpace::Global: return B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.at(var.str));
  case VarSpace::System: break;
  }
  return scratch;
}

Val Codegen::loadVar(const Expr &var) {
  if (var.space == VarSpace::System) {  // asked of the executor when the program runs
    SysVar sv = SysVar::Count;
    sysVarFromName(var.str, sv);
    Value *v = B.CreateCall(fSysVar, {ctxArg, B.getInt32((uint32_t)sv)});
    Value *none = B.CreateICmpEQ(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS));
    faultIf(none, var.loc, NCRT_FAULT_SYSVAR, var.str, nullptr);
    return {v, false};
  }
  Value *v = B.CreateLoad(dblTy, varPtr(var, false));
  if (var.space == VarSpace::Local || var.space == VarSpace::Global) {
    Value *unset = B.CreateICmpEQ(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS));
    if (var.args.empty()) faultIf(unset, var.loc, NCRT_FAULT_UNSET_VAR, var.str, nullptr);
    else faultIf(unset, var.loc, NCRT_FAULT_UNSET_ELEM, var.str, lastIndex);
  }
  return {v, true};
}

void Codegen::storeVar(const Expr &var, Value *value) {
  if (var.space == VarSpace::System) {
    fail(var.loc, fmt::format("system variable '{}' is read-only", var.str));
    return;
  }
  B.CreateStore(value, varPtr(var, true));
}

// String expressions (ir/Value.h): the leaves are appended to the runtime's text buffer.
void Codegen::appendString(const Expr &e, bool fixed) {
  if (e.kind == ExprKind::String) B.CreateCall(fStrCat, {ctxArg, cstring(e.str)});
  else if (e.kind == ExprKind::Binary && e.op == OpCode::Concat) {
    appendString(*e.args[0], fixed);
    appendString(*e.args[1], fixed);
  } else if (fixed && e.kind == ExprKind::Var && e.args.empty() &&
             (e.space == VarSpace::Local || e.space == VarSpace::Global)) {
    // LinuxCNC prints an unset named parameter as ###### (fixedNumberText): the raw slot.
    B.CreateCall(fStrNumFixed, {ctxArg, B.CreateLoad(dblTy, varPtr(e, false))});
  } else B.CreateCall(fixed ? fStrNumFixed : fStrNum, {ctxArg, expr(e).v});
}

Value *Codegen::stringValue(const Expr &e, bool fixed) {
  B.CreateCall(fStrClear, {ctxArg});
  appendString(e, fixed);
  return B.CreateCall(fStr, {ctxArg});
}

Val Codegen::expr(const Expr &e) {
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Bool: return {ConstantFP::get(dblTy, e.num), false};
  case ExprKind::Vacant: return {ConstantFP::get(dblTy, vacantValue()), true};
  case ExprKind::String:
  case ExprKind::Symbol: fail(e.loc, "strings are not supported in numeric expressions yet"); break;
  case ExprKind::Var: return loadVar(e);
  case ExprKind::Unary: {
    if (e.args.size() != 1) break;
    Val a = expr(*e.args[0]);
    if (e.op == OpCode::Neg) return {B.CreateFNeg(numOf(a)), false};
    if (e.op == OpCode::Not) return {toDouble(B.CreateNot(truthy(a))), false};
    fail(e.loc, "bad unary operator");
    break;
  }
  case ExprKind::Binary:
    if (e.args.size() == 2) return binary(e);
    break;
  case ExprKind::Call: return callBuiltin(e);
  }
  fail(e.loc, "bad expression");
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
  case OpCode::BAnd:
  case OpCode::BOr:
  case OpCode::BXor: {
    Value *r = B.CreateCall(fBitwise, {B.getInt32((int)e.op - (int)OpCode::BAnd), numOf(a), numOf(b)});
    failIf(B.CreateFCmpUNO(r, r), e.loc, bitwiseOperandMessage(ir::opCodeName(e.op)));
    return {r, false};
  }
  default: fail(e.loc, fmt::format("operator '{}' is not supported on numbers", ir::opCodeName(e.op))); break;
  }
  return {ConstantFP::get(dblTy, 0.0), false};
}

// Builtins get num() arguments; a NaN result is the eval engine's domain error.
Val Codegen::callBuiltin(const Expr &e) {
  if (isExistsCall(e.str, e.args.size()) && e.args[0]) {
    // A named scalar exists when its slot is not unset; everything else always has a value.
    const Expr &v = *e.args[0];
    if (v.kind != ExprKind::Var || !v.args.empty() || (v.space != VarSpace::Local && v.space != VarSpace::Global))
      return {ConstantFP::get(dblTy, 1.0), false};
    Value *raw = B.CreateLoad(dblTy, varPtr(v, false));
    Value *set = B.CreateICmpNE(B.CreateBitCast(raw, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS));
    return {toDouble(set), false};
  }
  const BuiltinInfo *bi = findBuiltin(e.str);
  if (!bi) {
    fail(e.loc, fmt::format("unknown function '{}'", e.str));
    return {ConstantFP::get(dblTy, 0.0), false};
  }
  if (e.args.size() != bi->arity) {
    fail(e.loc, fmt::format("'{}' takes {} argument(s), {} given", bi->name, bi->arity, e.args.size()));
    return {ConstantFP::get(dblTy, 0.0), false};
  }
  std::vector<Value *> vals;
  for (auto &a : e.args) vals.push_back(numOf(expr(*a)));
  if (!argSlot) argSlot = allocaEntry(ArrayType::get(dblTy, 4), "args");
  for (unsigned i = 0; i < vals.size() && i < 4; ++i) B.CreateStore(vals[i], B.CreateConstGEP1_32(dblTy, argSlot, i));
  Value *r = B.CreateCall(builtins_.at(bi->name), {argSlot});
  failIf(B.CreateFCmpUNO(r, r), e.loc, fmt::format("'{}' argument out of domain", bi->name));
  return {r, false};
}

}  // namespace ncc::jit
