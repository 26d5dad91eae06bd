// Numbered parameters that are controller state: LinuxCNC's #5161-#5428 and Fanuc Custom Macro
// B's system variables (#1000 and up). One map from number to system variable (ir/SystemVars.h)
// for the ISO front end, which resolves a constant `#5221` when the program is compiled, and for
// both engines, which resolve a computed `#[5200+#1*20+1]` when it runs: the same numbers read
// the same state, and the same numbers are errors, either way.
//
// Which map applies depends on the dialect and the machine: LinuxCNC's numbers, or Macro B's
// with the tool offsets of Fanuc tool compensation memory C (`[controller] offset_memory`),
// without them, or those of a lathe (whose offset variables ncc does not provide). The NC IR
// names the map of a computed number with the builtin around it (docs/IR.md §3):
// `#[(MACRO_VARIABLE_C (add 2000 #1))]`.
#pragma once
#include "ir/CmdSink.h"
#include "ir/Strings.h"
#include "ir/NCIR.h"
#include "ir/SystemVars.h"

#include <string>
#include <string_view>

namespace ncc {

enum class ParamMap : uint8_t {
  Rs274,          // LinuxCNC: NGC_PARAMETER
  MacroB,         // Fanuc Custom Macro B, no offset memory: MACRO_VARIABLE
  MacroBMemoryC,  // with tool compensation memory C: MACRO_VARIABLE_C
  MacroBLathe,    // on a lathe (offset variables are errors): MACRO_VARIABLE_LATHE
  Count
};
// The builtin of ir/Builtins.h that names map m in NC IR, and back (false: no such builtin).
const char *paramMapBuiltin(ParamMap m);
bool paramMapFromBuiltin(std::string_view name, ParamMap &out);
// The number a computed `#[x]` addresses: x rounded to the nearest integer (as the engines index
// storage), clamped to ±1e9 so that messages stay readable.
double parameterNumber(double x);

// Plain storage, not controller state: LinuxCNC #0-#5000 and #5599-#5601; Macro B #0-#33 and
// #100-#999. Ranges of whole numbers, inclusive, at most kPlainRanges per map: the JIT inlines
// exactly these comparisons (the hot path of a computed number).
struct PlainRange {
  double first, last;
};
constexpr int kPlainRanges = 2;
const PlainRange *plainRanges(ParamMap m);
bool plainParameter(ParamMap m, double n);  // n: a whole number (parameterNumber)
// The plain ranges as messages name them: "#0-#5000 or #5599-#5601".
std::string plainRangesText(ParamMap m);

// What number n is under a map: a plain parameter, controller state (a System variable),
// Fanuc's #3000/#3006 (alarm and stop with a message, assignment with a constant number only),
// or a number ncc does not provide (an error: `what` says why).
struct SystemParam {
  enum Kind { Plain, System, Alarm, Unsupported } kind = Plain;
  SysRef var{SysVar::Count};
  std::string what;  // System: what the parameter is ("work offset 1 X"); Unsupported: the error
};
SystemParam classifyParameter(ParamMap m, long n);

// The errors of reading or writing number n, the same texts for a constant and a computed number.
std::string readOnlyParameterMessage(long n, const std::string &what);  // "#5420 (current X) is read-only"
std::string alarmParameterMessage(long n, bool computed);

// A computed `#[(MACRO_VARIABLE e)]`: e and the map its builtin names; null for any other variable.
const ir::Expr *computedParameterNumber(const ir::Expr &var, ParamMap &map);

// A computed number that is not plain, when the program runs (both engines): resolved through
// map m and read into v or written from v through the sink (the executor), as a constant number's
// System variable is (ir/SystemAccess.h); Reference (a by-reference argument) is always an error. False with the
// error: the constant form's text for a number ncc does not provide or a read-only one written.
enum class ParamAccess : uint8_t { Read, Write, Reference };
bool accessSystemParameter(CmdSink &sink, ValuePool &pool, ParamMap m, double n, ParamAccess a, double &v,
                           SourceLoc loc, std::string &err);

}  // namespace ncc
