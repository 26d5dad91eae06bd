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
#include <unordered_map>
#include <vector>

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
// A goto whose target is a constant (n= a number, label= a string): resolved before the run;
// any other is computed when it runs.
bool constantJump(const Op &go);

// The index of the entry `go` reaches from `from` among `entries` (sorted by pos), or -1. A block
// number n matches blocks with that number; a label name matches that label, and when no label
// has the name, "N<int>" matches the block number (Sinumerik GOTOF "N"<<R10).
int64_t findJump(const JumpEntry *entries, size_t count, bool label, double n, std::string_view name,
                 uint32_t from, JumpDir dir);

// The run-time error for a target that findJump did not find.
std::string missingJumpMessage(bool label, double n, std::string_view name);

// Section calls (`call_section from= to= count=`, docs/IR.md §5.3): where each call's section
// ends, in the places both engines mark. With `to`, after the block of the `to` label: before
// the next `block` or `label` op of the label's region, else at the end of that region; without
// `to`, just before the call itself (the section runs from the label up to the call).
struct SectionEnds {
  std::unordered_map<const Op *, std::vector<const Op *>> before;     // op -> calls ending before it
  std::unordered_map<const Region *, std::vector<const Op *>> atEnd;  // region -> calls ending at its end
  const std::vector<const Op *> *endingBefore(const Op &op) const {
    auto it = before.find(&op);
    return it == before.end() ? nullptr : &it->second;
  }
  const std::vector<const Op *> *endingAt(const Region &r) const {
    auto it = atEnd.find(&r);
    return it == atEnd.end() ? nullptr : &it->second;
  }
};
SectionEnds sectionEnds(const Function &f);

// At most this many section calls active in one function activation (a section calling a
// section); one more is the run-time error sectionDepthMessage().
constexpr unsigned kMaxSectionDepth = 16;
std::string sectionDepthMessage();

}  // namespace ncc::ir
