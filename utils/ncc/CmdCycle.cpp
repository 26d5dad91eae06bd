// ncc cycle: run one cycle of the library (runtime/cycles/Library.h) alone and print its Motion
// IR, to see what a CYCLE83 or a CYCL DEF 200 with given parameters does before a program uses it.
//   ncc cycle CYCLE [NAME=VALUE…] [PATTERN [NAME=VALUE…]] [--at X,Y,Z] [--feed F] [--speed S]
//             [--tool-radius R] [--ccw]
#include "runtime/Executor.h"
#include "utils/ncc/Driver.h"

#include <fmt/format.h>

#include <cstdlib>

namespace ncc::driver {

namespace {
// NAME=VALUE into args: a number, or text (quotes optional) for STRING parameters.
bool addArg(const std::string &tok, CycleArgs &args) {
  size_t eq = tok.find('=');
  if (eq == 0 || eq == std::string::npos) return false;
  std::string k = tok.substr(0, eq), v = tok.substr(eq + 1);
  char *end = nullptr;
  double d = std::strtod(v.c_str(), &end);
  if (!v.empty() && end && *end == 0 && std::isfinite(d)) args.num[k] = d;
  else args.text[k] = v.size() >= 2 && v.front() == '"' && v.back() == '"' ? v.substr(1, v.size() - 2) : v;
  return true;
}
}  // namespace

int cmdCycle(int argc, char **argv) {
  Session s;
  std::vector<std::string> tokens;
  std::string at, out, plane = "G17";
  double feed = 0, speed = 0, toolRadius = 0;
  bool list = false, ccw = false;
  po::options_description desc("ncc cycle options");
  desc.add_options()
      ("tokens", po::value(&tokens)->multitoken(), "CYCLE [NAME=VALUE…] [PATTERN [NAME=VALUE…]]")
      ("list", po::bool_switch(&list), "list the cycles of the library with their parameters")
      ("at", po::value(&at), "start position X,Y,Z in mm (default 0,0,0; the tool rapids there first)")
      ("feed", po::value(&feed), "modal feed before the cycle, mm/min")
      ("speed", po::value(&speed), "spindle speed before the cycle, rpm (the spindle turns clockwise)")
      ("plane", po::value(&plane), "G17, G18 or G19")
      ("ccw", po::bool_switch(&ccw), "with --speed: the spindle turns counter-clockwise (M4)")
      ("tool-radius", po::value(&toolRadius), "radius of the tool in the spindle, mm (tool 1; pockets, slots, studs)")
      ("output,o", po::value(&out), "output file (default: standard output)");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("tokens", -1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc cycle CYCLE [NAME=VALUE…] [PATTERN [NAME=VALUE…]] [--at X,Y,Z]");
  if (rc >= 0) return rc;
  if (list) {
    std::string text;
    for (auto &d : cycleLibrary())
      text += fmt::format("{:<12} {:<32} {}\n", d.name, d.what, d.params);
    return writeOutput(s, out, text) ? kExitOk : kExitErrors;
  }
  if (tokens.empty()) {
    std::fprintf(stderr, "ncc: error: no cycle given (ncc cycle --list shows them)\n");
    return kExitUsage;
  }
  const CycleDef *cycle = nullptr, *pattern = nullptr;
  CycleArgs cycleArgs, patternArgs;
  for (auto &t : tokens) {
    if (t.find('=') == std::string::npos) {
      const CycleDef *d = findCycle(t);
      if (!d || (cycle && pattern)) {
        std::fprintf(stderr, "ncc: error: %s '%s' (ncc cycle --list shows the cycles)\n",
                     d ? "more than a cycle and a pattern:" : "unknown cycle", t.c_str());
        return kExitUsage;
      }
      (cycle ? pattern : cycle) = d;
      continue;
    }
    if (!cycle || !addArg(t, pattern ? patternArgs : cycleArgs)) {
      std::fprintf(stderr, "ncc: error: '%s': expected NAME=VALUE after a cycle name\n", t.c_str());
      return kExitUsage;
    }
  }
  if (pattern && !cycle->positions == !pattern->positions) {
    std::fprintf(stderr, "ncc: error: give one machining cycle and one position pattern\n");
    return kExitUsage;
  }
  if (pattern && cycle->positions) std::swap(cycle, pattern), std::swap(cycleArgs, patternArgs);
  std::array<double, 3> start{};
  if (!at.empty() && std::sscanf(at.c_str(), "%lf,%lf,%lf", &start[0], &start[1], &start[2]) != 3) {
    std::fprintf(stderr, "ncc: error: --at wants X,Y,Z\n");
    return kExitUsage;
  }
  ModeValue pl;
  if (plane == "G17") pl = ModeValue::XY;
  else if (plane == "G18") pl = ModeValue::ZX;
  else if (plane == "G19") pl = ModeValue::YZ;
  else {
    std::fprintf(stderr, "ncc: error: --plane wants G17, G18 or G19\n");
    return kExitUsage;
  }
  if (!s.setUp()) return kExitErrors;
  if (toolRadius < 0) {
    std::fprintf(stderr, "ncc: error: --tool-radius must not be negative\n");
    return kExitUsage;
  }
  if (toolRadius > 0) {
    ToolEdge edge;
    edge.radius = toolRadius;
    s.machine.addTool(1, edge);
  }
  std::string text;
  MotionTextWriter sink(text);  // the one Motion IR printer
  Executor exec(s.machine, sink, s.diags);
  // The state before the cycle: plane, feed, spindle, position.
  MachineCmd c;
  c.kind = CmdKind::Mode;
  c.modes[c.nmodes++] = pl;
  bool ok = exec.exec(c);
  if (toolRadius > 0) {  // tool 1 with that radius, changed into the spindle
    c = {}, c.kind = CmdKind::ToolSelect, c.set(Word::T, 1);
    ok = ok && exec.exec(c);
    c = {}, c.kind = CmdKind::ToolChange;
    ok = ok && exec.exec(c);
  }
  if (feed > 0) {
    c = {}, c.kind = CmdKind::Feed, c.set(Word::F, feed);
    ok = ok && exec.exec(c);
  }
  if (speed > 0) {
    c = {}, c.kind = CmdKind::Speed, c.set(Word::S, speed);
    ok = ok && exec.exec(c);
    c = {}, c.kind = CmdKind::Spindle, c.sub = ccw ? 2 : 1;
    ok = ok && exec.exec(c);
  }
  c = {}, c.kind = CmdKind::Move;
  for (int i = 0; i < 3; ++i) c.set((Word)i, start[i]);
  ok = ok && exec.exec(c);  // rapid (the start-up motion mode)
  ok = ok && exec.runCycle(*cycle, cycleArgs, pattern, pattern ? &patternArgs : nullptr, {});
  exec.finish(false);
  if (!ok || s.diags.hasErrors()) return kExitErrors;
  return writeOutput(s, out, text) ? kExitOk : kExitErrors;
}

}  // namespace ncc::driver
