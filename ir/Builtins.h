// Builtin functions of the expression language, one table for every engine: the eval engine
// calls `fn` directly, the JIT emits calls to the same C functions by address (ncc_builtin_*).
// Argument and result conventions follow ir/Value.h (vacant counts as 0; degrees).
#pragma once
#include <string_view>

namespace ncc {

using BuiltinFn = double (*)(const double *args);

struct BuiltinInfo {
  const char *name;    // upper case, as written in NC IR: SIN, ATAN2, ...
  unsigned arity;
  BuiltinFn fn;
  const char *symbol;  // exported C symbol name (for JIT linking), e.g. "ncc_builtin_sin"
};

// Returns null for an unknown name (the name is compared case-insensitively).
const BuiltinInfo *findBuiltin(std::string_view name);
const BuiltinInfo *builtinTable(unsigned &count);
// EXISTS[var]: 1 when the variable has a value (a named variable that was assigned; numbered,
// R, Q and known system variables always), else 0. The engines evaluate it themselves.
inline bool isExistsCall(std::string_view name, size_t args) { return args == 1 && name == "EXISTS"; }

}  // namespace ncc
