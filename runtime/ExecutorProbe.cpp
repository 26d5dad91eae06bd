// LinuxCNC straight probing G38.2-G38.5 (docs/PROBING.md), simulated against the probe-results
// file: each probe move takes the file's next line, which says where the probe switched (or that
// it did not). rs274's checks come first, with its messages; the move is one Probe record from the
// start to where the machine stopped; #5061-#5070 keep the result.
#include "runtime/ExecutorImpl.h"
#include "runtime/ProbeResults.h"

#include <fmt/format.h>

namespace ncc {

namespace {
struct ProbeMode {
  ModeValue mode;
  const char *code;
  ProbeSignal signal;
  bool missIsError;
};
constexpr ProbeMode kProbeModes[] = {
    {ModeValue::ProbeToward, "G38.2", ProbeSignal::Contact, true},
    {ModeValue::ProbeTowardNoError, "G38.3", ProbeSignal::Contact, false},
    {ModeValue::ProbeAway, "G38.4", ProbeSignal::Release, true},
    {ModeValue::ProbeAwayNoError, "G38.5", ProbeSignal::Release, false},
    {ModeValue::Skip, "G31", ProbeSignal::Contact, false},
};
}  // namespace

// Program coordinates and units of a machine position (as #5420… read the current one).
AxisVec Executor::Impl::programUnits(const AxisVec &machinePos) const {
  AxisVec p = frameIn(machinePos);
  for (int i = 0; i < kAxes; ++i) p[i] = (p[i] - frameOffset(i)) / axisScale(i);
  return p;
}

bool Executor::Impl::probeMove(const MachineCmd &c) {
  const ProbeMode *mode = kProbeModes;
  while (mode->mode != st.motion) ++mode;  // execMove calls it in the four probe modes only
  const ProbeMode &m = *mode;
  if (!compForbids("Cannot probe with cutter radius comp on")) return false;
  if (st.feedMode == ModeValue::InverseTime) return error("Cannot probe in inverse time feed mode", "motion-without-feed");
  if (st.feedMode == ModeValue::PerRev) return error("Cannot probe with feed per rev mode", "motion-without-feed");
  if (!(feedMM > 0)) return error("Cannot probe with zero feed rate", "motion-without-feed");
  if (compExit || corner.active || corner.requested)  // the move would not start where it is programmed
    return error(fmt::format("{} cannot be the move after G40 or a chamfer/rounding", m.code), "unsupported-code");
  const AxisVec to = target(c);
  // rs274 checks this for G38.2 and G38.4 only: G38.3 and G38.5 may probe where they stand.
  if (m.missIsError && to == st.position) return error("Start point too close to probe point", "probe-invalid");
  const std::shared_ptr<const ProbeResults> &results = machine.probeResults;
  if (!results)
    return error(fmt::format("{} needs a probe-results file (--probe-results=FILE, docs/PROBING.md): where the probe "
                             "switches is not in the program",
                             m.code),
                 "probe-needs-results");
  if (probeNext >= results->outcomes.size())
    return error(fmt::format("{} is probe move {} of the run, but the probe-results file '{}' has {} line{}", m.code,
                             probeNext + 1, results->file, results->outcomes.size(),
                             results->outcomes.size() == 1 ? "" : "s"),
                 "probe-results");
  const ProbeOutcome &o = results->outcomes[probeNext++];
  const AxisVec from = programUnits(st.position), aim = programUnits(to);
  double t;
  std::string why;
  if (!probeStopFraction(o, from, aim, t, why)) {
    error(fmt::format("{}: the probe-results line does not fit this move: {}", m.code, why), "probe-results");
    diags.note(o.loc, "the line of this probe move");
    return false;
  }
  if (!o.tripped && m.missIsError) {
    error(fmt::format("{} move finished without {} contact (the probe-results line says miss)", m.code,
                      m.signal == ProbeSignal::Contact ? "making" : "breaking"),
          "probe-miss");
    diags.note(o.loc, "the line of this probe move");
    return false;
  }
  MotionRecord r = record(RecordKind::Probe);
  for (int i = 0; i < kAxes; ++i) r.end[i] = t == 1 ? to[i] : r.start[i] + t * (to[i] - r.start[i]);
  r.feed = feedMM;
  r.exactStop = true;  // the machine stops where the probe switched, or at the target
  r.setProbe(ProbeData{to, m.signal, m.missIsError, o.tripped});
  if (std::string bad = probeError(r); !bad.empty()) return error(bad, "probe-invalid");
  for (int i = 0; i < kAxes; ++i) probeResult[i] = t == 1 ? aim[i] : from[i] + t * (aim[i] - from[i]);
  probeTripped = o.tripped ? 1 : 0;
  st.position = r.end;
  return emitMove(r);
}

// Lines left over mean the file does not describe this run (another branch was taken, or it
// belongs to another program).
void Executor::Impl::probeResultsUnused() {
  const ProbeResults *results = machine.probeResults.get();
  if (!results || probeNext >= results->outcomes.size()) return;
  diags.warning(results->outcomes[probeNext].loc,
                fmt::format("the run made {} probe move{}, but the probe-results file has {} lines: this one and the "
                            "ones after it were not used",
                            probeNext, probeNext == 1 ? "" : "s", results->outcomes.size()),
                "probe-results-unused");
}

}  // namespace ncc
