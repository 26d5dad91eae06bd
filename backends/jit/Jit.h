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
// Host object file (O2), written atomically (`ncc compile --emit=obj`). Beside the entry it
// defines `ncc_program_info`, the encoded `info` (its abi is set here), so that the object runs
// without its source (docs/AOT.md).
bool emitObject(const ir::Module &m, const std::string &path, Diagnostics &diags, const ncrt::ProgramInfo &info = {});

}  // namespace ncc::jit
