// Lathe single cycles (808D G90 and G94 of system A, G77 and G79 of B, spec seed001 3.1): modal in group 01; each move
// block runs four steps from the current point A in the ZX plane and ends at A again. G90 (turn
// along Z): rapid across to the end X (plus the taper R at A's Z), feed to the end point, feed
// out across to A's X, rapid back along Z. G94 (along X): rapid along Z to the end Z (plus R),
// feed to the end point, feed out along Z to A's Z, rapid back across to A's X. A repeat block
// gives only what changes: the other end coordinate and R stay from the cycle before.
// G92 (system B G78), the single thread cycle, runs G90's steps with a thread (lead F, start
// angle Q, along Z unless the taper is steeper than 45 degrees) for the cut and a rapid out;
// the run-out chamfer the 808D makes on a machine signal is not modelled (no such signal here).
#include "runtime/ExecutorImpl.h"
#include "runtime/cycles/Grooving.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

bool Executor::Impl::turnCycle(const MachineCmd &c) {
  const bool thread = st.motion == ModeValue::ThreadSingle;
  const bool alongZ = st.motion == ModeValue::TurnAlongZ || thread;
  const char *code = thread ? "G92 (G78)" : alongZ ? "G90 (G77)" : "G94 (G79)";  // systems A (B)
  if (plane() != Plane::ZX) return error(std::string(code) + " needs the ZX plane (G18)", "unsupported-code");
  if (linearFrame()) return error(std::string(code) + " under a rotation, scaling or mirror is not supported", "unsupported-code");
  if (!compForbids("Cannot use turning cycles with cutter compensation on")) return false;
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Z)))
    return error(std::string(code) + " takes X (U), Z (W) and R", "unsupported-code");
  if (!(c.mask & (wordBit(Word::X) | wordBit(Word::Z)))) {
    if (c.has(Word::R)) return error(std::string(code) + " needs X (U) or Z (W)", "missing-word");
    return true;
  }
  if (thread ? !threadAllowed(code) : !checkFeed(code)) return false;
  if (thread && !(feedMM > 0)) return error(std::string(code) + " needs F, the thread lead", "thread-invalid");
  const AxisVec a = st.position;
  AxisVec e = target(c);
  if (turnSet) {  // a repeat: the words not given keep the last cycle's end point
    if (!c.has(Word::X)) e[0] = turnEnd[0];
    if (!c.has(Word::Z)) e[2] = turnEnd[2];
  } else {
    turnTaper = 0;
    if (!c.has(Word::X) || !c.has(Word::Z))
      return error(std::string(code) + " needs both end point words, X (U) and Z (W), in its first block", "missing-word");
  }
  if (c.has(Word::R)) turnTaper = c.get(Word::R) * scale();  // a radius (G90) / Z length (G94)
  turnEnd = e, turnSet = true;
  MotionRecord begin = record(RecordKind::CycleBegin);
  begin.text = thread ? "iso.thread_z" : alongZ ? "iso.turn_z" : "iso.turn_x";
  emit(begin);
  AxisVec p1 = a, p3 = e;
  if (alongZ) p1[0] = e[0] + turnTaper, p3[0] = a[0];
  else p1[2] = e[2] + turnTaper, p3[2] = a[2];
  auto cut = [&] {
    if (!thread) return moveTo(RecordKind::Linear, e);
    const ThreadAxis along = std::fabs(e[0] - p1[0]) <= std::fabs(e[2] - p1[2]) ? ThreadAxis::Z : ThreadAxis::X;
    return threadTo(e, feedMM, along, ThreadSync::Index, c.has(Word::Q) ? c.get(Word::Q) : 0);
  };
  bool ok = moveTo(RecordKind::Rapid, p1) && cut() && moveTo(thread ? RecordKind::Rapid : RecordKind::Linear, p3) &&
            moveTo(RecordKind::Rapid, a);
  emit(record(RecordKind::CycleEnd));
  return ok;
}

// Tool nose radius compensation (808D manual L2186-2512): the program and the tool offsets
// describe the imaginary tool tip; CutterComp offsets the nose centre's path by the radius and
// the machine position is that centre plus the tip vector. Tips 0 and 9 are the centre itself.
bool Executor::Impl::noseTipShift(const ToolData &t, double radius, int side, bool rs274) {
  if (linearFrame())
    return error("tool nose radius compensation under a rotation, scaling or mirror is not supported", "unsupported-code");
  // rs274's orientations 1-8 (interp_queue.cc's latheorigin) are the Fanuc tips mirrored in X.
  static const int kRs274Tip[10] = {0, 4, 3, 2, 1, 5, 8, 7, 6, 9};
  const Point2 v = noseTipVector(rs274 && t.tip >= 0 && t.tip <= 9 ? kRs274Tip[t.tip] : t.tip);
  if (v.x == 0 && v.y == 0) return true;
  if (plane() != Plane::ZX && rs274)
    return error(fmt::format("G{} with lathe tool, but plane is not G18", side == 2 ? 42 : 41), "cutcomp-plane");
  if (plane() != Plane::ZX)
    return error("tool nose radius compensation with an imaginary tool tip 1-8 needs the ZX plane (G18)",
                 "unsupported-code");
  AxisVec s{};
  s[0] = v.x * radius, s[1] = v.y * radius;  // compensation plane: Z first, X second
  compOut.shift = fromCompPlane(s, Plane::ZX);
  return true;
}

// Fanuc starts the compensation in the block where G41/G42 is given or where, in G41/G42, the
// offset number becomes one with a radius [model: the 808D manual says only "G41/G42 with T"]:
// G41/G42 again, now with the T word's offset.
bool Executor::Impl::noseCompAfterT() {
  MachineCmd g;
  g.kind = CmdKind::CutterComp;
  g.sub = (uint8_t)st.cutterComp;
  st.cutterComp = 0;
  return execCutterComp(g);
}

}  // namespace ncc

// The peck cycles G74 (pecks along Z, grooves shifted along X) and G75 (pecks along X, shifted
// along Z), 808D manual 1.5.1 (L3660-3716), Fanuc's two-block form: `G74 R<e>` sets the retract
// after each peck (modal; the machine's `peck_retract` until then), `G74 X(U) Z(W) P<Δi> Q<Δk>
// R<Δd> F` cuts from the start point A to the end point. P is the X amount, Q the Z amount (radii,
// least increments), R the relief Δd when the block names the shift axis (G74 X, G75 Z), else e.
// Without the shift axis the cycle drills (G74) or cuts one groove (G75); P (G74) / Q (G75) are
// then errors, as in the manual. runtime/cycles/Grooving.h makes the moves.
namespace ncc {

bool Executor::Impl::peckCycle(const MachineCmd &c) {
  const bool alongZ = st.motion == ModeValue::PeckAlongZ;
  st.motion = threadReturn;  // one-shot
  const char *code = alongZ ? "G74" : "G75";
  const int peckAxis = alongZ ? 2 : 0, shiftAxis = alongZ ? 0 : 2;
  const Word peckWord = alongZ ? Word::Q : Word::P, shiftWord = alongZ ? Word::P : Word::Q;
  const char *peckName = alongZ ? "Z (W)" : "X (U)", *shiftName = alongZ ? "X (U)" : "Z (W)";
  const char peckLetter = alongZ ? 'Q' : 'P', shiftLetter = alongZ ? 'P' : 'Q';
  const bool shifts = c.has(alongZ ? Word::X : Word::Z);
  auto amount = [&](Word w, char letter, const char *what, double &v) {
    v = c.has(w) ? c.get(w) * scale() : 0;
    return v >= 0 || error(fmt::format("{} {} ({}) must not be negative: it is written without a sign", code, letter, what), "cycle-invalid");
  };
  if (c.has(Word::R) && !shifts) {
    double e;
    if (!amount(Word::R, 'R', "the retract e", e)) return false;
    peckRetract = e;
  }
  if (c.mask & kAxisMask & ~(wordBit(Word::X) | wordBit(Word::Z)))
    return error(fmt::format("{} takes X (U), Z (W), P, Q, R and F", code), "unsupported-code");
  if (!(c.mask & (wordBit(Word::X) | wordBit(Word::Z)))) {
    if (c.has(Word::P) || c.has(Word::Q))
      return error(fmt::format("{} P and Q need the end point {} in their block", code, peckName), "missing-word");
    if (!c.has(Word::R)) return error(fmt::format("{} needs R (the retract e) or an end point", code), "missing-word");
    return true;  // the data block
  }
  if (!c.has(alongZ ? Word::Z : Word::X))
    return error(fmt::format("{} needs the end point {} (the depth of its pecks)", code, peckName), "missing-word");
  if (!shifts && c.has(shiftWord))
    return error(fmt::format("{} {} (the shift between grooves) needs {} in its block (without it the cycle {})", code,
                             shiftLetter, shiftName, alongZ ? "drills" : "cuts one groove"),
                 "cycle-invalid");
  if (plane() != Plane::ZX) return error(fmt::format("{} needs the ZX plane (G18)", code), "unsupported-code");
  if (linearFrame()) return error(fmt::format("{} under a rotation, scaling or mirror is not supported", code), "unsupported-code");
  if (!compForbids("Cannot use turning cycles with cutter compensation on") || !checkFeed(code)) return false;
  PeckGroove g;
  if (!amount(peckWord, peckLetter, "the depth per peck", g.peck) || !amount(shiftWord, shiftLetter, "the shift", g.shift))
    return false;
  if (shifts && !amount(Word::R, 'R', "the relief at the bottom", g.relief)) return false;
  g.retract = peckRetract >= 0 ? peckRetract : machine.controller.peckRetract;
  const AxisVec a = st.position, e = target(c);
  g.start = {a[peckAxis], a[shiftAxis]}, g.end = {e[peckAxis], e[shiftAxis]};
  if (std::fabs(g.end.a - g.start.a) > 1e-9 && !c.has(peckWord))
    return error(fmt::format("{} needs {} (the depth per peck)", code, peckLetter), "missing-word");
  if (std::fabs(g.end.b - g.start.b) > 1e-9 && !c.has(shiftWord))
    return error(fmt::format("{} needs {} (the shift between grooves) to reach its end {}", code, shiftLetter, shiftName),
                 "missing-word");
  std::vector<ContourElem> moves;
  std::string why;
  if (!peckGrooves(g, moves, why)) return error(fmt::format("{}: {}", code, why), "cycle-invalid");
  MotionRecord begin = record(RecordKind::CycleBegin);
  begin.text = alongZ ? "iso.G74" : "iso.G75";
  begin.setParam("X", e[0] - frameOffset(0)), begin.setParam("Z", e[2] - frameOffset(2));
  begin.setParam(std::string(1, peckLetter), g.peck), begin.setParam(std::string(1, shiftLetter), g.shift);
  begin.setParam("R", g.relief), begin.setParam("E", g.retract);
  emit(begin);
  bool ok = true;
  for (const ContourElem &m : moves) {
    AxisVec to = a;
    to[peckAxis] = m.end.a, to[shiftAxis] = m.end.b;
    if (!(ok = moveTo(m.kind == ContourKind::Rapid ? RecordKind::Rapid : RecordKind::Linear, to))) break;
  }
  emit(record(RecordKind::CycleEnd));
  return ok;
}

}  // namespace ncc
