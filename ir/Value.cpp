#include "ir/Value.h"

#include <fmt/format.h>

#include <cstring>

namespace ncc {

std::string numberText(double v) {
  if (isVacant(v)) return "";
  if (v == std::trunc(v) && std::fabs(v) < 1e15) return fmt::format("{}", (long long)v);
  if (!std::isfinite(v)) return fmt::format("{}", v);
  // Sinumerik converts a REAL to text with up to 10 decimal places (manual L3564-L3565): SIN(30)
  // is "0.5", not its double's 17 digits; trailing zeros are dropped.
  std::string s = fmt::format("{:.10f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string fixedNumberText(double v) {
  if (isUnset(v)) return "######";
  return fmt::format("{:.6f}", isVacant(v) ? 0.0 : v);
}

std::string bitwiseOperandMessage(std::string_view op) {
  return fmt::format("bitwise '{}' needs integer operands", op);
}

double unsetValue() { return bitsValue(kUnsetBits); }
bool isUnset(double v) { return valueBits(v) == kUnsetBits; }

bool programName(double v, std::string &out) {
  v = num(v);
  if (!(v >= 0 && v < 1e15) || v != std::trunc(v)) return false;
  out = fmt::format("O{}", (long long)v);
  return true;
}

std::string unknownProgramMessage(std::string_view name) {
  return fmt::format("call to unknown program '{}'", name);
}
std::string noReturnValueMessage() { return "the called function returned no value for 'result'"; }
std::string badProgramNumberMessage(double v) {
  return fmt::format("call target {} is not a program number (a non-negative integer)", numberText(v));
}

std::string unsetElementMessage(std::string_view name, double index) {
  return fmt::format("array element '{}[{}]' used before assignment", name, numberText(index));
}

}  // namespace ncc
