// What a front end needs to know of the cycle library (runtime/cycles/Library.h) to lower a
// vendor cycle call onto the `cycle` op (docs/IR.md §5.8): an entry's positional parameters and
// whether it is a position pattern. The library lives in runtime/, which front ends may not
// include, so the driver hands them its lookup (FrontendOptions::cycles).
#pragma once
#include <string_view>

namespace ncc {

struct CycleSignature {
  const char *name = nullptr;    // "sin.CYCLE81"
  const char *params = nullptr;  // the positional parameter names, space-separated
  const char *strings = nullptr; // the STRING parameters (the others take numbers)
  bool pattern = false;          // a position pattern (HOLES1), not a machining cycle
};
// False when the library has no entry of that name.
using CycleLookup = bool (*)(std::string_view name, CycleSignature &out);

}  // namespace ncc
