// Runs compiled NC programs in-process with ORC LLJIT; the runtime's C ABI and the builtin
// functions are handed to the JIT as absolute symbols (the ncc binary does not export them).
#include "backends/jit/Codegen.h"
#include "backends/jit/Jit.h"

#include "passes/Eval.h"
#include "runtime/Executor.h"
#include "runtime/ncrt.h"

#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>
#include <llvm/IR/Dominators.h>
#include <llvm/IR/InstIterator.h>
#include <llvm/IR/IntrinsicInst.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/MC/TargetRegistry.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>
#include <llvm/TargetParser/Host.h>

#include <mutex>

namespace ncc::jit {

using namespace llvm;

static void initLLVM() {
  static std::once_flag once;
  std::call_once(once, [] {
    InitializeNativeTarget();
    InitializeNativeTargetAsmPrinter();
  });
}

static std::string errorText(Error e) {
  std::string s;
  raw_string_ostream os(s);
  logAllUnhandledErrors(std::move(e), os);
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

std::unique_ptr<TargetMachine> hostTargetMachine(Diagnostics &diags, bool optimise) {
  initLLVM();
  auto jtmb = orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) {
    diags.error({}, "cannot target the host: " + errorText(jtmb.takeError()));
    return nullptr;
  }
  jtmb->setRelocationModel(Reloc::PIC_);
  jtmb->setCodeModel(CodeModel::Small);  // as a compiler's objects (the JIT's default is large)
  jtmb->setCodeGenOptLevel(optimise ? CodeGenOptLevel::Default : CodeGenOptLevel::None);
  auto tm = jtmb->createTargetMachine();
  if (!tm) {
    diags.error({}, "cannot target the host: " + errorText(tm.takeError()));
    return nullptr;
  }
  return std::move(*tm);
}

std::unique_ptr<Module> buildHostModule(const ir::Module &m, LLVMContext &ctx, TargetMachine &tm,
                                        Diagnostics &diags) {
  std::unique_ptr<Module> mod = buildModule(m, ctx, diags);
  if (!mod) return nullptr;
  mod->setDataLayout(tm.createDataLayout());
  mod->setTargetTriple(tm.getTargetTriple().str());
  return mod;
}

// SIN[a] and COS[a] of the same angle (a rotation: X[r * COS[a]] Y[r * SIN[a]]): the code
// generator makes one sincos call of a sin and a cos with one operand in one basic block, but
// each builtin's domain check ends a block. Both intrinsics are pure, so the later one moves up
// to right after the one that dominates it (glibc's sincos gives sin's and cos's bits).
static void pairSinCos(Module &mod) {
  for (Function &f : mod) {
    if (f.isDeclaration()) continue;
    std::vector<IntrinsicInst *> calls;
    for (Instruction &i : instructions(f))
      if (auto *c = dyn_cast<IntrinsicInst>(&i); c && (c->getIntrinsicID() == Intrinsic::sin || c->getIntrinsicID() == Intrinsic::cos))
        calls.push_back(c);
    if (calls.size() < 2) continue;
    DominatorTree dt(f);
    std::vector<bool> paired(calls.size());
    for (size_t i = 0; i < calls.size(); ++i)
      for (size_t j = i + 1; j < calls.size() && !paired[i]; ++j) {
        IntrinsicInst *a = calls[i], *b = calls[j];
        if (paired[j] || a->getIntrinsicID() == b->getIntrinsicID() || a->getArgOperand(0) != b->getArgOperand(0)) continue;
        if (dt.dominates(b, a)) std::swap(a, b);
        if (!dt.dominates(a, b)) continue;
        if (a->getParent() != b->getParent()) b->moveAfter(a);
        paired[i] = paired[j] = true;
      }
  }
}

void optimizeModule(Module &mod, TargetMachine *tm, int level) {
  if (level <= 0) return;
  LoopAnalysisManager LAM;
  FunctionAnalysisManager FAM;
  CGSCCAnalysisManager CGAM;
  ModuleAnalysisManager MAM;
  PassBuilder PB(tm);
  PB.registerModuleAnalyses(MAM);
  PB.registerCGSCCAnalyses(CGAM);
  PB.registerFunctionAnalyses(FAM);
  PB.registerLoopAnalyses(LAM);
  PB.crossRegisterProxies(LAM, FAM, CGAM, MAM);
  OptimizationLevel lvl = level == 1 ? OptimizationLevel::O1 : level == 2 ? OptimizationLevel::O2 : OptimizationLevel::O3;
  PB.buildPerModuleDefaultPipeline(lvl).run(mod, MAM);
  pairSinCos(mod);
}

// Every external symbol generated code may reference (runtime/ncrt.h), with its address here.
static orc::SymbolMap runtimeSymbols(orc::LLJIT &jit) {
  orc::SymbolMap syms;
  for (const ncrt::RuntimeSymbol &s : ncrt::runtimeSymbols())
    syms[jit.mangleAndIntern(s.name)] = {orc::ExecutorAddr::fromPtr(s.address),
                                         JITSymbolFlags::Exported | JITSymbolFlags::Callable};
  return syms;
}

// An LLJIT for the host whose main dylib resolves the runtime, the builtins and libc/libm
// (memcpy, memset, round on CPUs without SSE4.1); null after reporting an error.
static std::unique_ptr<orc::LLJIT> makeJit(orc::JITTargetMachineBuilder jtmb, Diagnostics &diags) {
  auto jit = orc::LLJITBuilder().setJITTargetMachineBuilder(std::move(jtmb)).create();
  if (!jit) {
    diags.error({}, "JIT: " + errorText(jit.takeError()));
    return nullptr;
  }
  orc::JITDylib &jd = (*jit)->getMainJITDylib();
  if (Error e = jd.define(orc::absoluteSymbols(runtimeSymbols(**jit)))) {
    diags.error({}, "JIT: " + errorText(std::move(e)));
    return nullptr;
  }
  auto process = orc::DynamicLibrarySearchGenerator::GetForCurrentProcess((*jit)->getDataLayout().getGlobalPrefix());
  if (!process) {
    diags.error({}, "JIT: " + errorText(process.takeError()));
    return nullptr;
  }
  jd.addGenerator(std::move(*process));
  return std::move(*jit);
}

// Looks up the entry and runs it against the sink.
static bool runEntry(orc::LLJIT &jit, CmdSink &sink, Diagnostics &diags, const ExecLimits &limits) {
  auto sym = jit.lookup("ncc_program_main");
  if (!sym) {
    diags.error({}, "JIT: " + errorText(sym.takeError()));
    return false;
  }
  return ncrt::runEntry(sym->toPtr<ncrt_entry>(), sink, diags, limits);
}

bool runModule(const ir::Module &m, CmdSink &sink, Diagnostics &diags, const JitOptions &opts) {
  initLLVM();
  auto jtmb = orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) {
    diags.error({}, "JIT: " + errorText(jtmb.takeError()));
    return false;
  }
  auto tm = jtmb->createTargetMachine();
  if (!tm) {
    diags.error({}, "JIT: " + errorText(tm.takeError()));
    return false;
  }
  auto ctx = std::make_unique<LLVMContext>();
  std::unique_ptr<Module> mod = buildModule(m, *ctx, diags, sink.mergesBlocks());
  if (!mod) return false;
  mod->setDataLayout((*tm)->createDataLayout());
  mod->setTargetTriple(jtmb->getTargetTriple().str());
  optimizeModule(*mod, tm->get(), opts.optLevel);
  auto jit = makeJit(std::move(*jtmb), diags);
  if (!jit) return false;
  if (Error e = jit->addIRModule(orc::ThreadSafeModule(std::move(mod), std::move(ctx)))) {
    diags.error({}, "JIT: " + errorText(std::move(e)));
    return false;
  }
  return runEntry(*jit, sink, diags, opts.limits);
}

bool runObjectFile(const std::string &path, CmdSink &sink, Diagnostics &diags, const JitOptions &opts) {
  initLLVM();
  auto buf = MemoryBuffer::getFile(path);
  if (!buf) {
    diags.error({}, "cannot read '" + path + "': " + buf.getError().message());
    return false;
  }
  auto jtmb = orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) {
    diags.error({}, "JIT: " + errorText(jtmb.takeError()));
    return false;
  }
  auto jit = makeJit(std::move(*jtmb), diags);
  if (!jit) return false;
  if (Error e = jit->addObjectFile(std::move(*buf))) {
    diags.error({}, "'" + path + "': " + errorText(std::move(e)));
    return false;
  }
  return runEntry(*jit, sink, diags, opts.limits);
}

bool runModule(const ir::Module &m, Executor &exec, Diagnostics &diags, const JitOptions &opts) {
  ExecutorSink sink(exec);
  return runModule(m, sink, diags, opts);
}

bool emitLLVM(const ir::Module &m, std::string &out, Diagnostics &diags) {
  auto tm = hostTargetMachine(diags);
  if (!tm) return false;
  LLVMContext ctx;
  std::unique_ptr<Module> mod = buildHostModule(m, ctx, *tm, diags);
  if (!mod) return false;
  out.clear();
  raw_string_ostream os(out);
  mod->print(os, nullptr);
  os.flush();
  return true;
}

}  // namespace ncc::jit
