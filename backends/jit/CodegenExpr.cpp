// NC IR -> LLVM IR: expressions and variables, with the value rules of ir/Value.h and
// ir/Arith.h. Vacant checks are emitted only for values that can be vacant (variable reads).
#include "backends/jit/CodegenImpl.h"

#include "ir/Value.h"
#include "ir/Builtins.h"
#include "ir/Strings.h"
#include "ir/SystemVars.h"
#include "runtime/ncrt.h"

#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/MDBuilder.h>

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

Value *Codegen::isStr(Value *v) {
  return B.CreateICmpEQ(B.CreateAnd(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, kStringTagMask)),
                        ConstantInt::get(i64Ty, kStringTag));
}

Value *Codegen::isHandleBits(Value *v) {  // a string or a frame (ir/Value.h isHandle)
  return B.CreateICmpEQ(B.CreateAnd(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, kHandleMask)),
                        ConstantInt::get(i64Ty, kStringTag));
}

Value *Codegen::isFrameHandle(Value *v) {
  return B.CreateICmpEQ(B.CreateAnd(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, kStringTagMask)),
                        ConstantInt::get(i64Ty, kFrameTag));
}

void Codegen::checkNotHandle(Val v, SourceLoc loc, HandleUse use, std::string_view name, bool stringsOk) {
  if (!v.mayHandle) return;
  if (!stringsOk) failIf(isStr(v.v), loc, handleMessage(use, "string", name));
  failIf(isFrameHandle(v.v), loc, handleMessage(use, "frame", name));
}

Value *Codegen::numOf(Val v) { return numOf(v, v.loc, HandleUse::AsNumber); }

Value *Codegen::numOf(Val v, SourceLoc loc, HandleUse use, std::string_view name) {
  checkNotHandle(v, loc, use, name);
  if (!v.mayVacant) return v.v;
  return B.CreateSelect(isVacant(v.v), ConstantFP::get(dblTy, 0.0), v.v);
}

// A runtime call's result: the unset bits mean it reported an error.
Value *Codegen::checked(Value *r) {
  BasicBlock *ok = newBlock("ok");
  B.CreateCondBr(B.CreateICmpEQ(B.CreateBitCast(r, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS)), failBB, ok);
  B.SetInsertPoint(ok);
  return r;
}

Val Codegen::stringConst(const std::string &s, SourceLoc loc) {
  auto l = locArgs(loc);
  Value *h = checked(B.CreateCall(fStrConst, {ctxArg, cstring(s), B.getInt64(s.size()), l[0], l[1], l[2]}));
  return {h, false, true, loc};
}

// truthy = not vacant and != 0 (a NaN is true, as `v != 0.0` is in C++); a string is an error.
Value *Codegen::truthy(Val v) {
  checkNotHandle(v, v.loc, HandleUse::AsNumber);
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
  ParamMap map;
  if (const Expr *e = computedParameterNumber(var, map)) {  // a by-reference argument (loads and stores: below)
    BasicBlock *plain = newBlock("param.plain"), *sys = newBlock("param.sys");
    Value *x = splitComputed(*e, map, plain, sys);
    B.SetInsertPoint(sys);
    auto l = locArgs(var.loc);
    sinkCall(fParam, {ctxArg, B.getInt32((uint32_t)map), B.getInt32((uint32_t)ParamAccess::Reference), x,
                          ConstantFP::get(dblTy, 0.0), l[0], l[1], l[2]});
    B.CreateBr(failBB);
    B.SetInsertPoint(plain);
    return numberedSlot(var, x, write);
  }
  return numberedSlot(var, numOf(expr(*var.args[0])), write);
}

Value *Codegen::numberedSlot(const Expr &var, Value *x, bool write) {
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

// The inline test that rounded number r is plain storage under map m: the comparisons of
// ir/SystemParams.h plainRanges, so a loop over plain parameters never leaves compiled code.
Value *Codegen::plainNumber(ParamMap m, Value *r) {
  Value *any = B.getFalse();
  const PlainRange *pr = plainRanges(m);
  for (int i = 0; i < kPlainRanges; ++i)
    if (pr[i].first <= pr[i].last)
      any = B.CreateOr(any, B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, pr[i].first)),
                                        B.CreateFCmpOLE(r, ConstantFP::get(dblTy, pr[i].last))));
  return any;
}

// A computed `#[e]` under map m: evaluates e and branches to `plain` when it is plain storage,
// else (controller state, or an error) to `sys`; the number e gave.
Value *Codegen::splitComputed(const Expr &e, ParamMap m, BasicBlock *plain, BasicBlock *sys) {
  Value *x = numOf(expr(e));
  B.CreateCondBr(plainNumber(m, roundOf(x)), plain, sys, MDBuilder(C).createBranchWeights(1000, 1));
  return x;
}

Val Codegen::loadComputed(const Expr &var, const Expr &e, ParamMap m) {
  BasicBlock *plain = newBlock("param.plain"), *sys = newBlock("param.sys"), *join = newBlock("param.join");
  Value *x = splitComputed(e, m, plain, sys);
  B.SetInsertPoint(sys);
  auto l = locArgs(var.loc);
  Value *sv = checked(sinkCall(fParam, {ctxArg, B.getInt32((uint32_t)m), B.getInt32((uint32_t)ParamAccess::Read), x,
                                            ConstantFP::get(dblTy, 0.0), l[0], l[1], l[2]}));
  BasicBlock *sysEnd = B.GetInsertBlock();
  B.CreateBr(join);
  B.SetInsertPoint(plain);
  Value *pv = B.CreateLoad(dblTy, numberedSlot(var, x, false));
  BasicBlock *plainEnd = B.GetInsertBlock();
  B.CreateBr(join);
  B.SetInsertPoint(join);
  return {joined(pv, plainEnd, sv, sysEnd), true, false, var.loc};
}

// The value of two paths meeting at the current block: a when coming from aEnd, b from bEnd.
Value *Codegen::joined(Value *a, BasicBlock *aEnd, Value *b, BasicBlock *bEnd) {
  PHINode *phi = B.CreatePHI(dblTy, 2);
  phi->addIncoming(a, aEnd);
  phi->addIncoming(b, bEnd);
  return phi;
}

void Codegen::storeComputed(const Expr &var, const Expr &e, ParamMap m, Val value) {
  Value *v = convertFor(var, declOf(var), value);  // no strings
  BasicBlock *plain = newBlock("param.plain"), *sys = newBlock("param.sys"), *join = newBlock("param.join");
  Value *x = splitComputed(e, m, plain, sys);
  B.SetInsertPoint(sys);
  auto l = locArgs(var.loc);
  checked(sinkCall(fParam, {ctxArg, B.getInt32((uint32_t)m), B.getInt32((uint32_t)ParamAccess::Write), x, v, l[0],
                                l[1], l[2]}));
  B.CreateBr(join);
  B.SetInsertPoint(plain);
  B.CreateStore(v, numberedSlot(var, x, true));
  B.CreateBr(join);
  B.SetInsertPoint(join);
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

// Element of a declared array: each index an integer within its dimension, row-major.
Value *Codegen::declaredElemPtr(const Expr &var, Value *base, const VarDecl &d) {
  Value *flat = B.getInt64(0);
  for (unsigned k = 0; k < d.rank; ++k) {
    Value *x = numOf(expr(*var.args[k]));
    Value *ok = B.CreateAnd(B.CreateAnd(B.CreateFCmpOGE(x, ConstantFP::get(dblTy, 0.0)),
                                        B.CreateFCmpOLT(x, ConstantFP::get(dblTy, (double)d.dims[k]))),
                            B.CreateFCmpOEQ(x, B.CreateUnaryIntrinsic(Intrinsic::trunc, x)));
    BasicBlock *err = newBlock("bad.index"), *cont = newBlock("cont");
    B.CreateCondBr(ok, cont, err);
    B.SetInsertPoint(err);
    auto l = locArgs(var.loc);
    B.CreateCall(fBadIndex, {ctxArg, l[0], l[1], l[2], cstring(var.str), x, B.getInt32(k + 1), B.getInt32(d.rank),
                             B.getInt32(d.dims[k])});
    B.CreateBr(failBB);
    B.SetInsertPoint(cont);
    flat = B.CreateAdd(B.CreateMul(flat, B.getInt64(d.dims[k])), B.CreateFPToSI(x, i64Ty));
  }
  return B.CreateGEP(dblTy, base, flat);
}

const VarDecl *Codegen::declOf(const Expr &var) { return decls_.find(*cur_->fn, var); }

Value *Codegen::varPtr(const Expr &var, bool write) {
  if (!kept_.empty())  // in a loop that keeps its variables in slots
    if (auto it = kept_.find(cacheKey(var)); it != kept_.end()) return it->second;
  const VarDecl *d = declOf(var);
  if (d && d->rank) {
    Value *base = var.space == VarSpace::Global
                      ? B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.size() + globalArrays_.at(var.str).offset)
                      : B.CreateConstGEP1_64(dblTy, localArrays, cur_->arrays.at(var.str).offset);
    return declaredElemPtr(var, base, *d);
  }
  if (!var.args.empty() && var.space == VarSpace::Local)
    return elemPtr(var, B.CreateConstGEP1_64(dblTy, localArrays, cur_->arrays.at(var.str).offset));
  if (!var.args.empty() && var.space == VarSpace::Global)
    return elemPtr(var, B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.size() + globalArrays_.at(var.str).offset));
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
  case VarSpace::Local: {
    Value *slot = B.CreateConstGEP1_64(dblTy, frameArg, kFrameLocals + 1 + cur_->locals.at(var.str));
    if (const ir::Param *p = cur_->fn->param(var.str); p && p->byRef)  // the slot holds the address
      return B.CreateIntToPtr(B.CreateLoad(i64Ty, slot), ptrTy);
    return slot;
  }
  case VarSpace::Global: return B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.at(var.str));
  case VarSpace::System: break;
  }
  return scratch;
}

// The SysRef a system variable names, as its number (sysRefNumber): a constant, or computed
// from a family's indices when the program runs (`$_work_offset[s, a]`, an axis symbol is a
// constant index; `$_tool_data[t, d, k]`).
Value *Codegen::sysVarRef(const Expr &var) {
  SysFamily f;
  int dims = sysFamilyFromName(var.str, f);
  if (!dims) {
    SysRef ref;  // the verifier has checked the name
    sysVarFromName(var.str, ref.var);
    return ConstantFP::get(dblTy, sysRefNumber(ref));
  }
  Value *ix[3] = {ConstantFP::get(dblTy, 0.0), ConstantFP::get(dblTy, 0.0), ConstantFP::get(dblTy, 0.0)};
  for (int k = 0; k < dims && k < (int)var.args.size(); ++k)
    ix[k] = var.args[k]->kind == ExprKind::Symbol ? ConstantFP::get(dblTy, (double)axisIndex(var.args[k]->str))
                                                   : numOf(expr(*var.args[k]));
  auto l = locArgs(var.loc);
  return checked(
      sinkCall(fSysVarAt, {ctxArg, B.getInt32((uint32_t)f), ix[0], ix[1], ix[2], cstring(var.str), l[0], l[1], l[2]}));
}

Val Codegen::loadVar(const Expr &var) {
  if (var.space == VarSpace::System) {  // asked of the executor when the program runs
    Value *ref = sysVarRef(var);
    auto l = locArgs(var.loc);
    return {checked(sinkCall(fSysVar, {ctxArg, ref, cstring(var.str), l[0], l[1], l[2]})), false,
            sysVarNameIsFrame(var.str), var.loc};
  }
  ParamMap map;
  if (const Expr *e = computedParameterNumber(var, map)) return loadComputed(var, *e, map);
  Value *v = B.CreateLoad(dblTy, varPtr(var, false));
  bool mayHandle = var.space == VarSpace::QParam && var.str == "QS";
  if (var.space == VarSpace::Local || var.space == VarSpace::Global) {
    const VarDecl *d = declOf(var);
    mayHandle = !d || holdsHandle(d->type);
    if (d && !d->param) return {v, d->type == ValueType::Real, mayHandle, var.loc};  // never unset
    Value *unset = B.CreateICmpEQ(B.CreateBitCast(v, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS));
    if (var.args.empty()) faultIf(unset, var.loc, NCRT_FAULT_UNSET_VAR, var.str, nullptr);
    else faultIf(unset, var.loc, NCRT_FAULT_UNSET_ELEM, var.str, lastIndex);
  }
  return {v, true, mayHandle, var.loc};
}

// The value a store keeps (ir/Strings.h convertForStore, as the eval engine): converted to the
// declared type; numeric parameters take no strings. REAL stores of numbers stay inline.
Value *Codegen::convertFor(const Expr &var, const VarDecl *d, Val value) {
  bool paramSpace = var.space == VarSpace::Numbered || var.space == VarSpace::RParam || var.space == VarSpace::QParam;
  if (!d || d->type == ValueType::Any) {
    bool qs = var.space == VarSpace::QParam && var.str == "QS";  // strings, not frames
    if (paramSpace) checkNotHandle(value, var.loc, HandleUse::InParameter, {}, qs);
    return value.v;
  }
  if (d->type == ValueType::Real && !value.mayHandle) return value.v;
  auto l = locArgs(var.loc);
  return checked(B.CreateCall(fConvert, {ctxArg, B.getInt32((uint32_t)d->type), B.getInt32(d->len), cstring(var.str),
                                         value.v, l[0], l[1], l[2]}));
}

void Codegen::storeVar(const Expr &var, Val value) {
  if (var.space == VarSpace::System) {
    auto l = locArgs(var.loc);
    Value *ref = sysVarRef(var);
    // A frame variable takes the handle as it is; the runtime checks what a store holds.
    Value *v = sysVarNameIsFrame(var.str) ? value.v : numOf(value);
    checked(sinkCall(fSysVarSet, {ctxArg, ref, v, l[0], l[1], l[2]}));
    return;
  }
  ParamMap map;
  if (const Expr *e = computedParameterNumber(var, map)) return storeComputed(var, *e, map, value);
  Value *v = convertFor(var, declOf(var), value);
  B.CreateStore(v, varPtr(var, true));
}

// The leaves of a concat chain, in order.
void Codegen::collectLeaves(const Expr &e, std::vector<const Expr *> &out) {
  if (e.kind == ExprKind::Binary && e.op == OpCode::Concat && e.args.size() == 2) {
    collectLeaves(*e.args[0], out);
    collectLeaves(*e.args[1], out);
  } else {
    out.push_back(&e);
  }
}

// String expressions (ir/Strings.h): the leaves that are not constants are evaluated first (they
// may build strings of their own), then all are appended to the runtime's text buffer: strings
// as they are, numbers as numberText (fixed: fixedNumberText).
void Codegen::appendString(const Expr &e, bool fixed) {
  std::vector<const Expr *> leaves;
  collectLeaves(e, leaves);
  std::vector<Value *> vals;
  for (const Expr *l : leaves) {
    if (l->kind == ExprKind::String) vals.push_back(nullptr);
    else if (fixed && l->kind == ExprKind::Var && l->args.empty() &&
             (l->space == VarSpace::Local || l->space == VarSpace::Global))
      // LinuxCNC prints an unset named parameter as ###### (fixedNumberText): the raw slot.
      vals.push_back(B.CreateLoad(dblTy, varPtr(*l, false)));
    else vals.push_back(expr(*l).v);
  }
  B.CreateCall(fStrClear, {ctxArg});
  for (size_t i = 0; i < leaves.size(); ++i)
    if (!vals[i]) B.CreateCall(fStrCat, {ctxArg, cstring(leaves[i]->str)});
    else B.CreateCall(fixed ? fStrNumFixed : fStrNum, {ctxArg, vals[i]});
}

Value *Codegen::stringValue(const Expr &e, bool fixed) {
  appendString(e, fixed);
  return B.CreateCall(fStr, {ctxArg});
}

// A concat as a value: the text of the whole chain, one new string.
Val Codegen::concat(const Expr &e) {
  appendString(e, false);
  auto l = locArgs(e.loc);
  return {checked(B.CreateCall(fStrIntern, {ctxArg, l[0], l[1], l[2]})), false, true, e.loc};
}

// A comparison where an operand may be a string: strings go to ncrt_compare, numbers stay
// inline (valueEq for eq/ne).
Val Codegen::compare(const Expr &e, Val a, Val b) {
  auto numeric = [&]() -> Value * {
    switch (e.op) {
    case OpCode::Eq:
    case OpCode::Ne: {
      Value *eq = B.CreateFCmpOEQ(a.v, b.v);
      if (a.mayVacant || b.mayVacant) {
        Value *va = a.mayVacant ? isVacant(a.v) : B.getFalse();
        Value *vb = b.mayVacant ? isVacant(b.v) : B.getFalse();
        eq = B.CreateSelect(B.CreateOr(va, vb), B.CreateAnd(va, vb), eq);
      }
      return toDouble(e.op == OpCode::Eq ? eq : B.CreateNot(eq));
    }
    case OpCode::Lt: return toDouble(B.CreateFCmpOLT(numOf({a.v, a.mayVacant}), numOf({b.v, b.mayVacant})));
    case OpCode::Le: return toDouble(B.CreateFCmpOLE(numOf({a.v, a.mayVacant}), numOf({b.v, b.mayVacant})));
    case OpCode::Gt: return toDouble(B.CreateFCmpOGT(numOf({a.v, a.mayVacant}), numOf({b.v, b.mayVacant})));
    default: return toDouble(B.CreateFCmpOGE(numOf({a.v, a.mayVacant}), numOf({b.v, b.mayVacant})));
    }
  };
  if (!a.mayHandle && !b.mayHandle) return {numeric(), false};
  Value *anyStr = B.CreateOr(a.mayHandle ? isHandleBits(a.v) : B.getFalse(), b.mayHandle ? isHandleBits(b.v) : B.getFalse());
  BasicBlock *strBB = newBlock("cmp.str"), *numBB = newBlock("cmp.num"), *done = newBlock("cmp.done");
  B.CreateCondBr(anyStr, strBB, numBB);
  B.SetInsertPoint(strBB);
  auto l = locArgs(e.loc);
  Value *rs = checked(B.CreateCall(
      fCompare, {ctxArg, B.getInt32((int)e.op - (int)OpCode::Eq), a.v, b.v, l[0], l[1], l[2]}));
  BasicBlock *strEnd = B.GetInsertBlock();
  B.CreateBr(done);
  B.SetInsertPoint(numBB);
  Value *rn = numeric();
  BasicBlock *numEnd = B.GetInsertBlock();
  B.CreateBr(done);
  B.SetInsertPoint(done);
  return {joined(rs, strEnd, rn, numEnd), false};
}

Val Codegen::expr(const Expr &e) {
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Bool: return {ConstantFP::get(dblTy, e.num), false};
  case ExprKind::Vacant: return {ConstantFP::get(dblTy, vacantValue()), true};
  case ExprKind::String:
  case ExprKind::Symbol: return stringConst(e.str, e.loc);
  case ExprKind::Var: return loadVar(e);
  case ExprKind::Unary: {
    if (e.args.size() != 1) break;
    Val a = expr(*e.args[0]);
    checkNotHandle(a, e.loc, HandleUse::Operator, ir::opCodeName(e.op));
    a.mayHandle = false;
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
  if (e.op == OpCode::Concat) return concat(e);
  Val a = expr(*e.args[0]), b = expr(*e.args[1]);
  if (e.op >= OpCode::Eq && e.op <= OpCode::Ge) return compare(e, a, b);
  // Any other operator on a string is an error (the eval engine checks both after evaluating).
  checkNotHandle(a, e.loc, HandleUse::Operator, ir::opCodeName(e.op));
  checkNotHandle(b, e.loc, HandleUse::Operator, ir::opCodeName(e.op));
  a.mayHandle = b.mayHandle = false;
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

// Builtins that are one IEEE operation on num() of their argument: inline, bit for bit the
// C function's result (ir/Builtins.cpp), and no call left in a loop.
static const std::pair<std::string_view, Intrinsic::ID> kInlineBuiltins[] = {
    {"ncc_builtin_abs", Intrinsic::fabs},   {"ncc_builtin_round", Intrinsic::round},
    {"ncc_builtin_fix", Intrinsic::floor},  {"ncc_builtin_fup", Intrinsic::ceil},
    {"ncc_builtin_trunc", Intrinsic::trunc}};

// SIN and COS: the same product in degrees and libm's function (ir/Builtins.cpp), as intrinsics
// so that a SIN and a COS of one angle become one sincos call (optimizeModule's pairSinCos).
static const std::pair<std::string_view, Intrinsic::ID> kDegreeBuiltins[] = {{"ncc_builtin_sin", Intrinsic::sin},
                                                                            {"ncc_builtin_cos", Intrinsic::cos}};

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
  if (!bi->accepts(e.args.size())) {
    fail(e.loc, fmt::format("'{}' takes {} argument(s), {} given", bi->name, builtinArity(*bi), e.args.size()));
    return {ConstantFP::get(dblTy, 0.0), false};
  }
  std::vector<Val> raw;
  for (auto &a : e.args) raw.push_back(expr(*a));
  if (!argSlot) argSlot = allocaEntry(ArrayType::get(dblTy, kMaxBuiltinArgs), "args");
  if (bi->sfn) {  // typed builtins (strings, frames): raw values through ncrt_strfn (ir/Builtins.h table index)
    unsigned count = 0;
    const BuiltinInfo *tab = builtinTable(count);
    for (unsigned i = 0; i < raw.size() && i < kMaxBuiltinArgs; ++i) B.CreateStore(raw[i].v, B.CreateConstGEP1_32(dblTy, argSlot, i));
    auto l = locArgs(e.loc);
    Value *r = checked(sinkCall(fStrFn, {ctxArg, B.getInt32((uint32_t)(bi - tab)), argSlot,
                                             B.getInt32((uint32_t)raw.size()), l[0], l[1], l[2]}));
    return {r, false, bi->result != 'n', e.loc};
  }
  std::vector<Value *> vals;
  for (auto &a : raw) checkNotHandle(a, e.loc, HandleUse::Builtin, bi->name);
  for (auto &a : raw) {
    a.mayHandle = false;
    vals.push_back(numOf(a));
  }
  Value *r = nullptr;
  for (auto &[symbol, id] : kInlineBuiltins)
    if (vals.size() == 1 && symbol == bi->symbol) r = B.CreateUnaryIntrinsic(id, vals[0]);
  for (auto &[symbol, id] : kDegreeBuiltins)
    if (vals.size() == 1 && symbol == bi->symbol)
      r = B.CreateUnaryIntrinsic(id, B.CreateFMul(vals[0], ConstantFP::get(dblTy, kRadiansPerDegree)));
  if (!r) {
    for (unsigned i = 0; i < vals.size() && i < kMaxBuiltinArgs; ++i) B.CreateStore(vals[i], B.CreateConstGEP1_32(dblTy, argSlot, i));
    r = B.CreateCall(builtins_.at(bi->name), {argSlot});
  }
  failIf(B.CreateFCmpUNO(r, r), e.loc, builtinDomainError(*bi));
  return {r, false};
}

}  // namespace ncc::jit
