// AOT: the JIT's LLVM IR, optimised at O2 (or not at all: the JIT cache's quick tier) and compiled for the host into an object file whose
// entry is `int ncc_program_main(ncrt_ctx *)` and which describes the program in
// `ncc_program_info`; link it with the ncc runtime (ncrt_*, builtins) or run it with `ncc run`.
#include "backends/jit/Codegen.h"
#include "backends/jit/Jit.h"

#include <fmt/format.h>

#include <llvm/IR/Constants.h>
#include <llvm/IR/GlobalVariable.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>

namespace ncc::jit {

using namespace llvm;

// The program description (runtime/ncrt.h ProgramInfo) as a constant the loader finds by name.
static void addProgramInfo(Module &mod, ncrt::ProgramInfo info) {
  info.abi = ncrt::abiFingerprint();
  std::string bytes = ncrt::encodeProgramInfo(info);
  Constant *data = ConstantDataArray::getRaw(bytes, bytes.size(), Type::getInt8Ty(mod.getContext()));
  auto *gv = new GlobalVariable(mod, data->getType(), true, GlobalValue::ExternalLinkage, data, "ncc_program_info");
  gv->setAlignment(Align(8));
}

bool emitObject(const ir::Module &m, const std::string &path, Diagnostics &diags, const ncrt::ProgramInfo &info,
                int optLevel) {
  if (std::string why; !compilesQuickly(m, why)) {  // no engine to fall back to here
    diags.error({}, fmt::format("cannot compile ahead of time: {}, which takes LLVM minutes", why), "unsupported-code");
    return false;
  }
  auto tm = hostTargetMachine(diags, optLevel > 0);
  if (!tm) return false;
  LLVMContext ctx;
  std::unique_ptr<Module> mod = buildHostModule(m, ctx, *tm, diags);
  if (!mod) return false;
  addProgramInfo(*mod, info);
  optimizeModule(*mod, tm.get(), optLevel);

  SmallVector<char, 0> buf;
  raw_svector_ostream os(buf);
  legacy::PassManager pm;
  if (tm->addPassesToEmitFile(pm, os, nullptr, CodeGenFileType::ObjectFile)) {
    diags.error({}, "the host target cannot emit object files");
    return false;
  }
  pm.run(*mod);
  std::string bytes(buf.data(), buf.size());
  bytes += ncrt::objectTrailer(bytes);
  std::string err;
  if (!writeFileAtomic(path, bytes, err)) {
    diags.error({}, "cannot write '" + path + "': " + err);
    return false;
  }
  return true;
}

}  // namespace ncc::jit
