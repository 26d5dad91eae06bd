// The Heidenhain cycles the front end knows: their parameter lists (the digests' §3, the same
// lists the cycle library's hei.* entries take) and whether they act at CYCL DEF.
#pragma once
#include <string_view>

namespace ncc::hei {

struct CycleInfo {
  int number;
  bool defActive;      // acts where it is defined (220, 221, transformations …)
  const char *params;  // "Q200 Q201 …"; null: not checked
};

// Null when ncc has no row for the cycle.
const CycleInfo *findCycle(int number);
// The DEF-active cycles without a row (coordinate transformations, SL data, probing …).
bool defActiveCycle(int number);
bool cycleTakes(const CycleInfo &c, std::string_view q);

}  // namespace ncc::hei
