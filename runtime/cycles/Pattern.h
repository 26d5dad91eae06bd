// Pattern walkers: the hole positions of position patterns (Sinumerik HOLES1, HOLES2, CYCLE801,
// Heidenhain 220, 221, ISO repeats), in the working plane, in the order the controller visits
// them. Pure functions of their parameters.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace ncc {

using PlanePoint = std::array<double, 2>;

// count points on a line from `origin` at angle `degrees`: the first `first` away, then every
// `spacing`.
std::vector<PlanePoint> linePattern(PlanePoint origin, double degrees, double first, double spacing, int count);

// count points on a circle about `centre`: from `start` degrees every `step` degrees (a negative
// step runs clockwise).
std::vector<PlanePoint> circlePattern(PlanePoint centre, double radius, double start, double step, int count);

// A grid of n1 x n2 points from `origin` (spacing d1 along the rotated first axis, d2 across),
// rotated by `degrees` about the origin. Rows alternate direction (meander) when `meander`;
// `frameOnly` keeps the points on the border.
std::vector<PlanePoint> gridPattern(PlanePoint origin, double degrees, double d1, double d2, int n1, int n2,
                                    bool meander, bool frameOnly);
// The same grid with its two directions turned apart: the first axis at `degrees1`, the second
// at 90 + `degrees2` (equal angles: the rotated grid above; different: a sheared one).
std::vector<PlanePoint> shearedGridPattern(PlanePoint origin, double degrees1, double degrees2, double d1, double d2,
                                           int n1, int n2, bool meander, bool frameOnly);

// Sinumerik `_HIDE` lists ("1,3,5" or "2-4", 1-based positions) applied to a pattern; false with a
// message on a malformed list.
bool hidePositions(std::vector<PlanePoint> &pts, const std::string &list, std::string &err);

}  // namespace ncc
