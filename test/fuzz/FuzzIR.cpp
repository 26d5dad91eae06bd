// libFuzzer target: the NC IR text parser (ir/Parser.cpp), then what `ncc opt`, `ncc compile`,
// `ncc run` and `ncc lint` do with a .ncir file (see FuzzCommon.h).
#include "test/fuzz/FuzzCommon.h"

using namespace ncc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text((const char *)data, size);
  bool small = size <= fuzz::kMaxRunBytes;
  if (small) {
    fuzz::Session s;
    s.diags.setErrorLimit(100000);
    s.lint(s.add("fuzz.ncir", text));
  }
  fuzz::Session s;
  uint32_t f = s.add("fuzz.ncir", text);
  ir::Module m;
  if (!s.load(f, m)) return 0;
  fuzz::roundTrip(s, m);
  if (small) fuzz::run(s, f);
  return 0;
}
