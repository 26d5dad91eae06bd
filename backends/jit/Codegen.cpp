// NC IR -> LLVM IR: module set-up, functions and control flow. Every NC function becomes
//   internal i32 @"nc.<name>"(ptr ctx, ptr storage, ptr frame)
// returning NCRT_OK / NCRT_END / NCRT_ERROR; `frame` holds #0..#33 and the named locals.
#include "backends/jit/Codegen.h"
#include "backends/jit/CodegenImpl.h"

#include "ir/Value.h"
#include "ir/Builtins.h"
#include "runtime/ncrt.h"

#include <llvm/IR/Verifier.h>
#include <llvm/Transforms/Utils/BasicBlockUtils.h>
#include <llvm/Support/raw_ostream.h>

#include <algorithm>
#include <set>
#include <cmath>
#include <cstddef>

namespace ncc::jit {

using namespace llvm;
using ir::Expr;
using ir::ExprKind;
using ir::Op;
using ir::OpKind;


// The LLVM struct types below mirror these C++ layouts.
static_assert(offsetof(MachineCmd, sub) == 2 && offsetof(MachineCmd, modes) == 7 && offsetof(MachineCmd, mask) == 24 &&
              offsetof(MachineCmd, blockNumber) == 32 && offsetof(MachineCmd, loc) == 40 &&
              offsetof(MachineCmd, text) == 56 && offsetof(MachineCmd, w) == 64 && sizeof(MachineCmd) == 64 + 8 * kWords,
              "MachineCmd layout changed: update cmdTy");
static_assert(offsetof(ncrt_storage, max_loop) == 32 && offsetof(ncrt_storage, depth) == 44 &&
              offsetof(ncrt_storage, poll) == 48 && sizeof(ncrt_storage) == 56,
              "ncrt_storage layout changed: update storageTy");

Codegen::Codegen(const ir::Module &src, LLVMContext &ctx, Diagnostics &diags, bool mergeBlocks)
    : src_(src), C(ctx), diags_(diags), mergeBlocks_(mergeBlocks), M(std::make_unique<Module>(src.name.empty() ? "nc" : src.name, ctx)),
      B(ctx) {
  dblTy = Type::getDoubleTy(C);
  i8Ty = Type::getInt8Ty(C);
  i16Ty = Type::getInt16Ty(C);
  i32Ty = Type::getInt32Ty(C);
  i64Ty = Type::getInt64Ty(C);
  i1Ty = Type::getInt1Ty(C);
  ptrTy = PointerType::getUnqual(C);
  cmdTy = StructType::create(C,
                             {i8Ty, i16Ty, i16Ty, i8Ty, ArrayType::get(i8Ty, kMaxModes), i64Ty, i64Ty,
                              ArrayType::get(i32Ty, 3), ptrTy, ArrayType::get(dblTy, kWords)},
                             "ncrt_cmd");
  storageTy = StructType::create(C, {ptrTy, ptrTy, ptrTy, ptrTy, i64Ty, i32Ty, i32Ty, i64Ty}, "ncrt_storage");
  ncFnTy = FunctionType::get(i32Ty, {ptrTy, ptrTy, ptrTy}, false);
}

void Codegen::declareRuntime() {
  auto decl = [&](const char *name, Type *ret, ArrayRef<Type *> params) {
    return M->getOrInsertFunction(name, FunctionType::get(ret, params, false));
  };
  Type *voidTy = Type::getVoidTy(C);
  fBegin = decl("ncrt_begin", ptrTy, {ptrTy, i32Ty, i32Ty});
  fExec = decl("ncrt_exec", i32Ty, {ptrTy, ptrTy});
  fExecTable = decl("ncrt_exec_table", i32Ty, {ptrTy, ptrTy, i64Ty});
  fExecBlocks = decl("ncrt_exec_blocks", i32Ty, {ptrTy, ptrTy, i64Ty});
  fExecPacked = decl("ncrt_exec_packed", i32Ty, {ptrTy, ptrTy, i64Ty});
  fExecMode = decl("ncrt_exec_mode", i32Ty, {ptrTy, ptrTy, i64Ty, ptrTy});
  fExecMove = decl("ncrt_exec_move", i32Ty, {ptrTy, ptrTy, i64Ty, ptrTy, ptrTy});
  fError = decl("ncrt_error", voidTy, {ptrTy, i32Ty, i32Ty, i32Ty, ptrTy});
  fFault = decl("ncrt_fault", voidTy, {ptrTy, i32Ty, i32Ty, i32Ty, i32Ty, ptrTy, dblTy});
  fPoll = decl("ncrt_poll", i32Ty, {ptrTy, i32Ty, i32Ty, i32Ty});
  fMod = decl("ncrt_mod", dblTy, {dblTy, dblTy});
  fIDiv = decl("ncrt_idiv", dblTy, {dblTy, dblTy});
  fPow = decl("ncrt_pow", dblTy, {dblTy, dblTy});
  fBitwise = decl("ncrt_bitwise", dblTy, {i32Ty, dblTy, dblTy});
  fUnset = decl("ncrt_unset", voidTy, {ptrTy, i64Ty});
  fStrClear = decl("ncrt_str_clear", voidTy, {ptrTy});
  fStrCat = decl("ncrt_str_cat", voidTy, {ptrTy, ptrTy});
  fStrNum = decl("ncrt_str_num", voidTy, {ptrTy, dblTy});
  fSysVar = decl("ncrt_sysvar", dblTy, {ptrTy, dblTy, ptrTy, i32Ty, i32Ty, i32Ty});
  fSysVarAt = decl("ncrt_sysvar_at", dblTy, {ptrTy, i32Ty, dblTy, dblTy, dblTy, ptrTy, i32Ty, i32Ty, i32Ty});
  fSysVarSet = decl("ncrt_sysvar_set", dblTy, {ptrTy, dblTy, dblTy, i32Ty, i32Ty, i32Ty});
  fParam = decl("ncrt_param", dblTy, {ptrTy, i32Ty, i32Ty, dblTy, dblTy, i32Ty, i32Ty, i32Ty});
  fStrNumFixed = decl("ncrt_str_num_fixed", voidTy, {ptrTy, dblTy});
  fStr = decl("ncrt_str", ptrTy, {ptrTy});
  fCallee = decl("ncrt_callee", i64Ty, {ptrTy, i32Ty, dblTy, ptrTy, i64Ty, i32Ty, i32Ty, i32Ty});
  fStrConst = decl("ncrt_str_const", dblTy, {ptrTy, ptrTy, i64Ty, i32Ty, i32Ty, i32Ty});
  fStrIntern = decl("ncrt_str_intern", dblTy, {ptrTy, i32Ty, i32Ty, i32Ty});
  fStrFn = decl("ncrt_strfn", dblTy, {ptrTy, i32Ty, ptrTy, i32Ty, i32Ty, i32Ty, i32Ty});
  fCompare = decl("ncrt_compare", dblTy, {ptrTy, i32Ty, dblTy, dblTy, i32Ty, i32Ty, i32Ty});
  fConvert = decl("ncrt_convert", dblTy, {ptrTy, i32Ty, i32Ty, ptrTy, dblTy, i32Ty, i32Ty, i32Ty});
  fFill = decl("ncrt_fill", voidTy, {ptrTy, i64Ty, dblTy});
  fSetModalHook = decl("ncrt_set_modal_hook", Type::getVoidTy(C), {ptrTy, ptrTy});
  fSaveModal = decl("ncrt_save_modal", i32Ty, {ptrTy});
  fModalTrigger = decl("ncrt_modal_trigger", i32Ty, {ptrTy, i32Ty, i32Ty, i32Ty});
  fRestoreModal = decl("ncrt_restore_modal", i32Ty, {ptrTy, i32Ty, i32Ty, i32Ty});
  fJump = decl("ncrt_jump", i64Ty, {ptrTy, i32Ty, dblTy, ptrTy, i64Ty, i32Ty, i32Ty, i32Ty, i32Ty, i32Ty});
  fBadIndex = decl("ncrt_bad_index", voidTy, {ptrTy, i32Ty, i32Ty, i32Ty, ptrTy, dblTy, i32Ty, i32Ty, i32Ty});
  // Pure arithmetic helpers: lets LLVM keep variables in registers across them.
  for (auto *fc : {&fMod, &fIDiv, &fPow, &fBitwise}) {
    auto *fn = cast<Function>(fc->getCallee());
    fn->setDoesNotAccessMemory();
    fn->setDoesNotThrow();
    fn->addFnAttr(Attribute::WillReturn);
  }
  for (auto *fc : {&fError, &fFault, &fBadIndex}) cast<Function>(fc->getCallee())->addFnAttr(Attribute::Cold);
  unsigned n = 0;
  const BuiltinInfo *tab = builtinTable(n);
  for (unsigned i = 0; i < n; ++i) {
    if (!tab[i].fn) continue;  // string builtins go through ncrt_strfn
    auto fc = decl(tab[i].symbol, dblTy, {ptrTy});
    auto *fn = cast<Function>(fc.getCallee());
    fn->setMemoryEffects(MemoryEffects::argMemOnly(ModRefInfo::Ref));  // reads only its arguments
    fn->addParamAttr(0, Attribute::NoCapture);  // so the argument slot aliases no variable
    fn->setDoesNotThrow();
    fn->addFnAttr(Attribute::WillReturn);
    builtins_[tab[i].name] = fc;
  }
}

// Runtime calls that touch only their arguments (the context, a command) and the runtime's own
// state (executor, diagnostics, clock), never the program's variables: LLVM may then keep
// variables in registers across them (a loop's numbers are loaded once, stored at its exits).
// The command calls run the modal call's NC code after a move, so they qualify only without one.
void Codegen::markRuntimeOnly() {
  std::vector<FunctionCallee *> calls = {&fPoll};
  if (!modalFn_) calls.insert(calls.end(), {&fExec, &fExecTable, &fExecPacked, &fExecBlocks, &fExecMode, &fExecMove});
  for (FunctionCallee *fc : calls)
    cast<Function>(fc->getCallee())
        ->setMemoryEffects(MemoryEffects::argMemOnly() | MemoryEffects::inaccessibleMemOnly());
  auto readOnly = [](FunctionCallee &fc, unsigned arg) {  // commands are read, not kept
    cast<Function>(fc.getCallee())->addParamAttr(arg, Attribute::NoCapture);
    cast<Function>(fc.getCallee())->addParamAttr(arg, Attribute::ReadOnly);
  };
  for (FunctionCallee *fc : {&fExec, &fExecTable, &fExecPacked, &fExecBlocks, &fExecMode, &fExecMove}) readOnly(*fc, 1);
  readOnly(fExecMode, 3);
  readOnly(fExecMove, 3);
  readOnly(fExecMove, 4);
}

// ---------------------------------------------------------------- name scan
// Named locals get slots per function (a frame=shared call gets fresh named locals, as in the
// eval engine); named globals and Q prefixes get module-wide slots.
void Codegen::scanExprNames(FnInfo &fi, const Expr &e) {
  if (e.kind == ExprKind::Var) {
    // Arrays: declared ones (a declare op's var has the dimensions as indices) with their size,
    // undeclared ones with kArrayElements.
    bool indexed = !e.args.empty();
    const VarDecl *d = decls_.find(*fi.fn, e);
    uint64_t size = d && d->rank ? d->size() : kArrayElements;
    if (d && d->rank) indexed = true;
    if (e.space == ir::VarSpace::Local && indexed && !fi.arrays.count(e.str)) {
      fi.arrays[e.str] = {fi.arraySlots, size};
      fi.arraySlots += size;
    }
    if (e.space == ir::VarSpace::Local && !indexed) fi.locals.emplace(e.str, (unsigned)fi.locals.size());
    if (e.space == ir::VarSpace::Global && indexed && !globalArrays_.count(e.str)) {
      globalArrays_[e.str] = {globalArraySlots_, size};
      globalArraySlots_ += size;
    }
    if (e.space == ir::VarSpace::Global && !indexed) globalNames_.emplace(e.str, (unsigned)globalNames_.size());
    if (e.space == ir::VarSpace::QParam) qSpaces_ = std::max(qSpaces_, (unsigned)(qPrefixIndex(e.str) + 1));
  }
  for (auto &a : e.args)
    if (a) scanExprNames(fi, *a);
}

void Codegen::scanNames(FnInfo &fi, const ir::Region &r) {
  for (auto &op : r) {
    fi.hasBlocks |= op.kind == OpKind::Block;
    for (auto &a : op.args)
      if (a.value) scanExprNames(fi, *a.value);
    for (auto &sub : op.regions) scanNames(fi, sub);
  }
}

// ---------------------------------------------------------------- helpers
BasicBlock *Codegen::newBlock(const char *name) { return BasicBlock::Create(C, name, F); }

void Codegen::startBlock(BasicBlock *bb) {
  if (!B.GetInsertBlock()->getTerminator()) B.CreateBr(bb);
  B.SetInsertPoint(bb);
}

void Codegen::ensureOpen() {
  if (B.GetInsertBlock()->getTerminator()) B.SetInsertPoint(newBlock("dead"));
}

Value *Codegen::allocaEntry(Type *t, const char *name, Constant *init) {
  IRBuilder<> tmp(entryBB, entryBB->begin());
  Value *a = tmp.CreateAlloca(t, nullptr, name);
  if (init) tmp.CreateStore(init, a);
  return a;
}

Constant *Codegen::cstring(const std::string &s) {
  auto it = strings_.find(s);
  if (it != strings_.end()) return it->second;
  Constant *c = B.CreateGlobalStringPtr(s, ".str", 0, M.get());
  strings_[s] = c;
  return c;
}

std::vector<Value *> Codegen::locArgs(SourceLoc loc) {
  if (!dynLoc_.empty()) return dynLoc_;  // inside nc.modal.run: the caller's location
  return {B.getInt32(loc.file), B.getInt32(loc.line), B.getInt32(loc.col)};
}

void Codegen::checkStatus(Value *status) {
  BasicBlock *cont = newBlock("ok");
  exitPhi->addIncoming(status, B.GetInsertBlock());
  B.CreateCondBr(B.CreateICmpNE(status, B.getInt32(NCRT_OK)), exitBB, cont);
  B.SetInsertPoint(cont);
}

void Codegen::failIf(Value *cond, SourceLoc loc, const std::string &msg) {
  BasicBlock *err = newBlock("error"), *cont = newBlock("cont");
  B.CreateCondBr(cond, err, cont);
  B.SetInsertPoint(err);
  flushPendingMode();
  auto args = locArgs(loc);
  B.CreateCall(fError, {ctxArg, args[0], args[1], args[2], cstring(msg)});
  B.CreateBr(failBB);
  B.SetInsertPoint(cont);
}

void Codegen::fail(SourceLoc loc, const std::string &msg) {
  flushPendingMode();
  auto args = locArgs(loc);
  B.CreateCall(fError, {ctxArg, args[0], args[1], args[2], cstring(msg)});
  B.CreateBr(failBB);
  B.SetInsertPoint(newBlock("dead"));
}

void Codegen::faultIf(Value *cond, SourceLoc loc, unsigned kind, const std::string &name, Value *value) {
  BasicBlock *err = newBlock("fault"), *cont = newBlock("cont");
  B.CreateCondBr(cond, err, cont);
  B.SetInsertPoint(err);
  flushPendingMode();
  auto args = locArgs(loc);
  B.CreateCall(fFault, {ctxArg, args[0], args[1], args[2], B.getInt32(kind), cstring(name),
                        value ? value : ConstantFP::get(dblTy, 0.0)});
  B.CreateBr(failBB);
  B.SetInsertPoint(cont);
}

// Fresh frame slots: [from, 34) vacant (#n), [34, size) unset (named locals).
void Codegen::initFrame(Value *frame, unsigned size, unsigned from) {
  Constant *vac = ConstantFP::get(dblTy, vacantValue());
  uint64_t unsetBits = NCRT_UNSET_BITS;
  Constant *unset = ConstantExpr::getBitCast(ConstantInt::get(i64Ty, unsetBits), dblTy);
  // Unrolled stores let SROA keep main's locals in registers.
  for (unsigned i = from; i < size; ++i)
    B.CreateStore(i <= kFrameLocals ? vac : unset, B.CreateConstGEP1_32(dblTy, frame, i));
}

// Every NCRT_POLL_INTERVAL loop iterations or backward jumps, the runtime checks the time limit.
void Codegen::emitTimeCheck(SourceLoc loc) {
  Value *p = B.CreateSub(B.CreateLoad(i64Ty, pollPtr), B.getInt64(1));
  B.CreateStore(p, pollPtr);
  BasicBlock *poll = newBlock("poll"), *cont = newBlock("cont");
  B.CreateCondBr(B.CreateICmpSLT(p, B.getInt64(0)), poll, cont);
  B.SetInsertPoint(poll);
  auto args = locArgs(loc);
  Value *st = B.CreateCall(fPoll, {ctxArg, args[0], args[1], args[2]});
  B.CreateCondBr(B.CreateICmpNE(st, B.getInt32(NCRT_OK)), failBB, cont);
  B.SetInsertPoint(cont);
}

// ---------------------------------------------------------------- functions
// After the entry block's set-up: the shared fail (returns NCRT_ERROR) and exit (returns the
// status checkStatus passes on) blocks, then the body, where emission continues.
// Both pass on the blocks still waiting (their status does not matter: the run stops).
void Codegen::startBody() {
  if (blkOn_) {
    blkCount = B.CreateAlloca(i64Ty, nullptr, "blocks.count");
    blkLast = B.CreateAlloca(ptrTy, nullptr, "blocks.last");
    B.CreateStore(B.getInt64(0), blkCount);
    B.CreateStore(ConstantPointerNull::get(ptrTy), blkLast);
  }
  failBB = newBlock("fail");
  exitBB = newBlock("exit");
  BasicBlock *body = newBlock("body");
  B.CreateBr(body);
  B.SetInsertPoint(failBB);
  flushBlocks(false);
  B.CreateRet(B.getInt32(NCRT_ERROR));
  B.SetInsertPoint(exitBB);
  exitPhi = B.CreatePHI(i32Ty, 4, "status");
  flushBlocks(false);
  B.CreateRet(exitPhi);
  B.SetInsertPoint(body);
}

void Codegen::flushBlocks(bool check) {
  if (!blkOn_) return;
  Value *n = B.CreateLoad(i64Ty, blkCount);
  BasicBlock *flush = newBlock("blocks.flush"), *cont = newBlock("blocks.done");
  B.CreateCondBr(B.CreateICmpNE(n, B.getInt64(0)), flush, cont);  // folds away where none wait
  B.SetInsertPoint(flush);
  Value *st = B.CreateCall(fExecBlocks, {ctxArg, B.CreateLoad(ptrTy, blkLast), n});
  B.CreateStore(B.getInt64(0), blkCount);
  if (check) checkStatus(st);
  B.CreateBr(cont);
  B.SetInsertPoint(cont);
}

CallInst *Codegen::sinkCall(FunctionCallee f, ArrayRef<Value *> args) {
  flushBlocks();
  return B.CreateCall(f, args);
}

void Codegen::emitReturn() {
  flushBlocks();
  B.CreateRet(B.getInt32(NCRT_OK));
}

void Codegen::emitFunction(FnInfo &fi) {
  cur_ = &fi;
  F = fi.F;
  ctxArg = F->getArg(0);
  stArg = F->getArg(1);
  frameArg = F->getArg(2);
  blkOn_ = mergeBlocks_ && fi.hasBlocks;
  entryBB = newBlock("entry");
  B.SetInsertPoint(entryBB);
  auto field = [&](unsigned i) { return B.CreateStructGEP(storageTy, stArg, i); };
  numberedBase = B.CreateLoad(ptrTy, field(0), "numbered");
  rBase = B.CreateLoad(ptrTy, field(1), "rparam");
  qBase = B.CreateLoad(ptrTy, field(2), "qparam");
  namedBase = B.CreateLoad(ptrTy, field(3), "named");
  maxLoop = B.CreateLoad(i64Ty, field(4), "max_loop");
  depthPtr = field(6);
  pollPtr = field(7);
  cmdSlot = argSlot = nullptr;
  siteSlots_ = 0;
  backJumps = B.CreateAlloca(i64Ty, nullptr, "backjumps");
  scratch = B.CreateAlloca(dblTy, nullptr, "scratch");
  B.CreateStore(B.getInt64(0), backJumps);
  localArrays = nullptr;
  if (!fi.arrays.empty()) {  // fresh arrays per activation: unset, declared ones initial values
    uint64_t n = fi.arraySlots;
    localArrays = B.CreateAlloca(ArrayType::get(dblTy, n), nullptr, "arrays");
    B.CreateCall(fUnset, {localArrays, B.getInt64(n)});
  }
  // Declared locals hold their type's initial value from the start of each activation.
  if (auto it = decls_.locals.find(fi.fn); it != decls_.locals.end())
    for (auto &[name, d] : it->second) {
      if (d.param) continue;
      Constant *init = ConstantFP::get(dblTy, initialValue(d.type));
      if (d.rank) {
        auto &a = fi.arrays.at(name);
        B.CreateCall(fFill, {B.CreateConstGEP1_64(dblTy, localArrays, a.offset), B.getInt64(a.size), init});
      } else if (auto l = fi.locals.find(name); l != fi.locals.end()) {
        B.CreateStore(init, B.CreateConstGEP1_64(dblTy, frameArg, kFrameLocals + 1 + l->second));
      }
    }
  startBody();

  order_.clear();
  jumps_.clear();
  jumpOps_.clear();
  targetBBs_.clear();
  loops_.clear();
  kept_.clear();
  run_.clear();
  packed_.clear();
  if (!fi.compileErrors.empty()) {
    // The eval engine rejects this function when it first runs it: so does the compiled code.
    for (auto &e : fi.compileErrors) {
      auto args = locArgs(e.first);
      B.CreateCall(fError, {ctxArg, args[0], args[1], args[2], cstring(e.second)});
    }
    B.CreateBr(failBB);
  } else {
    emitParamDefaults(fi);
    startSections(fi);
    scanTargets(fi.fn->body);
    emitRegion(fi.fn->body);
    if (!B.GetInsertBlock()->getTerminator()) emitReturn();
  }
  EliminateUnreachableBlocks(*F);  // an unused exit (and its block flush), dead blocks
}

// The module's modal calls: their argument keys, the functions they may call (all of them for a
// computed callee), the globals that hold the setting.
void Codegen::scanModalCalls() {
  bool any = false, computed = false;
  std::set<FnInfo *> callees;
  auto walk = [&](auto &self, const ir::Region &r) -> void {
    for (auto &op : r) {
      if (op.kind == OpKind::ModalCall) {
        any = true;
        for (auto &a : op.args)
          if (a.key.rfind("a.", 0) == 0) modalKeys_.emplace(a.key.substr(2), (unsigned)modalKeys_.size());
        std::string name;
        if (const Expr *c = op.get("callee"); c && c->kind == ExprKind::String && src_.find(c->str))
          callees.insert(&functions_.at(c->str));
        else if (c) computed = true;
      }
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  for (auto &fn : src_.functions) walk(walk, fn.body);
  if (!any) return;
  for (auto &fn : src_.functions)
    if (computed || callees.count(&functions_.at(fn.name))) modalCallees_.push_back(&functions_.at(fn.name));
  auto global = [&](Type *t, Constant *init, const char *name) {
    return new GlobalVariable(*M, t, false, GlobalValue::PrivateLinkage, init, name);
  };
  modalFn_ = global(i64Ty, B.getInt64(-1), "nc.modal.fn");
  modalIn_ = global(i32Ty, B.getInt32(0), "nc.modal.in");
  modalCount_ = global(dblTy, ConstantFP::get(dblTy, 1.0), "nc.modal.count");
  auto *argsTy = ArrayType::get(dblTy, std::max<size_t>(1, modalKeys_.size()));
  modalArgs_ = global(argsTy, ConstantAggregateZero::get(argsTy), "nc.modal.args");
}

// The section-call state of one activation (only functions with call_section get it).
void Codegen::startSections(FnInfo &fi) {
  sectionEnds_ = ir::sectionEnds(*fi.fn);
  sectionIds_.clear();
  sectionRet_.clear();
  auto walk = [&](auto &self, const ir::Region &r) -> void {  // ids in program order
    for (auto &op : r) {
      if (op.kind == OpKind::CallSection) sectionIds_.emplace(&op, (unsigned)sectionIds_.size());
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  walk(walk, fi.fn->body);
  if (sectionIds_.empty()) return;
  sectionSp_ = allocaEntry(i32Ty, "section.sp", B.getInt32(0));
  sectionCalls_ = allocaEntry(ArrayType::get(i32Ty, ir::kMaxSectionDepth), "section.calls");
  sectionLeft_ = allocaEntry(ArrayType::get(dblTy, ir::kMaxSectionDepth), "section.left");
}

// Parameters the call omitted (their slot is still unset): the default, else the type's initial
// value, converted; an omitted VAR parameter aliases a slot of this activation.
void Codegen::emitParamDefaults(FnInfo &fi) {
  for (auto &p : fi.fn->params) {
    Value *slot = B.CreateConstGEP1_64(dblTy, frameArg, kFrameLocals + 1 + fi.locals.at(p.name));
    Value *omitted = B.CreateICmpEQ(B.CreateLoad(i64Ty, slot), ConstantInt::get(i64Ty, NCRT_UNSET_BITS));
    BasicBlock *fill = newBlock("param.default"), *cont = newBlock("param.done");
    B.CreateCondBr(omitted, fill, cont);
    B.SetInsertPoint(fill);
    const VarDecl *d = decls_.find(*fi.fn, ir::VarSpace::Local, p.name);
    Val v = p.defaultValue ? expr(*p.defaultValue)
                           : Val{ConstantFP::get(dblTy, initialValue(d ? d->type : ValueType::Real)), false};
    Value *c = convertArg(fi, p.name, v, fi.fn->loc);
    if (p.byRef) {
      Value *own = allocaEntry(dblTy, "param.own");
      B.CreateStore(c, own);
      c = B.CreateBitCast(B.CreatePtrToInt(own, i64Ty), dblTy);
    }
    B.CreateStore(c, slot);
    B.CreateBr(cont);
    B.SetInsertPoint(cont);
  }
}

void Codegen::emitEntry() {
  auto *main = Function::Create(FunctionType::get(i32Ty, {ptrTy}, false), GlobalValue::ExternalLinkage,
                                "ncc_program_main", M.get());
  F = main;
  entryBB = newBlock("entry");
  B.SetInsertPoint(entryBB);
  Value *ctx = main->getArg(0);
  uint64_t named = globalNames_.size() + globalArraySlots_;
  Value *st = B.CreateCall(fBegin, {ctx, B.getInt32((uint32_t)named),
                                    B.getInt32(qSpaces_)});
  // Declared globals hold their type's initial value from the start of the run.
  Value *namedPtr = B.CreateLoad(ptrTy, B.CreateStructGEP(storageTy, st, 3));
  for (auto &[name, d] : decls_.globals) {
    Constant *init = ConstantFP::get(dblTy, initialValue(d.type));
    if (d.rank) {
      auto it = globalArrays_.find(name);
      if (it == globalArrays_.end()) continue;
      B.CreateCall(fFill, {B.CreateConstGEP1_64(dblTy, namedPtr, globalNames_.size() + it->second.offset),
                           B.getInt64(it->second.size), init});
    } else if (auto it = globalNames_.find(name); it != globalNames_.end()) {
      B.CreateStore(init, B.CreateConstGEP1_64(dblTy, namedPtr, it->second));
    }
  }
  if (modalFn_) {  // no modal call at the start of each run; the runtime calls nc.modal.run
    B.CreateStore(B.getInt64(-1), modalFn_);
    B.CreateStore(B.getInt32(0), modalIn_);
    B.CreateCall(fSetModalHook, {ctx, modalRun_});
  }
  FnInfo &fi = functions_.at(src_.functions[0].name);
  Value *frame = B.CreateAlloca(ArrayType::get(dblTy, fi.frameSize), nullptr, "frame");
  initFrame(frame, fi.frameSize, 0);
  B.CreateRet(B.CreateCall(fi.F, {ctx, st, frame}));
}

std::unique_ptr<Module> Codegen::run() {
  if (!ir::verifyRunnable(src_, diags_)) return nullptr;
  ir::collectDecls(src_, decls_, nullptr);
  declareRuntime();
  for (auto &fn : src_.functions) {
    if (functions_.count(fn.name)) {
      diags_.error(fn.loc, "function '" + fn.name + "' defined twice");
      return nullptr;
    }
    FnInfo &fi = functions_[fn.name];
    fi.fn = &fn;
    for (auto &p : fn.params) fi.locals.emplace(p.name, (unsigned)fi.locals.size());
    scanNames(fi, fn.body);
    fi.frameSize = (unsigned)(kFrameLocals + 1 + fi.locals.size() + 1);  // the last slot: return value
    fi.F = Function::Create(ncFnTy, GlobalValue::InternalLinkage, "nc." + fn.name, M.get());
    validate(fi);
  }
  if (src_.functions.empty()) {
    // Nothing to run: an entry that succeeds at once (the eval engine does the same).
    auto *main = Function::Create(FunctionType::get(i32Ty, {ptrTy}, false), GlobalValue::ExternalLinkage,
                                  "ncc_program_main", M.get());
    B.SetInsertPoint(BasicBlock::Create(C, "entry", main));
    B.CreateRet(B.getInt32(NCRT_OK));
  } else {
    scanModalCalls();
    markRuntimeOnly();
    if (modalFn_) emitModalRun();
    for (auto &fn : src_.functions) emitFunction(functions_.at(fn.name));
    emitEntry();
  }
  if (failed_) return nullptr;
  std::string err;
  raw_string_ostream os(err);
  if (verifyModule(*M, &os)) {
    diags_.error({}, "internal error: invalid LLVM IR: " + os.str());
    return nullptr;
  }
  return std::move(M);
}

std::unique_ptr<Module> buildModule(const ir::Module &m, LLVMContext &ctx, Diagnostics &diags, bool mergeBlocks) {
  Codegen cg(m, ctx, diags, mergeBlocks);
  return cg.run();
}

}  // namespace ncc::jit
