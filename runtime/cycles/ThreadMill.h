// The thread-milling helix the Heidenhain (262-267, HeiThreadMill.cpp) and Sinumerik (CYCLE70,
// SinThreadMill.cpp) entries share: docs/CYCLES.md "Heidenhain thread milling".
#pragma once
#include "runtime/cycles/Library.h"
#include "runtime/cycles/Mill.h"

#include <string>

namespace ncc::entry {

// A thread job in the hole's own frame: the centre at the origin, depths d >= 0 measured from
// the surface into the material (the level of depth d is surface + dir * d).
struct Thread {
  double surface = 0, dir = -1, zsc = 0, z2 = 0;
  double radius = 0;  // the radius the milling feed refers to (the nominal radius Q335 / 2)
  double pitch = 0;   // |Q239|
  double centre = 0;  // the tool-centre circle: radius - r inside, radius + r outside
  double start = 0;   // the start point on +x: 0 (the hole's centre) or outside the stud (267)
  bool ccw = true;    // the turning sense of the helix about the tool axis
  double pre = 0, mill = 0, approach = 0;  // feeds Q253 (0: rapid), Q207 (at the cutting edge), Q512
  double level(double d) const { return surface + dir * d; }
};

// One helix from depth `from` to depth `to`: along the axis at `pre` to the starting plane, the
// compensating move, the tangential approach (a helical half circle climbing with the helix's
// slope), |to - from| / pitch turns at the milling feed (referred to the cutting edge: the
// tool-centre feed is mill x centre / radius), the tangential departure back to the start point's
// radius at `approach`.
void helix(Mill &m, const Thread &t, double from, double to);

// The Sinumerik thread pitch in mm (SinThreadMill.cpp; CYCLE70 and CYCLE78): _PIT by _PITA, mm (0,
// 1), threads per inch (2), inches (3) or a module (4).
bool sinPitchMm(const CycleArgs &a, double &pitch, std::string &err);

}  // namespace ncc::entry
