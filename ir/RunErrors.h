// The run-time errors both engines raise from the same conditions, one table of texts: the eval
// engine formats them directly, compiled code through ncrt_fault (runtime/ncrt.h numbers its
// NCRT_FAULT_* kinds like RunError, checked there), so the two cannot drift apart.
#pragma once
#include "ir/ExecLimits.h"

#include <string>
#include <string_view>

namespace ncc {

enum class RunError : unsigned {
  LoopLimit = 1,  // loop did not terminate after N iterations
  BackJump,       // backward jump repeated more than N times
  CallDepth,      // call depth limit N exceeded
  UnsetVar,       // variable 'name' used before assignment
  Numbered,       // parameter number #value out of range
  RParam,         // R parameter index value out of range
  QParam,         // Q parameter index value out of range
  Index,          // index value of array 'name' is not an integer in 0..N
  UnsetElem,      // array element 'name[value]' used before assignment
  SysVar,         // system variable 'name' is not available here
  TimeLimit,      // run time limit of N s exceeded
};

// `name` and `value` as the comment of each kind says; limits from `l`.
std::string runErrorMessage(RunError kind, const ExecLimits &l, std::string_view name = {}, double value = 0);

}  // namespace ncc
