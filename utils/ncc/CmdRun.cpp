// ncc run: compile, execute, drive the trajectory core; print the summary or a trace.
#include "runtime/CanonTrace.h"
#include "runtime/RunOutputs.h"
#include "runtime/Sinks.h"
#include "utils/ncc/Driver.h"

#include <fmt/format.h>

#include <memory>

namespace ncc::driver {

int cmdRun(int argc, char **argv) {
  Session s;
  std::string file, trace, out, plot, samples, velocityPlot;
  double period = 0.01;
  bool quiet = false;
  po::options_description desc("ncc run options");
  desc.add_options()
      ("file", po::value(&file)->required(), "program to run")
      ("trace", po::value(&trace), "write a trace: canon (LinuxCNC rs274 format, machine coordinates) or jsonl")
      ("output,o", po::value(&out), "trace file (default: standard output)")
      ("plot", po::value(&plot), "write an SVG plot of the toolpath")
      ("samples", po::value(&samples), "write CSV samples of the planned motion")
      ("plot-velocity", po::value(&velocityPlot), "write an SVG plot of path speed and acceleration over time")
      ("sample-period", po::value(&period)->default_value(0.01), "sample period in seconds")
      ("quiet,q", po::bool_switch(&quiet), "do not print the summary (and skip planning unless --plot/--samples/--plot-velocity)");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("file", 1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc run FILE [options]");
  if (rc >= 0) return rc;
  if (!trace.empty() && trace != "canon" && trace != "jsonl") {
    std::fprintf(stderr, "ncc: error: unknown trace format '%s' (expected canon or jsonl)\n", trace.c_str());
    return kExitUsage;
  }
  uint32_t f = s.start(file);
  if (!f) return kExitErrors;

  RunOutputOptions ro;
  ro.svgPath = plot;
  ro.csvPath = samples;
  ro.velocityPath = velocityPlot;
  ro.samplePeriod = period;
  ro.programName = file;
  RunOutputs outputs(s.machine, ro);
  MotionTee tee;
  // The planner runs for the summary, the plot and the samples; a quiet trace-only run skips it.
  bool plan = !quiet || !plot.empty() || !samples.empty() || !velocityPlot.empty();
  if (plan) tee.add(&outputs);

  // The trace goes to a temporary file renamed on success, or to stdout.
  std::unique_ptr<AtomicFile> traceFile;
  std::FILE *traceStream = stdout;
  if (!trace.empty() && !out.empty() && out != "-") {
    traceFile = std::make_unique<AtomicFile>(out);
    if (!traceFile->ok()) {
      s.diags.error({}, fmt::format("cannot create '{}'", out));
      return kExitErrors;
    }
    traceStream = traceFile->stream();
  }
  std::unique_ptr<MotionSink> traceSink;
  if (trace == "canon") traceSink = std::make_unique<CanonTraceWriter>(traceStream);
  else if (trace == "jsonl") traceSink = std::make_unique<JsonlTraceWriter>(traceStream);
  if (traceSink) tee.add(traceSink.get());

  uint64_t blocks = 0;
  bool ok = s.execute(f, tee, &blocks);
  // Motion IR text has no blocks to count: the summary counts the source positions of the records.
  if (s.kindOf(f) != SourceKind::Motion) outputs.setBlockCount(blocks);
  ok &= tee.finish(s.diags);
  std::fflush(stdout);
  if (ok && traceFile) {
    std::string err;
    if (!traceFile->commit(err)) {
      s.diags.error({}, err);
      ok = false;
    }
  }
  bool traceToStdout = !trace.empty() && (out.empty() || out == "-");
  if (ok && !quiet && !traceToStdout) std::fputs(outputs.summaryText().c_str(), stdout);
  return ok && !s.diags.hasErrors() ? kExitOk : kExitErrors;
}

}  // namespace ncc::driver
