// ncc compile: stop after a stage and print it (NC IR, Motion IR, LLVM IR, object file);
// ncc opt: run named passes on a program or on textual NC IR.
#include "passes/Pass.h"
#include "utils/ncc/AotRun.h"
#include "utils/ncc/Driver.h"
#include "utils/ncc/ExeLink.h"
#include "utils/ncc/JitLoader.h"

#include <fmt/format.h>

#include <cstdio>
#include <sstream>
#include <unistd.h>

namespace ncc::driver {

// What an object carries so that it runs without its source (runtime/ncrt.h ProgramInfo).
bool programInfo(Session &s, uint32_t program, ncrt::ProgramInfo &info) {
  info.program = s.sm.name(program);
  info.nccVersion = ncrt_version();
  info.machineName = s.opts.machine;
  if (!readMachineText(s.opts.machine, info.machineText)) {
    s.diags.error({}, fmt::format("cannot read machine '{}'", s.opts.machine));
    return false;
  }
  for (uint32_t f = 1; f <= s.sm.fileCount(); ++f) info.files.push_back({s.sm.name(f), ncrt::textHash(s.sm.text(f))});
  return true;
}

namespace {
std::vector<std::string> splitList(const std::string &s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}
// The object beside the executable, linked, then removed.
bool emitExecutable(Session &s, const jit::JitApi &jit, const ir::Module &m, const ncrt::ProgramInfo &info,
                    const std::string &out) {
  std::string obj = out + ".ncc-" + std::to_string(getpid()) + ".o";
  bool ok = jit.emitObject(m, obj, s.diags, info, 2) && linkExecutable(obj, out, s.diags);
  std::remove(obj.c_str());
  return ok;
}
}  // namespace

int cmdCompile(int argc, char **argv) {
  Session s;
  std::string file, emit, out;
  po::options_description desc("ncc compile options");
  desc.add_options()
      ("file", po::value(&file)->required(), "program to compile")
      ("emit", po::value(&emit)->required(), "what to produce: ir|motion|llvm|obj|exe")
      ("output,o", po::value(&out), "output file (default: standard output; required for obj and exe)");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("file", 1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc compile FILE --emit=ir|motion|llvm|obj|exe [-o OUT]");
  if (rc >= 0) return rc;
  if (emit != "ir" && emit != "motion" && emit != "llvm" && emit != "obj" && emit != "exe") {
    std::fprintf(stderr, "ncc: error: unknown --emit '%s' (expected ir, motion, llvm, obj or exe)\n", emit.c_str());
    return kExitUsage;
  }
  if ((emit == "obj" || emit == "exe") && (out.empty() || out == "-")) {
    std::fprintf(stderr, "ncc: error: --emit=%s needs -o FILE\n", emit.c_str());
    return kExitUsage;
  }
  uint32_t f = s.start(file);
  if (!f) return kExitErrors;
  ir::Module m;
  if (emit == "motion") {
    // Motion IR text is parsed and printed again (a round trip); a program runs whole.
    std::string text;
    MotionTextWriter w(text);
    bool motionText = s.kindOf(f) == SourceKind::Motion;
    if (motionText ? !s.execute(f, w) : !(s.load(f, m) && s.executeModule(m, w))) return kExitErrors;
    writeOutput(s, out, text);
    return s.exitCode();
  }
  if (!s.load(f, m)) return kExitErrors;
  if (emit == "ir") {
    writeOutput(s, out, ir::printModule(m, s.sm));
    return s.exitCode();
  }
  const jit::JitApi *jit = jitBackend(s.diags);
  if (!jit) return kExitErrors;
  if (emit == "llvm") {
    std::string text;
    if (!jit->emitLLVM(m, text, s.diags)) return kExitErrors;
    writeOutput(s, out, text);
  } else {
    ncrt::ProgramInfo info;
    if (!programInfo(s, f, info)) return kExitErrors;
    if (emit == "obj" ? !jit->emitObject(m, out, s.diags, info, 2) : !emitExecutable(s, *jit, m, info, out))
      return kExitErrors;
  }
  return s.exitCode();
}

int cmdOpt(int argc, char **argv) {
  Session s;
  std::string file, passes, out;
  bool list = false;
  po::options_description desc("ncc opt options");
  desc.add_options()
      ("file", po::value(&file), "textual NC IR (.ncir) or a program in any dialect")
      ("passes", po::value(&passes), "comma-separated pass names, run in order")
      ("list-passes", po::bool_switch(&list), "list the available passes")
      ("output,o", po::value(&out), "output file (default: standard output)");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("file", 1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc opt FILE [--passes=a,b,c] [-o OUT]");
  if (rc >= 0) return rc;
  if (list) {
    unsigned n;
    const PassInfo *t = passTable(n);
    for (unsigned i = 0; i < n; ++i) std::printf("  %-14s %s\n", t[i].name, t[i].description);
    return kExitOk;
  }
  if (file.empty()) {
    std::fprintf(stderr, "ncc: error: no input file\n");
    return kExitUsage;
  }
  uint32_t f = s.start(file);
  if (!f) return kExitErrors;
  ir::Module m;
  if (!s.load(f, m)) return kExitErrors;
  std::string motion;
  PassContext ctx;
  ctx.machine = &s.machine;
  ctx.limits = s.opts.limits;
  ctx.motionText = &motion;
  auto names = splitList(passes);
  for (auto &n : names)
    if (!findPass(n)) {
      std::fprintf(stderr, "ncc: error: unknown pass '%s' (see --list-passes)\n", n.c_str());
      return kExitUsage;
    }
  if (!runPasses(m, names, s.diags, ctx)) return kExitErrors;
  bool lowered = !names.empty() && names.back() == "lower-motion";
  writeOutput(s, out, lowered ? motion : ir::printModule(m, s.sm));
  return s.exitCode();
}

}  // namespace ncc::driver
