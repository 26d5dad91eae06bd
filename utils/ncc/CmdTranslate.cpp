// ncc translate: run the program to Motion IR and print it for another controller;
// --verify runs the output back through the pipeline and compares the two paths.
#include "backends/emit/ControllerTable.h"
#include "backends/emit/Emitter.h"
#include "ir/MotionCompare.h"
#include "utils/ncc/Driver.h"
#include "utils/ncc/TranslateStructured.h"

#include <fmt/format.h>

#include <cstdio>
#include <memory>

namespace ncc::driver {

bool samePaths(Session &s, const MotionBuffer &source, const MotionBuffer &back, double tolerance, bool rapidLegs) {
  PathCompareOptions po;
  po.tolerance = tolerance;
  po.rapidLegs = rapidLegs;
  std::string report;
  if (comparePaths(source.records, back.records, po, report)) return true;
  s.diags.error({}, "verification failed: " + report);
  return false;
}

namespace {
// The error limit of the session's diagnostics (Diagnostics' default: translate sets none).
constexpr unsigned kSessionErrorLimit = 50;

// Replays what a collecting Diagnostics holds into the session's, in order.
void replay(const Diagnostics &from, Diagnostics &to) {
  for (const Diagnostic &d : from.collected()) to.report(d.severity, d.loc, d.message, d.rule);
}

// Copies a spooled output to standard output.
bool copyOut(std::FILE *spool) {
  std::rewind(spool);
  char buf[1 << 16];
  bool ok = true;
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, spool)) > 0;) ok &= std::fwrite(buf, 1, n, stdout) == n;
  return ok && !std::ferror(spool);
}

// Without --verify the program's records go from the run straight into the emitter, and its
// text straight into a temporary file (the output's own, renamed at the end; for standard output
// an anonymous one copied out at the end), so neither the Motion IR stream nor the program text
// is ever held whole: with a streamed front end (ISO flat programs, ADEM CLData) the memory stays
// flat whatever the length (docs/CLDATA.md "Streaming", bench/cldata.sh). What the reader sees is
// what the buffered translation gave: the emitter's diagnostics wait in a collecting Diagnostics
// until the run is over (a refusal does not stop the run, and a failed run reports none of them),
// and a failed translation writes nothing. Returns -1 when it cannot start (the output cannot be
// created, the machine's [emit] section is bad): the buffered path then reports it as before.
int translateStreamed(Session &s, uint32_t f, const emit::EmitOptions &eo, const std::string &out) {
  const bool toStdout = out.empty() || out == "-";
  std::unique_ptr<AtomicFile> file;
  std::unique_ptr<std::FILE, int (*)(std::FILE *)> anon(toStdout ? std::tmpfile() : nullptr, &std::fclose);
  if (!toStdout) file = std::make_unique<AtomicFile>(out);
  std::FILE *spool = toStdout ? anon.get() : file->stream();
  if (!spool) return -1;
  Diagnostics emitDiags(s.sm);
  emitDiags.setCollect(true);
  emitDiags.setErrorLimit(kSessionErrorLimit + 1);  // one more: the session then says "too many errors"
  auto emitter = emit::ProgramEmitter::create(s.machine, eo, spool, emitDiags);
  if (!emitter) return -1;
  if (!s.execute(f, *emitter)) return kExitErrors;
  bool ok = emitter->finish(emitDiags);
  replay(emitDiags, s.diags);
  if (!ok) return kExitErrors;
  if (toStdout) {
    if (copyOut(spool)) return s.exitCode();
    s.diags.error({}, "cannot write the translation to standard output");
    return kExitErrors;
  }
  std::string err;
  if (file->commit(err)) return s.exitCode();
  s.diags.error({}, err);
  return kExitErrors;
}
}  // namespace

int cmdTranslate(int argc, char **argv) {
  Session s;
  std::string file, to, out;
  bool verify = false, noComments = false, checkTravel = false, binary = false, keepStructure = false;
  double tol = 1e-3;
  po::options_description desc("ncc translate options");
  desc.add_options()
      ("file", po::value(&file)->required(), "program to translate")
      ("to", po::value(&to)->required(), "target: iso|sinumerik|heidenhain|nc200, or CL records apt|cldata (ADEM)")
      ("binary", po::bool_switch(&binary), "with --to=cldata: the binary record file (8-byte cells) instead of the listing")
      ("output,o", po::value(&out), "output file (default: standard output)")
      ("verify", po::bool_switch(&verify), "run source and output through the motion pipeline; fail if the paths differ")
      ("tolerance", po::value(&tol)->default_value(1e-3), "--verify position tolerance in mm")
      ("no-comments", po::bool_switch(&noComments), "drop comments")
      ("keep-structure", po::bool_switch(&keepStructure),
       "keep loops, branches, variables and subprogram calls (iso <-> sinumerik; docs/EMIT.md)")
      ("check-travel", po::bool_switch(&checkTravel),
       "a move outside the machine's axis limits (machine coordinates) is an error");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("file", 1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc translate FILE --to=iso|sinumerik|heidenhain|nc200|apt|cldata [--binary] [-o OUT] [--verify] [--keep-structure]");
  if (rc >= 0) return rc;
  emit::EmitOptions eo;
  if (!emit::targetFromName(to, eo.target)) {
    std::fprintf(stderr, "ncc: error: unknown target '%s' (expected iso, sinumerik, heidenhain, nc200, apt or cldata)\n", to.c_str());
    return kExitUsage;
  }
  if (binary && eo.target != emit::Target::Adem) {
    std::fprintf(stderr, "ncc: error: --binary needs --to=cldata (only ADEM CLData has a binary form)\n");
    return kExitUsage;
  }
  if (verify && eo.target == emit::Target::Nc200) {
    // No NC-200 front end: the output cannot be run back (its header says it is unverified).
    std::fprintf(stderr, "ncc: error: --verify cannot read an NC-200 program back (ncc has no NC-200 front end)\n");
    return kExitUsage;
  }
  eo.binary = binary;
  eo.comments = !noComments;
  eo.checkTravel = checkTravel;
  eo.programName = file;
  uint32_t f = s.start(file);
  if (!f) return kExitErrors;
  if (keepStructure) return translateStructured(s, f, eo, out, verify, tol);
  if (!verify)
    if (int rc = translateStreamed(s, f, eo, out); rc >= 0) return rc;

  // --verify runs the translation back and compares it with the source's records: both held.

  MotionBuffer source;
  if (!s.execute(f, source)) return kExitErrors;
  std::string text;
  auto emitter = emit::ProgramEmitter::create(s.machine, eo, text, s.diags);
  if (!emitter) return kExitErrors;
  for (auto &r : source.records) emitter->record(r);
  if (!emitter->finish(s.diags)) return kExitErrors;

  if (verify) {
    // The output is read back by the target's own front end.
    static const char *const kExt[] = {".nc", ".mpf", ".h", ".apt", ".cld"};
    std::string name = (out.empty() || out == "-") ? std::string("<translated>") + kExt[(size_t)eo.target] : out;
    uint32_t tf = s.sm.addBuffer(name, text);
    std::string savedDialect = s.opts.dialect;
    s.opts.dialect = emit::targetName(eo.target);
    MotionBuffer back;
    bool ok = s.execute(tf, back);
    s.opts.dialect = savedDialect;
    if (!ok) {
      s.diags.error({}, "verification failed: the translated program does not run");
      return kExitErrors;
    }
    // A passport's rapid legs (rapid_split) change the rapid path on purpose: each leg is checked
    // to stay within the box of the source's rapid.
    bool rapidLegs = false;
    if (eo.target == emit::Target::ISO || eo.target == emit::Target::Sinumerik) {
      emit::ControllerStyle style = emit::defaultStyle(eo.target);
      Diagnostics quiet(s.sm);
      quiet.setCollect(true);
      emit::applyMachineSection(s.machine, style, quiet);
      rapidLegs = style.rapidSplit != emit::RapidSplit::Together;
    }
    if (!samePaths(s, source, back, tol, rapidLegs)) return kExitErrors;
    std::fprintf(stderr, "ncc: verified: %s and its translation give the same path\n", file.c_str());
  }
  if (!writeOutput(s, out, text)) return kExitErrors;
  return s.exitCode();
}

}  // namespace ncc::driver
