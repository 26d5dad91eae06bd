// Runs a flat program as a two-stage pipeline: one thread parses and lowers blocks into chunks
// of NC IR while the calling thread evaluates and executes the previous chunk. The parser keeps
// its own diagnostics, handed over with each chunk, so messages come out in program order and a
// parse error stops execution exactly where the sequential version would.
#include "passes/Eval.h"
#include "passes/Pass.h"
#include "runtime/Executor.h"
#include "utils/ncc/Driver.h"

#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <thread>

namespace ncc::driver {

namespace {
constexpr size_t kChunkBlocks = 4096;
constexpr size_t kQueueDepth = 4;

struct Chunk {
  ir::Region ops;
  std::vector<Diagnostic> diags;
  bool failed = false;
};

class ChunkQueue {
public:
  // Blocks while full; false when the consumer has gone.
  bool push(Chunk c) {
    std::unique_lock<std::mutex> l(mu_);
    notFull_.wait(l, [&] { return q_.size() < kQueueDepth || cancelled_; });
    if (cancelled_) return false;
    q_.push_back(std::move(c));
    notEmpty_.notify_one();
    return true;
  }
  // Blocks while empty; false at the end of input.
  bool pop(Chunk &c) {
    std::unique_lock<std::mutex> l(mu_);
    notEmpty_.wait(l, [&] { return !q_.empty() || closed_; });
    if (q_.empty()) return false;
    c = std::move(q_.front());
    q_.pop_front();
    notFull_.notify_one();
    return true;
  }
  void close() {
    std::lock_guard<std::mutex> l(mu_);
    closed_ = true;
    notEmpty_.notify_all();
  }
  void cancel() {
    std::lock_guard<std::mutex> l(mu_);
    cancelled_ = true;
    notFull_.notify_all();
  }

private:
  std::mutex mu_;
  std::condition_variable notFull_, notEmpty_;
  std::deque<Chunk> q_;
  bool closed_ = false, cancelled_ = false;
};
}  // namespace

bool Session::executeStreamed(uint32_t file, MotionSink &sink, uint64_t *blocks, bool &streamed) {
  streamed = false;
  Diagnostics parseDiags(sm);
  parseDiags.setCollect(true);
  auto stream = openBlockStream(kindOf(file), sm, file, frontendOptions(file), parseDiags);
  if (!stream) return true;
  streamed = true;

  ChunkQueue queue;
  std::thread parser([&] {
    size_t seen = 0;
    bool more = true;
    while (more) {
      Chunk c;
      more = stream->next(c.ops, kChunkBlocks);
      const auto &all = parseDiags.collected();
      c.diags.assign(all.begin() + (long)seen, all.end());
      seen = all.size();
      c.failed = parseDiags.hasErrors();
      bool stop = c.failed;
      if (!queue.push(std::move(c)) || stop) break;
    }
    queue.close();
  });

  // Front-end output is verified by the test suite; per-chunk checks cost ~15% here.
  bool verifyChunks = std::getenv("NCC_VERIFY_CHUNKS") != nullptr;
  Executor exec(machine, sink, diags);
  ExecutorSink es(exec);
  Evaluator ev(es, diags, opts.limits);
  PassContext ctx;
  ctx.machine = &machine;
  ir::Module module;
  module.name = sm.name(file);
  module.functions.emplace_back();
  module.functions[0].name = "main";
  bool ok = true;
  Chunk c;
  while (ok && !ev.ended() && queue.pop(c)) {
    for (auto &d : c.diags) diags.report(d.severity, d.loc, d.message, d.rule);
    if (c.failed || diags.hasErrors()) {
      ok = false;
      break;
    }
    module.functions[0].body = std::move(c.ops);
    if (verifyChunks && !runPasses(module, {"verify", "sema"}, diags, ctx)) ok = false;
    else if (!ev.run(module)) ok = false;
  }
  queue.cancel();
  parser.join();
  if (!ok) return false;
  ok = exec.finish();
  if (blocks) *blocks = exec.blockCount();
  return ok && !diags.hasErrors();
}

}  // namespace ncc::driver
