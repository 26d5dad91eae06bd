#include "backends/emit/WordFormat.h"

#include <cmath>
#include <cstdio>

namespace ncc::emit {

static const double kPow10[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

static int clampDecimals(int d) { return d < 0 ? 0 : d > 9 ? 9 : d; }

double roundTo(double v, int decimals) {
  double s = kPow10[clampDecimals(decimals)];
  double r = std::round(v * s) / s;
  return r == 0 ? 0.0 : r;  // no negative zero
}

bool formatNumber(double v, const NumberFormat &fmt, std::string &out) {
  if (!std::isfinite(v)) return false;
  int dec = clampDecimals(fmt.decimals);
  double scaled = std::round(std::fabs(v) * kPow10[dec]);
  if (scaled >= 9.0e18) return false;  // beyond int64: no controller reads that
  uint64_t units = (uint64_t)scaled;
  bool negative = v < 0 && units != 0;
  uint64_t scale = (uint64_t)kPow10[dec];
  uint64_t ipart = units / scale, fpart = units % scale;

  if (fmt.discrete) {  // the passport's "integer number of discretes": the units themselves
    ipart = units;
    fpart = 0;
    dec = 0;
  }
  std::string digits = std::to_string(ipart);
  if (fmt.maxIntDigits > 0 && (int)digits.size() > fmt.maxIntDigits) return false;
  std::string frac;
  if (dec > 0) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%0*llu", dec, (unsigned long long)fpart);
    frac = buf;
    if (!fmt.trailingZeros)
      while (!frac.empty() && frac.back() == '0') frac.pop_back();
  }
  if (ipart == 0 && !frac.empty() && !fmt.leadingZero) digits.clear();
  while ((int)digits.size() < fmt.padDigits) digits.insert(digits.begin(), '0');

  out.clear();
  if (negative) out += '-';
  else if (fmt.plusSign && units != 0) out += '+';
  out += digits;
  if (!frac.empty()) {
    out += '.';
    out += frac;
  } else if (fmt.pointOnInteger && !fmt.discrete) {
    out += '.';
  }
  return true;
}

std::string formatInteger(int64_t v, int pad) {
  char buf[48];
  int p = pad < 0 ? 0 : pad > 20 ? 20 : pad;
  std::snprintf(buf, sizeof buf, "%0*lld", v < 0 ? p + 1 : p, (long long)v);
  return buf;
}

std::string sanitizeText(std::string_view text, std::string_view forbidden, std::string_view replacement) {
  std::string s;
  s.reserve(text.size());
  for (char c : text) {
    unsigned char u = (unsigned char)c;
    if (u < 0x20 || u == 0x7f) {
      s += ' ';
      continue;
    }
    size_t k = forbidden.find(c);
    s += k == std::string_view::npos ? c : (k < replacement.size() ? replacement[k] : ' ');
  }
  size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace ncc::emit
