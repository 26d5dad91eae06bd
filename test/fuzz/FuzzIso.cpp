// libFuzzer target: the ISO front end, each input read both as a Fanuc .nc program and as a
// LinuxCNC .ngc program, then everything a user would run on it (see FuzzCommon.h).
#include "frontend/iso/IsoFrontend.h"
#include "test/fuzz/FuzzCommon.h"

using namespace ncc;

static void readAs(std::string_view name, std::string_view text) {
  bool small = text.size() <= fuzz::kMaxRunBytes;
  // ncc lint: recovery after front-end errors, static rules, a keep-going run.
  {
    fuzz::Session s;
    s.diags.setErrorLimit(100000);
    uint32_t f = s.add(name, text);
    if (small) s.lint(f);
  }
  // ncc compile --emit=ir / ncc opt, and ncc run on the whole-program module.
  fuzz::Session s;
  // Fanuc decimal modes change how every number is read; pick one per input.
  static const char *const kModes[] = {"calculator", "is-b", "is-c"};
  if (name.ends_with(".nc")) s.opts.decimalMode = kModes[text.size() % 3];
  uint32_t f = s.add(name, text);
  ir::Module m;
  if (!s.load(f, m)) return;
  fuzz::roundTrip(s, m);
  if (!small) return;
  MotionBuffer whole;
  bool wholeOk = s.executeModule(m, whole) && fuzz::feedSinks(s, whole);
  // ncc run streams flat programs block by block: it must give the same path as the whole
  // program (both succeed or not; the records are equal).
  if (!iso::isoIsStreamable(text)) return;
  fuzz::Session st;
  st.opts.decimalMode = s.opts.decimalMode;
  MotionBuffer streamed;
  bool streamedOk = fuzz::run(st, st.add(name, text), &streamed);
  if (wholeOk && streamedOk) {
    std::string a = fuzz::motionText(whole), b = fuzz::motionText(streamed);
    fuzzCheck(a == b, "streamed and whole-program runs differ:\n" + a + "---\n" + b);
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text((const char *)data, size);
  readAs("fuzz.nc", text);
  readAs("fuzz.ngc", text);
  return 0;
}
