// What the calls of a whole ISO program need once every program of it is known
// (parseIsoProgram): the 808D call context only where a callee reads it, the caller's side of
// M99 P<n>, and the start-up values of the globals the lowered calls use (LowerCalls.cpp).
#include "frontend/iso/Lower.h"

#include <fmt/format.h>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace ncc::iso {

using ir::Expr, ir::ExprPtr, ir::Op, ir::OpKind, ir::Region;

namespace {

void eachExpr(const Expr &e, const std::function<void(const Expr &)> &f) {
  f(e);
  for (auto &a : e.args)
    if (a) eachExpr(*a, f);
}

void eachOp(Region &r, const std::function<void(Op &)> &f) {
  for (auto &op : r) {
    f(op);
    for (auto &sub : op.regions) eachOp(sub, f);
  }
}

bool isVar(const Expr &e, ir::VarSpace space, const char *name) {
  return e.kind == ir::ExprKind::Var && e.space == space && e.str == name;
}

// The names of the Local variables `f` reads.
std::set<std::string> localsRead(ir::Function &f) {
  std::set<std::string> out;
  eachOp(f.body, [&](Op &op) {
    for (auto &a : op.args)
      if (a.value) eachExpr(*a.value, [&](const Expr &e) {
          if (e.kind == ir::ExprKind::Var && e.space == ir::VarSpace::Local) out.insert(e.str);
        });
  });
  return out;
}

const std::string *constCallee(const Op &op) {
  const Expr *c = op.get("callee");
  return c && c->kind == ir::ExprKind::String ? &c->str : nullptr;
}

Op globalAssign(const char *name, ExprPtr value, SourceLoc loc) {
  Op op(OpKind::Assign, loc);
  op.set("target", Expr::var(ir::VarSpace::Global, name, nullptr, loc));
  op.set("value", std::move(value));
  return op;
}

// After a call of a program with M99 P: `if %%_m99_block <> 0 { go to that block }`, searched
// forward from the call, then from the start (ir/Jumps.h dir=any), as the 808D does.
Op resumeAt(SourceLoc loc) {
  auto var = [&](const char *n) { return Expr::var(ir::VarSpace::Global, n, nullptr, loc); };
  Op check(OpKind::If, loc);
  check.set("cond", Expr::binary(ir::OpCode::Ne, var(BlockLowerer::kM99Block), Expr::number(0, ir::Type::Int, loc), loc));
  check.regions.emplace_back();
  Region &r = check.regions[0];
  r.push_back(globalAssign(BlockLowerer::kM99Target, var(BlockLowerer::kM99Block), loc));
  r.push_back(globalAssign(BlockLowerer::kM99Block, Expr::number(0, ir::Type::Int, loc), loc));
  Op go(OpKind::Goto, loc);
  go.set("n", var(BlockLowerer::kM99Target));
  r.push_back(std::move(go));
  return check;
}

}  // namespace

bool finishCalls(ir::Module &m, Diagnostics &diags) {
  bool ok = true;
  std::map<std::string, std::set<std::string>> reads;  // function -> Locals it reads
  std::set<std::string> resumers;                       // functions with M99 P
  bool byCode = false, restart = false;
  for (auto &f : m.functions) {
    reads[f.name] = localsRead(f);
    eachOp(f.body, [&](Op &op) {
      for (auto &a : op.args)
        if (a.value) eachExpr(*a.value, [&](const Expr &e) {
            byCode |= isVar(e, ir::VarSpace::Global, BlockLowerer::kByCodeFlag);
            if (isVar(e, ir::VarSpace::Global, BlockLowerer::kM99Block) && a.key == "target") resumers.insert(f.name);
          });
      const Expr *label = op.kind == OpKind::Goto ? op.get("label") : nullptr;
      restart |= label && label->kind == ir::ExprKind::String && label->str == BlockLowerer::kMainStart;
    });
  }
  for (auto &f : m.functions) {
    // Ops are inserted after calls, so each region is rebuilt.
    std::function<void(Region &)> walk = [&](Region &r) {
      Region out;
      std::optional<SourceLoc> pending;  // a resume check waits for the op after its call
      bool copyStart = false;            // the op before started a G72.x (its copy 0 call follows)
      for (auto &op : r) {
        for (auto &sub : op.regions) walk(sub);
        bool isCall = op.kind == OpKind::Call || op.kind == OpKind::ModalCall;
        const std::string *callee = isCall ? constCallee(op) : nullptr;
        if (isCall) {  // a._C_ALL_PROG, a._C_TYP_PROG, a._C_G: only for a callee that reads them
          auto it = callee ? reads.find(*callee) : reads.end();
          for (size_t i = op.args.size(); i-- > 0;) {
            const std::string &k = op.args[i].key;
            if (k.rfind("a._C_", 0) == 0 && (it == reads.end() || !it->second.count(k.substr(2))))
              op.args.erase(op.args.begin() + (long)i);
          }
        }
        bool resumes = isCall && !resumers.empty() && (!callee || resumers.count(*callee));
        const bool afterCopyStart = copyStart;
        const Expr *slot = op.kind == OpKind::Frame ? op.get("slot") : nullptr;
        const Expr *action = op.kind == OpKind::Frame ? op.get("action") : nullptr;
        copyStart = slot && slot->kind == ir::ExprKind::Symbol && slot->str == "copy" && action &&
                    action->kind == ir::ExprKind::Symbol && action->str == "set";
        if (resumes && op.kind == OpKind::ModalCall) {
          diags.error(op.loc, fmt::format("{} ends with M99 P<n>, which a modal call (G66) cannot return by", *callee),
                      "unsupported-code");
          ok = false;
        } else if (resumes) {
          const Expr *count = op.get("count");
          // G72.1/G72.2 (LowerCopy.cpp) call copy 0, then a loop of copies.
          const char *why = afterCopyStart ? "G72.1/G72.2 cannot repeat it"
                            : count && !(count->kind == ir::ExprKind::Number && count->num == 1)
                                ? "it cannot be called repeatedly (L or the repeat digits of P)"
                                : nullptr;
          if (why) {
            diags.error(op.loc,
                        fmt::format("{} may end with M99 P<n> (back to a block of the caller): {}",
                                    callee ? *callee : std::string("the called program"), why),
                        "unsupported-code");
            ok = false;
          }
        }
        // A call by code resets its flag first (LowerCalls.cpp): the jump comes after that.
        bool flagReset = op.kind == OpKind::Assign && op.get("target") &&
                         isVar(*op.get("target"), ir::VarSpace::Global, BlockLowerer::kByCodeFlag);
        if (pending && !flagReset) out.push_back(resumeAt(*pending));
        SourceLoc loc = op.loc;
        out.push_back(std::move(op));
        if (pending && flagReset) out.push_back(resumeAt(*pending));
        pending.reset();
        if (resumes && out.back().kind == OpKind::Call) pending = loc;
      }
      if (pending) out.push_back(resumeAt(*pending));
      r = std::move(out);
    };
    walk(f.body);
  }
  if (ir::Function *main = m.find("main")) {
    Region start;
    SourceLoc loc = main->loc;
    if (byCode) start.push_back(globalAssign(BlockLowerer::kByCodeFlag, Expr::number(0, ir::Type::Int, loc), loc));
    if (!resumers.empty()) start.push_back(globalAssign(BlockLowerer::kM99Block, Expr::number(0, ir::Type::Int, loc), loc));
    if (restart) {
      Op label(OpKind::Label, loc);
      label.set("name", Expr::string(BlockLowerer::kMainStart, loc));
      start.push_back(std::move(label));
    }
    for (auto &op : main->body) start.push_back(std::move(op));
    main->body = std::move(start);
  }
  return ok;
}

}  // namespace ncc::iso
