// Heidenhain SL side finishing (cycle 24) and contour train (cycle 25): the walls of a region
// (Region.h) finished once round each, and an open contour milled on its RL/RR side, level by
// level (docs/CYCLES.md "Heidenhain side finishing (cycle 24)", docs/HEIDENHAIN.md). Plane coordinates as
// Region.h's; levels on the tool axis in the coordinates of `at`.
#pragma once
#include "runtime/CutterComp.h"
#include "runtime/cycles/Region.h"

namespace ncc {

// Cycle 24 (L9671-L9840): each wall of the region (the outer walls and the islands' walls of
// every separate area) on the tool-centre ring `toolRadius + finishAllowance` off it, exact lines
// and arcs from the sub-contours' own elements (ArcRegion.h), all its levels before the next;
// onto the ring and off it on tangential quarter helices.
struct SideFinishJob {
  int plane = 0;
  std::array<double, 3> at{};
  double surface = 0, depth = 0, infeed = 0;  // depth > 0 below the surface; infeed 0: one level
  double clearance = 0, height = 0;           // Q6 (over the surface), Q7 (absolute)
  double toolRadius = 0, finishAllowance = 0;
  double plungeFeed = 0, feed = 0;  // 0: the programmed feed
  bool ccw = true;                  // outer walls counter-clockwise (climb with M3)
};
bool sideFinish(const PocketRegion &region, const SideFinishJob &job, std::vector<CycleStep> &out, std::string &err);

// Cycle 25 (L9841-L10009): the contour `elems` (its first point elems[0].start) offset by
// `offset` (the tool radius + Q3) to `side` (+1 left, -1 right of the programmed direction; 0
// with offset 0: the programmed path itself),
// its convex corners rounded about the programmed corner, its concave ones cut where the offsets
// meet; extended by `extension` along the tangent at both ends. `forward`: the first level in the
// programmed direction; `alternate` (Q15 = 0): each further level the other way round without
// lifting, else up to `height` and back to the start.
// Cycle 270 (L10239-L10305) puts an approach before and a departure after every pass: `approach`
// 0 none, 1 a tangential arc of `radius` through `angle` degrees, 2 a tangential line, 3 a line
// normal to the path, both `distance` long; on the tool's side (away from the contour).
struct TrainJob {
  int approach = 0;
  double radius = 0, angle = 0, distance = 0;
  int plane = 0;
  std::array<double, 3> at{};
  double surface = 0, depth = 0, infeed = 0, height = 0;
  double offset = 0, extension = 0;
  double plungeFeed = 0, feed = 0;
  int side = 1;
  bool forward = true, alternate = false;
};
bool contourTrain(const std::vector<PathElem> &elems, const TrainJob &job, std::vector<CycleStep> &out, std::string &err);

}  // namespace ncc
