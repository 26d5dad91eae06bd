#include "passes/EvalCode.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::eval {

namespace {
[[noreturn]] void fail(SourceLoc loc, std::string msg) { throw EvalError{loc, std::move(msg)}; }

struct LoopCtx {
  std::vector<uint32_t> breaks, continues;
};
struct Fixup {
  uint32_t instr;
  const Op *op;
};

void compileRegion(CompiledFn &cf, const Region &r, std::vector<LoopCtx> &loops, std::vector<Fixup> &gotos,
                   Diagnostics &diags) {
  auto emit = [&](Instr in) {
    cf.code.push_back(in);
    return (uint32_t)cf.code.size() - 1;
  };
  auto sectionEnd = [&](const std::vector<const Op *> *calls) {
    Instr in{IK::SectionEnd};
    in.calls = calls;
    if (calls) emit(in);
  };
  for (const Op &op : r) {
    sectionEnd(cf.sectionEnds.endingBefore(op));
    if (isMachineOp(op.kind)) {
      CmdTemplate t;
      if (!buildCmdTemplate(op, t, diags)) fail(op.loc, "invalid machine operation");
      if (op.kind == OpKind::Block && t.base.blockNumber >= 0)
        cf.jumps.push_back({(double)t.base.blockNumber, nullptr, (uint32_t)cf.code.size()});
      Instr in{IK::Machine};
      in.slot = (uint32_t)cf.templates.size();
      in.op = &op;
      cf.templates.push_back(std::move(t));
      emit(in);
      continue;
    }
    switch (op.kind) {
    case OpKind::Assign:
    case OpKind::Declare: {
      Instr in{op.kind == OpKind::Assign ? IK::Assign : IK::Declare};
      in.op = &op;
      in.target = op.get(op.kind == OpKind::Assign ? "target" : "var");
      in.expr = op.get(op.kind == OpKind::Assign ? "value" : "init");
      if (!in.target || in.target->kind != ExprKind::Var) fail(op.loc, "assignment target is not a variable");
      if (in.target->space == VarSpace::Local && in.target->args.empty()) localSlot(cf, in.target->str);
      emit(in);
      break;
    }
    case OpKind::If: {
      Instr jf{IK::JumpIfFalse};
      jf.expr = op.get("cond");
      jf.op = &op;
      uint32_t j = emit(jf);
      compileRegion(cf, op.regions[0], loops, gotos, diags);
      if (op.regions.size() > 1) {
        uint32_t skip = emit(Instr{IK::Jump});
        cf.code[j].jump = (uint32_t)cf.code.size();
        compileRegion(cf, op.regions[1], loops, gotos, diags);
        cf.code[skip].jump = (uint32_t)cf.code.size();
      } else {
        cf.code[j].jump = (uint32_t)cf.code.size();
      }
      break;
    }
    case OpKind::While:
    case OpKind::Loop: {
      uint32_t slot = cf.slots;
      cf.slots += 2;
      Instr enter{IK::LoopEnter};
      enter.slot = slot;
      enter.op = &op;
      emit(enter);
      uint32_t test;
      if (op.kind == OpKind::While) {
        Instr jf{IK::JumpIfFalse};
        jf.expr = op.get("cond");
        jf.op = &op;
        test = emit(jf);
      } else {
        Instr init{IK::CountInit};
        init.slot = slot + 1;
        init.expr = op.get("count");
        init.op = &op;
        emit(init);
        Instr t{IK::CountTest};
        t.slot = slot + 1;
        t.op = &op;
        test = emit(t);
      }
      uint32_t head = test;
      loops.emplace_back();
      compileRegion(cf, op.regions[0], loops, gotos, diags);
      uint32_t back = (uint32_t)cf.code.size();
      Instr lb{IK::LoopBack};
      lb.slot = slot;
      lb.jump = head;
      lb.op = &op;
      emit(lb);
      uint32_t end = (uint32_t)cf.code.size();
      cf.code[test].jump = end;
      for (uint32_t b : loops.back().breaks) cf.code[b].jump = end;
      for (uint32_t c : loops.back().continues) cf.code[c].jump = back;
      loops.pop_back();
      break;
    }
    case OpKind::Break:
    case OpKind::Continue: {
      if (loops.empty()) fail(op.loc, fmt::format("'{}' outside a loop", opInfo(op.kind).name));
      uint32_t i = emit(Instr{IK::Jump});
      (op.kind == OpKind::Break ? loops.back().breaks : loops.back().continues).push_back(i);
      break;
    }
    case OpKind::Label:
      if (const Expr *e = op.get("name")) cf.jumps.push_back({NAN, e->str.c_str(), (uint32_t)cf.code.size()});
      break;
    case OpKind::Goto: {
      const Expr *n = op.get("n");
      Instr j{constantJump(op) ? IK::Jump : IK::JumpComputed};
      j.op = &op;
      j.expr = n ? n : op.get("label");
      uint32_t i = emit(j);
      if (j.kind == IK::Jump) gotos.push_back({i, &op});
      break;
    }
    case OpKind::Call:
    case OpKind::Return:
    case OpKind::ModalCall:
    case OpKind::ModalTrigger: {  // the op is all they need
      Instr c{op.kind == OpKind::Call     ? IK::Call
              : op.kind == OpKind::Return ? IK::Return
              : op.kind == OpKind::ModalCall ? IK::ModalCall
                                             : IK::ModalTrigger};
      c.op = &op;
      emit(c);
      break;
    }
    case OpKind::CallSection: {
      Instr c{IK::SectionCall};
      c.op = &op;
      c.expr = op.get("count");
      gotos.push_back({emit(c), &op});  // `from` resolves like a goto's label
      break;
    }
    default:
      fail(op.loc, fmt::format("the eval engine cannot execute '{}'", opInfo(op.kind).name));
    }
  }
  sectionEnd(cf.sectionEnds.endingAt(r));
}

}  // namespace

uint32_t localSlot(CompiledFn &cf, const std::string &name) {
  auto it = (*cf.names).find(name);
  if (it != (*cf.names).end()) return it->second;
  uint32_t s = (uint32_t)(*cf.names).size();
  (*cf.names).emplace(name, s);
  return s;
}

void linearize(const Function &f, CompiledFn &cf, Diagnostics &diags) {
  cf.fn = &f;
  std::vector<LoopCtx> loops;
  std::vector<Fixup> gotos;
  for (auto &p : f.params) localSlot(cf, p.name);
  cf.sectionEnds = sectionEnds(f);
  compileRegion(cf, f.body, loops, gotos, diags);
  cf.code.push_back(Instr{IK::Return});
  // Constant targets resolve now (ir/Jumps.h); a missing one fails the function's first call.
  for (auto &g : gotos) {
    const Expr *l = g.op->get(g.op->kind == OpKind::CallSection ? "from" : "label");
    double n = l ? NAN : g.op->get("n")->num;
    int64_t t = findJump(cf.jumps.data(), cf.jumps.size(), l, n, l ? l->str : "", g.instr, jumpDir(*g.op));
    if (t < 0) fail(g.op->loc, missingJumpMessage(l, n, l ? l->str : ""));
    cf.code[g.instr].jump = cf.jumps[t].pos;
    cf.code[g.instr].backward = cf.jumps[t].pos <= g.instr;
  }
}

}  // namespace ncc::eval
