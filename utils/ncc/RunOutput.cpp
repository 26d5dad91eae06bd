#include "utils/ncc/RunOutput.h"

#include "runtime/CanonTrace.h"
#include "runtime/Executor.h"
#include "runtime/ProbeResults.h"
#include "runtime/Sinks.h"
#include "ir/FileCommands.h"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace ncc::driver {

int parseArgs(int argc, char **argv, po::options_description &desc, po::positional_options_description &pos,
              po::variables_map &vm, const char *usage) {
  desc.add_options()("help,h", "show this help");
  try {
    // allow_long_disguise accepts -Werror as well as --Werror (compiler habit).
    po::store(po::command_line_parser(argc, argv)
                  .options(desc)
                  .positional(pos)
                  .style(po::command_line_style::default_style | po::command_line_style::allow_long_disguise)
                  .run(),
              vm);
    if (vm.count("help")) {
      std::cout << "usage: " << usage << "\n\n" << desc << "\n";
      return kExitOk;
    }
    po::notify(vm);
  } catch (const po::error &e) {
    std::cerr << "ncc: error: " << e.what() << "\nusage: " << usage << "\n";
    return kExitUsage;
  }
  return -1;
}

void addRunTimeOptions(po::options_description &desc, RunTimeOptions &o) {
  desc.add_options()
      ("machine", po::value(&o.machine)->default_value("default"), "machine description: 'default' or a file")
      ("max-loop-iterations", po::value(&o.limits.maxLoopIterations)->default_value(o.limits.maxLoopIterations),
       "stop a loop after this many iterations")
      ("max-call-depth", po::value(&o.limits.maxCallDepth)->default_value(o.limits.maxCallDepth), "subprogram nesting limit")
      ("max-seconds", po::value(&o.limits.maxSeconds)->default_value(o.limits.maxSeconds), "run-time limit in seconds")
      ("probe-results", po::value(&o.probeResults), "where each probe move (G38.2-G38.5) stops: a probe-results file (docs/PROBING.md)")
      ("sandbox", po::value(&o.sandbox), "the folder Sinumerik file commands (WRITE, READ, DELETE, ISFILE, FILEINFO …) work in; without it they are errors")
      ("diagnostics-format", po::value(&o.diagnosticsFormat)->default_value("text"), "text|json")
      ("Werror", po::bool_switch(&o.werror), "treat warnings as errors");
}

bool applySandbox(const RunTimeOptions &o, Diagnostics &diags) {
  if (o.sandbox.empty()) return true;
  std::error_code ec;
  if (!std::filesystem::is_directory(o.sandbox, ec)) {
    diags.error({}, fmt::format("--sandbox '{}' is not a folder", o.sandbox), "options");
    return false;
  }
  setFileSandbox(o.sandbox);
  return true;
}

void applyDiagnosticsOptions(const RunTimeOptions &o, Diagnostics &diags) {
  diags.setFormat(o.diagnosticsFormat == "json" ? Diagnostics::Format::Json : Diagnostics::Format::Text);
  diags.setWarningsAsErrors(o.werror);
}

bool loadProbeResults(const RunTimeOptions &o, SourceManager &sm, Diagnostics &diags, Machine &machine) {
  if (o.probeResults.empty()) return true;
  uint32_t f = sm.addFile(o.probeResults);
  if (!f) diags.error({}, fmt::format("cannot read '{}'", o.probeResults));
  auto results = std::make_shared<ProbeResults>();
  if (!f || !parseProbeResults(sm, f, diags, *results)) return false;
  machine.probeResults = std::move(results);
  return true;
}

void addRunOutputOptions(po::options_description &desc, RunOutputArgs &a) {
  desc.add_options()
      ("trace", po::value(&a.trace), "write a trace: canon (LinuxCNC rs274 format, machine coordinates) or jsonl")
      ("output,o", po::value(&a.out), "trace file (default: standard output)")
      ("plot", po::value(&a.plot), "write an SVG plot of the toolpath")
      ("samples", po::value(&a.samples), "write CSV samples of the planned motion")
      ("plot-velocity", po::value(&a.velocityPlot), "write an SVG plot of path speed and acceleration over time")
      ("sample-period", po::value(&a.period)->default_value(0.01), "sample period in seconds")
      ("quiet,q", po::bool_switch(&a.quiet),
       "print neither the summary nor the progress line (and skip planning unless --plot/--samples/--plot-velocity)");
}

static RunOutputOptions outputOptions(const RunOutputArgs &a, const std::string &programName) {
  RunOutputOptions ro;
  ro.svgPath = a.plot;
  ro.csvPath = a.samples;
  ro.velocityPath = a.velocityPlot;
  ro.samplePeriod = a.period;
  ro.programName = programName;
  return ro;
}

RunOutputSet::RunOutputSet(const Machine &machine, const RunOutputArgs &args, const std::string &programName)
    : args_(args), outputs_(machine, outputOptions(args, programName)) {}
RunOutputSet::~RunOutputSet() = default;

int RunOutputSet::checkUsage(const RunOutputArgs &a) {
  if (a.trace.empty() || a.trace == "canon" || a.trace == "jsonl") return -1;
  std::fprintf(stderr, "ncc: error: unknown trace format '%s' (expected canon or jsonl)\n", a.trace.c_str());
  return kExitUsage;
}

bool RunOutputSet::open(Diagnostics &diags) {
  // The planner runs for the summary, the plot and the samples; a quiet trace-only run skips it.
  if (!args_.quiet || !args_.plot.empty() || !args_.samples.empty() || !args_.velocityPlot.empty()) tee_.add(&outputs_);
  // The trace goes to a temporary file renamed on success, or to stdout.
  std::FILE *traceStream = stdout;
  if (!args_.trace.empty() && !args_.out.empty() && args_.out != "-") {
    traceFile_ = std::make_unique<AtomicFile>(args_.out);
    if (!traceFile_->ok()) {
      diags.error({}, fmt::format("cannot create '{}'", args_.out));
      return false;
    }
    traceStream = traceFile_->stream();
  }
  if (args_.trace == "canon") trace_ = std::make_unique<CanonTraceWriter>(traceStream);
  else if (args_.trace == "jsonl") trace_ = std::make_unique<JsonlTraceWriter>(traceStream);
  if (trace_) tee_.add(trace_.get());
  if (ProgressLine::wanted(args_.quiet, isatty(STDERR_FILENO))) {
    progress_ = std::make_unique<ProgressLine>(stderr);
    tee_.add(progress_.get());
  }
  return true;
}

void RunOutputSet::watch(const Executor &exec) {
  if (progress_) progress_->watch(exec);
}

int RunOutputSet::finish(bool ok, Diagnostics &diags) {
  ok &= tee_.finish(diags);
  std::fflush(stdout);
  if (ok && traceFile_) {
    std::string err;
    if (!traceFile_->commit(err)) {
      diags.error({}, err);
      ok = false;
    }
  }
  bool traceToStdout = !args_.trace.empty() && (args_.out.empty() || args_.out == "-");
  if (ok && !args_.quiet && !traceToStdout) std::fputs(outputs_.summaryText().c_str(), stdout);
  return ok && !diags.hasErrors() ? kExitOk : kExitErrors;
}

// ---------------------------------------------------------------- progress line
ProgressLine::ProgressLine(std::FILE *out) : out_(out), start_(std::chrono::steady_clock::now()) {}

// 1234567 -> "1,234,567" (fmt's {:L} follows the C locale, which groups nothing).
static std::string grouped(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string ProgressLine::format(uint64_t blocks, double seconds) {
  uint64_t rate = seconds > 0 ? (uint64_t)(blocks / seconds) : 0;
  return fmt::format("\r{} blocks  {} blocks/s  {:.1f} s\x1b[K", grouped(blocks), grouped(rate), seconds);
}

void ProgressLine::record(const MotionRecord &r) {
  if (r.loc.line != last_.line || r.loc.file != last_.file) {
    ++blocks_;
    last_ = r.loc;
  }
  if (++records_ % kCheckEvery == 0) tick();
}

void ProgressLine::tick() {
  double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (t < kDelay || t - lastDraw_ < kRedraw) return;
  lastDraw_ = t;
  drawn_ = true;
  std::fputs(format(exec_ ? exec_->blockCount() : blocks_, t).c_str(), out_);
  std::fflush(out_);
}

bool ProgressLine::finish(Diagnostics &) {
  if (drawn_) std::fputs("\r\x1b[K", out_);
  drawn_ = false;
  return true;
}

}  // namespace ncc::driver
