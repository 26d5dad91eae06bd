// The arguments of a typed builtin (ir/Builtins.h StrBuiltinFn) read by kind, with the error
// text both engines report for a wrong kind. Shared by the string and the file builtins.
#pragma once
#include "ir/Strings.h"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace ncc {

struct StrArgs {
  ValuePool &pool;
  const double *a;
  unsigned n;
  std::string &error;
  const char *fn;
  bool str(unsigned i, std::string_view &out) {
    if (!isString(a[i])) {
      error = fmt::format("'{}' argument {} must be a string", fn, i + 1);
      return false;
    }
    out = pool.text(a[i]);
    return true;
  }
  bool chr(unsigned i, char &out) {
    std::string_view s;
    if (!str(i, s)) return false;
    if (s.size() != 1) {
      error = fmt::format("'{}' argument {} must be a one-character string", fn, i + 1);
      return false;
    }
    out = s[0];
    return true;
  }
  bool number(unsigned i, double &out) {
    if (isString(a[i])) {
      error = fmt::format("'{}' argument {} must be a number", fn, i + 1);
      return false;
    }
    out = num(a[i]);
    return true;
  }
  bool ret(std::string_view s, double &out) { return pool.intern(s, out, error); }
};

}  // namespace ncc
