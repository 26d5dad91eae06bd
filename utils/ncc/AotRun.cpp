#include "utils/ncc/AotRun.h"

#include "runtime/Executor.h"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <sstream>

namespace ncc::driver {

static bool readText(const std::string &path, std::string &out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

bool readMachineText(const std::string &nameOrPath, std::string &text) {
  if (nameOrPath != "default") return readText(nameOrPath, text);
  text = Machine::builtinDefaultText();
  return true;
}

// The machine to run on: the one compiled in; a --machine must be that one (the front end read
// the program with its settings: decimal mode, lathe codes, start-up modes).
static bool programMachine(const ncrt::ProgramInfo &info, const RunTimeOptions &rt, bool machineGiven,
                           const std::string &name, Machine &out, Diagnostics &diags) {
  if (machineGiven) {
    std::string text;
    if (!readMachineText(rt.machine, text)) {
      diags.error({}, fmt::format("cannot read machine '{}'", rt.machine));
      return false;
    }
    if (text != info.machineText) {
      diags.error({}, fmt::format("'{}' was compiled for machine '{}', not '{}': compile it again for this machine",
                                  name, info.machineName, rt.machine));
      return false;
    }
  }
  std::string err;
  if (Machine::parse(info.machineText, info.machineName, out, err)) return true;
  diags.error({}, fmt::format("'{}': its machine description does not load: {}", name, err));
  return false;
}

// The compile's files under their ids; a file's text only while it is the one compiled, so a
// message never shows a line of another version.
static void registerSources(const ncrt::ProgramInfo &info, const std::string &name, SourceManager &sm,
                            Diagnostics &diags) {
  for (auto &f : info.files) {
    std::string text;
    bool present = readText(f.name, text);
    bool same = present && ncrt::textHash(text) == f.hash;
    sm.addBuffer(f.name, same ? std::move(text) : std::string());
    if (present && !same)
      diags.warning({}, fmt::format("'{}' has changed since '{}' was compiled: messages show no source lines", f.name, name));
  }
}

int runCompiled(const CompiledProgram &p, const RunTimeOptions &rt, bool machineGiven, const RunOutputArgs &out) {
  SourceManager sm;
  Diagnostics diags(sm);
  applyDiagnosticsOptions(rt, diags);
  if (int rc = RunOutputSet::checkUsage(out); rc >= 0) return rc;
  ncrt::ProgramInfo info;
  std::string err;
  if (!ncrt::decodeProgramInfo(p.info, p.infoSize, info, err)) {
    diags.error({}, fmt::format("cannot run '{}': {}", p.name, err));
    return kExitErrors;
  }
  Machine machine;
  if (!programMachine(info, rt, machineGiven, p.name, machine, diags)) return kExitErrors;
  registerSources(info, p.name, sm, diags);
  if (!loadProbeResults(rt, sm, diags, machine) || !applySandbox(rt, diags)) return kExitErrors;
  std::string program = info.program.empty() ? p.name : info.program;
  RunOutputSet outputs(machine, out, program);
  if (!outputs.open(diags)) return kExitErrors;
  Executor exec(machine, outputs.sink(), diags);
  outputs.watch(exec);
  ExecutorSink sink(exec);
  bool ok = ncrt::runEntry(p.entry, sink, diags, rt.limits);
  ok &= exec.finish(ok);
  outputs.setBlockCount(exec.blockCount());
  return outputs.finish(ok && !diags.hasErrors(), diags);
}

}  // namespace ncc::driver

// An executable's main (utils/ncc/AotMain.cpp) and any program that links compiled part programs.
extern "C" int ncrt_main(int argc, char **argv, ncrt_entry entry, const unsigned char *info) {
  using namespace ncc::driver;
  RunTimeOptions rt;
  RunOutputArgs out;
  po::options_description desc("options");
  addRunOutputOptions(desc, out);
  addRunTimeOptions(desc, rt);
  po::positional_options_description pos;
  po::variables_map vm;
  std::string name = argc > 0 ? argv[0] : "program";
  std::string usage = name + " [options]   (a part program compiled by ncc " + ncrt_version() + ")";
  if (int rc = parseArgs(argc, argv, desc, pos, vm, usage.c_str()); rc >= 0) return rc;
  // The description says how long it is; the decoder checks it against the length it states.
  uint64_t size = 0;
  std::memcpy(&size, info + 8, sizeof size);
  return runCompiled({entry, info, (size_t)size, name}, rt, !vm["machine"].defaulted(), out);
}
