// NC IR -> LLVM IR: statements and control flow (assign, if, while, loop, goto, call), with the
// eval engine's semantics: loop limits counted at the back edge, backward jumps counted per
// function activation, calls sharing or renewing the #1..#33 frame.
#include "backends/jit/CodegenImpl.h"
#include "backends/jit/Jit.h"

#include "ir/Jumps.h"
#include "ir/Strings.h"
#include "ir/Value.h"
#include "runtime/ncrt.h"

#include <llvm/Transforms/Utils/BasicBlockUtils.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace ncc::jit {

using namespace llvm;
using ir::Expr;
using ir::ExprKind;
using ir::Op;
using ir::OpKind;


// Numbers every op in pre-order (the eval engine's instruction order), lists block numbers and
// labels as jump targets (ir/Jumps.h) and marks the ops gotos reach: they start a basic block
// (and end a constant run). A computed goto may reach every target.
void Codegen::scanTargets(const ir::Region &body) {
  order_.clear();
  jumps_.clear();
  jumpOps_.clear();
  targetBBs_.clear();
  jumpTable_ = nullptr;
  std::vector<const Op *> gotos;
  bool computed = false;
  auto walk = [&](auto &self, const ir::Region &r) -> void {
    for (auto &op : r) {
      unsigned pos = order_[&op] = (unsigned)order_.size();
      if (op.kind == OpKind::Block)
        if (const Expr *n = op.get("n"); n && (n->kind == ExprKind::Number || n->kind == ExprKind::Bool) &&
                                         (int64_t)n->num >= 0) {
          jumps_.push_back({(double)(int64_t)n->num, nullptr, pos});
          jumpOps_.push_back(&op);
        }
      if (op.kind == OpKind::Label)
        if (const Expr *l = op.get("name")) {
          jumps_.push_back({NAN, l->str.c_str(), pos});
          jumpOps_.push_back(&op);
        }
      if (op.kind == OpKind::Goto) {
        gotos.push_back(&op);
        computed |= !ir::constantJump(op);
      }
      if (op.kind == OpKind::CallSection) gotos.push_back(&op);  // its `from` label is a target
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  walk(walk, body);
  for (const Op *go : gotos)
    if (const Op *t = go->kind == OpKind::CallSection || ir::constantJump(*go) ? resolveTarget(*go) : nullptr)
      targetBBs_[t] = nullptr;
  if (computed)
    for (const Op *t : jumpOps_) targetBBs_[t] = nullptr;
}

bool compilesQuickly(const ir::Module &m, std::string &why) {
  for (const ir::Function &f : m.functions) {
    size_t targets = 0;
    bool computed = false;
    auto walk = [&](auto &self, const ir::Region &r) -> void {
      for (auto &op : r) {
        targets += (op.kind == OpKind::Block && op.get("n")) || op.kind == OpKind::Label;
        computed |= op.kind == OpKind::Goto && !ir::constantJump(op);
        for (auto &sub : op.regions) self(self, sub);
      }
    };
    walk(walk, f.body);
    if (computed && targets > kMaxComputedGotoTargets) {
      why = fmt::format("'{}' has a computed goto over {} numbered blocks and labels (more than {})", f.name, targets,
                        kMaxComputedGotoTargets);
      return false;
    }
  }
  return true;
}

// A constant target (a call_section's `from`), as the eval engine resolves it when it compiles
// the function.
const Op *Codegen::resolveTarget(const Op &go) {
  const Expr *l = go.get(go.kind == OpKind::CallSection ? "from" : "label");
  double n = l ? NAN : go.get("n")->num;
  int64_t t = findJump(jumps_.data(), jumps_.size(), l, n, l ? l->str : "", order_.at(&go), ir::jumpDir(go));
  return t < 0 ? nullptr : jumpOps_[t];
}

// The errors the eval engine raises when it compiles a function (on its first call): invalid
// machine ops, bad assignment targets, break outside loops, unsupported ops, unresolved gotos.
void Codegen::validate(FnInfo &fi) {
  Diagnostics tmp(diags_.sources());
  tmp.setCollect(true);
  auto &errs = fi.compileErrors;
  std::vector<const Op *> gotos;
  auto walk = [&](auto &self, const ir::Region &r, unsigned loopDepth) -> bool {
    for (auto &op : r) {
      if (isMachineOp(op.kind)) {
        CmdTemplate t;
        if (!buildCmdTemplate(op, t, tmp)) {
          for (auto &d : tmp.collected()) errs.push_back({d.loc, d.message});
          errs.push_back({op.loc, "invalid machine operation"});
          return false;
        }
        continue;
      }
      switch (op.kind) {
      case OpKind::Assign:
      case OpKind::Declare: {
        const Expr *t = op.get(op.kind == OpKind::Assign ? "target" : "var");
        if (!t || t->kind != ExprKind::Var) {
          errs.push_back({op.loc, "assignment target is not a variable"});
          return false;
        }
        break;
      }
      case OpKind::If:
      case OpKind::While:
      case OpKind::Loop:
        if (op.regions.empty() || ((op.kind != OpKind::Loop) && !op.get("cond"))) {
          errs.push_back({op.loc, fmt::format("malformed '{}'", ir::opInfo(op.kind).name)});
          return false;
        }
        for (auto &sub : op.regions)
          if (!self(self, sub, loopDepth + (op.kind == OpKind::If ? 0 : 1))) return false;
        break;
      case OpKind::Break:
      case OpKind::Continue:
        if (!loopDepth) {
          errs.push_back({op.loc, fmt::format("'{}' outside a loop", ir::opInfo(op.kind).name)});
          return false;
        }
        break;
      case OpKind::Goto: gotos.push_back(&op); break;
      case OpKind::CallSection: gotos.push_back(&op); break;
      case OpKind::ModalCall:
      case OpKind::ModalTrigger:
      case OpKind::Label:
      case OpKind::Call:
      case OpKind::Return: break;
      default:
        errs.push_back({op.loc, fmt::format("the JIT cannot execute '{}'", ir::opInfo(op.kind).name)});
        return false;
      }
    }
    return true;
  };
  if (!walk(walk, fi.fn->body, 0)) return;
  scanTargets(fi.fn->body);
  for (const Op *go : gotos) {
    if (go->kind == OpKind::Goto && !ir::constantJump(*go)) continue;  // resolved when it runs
    if (!resolveTarget(*go)) {
      const Expr *l = go->get(go->kind == OpKind::CallSection ? "from" : "label");
      errs.push_back({go->loc, ir::missingJumpMessage(l, l ? NAN : go->get("n")->num, l ? l->str : "")});
      return;
    }
  }
}

BasicBlock *Codegen::targetBlock(const Op *op) {
  BasicBlock *&bb = targetBBs_[op];
  if (!bb) bb = newBlock(op->kind == OpKind::Label ? "label" : "block");
  return bb;
}

void Codegen::emitRegion(const ir::Region &r) {
  for (auto &op : r) {
    if (auto *calls = sectionEnds_.endingBefore(op)) {  // before the op: a jump to it skips this
      flushRun();
      ensureOpen();
      emitSectionEnd(*calls);
    }
    if (targetBBs_.count(&op)) {
      flushRun();
      startBlock(targetBlock(&op));
    }
    if (op.kind == OpKind::Label) continue;
    if (isMachineOp(op.kind)) {
      emitMachineOp(op);
      continue;
    }
    flushRun();
    ensureOpen();
    emitOp(op);
  }
  flushRun();
  if (auto *calls = sectionEnds_.endingAt(r)) {
    ensureOpen();
    emitSectionEnd(*calls);
  }
}

// call_section (ir/Jumps.h): the activation's stack of active sections holds each one's call
// (an index into sectionIds_) and repetitions left. count below 1 runs nothing.
void Codegen::emitCallSection(const Op &op) {
  const Expr *countE = op.get("count");
  Value *n = countE ? roundOf(numOf(expr(*countE))) : ConstantFP::get(dblTy, 1.0);
  BasicBlock *run = newBlock("section.call");
  B.CreateCondBr(B.CreateFCmpOGE(n, ConstantFP::get(dblTy, 1.0)), run, sectionReturn(op));
  B.SetInsertPoint(run);
  Value *sp = B.CreateLoad(i32Ty, sectionSp_);
  failIf(B.CreateICmpUGE(sp, B.getInt32(ir::kMaxSectionDepth)), op.loc, ir::sectionDepthMessage());
  B.CreateStore(B.getInt32(sectionIds_.at(&op)), B.CreateGEP(i32Ty, sectionCalls_, sp));
  B.CreateStore(n, B.CreateGEP(dblTy, sectionLeft_, sp));
  B.CreateStore(B.CreateAdd(sp, B.getInt32(1)), sectionSp_);
  B.CreateBr(targetBlock(resolveTarget(op)));
  B.SetInsertPoint(sectionReturn(op));
}

// Where sections end: if the innermost active section is one of `calls`, count a repetition and
// run it again from its label, or pop it and continue after its call.
void Codegen::emitSectionEnd(const std::vector<const Op *> &calls) {
  Value *sp = B.CreateLoad(i32Ty, sectionSp_);
  BasicBlock *check = newBlock("section.check"), *cont = newBlock("section.cont");
  B.CreateCondBr(B.CreateICmpSGT(sp, B.getInt32(0)), check, cont);
  B.SetInsertPoint(check);
  Value *top = B.CreateSub(sp, B.getInt32(1));
  SwitchInst *sw = B.CreateSwitch(B.CreateLoad(i32Ty, B.CreateGEP(i32Ty, sectionCalls_, top)), cont);
  for (const Op *call : calls) {
    BasicBlock *bb = newBlock("section.end"), *done = newBlock("section.done");
    sw->addCase(B.getInt32(sectionIds_.at(call)), bb);
    B.SetInsertPoint(bb);
    Value *leftPtr = B.CreateGEP(dblTy, sectionLeft_, top);
    Value *left = B.CreateFSub(B.CreateLoad(dblTy, leftPtr), ConstantFP::get(dblTy, 1.0));
    B.CreateStore(left, leftPtr);
    emitTimeCheck(call->loc);
    B.CreateCondBr(B.CreateFCmpOGT(left, ConstantFP::get(dblTy, 0.0)), targetBlock(resolveTarget(*call)), done);
    B.SetInsertPoint(done);
    B.CreateStore(top, sectionSp_);
    B.CreateBr(sectionReturn(*call));
  }
  B.SetInsertPoint(cont);
}

BasicBlock *Codegen::sectionReturn(const Op &call) {
  BasicBlock *&bb = sectionRet_[&call];
  if (!bb) bb = newBlock("section.return");
  return bb;
}

void Codegen::emitOp(const Op &op) {
  switch (op.kind) {
  case OpKind::Assign: {
    const Expr *value = op.get("value");
    storeVar(*op.get("target"), value ? expr(*value) : Val{ConstantFP::get(dblTy, vacantValue()), true});
    return;
  }
  case OpKind::Declare: {  // the init value (or the type's initial value); arrays: every element
    const Expr *init = op.get("init"), &var = *op.get("var");
    const VarDecl *d = declOf(var);
    Val v = init ? expr(*init) : Val{ConstantFP::get(dblTy, initialValue(d ? d->type : ValueType::Real)), false};
    if (d && d->rank) {
      Value *c = convertFor(var, d, v);
      Value *base = var.space == ir::VarSpace::Global
                        ? B.CreateConstGEP1_64(dblTy, namedBase, globalNames_.size() + globalArrays_.at(var.str).offset)
                        : B.CreateConstGEP1_64(dblTy, localArrays, cur_->arrays.at(var.str).offset);
      B.CreateCall(fFill, {base, B.getInt64(d->size()), c});
      return;
    }
    storeVar(var, v);
    return;
  }
  case OpKind::If: emitIf(op); return;
  case OpKind::While:
  case OpKind::Loop: emitLoop(op); return;
  case OpKind::Break: B.CreateBr(loops_.back().brk); return;
  case OpKind::Continue: B.CreateBr(loops_.back().cont); return;
  case OpKind::Goto: emitGoto(op); return;
  case OpKind::Call: emitCall(op); return;
  case OpKind::CallSection: emitCallSection(op); return;
  case OpKind::ModalCall: emitModalCall(op); return;
  case OpKind::ModalTrigger: {  // the runtime runs the modal call as after a move (ncrt_modal_trigger)
    auto l = locArgs(op.loc);
    checkStatus(sinkCall(fModalTrigger, {ctxArg, l[0], l[1], l[2]}));
    return;
  }
  case OpKind::Return:
    if (const Expr *v = op.get("value"))
      B.CreateStore(expr(*v).v, B.CreateConstGEP1_32(dblTy, frameArg, cur_->frameSize - 1));
    emitReturn();
    return;
  default: return;  // rejected by validate()
  }
}

void Codegen::emitIf(const Op &op) {
  Value *c = truthy(expr(*op.get("cond")));
  BasicBlock *thenBB = newBlock("then"), *elseBB = op.regions.size() > 1 ? newBlock("else") : nullptr,
             *done = newBlock("endif");
  B.CreateCondBr(c, thenBB, elseBB ? elseBB : done);
  B.SetInsertPoint(thenBB);
  emitRegion(op.regions[0]);
  if (elseBB) {
    startBlock(done);  // closes the then branch
    B.SetInsertPoint(elseBB);
    emitRegion(op.regions[1]);
  }
  startBlock(done);
}

// while: enter (counter = 0) -> head: cond -> body -> latch -> head.
// loop:  enter, remaining = round(count) (-1 = endless) -> head: remaining == 0 ? exit :
//        (remaining > 0 ? remaining - 1) -> body -> latch -> head.
// The latch (also the target of continue) counts the iteration: reaching maxLoopIterations is
// the error, as in the eval engine.
void Codegen::emitLoop(const Op &op) {
  Value *counter = allocaEntry(i64Ty, "loop.count", B.getInt64(0));
  B.CreateStore(B.getInt64(0), counter);
  Value *remaining = nullptr;
  if (op.kind == OpKind::Loop) {
    remaining = allocaEntry(dblTy, "loop.remaining", ConstantFP::get(dblTy, 0.0));
    const Expr *count = op.get("count");
    B.CreateStore(count ? roundOf(numOf(expr(*count))) : ConstantFP::get(dblTy, -1.0), remaining);
  }
  BasicBlock *head = newBlock("loop.head"), *body = newBlock("loop.body"), *latch = newBlock("loop.latch"),
             *done = newBlock("loop.end");
  std::vector<KeptVar> kept = keepLoopVars(op);
  startBlock(head);
  if (remaining) {
    Value *r = B.CreateLoad(dblTy, remaining);
    BasicBlock *more = newBlock("loop.more");
    B.CreateCondBr(B.CreateFCmpOEQ(r, ConstantFP::get(dblTy, 0.0)), done, more);
    B.SetInsertPoint(more);
    Value *dec = B.CreateFSub(r, ConstantFP::get(dblTy, 1.0));
    B.CreateStore(B.CreateSelect(B.CreateFCmpOGT(r, ConstantFP::get(dblTy, 0.0)), dec, r), remaining);
    B.CreateBr(body);
  } else {
    B.CreateCondBr(truthy(expr(*op.get("cond"))), body, done);
  }
  B.SetInsertPoint(body);
  loops_.push_back({latch, done});
  emitRegion(op.regions[0]);
  loops_.pop_back();
  startBlock(latch);
  Value *n = B.CreateAdd(B.CreateLoad(i64Ty, counter), B.getInt64(1));
  B.CreateStore(n, counter);
  faultIf(B.CreateICmpUGE(n, maxLoop), op.loc, NCRT_FAULT_LOOP_LIMIT, "", nullptr);
  emitTimeCheck(op.loc);
  B.CreateBr(head);
  B.SetInsertPoint(done);
  releaseLoopVars(kept);
}

// A jump to `target`: a backward one counts toward the loop limit (per activation).
void Codegen::emitJumpTo(const Op &go, const Op *target) {
  if (order_[target] <= order_[&go]) emitBackJump(go.loc);
  B.CreateBr(targetBlock(target));
}

void Codegen::emitBackJump(SourceLoc loc) {
  Value *n = B.CreateAdd(B.CreateLoad(i64Ty, backJumps), B.getInt64(1));
  B.CreateStore(n, backJumps);
  faultIf(B.CreateICmpUGT(n, maxLoop), loc, NCRT_FAULT_BACKJUMP, "", nullptr);
  emitTimeCheck(loc);
}

// A computed goto: ncrt_jump searches the function's target table (ir/Jumps.h, as the eval
// engine does) and returns the entry's index, which a switch turns into its block.
void Codegen::emitGoto(const Op &go) {
  if (ir::constantJump(go)) {
    emitJumpTo(go, resolveTarget(go));  // validate() guarantees one
    return;
  }
  if (!jumpTable_) {
    auto *entryTy = StructType::get(C, {dblTy, ptrTy, i32Ty});
    std::vector<Constant *> rows;
    for (auto &e : jumps_)
      rows.push_back(ConstantStruct::get(entryTy, {ConstantFP::get(dblTy, e.n),
                                                   e.label ? cstring(e.label) : ConstantPointerNull::get(ptrTy),
                                                   B.getInt32(e.pos)}));
    auto *arrTy = ArrayType::get(entryTy, rows.size());
    jumpTable_ = new GlobalVariable(*M, arrTy, true, GlobalValue::PrivateLinkage, ConstantArray::get(arrTy, rows),
                                    "nc.jumps");
  }
  const Expr *l = go.get("label");
  Value *n = ConstantFP::get(dblTy, NAN);
  if (l) appendString(*l, false);
  else n = numOf(expr(*go.get("n")));
  auto loc = locArgs(go.loc);
  Value *index = B.CreateCall(fJump, {ctxArg, B.getInt32(l != nullptr), n, jumpTable_, B.getInt64(jumps_.size()),
                                      B.getInt32(order_.at(&go)), B.getInt32((uint32_t)ir::jumpDir(go)), loc[0], loc[1],
                                      loc[2]});
  // One backward check for the target found (its pos at or before the goto's), then a switch
  // that branches straight to the target blocks: a computed goto stays small in a long program.
  BasicBlock *found = newBlock("jump.found"), *back = newBlock("jump.back"), *go2 = newBlock("jump.go");
  B.CreateCondBr(B.CreateICmpSLT(index, B.getInt64(0)), failBB, found);
  B.SetInsertPoint(found);
  Value *pos = B.CreateLoad(i32Ty, B.CreateInBoundsGEP(jumpTable_->getValueType(), jumpTable_,
                                                         {B.getInt64(0), index, B.getInt32(2)}));
  B.CreateCondBr(B.CreateICmpULE(pos, B.getInt32(order_.at(&go))), back, go2);
  B.SetInsertPoint(back);
  emitBackJump(go.loc);
  B.CreateBr(go2);
  B.SetInsertPoint(go2);
  SwitchInst *sw = B.CreateSwitch(index, failBB, (unsigned)jumpOps_.size());
  for (size_t i = 0; i < jumpOps_.size(); ++i) sw->addCase(B.getInt64(i), targetBlock(jumpOps_[i]));
}

// The callee of a call or modal_call: a constant one as `fixed`, else `index` (into the
// module's functions) looked up at run time by ncrt_callee (an unknown one fails there).
bool Codegen::calleeOf(const Op &op, FnInfo *&fixed, Value *&index) {
  const Expr *callee = op.get("callee");
  fixed = nullptr;
  index = nullptr;
  if (callee && callee->kind == ExprKind::String) {
    const ir::Function *target = src_.find(callee->str);
    if (!target) {
      fail(op.loc, unknownProgramMessage(callee->str));
      return false;
    }
    fixed = &functions_.at(target->name);
  } else if (callee) {
    bool numeric = !callee->isStringExpr();
    Value *v = numeric ? expr(*callee).v : (stringValue(*callee), ConstantFP::get(dblTy, 0.0));
    if (!calleeNames) {
      std::vector<Constant *> names;
      for (auto &fn : src_.functions) names.push_back(cstring(fn.name));
      auto *arrTy = ArrayType::get(ptrTy, names.size());
      calleeNames = new GlobalVariable(*M, arrTy, true, GlobalValue::PrivateLinkage, ConstantArray::get(arrTy, names),
                                       "nc.functions");
    }
    auto loc = locArgs(op.loc);
    index = B.CreateCall(fCallee, {ctxArg, B.getInt32(numeric), v, calleeNames, B.getInt64(src_.functions.size()),
                                   loc[0], loc[1], loc[2]});
    BasicBlock *found = newBlock("callee.found");
    B.CreateCondBr(B.CreateICmpSLT(index, B.getInt64(0)), failBB, found);
    B.SetInsertPoint(found);
  } else {
    fail(op.loc, unknownProgramMessage("?"));
    return false;
  }
  return true;
}

// `body` llround(count) times (null count: once); NaN and counts below 1 run none. Each
// repetition checks the run-time limit (count=1e308 must not outlive --max-seconds).
void Codegen::emitRepeated(Value *count, SourceLoc loc, const std::function<void()> &body) {
  if (!count) {
    body();
    return;
  }
  Value *r = roundOf(count);
  Value *c = B.CreateSelect(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, 1.0)), r, ConstantFP::get(dblTy, 0.0));
  c = B.CreateSelect(B.CreateFCmpOGT(c, ConstantFP::get(dblTy, 0x1p62)), ConstantFP::get(dblTy, 0x1p62), c);
  Value *limit = B.CreateFPToSI(c, i64Ty);
  Value *counter = allocaEntry(i64Ty, "repeat.count");
  B.CreateStore(B.getInt64(0), counter);
  BasicBlock *head = newBlock("repeat.head"), *done = newBlock("repeat.end"), *bodyBB = newBlock("repeat.body");
  startBlock(head);
  Value *i = B.CreateLoad(i64Ty, counter);
  B.CreateCondBr(B.CreateICmpSLT(i, limit), bodyBB, done);
  B.SetInsertPoint(bodyBB);
  B.CreateStore(B.CreateAdd(i, B.getInt64(1)), counter);
  emitTimeCheck(loc);
  body();
  B.CreateBr(head);
  B.SetInsertPoint(done);
}

// A switch on a function index (into the module's functions) with `body` emitted for each of
// `fns`; other indices fail. Continues after the switch.
void Codegen::switchOnFunction(Value *index, const std::vector<FnInfo *> &fns, const std::function<void(FnInfo &)> &body) {
  BasicBlock *joined = newBlock("fn.joined");
  SwitchInst *sw = B.CreateSwitch(index, failBB, (unsigned)fns.size());
  for (FnInfo *fi : fns) {
    BasicBlock *bb = newBlock("fn.case");
    sw->addCase(B.getInt64(functionIndex(*fi)), bb);
    B.SetInsertPoint(bb);
    body(*fi);
    B.CreateBr(joined);
  }
  B.SetInsertPoint(joined);
}

std::vector<FnInfo *> Codegen::allFunctions() {
  std::vector<FnInfo *> out;
  for (auto &fn : src_.functions) out.push_back(&functions_.at(fn.name));
  return out;
}

// modal_call (docs/IR.md §5.5): the callee's index and every argument slot of the module's
// modal calls go to module globals (a slot this op does not set: vacant for #n, unset for a
// named parameter, so its default applies). Named arguments convert for the callee now.
void Codegen::emitModalCall(const Op &op) {
  if (!op.get("callee")) {
    B.CreateStore(B.getInt64(-1), modalFn_);
    return;
  }
  FnInfo *fixed = nullptr;
  Value *index = nullptr;
  if (!calleeOf(op, fixed, index)) return;
  const Expr *countE = op.get("count");  // calls per move (Fanuc G66 L)
  B.CreateStore(countE ? numOf(expr(*countE)) : ConstantFP::get(dblTy, 1.0), modalCount_);
  std::vector<std::pair<std::string, Val>> args;
  for (auto &a : op.args)
    if (a.key.rfind("a.", 0) == 0 && a.value) {
      std::string k = a.key.substr(2);
      Val v = expr(*a.value);
      if (numberedKey(k)) checkNotHandle(v, op.loc, HandleUse::InParameter);
      else if (fixed) v = {convertArg(*fixed, k, v, op.loc), false};
      args.push_back({k, v});
    }
  auto store = [&](FnInfo *fi) {  // every slot, converted for `fi` when the callee is computed
    Constant *vac = ConstantFP::get(dblTy, vacantValue());
    Constant *unset = ConstantExpr::getBitCast(ConstantInt::get(i64Ty, NCRT_UNSET_BITS), dblTy);
    for (auto &[k, slot] : modalKeys_) {
      Value *v = numberedKey(k) ? vac : unset;
      for (auto &[ak, av] : args)
        if (ak == k) v = fi && !numberedKey(k) ? convertArg(*fi, k, {av.v, true, true, op.loc}, op.loc) : av.v;
      B.CreateStore(v, B.CreateConstGEP2_64(modalArgs_->getValueType(), modalArgs_, 0, slot));
    }
  };
  if (fixed) {
    store(nullptr);
    B.CreateStore(B.getInt64(functionIndex(*fixed)), modalFn_);
    return;
  }
  switchOnFunction(index, allFunctions(), [&](FnInfo &fi) { store(&fi); });
  B.CreateStore(index, modalFn_);
}

// After a move: the modal callee, if one is set and none is running, in a new frame with the
// stored arguments (as the eval engine's runModal).
// After a move: the modal callee, if one is set and none is running, in a new frame with the
// stored arguments (as the eval engine's runModal). One function per module, which the runtime
// calls after each move command (ncrt_set_modal_hook), so moves stay in constant runs:
// i32 @nc.modal.run(ctx, storage, file, line, col), the move's location as arguments (locArgs
// reads them while this is emitted).
void Codegen::emitModalRun() {
  modalRun_ = Function::Create(FunctionType::get(i32Ty, {ptrTy, ptrTy, i32Ty, i32Ty, i32Ty}, false),
                               GlobalValue::InternalLinkage, "nc.modal.run", M.get());
  F = modalRun_;
  ctxArg = F->getArg(0);
  stArg = F->getArg(1);
  frameArg = nullptr;  // the modal callee always gets a new frame
  blkOn_ = false;      // no blocks of its own
  dynLoc_ = {F->getArg(2), F->getArg(3), F->getArg(4)};
  entryBB = newBlock("entry");
  B.SetInsertPoint(entryBB);
  depthPtr = B.CreateStructGEP(storageTy, stArg, 6);
  pollPtr = B.CreateStructGEP(storageTy, stArg, 7);
  startBody();
  SourceLoc loc;  // unused: dynLoc_
  BasicBlock *run = newBlock("modal.run"), *none = newBlock("modal.none");
  B.CreateCondBr(B.CreateAnd(B.CreateICmpSGE(B.CreateLoad(i64Ty, modalFn_), B.getInt64(0)),
                             B.CreateICmpEQ(B.CreateLoad(i32Ty, modalIn_), B.getInt32(0))),
                 run, none);
  B.SetInsertPoint(none);
  B.CreateRet(B.getInt32(NCRT_OK));
  B.SetInsertPoint(run);
  Value *depth = B.CreateLoad(i32Ty, depthPtr);
  Value *maxDepth = B.CreateLoad(i32Ty, B.CreateStructGEP(storageTy, stArg, 5));
  faultIf(B.CreateICmpUGE(depth, maxDepth), loc, NCRT_FAULT_CALL_DEPTH, "", nullptr);
  B.CreateStore(B.CreateAdd(depth, B.getInt32(1)), depthPtr);
  B.CreateStore(B.getInt32(1), modalIn_);
  Value *fn = B.CreateLoad(i64Ty, modalFn_);
  emitRepeated(B.CreateLoad(dblTy, modalCount_), loc, [&] {
    switchOnFunction(fn, modalCallees_, [&](FnInfo &fi) {
      std::vector<std::pair<std::string, Value *>> args;
      for (auto &[k, slot] : modalKeys_)
        args.push_back({k, B.CreateLoad(dblTy, B.CreateConstGEP2_64(modalArgs_->getValueType(), modalArgs_, 0, slot))});
      emitInvoke(fi, args, true, loc);
    });
  });
  B.CreateStore(B.getInt32(0), modalIn_);
  B.CreateStore(depth, depthPtr);
  B.CreateRet(B.getInt32(NCRT_OK));
  EliminateUnreachableBlocks(*F);  // an unused exit (and its block flush), dead blocks
  dynLoc_.clear();
}

// call callee=<name> count=<n>? frame=new|shared a.<key>=<expr>...: count and arguments are
// evaluated once in the caller; frame=new gives each repetition fresh #1..#33 holding the
// numbered arguments (and the callee's named locals that are named arguments); otherwise
// (shared, the default) the callee works on the caller's #1..#33. Named locals are per call.
// A computed callee (a string expression, or a number meaning O<n>) is looked up at run time
// by ncrt_callee and dispatched by a switch over the module's functions.
void Codegen::emitCall(const Op &op) {
  FnInfo *fixed = nullptr;
  Value *index = nullptr;
  if (!calleeOf(op, fixed, index)) return;
  const Expr *countE = op.get("count");
  Value *count = countE ? numOf(expr(*countE)) : nullptr;
  const Expr *frameE = op.get("frame");
  bool newFrame = frameE && frameE->str == "new";
  Value *depth = B.CreateLoad(i32Ty, depthPtr);
  Value *maxDepth = B.CreateLoad(i32Ty, B.CreateStructGEP(storageTy, stArg, 5));
  faultIf(B.CreateICmpUGE(depth, maxDepth), op.loc, NCRT_FAULT_CALL_DEPTH, "", nullptr);
  const Expr *result = op.get("result");
  Value *ret = nullptr;  // the last repetition's return value
  if (result) {
    ret = allocaEntry(dblTy, "call.ret");
    B.CreateStore(ConstantExpr::getBitCast(ConstantInt::get(i64Ty, NCRT_UNSET_BITS), dblTy), ret);
  }
  // The arguments for callee `fi`, evaluated once: a VAR parameter gets the address of the
  // caller's variable (in the frame slot's bits), a typed one the converted value
  // (ir/Strings.h convertForStore).
  auto argsFor = [&](FnInfo &fi) {
    std::vector<std::pair<std::string, Value *>> args;  // key after "a.", value
    for (auto &a : op.args)
      if (a.key.rfind("a.", 0) == 0 && a.value) {
        std::string k = a.key.substr(2);
        if (const ir::Param *p = fi.fn->param(k); p && p->byRef) {
          args.push_back({k, B.CreateBitCast(B.CreatePtrToInt(varPtr(*a.value, true), i64Ty), dblTy)});
          continue;
        }
        Val v = expr(*a.value);
        if (numberedKey(k)) checkNotHandle(v, op.loc, HandleUse::InParameter);
        else v.v = convertArg(fi, k, v, op.loc);
        args.push_back({k, v.v});
      }
    B.CreateStore(B.CreateAdd(depth, B.getInt32(1)), depthPtr);
    return args;
  };
  auto invoke = [&](FnInfo &fi) {
    auto args = argsFor(fi);
    emitRepeated(count, op.loc, [&] {
      Value *r = emitInvoke(fi, args, newFrame, op.loc);
      if (ret) B.CreateStore(r, ret);
    });
  };
  // A computed callee: one branch per function of the module, each with its own argument
  // passing (by value or VAR, its parameters' types).
  if (fixed) invoke(*fixed);
  else switchOnFunction(index, allFunctions(), invoke);
  B.CreateStore(depth, depthPtr);
  if (result) {
    Value *r = B.CreateLoad(dblTy, ret);
    failIf(B.CreateICmpEQ(B.CreateBitCast(r, i64Ty), ConstantInt::get(i64Ty, NCRT_UNSET_BITS)), op.loc,
           noReturnValueMessage());
    storeVar(*result, {r, true, true, op.loc});
  }
}

// An argument for the named parameter `key` of `fi`, converted when the parameter is typed.
Value *Codegen::convertArg(FnInfo &fi, const std::string &key, Val v, SourceLoc loc) {
  const VarDecl *d = decls_.find(*fi.fn, ir::VarSpace::Local, key);
  if (!d) return v.v;
  ir::Expr param;
  param.kind = ExprKind::Var;
  param.str = key;
  param.loc = loc;
  return convertFor(param, d, v);
}

// One activation of `fi` with the caller's evaluated arguments.
Value *Codegen::emitInvoke(FnInfo &fi, const std::vector<std::pair<std::string, Value *>> &args, bool newFrame,
                           SourceLoc loc) {
  if (fi.fn->save) checkStatus(sinkCall(fSaveModal, {ctxArg}));  // SAVE (docs/IR.md §5.4)
  Value *frame = allocaEntry(ArrayType::get(dblTy, fi.frameSize), "callee.frame");
  const uint64_t localsBytes = (kFrameLocals + 1) * sizeof(double);
  if (newFrame) {
    initFrame(frame, fi.frameSize, 0);
    for (auto &[k, v] : args) {
      unsigned slot = 0;
      if (!k.empty() && k[0] >= '0' && k[0] <= '9') {
        long n = std::atol(k.c_str());
        if (n >= 1 && n <= kFrameLocals) slot = (unsigned)n;
      } else if (auto it = fi.locals.find(k); it != fi.locals.end()) {
        slot = (unsigned)(kFrameLocals + 1 + it->second);
      }
      if (slot) B.CreateStore(v, B.CreateConstGEP1_32(dblTy, frame, slot));
    }
  } else {
    B.CreateMemCpy(frame, MaybeAlign(8), frameArg, MaybeAlign(8), localsBytes);
    initFrame(frame, fi.frameSize, kFrameLocals + 1);
  }
  Value *st = sinkCall(fi.F, {ctxArg, stArg, frame});
  checkStatus(st);
  if (!newFrame) B.CreateMemCpy(frameArg, MaybeAlign(8), frame, MaybeAlign(8), localsBytes);
  if (fi.fn->save) {
    auto l = locArgs(loc);
    checkStatus(sinkCall(fRestoreModal, {ctxArg, l[0], l[1], l[2]}));
  }
  return B.CreateLoad(dblTy, B.CreateConstGEP1_32(dblTy, frame, fi.frameSize - 1));
}

}  // namespace ncc::jit
