// Arithmetic and variable-addressing rules shared by the eval engine (passes/Eval) and the JIT
// (backends/jit, through runtime/ncrt), so both engines compute the same numbers and report the
// same run-time errors. Vacant handling follows ir/Value.h: callers pass raw values, these
// functions apply num() themselves.
//
// Decisions (documented in docs/JIT.md as well):
//  - DIV, MOD and IDIV by zero (vacant divisor counts as 0) are the run-time error
//    "division by zero" at the expression's loc; the functions below assume b != 0.
//  - MOD: fmod(a, b) adjusted to take the sign of b (LinuxCNC MOD; 7 MOD 3 = 1, -7 MOD 3 = 2).
//  - IDIV (Sinumerik DIV): a / b truncated toward zero.
//  - POW: std::pow on num() values.
//  - Numbered variable index (#[expr]): num(), rounded half away from zero (std::round).
//    #1..#33 are the current call frame's locals; #0 reads as vacant and cannot be written;
//    every other index in [0, kNumberedVars) is one global array; other indices (and NaN) are
//    the run-time error "parameter number out of range".
//  - R parameters: one global array of kRParams; Q parameters: one array of kQParams per
//    prefix (Q, QL, QR, QS); out-of-range index -> "parameter number out of range".
#pragma once
#include "ir/Value.h"

#include <cmath>
#include <cstdint>

namespace ncc {

constexpr int64_t kNumberedVars = 100000;  // #0 .. #99999
constexpr int64_t kFrameLocals = 33;       // #1 .. #33
constexpr int64_t kRParams = 10000;
constexpr int64_t kQParams = 10000;

inline double arithMod(double a, double b) {
  double x = num(a), y = num(b);
  double r = std::fmod(x, y);
  if (r != 0 && ((r < 0) != (y < 0))) r += y;
  return r;
}
inline double arithIDiv(double a, double b) { return std::trunc(num(a) / num(b)); }
inline double arithPow(double a, double b) { return std::pow(num(a), num(b)); }

enum class VarSlot : uint8_t { Local, Global, OutOfRange };

// Resolves a numbered-variable index expression value. slot gets the array index: 1..33 for
// Local (index into the frame), 0..kNumberedVars-1 for Global.
inline VarSlot numberedSlot(double index, bool write, int64_t &slot) {
  double r = std::round(num(index));
  if (!(r >= 0 && r < (double)kNumberedVars)) return VarSlot::OutOfRange;
  slot = (int64_t)r;
  if (slot >= 1 && slot <= kFrameLocals) return VarSlot::Local;
  if (slot == 0 && write) return VarSlot::OutOfRange;
  return VarSlot::Global;
}
// R/Q parameter index: same rounding; returns false when out of range.
inline bool paramSlot(double index, int64_t count, int64_t &slot) {
  double r = std::round(num(index));
  if (!(r >= 0 && r < (double)count)) return false;
  slot = (int64_t)r;
  return true;
}

}  // namespace ncc
