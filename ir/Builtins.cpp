#include "ir/Builtins.h"
#include "ir/Arith.h"
#include "ir/Value.h"

#include <cmath>

namespace ncc {

static constexpr double kDeg = M_PI / 180.0;

extern "C" {
double ncc_builtin_sin(const double *a) { return std::sin(num(a[0]) * kDeg); }
double ncc_builtin_cos(const double *a) { return std::cos(num(a[0]) * kDeg); }
double ncc_builtin_tan(const double *a) { return std::tan(num(a[0]) * kDeg); }
double ncc_builtin_asin(const double *a) { return std::asin(num(a[0])) / kDeg; }
double ncc_builtin_acos(const double *a) { return std::acos(num(a[0])) / kDeg; }
// One-argument ATAN; Macro B's ATAN[a]/[b] and RS274's ATAN[a]/[b] lower to ATAN2.
double ncc_builtin_atan(const double *a) { return std::atan(num(a[0])) / kDeg; }
// ATAN2 in [0, 360) as Fanuc returns it.
double ncc_builtin_atan2(const double *a) {
  double d = std::atan2(num(a[0]), num(a[1])) / kDeg;
  return d < 0 ? d + 360.0 : d;
}
double ncc_builtin_sqrt(const double *a) { return std::sqrt(num(a[0])); }
double ncc_builtin_abs(const double *a) { return std::fabs(num(a[0])); }
// Rounds half away from zero (Fanuc ROUND, RS274 ROUND).
double ncc_builtin_round(const double *a) { return std::round(num(a[0])); }
double ncc_builtin_fix(const double *a) { return std::floor(num(a[0])); }
double ncc_builtin_fup(const double *a) { return std::ceil(num(a[0])); }
double ncc_builtin_awayfromzero(const double *a) { return arithAwayFromZero(num(a[0])); }
double ncc_builtin_trunc(const double *a) { return std::trunc(num(a[0])); }
double ncc_builtin_ln(const double *a) { return std::log(num(a[0])); }
double ncc_builtin_exp(const double *a) { return std::exp(num(a[0])); }
double ncc_builtin_pow(const double *a) { return std::pow(num(a[0]), num(a[1])); }
double ncc_builtin_min(const double *a) { return std::fmin(num(a[0]), num(a[1])); }
double ncc_builtin_max(const double *a) { return std::fmax(num(a[0]), num(a[1])); }
// EXISTS[#<name>] (RS274NGC) asks whether a variable has a value: both engines answer it from
// their variable storage (isExistsCall), never through this function.
double ncc_builtin_exists(const double *) { return 1.0; }
}

static const BuiltinInfo kBuiltins[] = {
    {"SIN", 1, ncc_builtin_sin, "ncc_builtin_sin"},       {"COS", 1, ncc_builtin_cos, "ncc_builtin_cos"},
    {"TAN", 1, ncc_builtin_tan, "ncc_builtin_tan"},       {"ASIN", 1, ncc_builtin_asin, "ncc_builtin_asin"},
    {"ACOS", 1, ncc_builtin_acos, "ncc_builtin_acos"},    {"ATAN", 1, ncc_builtin_atan, "ncc_builtin_atan"},
    {"ATAN2", 2, ncc_builtin_atan2, "ncc_builtin_atan2"}, {"SQRT", 1, ncc_builtin_sqrt, "ncc_builtin_sqrt"},
    {"ABS", 1, ncc_builtin_abs, "ncc_builtin_abs"},       {"ROUND", 1, ncc_builtin_round, "ncc_builtin_round"},
    {"FIX", 1, ncc_builtin_fix, "ncc_builtin_fix"},       {"FUP", 1, ncc_builtin_fup, "ncc_builtin_fup"},
    {"TRUNC", 1, ncc_builtin_trunc, "ncc_builtin_trunc"}, {"LN", 1, ncc_builtin_ln, "ncc_builtin_ln"},
    {"EXP", 1, ncc_builtin_exp, "ncc_builtin_exp"},       {"POT", 2, ncc_builtin_pow, "ncc_builtin_pow"},
    {"MINVAL", 2, ncc_builtin_min, "ncc_builtin_min"},    {"MAXVAL", 2, ncc_builtin_max, "ncc_builtin_max"},
    {"EXISTS", 1, ncc_builtin_exists, "ncc_builtin_exists"},
    {"AWAYFROMZERO", 1, ncc_builtin_awayfromzero, "ncc_builtin_awayfromzero"},
};

const BuiltinInfo *builtinTable(unsigned &count) {
  count = sizeof(kBuiltins) / sizeof(kBuiltins[0]);
  return kBuiltins;
}

const BuiltinInfo *findBuiltin(std::string_view name) {
  for (auto &b : kBuiltins) {
    std::string_view n = b.name;
    if (n.size() != name.size()) continue;
    bool eq = true;
    for (size_t i = 0; i < n.size() && eq; ++i) {
      char c = name[i];
      if (c >= 'a' && c <= 'z') c = (char)(c - 32);
      eq = c == n[i];
    }
    if (eq) return &b;
  }
  return nullptr;
}

}  // namespace ncc
