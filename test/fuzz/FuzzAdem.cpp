// libFuzzer target: the ADEM CLData reader (frontend/cldata, .cld), then everything a user would
// run on the module (see FuzzCommon.h). The first input byte picks the form the rest is read in:
//   0 mod 3: the text listing (NULs in its first 64 bytes become blanks, so it reads as text);
//   1 mod 3: the binary file of 8-byte cells, as it is;
//   2 mod 3: the binary file, written from 2-byte cells: each little-endian int16 is one cell's
//            value, the lowest few stand for NaN, infinities and fractions. Mutations then keep
//            the cell structure (lengths, codes, ordinals) the raw form rarely keeps.
#include "test/fuzz/FuzzCommon.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace {
double compactCell(int16_t n) {
  static const double kSpecial[] = {std::numeric_limits<double>::quiet_NaN(), INFINITY, -INFINITY, 0.5, -0.25,
                                    1e300, -1e-300, -0.0, 0.1, 4194304, 1e9, 2147483648.0};
  int k = n - std::numeric_limits<int16_t>::min();
  return k < (int)std::size(kSpecial) ? kSpecial[k] : n;
}

std::string binaryFromCompact(std::string_view in) {
  std::string out;
  for (size_t i = 0; i + 1 < in.size(); i += 2) {
    int16_t n = (int16_t)((uint8_t)in[i] | (uint8_t)in[i + 1] << 8);
    double d = compactCell(n);
    uint64_t u;
    std::memcpy(&u, &d, 8);
    for (int k = 0; k < 8; ++k) out += (char)(u >> (8 * k) & 0xFF);  // little-endian, as the reader
  }
  return out;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size == 0) return 0;
  std::string rest((const char *)data + 1, size - 1);
  switch (data[0] % 3) {
  case 0:
    for (size_t i = 0; i < rest.size() && i < 64; ++i)
      if (rest[i] == '\0') rest[i] = ' ';
    break;
  case 1: break;
  case 2: rest = binaryFromCompact(rest); break;
  }
  ncc::fuzz::loadAndRun("fuzz.cld", rest);
  return 0;
}
