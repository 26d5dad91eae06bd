// The probe-results file (docs/PROBING.md): what a simulated probe meets, one line per probe move
// of the run, in order. The executor takes the next line at each G38.x and stops the move where
// the line says (runtime/ExecutorProbe.cpp).
#pragma once
#include "ir/Diagnostics.h"
#include "ir/MotionIR.h"

#include <array>
#include <string>
#include <vector>

namespace ncc {

struct ProbeOutcome {
  bool tripped = true;          // `trip` / `end`; false: `miss`
  std::array<bool, kAxes> has{};  // the axes the line gives
  AxisVec at{};                 // program coordinates and units of the probe block
  SourceLoc loc;                // the line in the file
};

struct ProbeResults {
  std::string file;  // its name, for messages
  std::vector<ProbeOutcome> outcomes;
};

// Reads the file's text (registered in the SourceManager); errors are located diagnostics at
// its lines. False after an error.
bool parseProbeResults(const SourceManager &sm, uint32_t file, Diagnostics &diags, ProbeResults &out);

// Where on the straight move from `start` to `target` (program coordinates and units) the
// outcome stops it, as the fraction t of the move (0 < t <= 1): 1 for a miss or a trip without
// axes; else the given axes must lie on the move (within 0.0001) and fix the point. False with
// the reason in `err`.
bool probeStopFraction(const ProbeOutcome &o, const AxisVec &start, const AxisVec &target, double &t, std::string &err);

}  // namespace ncc
