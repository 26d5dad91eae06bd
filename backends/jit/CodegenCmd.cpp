// NC IR -> LLVM IR: machine commands. Runs of constant commands become one constant table and
// one runtime call (a MachineCmd array for short runs, the packed encoding of runtime/ncrt.h for
// long ones, so a million-line flat program is a few MB of data, not a million calls); commands
// with computed operands are built in a stack slot and passed to ncrt_exec.
#include "backends/jit/CodegenImpl.h"

#include "ir/Arith.h"
#include "runtime/ncrt.h"

namespace ncc::jit {

using namespace llvm;

// Runs up to this length are MachineCmd arrays (no decoding); longer runs are packed.
static constexpr size_t kSmallRun = 16;

static bool hasText(const MachineCmd &c) { return c.kind == CmdKind::Comment || c.kind == CmdKind::Message; }

Constant *Codegen::cmdConstant(const CmdSpec &s) {
  const MachineCmd &c = s.cmd;
  uint8_t modes[6];
  for (int i = 0; i < 6; ++i) modes[i] = (uint8_t)c.modes[i];
  uint32_t loc[3] = {c.loc.file, c.loc.line, c.loc.col};
  Constant *text = hasText(c) ? cstring(s.text) : ConstantPointerNull::get(ptrTy);
  return ConstantStruct::get(
      cmdTy, {B.getInt8((uint8_t)c.kind), B.getInt8(c.sub), B.getInt8(c.sub2), B.getInt8(c.nmodes),
              ConstantDataArray::get(C, ArrayRef<uint8_t>(modes, 6)), B.getInt32(c.mask),
              B.getInt64((uint64_t)c.blockNumber), ConstantDataArray::get(C, ArrayRef<uint32_t>(loc, 3)), text,
              ConstantDataArray::get(C, ArrayRef<double>(c.w, kWords))});
}

void Codegen::emitMachineOp(const ir::Op &op) {
  std::vector<CmdSpec> specs;
  if (!lowerMachineOp(op, specs, diags_)) {
    failed_ = true;
    return;
  }
  bool dynamic = false;
  for (auto &s : specs) dynamic |= s.dynamic();
  if (!dynamic) {
    for (auto &s : specs) run_.push_back(std::move(s));
    return;
  }
  flushRun();
  ensureOpen();
  for (auto &s : specs) {
    if (s.dynamic()) {
      emitDynamicCmd(s);
    } else {
      run_.push_back(std::move(s));
      flushRun();
    }
  }
}

void Codegen::flushRun() {
  if (run_.empty()) return;
  ensureOpen();
  Value *st;
  if (run_.size() <= kSmallRun) {
    std::vector<Constant *> cmds;
    for (auto &s : run_) cmds.push_back(cmdConstant(s));
    auto *arrTy = ArrayType::get(cmdTy, cmds.size());
    auto *gv = new GlobalVariable(*M, arrTy, true, GlobalValue::PrivateLinkage, ConstantArray::get(arrTy, cmds),
                                  "nc.cmds");
    st = B.CreateCall(fExecTable, {ctxArg, gv, B.getInt64(cmds.size())});
  } else {
    std::string bytes;
    for (auto &s : run_) ncrt::packCmd(s.cmd, hasText(s.cmd) ? s.text.c_str() : nullptr, bytes);
    Constant *data = ConstantDataArray::getString(C, bytes, false);
    auto *gv = new GlobalVariable(*M, data->getType(), true, GlobalValue::PrivateLinkage, data, "nc.table");
    st = B.CreateCall(fExecPacked, {ctxArg, gv, B.getInt64(bytes.size())});
  }
  run_.clear();
  checkStatus(st);
}

void Codegen::emitDynamicCmd(const CmdSpec &s) {
  if (!cmdSlot) cmdSlot = allocaEntry(cmdTy, "cmd");
  B.CreateStore(cmdConstant(s), cmdSlot);
  Value *mask = B.getInt32(s.cmd.mask);
  for (auto &dw : s.words) {
    Val v = expr(*dw.value);
    B.CreateStore(v.v, B.CreateInBoundsGEP(cmdTy, cmdSlot, {B.getInt32(0), B.getInt32(9), B.getInt32((unsigned)dw.word)}));
    Value *bit = B.getInt32(wordBit(dw.word));
    if (v.mayVacant) bit = B.CreateSelect(isVacant(v.v), B.getInt32(0), bit);  // vacant word: left out
    mask = B.CreateOr(mask, bit);
  }
  B.CreateStore(mask, B.CreateStructGEP(cmdTy, cmdSlot, 5));
  if (s.subExpr) {
    Val v = expr(*s.subExpr);
    Value *sub;
    if (s.subRule == CmdSpec::SubRule::Round) {
      Value *r = roundIndex(v);
      Value *ok = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 0.0)),
                              B.CreateFCmpOLE(r, ConstantFP::get(dblTy, 255.0)));
      sub = B.CreateFPToUI(B.CreateSelect(ok, r, ConstantFP::get(dblTy, 0.0)), i8Ty);
    } else {
      sub = B.CreateSelect(truthy(v), B.getInt8(0), B.getInt8(1));
    }
    B.CreateStore(sub, B.CreateStructGEP(cmdTy, cmdSlot, 1));
  }
  checkStatus(B.CreateCall(fExec, {ctxArg, cmdSlot}));
}

}  // namespace ncc::jit
