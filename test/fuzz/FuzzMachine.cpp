// libFuzzer target: the machine-description reader (Machine::parse), then `ncc machine --check`,
// `ncc run` and `ncc translate` of fixed programs on the machine read (see FuzzCommon.h).
#include "runtime/Machine.h"
#include "test/fuzz/FuzzCommon.h"

#include <fmt/format.h>

using namespace ncc;

// What a machine description changes: axes and limits (soft limits, rotary A), tools and tool
// lengths, work offsets, home positions, decimal mode, feeds for the planner, arcs and cycles
// for the emitters, inch output. Rotary axes the machine has are moved before the end.
static const char kProgram[] = R"(O1234
G21 G17 G40 G49 G80 G90 G94
T1 M6
G54 G0 X0 Y0 Z5 S1200 M3
G43 H1 Z2
G1 Z-1 F200
G1 X20 Y5 F600
G2 X30 Y15 R10
G3 X20 Y25 I-10 J0
G91 G1 X-5 Y-5
G90 G41 D1 G1 X0 Y0
G40 G0 Z5
G81 X10 Y10 Z-3 R1 F100
G83 X20 Y10 Z-6 Q2 R1
G80
G55 G0 X1 Y1
G4 P500
G20 G1 X1 Y1 F10
G21 G28 Z10
G30
)";

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string text((const char *)data, size);
  Machine machine;
  std::string err;
  if (!Machine::parse(text, "fuzz.ini", machine, err)) return 0;
  fuzz::Session s;
  s.machine = machine;
  std::string program = kProgram;
  for (int a = 3; a < kAxes; ++a)
    if (machine.axes[a].present) program += fmt::format("G0 {}30\n", kAxisLetters[a]);
  program += "M5 M9\nM30\n";
  uint32_t f = s.add("prog.nc", program);
  // ncc translate --verify: the ISO output runs on the same machine.
  std::string iso;
  if (!fuzz::run(s, f, nullptr, &iso) || iso.empty()) return 0;
  fuzz::Session back;
  back.machine = machine;
  fuzz::run(back, back.add("translated.nc", iso));
  return 0;
}
