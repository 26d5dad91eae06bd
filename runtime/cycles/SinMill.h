// What the Sinumerik milling entries share (SinClearingEntries.cpp: pockets and slots,
// SinSpigotEntries.cpp: spigots): their parameter names and the MillJob filled from them.
#pragma once
#include "runtime/cycles/Pocket.h"

#include <string>

namespace ncc::entry {

// The parameter names of the Sinumerik milling cycles (POCKET3/4 write _RTP, SLOT1 RTP …); null:
// the cycle has none (its default applies).
struct SinNames {
  const char *rtp, *rfp, *sdis, *mid, *fal, *fald, *ffp1, *ffd, *cdir, *vari, *helixRadius, *helixPitch;
  // The depth by _AMODE 1st digit: kDepthDP _DP, absolute (0) or below the reference plane (1);
  // kDepthSlot _DP absolute (2) or _DPR below it (1), 0: _DPR when given (SLOT1, LONGHOLE);
  // kDepthSpigot _DP absolute (0, 2) or _DPR below it (1) (CYCLE76, CYCLE77).
  int depthMode;
};
enum : int { kDepthDP = 0, kDepthSlot = 1, kDepthSpigot = 2 };

// _GMODE 4th digit (POCKET3, CYCLE76): 0, 1 the reference point is the centre; 2-5 a corner, the
// element running +/-_LENG, +/-_WID from it: the centre from the corner in half sides.
inline constexpr double kSinCorner[6][2] = {{0, 0}, {0, 0}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};

// The levels (depth by _AMODE 1st digit), infeed, allowances, feeds, milling direction (CDIR) and,
// with n.vari, the machining (1st digit) and plunge (2nd digit) of a Sinumerik milling cycle; without
// n.vari roughing.
bool sinPocketJob(const CycleArgs &a, const CycleContext &ctx, const SinNames &n, MillJob &m, std::string &err);
// _MIDA, mm or (_AMODE 2nd digit 1) percent of the tool diameter, 0: 80 % of it, into m.stepover.
bool sinMida(const CycleArgs &a, MillJob &m, std::string &err);
// The reference point of a Sinumerik element: (ka, kb) when programmed, else (null) the tool's
// position, so that MCALL with a position pattern puts one at each position [model].
const PlanePoint *reference(const CycleArgs &a, const char *ka, const char *kb, PlanePoint &out);

}  // namespace ncc::entry
