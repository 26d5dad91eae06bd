// Regions bounded by lines and arcs, kept exact (nothing sampled): the boundary of a Heidenhain
// SL contour's region (its pockets united, or two intersected, less its islands) and the walls of
// the tool-centre region that keeps a distance d from that boundary (cycle 24's finishing rings,
// docs/CYCLES.md "Heidenhain side finishing (cycle 24)"). Both are built the same way: the
// candidate elements are split where they meet, a piece stays when the region lies on one side of
// it and not on the other (tested a hair to each side of its middle), and the pieces that stay
// are linked into loops, the pieces of one element joined again.
#pragma once
#include "runtime/CutterComp.h"
#include "runtime/cycles/ContourFormula.h"

#include <string>
#include <vector>

namespace ncc {

// A closed path: each element starts where the one before it ends, the last ends at the first's
// start (arcs: dir +1 counter-clockwise, -1 clockwise; an arc ending at its start is a full circle).
using ArcLoop = std::vector<PathElem>;

// Whether p lies inside the loop (a non-zero winding number, as Clipper's pftNonZero).
bool insideLoop(const ArcLoop &loop, Point2 p);

// An SL contour's region: inside a pocket (inside both when `intersect`: the first pocket starts
// inside the second, L9140-L9173), outside every island; or a contour formula's.
struct ArcRegion {
  std::vector<ArcLoop> pockets, islands;
  bool intersect = false;
  // A contour formula's region (root >= 0): the formula over `pockets`, the k-th the formula's
  // capture k (ContourFormula.h); `intersect` and `islands` are then unused.
  ContourFormula formula;
  bool contains(Point2 p) const;
};

// The region's boundary: loops with the region on their left (outer walls counter-clockwise,
// islands clockwise). False with a message when the pieces do not close into loops.
bool regionBoundary(const ArcRegion &region, std::vector<ArcLoop> &out, std::string &err);

// The distance from p to the nearest point of the loops.
double distanceTo(const std::vector<ArcLoop> &loops, Point2 p);

// The points of `region` at least `d` from its boundary (the loops regionBoundary gave): where the
// centre of a tool of radius d may stand.
struct ToolCentreRegion {
  const ArcRegion &region;
  const std::vector<ArcLoop> &boundary;
  double d;
  bool contains(Point2 p) const;
};

// The tool-centre region's boundary, the region on the left: each boundary element offset by d
// into the region, an arc of radius d about each corner the tool goes round (the region turning
// right), cut away wherever it comes nearer than d to another part of the boundary (concave
// corners, narrow places, islands near walls or each other). Empty when the tool fits nowhere.
bool toolCentreBoundary(const ToolCentreRegion &centres, std::vector<ArcLoop> &out, std::string &err);

}  // namespace ncc
