// lower-motion: runs the program's machine ops through the executor (modal resolution, units,
// incremental->absolute, work and tool offsets, cycles) and produces Motion IR.
#include "passes/Eval.h"
#include "passes/Pass.h"
#include "runtime/Executor.h"

namespace ncc {

bool runLowerMotion(ir::Module &m, Diagnostics &diags, PassContext &ctx) {
  std::string local;
  std::string &out = ctx.motionText ? *ctx.motionText : local;
  out.clear();
  MotionTextWriter sink(out);
  Executor exec(ctx.machine ? *ctx.machine : Machine::builtinDefault(), sink, diags);
  ExecutorSink es(exec);
  Evaluator ev(es, diags, ctx.limits);
  bool ok = ev.run(m);
  ok &= exec.finish(ok);
  return ok && !diags.hasErrors();
}

}  // namespace ncc
