// Compares two Motion IR streams as paths: the motion records (rapid, linear, arc, dwell) must
// match in order, end points and arc centres within a tolerance, and every move other than a
// rapid must run with the same tool, spindle state and speed, and coolant. A move of the first
// stream may be several of the second that lie on it (a straight move in parts, an arc split at
// quadrants). Used by `ncc translate --verify` and the engine-equivalence tests.
#pragma once
#include "ir/MotionIR.h"

#include <string>
#include <vector>

namespace ncc {

struct PathCompareOptions {
  double tolerance = 1e-3;  // mm
  bool compareFeed = true;
  bool compareState = true;  // tool, spindle and coolant at each feed move, dwell and thread
  // A rapid of the first stream may be several rapids in the second, each ending inside the box
  // its start and end span (a postprocessor passport's rapid legs: XY, then Z).
  bool rapidLegs = false;
};

// Returns true when equal; otherwise `report` names the first difference.
bool comparePaths(const std::vector<MotionRecord> &a, const std::vector<MotionRecord> &b,
                  const PathCompareOptions &opts, std::string &report);

}  // namespace ncc
