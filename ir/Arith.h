// Arithmetic shared by the eval engine and JIT code (the JIT calls these through ncrt or
// reproduces them exactly). Operands follow ir/Value.h: vacant counts as 0.
#pragma once
#include "ir/Value.h"

#include <cmath>
#include <cstdint>

namespace ncc {

// MOD with the sign of the divisor (LinuxCNC MOD, Fanuc #a - FIX[#a/#b]*#b differs for
// negative operands: front ends that need that form write it out).
inline double arithMod(double a, double b) {
  double r;
  // Whole numbers below 2^53 (loop counters: the usual case) take the integer remainder, which
  // is fmod's exactly (sign of a, -0 for a negative a that divides), at a fraction of its cost.
  if (std::fabs(a) < 0x1p53 && std::fabs(b) < 0x1p53 && (double)(int64_t)a == a && (double)(int64_t)b == b && b != 0) {
    r = (double)((int64_t)a % (int64_t)b);
    if (r == 0) r = std::copysign(0.0, a);
  } else {
    r = std::fmod(a, b);
  }
  if (r != 0 && ((r < 0) != (b < 0))) r += b;
  return r;
}
inline double arithPow(double a, double b) { return std::pow(a, b); }
// Integer division (Sinumerik DIV): truncates toward zero.
inline double arithIDiv(double a, double b) { return std::trunc(a / b); }

// Bitwise AND/OR/XOR (Fanuc Macro B, `[12 OR 3]` = 15) on integral operands below 2^53; NaN
// when an operand is not such an integer (a run-time error in both engines).
inline double arithBitwise(int op, double a, double b) {  // op: 0 and, 1 or, 2 xor
  a = num(a), b = num(b);
  if (a != std::trunc(a) || b != std::trunc(b) || std::fabs(a) > 9007199254740992.0 ||
      std::fabs(b) > 9007199254740992.0)
    return std::nan("");
  long long x = (long long)a, y = (long long)b;
  return (double)(op == 0 ? (x & y) : op == 1 ? (x | y) : (x ^ y));
}
// Fanuc FUP: the integer next away from zero (FUP[-1.2] = -2); LinuxCNC FUP is ceil.
inline double arithAwayFromZero(double a) { return a < 0 ? std::floor(a) : std::ceil(a); }

}  // namespace ncc
