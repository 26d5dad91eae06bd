// Runs a flat program a chunk of blocks at a time: parse and lower streamChunkBlocks (4096)
// blocks, evaluate and execute them, drop them, go on. Memory stays bounded whatever the length.
// Plain blocks skip the ops and the evaluator: the stream sends their machine commands to the
// executor as it reads them (the lean path, BlockLowerer::lowerLean).
// (A two-thread pipeline, parsing the next chunk while executing this one, gave no clear gain on
// flat_moves: 0.91 s against 0.95 s at 128% CPU, as execution dominates. Not worth the threads.)
#include "passes/Eval.h"
#include "passes/Pass.h"
#include "runtime/Executor.h"
#include "utils/ncc/Driver.h"

#include <cstdlib>

namespace ncc::driver {

namespace {
// The stream's plain blocks as machine commands straight to the executor (the lean path); notes
// a refusal, which ends the run as a failed evaluation would.
class LeanSink : public CmdSink {
public:
  explicit LeanSink(Executor &e) : exec_(e) {}
  bool exec(const MachineCmd &cmd) override { return exec_.exec(cmd) || (refused = true, false); }
  bool execMove(const MachineCmd *last, uint64_t blocks, const MachineCmd *mode, const MachineCmd &move) override {
    return exec_.execMove(last, blocks, mode, move) || (refused = true, false);
  }
  bool refused = false;

private:
  Executor &exec_;
};
}  // namespace

bool Session::executeStreamed(uint32_t file, MotionSink &sink, uint64_t *blocks, bool &streamed) {
  streamed = false;
  auto stream = openBlockStream(kindOf(file), sm, file, frontendOptions(file), diags);
  if (!stream) return !diags.hasErrors();
  streamed = true;
  // Front-end output is verified by the test suite; per-chunk checks cost ~15% here.
  bool verifyChunks = std::getenv("NCC_VERIFY_CHUNKS") != nullptr;
  Executor exec(machine, sink, diags);
  if (onExecutor) onExecutor(exec);
  ExecutorSink es(exec);
  LeanSink lean(exec);
  Evaluator ev(es, diags, opts.limits);
  ev.trustInput(!verifyChunks);  // front-end output; per-chunk checks cost ~25% here
  PassContext ctx;
  ctx.machine = &machine;
  ir::Module chunk;
  chunk.name = sm.name(file);
  chunk.functions.emplace_back();
  chunk.functions[0].name = "main";
  bool more = true;
  while (more && !ev.ended()) {
    chunk.functions[0].body.clear();
    more = stream->next(chunk.functions[0].body, streamChunkBlocks, verifyChunks ? nullptr : &lean);
    if (lean.refused) exec.finish(false);
    if (diags.hasErrors()) return false;
    if (verifyChunks && !runPasses(chunk, {"verify", "sema"}, diags, ctx)) return false;  // verify includes runnable
    if (!ev.run(chunk)) {
      exec.finish(false);
      return false;
    }
  }
  bool ok = exec.finish();
  if (blocks) *blocks = exec.blockCount();
  return ok && !diags.hasErrors();
}

}  // namespace ncc::driver
