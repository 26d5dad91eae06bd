// NC IR -> LLVM IR: machine commands. Runs of constant commands become one constant table and
// one runtime call (a MachineCmd array for short runs, the packed encoding of runtime/ncrt.h for
// long ones, so a million-line flat program is a few MB of data, not a million calls); commands
// with computed operands are built in a stack slot and passed to ncrt_exec (a move: with the
// waiting blocks and mode, to ncrt_exec_move).
#include "backends/jit/CodegenImpl.h"

#include "ir/Builtins.h"
#include "ir/Strings.h"
#include "ir/SystemParams.h"
#include "runtime/ncrt.h"

#include <llvm/IR/Intrinsics.h>

namespace ncc::jit {

using namespace llvm;

// Runs up to this length are MachineCmd arrays (no decoding); longer runs are packed.
static constexpr size_t kSmallRun = 16;

static bool hasText(const MachineCmd &c) {
  return c.kind == CmdKind::Comment || c.kind == CmdKind::Message || c.kind == CmdKind::Cycle;
}

Constant *Codegen::cmdConstant(const MachineCmd &c) {
  uint8_t modes[kMaxModes];
  for (int i = 0; i < kMaxModes; ++i) modes[i] = (uint8_t)c.modes[i];
  uint32_t loc[3] = {c.loc.file, c.loc.line, c.loc.col};
  Constant *text = hasText(c) && c.text ? cstring(c.text) : ConstantPointerNull::get(ptrTy);
  return ConstantStruct::get(
      cmdTy, {B.getInt8((uint8_t)c.kind), B.getInt16(c.sub), B.getInt16(c.sub2), B.getInt8(c.nmodes),
              ConstantDataArray::get(C, ArrayRef<uint8_t>(modes, kMaxModes)), B.getInt64(c.mask),
              B.getInt64((uint64_t)c.blockNumber), ConstantDataArray::get(C, ArrayRef<uint32_t>(loc, 3)), text,
              ConstantDataArray::get(C, ArrayRef<double>(c.w, kWords))});
}

// An operand whose code calls nothing in the runtime but the pure arithmetic and numeric
// builtins: no system variable, computed parameter number, array element, string or comparison
// (those reach the target, or report errors themselves). Its errors go through failIf/faultIf.
static bool quietOperand(const ir::Expr &e) {
  using ir::ExprKind, ir::OpCode;
  auto quiet = [](const ir::ExprPtr &a) { return a && quietOperand(*a); };
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Bool:
  case ExprKind::Vacant: return true;
  case ExprKind::Var: {  // a named scalar, or #n, R n, Q n with a literal number (no array element)
    using ir::VarSpace;
    auto literal = [](const ir::ExprPtr &a) { return a && (a->kind == ExprKind::Number || a->kind == ExprKind::Bool); };
    const bool param = e.space == VarSpace::Numbered || e.space == VarSpace::RParam || e.space == VarSpace::QParam;
    ParamMap map;
    if (computedParameterNumber(e, map)) return false;
    if (e.args.empty()) return e.space != VarSpace::System;
    return param && std::all_of(e.args.begin(), e.args.end(), literal);
  }
  case ExprKind::Unary: return e.op == OpCode::Neg && e.args.size() == 1 && quiet(e.args[0]);
  case ExprKind::Binary: {
    static constexpr OpCode kArithmetic[] = {OpCode::Add, OpCode::Sub, OpCode::Mul, OpCode::Div,
                                             OpCode::Mod, OpCode::Pow, OpCode::IDiv};
    return std::find(std::begin(kArithmetic), std::end(kArithmetic), e.op) != std::end(kArithmetic) &&
           e.args.size() == 2 && quiet(e.args[0]) && quiet(e.args[1]);
  }
  case ExprKind::Call: {
    const BuiltinInfo *bi = findBuiltin(e.str);
    if (isExistsCall(e.str, e.args.size()) || !bi || bi->sfn || !bi->fn || !bi->accepts(e.args.size())) return false;
    return std::all_of(e.args.begin(), e.args.end(), quiet);
  }
  default: return false;
  }
}

void Codegen::emitMachineOp(const ir::Op &op) {
  Diagnostics quiet(diags_.sources());  // validate() already reported template errors
  quiet.setCollect(true);
  CmdTemplate t;
  if (!buildCmdTemplate(op, t, quiet)) return;
  if (t.slots.empty() && !t.text) {
    if (t.base.kind == CmdKind::Block && blkOn_ && run_.empty() && packed_.empty()) emitBlockCmd(t.base);
    else appendToRun(t.base);
    return;
  }
  // A move that nothing between its mode line and its call can observe goes in one call with
  // them (a loop's `G1 X[…]` line: one runtime call per iteration instead of two).
  const bool oneCall = t.base.kind == CmdKind::Move && !t.text &&
                       std::all_of(t.slots.begin(), t.slots.end(), [](auto &s) { return quietOperand(*s.expr); });
  if (oneCall) pendingMode_ = takeModeRun();
  else flushRun();
  ensureOpen();
  emitDynamicCmd(t, oneCall);
}

Value *Codegen::takeModeRun() {
  if (!packed_.empty() || run_.size() != 1 || run_[0].kind != CmdKind::Mode) {
    flushRun();
    return nullptr;
  }
  auto *gv = new GlobalVariable(*M, cmdTy, true, GlobalValue::PrivateLinkage, cmdConstant(run_[0]), "nc.mode");
  run_.clear();
  return gv;
}

void Codegen::takeWaitingBlocks(Value *&last, Value *&count) {
  count = B.getInt64(0), last = ConstantPointerNull::get(ptrTy);
  if (!blkOn_) return;
  count = B.CreateLoad(i64Ty, blkCount);
  last = B.CreateLoad(ptrTy, blkLast);
  B.CreateStore(B.getInt64(0), blkCount);
}

// In an error branch of a quiet move's operands: the mode it carries is executed first, as it
// was before the operands (a mode that fails stops the run with its own error instead).
void Codegen::flushPendingMode() {
  if (!pendingMode_) return;
  Value *last, *count;
  takeWaitingBlocks(last, count);
  Value *st = B.CreateCall(fExecMode, {ctxArg, last, count, pendingMode_});
  BasicBlock *report = newBlock("mode.done");
  B.CreateCondBr(B.CreateICmpNE(st, B.getInt32(NCRT_OK)), failBB, report);
  B.SetInsertPoint(report);
}

// Short runs stay MachineCmds; once a run is longer it is packed as it grows (a flat program
// must not hold a 224-byte struct per command).
void Codegen::appendToRun(const MachineCmd &c) {
  if (packed_.empty() && run_.size() < kSmallRun) {
    run_.push_back(c);
    return;
  }
  for (auto &r : run_) ncrt::packCmd(r, hasText(r) ? r.text : nullptr, packed_);
  run_.clear();
  ncrt::packCmd(c, hasText(c) ? c.text : nullptr, packed_);
}

void Codegen::flushRun() {
  if (run_.empty() && packed_.empty()) return;
  ensureOpen();
  Value *st;
  if (packed_.empty() && run_.size() == 1 && run_[0].kind == CmdKind::Mode) {
    // The `G1` of a loop's `G1 X[…]` line: with the waiting blocks in one call, and a compare in
    // the target when that mode is in force.
    auto *gv = new GlobalVariable(*M, cmdTy, true, GlobalValue::PrivateLinkage, cmdConstant(run_[0]), "nc.mode");
    Value *n, *last;
    takeWaitingBlocks(last, n);
    st = B.CreateCall(fExecMode, {ctxArg, last, n, gv});
  } else if (packed_.empty()) {
    std::vector<Constant *> cmds;
    for (auto &c : run_) cmds.push_back(cmdConstant(c));
    auto *arrTy = ArrayType::get(cmdTy, cmds.size());
    auto *gv = new GlobalVariable(*M, arrTy, true, GlobalValue::PrivateLinkage, ConstantArray::get(arrTy, cmds),
                                  "nc.cmds");
    st = sinkCall(fExecTable, {ctxArg, gv, B.getInt64(cmds.size())});
  } else {
    Constant *data = ConstantDataArray::getString(C, packed_, false);
    auto *gv = new GlobalVariable(*M, data->getType(), true, GlobalValue::PrivateLinkage, data, "nc.table");
    st = sinkCall(fExecPacked, {ctxArg, gv, B.getInt64(packed_.size())});
    std::string().swap(packed_);
  }
  run_.clear();
  checkStatus(st);
}

// A Block command that starts a run waits for the next call that reaches the target (a loop of
// assignments makes no call per block).
void Codegen::emitBlockCmd(const MachineCmd &c) {
  ensureOpen();
  auto *arrTy = ArrayType::get(cmdTy, 1);
  auto *gv = new GlobalVariable(*M, arrTy, true, GlobalValue::PrivateLinkage,
                                ConstantArray::get(arrTy, {cmdConstant(c)}), "nc.block");
  B.CreateStore(B.CreateAdd(B.CreateLoad(i64Ty, blkCount), B.getInt64(1)), blkCount);
  B.CreateStore(gv, blkLast);
}

// Where a computed command is built. In a loop, up to kLoopCmdSlots sites per function get a slot
// of their own whose constant part (kind, modes, location, constant words) is stored on the
// first pass only; each pass then writes just the computed words and the mask. Elsewhere one
// shared slot, filled whole.
static constexpr unsigned kLoopCmdSlots = 16;

// A copy of a constant command, not a store of the aggregate: the unoptimised code generator
// (the JIT cache's quick tier) selects a memcpy quickly and falls back to SelectionDAG for the
// aggregate; at O2 both become the same field stores.
void Codegen::storeCmd(const MachineCmd &c, Value *slot) {
  auto *gv = new GlobalVariable(*M, cmdTy, true, GlobalValue::PrivateLinkage, cmdConstant(c), "nc.cmd");
  const DataLayout &dl = M->getDataLayout();
  Align a = dl.getABITypeAlign(cmdTy);
  B.CreateMemCpy(slot, a, gv, a, dl.getTypeAllocSize(cmdTy));
}

Value *Codegen::cmdSiteSlot(const MachineCmd &base) {
  if (loops_.empty() || siteSlots_ >= kLoopCmdSlots) {
    if (!cmdSlot) cmdSlot = allocaEntry(cmdTy, "cmd");
    storeCmd(base, cmdSlot);
    return cmdSlot;
  }
  ++siteSlots_;
  Value *slot = allocaEntry(cmdTy, "cmd.site");
  Value *filled = allocaEntry(i1Ty, "cmd.filled", B.getFalse());
  BasicBlock *fill = newBlock("cmd.fill"), *ready = newBlock("cmd.ready");
  B.CreateCondBr(B.CreateLoad(i1Ty, filled), ready, fill);
  B.SetInsertPoint(fill);
  storeCmd(base, slot);
  B.CreateStore(B.getTrue(), filled);
  B.CreateBr(ready);
  B.SetInsertPoint(ready);
  return slot;
}

// Operands in template order: a vacant value leaves its word out, a non-finite one is an error.
// oneCall: a quiet move, passed with the waiting blocks and pendingMode_ (ncrt_exec_move).
void Codegen::emitDynamicCmd(const CmdTemplate &t, bool oneCall) {
  Value *slot = cmdSiteSlot(t.base);
  Value *mask = B.getInt64(t.base.mask);
  Constant *inf = ConstantFP::getInfinity(dblTy);
  for (auto &s : t.slots) {
    Val v = expr(*s.expr);
    checkNotHandle(v, s.expr->loc, HandleUse::AsNumber);
    Value *finite = B.CreateFCmpOLT(B.CreateUnaryIntrinsic(Intrinsic::fabs, v.v), inf);
    Value *vacant = v.mayVacant ? isVacant(v.v) : B.getFalse();
    failIf(B.CreateAnd(B.CreateNot(vacant), B.CreateNot(finite)), s.expr->loc, "value is not a finite number");
    B.CreateStore(v.v, B.CreateInBoundsGEP(cmdTy, slot, {B.getInt32(0), B.getInt32(9), B.getInt32((unsigned)s.word)}));
    Value *bit = B.getInt64(wordBit(s.word));
    if (v.mayVacant) bit = B.CreateSelect(vacant, B.getInt64(0), bit);
    mask = B.CreateOr(mask, bit);
  }
  B.CreateStore(mask, B.CreateStructGEP(cmdTy, slot, 5));
  if (t.text) {
    bool fixed = t.base.kind == CmdKind::Message && t.base.sub != (uint8_t)MessageKind::Msg;
    B.CreateStore(stringValue(*t.text, fixed), B.CreateStructGEP(cmdTy, slot, 8));
  }
  if (!oneCall) return checkStatus(sinkCall(fExec, {ctxArg, slot}));
  Value *last, *count;
  takeWaitingBlocks(last, count);
  Value *mode = pendingMode_ ? pendingMode_ : ConstantPointerNull::get(ptrTy);
  pendingMode_ = nullptr;
  checkStatus(B.CreateCall(fExecMove, {ctxArg, last, count, mode, slot}));
}

}  // namespace ncc::jit
