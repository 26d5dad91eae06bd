// Helpers the entry files of the library share (Library.cpp, Pocket.cpp, the clearing entries): errors,
// Sinumerik mode-word digits and the Heidenhain 2xx clearance levels.
#pragma once
#include "runtime/cycles/Library.h"

#include <string>
#include <string_view>

namespace ncc::entry {

inline bool fail(std::string &err, std::string msg) {
  err = std::move(msg);
  return false;
}

// A parameter value that would change the motion in a way the entry does not model: the
// executor reports it as `unsupported-code` (not `cycle-invalid`).
inline constexpr std::string_view kUnsupported = "\x01unsupported:";
inline bool unsupported(std::string &err, std::string msg) { return fail(err, std::string(kUnsupported) + msg); }

// Digit n (1 = units) of a Sinumerik mode word (_AMODE, _VARI, _DMODE …).
int digit(double word, int n);

// The plane of a Sinumerik cycle: _DMODE 1st digit 1/2/3 = G17/G18/G19 inside the cycle, else
// the active one.
int sinPlane(const CycleArgs &a, const CycleContext &ctx);

// Heidenhain 2xx levels on the tool axis: Q200 set-up clearance, Q201 depth (its sign is the
// direction), Q203 surface, Q204 2nd set-up clearance (used when larger than Q200). Q206 is
// required and must be greater than 0.
struct HeiLevels {
  double zsc, bottom, z2, dir;
};
bool heiLevels(const CycleArgs &a, HeiLevels &l, std::string &err);

}  // namespace ncc::entry
