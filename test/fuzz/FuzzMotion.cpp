// libFuzzer target: the Motion IR text parser (ir/MotionText.cpp), then what `ncc run`,
// `ncc translate` and `ncc compile --emit=motion` do with a .motion file: every sink gets the
// records that parse (see FuzzCommon.h), and those records print to text that parses back to
// the same text.
#include "test/fuzz/FuzzCommon.h"

using namespace ncc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text((const char *)data, size);
  fuzz::Session s;
  s.diags.setErrorLimit(100000);
  uint32_t f = s.add("fuzz.motion", text);
  MotionBuffer records;
  if (size <= fuzz::kMaxRunBytes) {
    fuzz::run(s, f, &records);
  } else {
    parseMotionText(s.sm, f, records, s.diags);
  }
  std::string once = fuzz::motionText(records);
  fuzz::Session again;
  MotionBuffer back;
  bool parsed = parseMotionText(again.sm, again.add("again.motion", once), back, again.diags);
  fuzzCheck(parsed && !again.diags.hasErrors(), "the printed records must parse back:\n" + once);
  fuzzCheck(fuzz::motionText(back) == once, "the parsed records must print the same text:\n" + once);
  return 0;
}
