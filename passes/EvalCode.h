// The eval engine's code (passes/Eval.cpp): each function linearised once into instructions
// (structured control flow, gotos and sections become jumps), which Evaluator::Impl runs.
#pragma once
#include "ir/Jumps.h"
#include "ir/NCIR.h"
#include "passes/CmdTemplate.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace ncc::eval {
using namespace ir;

struct EvalError {
  SourceLoc loc;
  std::string message;
};
struct ProgramEnd {};

enum class IK : uint8_t {
  Machine,      // tmpl
  Assign,       // target, expr
  Declare,      // target, expr (init, may be null)
  JumpIfFalse,  // expr -> jump
  Jump,         // -> jump; backward gotos count toward the loop limit
  JumpComputed, // op: a goto whose target is computed when it runs (ir/Jumps.h)
  LoopEnter,    // slot: reset the iteration counter
  LoopBack,     // slot: count an iteration, then jump
  CountInit,    // slot: remaining = expr (null = endless)
  CountTest,    // slot: if remaining == 0 -> jump, else remaining -= 1
  Call,         // op
  ModalCall,    // op: set or cancel the modal call
  ModalTrigger, // op: run the active modal call now
  Return,
  SectionCall,  // op -> jump (the `from` label): push a section, run it (ir/Jumps.h)
  SectionEnd,   // calls: the innermost active section, if one of these, repeats or returns
};

struct Instr {
  IK kind;
  bool backward = false;
  uint32_t jump = 0;
  uint32_t slot = 0;
  const Op *op = nullptr;
  const Expr *expr = nullptr;
  const Expr *target = nullptr;
  const std::vector<const Op *> *calls = nullptr;  // SectionEnd
};

struct CompiledFn {
  const Function *fn = nullptr;
  std::vector<Instr> code;
  std::vector<CmdTemplate> templates;
  uint32_t slots = 0;
  std::vector<JumpEntry> jumps;  // block numbers and labels in code order (ir/Jumps.h)
  SectionEnds sectionEnds;       // where call_section sections end
  std::unordered_map<std::string, uint32_t> ownNames;
  // Slots of named locals: the function's own, or for the main program one map that outlives
  // the module, so a streamed program keeps its named locals from chunk to chunk.
  std::unordered_map<std::string, uint32_t> *names = &ownNames;
};

// The slot of named local `name` (created on first use).
uint32_t localSlot(CompiledFn &cf, const std::string &name);
// Linearises f into cf (params first in the slots, constant jump targets resolved); throws
// EvalError at what the engine cannot run.
void linearize(const Function &f, CompiledFn &cf, Diagnostics &diags);

}  // namespace ncc::eval
