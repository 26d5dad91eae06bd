// The minor words of APT CL records whose meaning ncc maps (docs/APT.md): one table per word
// group, read by the APT front end (frontend/cldata/Lower.cpp) and written by the APT CL writer
// (backends/emit/ClRecords.cpp), so the two directions cannot drift apart.
#pragma once
#include <string_view>

namespace ncc::cld {

// CYCLE/ kinds and the cycle library entry that does exactly the same (null: none does).
struct AptCycleWord {
  const char *word;
  const char *entry;
};
inline constexpr AptCycleWord kAptCycles[] = {
    {"DRILL", "sin.CYCLE81"}, {"BORE", "sin.CYCLE85"}, {"DEEP", nullptr}, {"TAP", nullptr},
    {"BRKCHP", nullptr},      {"REAM", nullptr},       {"FACE", nullptr},
};

// FEDRAT units.
struct AptFeedUnit {
  const char *word;
  bool inch, perRev;
};
inline constexpr AptFeedUnit kAptFeedUnits[] = {
    {"MMPM", false, false}, {"IPM", true, false}, {"MMPR", false, true}, {"IPR", true, true}};

// COOLNT/ words: the coolant they switch on ("flood", "mist"), null for OFF (every coolant).
// The first word of a coolant is the one the writer uses.
struct AptCoolantWord {
  const char *word;
  const char *coolant;
};
inline constexpr AptCoolantWord kAptCoolants[] = {{"ON", "flood"}, {"FLOOD", "flood"}, {"MIST", "mist"}, {"OFF", nullptr}};

// SPINDL/ directions (CLW is ISO 4343's default).
struct AptSpindleWord {
  const char *word;
  const char *dir;
};
inline constexpr AptSpindleWord kAptSpindleDirs[] = {{"CLW", "cw"}, {"CCLW", "ccw"}};

// The first row of `table` whose `field` equals `value` (nullptr when none).
template <class Row, size_t N, class F>
const Row *aptFind(const Row (&table)[N], F match) {
  for (const Row &r : table)
    if (match(r)) return &r;
  return nullptr;
}

}  // namespace ncc::cld
