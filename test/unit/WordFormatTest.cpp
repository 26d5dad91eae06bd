// The emitters' word numbers without printf (backends/emit/WordFormat.cpp on runtime/Fixed4.h's
// digit writers) against the printf-based formatter they replace: the same bytes for every word
// format (decimals 0..9, trailing zeros, point on integers, leading zero, plus sign, digit limit,
// discretes) on edge and random values. The reference rounds the same way the word formats
// always have (half away from zero of |v| * 10^decimals) and prints with snprintf; a second check
// holds that rounding to printf's own "%.*f" where the two rules must agree.
#include "backends/emit/WordFormat.h"
#include "runtime/Fixed4.h"

#include <gtest/gtest.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace ncc;
using namespace ncc::emit;

namespace {

// The formatter as it was (printf for the digits): the reference output.
bool referenceNumber(double v, const NumberFormat &fmt, std::string &out) {
  if (!std::isfinite(v)) return false;
  int dec = fmt.decimals < 0 ? 0 : fmt.decimals > 9 ? 9 : fmt.decimals;
  const double scale = std::pow(10.0, dec);  // exact for 10^0..10^9
  double scaled = std::round(std::fabs(v) * scale);
  if (scaled >= 9.0e18) return false;
  uint64_t units = (uint64_t)scaled;
  bool negative = v < 0 && units != 0;
  uint64_t ipart = units / (uint64_t)scale, fpart = units % (uint64_t)scale;
  if (fmt.discrete) ipart = units, fpart = 0, dec = 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%" PRIu64, ipart);
  std::string digits = buf;
  if (fmt.maxIntDigits > 0 && (int)digits.size() > fmt.maxIntDigits) return false;
  std::string frac;
  if (dec > 0) {
    std::snprintf(buf, sizeof buf, "%0*" PRIu64, dec, fpart);
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
  if (!frac.empty()) out += '.' + frac;
  else if (fmt.pointOnInteger && !fmt.discrete) out += '.';
  return true;
}

// Every combination of the format's switches at one number of decimals (64 formats).
std::vector<NumberFormat> formatsAt(int decimals) {
  std::vector<NumberFormat> all;
  for (unsigned bits = 0; bits < 64; ++bits) {
    NumberFormat f;
    f.decimals = decimals;
    f.trailingZeros = bits & 1;
    f.pointOnInteger = bits & 2;
    f.leadingZero = bits & 4;
    f.plusSign = bits & 8;
    f.discrete = bits & 16;
    f.maxIntDigits = bits & 32 ? 4 : 0;
    f.padDigits = bits & 32 ? 2 : 0;
    all.push_back(f);
  }
  return all;
}

void expectSame(double v, const NumberFormat &f) {
  std::string got = "unchanged", want = "unchanged";
  bool okGot = formatNumber(v, f, got), okWant = referenceNumber(v, f, want);
  ASSERT_EQ(okGot, okWant) << std::hexfloat << v << " at " << f.decimals;
  if (okGot) ASSERT_EQ(got, want) << std::hexfloat << v << " at " << f.decimals << " decimals";
  else ASSERT_EQ(got, "unchanged");
}

}  // namespace

TEST(EmitWordFormat, DigitWriters) {
  char buf[32];
  std::mt19937_64 g(20261129);
  for (int i = 0; i < 200000; ++i) {
    uint64_t v = g() >> (g() % 64);
    char want[32];
    std::snprintf(want, sizeof want, "%" PRIu64, v);
    ASSERT_EQ(std::string(buf, writeUnsigned(buf, v)), want);
    for (int n = 0; n <= 9; ++n) {
      uint64_t f = v % (uint64_t)std::pow(10.0, n);
      std::snprintf(want, sizeof want, "%0*" PRIu64, n, f);
      ASSERT_EQ(std::string(buf, writePadded(buf, f, n)), n ? want : "") << f << " in " << n;
    }
  }
  for (uint64_t v : {uint64_t(0), uint64_t(9), uint64_t(10), uint64_t(99), uint64_t(100), UINT64_MAX}) {
    char want[32];
    std::snprintf(want, sizeof want, "%" PRIu64, v);
    EXPECT_EQ(std::string(buf, writeUnsigned(buf, v)), want);
  }
  for (int64_t v : {int64_t(0), int64_t(7), int64_t(-7), int64_t(123456), INT64_MIN, INT64_MAX})
    for (int pad : {-3, 0, 1, 3, 8, 20, 30}) {
      char want[48];
      int p = pad < 0 ? 0 : pad > 20 ? 20 : pad;
      std::snprintf(want, sizeof want, "%0*" PRId64, v < 0 ? p + 1 : p, v);
      EXPECT_EQ(formatInteger(v, pad), want) << v << " pad " << pad;
    }
}

// Halfway cases, both signs and -0, the ends of each decimals count's range, values that round
// up into a new integer digit, and the first values that fail the digit limit or int64.
TEST(EmitWordFormat, EdgeValuesEqualPrintfFormatter) {
  const double edge[] = {0.0, -0.0, 0.5, -0.5, 1.5, 2.5, -2.5, 0.05, 0.005, 0.0005, 0.00005, 0.000005, 5e-7, 5e-8,
                         5e-9, 5e-10, 0.00015, 0.00025, 1.0005, 1.0015, -1.0005, 0.125, 0.375, 9.5, 99.95, 999.995,
                         9999.99995, 9999.9999, 99999.999995, 999999.9999995, 12.5, 1234.5678, 0.1, 0.2, 0.3,
                         1e-300, -1e-300, 5e-324, -4e-4, -4e-10, 1e9, 9.2e9, 8.9e17, 9e17, 8.99999e18, 9e18,
                         1e19, 1e300, -1e300, INFINITY, -INFINITY, NAN};
  for (int dec = -1; dec <= 10; ++dec)
    for (const NumberFormat &f : formatsAt(dec))
      for (double v : edge) {
        expectSame(v, f);
        expectSame(-v, f);
        for (double w : {std::nextafter(v, INFINITY), std::nextafter(v, -INFINITY)}) expectSame(w, f);
      }
}

TEST(EmitWordFormat, RandomValuesEqualPrintfFormatter) {
  std::mt19937_64 g(20261129);
  for (int dec = 0; dec <= 9; ++dec) {
    const std::vector<NumberFormat> formats = formatsAt(dec);
    const double scale = std::pow(10.0, dec);
    for (int i = 0; i < 20000; ++i) {
      double v = std::ldexp((double)(g() >> 11), -53) * std::pow(10.0, (int)(g() % 16) - 6);
      if (g() & 1) v = -v;
      double tie = (std::floor(v * scale) + 0.5) / scale;  // the nearest decimal tie, its neighbours
      const NumberFormat &f = formats[g() % formats.size()];
      for (double w : {v, tie, std::nextafter(tie, INFINITY), std::nextafter(tie, -INFINITY)}) expectSame(w, f);
    }
  }
}

// The rounding itself, against printf: where |v| * 10^decimals is exact in a double and not a
// tie, the word formats and printf's "%.*f" round alike; at exact ties the word formats go away
// from zero (printf to even). A rounding change in writeNumber fails here.
TEST(EmitWordFormat, RoundingAgreesWithPrintfAwayFromTies) {
  std::mt19937_64 g(4343);
  for (int dec = 0; dec <= 6; ++dec) {
    NumberFormat f;
    f.decimals = dec;
    f.trailingZeros = true;
    const double scale = std::pow(10.0, dec);
    for (int i = 0; i < 50000; ++i) {
      // k / 2^s: exact binary, its product with 10^dec exact for these sizes.
      double v = std::ldexp((double)(g() % (1u << 24)), -(int)(g() % 12));
      if (g() & 1) v = -v;
      double p = std::fabs(v) * scale;
      std::string got;
      ASSERT_TRUE(formatNumber(v, f, got));
      char want[64];
      if (p - std::floor(p) == 0.5) {  // a tie: away from zero
        std::snprintf(want, sizeof want, "%.*f", dec, (v < 0 ? -1 : 1) * (std::floor(p) + 1) / scale);
      } else {
        std::snprintf(want, sizeof want, "%.*f", dec, v);
      }
      std::string w = want;
      if (w.find_first_not_of("-0.") == std::string::npos && w[0] == '-') w.erase(0, 1);  // no "-0"
      ASSERT_EQ(got, w) << std::hexfloat << v << " at " << dec;
    }
  }
  NumberFormat f4;
  f4.decimals = 4;
  f4.trailingZeros = true;
  std::string s;
  ASSERT_TRUE(formatNumber(0.00005, f4, s));
  EXPECT_EQ(s, "0.0001");
  ASSERT_TRUE(formatNumber(-0.00005, f4, s));
  EXPECT_EQ(s, "-0.0001");
  ASSERT_TRUE(formatNumber(-0.00004, f4, s));
  EXPECT_EQ(s, "0.0000");  // no negative zero
  ASSERT_TRUE(formatNumber(-0.0, f4, s));
  EXPECT_EQ(s, "0.0000");
  ASSERT_TRUE(formatNumber(0.00015, f4, s));
  EXPECT_EQ(s, "0.0001");  // 0.00015 * 10^4 is 1.4999999999999998 as a double: below the tie
  ASSERT_TRUE(formatNumber(1.0005, NumberFormat{}, s));
  EXPECT_EQ(s, "1.001");  // 1.0005 * 10^3 is 1000.5 as a double: a tie, away from zero
  ASSERT_TRUE(formatNumber(9999.99995, f4, s));
  EXPECT_EQ(s, "10000.0000");
}
