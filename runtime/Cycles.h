// Canned drilling cycles (G73 G74 G81-G86 G89) expanded into elementary steps, the way LinuxCNC's
// rs274 expands them (the reference the oracle tests compare against), and the 808D/Fanuc boring
// cycles G76 and G87: the ISO entry of the cycle library, positioning and repeats here, each hole
// a HoleSpec or BackBoreSpec (runtime/cycles/Hole.h).
// A pure function: the executor calls it with offset-frame values.
#pragma once
#include "ir/ModeTable.h"
#include "ir/MotionIR.h"
#include "runtime/cycles/Hole.h"

#include <array>
#include <string>
#include <vector>

namespace ncc {

struct CycleInput {
  ModeValue cycle = ModeValue::Drill;  // Drill .. BoreDwell, BoreFine, BoreBack
  Plane plane = Plane::XY;             // drilling axis: XY -> Z, ZX -> Y, YZ -> X
  bool retractToR = false;             // G99 (else G98: back to max(initial level, R))
  bool incremental = false;            // G91: target = increments, R from the initial level,
                                       // Z (bottom) from the R level
  std::array<double, 3> current{};     // position before the block, X Y Z
  // Hole position: absolute X Y Z (G90) or the increments (G91); only the two plane axes are used.
  std::array<double, 3> target{};
  double initialLevel = 0;  // drilling-axis position when the cycle mode was entered
  // The previous block ran the same cycle: rs274 then moves to the hole at the clear level (at
  // least), after a change of cycle at the R level (at least).
  bool sameCycle = false;
  double r = 0;             // R word (absolute level, or increment in G91)
  double z = 0;             // bottom (absolute, or increment from R in G91)
  double q = 0;             // peck depth (G73/G83), > 0
  double p = 0;             // dwell seconds (G82 G84 G86 G89)
  int repeats = 1;          // L (Fanuc K)
  int spindle = 1;          // spindle direction before the cycle: 1 cw, 2 ccw (G86 restart)
  double peckClearance = 0.254;  // G83 stop short / G73 retract (0.010 inch), same unit as positions
  double chipBreak = -1;         // G73 retract when >= 0 (808D: _ZSFR[1]), else peckClearance
  // 808D/Fanuc G84/G74: reversed out to R with the dwell P there too, then a rapid to the
  // initial level in G98 (manual L8662, figure 2-44); false: rs274's feed out to the clear level.
  bool tapOutToR = false;
  // RS274NGC polar hole positions (XY plane): each repeat applies the @ ^ step (polarStep) to
  // the previous hole, about the program origin `origin`, instead of `target`.
  bool polar = false, polarHasR = false, polarHasA = false;
  double polarR = 0, polarA = 0;  // radius (position units), angle (degrees)
  std::array<double, 2> origin{};
  // 808D/Fanuc G76 fine boring and G87 back boring (the .ngc front end rejects both): the
  // oriented stop's angle and the side the tool moves off the wall by Q (Controller::boringLift).
  double orientAngle = 0;
  int lift = 0;
  // 808D peck tapping (G84/G74 with Q, machine peck_tapping = GUD _ZSFI[1]): 0 one pass, 2 chip
  // breaking (back by tapBack after each infeed of q), 3 chip removal (back to R, then in again
  // at the feed to tapBack short of the last depth).
  int tapPecks = 0;
  double tapBack = 1;
};

// Appends the steps of one cycle block to `out`. Returns false with an rs274-like message in
// `err` on invalid parameters (R below the bottom, Q <= 0, repeats < 1).
bool expandCycle(const CycleInput &in, std::vector<CycleStep> &out, std::string &err);

// "G81" etc. for messages.
const char *cycleCodeName(ModeValue cycle);

}  // namespace ncc
