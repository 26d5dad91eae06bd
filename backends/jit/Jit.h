// JIT and AOT backend: compiles NC IR (ir/NCIR.h) to LLVM IR whose code builds MachineCmds and
// calls the runtime's C ABI (runtime/ncrt.h). runModule runs it in-process with ORC LLJIT;
// emitObject writes the same code as a host object file with entry `ncc_program_main`.
// Semantics match the eval engine (ir/Value.h, ir/Arith.h, docs/JIT.md).
#pragma once
#include "ir/NCIR.h"
#include "ir/ExecLimits.h"
#include "runtime/ncrt.h"

#include <string>

namespace ncc {
class Executor;
class CmdSink;
}  // namespace ncc

namespace ncc::jit {

struct JitOptions {
  int optLevel = 2;  // 0..3
  ExecLimits limits;
};

// Compiles and runs the program; its commands go to the executor. Does not call
// exec.finish() (the caller does, as for the eval engine). Returns false on a compile or
// run-time error (diagnostics already reported). An empty module runs nothing.
bool runModule(const ir::Module &m, Executor &exec, Diagnostics &diags, const JitOptions &opts);
// The same with any command sink (tests record the command stream).
bool runModule(const ir::Module &m, CmdSink &sink, Diagnostics &diags, const JitOptions &opts);

// A computed goto may reach every numbered block and label of its function, and LLVM's code
// generator takes minutes over such a switch (1000 blocks: over 2 min even at -O0's 11 s). Above
// this many targets the driver runs the program with the eval engine, which is equivalent.
constexpr size_t kMaxComputedGotoTargets = 64;
// False, with the function and its target count in `why`, when `m` has such a function.
bool compilesQuickly(const ir::Module &m, std::string &why);

// Loads an object file written by emitObject into the JIT and runs it (checks AOT output
// without a system linker).
bool runObjectFile(const std::string &path, CmdSink &sink, Diagnostics &diags, const JitOptions &opts);

// Textual LLVM IR of the program, before optimisation (`ncc compile --emit=llvm`).
bool emitLLVM(const ir::Module &m, std::string &out, Diagnostics &diags);
// Host object file, written atomically (`ncc compile --emit=obj`). Beside the entry it defines
// `ncc_program_info`, the encoded `info` (its abi is set here), so that the object runs without
// its source (docs/AOT.md). optLevel 2: the O2 pipeline and code generator; 0: neither (about a
// quarter of the compile time, for code that does not run long: the JIT cache's first run).
bool emitObject(const ir::Module &m, const std::string &path, Diagnostics &diags, const ncrt::ProgramInfo &info = {},
                int optLevel = 2);

// The JIT as a separately loaded part (libncc-jit.so, dlopen'ed by the driver on first use), so
// that a process that compiles nothing never maps LLVM. The module resolves everything outside
// backends/jit from the ncc binary, which exports its symbols; the stamp guards against a module
// of another build.
struct JitApi {
  uint64_t stamp;
  bool (*runModule)(const ir::Module &, CmdSink &, Diagnostics &, const JitOptions &);
  bool (*compilesQuickly)(const ir::Module &, std::string &);
  bool (*emitLLVM)(const ir::Module &, std::string &, Diagnostics &);
  bool (*emitObject)(const ir::Module &, const std::string &, Diagnostics &, const ncrt::ProgramInfo &, int optLevel);
};
// What both sides compute from the headers they were built with.
constexpr uint64_t jitApiStamp() {
  return (uint64_t)NCRT_ABI_VERSION << 56 ^ (uint64_t)sizeof(ir::Module) << 40 ^ (uint64_t)sizeof(Diagnostics) << 24 ^
         (uint64_t)sizeof(JitOptions) << 12 ^ sizeof(ncrt::ProgramInfo);
}
// The entry point libncc-jit.so exports.
#define NCC_JIT_API_SYMBOL "ncc_jit_api_v1"

}  // namespace ncc::jit
