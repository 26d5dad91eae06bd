// Run-time value semantics shared by the eval engine and JIT-compiled code, so both engines
// compute the same numbers. Numeric values are doubles; Macro B's "vacant" (#0, unset locals)
// is a NaN with a fixed payload so it survives copies and is told apart from real NaNs.
//
// Rules (Fanuc Custom Macro B):
//  - vacant in arithmetic and in function arguments counts as 0 (vacant + 1 = 1, -vacant = 0);
//  - assigning vacant keeps it vacant (#2 = #0 makes #2 vacant);
//  - EQ/NE: vacant equals only vacant (#1 EQ #0 is true when #1 is vacant; vacant EQ 0 false);
//  - LT/LE/GT/GE: vacant counts as 0;
//  - a word whose value is vacant is as if not programmed (G1 X#0 moves no axis).
//  - booleans are 1.0 / 0.0; any non-zero, non-vacant value is true.
// Angles of trigonometric builtins are degrees (every dialect ncc reads uses degrees).
// Strings and frames are NaN-boxed handles too (kStringTag, kFrameTag below; the pool and the
// typed-value rules are in ir/Strings.h and ir/FrameValue.h).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace ncc {

// Macro B call locals #1..#33 (a new frame per G65 call); other numbers are commons/system.
constexpr int kMacroLocals = 33;

constexpr uint64_t kVacantBits = 0x7ff8dead0000beefull;

inline uint64_t valueBits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
inline double bitsValue(uint64_t b) {
  double d;
  std::memcpy(&d, &b, sizeof d);
  return d;
}
inline double vacantValue() { return bitsValue(kVacantBits); }
inline bool isVacant(double v) { return valueBits(v) == kVacantBits; }
// The value used in arithmetic.
inline double num(double v) { return isVacant(v) ? 0.0 : v; }
inline bool truthy(double v) { return !isVacant(v) && v != 0.0; }


// A string value is a NaN-boxed handle into the run's ValuePool (ir/Strings.h): the bits
// kStringTag | index. Handle 0 is the empty string.
constexpr uint64_t kStringTag = 0x7ffc000000000000ull;
constexpr uint64_t kStringTagMask = 0xffff000000000000ull;
constexpr uint64_t kEmptyStringBits = kStringTag;
inline bool isString(double v) { return (valueBits(v) & kStringTagMask) == kStringTag; }
inline double emptyString() { return bitsValue(kEmptyStringBits); }
// A FRAME value is a handle too: kFrameTag | index into the run's FramePool (ir/FrameValue.h);
// handle 0 is the identity frame. Strings and frames are the "handles": never numbers.
constexpr uint64_t kFrameTag = 0x7ffd000000000000ull;
inline bool isFrame(double v) { return (valueBits(v) & kStringTagMask) == kFrameTag; }
inline double identityFrame() { return bitsValue(kFrameTag); }
constexpr uint64_t kHandleMask = 0xfffe000000000000ull;  // the tag bits strings and frames share
inline bool isHandle(double v) { return (valueBits(v) & kHandleMask) == kStringTag; }

// Initial values, one place per variable space (docs/IR.md §3): Macro B `#n` starts vacant
// (numberedStart); Sinumerik R and Heidenhain Q/QL/QR parameters start at 0; Heidenhain QS
// (string parameters) start as the empty string; named variables start unset unless declared
// (declared ones: initialValue(ValueType), ir/Strings.h). Q prefixes have fixed array numbers
// in both engines.
constexpr std::string_view kQPrefixes[] = {"Q", "QL", "QR", "QS"};
constexpr int kQSpaces = 4;
inline int qPrefixIndex(std::string_view prefix) {
  for (int i = 0; i < kQSpaces; ++i)
    if (kQPrefixes[i] == prefix) return i;
  return -1;
}
inline double numberedStart() { return vacantValue(); }
inline double rParamStart() { return 0.0; }
inline double qParamStart(int prefixIndex) { return kQPrefixes[prefixIndex] == "QS" ? emptyString() : 0.0; }

// Named arrays: an indexed named variable (%A[i], %%A[i]) is element i of the array A, apart
// from the scalar %A. Indices are integers 0..kArrayElements-1 (vacant counts as 0); anything
// else is a run-time error. Elements start unset, like named scalars.
constexpr uint32_t kArrayElements = 1000;
inline bool arrayIndex(double v, uint32_t &out) {
  double x = num(v);
  if (!(x >= 0 && x < kArrayElements) || x != std::trunc(x)) return false;
  out = (uint32_t)x;
  return true;
}

inline double valueEq(double a, double b) {
  bool va = isVacant(a), vb = isVacant(b);
  if (va || vb) return (va && vb) ? 1.0 : 0.0;
  return a == b ? 1.0 : 0.0;
}

// The text of a number where a string is built (concat, messages, TOSTR; strings themselves are
// handles, see ir/Strings.h valueText): vacant is empty, integral values print without a
// decimal point (5, -12), others with up to 10 decimal places, trailing zeros dropped (0.1, 2.5,
// 0.0000001; SIN(30) gives 0.5), as Sinumerik's REAL to STRING conversion.
std::string numberText(double v);
// LinuxCNC's (DEBUG,…)/(PRINT,…)/(ABORT,…) substitution: "%f" (6 decimals); vacant reads 0,
// an unset named parameter "######" (as rs274 prints it).
std::string fixedNumberText(double v);

// A named variable that was never assigned holds this NaN: reading it is an error (unlike
// Macro B's vacant). Generated code uses the same bits (runtime/ncrt.h NCRT_UNSET_BITS).
constexpr uint64_t kUnsetBits = 0x7ff8dead0000f00dull;
double unsetValue();
bool isUnset(double v);
// The run-time error of a bitwise operator on a non-integer, the same in both engines.
std::string bitwiseOperandMessage(std::string_view op);
// A numeric callee is an ISO program number: n names the function "O<n>". False unless n is a
// non-negative integer.
bool programName(double v, std::string &out);
// Run-time errors of computed calls, the same in both engines.
std::string unknownProgramMessage(std::string_view name);
std::string badProgramNumberMessage(double v);
// `call result=` after a callee that ended without `return value=`.
std::string noReturnValueMessage();
// Run-time errors of named arrays, the same in both engines.
std::string arrayIndexMessage(std::string_view name, double index);
std::string unsetElementMessage(std::string_view name, double index);

}  // namespace ncc
