#include "ir/Builtins.h"
#include "ir/ContourMath.h"
#include "ir/FrameBuiltins.h"
#include "ir/Arith.h"
#include "ir/StrArgs.h"
#include "ir/FileCommands.h"
#include "ir/Sprint.h"
#include "ir/SystemParams.h"
#include "ir/Value.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace ncc {

static constexpr double kDeg = kRadiansPerDegree;

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
// A computed parameter number (ir/SystemParams.h), one function per map: the number itself when
// it is plain storage, else NaN (the domain error). As the index of `#[…]` the engines resolve
// the number through the map instead, controller state included; this is the call alone.
static double plainOrNan(ParamMap m, double n) { return plainParameter(m, parameterNumber(n)) ? n : NAN; }
double ncc_builtin_ngc_parameter(const double *a) { return plainOrNan(ParamMap::Rs274, num(a[0])); }
double ncc_builtin_macro_variable(const double *a) { return plainOrNan(ParamMap::MacroB, num(a[0])); }
double ncc_builtin_macro_variable_c(const double *a) { return plainOrNan(ParamMap::MacroBMemoryC, num(a[0])); }
double ncc_builtin_macro_variable_lathe(const double *a) { return plainOrNan(ParamMap::MacroBLathe, num(a[0])); }
double ncc_builtin_ln(const double *a) { return std::log(num(a[0])); }
double ncc_builtin_exp(const double *a) { return std::exp(num(a[0])); }
double ncc_builtin_pow(const double *a) { return std::pow(num(a[0]), num(a[1])); }
double ncc_builtin_min(const double *a) { return std::fmin(num(a[0]), num(a[1])); }
double ncc_builtin_max(const double *a) { return std::fmax(num(a[0]), num(a[1])); }
// Sinumerik BOUND(min, max, x): x clamped to [min, max] (a value equal to a limit is x).
double ncc_builtin_bound(const double *a) { return std::fmin(std::fmax(num(a[2]), num(a[0])), num(a[1])); }
// Sinumerik ROUNDUP: the smallest integer >= x (ROUNDUP(-3.6) = -3).
double ncc_builtin_roundup(const double *a) { return std::ceil(num(a[0])); }
// Sinumerik ATAN2(a, b): the angle of the vector (b, a) in (-180, 180], unlike Fanuc's [0, 360).
double ncc_builtin_atan2_signed(const double *a) { return std::atan2(num(a[0]), num(a[1])) / kDeg; }
// EXISTS[#<name>] (RS274NGC) asks whether a variable has a value: both engines answer it from
// their variable storage (isExistsCall), never through this function.
double ncc_builtin_exists(const double *) { return 1.0; }
// Comparisons with a relative tolerance (Sinumerik compares REALs so, relative 1e-12): a and b
// are equal when |a - b| <= tol * max(|a|, |b|); the front end supplies tol (args[2]).
static bool tolEqual(const double *a) {
  double x = num(a[0]), y = num(a[1]);
  return x == y || std::fabs(x - y) <= num(a[2]) * std::fmax(std::fabs(x), std::fabs(y));
}
double ncc_builtin_toleq(const double *a) { return tolEqual(a) ? 1.0 : 0.0; }
double ncc_builtin_tolne(const double *a) { return tolEqual(a) ? 0.0 : 1.0; }
double ncc_builtin_tollt(const double *a) { return num(a[0]) < num(a[1]) && !tolEqual(a) ? 1.0 : 0.0; }
double ncc_builtin_tolle(const double *a) { return num(a[0]) < num(a[1]) || tolEqual(a) ? 1.0 : 0.0; }
double ncc_builtin_tolgt(const double *a) { return num(a[0]) > num(a[1]) && !tolEqual(a) ? 1.0 : 0.0; }
double ncc_builtin_tolge(const double *a) { return num(a[0]) > num(a[1]) || tolEqual(a) ? 1.0 : 0.0; }
}

// ---------------------------------------------------------------- string builtins
// Positions are 0-based and -1 means "not found" (Sinumerik INDEX/RINDEX/MINDEX/MATCH/SUBSTR).
namespace {
double position(size_t p) { return p == std::string_view::npos ? -1.0 : (double)p; }
}  // namespace

#define NCC_STRFN(NAME) \
  static bool NAME(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error)

NCC_STRFN(strStrlen) {
  StrArgs a{pool, args, n, error, "STRLEN"};
  std::string_view s;
  if (!a.str(0, s)) return false;
  out = (double)s.size();
  return true;
}
// INDEX/RINDEX(s, c): first/last position of the character c; MINDEX(s, list): first position
// of any character of list; MATCH(s, t): first position of the substring t.
template <size_t (*Find)(std::string_view, std::string_view)>
static bool search(StrArgs a, bool oneChar, double &out) {
  std::string_view s, t;
  char c;
  if (!a.str(0, s)) return false;
  if (oneChar ? !a.chr(1, c) : !a.str(1, t)) return false;
  out = position(Find(s, oneChar ? std::string_view(&c, 1) : t));
  return true;
}
static size_t findFirst(std::string_view s, std::string_view t) { return s.find(t); }
static size_t findLast(std::string_view s, std::string_view t) { return s.rfind(t); }
static size_t findAny(std::string_view s, std::string_view t) { return s.find_first_of(t); }
NCC_STRFN(strIndex) { return search<findFirst>({pool, args, n, error, "INDEX"}, true, out); }
NCC_STRFN(strRindex) { return search<findLast>({pool, args, n, error, "RINDEX"}, true, out); }
NCC_STRFN(strMindex) { return search<findAny>({pool, args, n, error, "MINDEX"}, false, out); }
NCC_STRFN(strMatch) { return search<findFirst>({pool, args, n, error, "MATCH"}, false, out); }
// SUBSTR(s, i[, len]): from index i, len characters or to the end; i past the end gives "".
NCC_STRFN(strSubstr) {
  StrArgs a{pool, args, n, error, "SUBSTR"};
  std::string_view s;
  double i, len = -1;
  if (!a.str(0, s) || !a.number(1, i) || (n > 2 && !a.number(2, len))) return false;
  if (i < 0 || i != std::trunc(i) || (n > 2 && (len < 0 || len != std::trunc(len)))) {
    error = "'SUBSTR' index and length must be non-negative integers";
    return false;
  }
  size_t from = i >= (double)s.size() ? s.size() : (size_t)i;
  size_t count = n > 2 && len < (double)s.size() ? (size_t)len : std::string_view::npos;
  return a.ret(s.substr(from, count), out);
}
// s[i] (Sinumerik character access, L3870-L3893): the index 0 … length-1 of the string as it is.
static bool charIndex(StrArgs &a, std::string_view s, double &i) {
  if (!a.number(1, i)) return false;
  if (i < 0 || i != std::trunc(i) || i >= (double)s.size()) {
    a.error = fmt::format("character index {} is outside the string of {} characters", numberText(i), s.size());
    return false;
  }
  return true;
}
NCC_STRFN(strCharAt) {
  StrArgs a{pool, args, n, error, "CHAR_AT"};
  std::string_view s;
  double i;
  if (!a.str(0, s) || !charIndex(a, s, i)) return false;
  return a.ret(s.substr((size_t)i, 1), out);
}
// s[i] = c: the string with character i replaced; the character 0 (the number 0 or "") ends the
// string there (L3543-L3555).
NCC_STRFN(strSetChar) {
  StrArgs a{pool, args, n, error, "CHAR_SET"};
  std::string_view s;
  double i;
  if (!a.str(0, s) || !charIndex(a, s, i)) return false;
  std::string r(s);
  std::string_view c = isString(args[2]) ? pool.text(args[2]) : std::string_view();
  double code = isString(args[2]) ? (c.empty() ? 0 : -1) : num(args[2]);
  if (code == 0) r.resize((size_t)i);
  else if (c.size() == 1) r[(size_t)i] = c[0];
  else if (code >= 1 && code <= 255 && code == std::trunc(code)) r[(size_t)i] = (char)(int)code;
  else {
    error = "a character of a string takes a CHAR (one character) or a code 0…255";
    return false;
  }
  return a.ret(r, out);
}
static bool changeCase(StrArgs a, int (*f)(int), double &out) {
  std::string_view s;
  if (!a.str(0, s)) return false;
  std::string r(s);
  for (char &c : r) c = (char)f((unsigned char)c);
  return a.ret(r, out);
}
NCC_STRFN(strToupper) { return changeCase({pool, args, n, error, "TOUPPER"}, ::toupper, out); }
NCC_STRFN(strTolower) { return changeCase({pool, args, n, error, "TOLOWER"}, ::tolower, out); }
// A number literal, surrounding blanks allowed: what NUMBER converts and ISNUMBER accepts. The
// exponent may be written Sinumerik's way, EX (any case): "1234.9876Ex-7".
static bool parseNumber(std::string_view s, double &out) {
  std::string t(s);
  size_t b = t.find_first_not_of(" \t"), e = t.find_last_not_of(" \t");
  if (b == std::string::npos) return false;
  t = t.substr(b, e - b + 1);
  for (size_t i = 0; i + 1 < t.size(); ++i)
    if ((t[i] == 'e' || t[i] == 'E') && (t[i + 1] == 'x' || t[i + 1] == 'X')) {
      t.erase(i + 1, 1);
      break;
    }
  char *end;
  out = std::strtod(t.c_str(), &end);
  return *end == 0 && std::isfinite(out) && std::isdigit((unsigned char)t[t.find_first_not_of("+-.")]);
}
NCC_STRFN(strNumber) {
  StrArgs a{pool, args, n, error, "NUMBER"};
  std::string_view s;
  if (!a.str(0, s)) return false;
  if (!parseNumber(s, out)) {
    error = fmt::format("'NUMBER' cannot convert \"{}\" to a number", s);
    return false;
  }
  return true;
}
NCC_STRFN(strIsnumber) {
  StrArgs a{pool, args, n, error, "ISNUMBER"};
  std::string_view s;
  double v;
  if (!a.str(0, s)) return false;
  out = parseNumber(s, v) ? 1.0 : 0.0;
  return true;
}
// TOSTR(x): the text of any value (Sinumerik unary <<): numbers as numberText.
// AXNAME(s): the axis of that name (an AXIS holds its name); an error for a name that is no
// axis of ncc's channel (X Y Z A B C U V W), as the control's alarm for an unconfigured one.
NCC_STRFN(strAxname) {
  StrArgs a{pool, args, n, error, "AXNAME"};
  std::string_view s;
  if (!a.str(0, s)) return false;
  std::string up(s);
  for (char &c : up) c = (char)std::toupper((unsigned char)c);
  static const char *kAxes[] = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};
  for (const char *ax : kAxes)
    if (up == ax) return a.ret(up, out);
  error = fmt::format("'AXNAME': \"{}\" is not an axis (X Y Z A B C U V W)", s);
  return false;
}
NCC_STRFN(strTostr) { return StrArgs{pool, args, n, error, "TOSTR"}.ret(valueText(pool, args[0]), out); }
// CHR(code): the one-character string of a code 1..255 ("" for 0); ORD(s): the code of the
// first character of s, 0 for "".
NCC_STRFN(strChr) {
  StrArgs a{pool, args, n, error, "CHR"};
  double v;
  if (!a.number(0, v)) return false;
  if (!(v >= 0 && v <= 255) || v != std::trunc(v)) {
    error = fmt::format("'CHR' argument {} is not a character code 0..255", numberText(v));
    return false;
  }
  char c = (char)(unsigned char)v;
  return a.ret(v == 0 ? std::string_view() : std::string_view(&c, 1), out);
}
NCC_STRFN(strOrd) {
  StrArgs a{pool, args, n, error, "ORD"};
  std::string_view s;
  if (!a.str(0, s)) return false;
  out = s.empty() ? 0.0 : (double)(unsigned char)s[0];
  return true;
}
std::string sinumerikProgramName(std::string_view written, std::string &type) {
  size_t cut = written.find_last_of("/:");
  std::string name(written.substr(cut == std::string_view::npos ? 0 : cut + 1));
  for (auto &c : name) c = (char)std::toupper((unsigned char)c);
  type.clear();
  std::string t = name.size() > 4 ? name.substr(name.size() - 4) : "";
  if (name.size() > 7 && name.compare(0, 3, "_N_") == 0 && (t == "_MPF" || t == "_SPF")) {
    type = t.substr(1);
    name = name.substr(3, name.size() - 7);
  } else if (name.size() > 4 && (t == ".MPF" || t == ".SPF")) {  // a file name (EXTCALL, L8868)
    type = t.substr(1);
    name.resize(name.size() - 4);
  }
  return name;
}
NCC_STRFN(strSinProgname) {
  StrArgs a{pool, args, n, error, "SIN_PROGNAME"};
  std::string_view s;
  std::string type;
  return a.str(0, s) && a.ret(sinumerikProgramName(s, type), out);
}
#undef NCC_STRFN

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
    {"BOUND", 3, ncc_builtin_bound, "ncc_builtin_bound"},   {"ROUNDUP", 1, ncc_builtin_roundup, "ncc_builtin_roundup"},
    {"ATAN2_SIGNED", 2, ncc_builtin_atan2_signed, "ncc_builtin_atan2_signed"},
    {"NGC_PARAMETER", 1, ncc_builtin_ngc_parameter, "ncc_builtin_ngc_parameter"},
    {"MACRO_VARIABLE", 1, ncc_builtin_macro_variable, "ncc_builtin_macro_variable"},
    {"MACRO_VARIABLE_C", 1, ncc_builtin_macro_variable_c, "ncc_builtin_macro_variable_c"},
    {"MACRO_VARIABLE_LATHE", 1, ncc_builtin_macro_variable_lathe, "ncc_builtin_macro_variable_lathe"},
    {"AWAYFROMZERO", 1, ncc_builtin_awayfromzero, "ncc_builtin_awayfromzero"},
    {"TOLEQ", 3, ncc_builtin_toleq, "ncc_builtin_toleq"},   {"TOLNE", 3, ncc_builtin_tolne, "ncc_builtin_tolne"},
    {"TOLLT", 3, ncc_builtin_tollt, "ncc_builtin_tollt"},   {"TOLLE", 3, ncc_builtin_tolle, "ncc_builtin_tolle"},
    {"TOLGT", 3, ncc_builtin_tolgt, "ncc_builtin_tolgt"},   {"TOLGE", 3, ncc_builtin_tolge, "ncc_builtin_tolge"},
    // Sinumerik INTERSEC and CALCDAT (ir/ContourMath.h): the selector first.
    {"SIN_INTERSEC", 16, ncc_builtin_sin_intersec, "ncc_builtin_sin_intersec"},
    {"SIN_CALCDAT", 10, ncc_builtin_sin_calcdat, "ncc_builtin_sin_calcdat", nullptr, nullptr, 'n', 8},
    // String builtins: name, arity, -, -, function, argument kinds, result kind, fewest arguments.
    {"STRLEN", 1, nullptr, nullptr, strStrlen, "s", 'n'},
    {"INDEX", 2, nullptr, nullptr, strIndex, "ss", 'n'},
    {"RINDEX", 2, nullptr, nullptr, strRindex, "ss", 'n'},
    {"MINDEX", 2, nullptr, nullptr, strMindex, "ss", 'n'},
    {"MATCH", 2, nullptr, nullptr, strMatch, "ss", 'n'},
    {"SUBSTR", 3, nullptr, nullptr, strSubstr, "snn", 's', 2},
    {"CHAR_AT", 2, nullptr, nullptr, strCharAt, "sn", 's'},
    {"CHAR_SET", 3, nullptr, nullptr, strSetChar, "sna", 's'},
    {"TOUPPER", 1, nullptr, nullptr, strToupper, "s", 's'},
    {"TOLOWER", 1, nullptr, nullptr, strTolower, "s", 's'},
    {"NUMBER", 1, nullptr, nullptr, strNumber, "s", 'n'},
    {"ISNUMBER", 1, nullptr, nullptr, strIsnumber, "s", 'n'},
    {"TOSTR", 1, nullptr, nullptr, strTostr, "a", 's'},
    {"AXNAME", 1, nullptr, nullptr, strAxname, "s", 's'},
    {"CHR", 1, nullptr, nullptr, strChr, "n", 's'},
    {"ORD", 1, nullptr, nullptr, strOrd, "s", 'n'},
    {"SIN_PROGNAME", 1, nullptr, nullptr, strSinProgname, "s", 's'},
    {"SPRINT", 12, nullptr, nullptr, strSprint, "saaaaaaaaaaa", 's', 1},
    // File builtins (ir/FileCommands.h): the Sinumerik command name first.
    {"FILE_WRITE", 3, nullptr, nullptr, fileWrite, "sss", 'n'},
    {"FILE_DELETE", 2, nullptr, nullptr, fileDelete, "ss", 'n'},
    {"FILE_EXISTS", 2, nullptr, nullptr, fileExists, "ss", 'n'},
    {"FILE_STATUS", 2, nullptr, nullptr, fileStatus, "ss", 'n'},
    {"FILE_INFO", 3, nullptr, nullptr, fileInfo, "sss", 's'},
    {"FILE_SIZE", 2, nullptr, nullptr, fileSize, "ss", 'n'},
    {"FILE_READ_STATUS", 5, nullptr, nullptr, fileReadStatus, "ssnnn", 'n'},
    {"FILE_LINE", 6, nullptr, nullptr, fileLine, "ssnnnn", 's'},
    // Frame builtins (ir/FrameBuiltins.h): argument kinds 's' (an axis or component name), 'n',
    // 'f' (a frame); result 'f'.
    // The builders take 0 pairs too: CTRANS() is the identity (Sinumerik's empty TRANS).
    {"CTRANS", 12, nullptr, nullptr, frameCtrans, "snsnsnsnsnsn", 'f', 0},
    {"CFINE", 12, nullptr, nullptr, frameCfine, "snsnsnsnsnsn", 'f', 0},
    {"CROT", 6, nullptr, nullptr, frameCrot, "snsnsn", 'f', 0},
    {"CROTS", 6, nullptr, nullptr, frameCrots, "snsnsn", 'f', 0},
    {"CSCALE", 12, nullptr, nullptr, frameCscale, "snsnsnsnsnsn", 'f', 0},
    {"CMIRROR", 6, nullptr, nullptr, frameCmirror, "ssssss", 'f', 0},
    {"INVFRAME", 1, nullptr, nullptr, frameInvframe, "f", 'f'},
    {"FRAME_CHAIN", 2, nullptr, nullptr, frameChainFn, "ff", 'f'},
    {"FRAME_GET", 3, nullptr, nullptr, frameGet, "fss", 'n'},
    {"FRAME_SET", 4, nullptr, nullptr, frameSet, "fssn", 'f'},
};

const BuiltinInfo *builtinTable(unsigned &count) {
  count = sizeof(kBuiltins) / sizeof(kBuiltins[0]);
  return kBuiltins;
}

std::string builtinArity(const BuiltinInfo &b) {
  unsigned lo = b.fewest();
  if (lo == b.arity) return fmt::format("{}", b.arity);
  return fmt::format("{} {} {}", lo, lo + 1 == b.arity ? "or" : "to", b.arity);
}

std::string builtinDomainError(const BuiltinInfo &b) {
  std::string_view n = b.name;
  if (ParamMap m; paramMapFromBuiltin(n, m))  // a computed #[…] number used as a value
    return "computed parameter number is not " + plainRangesText(m) + " (a plain parameter of '" + std::string(n) + "')";
  return "'" + std::string(n) + "' argument out of domain";
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
