#pragma once
// The code that selects a work offset, for the executor's frame records and the emitters.
#include <string>

namespace ncc {

// Work offset n is Machine::workOffsets slot n (0: none). Sinumerik: G500, G54…G57, G505…G599;
// ISO: G54…G59, then LinuxCNC's G59.1-G59.3 or the 808D's G54 P1…P93. Empty when the set has
// no code for n.
enum class OffsetCodes { Sinumerik, LinuxCnc, Iso808 };
std::string workOffsetCode(int n, OffsetCodes codes);

}  // namespace ncc
