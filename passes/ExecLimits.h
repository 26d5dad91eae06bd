// Run-time limits shared by the eval engine and the JIT, so a runaway program stops with a
// diagnostic instead of hanging (both engines report the same errors at the same limits).
#pragma once
#include <cstdint>

namespace ncc {

struct ExecLimits {
  uint64_t maxLoopIterations = 10'000'000;
  unsigned maxCallDepth = 64;
  double maxSeconds = 600;
};

}  // namespace ncc
