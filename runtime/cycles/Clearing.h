// Area clearing for pocket, slot and face cycles: the tool-centre rings that clear a region,
// computed by polygon offsetting with the Clipper library (Debian libpolyclipping-dev), not by
// hand. Corners of the offset rings are rounded with chords that stay within `chordTolerance`
// of the true arc; the contour itself, where a cycle finishes it, is cut by the cycle with exact
// arcs.
#pragma once
#include "runtime/cycles/Pattern.h"

#include <string>
#include <vector>

namespace ncc {

using Polygon = std::vector<PlanePoint>;  // closed: the last point joins the first

struct ClearingSpec {
  Polygon contour;                // the region's outline (any orientation)
  std::vector<Polygon> islands;   // areas inside it that stay (any orientation)
  double toolRadius = 0;
  double stepover = 0;            // largest distance between rings, 0 < stepover <= 2 x toolRadius
  double allowance = 0;           // material left on the walls for finishing
  double chordTolerance = 0.001;  // mm
};

// The rings from the innermost outward (roughing from the middle to the wall), each closed and
// counter-clockwise. The tool run along them leaves nothing it can reach: where rings a whole
// stepover apart would leave material (between sharp corners, in the middle), the stepover
// shrinks and further rings follow, at most a tool radius apart. Climb milling with a clockwise
// spindle runs the rings as they are, conventional reversed. False with a message when the tool
// does not fit or the input is not a region.
bool clearingRings(const ClearingSpec &spec, std::vector<Polygon> &rings, std::string &err);

}  // namespace ncc
