// Goto resolution, one rule for both engines (passes/Eval.cpp, backends/jit/CodegenCtl.cpp)
// and for constant and computed targets: the jump targets of a function in program order, the
// search (Fanuc: forward from the goto, then from the start; Sinumerik GOTOF/GOTOB restrict it
// with dir=forward/backward) and the run-time error texts.
#pragma once
#include "ir/NCIR.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace ncc::ir {

// One jump target: a `block n=` (label null) or a `label name=` at position `pos` (the engine's
// own numbering, increasing in program order; the goto's `from` uses the same numbering). The
// layout is shared with generated code (backends/jit builds constant tables of it).
struct JumpEntry {
  double n;           // the block number; NaN for a label
  const char *label;  // the label name; null for a block
  uint32_t pos;
};

enum class JumpDir : uint8_t { Any, Forward, Backward };
JumpDir jumpDir(const Op &go);  // its dir= (absent: any)

// The index of the entry `go` reaches from `from` among `entries` (sorted by pos), or -1. A block
// number n matches blocks with that number; a label name matches that label, and when no label
// has the name, "N<int>" matches the block number (Sinumerik GOTOF "N"<<R10).
int64_t findJump(const JumpEntry *entries, size_t count, bool label, double n, std::string_view name,
                 uint32_t from, JumpDir dir);

// The run-time error for a target that findJump did not find.
std::string missingJumpMessage(bool label, double n, std::string_view name);

}  // namespace ncc::ir
