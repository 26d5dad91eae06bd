// Internal to backends/jit: NC IR -> LLVM IR.
#pragma once
#include "ir/NCIR.h"

#include <memory>

namespace llvm {
class LLVMContext;
class Module;
class TargetMachine;
}  // namespace llvm

namespace ncc::jit {

// Builds the LLVM module (entry `i32 ncc_program_main(ptr ctx)`); null after reporting errors.
// mergeBlocks: the code passes a run of Block commands as one ncrt_exec_blocks (for a target whose
// CmdSink::mergesBlocks; another target then sees the last block of each run `count` times).
std::unique_ptr<llvm::Module> buildModule(const ir::Module &m, llvm::LLVMContext &ctx, Diagnostics &diags,
                                          bool mergeBlocks = true);
// Runs the standard O1..O3 pipeline (level 0 does nothing).
void optimizeModule(llvm::Module &mod, llvm::TargetMachine *tm, int level);
// Host target machine (PIC, default CPU features; the code generator's default optimisation, or
// none: fast instruction selection and register allocation); null after reporting an error.
std::unique_ptr<llvm::TargetMachine> hostTargetMachine(Diagnostics &diags, bool optimise = true);
// buildModule with the host's data layout and triple (for --emit=llvm and --emit=obj).
std::unique_ptr<llvm::Module> buildHostModule(const ir::Module &m, llvm::LLVMContext &ctx,
                                              llvm::TargetMachine &tm, Diagnostics &diags);

}  // namespace ncc::jit
