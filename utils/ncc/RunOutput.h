// What `ncc run` and a compiled program's executable (ncc compile --emit=exe, ncrt_main) share:
// the run-time options (machine, limits, diagnostics), the outputs (summary, traces, plots,
// samples) with their options, and the progress line. Needs no front end and no LLVM.
#pragma once
#include "ir/Diagnostics.h"
#include "ir/ExecLimits.h"
#include "ir/MotionIR.h"
#include "runtime/Machine.h"
#include "runtime/RunOutputs.h"

#include <boost/program_options.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

namespace ncc {
class Executor;
}

namespace ncc::driver {

namespace po = boost::program_options;

// Exit codes (README "Exit codes").
constexpr int kExitOk = 0, kExitErrors = 1, kExitUsage = 2;

// Parses argv for a subcommand; prints help/usage errors. Returns -1 to continue, else an exit code.
int parseArgs(int argc, char **argv, po::options_description &desc, po::positional_options_description &pos,
              po::variables_map &vm, const char *usage);

// Options that act when a program runs, compiled or not.
struct RunTimeOptions {
  std::string machine = "default";
  ExecLimits limits;
  std::string diagnosticsFormat = "text";
  bool werror = false;
  std::string probeResults;  // what the simulated probe meets (docs/PROBING.md)
  std::string sandbox;       // the folder of Sinumerik file commands (ir/FileCommands.h); empty: none
};
void addRunTimeOptions(po::options_description &desc, RunTimeOptions &o);
// Applies the diagnostics options.
void applyDiagnosticsOptions(const RunTimeOptions &o, Diagnostics &diags);
// Makes --sandbox the folder of the file commands; false after reporting one that is no folder.
bool applySandbox(const RunTimeOptions &o, Diagnostics &diags);
// Reads --probe-results into the machine (its file joins sm); false after reporting.
bool loadProbeResults(const RunTimeOptions &o, SourceManager &sm, Diagnostics &diags, Machine &machine);

struct RunOutputArgs {
  std::string trace, out, plot, samples, velocityPlot;
  double period = 0.01;
  bool quiet = false;
};
void addRunOutputOptions(po::options_description &desc, RunOutputArgs &a);

// The progress line on stderr for long runs: blocks done (the executor's count; without one, a
// block per change of the records' source line), rate, elapsed. Reads the clock every
// kCheckEvery records and redraws at most every kRedraw seconds, from kDelay seconds on.
// finish() erases it.
class ProgressLine : public MotionSink {
public:
  static constexpr uint64_t kCheckEvery = 4096;
  static constexpr double kDelay = 1.0, kRedraw = 0.25;
  // Shown when not quiet and stderr is a terminal (the caller asks isatty, tests inject it).
  static bool wanted(bool quiet, bool stderrIsTerminal) { return !quiet && stderrIsTerminal; }
  // "\r12,345 blocks  6,172 blocks/s  2.0 s" (then erase to the end of the line).
  static std::string format(uint64_t blocks, double seconds);

  explicit ProgressLine(std::FILE *out);
  void watch(const Executor &exec) { exec_ = &exec; }
  void record(const MotionRecord &r) override;
  bool finish(Diagnostics &diags) override;

private:
  void tick();
  std::FILE *out_;
  const Executor *exec_ = nullptr;
  std::chrono::steady_clock::time_point start_;
  double lastDraw_ = 0;
  uint64_t records_ = 0, blocks_ = 0;
  SourceLoc last_{};
  bool drawn_ = false;
};

// The sinks of a run: planner + summary + files, the trace, the progress line.
class RunOutputSet {
public:
  RunOutputSet(const Machine &machine, const RunOutputArgs &args, const std::string &programName);
  ~RunOutputSet();
  // kExitUsage after printing the problem, else -1.
  static int checkUsage(const RunOutputArgs &args);
  // Creates the trace file; false after reporting.
  bool open(Diagnostics &diags);
  MotionSink &sink() { return tee_.single() ? *tee_.single() : tee_; }
  void setBlockCount(uint64_t n) { outputs_.setBlockCount(n); }
  // The executor whose blocks the progress line counts (when there is one).
  void watch(const Executor &exec);
  // Finishes the sinks, commits the trace file and prints the summary: the exit code.
  int finish(bool ok, Diagnostics &diags);

private:
  RunOutputArgs args_;
  MotionTee tee_;                       // outputs_ (when planning), trace_, progress_
  RunOutputs outputs_;
  std::unique_ptr<ProgressLine> progress_;
  std::unique_ptr<AtomicFile> traceFile_;  // trace_ writes to it: declared first, destroyed last
  std::unique_ptr<MotionSink> trace_;
};

}  // namespace ncc::driver
