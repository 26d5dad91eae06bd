// ncc translate: run the program to Motion IR and print it for another controller;
// --verify runs the output back through the pipeline and compares the two paths.
#include "backends/emit/ControllerTable.h"
#include "backends/emit/Emitter.h"
#include "ir/MotionCompare.h"
#include "utils/ncc/Driver.h"
#include "utils/ncc/TranslateStructured.h"

#include <fmt/format.h>

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
