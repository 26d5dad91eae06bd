// Passes over NC IR, registered by name so `ncc opt --passes=a,b` can run any list of them
// (like LLVM's opt) and each is testable alone.
#pragma once
#include "ir/NCIR.h"
#include "ir/ExecLimits.h"

#include <string>
#include <vector>

namespace ncc {

struct Machine;

struct PassContext {
  const Machine *machine = nullptr;
  ExecLimits limits;
  // Set by lower-motion: the Motion IR text of the program (`ncc opt` prints it instead of IR).
  std::string *motionText = nullptr;
};

using PassFn = bool (*)(ir::Module &, Diagnostics &, PassContext &);

struct PassInfo {
  const char *name;
  const char *description;
  PassFn run;
};

const PassInfo *findPass(std::string_view name);
const PassInfo *passTable(unsigned &count);
// Runs the named passes in order; stops at the first that fails.
bool runPasses(ir::Module &m, const std::vector<std::string> &names, Diagnostics &diags, PassContext &ctx);

// Individual passes (also used directly by the driver).
bool runSema(ir::Module &m, Diagnostics &diags, PassContext &ctx);
bool runFold(ir::Module &m, Diagnostics &diags, PassContext &ctx);
bool runEvalFlatten(ir::Module &m, Diagnostics &diags, PassContext &ctx);
bool runLint(ir::Module &m, Diagnostics &diags, PassContext &ctx);
bool runLowerMotion(ir::Module &m, Diagnostics &diags, PassContext &ctx);

}  // namespace ncc
