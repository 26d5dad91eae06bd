// printf's "%.4f" with integer arithmetic: the canonical trace prints every number this way
// (rs274's format), and it is most of the trace writer's time. The digit writers below are the
// one place that turns integers into decimal text without printf: the trace's %.4f and the
// emitters' word formats (backends/emit/WordFormat.cpp) both use them.
#pragma once
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ncc {

// Room formatFixed4 needs at its output: %.4f of the largest double takes 315 characters.
constexpr size_t kFixed4Max = 400;

namespace fixed4detail {
// "00".."99": two digits per lookup.
inline constexpr char kDigitPairs[] =
    "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849"
    "5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";
inline char *pair(char *p, unsigned v) {
  std::memcpy(p, kDigitPairs + 2 * v, 2);
  return p + 2;
}
}  // namespace fixed4detail

// Room writeUnsigned needs: 2^64 has 20 digits.
constexpr size_t kUnsignedMax = 20;

// Writes the decimal digits of v at p (no sign, no padding: "0" for 0) and returns the end.
inline char *writeUnsigned(char *p, uint64_t v) {
  char tmp[kUnsignedMax];
  char *end = tmp + kUnsignedMax, *d = end;
  for (; v >= 100; v /= 100) d -= 2, fixed4detail::pair(d, unsigned(v % 100));
  if (v >= 10) d -= 2, fixed4detail::pair(d, unsigned(v));
  else *--d = char('0' + v);
  std::memcpy(p, d, size_t(end - d));
  return p + (end - d);
}

// Writes exactly n digits of v (v < 10^n, n <= kUnsignedMax), zeros on the left: a fraction's
// digits ("0050" for 50 at n = 4). Returns the end.
inline char *writePadded(char *p, uint64_t v, int n) {
  char *end = p + n, *d = end;
  for (; d - p >= 2; v /= 100) d -= 2, fixed4detail::pair(d, unsigned(v % 100));
  if (d > p) *p = char('0' + v % 10);
  return end;
}

namespace fixed4detail {
// Writes q / 10^4 with four decimals at p for q >= 10^8, returns the end.
[[gnu::noinline]] inline char *digitsLarge(char *p, uint64_t q) {
  p = writeUnsigned(p, q / 10000);
  *p = '.';
  return writePadded(p + 1, q % 10000, 4);
}

// Writes the sign and q / 10^4 with four decimals at p for q < 10^8 (|v| < 10^4, the usual
// case: 32-bit arithmetic, at most four integer digits), returns the end.
inline char *digitsSmall(char *p, bool negative, uint32_t q) {
  *p = '-';
  p += negative;
  const uint32_t ip = q / 10000, f = q % 10000;
  if (ip < 10) *p++ = char('0' + ip);
  else if (ip < 100) p = pair(p, ip);
  else if (ip < 1000) *p = char('0' + ip / 100), p = pair(p + 1, ip % 100);
  else p = pair(pair(p, ip / 100), ip % 100);
  *p = '.';
  return pair(pair(p + 1, f / 100), f % 100);
}

// Writes the sign and q / 10^4 with four decimals at p, returns the end.
inline char *digits(char *p, bool negative, uint64_t q) {
  if (q < 100000000) return digitsSmall(p, negative, uint32_t(q));
  *p = '-';
  return digitsLarge(p + negative, q);
}

// round(|v| * 10^4), ties to even, exactly, for |v| < 2^46: v * 10^4 = m * 5^4 * 2^(e+4) with
// m < 2^53 fits 64 bits, and the bits shifted out decide the rounding.
inline uint64_t exactScaled(uint64_t bits) {
  const int biased = int(bits >> 52) & 0x7ff;
  uint64_t m = bits & ((uint64_t(1) << 52) - 1);
  int e = -1074;  // subnormal
  if (biased) m |= uint64_t(1) << 52, e = biased - 1075;
  const uint64_t x = m * 625;  // < 2^63
  const int s = e + 4;
  if (s >= 0) return x << s;  // |v| < 2^46 keeps it below 2^63
  if (s < -63) return 0;      // x < 2^63 <= half
  const uint64_t q = x >> -s, rem = x & ((uint64_t(1) << -s) - 1), half = uint64_t(1) << (-s - 1);
  return q + (rem > half || (rem == half && (q & 1)));
}
}  // namespace fixed4detail

// Writes v as printf's %.4f at p (room for kFixed4Max characters) and returns the end: the same
// text, "-0.0000" for -0 and for small negatives, ties of the exact binary value to even.
inline char *formatFixed4(char *p, double v) {
  uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const bool negative = bits >> 63;
  // |v| < 10^4, the usual case: |v| * 10^4 in double rounds to the integer the exact product
  // rounds to unless it lies within 0.0001 of a tie (the multiplication is monotonic and the
  // tie, an integer + 0.5, is a double), so near ties the exact path below decides.
  // Below 99999999 the rounded integer is below 10^8 too, and converts as a 32-bit one.
  const double a = std::fabs(v) * 1e4;
  if (a < 99999999.0) {
    const double r = (a + 0x1p52) - 0x1p52;  // a rounded to an integer (ties to even)
    if (std::fabs(a - r) < 0.4999) return fixed4detail::digitsSmall(p, negative, uint32_t(int32_t(r)));
  }
  if ((int(bits >> 52) & 0x7ff) >= 1023 + 46) {  // |v| >= 2^46, inf, nan: to_chars rounds like printf
    auto res = std::to_chars(p, p + kFixed4Max, v, std::chars_format::fixed, 4);
    return res.ec == std::errc() ? res.ptr : p;
  }
  return fixed4detail::digits(p, negative, fixed4detail::exactScaled(bits));
}

}  // namespace ncc
