#include "passes/Pass.h"

#include <fmt/format.h>

namespace ncc {

static bool runVerify(ir::Module &m, Diagnostics &diags, PassContext &) { return ir::verifyModule(m, diags); }
static bool runVerifyRunnable(ir::Module &m, Diagnostics &diags, PassContext &) {
  return ir::verifyModule(m, diags) && ir::verifyRunnable(m, diags);
}

static const PassInfo kPasses[] = {
    {"verify", "check the module's structure (ops, keys, regions, jump and call targets)", runVerify},
    {"verify-runnable", "verify, then reject what the engines cannot run yet (both engines check this)",
     runVerifyRunnable},
    {"sema", "name resolution and type checking of expressions", runSema},
    {"fold", "fold constant expressions", runFold},
    {"eval", "evaluate everything static: run the program and keep the machine ops it executes (flat IR)",
     runEvalFlatten},
    {"lint", "static lint rules: unreachable blocks, code after program end", runLint},
    {"lower-motion", "resolve modal state, units, incremental values and offsets into Motion IR", runLowerMotion},
};

const PassInfo *passTable(unsigned &count) {
  count = sizeof(kPasses) / sizeof(kPasses[0]);
  return kPasses;
}

const PassInfo *findPass(std::string_view name) {
  for (auto &p : kPasses)
    if (name == p.name) return &p;
  return nullptr;
}

bool runPasses(ir::Module &m, const std::vector<std::string> &names, Diagnostics &diags, PassContext &ctx) {
  unsigned before = diags.errorCount();
  for (auto &n : names) {
    const PassInfo *p = findPass(n);
    if (!p) {
      diags.error({}, fmt::format("unknown pass '{}'", n));
      return false;
    }
    if (!p->run(m, diags, ctx) || diags.errorCount() != before) return false;
  }
  return true;
}

}  // namespace ncc
