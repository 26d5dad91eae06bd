// Typed run-time values beyond doubles, shared by the eval engine (passes/Eval.cpp) and
// JIT-compiled code (through the ncrt_* wrappers of runtime/ncrt.cpp), so each rule exists once.
//
// Representation. Every run-time value stays a double. A string is a NaN-boxed handle:
// the bits kStringTag | i (ir/Value.h), where i indexes the run's ValuePool. Handle 0 is the empty string
// (a constant: QS parameters and STRING variables start with it, no pool needed). Strings are
// interned: equal contents have one handle, so a handle is never stale and `eq` on two strings
// could compare bits. Arithmetic never produces the tag (it yields the default NaN or propagates
// an operand's NaN, and string operands are rejected before arithmetic).
//
// Lifetime and limits. A pool lives for one run (the Evaluator, or the ncrt_ctx of a compiled
// program); strings are never freed before the run ends. A run may create at most
// kMaxPoolStrings distinct strings holding at most kMaxPoolBytes bytes, and one string holds at
// most kMaxStringBytes bytes; beyond that the run stops with poolLimitMessage() at the
// expression that needed the new string.
//
// Typed variables (declare type=, function parameters) convert what is stored into them with
// convertForStore; see docs/IR.md §2 for the rules.
#pragma once
#include "ir/FrameValue.h"
#include "ir/Value.h"

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_map>

namespace ncc {

constexpr uint32_t kMaxPoolStrings = 1000000;
constexpr uint64_t kMaxPoolBytes = 64ull << 20;
constexpr uint32_t kMaxStringBytes = 65535;
// STRING without a declared length (Sinumerik's maximum).
constexpr uint32_t kDefaultStringLength = 200;

// The run's typed values: its strings (below) and its frames (ir/FrameValue.h).
class ValuePool {
public:
  ValuePool();
  FramePool frames;
  // The handle of `s`; false (with `error` set) when a limit is exceeded.
  bool intern(std::string_view s, double &out, std::string &error);
  // The text of a string handle (empty for anything else).
  std::string_view text(double v) const;

private:
  std::deque<std::string> strings_;
  std::unordered_map<std::string_view, uint32_t> index_;
  uint64_t bytes_ = 0;
};

std::string poolLimitMessage();

// The text of a value: a string as it is, a number as numberText (ir/Value.h); `fixed`: as
// fixedNumberText (LinuxCNC DEBUG/PRINT).
std::string valueText(const ValuePool &pool, double v, bool fixed = false);

// Value types a variable can be declared with (declare type=, function parameters).
enum class ValueType : uint8_t { Any, Real, Int, Bool, Char, String, Axis, Frame };
bool valueTypeFromName(std::string_view lowerName, ValueType &out);
const char *valueTypeName(ValueType t);
// A variable of type t may hold a handle (a string or a frame, ir/Value.h).
inline bool holdsHandle(ValueType t) {
  return t == ValueType::Any || t == ValueType::Char || t == ValueType::String || t == ValueType::Axis ||
         t == ValueType::Frame;
}
// The value a declared variable (and each element of a declared array) starts with.
double initialValue(ValueType t);

// Converts `v` for a store into a variable of type `t` named `name` (STRING: at most `len`
// bytes). INT rounds half away from zero (Sinumerik ROUND) and must fit 32 bits; BOOL stores
// 0/1 (a string: empty = 0); CHAR holds a one-character string (a number is its code 0..255,
// 0 = ""); STRING and AXIS take strings only; FRAME frames only, and only FRAME (and untyped)
// variables take a frame. False with `error` set otherwise.
bool convertForStore(ValuePool &pool, ValueType t, uint32_t len, std::string_view name, double v, double &out,
                     std::string &error);

// Comparison of two values of which at least one is a string: two strings compare byte-wise;
// a string with a number is an error. op is eq ne lt le gt ge as 0..5.
bool compareStrings(const ValuePool &pool, int op, double a, double b, double &out, std::string &error);

// Run-time type errors of a handle (a string or a frame) where a number is needed, the same in
// both engines: `kind` is handleKind(v) ("string", "frame"), `name` the operator or builtin.
enum class HandleUse : uint8_t {
  Operator,     // operator 'add' needs numbers, found a string
  Builtin,      // 'SIN' needs numbers, found a frame
  AsNumber,     // a string is used where a number is needed
  InParameter,  // a frame cannot be stored in a numeric parameter
};
std::string handleMessage(HandleUse use, std::string_view kind, std::string_view name = {});
const char *handleKind(double v);

// Declared arrays: index `index` of dimension `dim` (1-based) of array `name` of `rank`
// dimensions is not an integer in 0..extent-1.
std::string declaredIndexMessage(std::string_view name, double index, unsigned dim, unsigned rank, uint32_t extent);

}  // namespace ncc
