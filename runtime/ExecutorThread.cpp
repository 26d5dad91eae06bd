// Thread cutting (docs/IR.md §9 "Threads", docs/CYCLES.md "Threads"): the spindle-synchronised
// move of LinuxCNC G33 (lead K per unit of path) and of the 808D's G32/G33 (lead F along the
// thread's main axis, start angle Q, chained blocks), LinuxCNC's rigid tap G33.1 and G76
// threading cycle, the 808D's multiple threading cycle G76; the single thread cycle G92/G78
// is the turning cycle of ExecutorTurning.cpp with a thread for its cut. The multi-pass
// cycles lay out their passes with runtime/cycles/Thread.h.
#include "runtime/ExecutorImpl.h"
#include "runtime/cycles/Thread.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
constexpr size_t kMaxThreadPasses = 10000;  // a runaway schedule (a tiny first cut) is an error
}

bool Executor::Impl::threadAllowed(const char *code) {
  if (!compForbids(fmt::format("Cannot use {} with cutter radius compensation on", code).c_str())) return false;
  if (linearFrame())
    return error(fmt::format("{} under a rotation, scaling or mirror is not supported", code), "unsupported-code");
  if (st.spindle == 0) return error(fmt::format("Spindle not turning in {}", code), "thread-spindle");
  if (!(st.speed > 0)) return error(fmt::format("{} needs a spindle speed (S is 0)", code), "thread-spindle");
  return true;
}

bool Executor::Impl::threadTo(const AxisVec &to, double lead, ThreadAxis along, ThreadSync sync, double angle,
                              double dlead) {
  // A synchronised run follows one spindle state: a chained block after S or M3/M4 changed
  // would cut another thread (the 808D manual, L1743-1746: the speed must not change).
  if (sync == ThreadSync::Chain && (st.speed != threadSpeed || st.spindle != threadSpindle))
    return error(fmt::format("the spindle changed inside a chained thread (S{} M{} -> S{} M{}): its lead would not hold",
                             threadSpeed, threadSpindle == 2 ? 4 : 3, st.speed, st.spindle == 2 ? 4 : 3),
                 "thread-spindle");
  if (sync == ThreadSync::Chain && st.pathMode == ModeValue::ExactStop)
    warning("a chained thread in exact-stop mode (G61.1/G9): the axes cannot stop while the spindle turns on; "
            "the join is planned as a stop", "thread-chain-stop");
  threadSpeed = st.speed, threadSpindle = st.spindle;
  MotionRecord r = record(RecordKind::Thread);
  r.end = to;
  r.value = lead;
  r.ivalue = (int64_t)along;
  r.sync = sync;
  r.value2 = angle;
  if (dlead != 0) r.setParam("dlead", dlead);
  r.exactStop = st.pathMode == ModeValue::ExactStop;
  if (std::string why = threadError(r); !why.empty()) return error(why, "thread-invalid");
  // Under G96 the spindle turns at the rpm of the tool's radius: a straight thread has one; a
  // tapered or face thread would change it along the cut, which ncc does not plan.
  double rpm = st.speed;
  if (st.css) {
    if (std::fabs(to[0] - st.position[0]) > 1e-9)
      return error("a thread that changes X under constant surface speed (G96): the spindle speed would change "
                   "along the cut; program G97 S<rpm> for it",
                   "unsupported-code");
    rpm = cssRpm(to[0]);
    if (!std::isfinite(rpm)) return error("a thread at X0 under G96 without a spindle-speed limit", "thread-spindle");
  }
  r.feed = threadPathLead(r) * rpm;
  st.position = to;
  notePath(r);
  if (corner.active)  // spec seed001 2.4: no chamfer or rounding at a thread block
    return error("a chamfer or rounding cannot join a thread move", "unsupported-code");
  emit(r);
  return true;
}

// The 808D's rule (Table 1-10): the lead acts along Z when the taper angle to Z is at most 45
// degrees, along X otherwise (a face thread).
static ThreadAxis mainAxis(const AxisVec &from, const AxisVec &to) {
  return std::fabs(to[0] - from[0]) <= std::fabs(to[2] - from[2]) ? ThreadAxis::Z : ThreadAxis::X;
}

bool Executor::Impl::threadMove(const MachineCmd &c) {
  if (!(c.mask & kAxisMask)) return true;
  // LinuxCNC G33 K; the 808D's G32/G33 take F as the lead, its G34 K the lead's change.
  const bool variable = st.motion == ModeValue::ThreadVariable;
  const bool lcnc = !variable && c.has(Word::K);
  const char *code = lcnc ? "G33" : variable ? "G34" : "G32 (G33)";
  if (!threadAllowed(code)) return false;
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Y) | wordBit(Word::Z)))
    return error(std::string(code) + " moves X, Y and Z only", "unsupported-code");
  const AxisVec to = target(c);
  if (lcnc) return threadTo(to, c.get(Word::K) * scale(), ThreadAxis::Path, ThreadSync::Index, 0);
  if (plane() != Plane::ZX) return error(std::string(code) + " needs the ZX plane (G18)", "unsupported-code");
  if (!(feedMM > 0)) return error(std::string(code) + " needs F, the thread lead", "thread-invalid");
  if (variable) {  // spec seed001 2.6 (L1820-1855): a new synchronisation, the lead F + K n at revolution n
    if (!c.has(Word::K)) return error("G34 needs K, the change of the lead per revolution", "missing-word");
    return threadTo(to, feedMM, mainAxis(st.position, to), ThreadSync::Index, 0, c.get(Word::K) * scale());
  }
  // Consecutive blocks make one continuous thread (spec seed001 2.6); Q restarts at an angle.
  const bool chain = threadChain && !c.has(Word::Q);
  double angle = c.has(Word::Q) ? c.get(Word::Q) : 0;
  return threadTo(to, feedMM, mainAxis(st.position, to), chain ? ThreadSync::Chain : ThreadSync::Index, angle);
}

// rs274's G33.1: RIGID_TAP to the point and back (the spindle reverses at the bottom); the
// position afterwards is where it started.
bool Executor::Impl::rigidTap(const MachineCmd &c) {
  if (!(c.mask & kAxisMask)) return true;
  if (!threadAllowed("G33.1")) return false;
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Y) | wordBit(Word::Z)))
    return error("G33.1 moves X, Y and Z only", "unsupported-code");
  if (!c.has(Word::K)) return error("G33.1 needs K, the lead", "missing-word");
  const AxisVec from = st.position;
  const double lead = c.get(Word::K) * scale();
  return threadTo(target(c), lead, ThreadAxis::Path, ThreadSync::TapIn, 0) &&
         threadTo(from, lead, ThreadAxis::Path, ThreadSync::TapOut, 0);
}

// Sinumerik's lead word: exactly one of I J K, the lead along X Y Z. It must name the thread's
// main axis, the one that travels furthest (a taper up to 45 degrees to Z takes K, a steeper one
// I; at exactly 45 degrees either).
static bool leadWord(const MachineCmd &c, const AxisVec &from, const AxisVec &to, double &lead, int &axis,
                     std::string &why) {
  static const Word kLead[] = {Word::I, Word::J, Word::K};
  axis = -1;
  for (int i = 0; i < 3; ++i)
    if (c.has(kLead[i])) {
      if (axis >= 0) return why = "a thread takes one lead word: I, J or K", false;
      axis = i;
    }
  if (axis < 0) return why = "the lead is missing: I (along X), J (along Y) or K (along Z)", false;
  lead = c.get(kLead[axis]);
  const double travel = std::fabs(to[axis] - from[axis]);
  for (int i = 0; i < 3; ++i)
    if (std::fabs(to[i] - from[i]) > travel + 1e-9)
      return why = fmt::format("the lead {} is along {}, but the thread's main axis (the longest travel) is {}",
                               "IJK"[axis], "XYZ"[axis], "XYZ"[i]),
             false;
  return true;
}

// Sinumerik G33 X Y Z I/J/K SF=: a thread of constant lead along its main axis. Blocks that
// follow one another chain into one thread; a new thread waits for the spindle's zero mark plus
// the start angle SF (modal, the offset of a multi-start thread's passes). G34/G35 add `dlead`,
// the lead's change per revolution along the same axis; such a thread starts a synchronisation
// of its own.
bool Executor::Impl::leadThread(const MachineCmd &c) {
  if (c.has(Word::Q)) threadStartAngle = c.get(Word::Q);
  if (!(c.mask & kAxisMask)) return true;
  if (!threadAllowed("G33")) return false;
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Y) | wordBit(Word::Z)))
    return error("G33 (G34, G35) moves X, Y and Z only", "unsupported-code");
  const AxisVec to = target(c);
  double lead = 0;
  int axis = 0;
  std::string why;
  const double dlead = c.has(Word::LeadChange) ? c.get(Word::LeadChange) * scale() : 0;
  const char *code = dlead > 0 ? "G34" : dlead < 0 ? "G35" : "G33";
  if (!leadWord(c, st.position, to, lead, axis, why)) return error(std::string(code) + ": " + why, "thread-invalid");
  if (dlead != 0 && threadChain)
    return error(fmt::format("{} right after a thread: a variable lead chained onto a thread is not supported", code),
                 "unsupported-code");
  const bool chain = threadChain;
  return threadTo(to, lead * scale(), (ThreadAxis)axis, chain ? ThreadSync::Chain : ThreadSync::Index,
                  chain ? 0 : threadStartAngle, dlead);
}

// Sinumerik G331 / G332: tapping without a compensating chuck. SPOS put the spindle in position
// control; G331 taps in at S with the lead I/J/K (> 0 a right-hand thread, < 0 left-hand), G332
// comes back out with the spindle reversed. ncc's record of a tap is LinuxCNC's rigid tap, down
// and back along one line: G332 must follow G331 at once and end where the tap began.
bool Executor::Impl::positionTap(const MachineCmd &c, bool in) {
  const char *code = in ? "G331" : "G332";
  if (!(c.mask & kAxisMask)) return true;
  if (!compForbids(fmt::format("Cannot use {} with cutter radius compensation on", code).c_str())) return false;
  if (linearFrame())
    return error(fmt::format("{} under a rotation, scaling or mirror is not supported", code), "unsupported-code");
  if (!spindlePositioned)
    return error(fmt::format("{} needs the spindle in position control: program SPOS first (M3/M4/M5 end it)", code),
                 "thread-spindle");
  if (!(st.speed > 0)) return error(fmt::format("{} needs a spindle speed (S is 0)", code), "thread-spindle");
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Y) | wordBit(Word::Z)))
    return error(fmt::format("{} moves X, Y and Z only", code), "unsupported-code");
  const AxisVec to = target(c);
  double lead = 0;
  int axis = 0;
  std::string why;
  if (!leadWord(c, st.position, to, lead, axis, why)) return error(fmt::format("{}: {}", code, why), "thread-invalid");
  lead = std::fabs(lead) * scale();
  if (in) {
    if (tapOpen) return error("G331 after G331: the first tap never came back out (G332)", "thread-invalid");
    tapStart = st.position, tapLead = lead;
    tapOpen = true;
    threadSpeed = st.speed;
    return threadTo(to, lead, (ThreadAxis)axis, ThreadSync::TapIn, 0);
  }
  if (!tapOpen || !threadChain) return error("G332 without the G331 tap before it", "thread-invalid");
  for (int i = 0; i < 3; ++i)
    if (std::fabs(to[i] - tapStart[i]) > 1e-9)
      return error("G332 must come back to where its G331 began (ncc's tap is one record down and back)",
                   "unsupported-code");
  if (std::fabs(lead - tapLead) > 1e-12) return error("G332 must take the lead of its G331", "thread-invalid");
  if (st.speed != threadSpeed)
    return error("a different speed for G332 than for its G331 is not supported (the tap is one record)",
                 "unsupported-code");
  tapOpen = false;
  return threadTo(to, lead, (ThreadAxis)axis, ThreadSync::TapOut, 0);
}

bool Executor::Impl::threadSteps(const std::vector<ThreadStep> &steps, ThreadAxis along) {
  for (const ThreadStep &s : steps) {
    AxisVec p = st.position;
    p[0] = s.x, p[2] = s.z;
    bool ok = s.kind == ThreadStepKind::Rapid
                  ? moveTo(RecordKind::Rapid, p)
                  : threadTo(p, s.lead, s.alongPath ? ThreadAxis::Path : along,
                             s.kind == ThreadStepKind::Start ? ThreadSync::Index : ThreadSync::Chain, 0);
    if (!ok) return false;
  }
  return true;
}

// LinuxCNC G76 (rs274 convert_threading_cycle): the drive line is the start X; I the crest's
// offset from it (negative: an outside thread), J the first cut, K the thread depth, R the depth
// degression, Q the compound angle, H spring passes, E the taper length and L which ends taper.
bool Executor::Impl::threadCycle(const MachineCmd &c) {
  if (!(c.mask & kAxisMask)) return true;
  if (!threadAllowed("G76")) return false;
  if (plane() != Plane::ZX) return error("G76 needs the ZX plane (G18)", "unsupported-code");
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Z)))
    return error("Cannot move rotary axes with G76", "unsupported-code");
  for (Word w : {Word::P, Word::I, Word::J, Word::K})
    if (!c.has(w)) return error(fmt::format("G76 needs {}", kWordKeys[(int)w]), "missing-word");
  const double xs = axisScale(0);  // I J K are X distances (diameters on a diameter machine)
  const double i = c.get(Word::I) * xs, j = c.get(Word::J) * xs, k = c.get(Word::K) * xs;
  if (c.get(Word::I) == 0) return error("In G76, I must not be 0", "thread-invalid");
  if (!(c.get(Word::J) > 0)) return error("In G76, J must be greater than 0", "thread-invalid");
  if (!(c.get(Word::K) > c.get(Word::J))) return error("In G76, K must be greater than J", "thread-invalid");
  const double pitch = c.get(Word::P) * scale();
  if (!(pitch > 0)) return error("In G76, P (the pitch) must be greater than 0", "thread-invalid");
  const AxisVec start = st.position, end = target(c);
  const bool boring = i > 0;
  const double safeX = start[0], offset = std::fabs(i), endDepth = std::fabs(k) + offset;
  double angle = c.has(Word::Q) ? c.get(Word::Q) : 0;
  if (angle == -1) angle = 0;
  angle *= M_PI / 180.0;
  if (end[2] > start[2]) angle = -angle;
  const int springs = c.has(Word::H) ? (int)c.get(Word::H) : 0;
  double degression = c.has(Word::R) ? c.get(Word::R) : 1.0;
  if (degression < 1.0) degression = 1.0;
  double taper = c.has(Word::E) ? c.get(Word::E) * scale() : 0.0;
  if (taper < 0) taper = 0;
  const double taperPitch = taper > 0 ? pitch * std::hypot(taper, std::fabs(k)) / taper : pitch;
  if (end[2] > start[2]) taper = -taper;
  const int flags = c.has(Word::L) ? std::max(0, (int)c.get(Word::L)) : 0;
  const double targetZ = end[2] + std::fabs(k) * std::tan(angle);
  const std::vector<double> depths = lcncThreadDepths(offset, std::fabs(j), std::fabs(k), degression, springs);
  if (depths.size() > kMaxThreadPasses)
    return error(fmt::format("G76 would cut {} passes (J too small for K and R)", depths.size()), "thread-invalid");
  MotionRecord begin = record(RecordKind::CycleBegin);
  begin.text = "rs274.G76";
  // The block's words in program coordinates, mm (X a radius), as the other cycles' cycle_begin.
  begin.setParam("P", pitch), begin.setParam("Z", end[2] - frameOffset(2)), begin.setParam("I", i), begin.setParam("J", j);
  begin.setParam("K", k);
  emit(begin);
  std::vector<ThreadStep> steps;
  auto x = [&](double depth) { return boring ? safeX + depth : safeX - depth; };
  for (double depth : depths) {
    const double zoff = (depth - offset) * std::tan(angle);
    ThreadPass p;
    p.retractX = boring ? safeX + depth - endDepth : safeX - depth + endDepth;
    p.startX = p.endX = x(depth);
    p.startZ = start[2] - zoff;
    p.endZ = targetZ - zoff;
    p.lead = pitch, p.alongPath = true;
    const double crest = boring ? safeX + depth - std::fabs(k) : safeX - depth + std::fabs(k);
    if (taper != 0 && (flags & 1)) p.entry = true, p.entryX = crest, p.entryDz = -taper, p.entryLead = taperPitch;
    if (taper != 0 && (flags & 2)) p.exit = true, p.exitX = crest, p.exitDz = -taper, p.exitLead = taperPitch;
    threadPass(p, steps);
  }
  bool ok = threadSteps(steps, ThreadAxis::Path) && moveTo(RecordKind::Rapid, end);
  emit(record(RecordKind::CycleEnd));
  return ok;
}

// The 808D's G76 (spec seed001 3.2): `G76 P<m><r><a> Q<min cut> R<allowance>` keeps the data;
// `G76 X(U) Z(W) R<taper> P<height> Q<first cut> F<lead>` cuts from the start point A: each pass
// rapids in along the flank (half the tool angle a), cuts to the end with the run-out chamfer
// r / 10 x lead at 45 degrees, rapids out to A's X and back.
bool Executor::Impl::threadMulti(const MachineCmd &c) {
  st.motion = threadReturn;  // one-shot
  if (!(c.mask & kAxisMask)) {  // the data block
    for (Word w : {Word::P, Word::Q, Word::R})
      if (!c.has(w)) return error(fmt::format("G76 P Q R (the data block) needs {}", kWordKeys[(int)w]), "missing-word");
    double p = c.get(Word::P);
    if (p < 0 || p != std::floor(p) || p > 999999)
      return error("G76 P of the data block is six digits: finishing passes, chamfer, tool angle", "thread-invalid");
    long long d = (long long)p;
    threadData.finishPasses = (int)(d / 10000), threadData.chamfer = (d / 100 % 100) * 0.1,
    threadData.toolAngle = (double)(d % 100);
    threadData.minCut = c.get(Word::Q) * scale(), threadData.allowance = c.get(Word::R) * scale();
    threadData.set = true;
    if (threadData.finishPasses < 1) return error("G76 needs at least one finishing pass (m of P)", "thread-invalid");
    return true;
  }
  if (!threadData.set) return error("G76 needs its data block (G76 P Q R) first", "missing-word");
  if (!threadAllowed("G76")) return false;
  if (plane() != Plane::ZX) return error("G76 needs the ZX plane (G18)", "unsupported-code");
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Z)))
    return error("G76 takes X (U), Z (W), R, P, Q and F", "unsupported-code");
  if (!c.has(Word::P) || !c.has(Word::Q)) return error("G76 needs P (the thread height) and Q (the first cut)", "missing-word");
  if (!(feedMM > 0)) return error("G76 needs F, the thread lead", "thread-invalid");
  // Radius values, as G90's R (the manual: "value of the radius").
  const double height = c.get(Word::P) * scale(), first = c.get(Word::Q) * scale();
  const double taper = c.has(Word::R) ? c.get(Word::R) * scale() : 0.0;
  if (!(height > 0) || !(first > 0)) return error("G76 P (height) and Q (first cut) must be greater than 0", "thread-invalid");
  if (threadData.allowance >= height) return error("the G76 finishing allowance R is not below the thread height P", "thread-invalid");
  const AxisVec a = st.position, e = target(c);
  if (e[2] == a[2]) return error("G76 needs a thread along Z (its end Z differs from the start's)", "thread-invalid");
  const double out = e[0] <= a[0] ? 1.0 : -1.0;  // the crest lies towards A: an outside thread when A is above
  const std::vector<double> depths =
      fanucThreadDepths(height, first, threadData.minCut, threadData.allowance, threadData.finishPasses);
  if (depths.size() > kMaxThreadPasses)
    return error(fmt::format("G76 would cut {} passes (Q too small for P)", depths.size()), "thread-invalid");
  const double dir = e[2] < a[2] ? -1.0 : 1.0;  // the cut's direction along Z
  const double flank = std::tan(threadData.toolAngle / 2 * M_PI / 180.0);
  const double chamfer = threadData.chamfer * feedMM;
  // The shallowest pass is the shortest (the flank infeed shortens it at both ends).
  if (chamfer >= std::fabs(e[2] - a[2]) - 2 * depths.front() * flank)
    return error(fmt::format("the G76 run-out chamfer ({} mm: r = {} x the lead) is not shorter than the thread",
                             chamfer, threadData.chamfer), "thread-invalid");
  MotionRecord begin = record(RecordKind::CycleBegin);
  begin.text = "iso.G76";
  begin.setParam("X", e[0] - frameOffset(0)), begin.setParam("Z", e[2] - frameOffset(2)), begin.setParam("R", taper);
  begin.setParam("P", height);
  begin.setParam("Q", first), begin.setParam("F", feedMM);
  emit(begin);
  std::vector<ThreadStep> steps;
  for (double depth : depths) {
    ThreadPass p;
    p.retractX = a[0];
    p.endX = e[0] + out * (height - depth);
    p.startX = p.endX + taper;
    // Deeper passes shift along the cut's direction (as LinuxCNC's compound infeed); the
    // full-depth pass ends at the programmed end.
    p.startZ = a[2] + dir * depth * flank;
    p.endZ = e[2] + dir * (depth - height) * flank;
    p.lead = feedMM;
    if (chamfer > 0) {
      p.exit = true, p.exitDz = dir * chamfer, p.exitLead = feedMM;
      p.exitX = p.endX + out * chamfer;
      if ((p.exitX - a[0]) * out > 0) p.exitX = a[0];  // never beyond the retract line
    }
    threadPass(p, steps);
  }
  bool ok = threadSteps(steps, ThreadAxis::Z) && moveTo(RecordKind::Rapid, a);
  emit(record(RecordKind::CycleEnd));
  return ok;
}

}  // namespace ncc
