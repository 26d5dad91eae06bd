// The compiled-object cache of `--engine=jit`: the object `ncc compile --emit=obj` would write,
// kept under a key of everything that shapes the generated code, and run through the object
// loader (utils/ncc/ObjectLoader) — so a run that hits never loads LLVM (docs/JIT.md "Cache").
#pragma once
#include "ir/NCIR.h"
#include "utils/ncc/Driver.h"

#include <string>

namespace ncc::driver {

// $NCC_CACHE_DIR, else $XDG_CACHE_HOME/ncc, else $HOME/.cache/ncc; empty (no cache) without any.
std::string cacheDirectory();
// Size above which the oldest entries are removed: $NCC_CACHE_MAX_MB, default 64 MiB.
uintmax_t cacheLimitBytes();

// Runs `m` (loaded by `s`) from the cache, compiling and storing it on a miss; `ok` is the run's
// result. False, having run nothing, when there is no cache (--no-cache, no directory) or the
// program is one the JIT does not compile: the caller runs it as before.
bool runCached(Session &s, const ir::Module &m, CmdSink &sink, bool &ok);

}  // namespace ncc::driver
