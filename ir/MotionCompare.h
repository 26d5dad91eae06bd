// Compares two Motion IR streams as paths: the motion records (rapid, linear, arc, dwell) must
// match in order, end points and arc centres within a tolerance, and every move other than a
// rapid must run with the same tool, spindle state and speed, and coolant. Used by
// `ncc translate --verify` and the engine-equivalence tests.
#pragma once
#include "ir/MotionIR.h"

#include <string>
#include <vector>

namespace ncc {

struct PathCompareOptions {
  double tolerance = 1e-3;  // mm
  bool compareFeed = true;
  bool compareState = true;  // tool, spindle and coolant at each feed move, dwell and thread
};

// Returns true when equal; otherwise `report` names the first difference.
bool comparePaths(const std::vector<MotionRecord> &a, const std::vector<MotionRecord> &b,
                  const PathCompareOptions &opts, std::string &report);

}  // namespace ncc
