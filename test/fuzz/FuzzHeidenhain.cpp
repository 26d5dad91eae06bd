// libFuzzer target: the Heidenhain Klartext front end (.h), then everything a user would run on
// the module (see FuzzCommon.h): the IR round trip and passes, the run into every sink.
#include "test/fuzz/FuzzCommon.h"

using namespace ncc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text((const char *)data, size);
  {
    fuzz::Session s;  // ncc lint: recovery after front-end errors
    s.diags.setErrorLimit(100000);
    uint32_t f = s.add("fuzz.h", text);
    if (size <= fuzz::kMaxRunBytes) s.lint(f);
  }
  fuzz::Session s;
  uint32_t f = s.add("fuzz.h", text);
  ir::Module m;
  if (!s.load(f, m)) return 0;
  fuzz::roundTrip(s, m);
  if (size > fuzz::kMaxRunBytes) return 0;
  MotionBuffer whole;
  if (s.executeModule(m, whole)) fuzz::feedSinks(s, whole);
  return 0;
}
