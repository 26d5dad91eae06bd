// The symbol-valued keys of NC IR ops (`spindle dir=cw`, `stop kind=end` …): the values each
// key allows and the code a value stands for in a MachineCmd (its sub or sub2). One table for the
// verifier (allowed values, in the order its messages list them) and the op <-> command
// translation of passes/CmdTemplate (codes); keys that never reach a MachineCmd have their index.
#pragma once
#include "ir/NCIR.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace ncc::ir {

struct OpSymbol {
  OpKind op;
  const char *key;
  const char *value;
  uint8_t code;
};
const OpSymbol *opSymbols(size_t &count);
// The allowed values of op.key, space-separated in table order ("" when the key is not symbolic).
std::string opSymbolValues(OpKind op, std::string_view key);
// The code of a value; false when the value is not allowed.
bool opSymbolCode(OpKind op, std::string_view key, std::string_view value, uint8_t &code);
// The value of a code ("?" when none).
const char *opSymbolName(OpKind op, std::string_view key, uint8_t code);

}  // namespace ncc::ir
