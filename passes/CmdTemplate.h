// Maps a machine-level NC IR op (block, mode, feed, move, …) onto a MachineCmd: the constant
// part is filled once, the operands that need evaluating are listed as (word, expression) slots.
// Both engines use it: the eval engine evaluates the slots, the JIT generates code for them.
#pragma once
#include "ir/MachineCmd.h"
#include "ir/NCIR.h"

#include <vector>

namespace ncc {

struct CmdSlot {
  Word word;
  const ir::Expr *expr;
};

struct CmdTemplate {
  MachineCmd base;             // kind, sub, modes, text, loc and the constant words
  std::vector<CmdSlot> slots;  // words whose value is computed at run time
  const ir::Expr *text = nullptr;  // a message text built at run time (concat), else base.text
};

// True for ops that become a MachineCmd.
bool isMachineOp(ir::OpKind k);
// Fills `out` for a machine op. Reports unsupported shapes (unknown symbol values) to diags.
bool buildCmdTemplate(const ir::Op &op, CmdTemplate &out, Diagnostics &diags);
// The inverse, for passes that turn evaluated commands back into IR (eval / flatten).
ir::Op cmdToOp(const MachineCmd &cmd);

}  // namespace ncc
