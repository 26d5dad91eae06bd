// Number and text formatting for NC words, after the window parameters of a postprocessor
// passport (seed 004 §3.5): decimals, trailing zeros, point on integers, leading zero, plus sign,
// integer-digit limit, left padding, integer count of discretes and the modal flag.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace ncc::emit {

struct NumberFormat {
  int decimals = 3;             // digits after the point; rounding half away from zero
  bool trailingZeros = false;   // X12.500 (true) vs X12.5
  bool pointOnInteger = false;  // X12. (true) vs X12
  bool leadingZero = true;      // X0.5 (true) vs X.5
  bool plusSign = false;        // X+12.5
  int maxIntDigits = 0;         // integer digits allowed; 0 = unlimited
  int padDigits = 0;            // left-pad the integer part with zeros (G01, T01)
  bool discrete = false;        // an integer count of 10^-decimals units, no point: X12500 for 12.5 at 3
  bool modal = true;            // written only when the formatted value changes
};

// The value after rounding to fmt.decimals (what the controller will read back).
double roundTo(double v, int decimals);

// Left padding beyond this many digits is not written (no controller reads wider numbers).
constexpr int kNumberPadMax = 40;
// Room writeNumber needs: sign, padding or 20 integer digits, point, 9 decimals.
constexpr size_t kNumberMax = 1 + kNumberPadMax + 20 + 1 + 9;

// Writes v at p (number only, no letter; room for kNumberMax characters) and returns the end, or
// nullptr when v is not finite or its integer part needs more than maxIntDigits digits.
char *writeNumber(char *p, double v, const NumberFormat &fmt);
// The same into out; false (out unchanged) where writeNumber gives nullptr.
bool formatNumber(double v, const NumberFormat &fmt, std::string &out);

// Room writeInteger needs: sign and 20 digits.
constexpr size_t kIntegerMax = 21;
// Writes an integer word value (T, M, N, O numbers) padded to `pad` digits (at most 20), as
// printf's "%0*lld" with the sign outside the width: -007 for -7 at 3. Returns the end.
char *writeInteger(char *p, int64_t v, int pad);
std::string formatInteger(int64_t v, int pad);

// Text for a comment or message: control characters become spaces, `forbidden` characters are
// replaced by the matching entry of `replacement` (same length), surrounding blanks trimmed.
std::string sanitizeText(std::string_view text, std::string_view forbidden, std::string_view replacement);

}  // namespace ncc::emit
