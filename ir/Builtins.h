// Builtin functions of the expression language, one table for every engine: the eval engine
// calls `fn` directly, the JIT emits calls to the same C functions by address (ncc_builtin_*).
// Argument and result conventions follow ir/Value.h (vacant counts as 0; degrees).
#pragma once
#include <string>
#include <string_view>

namespace ncc {

class ValuePool;

// Degrees to radians for the trigonometric builtins (the JIT inlines SIN and COS with it).
inline constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// Numeric builtins: num() arguments (vacant = 0), a double result; NaN = domain error.
using BuiltinFn = double (*)(const double *args);
// String builtins (ir/Strings.h): the raw argument values (string handles or numbers), n of
// them; false with `error` set on a run-time error (a wrong argument kind, NUMBER of a text
// that is no number, the pool limit).
// Frame builtins (ir/FrameBuiltins.h) are typed builtins of the same form.
using StrBuiltinFn = bool (*)(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error);

struct BuiltinInfo {
  const char *name;    // upper case, as written in NC IR: SIN, ATAN2, ...
  unsigned arity;      // the most arguments
  BuiltinFn fn;        // numeric builtins; null for string builtins
  const char *symbol;  // exported C symbol name of fn (for JIT linking), e.g. "ncc_builtin_sin"
  StrBuiltinFn sfn = nullptr;   // string builtins (the JIT calls them through ncrt_strfn)
  const char *args = nullptr;   // typed builtins: kind of each argument, 's' string, 'n' number, 'f' frame, 'a' any
  char result = 'n';            // 'n' number, 's' string, 'f' frame
  int minArity = -1;            // fewest arguments when fewer than arity are allowed (SUBSTR; -1: arity)
  unsigned fewest() const { return minArity < 0 ? arity : (unsigned)minArity; }
  bool accepts(size_t n) const { return n <= arity && n >= fewest(); }
  // The static kind of argument i: 's', 'n' or 'a' (any).
  char argKind(size_t i) const { return args ? args[i] : 'n'; }
};

// The most arguments of any builtin (Sinumerik INTERSEC's SIN_INTERSEC: two contour elements).
constexpr unsigned kMaxBuiltinArgs = 16;

// Returns null for an unknown name (the name is compared case-insensitively).
const BuiltinInfo *findBuiltin(std::string_view name);
const BuiltinInfo *builtinTable(unsigned &count);
// The run-time error of a numeric builtin whose result is NaN (both engines report this text).
std::string builtinDomainError(const BuiltinInfo &b);
// The arity text of error messages: "1", "2 or 3".
std::string builtinArity(const BuiltinInfo &b);
// EXISTS[var]: 1 when the variable has a value (a named variable that was assigned; numbered,
// R, Q and known system variables always), else 0. The engines evaluate it themselves.
// The program a Sinumerik call names (L6885-L6904, docs/SINUMERIK.md "Program memory"):
// `/_N_WKS_DIR/_N_P_WPD/_N_TEIL1_SPF`, `USB:WKS.DIR/TEIL1.SPF`, `_N_TEIL1_SPF` and `teil1` are
// TEIL1 (upper case; folders and device are left to the search path), with its type "MPF" or
// "SPF" in `type` when the name gives it, else "". The builtin SIN_PROGNAME(s) is this name.
std::string sinumerikProgramName(std::string_view written, std::string &type);
inline bool isExistsCall(std::string_view name, size_t args) { return args == 1 && name == "EXISTS"; }

}  // namespace ncc
