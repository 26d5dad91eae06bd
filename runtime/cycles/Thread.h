// Multi-pass thread cutting on a lathe, shared by every dialect's threading cycle: LinuxCNC G76,
// the 808D/Fanuc G76 (and later Sinumerik CYCLE97, Heidenhain's thread cycles). Pure geometry in
// the ZX plane (x a radius, z along the turning axis, machine mm): the entries compute the pass
// depths with one of the schedules below and let threadPass lay out each pass; the executor
// (runtime/ExecutorThread.cpp) turns the steps into Motion IR records.
#pragma once
#include <vector>

namespace ncc {

enum class ThreadStepKind : unsigned char {
  Rapid,  // traverse
  Start,  // a thread move that starts a new synchronisation (waits for the spindle's index)
  Chain,  // a thread move that continues the one before it (another lead or direction)
};
struct ThreadStep {
  ThreadStepKind kind = ThreadStepKind::Rapid;
  double x = 0, z = 0;
  double lead = 0;       // mm/rev (thread moves)
  bool alongPath = false;  // the lead is per unit of path length (LinuxCNC), else along Z
};

// One pass: rapid back to (retractX, startZ), in to the cut's start, the synchronised cut to
// (endX, endZ), rapid out to (retractX, endZ) ... (the exit's end Z when there is one).
// An entry taper (LinuxCNC G76 L1) feeds in synchronised from (entryX, startZ) to the cut's
// start, which is then (startX, startZ + entryDz); an exit (LinuxCNC G76 L2, the 808D's
// run-out chamfer) cuts to (endX, endZ - exitDz) and then to (exitX, endZ).
struct ThreadPass {
  double retractX = 0;
  double startX = 0, startZ = 0;
  double endX = 0, endZ = 0;
  double lead = 0;
  bool alongPath = false;
  bool entry = false;
  double entryX = 0, entryDz = 0, entryLead = 0;
  bool exit = false;
  double exitX = 0, exitDz = 0, exitLead = 0;
};
void threadPass(const ThreadPass &p, std::vector<ThreadStep> &out);

// LinuxCNC G76's depths (rs274 convert_threading_cycle), measured from the drive line: `offset`
// (|I|) + `first` (|J|), then offset + first * n^(1/degression) for pass n = 2, 3, ... while
// below offset + `full` (|K|); then 1 + `springPasses` passes at offset + full. The arithmetic
// is rs274's, so the positions match its trace to the last printed digit.
std::vector<double> lcncThreadDepths(double offset, double first, double full, double degression, int springPasses);

// The 808D/Fanuc G76 depths, measured from the crest (spec seed001 3.2, L3717-3824): pass n
// cuts to first * sqrt(n) (constant chip area), each increment at least `minCut`, until
// height - allowance; one pass there when the allowance is not 0, then `finishPasses` passes at
// the full `height`.
std::vector<double> fanucThreadDepths(double height, double first, double minCut, double allowance, int finishPasses);

}  // namespace ncc
