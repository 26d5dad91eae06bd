// Region pockets: an outline and islands, each a closed contour captured from the program
// (docs/IR.md §5.6 `use=outline|island`), roughed out level by level (`use=pocket`) for the
// Heidenhain SL cycles (20 CONTOUR DATA + 22 ROUGH-OUT) and Sinumerik CYCLE63. The route through
// the clearing rings (roughingRoute) never crosses an island or leaves the region at cutting
// depth; any pocket entry can use it. Plane coordinates as Mill.h's (the active plane's first and
// second axes); this header stays free of Mill.h so the executor's contour code can include it.
#pragma once
#include "runtime/cycles/Clearing.h"
#include "runtime/cycles/ContourFormula.h"
#include "runtime/cycles/Step.h"

#include <string>
#include <vector>

namespace ncc {

// A closed path of lines and arcs: from `start` through the segments back to `start`.
// Arcs of region contours are sampled within this (mm); the rings keep their margin from it.
constexpr double kRegionChordTolerance = 0.001;

struct RegionLoop {
  PlanePoint start{};
  std::vector<PathSeg> segs;
};

// A captured path as a region loop: closed (the last point is the first, or the first move only
// led to the contour's start and the rest closes there) and not crossing itself; sampled within
// `tol` so that the polygon takes in no more than the contour (an outline) or leaves out nothing
// of it (an island). False with a message otherwise.
bool regionPolygon(RegionLoop loop, bool island, double tol, Polygon &out, std::string &err);

// The loop closed as regionPolygon closes it (a first move that only led to the contour's first
// point dropped); false with a message when it is open.
bool closedLoop(RegionLoop &loop, std::string &err);

// A Heidenhain SL sub-contour (a label of cycle 14): its polygon (counter-clockwise, sampled on
// the safe side for what it is), whether it is a pocket, and its first point.
struct SubContour {
  Polygon poly;
  bool pocket = true;
  PlanePoint start{};
  RegionLoop loop;  // the closed path itself, exact (cycle 24's walls are offset from it)
};
// The sub-contour of a captured loop run with RL (`side` 1) or RR (2): a pocket when the tool is
// inside (RL and counter-clockwise, RR and clockwise: the manual's "traversed inside"), else an
// island.
bool subContour(RegionLoop loop, int side, double tol, SubContour &out, std::string &err);

// The region collected for the next pocket: the outline and its islands (overlapping islands
// merge), or the SL sub-contours, in the plane they were captured in.
struct PocketRegion {
  int plane = -1;  // -1: no outline yet
  Polygon outline;
  std::vector<Polygon> islands;
  std::vector<SubContour> subs;  // not empty: an SL contour (outline and islands unused)
  std::vector<FormulaStep> formula;  // not empty: a contour formula over the subs (ContourFormula.h)
};
// The SL contour's area (ClearingSpec::area): the pockets united (the intersection of two when the
// first starts inside the second, L9140-L9173), less the islands.
bool slArea(const std::vector<SubContour> &subs, std::vector<Polygon> &area, std::string &err);
// A contour formula's operand (DECLARE CONTOUR, CONTOUR DEF): always a pocket, whatever its
// direction (L11843); closed, not crossing itself.
bool formulaOperand(RegionLoop loop, double tol, SubContour &out, std::string &err);
// The region of a contour formula (PocketRegion::formula): its captures sampled within `tol` on
// the safe side of what they add or take away, combined by Clipper (ContourFormula.cpp).
bool formulaArea(const PocketRegion &region, double tol, std::vector<Polygon> &area, std::string &err);
// Whether `island` lies inside the outline (within `tol`): an island reaching out of it is an error.
bool islandInside(const PocketRegion &r, const Polygon &island, double tol);

// One stretch of a roughing route cut without lifting: the tool plunges at path[0] and feeds
// along the rest at the level.
struct RoughPass {
  std::vector<PlanePoint> path;
};
// The route of one level through the rings of `spec`: area by area (the separate parts of the
// region), in each from the innermost ring outward, every ring once round (counter-clockwise
// outer rings and clockwise island rings when `ccw`, all reversed otherwise) from the point
// nearest the tool. A link stays at the level when the straight move keeps the tool radius plus
// the allowance off every wall and island (segmentClear against `walls`); otherwise a new pass
// begins. The first pass starts on the ring nearest `from`.
bool roughingRoute(const ClearingSpec &spec, bool ccw, PlanePoint from, std::vector<RoughPass> &passes,
                   std::vector<Polygon> &walls, std::string &err);

// The roughing job (docs/IR.md `contour action=run use=pocket`), lengths in mm, levels on the
// tool axis in the coordinates of `at`.
struct RegionPocketJob {
  int plane = 0;
  std::array<double, 3> at{};  // where the tool is
  double surface = 0, depth = 0, infeed = 0;  // depth > 0 below the surface; infeed 0: one level
  double clearance = 0, height = 0;  // set-up clearance above the surface; clearance height (absolute)
  double stepover = 0, sideAllowance = 0, floorAllowance = 0;
  double plungeFeed = 0, feed = 0;  // 0: the programmed feed
  double retractFeed = -1;  // the last move up to the clearance height: < 0 rapid, 0 `feed`
  double cornerRadius = 0;  // Q8: the outermost ring's corners rounded (ClearingSpec)
  double done = 0;          // the depth already cut (floor finishing: the roughed floor)
  double toolRadius = 0;
  bool ccw = true;  // outer walls counter-clockwise (climb with M3)
  double chordTolerance = kRegionChordTolerance;
};
// Roughing of the region less its islands in levels of `infeed` down to depth - floorAllowance:
// over the first plunge point at the clearance height, down to the set-up clearance; each level
// runs the route's passes; between passes (and back to the first at the next level) the tool
// stays up by the set-up clearance over the last level when the straight move is clear of the
// walls, else it rises to the set-up clearance over the surface, moves across and comes down;
// it plunges vertically at the plunge feed. The end: up to the clearance height.
bool regionPocket(const PocketRegion &region, const RegionPocketJob &job, std::vector<CycleStep> &out,
                  std::string &err);

// Heidenhain cycle 21 (L9268-L9348): a hole at each plunge point of the roughing route that
// `job` describes (its tool radius the rough-out tool's): from the clearance height down to the
// set-up clearance at rapid, pecks of `infeed` at the plunge feed to depth - floor allowance,
// after each out to the set-up clearance and back at rapid to `pilotReentry` above the last
// depth; up to the clearance height between the holes and at the end.
double pilotReentry(double depth);
bool regionPilot(const PocketRegion &region, const RegionPocketJob &job, std::vector<CycleStep> &out,
                 std::string &err);

}  // namespace ncc
