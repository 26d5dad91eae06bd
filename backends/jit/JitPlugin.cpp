// The entry point of libncc-jit.so: the JIT's functions for the driver (utils/ncc/JitLoader).
#include "backends/jit/Jit.h"

namespace {
bool runWithSink(const ncc::ir::Module &m, ncc::CmdSink &sink, ncc::Diagnostics &diags, const ncc::jit::JitOptions &o) {
  return ncc::jit::runModule(m, sink, diags, o);
}
}  // namespace

extern "C" __attribute__((visibility("default"))) const ncc::jit::JitApi *ncc_jit_api_v1() {
  static const ncc::jit::JitApi api{ncc::jit::jitApiStamp(), runWithSink, ncc::jit::compilesQuickly,
                                    ncc::jit::emitLLVM, ncc::jit::emitObject};
  return &api;
}
