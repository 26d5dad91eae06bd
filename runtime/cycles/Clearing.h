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
  std::vector<Polygon> islands;   // areas inside it that stay (any orientation; overlapping ones merge)
  double toolRadius = 0;
  double stepover = 0;            // largest distance between rings, 0 < stepover <= 2 x toolRadius
  double allowance = 0;           // material left on the walls for finishing
  double chordTolerance = 0.001;  // mm
  // Extra distance the rings keep from the walls and islands: a rounded offset corner is chords
  // whose middles lie up to about two chord tolerances inside its arc, so a margin of
  // kChordSagFactor x chordTolerance keeps every point of every ring at least radius + allowance
  // off the walls (region pockets; the fixed-shape pockets keep 0).
  double margin = 0;
  // When not empty: the region itself, already combined (Heidenhain SL sub-contours united and
  // less their islands): outer rings counter-clockwise, holes clockwise, as Clipper's booleans
  // leave them; `contour` and `islands` are then not used.
  std::vector<Polygon> area;
  // Heidenhain Q8: the first ring (the tool touching the walls) has its convex corners, where the
  // region's inner corners are, rounded to this radius on the tool-centre path (0: sharp).
  double cornerRadius = 0;
};
constexpr double kChordSagFactor = 2.5;

// One element of a path of lines and arcs (Mill.h `Contour`, the region contours of Region.h):
// to `end`, on an arc about `centre` (counter-clockwise when `ccw`) when `arc`.
struct PathSeg {
  PlanePoint end{};
  bool arc = false;
  PlanePoint centre{};
  bool ccw = true;
};

// The rings from the innermost outward (roughing from the middle to the wall), each closed and
// counter-clockwise. The tool run along them leaves nothing it can reach: where rings a whole
// stepover apart would leave material (between sharp corners, in the middle), the stepover
// shrinks and further rings follow, at most a tool radius apart. Climb milling with a clockwise
// spindle runs the rings as they are, conventional reversed. False with a message when the tool
// does not fit or the input is not a region.
bool clearingRings(const ClearingSpec &spec, std::vector<Polygon> &rings, std::string &err);

// The same rings with their structure, for routes that must not cross islands (Region.h): one
// piece per connected part of each level (its outer ring and the rings round the islands inside
// it), levels from the wall inward; `parent` is the piece of the level before that holds it, -1
// for the first level, whose pieces are the separate areas of the region. Rings as
// clearingRings' (counter-clockwise, holes too). `walls` is the region itself (outline and
// islands as Clipper left them, the islands merged), for link tests (segmentClear).
struct RingPiece {
  Polygon outer;
  std::vector<Polygon> holes;
  int parent = -1;
};
bool clearingPieces(const ClearingSpec &spec, std::vector<RingPiece> &pieces, std::vector<Polygon> &walls,
                    std::string &err);

// Whether the straight move a -> b keeps at least `distance` from every edge of `walls` (the tool
// centre of a tool of radius `distance` then touches none of them).
bool segmentClear(const std::vector<Polygon> &walls, PlanePoint a, PlanePoint b, double distance);

}  // namespace ncc
