// Probe records (docs/PROBING.md): LinuxCNC G38.2-G38.5 to the programmed target; Sinumerik
// MEAS=1 / MEAS=-1 with G1 (measure on the probe's rising / falling edge and delete the rest of
// the move), which raises no alarm when the probe never switches, so only the probes without an
// error on a miss (G38.3, G38.5) have a Sinumerik block.
#include "backends/emit/EmitterImpl.h"

namespace ncc::emit::detail {

std::string Emitter::probeRefusal(const MotionRecord &r) const {
  if (st_.lathe) return "probing is not written for lathes";
  if (st_.target == Target::Sinumerik)
    return r.probe().missIsError ? "Sinumerik's MEAS raises no alarm when the probe does not switch: a probe that must "
                                   "trip (G38.2, G38.4) has no block of its own"
                                 : "";
  if (st_.target != Target::ISO || machine_.controller.family != "linuxcnc")
    return "probing is written for LinuxCNC (G38.2-G38.5: an ISO target of [controller] family \"linuxcnc\") and "
           "Sinumerik (MEAS) only";
  return {};
}

void Emitter::probe(const MotionRecord &r) {
  flushPending();
  ensurePosition(r);
  const ProbeData &p = r.probe();
  const bool release = p.signal == ProbeSignal::Release;
  Words w;
  if (st_.target == Target::Sinumerik) {
    push(w, release ? "MEAS=-1" : "MEAS=1");
    motionCode(Code::Linear, w);
  } else {
    static const char *kCodes[2][2] = {{"G38.3", "G38.2"}, {"G38.5", "G38.4"}};
    const char *g = kCodes[release][p.missIsError];
    if (motion_ != g) push(w, g);
    motion_ = g;
  }
  axisWords(p.target, w, r);
  double d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += (p.target[i] - r.start[i]) * (p.target[i] - r.start[i]);
  feedWord(r, w, std::sqrt(d2));
  writeBlock(w, r.blockNumber);
  // The machine stops where the probe switched: the next block starts from there.
  notePosition(r.end, kAxes);
  if (!probeWarned_)
    diags_.warning(r.loc,
                   "the moves after a probe move are written as the simulation computed them from the probe results "
                   "(--probe-results), not from what the machine will measure",
                   "probe-simulated");
  probeWarned_ = true;
}

}  // namespace ncc::emit::detail
