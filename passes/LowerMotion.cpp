// lower-motion: runs the program's machine ops through the executor (modal resolution, units,
// incremental->absolute, work and tool offsets, cycles) and produces Motion IR.
#include "passes/Eval.h"
#include "passes/Pass.h"
#include "runtime/Executor.h"

namespace ncc {

namespace {
class TextSink : public MotionSink {
public:
  explicit TextSink(std::string &out) : out_(out) {}
  void record(const MotionRecord &r) override {
    out_ += printMotionRecord(r);
    out_ += '\n';
  }

private:
  std::string &out_;
};
}  // namespace

bool runLowerMotion(ir::Module &m, Diagnostics &diags, PassContext &ctx) {
  std::string local;
  std::string &out = ctx.motionText ? *ctx.motionText : local;
  out.clear();
  TextSink sink(out);
  Executor exec(ctx.machine ? *ctx.machine : Machine::builtinDefault(), sink, diags);
  ExecutorSink es(exec);
  Evaluator ev(es, diags, ctx.limits);
  bool ok = ev.run(m);
  ok &= exec.finish(ok);
  return ok && !diags.hasErrors();
}

}  // namespace ncc
