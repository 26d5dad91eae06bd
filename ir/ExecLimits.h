// Limits that stop runaway programs in both engines (documented in README "Limits").
#pragma once
#include <cstdint>

namespace ncc {

struct ExecLimits {
  uint64_t maxLoopIterations = 10'000'000;  // per loop entry (while/loop/backward goto)
  unsigned maxCallDepth = 64;
  double maxSeconds = 600;
};

}  // namespace ncc
