// ncc run: compile, execute, drive the trajectory core; print the summary or a trace. An object
// from `ncc compile --emit=obj` runs as compiled (utils/ncc/ObjectLoader, AotRun).
#include "utils/ncc/AotRun.h"
#include "utils/ncc/Driver.h"
#include "utils/ncc/ObjectLoader.h"

#include <fmt/format.h>

namespace ncc::driver {

// Options that shape the compiled code: an object was compiled with its own.
static const char *const kCompileOptions[] = {"dialect", "engine", "decimal-mode", "block-delete", "include", "link"};

static int runObject(const std::string &file, const CommonOptions &opts, const po::variables_map &vm,
                     const RunOutputArgs &out) {
  for (const char *o : kCompileOptions)
    if (vm.count(o) && !vm[o].defaulted()) {
      std::fprintf(stderr, "ncc: error: --%s has no effect on '%s', which is compiled: give it to ncc compile\n", o,
                   file.c_str());
      return kExitUsage;
    }
  std::string err;
  auto obj = LoadedObject::load(file, err);
  CompiledProgram p;
  p.name = file;
  if (obj) {
    p.entry = reinterpret_cast<ncrt_entry>(const_cast<void *>(obj->symbol("ncc_program_main")));
    p.info = static_cast<const unsigned char *>(obj->symbol("ncc_program_info", &p.infoSize));
    if (!p.entry || !p.info) err = "it is not a part program compiled by ncc (no ncc_program_main/ncc_program_info)";
  }
  if (!p.info || !p.entry) {
    std::fprintf(stderr, "%s: error: cannot run it: %s\n", file.c_str(), err.c_str());
    return kExitErrors;
  }
  return runCompiled(p, opts, !vm["machine"].defaulted(), out);
}

int cmdRun(int argc, char **argv) {
  Session s;
  std::string file;
  RunOutputArgs out;
  po::options_description desc("ncc run options");
  desc.add_options()("file", po::value(&file)->required(), "program to run (a source, Motion IR text or an object from ncc compile --emit=obj)");
  addRunOutputOptions(desc, out);
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("file", 1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc run FILE [options]");
  if (rc >= 0) return rc;
  if (rc = RunOutputSet::checkUsage(out); rc >= 0) return rc;
  if (isObjectFile(file)) return runObject(file, s.opts, vm, out);
  uint32_t f = s.start(file);
  if (!f) return kExitErrors;

  RunOutputSet outputs(s.machine, out, file);
  if (!outputs.open(s.diags)) return kExitErrors;
  s.onExecutor = [&](const Executor &e) { outputs.watch(e); };
  uint64_t blocks = 0;
  bool ok = s.execute(f, outputs.sink(), &blocks);
  // Motion IR text has no blocks to count: the summary counts the source positions of the records.
  if (s.kindOf(f) != SourceKind::Motion) outputs.setBlockCount(blocks);
  return outputs.finish(ok, s.diags);
}

}  // namespace ncc::driver
