// Internal to backends/jit: the mapping from machine-level NC IR ops to MachineCmd fields.
// Pure data work (no LLVM): the code generator turns constant parts into tables and the
// dynamic parts (words and sub-fields given by expressions) into code.
#pragma once
#include "ir/MachineCmd.h"
#include "ir/NCIR.h"

#include <string>
#include <vector>

namespace ncc::jit {

struct CmdSpec {
  MachineCmd cmd;    // constant fields; words with constant values are already set
  std::string text;  // Comment/Message text (cmd.text is set by the code generator)
  struct DynWord {
    Word word;
    const ir::Expr *value;
  };
  std::vector<DynWord> words;  // computed at run time; left out when vacant
  enum class SubRule : uint8_t { None, Round, NotTruthy };
  SubRule subRule = SubRule::None;  // how to compute cmd.sub from subExpr
  const ir::Expr *subExpr = nullptr;
  bool dynamic() const { return !words.empty() || subExpr; }
};

// True for ops that become MachineCmds (including block, comment and message).
bool isMachineOp(ir::OpKind k);
// Lowers one machine op to its commands (usually one; mode ops with more than six groups and
// aux ops with several keys give more). Returns false after reporting an error.
bool lowerMachineOp(const ir::Op &op, std::vector<CmdSpec> &out, Diagnostics &diags);
// True when the expression is a literal (no variables, operators or calls).
bool isLiteral(const ir::Expr &e);

}  // namespace ncc::jit
