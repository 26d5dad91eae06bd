// Peck grooving and drilling on a lathe (ISO G74 along Z, G75 along X; later Sinumerik grooving):
// a row of grooves, each cut in pecks along one axis, the next one shifted across. Pure geometry:
// the executor (runtime/ExecutorTurning.cpp) maps the axes and emits the moves.
#pragma once
#include "runtime/cycles/Contour.h"

#include <string>

namespace ncc {

// Coordinates in mm: `a` along the pecks (G74: Z), `b` across (G74: X, a radius).
struct PeckGroove {
  Pt2 start;           // where the tool stands: the first groove starts here, the cycle ends here
  Pt2 end;             // the last groove's bottom
  double peck = 0;     // depth per peck along a (> 0)
  double shift = 0;    // distance between grooves along b (> 0 when end.b differs from start.b)
  double retract = 0;  // back off after each peck but the last (chip breaking), >= 0
  double relief = 0;   // at the bottom of every groove but the first: back off across, >= 0
};

// The moves (Rapid or Line elements, from the start) of the whole cycle. Each groove: pecks of at
// most `peck` towards end.a, after each one a rapid back by `retract` (never behind start.a), the
// next feed from there; at the bottom a rapid `relief` back towards start.b (not on the first
// groove, whose both walls are uncut; never beyond start.b), a rapid out to start.a and across to
// the next groove, at most `shift` further and never beyond end.b. At the end a rapid to start.
// False with `err` when the words cannot describe a cycle (no depth, a zero peck or shift, a
// negative amount, more than a million moves).
bool peckGrooves(const PeckGroove &g, std::vector<ContourElem> &out, std::string &err);

}  // namespace ncc
