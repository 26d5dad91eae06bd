#include "ir/Sprint.h"

#include "ir/StrArgs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace ncc {

namespace {
constexpr size_t kMaxSprintBytes = 400;  // L3966

// printf's exponent e+03 as Sinumerik's EX+03.
std::string exponentEX(const std::string &s) {
  size_t e = s.find_first_of("eE");
  if (e == std::string::npos) return s;
  return fmt::format("{}EX{}", s.substr(0, e), s.substr(e + 1));
}

std::string pad(std::string s, int width) {
  if ((int)s.size() < width) s.insert(0, (size_t)width - s.size(), ' ');
  return s;
}

// The width counts the EX exponent, so it pads after the exponent is rewritten.
std::string printfNumber(char conv, int width, int precision, double v) {
  char spec[32], buf[512];
  std::snprintf(spec, sizeof spec, "%%.%d%c", precision >= 0 ? precision : 6, conv);
  std::snprintf(buf, sizeof buf, spec, v);
  return pad(exponentEX(buf), width);
}
}  // namespace

bool strSprint(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  StrArgs a{pool, args, n, error, "SPRINT"};
  std::string_view format;
  if (!a.str(0, format)) return false;
  std::string text;
  unsigned next = 1;
  auto fail = [&](std::string msg) {
    error = "'SPRINT': " + msg;
    return false;
  };
  for (size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '%') {
      text += format[i];
      continue;
    }
    size_t at = i++;
    int width = 0, precision = -1;
    // A width or precision beyond the result's 400 bytes cannot fit: stop counting there.
    auto digits = [&](int &v) {
      while (i < format.size() && std::isdigit((unsigned char)format[i]))
        v = std::min(v * 10 + (format[i++] - '0'), (int)kMaxSprintBytes + 1);
    };
    digits(width);
    if (i < format.size() && format[i] == '.') {
      precision = 0;
      ++i;
      digits(precision);
    }
    if (width > (int)kMaxSprintBytes || precision > (int)kMaxSprintBytes)
      return fail(fmt::format("the width or precision of the descriptor at {} exceeds the result's {} bytes", at, kMaxSprintBytes));
    if (i >= format.size()) return fail(fmt::format("the format descriptor at {} has no letter", at));
    char d = (char)std::toupper((unsigned char)format[i]);
    if (d == 'P') return fail("%P (punched-tape and binary numbers, MD10750/MD10751) is not supported");
    if (next >= n) return fail(fmt::format("no value for the format descriptor %{}", d));
    double v = args[next++];
    bool str = isString(v);
    if (!str && isHandle(v)) return fail("a FRAME cannot be formatted: format its components (L4316)");
    std::string_view s = str ? pool.text(v) : std::string_view();
    double x = num(v);
    switch (d) {
    case 'B': text += pad(str ? (s.empty() ? "FALSE" : "TRUE") : (x != 0 ? "TRUE" : "FALSE"), width); break;
    case 'C':
      if (str && s.empty()) return fail("%C of an empty string");
      text += pad(str ? std::string(1, s[0]) : std::string(1, (char)(int)x), width);
      break;
    case 'D':
    case 'X': {
      if (str && s.size() != 1) return fail(fmt::format("%{} takes a number or a CHAR, not a string", d));
      double r = str ? (double)(unsigned char)s[0] : std::round(x);
      if (std::fabs(r) > 2147483647.0) return fail(fmt::format("%{} of {} does not fit an INT", d, x));
      text += d == 'D' ? pad(fmt::format("{}", (long long)r), width)
                       : pad(fmt::format("{:X}", (uint32_t)(int32_t)(long long)r), width);
      break;
    }
    case 'F':
    case 'E':
    case 'G':
      if (str) return fail(fmt::format("%{} takes a number, not a string", d));
      text += printfNumber(d == 'F' ? 'f' : d, width, precision, x);
      break;
    case 'S': {
      if (!str) return fail("%S takes a string or a CHAR, not a number");
      std::string_view part = precision >= 0 ? s.substr(0, (size_t)precision) : s;
      text += pad(std::string(part), width);
      break;
    }
    default: return fail(fmt::format("unknown format descriptor %{}", format[i]));
    }
  }
  if (next < n) return fail(fmt::format("{} values but {} format descriptors", n - 1, next - 1));
  if (text.size() > kMaxSprintBytes) return fail(fmt::format("the result has {} bytes, more than {}", text.size(), kMaxSprintBytes));
  return a.ret(text, out);
}

}  // namespace ncc
