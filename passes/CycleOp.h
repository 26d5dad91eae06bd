// The `cycle` op (docs/IR.md §5.8) against the cycle library (runtime/cycles/Library.h): which
// entries it names and which command word each argument fills. Sema reports what does not
// resolve; CmdTemplate builds the command from it; the executor decodes the words with
// cycleArgsFromCmd.
#pragma once
#include "ir/MachineCmd.h"
#include "ir/NCIR.h"
#include "runtime/cycles/Library.h"

#include <string>

namespace ncc {

struct CycleOpShape {
  CycleAction action = CycleAction::Run;
  const CycleDef *entry = nullptr;    // the machining cycle (run, define, modal)
  const CycleDef *pattern = nullptr;  // the position pattern (run, call)
  // The one STRING argument (a constant: HOLES1's _HIDE) travels as the command's text, its
  // word's index + 1 in the high byte of sub; -1 none.
  int textWord = -1;
};

// Resolves the op's entries and checks each a.<param> / p.<param> against them; false with the
// reason (naming the entry and the parameter) in err.
bool resolveCycleOp(const ir::Op &op, CycleOpShape &out, std::string &err);
// The command word of an argument: entry parameter i is word i, pattern parameter j follows the
// entry's parameters.
Word cycleArgWord(const CycleOpShape &shape, bool ofPattern, int index);

}  // namespace ncc
