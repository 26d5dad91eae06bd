// LinuxCNC's lathe contour cycles G70, G71 (.1 .2) and G72 (.1 .2) of `.ngc` programs: the cut
// pattern rs274 2.9 makes from the profile its Q subroutine describes (docs/CYCLES.md "LinuxCNC
// G70-G72"). It differs from the Fanuc/808D stock removal (Turning.h) in every step, so ncc
// follows rs274's output move for move: the profile is normalised by mirroring (and for G72 a
// quarter turn) so it runs towards -Z and -X, the finishing allowance D is a normal offset of the
// whole profile (rounded at convex corners), the layers start at the start point's X and go down
// by I, each cut retracts by R at 45 degrees, and pockets are cut one after another as the layers
// reach them. Pure geometry on a captured contour (runtime/cycles/Contour.h, G18: a = Z, b = X);
// the executor emits the moves.
#pragma once
#include "runtime/cycles/Contour.h"

#include <string>
#include <vector>

namespace ncc {

struct Rs274Turning {
  int cycle = 71;  // 70, 71 or 72
  int sub = 0;     // G71.1/G72.1: 1 (no pockets), G71.2/G72.2: 2 (only the pockets)
  // Words of the cycle block, mm: D the finishing distance (G70: of the first pass), E that of the
  // last pass, I the depth of cut, P the number of passes (G70), R the retract, U W a shift of the
  // profile along X and Z.
  double d = 0, e = 0, i = 1, passes = 1, r = 0.5, u = 0, w = 0;
};

// The moves (rapids, lines, arcs; feed 0: the modal feed) from the contour's start, which is the
// cycle block's X Z. False with `err` where rs274 stops with "G7X error: ...".
bool rs274Turning(const Contour &c, const Rs274Turning &s, std::vector<ContourElem> &out, std::string &err);

}  // namespace ncc
