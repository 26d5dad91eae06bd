// Arithmetic shared by the eval engine and JIT code (the JIT calls these through ncrt or
// reproduces them exactly). Operands follow ir/Value.h: vacant counts as 0.
#pragma once
#include "ir/Value.h"

#include <cmath>

namespace ncc {

// MOD with the sign of the divisor (LinuxCNC MOD, Fanuc #a - FIX[#a/#b]*#b differs for
// negative operands: front ends that need that form write it out).
inline double arithMod(double a, double b) {
  double r = std::fmod(a, b);
  if (r != 0 && ((r < 0) != (b < 0))) r += b;
  return r;
}
inline double arithPow(double a, double b) { return std::pow(a, b); }
// Integer division (Sinumerik DIV): truncates toward zero.
inline double arithIDiv(double a, double b) { return std::trunc(a / b); }

}  // namespace ncc
