// ncc canon-diff and ncc machine.
#include "backends/emit/ControllerTable.h"
#include "backends/emit/Emitter.h"
#include "runtime/CanonDiff.h"
#include "utils/ncc/Driver.h"

#include <fmt/format.h>

namespace ncc::driver {

int cmdCanonDiff(int argc, char **argv) {
  Session s;
  std::string a, b, level;
  double tol = 1e-4;
  po::options_description desc("ncc canon-diff options");
  desc.add_options()
      ("first", po::value(&a)->required(), "first trace (e.g. LinuxCNC rs274 output)")
      ("second", po::value(&b)->required(), "second trace (e.g. ncc run --trace=canon output)")
      ("level", po::value(&level)->default_value("machine"), "machine (motion in machine mm) or program (commands as printed)")
      ("tolerance", po::value(&tol)->default_value(1e-4), "numeric tolerance in program units");
  po::positional_options_description pos;
  pos.add("first", 1).add("second", 1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc canon-diff A B [--level=machine|program]");
  if (rc >= 0) return rc;
  CanonDiffOptions o;
  if (level == "machine") o.level = CanonDiffLevel::Machine;
  else if (level == "program") o.level = CanonDiffLevel::Program;
  else {
    std::fprintf(stderr, "ncc: error: unknown level '%s'\n", level.c_str());
    return kExitUsage;
  }
  o.tolerance = tol;
  uint32_t fa = s.open(a), fb = s.open(b);
  if (!fa || !fb) return kExitErrors;
  std::string report;
  bool same = canonDiff(s.sm.text(fa), s.sm.text(fb), o, report);
  if (!same) {
    std::fprintf(stderr, "%s\n", report.c_str());
    return kExitErrors;
  }
  return kExitOk;
}

int cmdMachine(int argc, char **argv) {
  Session s;
  bool printDefault = false;
  std::string check;
  po::options_description desc("ncc machine options");
  desc.add_options()
      ("print-default", po::bool_switch(&printDefault), "print the embedded default machine description")
      ("check", po::value(&check), "parse a machine description file and report errors");
  po::positional_options_description pos;
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc machine [--print-default] [--check FILE]");
  if (rc >= 0) return rc;
  if (printDefault) {
    std::fputs(Machine::builtinDefaultText(), stdout);
    return kExitOk;
  }
  if (!check.empty()) {
    Machine m;
    if (!s.loadMachine(check, m)) return kExitErrors;
    // The [emit.*] values as the emitters will read them (translate reports the same).
    bool ok = true;
    for (emit::Target t : {emit::Target::ISO, emit::Target::Sinumerik, emit::Target::Nc200}) {
      emit::ControllerStyle style = emit::defaultStyle(t);
      ok = emit::applyMachineSection(m, style, s.diags) && ok;
    }
    if (!ok) return kExitErrors;
    std::printf("%s: ok (machine '%s')\n", check.c_str(), m.name.c_str());
    // The axes with the controller's names (a named axis: NAME=slot).
    std::string axes;
    for (int i = 0; i < kAxes; ++i)
      if (m.axes[i].present)
        axes += " " + (m.axes[i].name.empty() ? std::string(1, kAxisLetters[i]) : m.axes[i].name + "=" + kAxisLetters[i]) +
                (m.axes[i].rotary ? " (rotary)" : "");
    std::printf("axes:%s\n", axes.c_str());
    return kExitOk;
  }
  std::fprintf(stderr, "ncc: error: nothing to do (see ncc machine --help)\n");
  return kExitUsage;
}

}  // namespace ncc::driver
