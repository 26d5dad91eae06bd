// What a front end needs to know of the cycle library (runtime/cycles/Library.h) to lower a
// vendor cycle call onto the `cycle` op (docs/IR.md §5.8): an entry's positional parameters and
// whether it is a position pattern. The library lives in runtime/, which front ends may not
// include, so the driver hands them its lookup (FrontendOptions::cycles).
#pragma once
#include <string_view>

namespace ncc {

// The Heidenhain touch probe's table (tchprobe.tp) as the machine file gives it ([controller]
// probe_feed, probe_fmax, probe_dist, probe_set_up, probe_prepos; docs/PROBING.md): what a front
// end needs to lower the probe cycles.
struct ProbeTable {
  double feed = 100;         // F: the probing feed, mm/min
  double fmax = 5000;        // FMAX: the feed between the probing points (and pre-positioning, below)
  double dist = 10;          // DIST: the longest probing path, mm
  double setUp = 2;          // SET_UP: the clearance before the probing point, added to Q320
  bool preposRapid = true;   // F_PREPOS: FMAX_MACHINE (pre-position at rapid) or FMAX_PROBE (at FMAX)
};

struct CycleSignature {
  const char *name = nullptr;    // "sin.CYCLE81"
  const char *params = nullptr;  // the positional parameter names, space-separated
  const char *strings = nullptr; // the STRING parameters (the others take numbers)
  bool pattern = false;          // a position pattern (HOLES1), not a machining cycle
  // The STRING parameter naming a contour the cycle cuts from (CYCLE95's NPP): the front end runs
  // that contour into a capture before the call (docs/IR.md §5.6 `use=keep`); null for none.
  const char *contour = nullptr;
};
// False when the library has no entry of that name.
using CycleLookup = bool (*)(std::string_view name, CycleSignature &out);

}  // namespace ncc
