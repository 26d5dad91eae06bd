// The `eval` pass: runs the program with the eval engine and keeps, in order, every machine op
// it executes with its operands evaluated. The result is a flat main program (loops unrolled,
// calls inlined, variables gone): the static part of the program fully evaluated.
#include "passes/CmdTemplate.h"
#include "passes/Eval.h"
#include "passes/Pass.h"

#include <deque>
#include <string>

namespace ncc {
using namespace ir;

namespace {
class FlattenSink : public CmdSink {
public:
  Region ops;
  bool exec(const MachineCmd &cmd) override {
    ops.push_back(cmdToOp(cmd));
    return true;
  }
};
}  // namespace

bool runEvalFlatten(Module &m, Diagnostics &diags, PassContext &ctx) {
  FlattenSink sink;
  Evaluator ev(sink, diags, ctx.limits);
  if (!ev.run(m)) return false;
  Function main;
  main.name = m.functions.empty() ? "main" : m.functions[0].name;
  main.loc = m.functions.empty() ? SourceLoc{} : m.functions[0].loc;
  main.body = std::move(sink.ops);
  m.functions.clear();
  m.functions.push_back(std::move(main));
  return true;
}

}  // namespace ncc
