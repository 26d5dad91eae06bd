// Lowering the Heidenhain touch-probe cycles (docs/PROBING.md "Heidenhain touch-probe cycles"):
// the parameters of one TCH PROBE definition and the builder that writes its NC IR ops: the
// positioning logic, the probing moves (LinuxCNC's G38.2 motion against the probe-results file),
// the results in Q150… and the datum or basic rotation written to the active preset.
#pragma once
#include "frontend/heidenhain/Parser.h"

#include <functional>
#include <map>

namespace ncc::hei {

struct ProbeCall {
  int number = 0;
  SourceLoc loc;                             // the TCH PROBE block
  std::map<std::string, ir::ExprPtr> given;  // "Q321" -> its value as written
  ProbeTable table;
  ir::Region *out = nullptr;
  std::set<std::string> *vars = nullptr;     // the scratch variables: declared by the main program
  std::function<bool(std::string, const char *)> error;  // a located error at the block
};

// One probe cycle's parameter list (in the order the control writes them) and its builder.
struct ProbeCycle {
  int number;
  const char *params;    // every parameter the cycle takes
  const char *optional;  // those with a default ("Q331=0 Q423=4")
  bool (*lower)(ProbeCall &c);
};
const ProbeCycle *findProbeCycle(int number);

// The old-style cycle 0 REFERENCE PLANE (`TCH PROBE 0.0 … Q5 X-` / `0.1 X+5 Y+0 Z-5`).
bool lowerReferencePlane(ProbeCall &c, int resultQ, char axis, int dir, ir::ExprPtr pre[3]);

}  // namespace ncc::hei
