// The eval engine: a reference interpreter of NC IR. It evaluates expressions and control flow
// and hands every machine op, with its operands evaluated, to a CmdSink (normally the
// Executor). The JIT must produce exactly the same command stream (tests assert it).
// Functions are first linearised into a small instruction list (jumps for if/while/loop/goto),
// so gotos out of nested loops need no special cases.
#pragma once
#include "ir/CmdSink.h"
#include "ir/ExecLimits.h"
#include "ir/NCIR.h"

#include <memory>

namespace ncc {

class Evaluator {
public:
  Evaluator(CmdSink &sink, Diagnostics &diags, const ExecLimits &limits = {});
  ~Evaluator();
  // Runs the module's entry function (functions[0]). Returns false on error.
  bool run(const ir::Module &m);
  // The caller vouches that every module it runs is runnable (ir::verifyRunnable): the ISO
  // block stream's flat chunks, checked in tests (NCC_VERIFY_CHUNKS) and by the fuzzers.
  void trustInput(bool trusted);
  // True once the program reached M2/M30 (stop kind=end|end_rewind).
  bool ended() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncc
