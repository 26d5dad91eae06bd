// The JIT backend (backends/jit/Jit.h JitApi), loaded on first use from libncc-jit.so beside the
// ncc binary or in its install tree; LLVM comes with it, so a run that compiles nothing never
// maps it.
#pragma once
#include "backends/jit/Jit.h"

namespace ncc::driver {

// Null after reporting why the module cannot be loaded.
const jit::JitApi *jitBackend(Diagnostics &diags);

}  // namespace ncc::driver
