// The ncc driver: one binary, subcommands (run, compile, opt, translate, lint, canon-diff,
// machine). This header holds what the subcommands share: the session (sources, diagnostics,
// machine) and the pipeline from a source file to a Motion IR sink.
#pragma once
#include "frontend/Frontend.h"
#include "ir/Diagnostics.h"
#include "ir/MotionIR.h"
#include "ir/NCIR.h"
#include "ir/ExecLimits.h"
#include "runtime/Machine.h"
#include "runtime/ncrt.h"
#include "utils/ncc/RunOutput.h"

#include <boost/program_options.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ncc::driver {

// The run-time options (machine, limits, diagnostics: utils/ncc/RunOutput.h), then those that
// act when the program is read and compiled.
struct CommonOptions : RunTimeOptions {
  std::string dialect;  // empty = detect
  std::string engine = "eval";
  std::string decimalMode;  // empty = the machine's
  std::vector<unsigned> blockDelete;
  std::vector<std::string> includeDirs;  // subprogram files, searched after the program's folder
  std::vector<std::string> linkFiles;    // programs/libraries linked in, each read by its own front end
  bool noCache = false;     // --engine=jit: compile every time (utils/ncc/JitCache.h)
  bool cacheStats = false;  // --engine=jit: say on stderr whether the compiled-object cache hit
};

// Adds the options every program-reading subcommand takes.
void addCommonOptions(po::options_description &desc, CommonOptions &o);

class Session {
public:
  Session() : diags(sm) {}
  SourceManager sm;
  Diagnostics diags;
  Machine machine;
  CommonOptions opts;

  // Applies opts (machine, diagnostics format). Reports and returns false on failure.
  // Loads a machine description into out; its problems become diagnostics in the file.
  bool loadMachine(const std::string &nameOrPath, Machine &out);
  bool checkEmitSections(const std::string &path, Machine &m);
  bool setUp();
  // Reads a source file; 0 after reporting when it cannot be read.
  uint32_t open(const std::string &path);
  // setUp() then open(path): what every single-program subcommand starts with.
  uint32_t start(const std::string &path) { return setUp() ? open(path) : 0; }
  SourceKind kindOf(uint32_t file) const;
  FrontendOptions frontendOptions(uint32_t file) const;
  // Front end + verifier + sema: the module every engine and backend starts from.
  bool load(uint32_t file, ir::Module &out);
  // Runs a program to a Motion IR sink with the chosen engine. Flat programs are streamed
  // block by block (eval engine) so memory stays bounded.
  // `blocks` receives the number of source blocks executed. Motion IR text (.motion,
  // --dialect=motion) is not executed: its records go to the sink as parsed (blocks = 0).
  bool execute(uint32_t file, MotionSink &sink, uint64_t *blocks = nullptr);
  // Flat programs with the eval engine, a chunk of blocks at a time, so memory stays bounded. `streamed` is false when the program needs whole-program parsing.
  bool executeStreamed(uint32_t file, MotionSink &sink, uint64_t *blocks, bool &streamed);
  // The same for an already-loaded module.
  bool executeModule(const ir::Module &m, MotionSink &sink, uint64_t *blocks = nullptr);
  // The end of a run: the executor's last commands, the block count, the result.
  bool finishRun(Executor &exec, bool ok, uint64_t *blocks);
  // `ncc lint` on one file: load (recovering after front-end errors), static rules, a run that
  // keeps going after executor errors. Diagnostics go to diags; false when it reported errors.
  bool lint(uint32_t file);
  // The program being run (execute() sets it): the compiled-object cache names it in the object.
  uint32_t mainFile = 0;
  // Called with each executor a run creates (the progress line counts its blocks).
  std::function<void(const Executor &)> onExecutor;
  // Blocks per streamed chunk (the fuzz targets use tiny chunks to reach the chunk boundaries).
  size_t streamChunkBlocks = 4096;

  int exitCode() const { return diags.hasErrors() ? kExitErrors : kExitOk; }
};

// What an object carries so that it runs without its source (runtime/ncrt.h ProgramInfo).
bool programInfo(Session &s, uint32_t program, ncrt::ProgramInfo &info);

// Output helper: writes `text` to `path` atomically, or to stdout for "" / "-".
bool writeOutput(Session &s, const std::string &path, const std::string &text);

int cmdRun(int argc, char **argv);
int cmdCompile(int argc, char **argv);
int cmdOpt(int argc, char **argv);
int cmdTranslate(int argc, char **argv);
int cmdLint(int argc, char **argv);
int cmdCanonDiff(int argc, char **argv);
int cmdMachine(int argc, char **argv);
int cmdCycle(int argc, char **argv);
int cmdKinematics(int argc, char **argv);

}  // namespace ncc::driver
