// Compares two Motion IR streams as paths: the motion records (rapid, linear, arc, dwell) must
// match in order, end points and arc centres within a tolerance. Used by
// `ncc translate --verify` and the engine-equivalence tests.
#pragma once
#include "ir/MotionIR.h"

#include <string>
#include <vector>

namespace ncc {

struct PathCompareOptions {
  double tolerance = 1e-3;  // mm
  bool compareFeed = true;
};

// Returns true when equal; otherwise `report` names the first difference.
bool comparePaths(const std::vector<MotionRecord> &a, const std::vector<MotionRecord> &b,
                  const PathCompareOptions &opts, std::string &report);

}  // namespace ncc
