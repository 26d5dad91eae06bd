// NC IR -> LLVM IR: statements and control flow (if, while, loop, goto, call).
#include "backends/jit/CodegenImpl.h"

#include "ir/Arith.h"
#include "runtime/ncrt.h"

#include <cmath>
#include <set>

namespace ncc::jit {

using namespace llvm;
using ir::Expr;
using ir::ExprKind;
using ir::Op;
using ir::OpKind;

static const Expr *literalGotoN(const Op &go) {
  const Expr *n = go.get("n");
  return n && n->kind == ExprKind::Number ? n : nullptr;
}
static const std::string *gotoLabel(const Op &go) {
  const Expr *l = go.get("label");
  return l && (l->kind == ExprKind::String || l->kind == ExprKind::Symbol) ? &l->str : nullptr;
}

// Numbers every op in pre-order and records block numbers and labels, then marks the ops that
// gotos can reach: those need a basic block of their own (and end a constant run).
void Codegen::scanTargets(const ir::Region &body) {
  std::vector<const Op *> gotos;
  auto walk = [&](auto &self, const ir::Region &r) -> void {
    for (auto &op : r) {
      order_[&op] = (unsigned)order_.size();
      if (op.kind == OpKind::Block)
        if (const Expr *n = op.get("n"); n && n->kind == ExprKind::Number)
          blocks_.push_back({(int64_t)std::llround(n->num), &op});
      if (op.kind == OpKind::Label)
        if (const Expr *l = op.get("name"); l && (l->kind == ExprKind::String || l->kind == ExprKind::Symbol))
          labels_.push_back({l->str, &op});
      if (op.kind == OpKind::Goto) gotos.push_back(&op);
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  walk(walk, body);
  for (const Op *go : gotos) {
    const Expr *n = literalGotoN(*go);
    const std::string *label = gotoLabel(*go);
    if (!n && !label) {
      dynamicGoto_ = true;
      continue;
    }
    if (const Op *t = resolveTarget(order_[go], *go, n ? std::llround(n->num) : 0, label)) targetBBs_[t] = nullptr;
  }
  if (dynamicGoto_)
    for (auto &b : blocks_) targetBBs_[b.second] = nullptr;
}

// Fanuc search order: forward from the goto, then from the start of the function.
const Op *Codegen::resolveTarget(unsigned from, const Op &go, int64_t n, const std::string *label) {
  std::string dir = "any";
  if (const Expr *d = go.get("dir"); d && (d->kind == ExprKind::Symbol || d->kind == ExprKind::String)) dir = d->str;
  auto search = [&](bool after) -> const Op * {
    if (label) {
      for (auto &l : labels_)
        if (l.first == *label && (order_[l.second] > from) == after) return l.second;
    } else {
      for (auto &b : blocks_)
        if (b.first == n && (order_[b.second] > from) == after) return b.second;
    }
    return nullptr;
  };
  const Op *t = nullptr;
  if (dir != "backward") t = search(true);
  if (!t && dir != "forward") t = search(false);
  return t;
}

BasicBlock *Codegen::targetBlock(const Op *op) {
  BasicBlock *&bb = targetBBs_[op];
  if (!bb) bb = newBlock(op->kind == OpKind::Label ? "label" : "block");
  return bb;
}

void Codegen::emitJump(const Op &go, const Op *target) {
  if (order_[target] < order_[&go]) emitIterationCheck(gotoCounter, go.loc);
  B.CreateBr(targetBlock(target));
}

void Codegen::emitRegion(const ir::Region &r) {
  for (auto &op : r) {
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
}

void Codegen::emitOp(const Op &op) {
  switch (op.kind) {
  case OpKind::Assign: {
    const Expr *target = op.get("target"), *value = op.get("value");
    if (!target || !value || target->kind != ExprKind::Var) {
      diags_.error(op.loc, "assign needs a variable target and a value");
      failed_ = true;
      return;
    }
    Val v = expr(*value);
    storeVar(*target, v.v);
    return;
  }
  case OpKind::Declare: {
    const Expr *var = op.get("var");
    if (!var || var->kind != ExprKind::Var) {
      diags_.error(op.loc, "declare needs a variable");
      failed_ = true;
      return;
    }
    const Expr *init = op.get("init");
    storeVar(*var, init ? expr(*init).v : ConstantFP::get(dblTy, 0.0));
    return;
  }
  case OpKind::If: emitIf(op); return;
  case OpKind::While: emitWhile(op); return;
  case OpKind::Loop: emitLoop(op); return;
  case OpKind::Break:
  case OpKind::Continue:
    if (loops_.empty()) {
      diags_.error(op.loc, std::string(ir::opInfo(op.kind).name) + " outside a loop");
      failed_ = true;
      return;
    }
    B.CreateBr(op.kind == OpKind::Break ? loops_.back().brk : loops_.back().cont);
    return;
  case OpKind::Goto: emitGoto(op); return;
  case OpKind::Call: emitCall(op); return;
  case OpKind::Return: B.CreateRet(B.getInt32(NCRT_OK)); return;
  default:
    diags_.error(op.loc, std::string("the JIT does not support '") + ir::opInfo(op.kind).name + "'");
    failed_ = true;
    return;
  }
}

void Codegen::emitIf(const Op &op) {
  const Expr *cond = op.get("cond");
  if (!cond || op.regions.empty()) {
    diags_.error(op.loc, "if needs cond and a then region");
    failed_ = true;
    return;
  }
  Value *c = truthy(expr(*cond));
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

void Codegen::emitWhile(const Op &op) {
  const Expr *cond = op.get("cond");
  if (!cond || op.regions.empty()) {
    diags_.error(op.loc, "while needs cond and a body");
    failed_ = true;
    return;
  }
  Value *counter = allocaEntry(i64Ty, "while.count");
  B.CreateStore(B.getInt64(0), counter);
  BasicBlock *condBB = newBlock("while.cond"), *bodyBB = newBlock("while.body"), *done = newBlock("while.end");
  startBlock(condBB);
  B.CreateCondBr(truthy(expr(*cond)), bodyBB, done);
  B.SetInsertPoint(bodyBB);
  emitIterationCheck(counter, op.loc);
  loops_.push_back({condBB, done});
  emitRegion(op.regions[0]);
  loops_.pop_back();
  startBlock(condBB);
  B.SetInsertPoint(done);
}

// Repeat count: rounded like an index, clamped so the conversion to an integer is defined;
// NaN and counts below 1 run nothing.
static Value *repeatCount(IRBuilder<> &B, Value *rounded) {
  Type *dbl = rounded->getType();
  Value *c = B.CreateSelect(B.CreateFCmpOGE(rounded, ConstantFP::get(dbl, 0.0)), rounded, ConstantFP::get(dbl, 0.0));
  c = B.CreateSelect(B.CreateFCmpOGT(c, ConstantFP::get(dbl, 0x1p62)), ConstantFP::get(dbl, 0x1p62), c);
  return B.CreateFPToSI(c, B.getInt64Ty());
}

void Codegen::emitLoop(const Op &op) {
  if (op.regions.empty()) {
    diags_.error(op.loc, "loop needs a body");
    failed_ = true;
    return;
  }
  Value *limit = nullptr;
  if (const Expr *count = op.get("count")) limit = repeatCount(B, roundIndex(expr(*count)));
  Value *counter = allocaEntry(i64Ty, "loop.count");
  B.CreateStore(B.getInt64(0), counter);
  BasicBlock *condBB = newBlock("loop.cond"), *bodyBB = newBlock("loop.body"), *done = newBlock("loop.end");
  startBlock(condBB);
  if (limit)
    B.CreateCondBr(B.CreateICmpSLT(B.CreateLoad(i64Ty, counter), limit), bodyBB, done);
  else
    B.CreateBr(bodyBB);  // endless until break/goto/return or the iteration limit
  B.SetInsertPoint(bodyBB);
  emitIterationCheck(counter, op.loc);
  loops_.push_back({condBB, done});
  emitRegion(op.regions[0]);
  loops_.pop_back();
  startBlock(condBB);
  B.SetInsertPoint(done);
}

void Codegen::emitGoto(const Op &go) {
  unsigned from = order_[&go];
  const Expr *n = literalGotoN(go);
  const std::string *label = gotoLabel(go);
  if (label || n) {
    int64_t num = n ? std::llround(n->num) : 0;
    if (const Op *t = resolveTarget(from, go, num, label)) {
      emitJump(go, t);
    } else if (label) {
      failIf(B.getTrue(), go.loc, "goto target '" + *label + "' not found");
      B.CreateBr(failBB);
    } else {
      faultIf(B.getTrue(), go.loc, NCRT_FAULT_GOTO_TARGET, "", ConstantFP::get(dblTy, (double)num));
      B.CreateBr(failBB);
    }
    return;
  }
  const Expr *dyn = go.get("n");
  if (!dyn) {
    diags_.error(go.loc, "goto needs n or label");
    failed_ = true;
    return;
  }
  // Computed goto: a switch over the function's block numbers, each resolved from here.
  Value *r = roundIndex(expr(*dyn));
  Value *inRange = B.CreateAnd(B.CreateFCmpOGE(r, ConstantFP::get(dblTy, -0x1p62)),
                               B.CreateFCmpOLE(r, ConstantFP::get(dblTy, 0x1p62)));
  Value *key = B.CreateFPToSI(B.CreateSelect(inRange, r, ConstantFP::get(dblTy, -0x1p63)), i64Ty);
  BasicBlock *missing = newBlock("goto.missing");
  SwitchInst *sw = B.CreateSwitch(key, missing);
  std::set<int64_t> seen;
  for (auto &b : blocks_) {
    if (!seen.insert(b.first).second) continue;
    const Op *t = resolveTarget(from, go, b.first, nullptr);
    BasicBlock *caseBB = newBlock("goto.case");
    sw->addCase(B.getInt64((uint64_t)b.first), caseBB);
    B.SetInsertPoint(caseBB);
    emitJump(go, t);
  }
  B.SetInsertPoint(missing);
  faultIf(B.getTrue(), go.loc, NCRT_FAULT_GOTO_TARGET, "", r);
  B.CreateBr(failBB);
}

// call callee=<name> count=<int>? frame=new|shared a.<n>=<expr>...: arguments are evaluated
// once in the caller; each repetition gets a fresh frame (frame=new) holding them.
void Codegen::emitCall(const Op &op) {
  const Expr *callee = op.get("callee");
  const ir::Function *target = nullptr;
  if (callee && (callee->kind == ExprKind::String || callee->kind == ExprKind::Symbol))
    target = src_.find(callee->str);
  if (!target) {
    diags_.error(op.loc, "call to unknown function" + (callee ? " '" + callee->str + "'" : std::string()));
    failed_ = true;
    return;
  }
  bool shared = false;
  if (const Expr *fr = op.get("frame"); fr && (fr->kind == ExprKind::Symbol || fr->kind == ExprKind::String)) {
    if (fr->str != "new" && fr->str != "shared") {
      diags_.error(op.loc, "frame must be new or shared");
      failed_ = true;
      return;
    }
    shared = fr->str == "shared";
  }
  std::vector<std::pair<unsigned, Value *>> args;  // frame slot, value
  std::set<std::string> given;
  for (auto &a : op.args) {
    if (a.key.size() <= 2 || a.key.compare(0, 2, "a.") != 0 || !a.value) continue;
    std::string name = a.key.substr(2);
    given.insert(name);
    unsigned slot;
    if (std::isdigit((unsigned char)name[0])) {
      long n = std::strtol(name.c_str(), nullptr, 10);
      if (n < 1 || n > kFrameLocals) {
        diags_.error(op.loc, "call argument '" + a.key + "' is not a local #1..#33");
        failed_ = true;
        return;
      }
      slot = (unsigned)n;
    } else {
      slot = (unsigned)(kFrameLocals + 1 + localNames_.at(name));
    }
    args.push_back({slot, expr(*a.value).v});
  }
  for (auto &p : target->params)
    if (!given.count(p.name) && p.defaultValue)
      args.push_back({(unsigned)(kFrameLocals + 1 + localNames_.at(p.name)), expr(*p.defaultValue).v});
  Value *limit = nullptr;
  if (const Expr *count = op.get("count")) limit = repeatCount(B, roundIndex(expr(*count)));

  Value *counter = nullptr;
  BasicBlock *condBB = nullptr, *done = nullptr;
  if (limit) {
    counter = allocaEntry(i64Ty, "call.count");
    B.CreateStore(B.getInt64(0), counter);
    condBB = newBlock("call.cond");
    done = newBlock("call.end");
    BasicBlock *body = newBlock("call.body");
    startBlock(condBB);
    Value *i = B.CreateLoad(i64Ty, counter);
    B.CreateCondBr(B.CreateICmpSLT(i, limit), body, done);
    B.SetInsertPoint(body);
    B.CreateStore(B.CreateAdd(i, B.getInt64(1)), counter);
  }
  Value *depth = B.CreateLoad(i32Ty, depthPtr);
  Value *maxDepth = B.CreateLoad(i32Ty, B.CreateStructGEP(storageTy, stArg, 5));
  faultIf(B.CreateICmpUGE(depth, maxDepth), op.loc, NCRT_FAULT_CALL_DEPTH, "", nullptr);
  B.CreateStore(B.CreateAdd(depth, B.getInt32(1)), depthPtr);
  Value *frame = frameArg;
  if (!shared) {
    if (!calleeFrame) calleeFrame = allocaEntry(ArrayType::get(dblTy, frameSize_), "callee.frame");
    frame = calleeFrame;
    initFrame(frame);
  }
  for (auto &a : args) B.CreateStore(a.second, B.CreateConstGEP1_32(dblTy, frame, a.first));
  Value *st = B.CreateCall(functions_.at(target->name), {ctxArg, stArg, frame});
  B.CreateStore(depth, depthPtr);
  checkStatus(st);
  if (limit) {
    B.CreateBr(condBB);
    B.SetInsertPoint(done);
  }
}

}  // namespace ncc::jit
