// Deep-hole drilling in infeeds along the tool axis, shared by the Heidenhain cycles 205 and 264
// (and in the hole's frame of runtime/cycles/Mill.h): depths d >= 0 from the surface into the
// material, the level of depth d being surface + dir * d.
#pragma once
#include "runtime/cycles/Mill.h"

#include <string>
#include <vector>

namespace ncc {

struct PeckPlan {
  double surface = 0, dir = -1;
  double start = 0;        // the depth the first infeed counts from (the surface or 205's Q379)
  double depth = 0;        // the bottom
  double infeed = 0;       // the first infeed (<= 0: one pass)
  double decrement = 0, minInfeed = 0;  // each next infeed smaller by `decrement`, not below `minInfeed`
  double chipEvery = 0;    // > 0: chip breaks after this much travel and at each infeed's end
  double chipBack = 0;     // the chip break's rapid back
  double removal = 0;      // without chip breaks: the chip-removal depth (rapid there after each infeed)
  double advFirst = 0, advLast = 0;  // back down at rapid to this much above the depth reached,
                                     // evenly from the first re-entry to the last
  double feed = 0;
  double level(double d) const { return surface + dir * d; }
};

// The depths where the infeeds end, from `start` to `depth`: `infeed` (<= 0: one), each next
// smaller by `decrement` down to `minInfeed` (without a minimum never down to nothing). False with
// `err` beyond kMaxPecks infeeds.
bool infeedEnds(double start, double depth, double infeed, double decrement, double minInfeed, std::vector<double> &ends,
                std::string &err);

// Feeds from the tool's level to the bottom as the plan says; the tool ends there. False with
// `err` when the infeeds would be more than kMaxPecks.
bool peckDrill(Mill &m, const PeckPlan &p, std::string &err);

}  // namespace ncc
