#include "backends/emit/WordFormat.h"

#include "runtime/Fixed4.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ncc::emit {

static const double kPow10[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
static const uint64_t kScale[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};

static int clampDecimals(int d) { return d < 0 ? 0 : d > 9 ? 9 : d; }

double roundTo(double v, int decimals) {
  double s = kPow10[clampDecimals(decimals)];
  double r = std::round(v * s) / s;
  return r == 0 ? 0.0 : r;  // no negative zero
}

// The rounding is the word format's own (half away from zero of |v| * 10^decimals as a double,
// what the emitters have always written), the digits come from runtime/Fixed4.h's writers: no
// printf on the per-record path.
char *writeNumber(char *p, double v, const NumberFormat &fmt) {
  if (!std::isfinite(v)) return nullptr;
  int dec = clampDecimals(fmt.decimals);
  double scaled = std::round(std::fabs(v) * kPow10[dec]);
  if (scaled >= 9.0e18) return nullptr;  // beyond int64: no controller reads that
  uint64_t units = (uint64_t)scaled;
  uint64_t ipart = units, fpart = 0;
  if (fmt.discrete) dec = 0;  // the passport's "integer number of discretes": the units themselves
  else ipart = units / kScale[dec], fpart = units % kScale[dec];

  char digits[kUnsignedMax], frac[kUnsignedMax];
  int ilen = int(writeUnsigned(digits, ipart) - digits);
  if (fmt.maxIntDigits > 0 && ilen > fmt.maxIntDigits) return nullptr;
  int flen = dec;
  writePadded(frac, fpart, dec);
  if (!fmt.trailingZeros)
    while (flen > 0 && frac[flen - 1] == '0') --flen;
  if (ipart == 0 && flen > 0 && !fmt.leadingZero) ilen = 0;

  if (v < 0 && units != 0) *p++ = '-';
  else if (fmt.plusSign && units != 0) *p++ = '+';
  for (int pad = std::min(fmt.padDigits, kNumberPadMax) - ilen; pad > 0; --pad) *p++ = '0';
  std::memcpy(p, digits, size_t(ilen));
  p += ilen;
  if (flen > 0) {
    *p = '.';
    std::memcpy(p + 1, frac, size_t(flen));
    p += flen + 1;
  } else if (fmt.pointOnInteger && !fmt.discrete) {
    *p++ = '.';
  }
  return p;
}

bool formatNumber(double v, const NumberFormat &fmt, std::string &out) {
  char buf[kNumberMax];
  char *end = writeNumber(buf, v, fmt);
  if (!end) return false;
  out.assign(buf, end);
  return true;
}

char *writeInteger(char *p, int64_t v, int pad) {
  uint64_t magnitude = v < 0 ? 0 - uint64_t(v) : uint64_t(v);
  char digits[kUnsignedMax];
  int len = int(writeUnsigned(digits, magnitude) - digits);
  if (v < 0) *p++ = '-';
  for (int n = std::clamp(pad, 0, 20) - len; n > 0; --n) *p++ = '0';
  std::memcpy(p, digits, size_t(len));
  return p + len;
}

std::string formatInteger(int64_t v, int pad) {
  char buf[kIntegerMax];
  return std::string(buf, writeInteger(buf, v, pad));
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
