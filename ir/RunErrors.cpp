#include "ir/RunErrors.h"

#include "ir/Value.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

std::string runErrorMessage(RunError kind, const ExecLimits &l, std::string_view name, double value) {
  switch (kind) {
  case RunError::LoopLimit:
    return fmt::format("loop did not terminate after {} iterations (limit --max-loop-iterations)", l.maxLoopIterations);
  case RunError::BackJump:
    return fmt::format("backward jump repeated more than {} times (limit --max-loop-iterations)", l.maxLoopIterations);
  case RunError::CallDepth: return fmt::format("call depth limit {} exceeded (limit --max-call-depth)", l.maxCallDepth);
  case RunError::UnsetVar: return fmt::format("variable '{}' used before assignment", name);
  case RunError::Numbered: return fmt::format("parameter number #{} out of range", std::lround(value));
  case RunError::RParam: return fmt::format("R parameter index {} out of range", std::lround(value));
  case RunError::QParam: return fmt::format("Q parameter index {} out of range", std::lround(value));
  case RunError::Index: return arrayIndexMessage(name, value);
  case RunError::UnsetElem: return unsetElementMessage(name, value);
  case RunError::SysVar: return fmt::format("system variable '{}' is not available here", name);
  case RunError::TimeLimit: return fmt::format("run time limit of {} s exceeded (limit --max-seconds)", l.maxSeconds);
  }
  return "internal error: unknown run-time fault";
}

}  // namespace ncc
