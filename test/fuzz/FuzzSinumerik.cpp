// libFuzzer target: the Sinumerik front end, each input a main program (.mpf) whose called
// subprograms are looked up in a directory that does not exist, then everything a user would
// run on the module (see FuzzCommon.h): the IR round trip and passes, the run into every sink.
#include "test/fuzz/FuzzCommon.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  ncc::fuzz::loadAndRun("fuzz.mpf", std::string_view((const char *)data, size));
  return 0;
}
