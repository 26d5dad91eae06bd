// Executor: canned-cycle blocks. Keeps the cycle's modal data (R, Z, Q, P, the initial level),
// resolves the words into the machine frame and turns the steps of expandCycle into records.
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/CycleFeed.h"
#include "runtime/cycles/Entry.h"

#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <string_view>

namespace ncc {

namespace {
// Drilling-axis word and index per plane (XY -> Z, ZX -> Y, YZ -> X).
constexpr Word kDrillWord[] = {Word::Z, Word::Y, Word::X};
constexpr int kDrillAxis[] = {2, 1, 0};
constexpr const char *kPlaneName[] = {"xy", "xz", "yz"};
// rs274 spells the codes in lower case in its messages ("Q word missing with g83").
std::string lower(const char *code) {
  std::string s = code;
  for (char &ch : s) ch = (char)std::tolower((unsigned char)ch);
  return s;
}
// CycleBegin's named numbers (docs/IR.md "Motion IR text"), in mm: the first hole's position in
// program coordinates (offset-frame step position minus the frame offsets), the drilling-axis
// bottom and R as programmed (G91: increments), Q and P when the cycle uses them, L the repeats.
void cycleParams(MotionRecord &r, const CycleInput &in, const std::vector<CycleStep> &steps,
                 const std::array<double, 3> &frameOffset, double z, double rLevel, int d) {
  for (const CycleStep &s : steps)
    if (!s.preMove) {
      for (int i = 0; i < 3; ++i)
        if (i != d) r.setParam(kWordKeys[i], s.pos[i] - frameOffset[i]);
      break;
    }
  r.setParam(kWordKeys[d], z);
  r.setParam("R", rLevel);
  const bool boring = in.cycle == ModeValue::BoreFine || in.cycle == ModeValue::BoreBack;
  if (in.cycle == ModeValue::Peck || in.cycle == ModeValue::PeckChipBreak || boring || in.tapPecks)
    r.setParam("Q", in.q);
  if (in.cycle == ModeValue::DrillDwell || in.cycle == ModeValue::BoreStop || in.cycle == ModeValue::BoreDwell ||
      boring)
    r.setParam("P", in.p);
  r.setParam("L", in.repeats);
}
}  // namespace

bool Executor::Impl::cycle(const MachineCmd &c) {
  const ModeValue cyc = st.motion;
  const char *code = cycleCodeName(cyc);
  const int pl = (int)plane();
  const int d = kDrillAxis[pl];
  const Word zWord = kDrillWord[pl];
  const bool first = lastCycle != cyc;
  const bool inc = st.distance == ModeValue::Incremental;

  if (first && !c.has(zWord))
    return error(std::string(kWordKeys[(int)zWord]) + " value unspecified in " + kPlaneName[pl] +
                     " plane canned cycle",
                 "cycle-missing-word");
  if (first && !c.has(Word::R)) return error("R clearance plane unspecified in cycle", "cycle-missing-word");
  bool dwells = cyc == ModeValue::DrillDwell || cyc == ModeValue::BoreStop || cyc == ModeValue::BoreDwell;
  if (first && dwells && !c.has(Word::P))
    return error(std::string("Dwell time p word missing with ") + lower(code), "cycle-missing-word");
  if (c.has(zWord)) cycleZ = c.get(zWord) * scale();
  if (c.has(Word::R)) cycleR = c.get(Word::R) * scale();
  if (c.has(Word::Q)) {
    cycleQ = c.get(Word::Q) * scale();
    haveQ = true;
  }
  if (c.has(Word::P)) cycleP = c.get(Word::P);
  for (int i = 3; i < kAxes; ++i)  // rs274: "Cannot put an a in canned cycle"
    if (c.has((Word)i))
      return error(std::string("Cannot put ") + (i == 3 ? "an " : "a ") + (char)std::tolower(kWordKeys[i][0]) +
                       " in canned cycle",
                   "cycle-invalid");
  if (!cycleFrameOk()) return false;
  if ((cyc == ModeValue::BoreFine || cyc == ModeValue::BoreBack) && (rotated() || pf.linear))
    return error(std::string(code) + " under a coordinate rotation, scaling or mirror is not supported: the shift "
                                     "off the wall would no longer point away from the oriented cutting edge",
                 "unsupported-code");
  const bool tapping = cyc == ModeValue::Tap || cyc == ModeValue::TapLeft;
  if (first) tapQ = false;
  if (tapping && c.has(Word::Q)) {
    // 808D peck tapping: the machine's GUD _ZSFI[1] says how; without it Q has no meaning.
    if (machine.controller.peckTapping == "off")
      return error(std::string(code) + " with Q (peck tapping) needs the machine's [controller] peck_tapping "
                                       "(808D GUD _ZSFI[1]: chip-breaking or chip-removal)",
                   "unsupported-code");
    if (!(cycleQ > 0)) return error("Negative or zero q value used", "cycle-invalid");
    tapQ = true;
  }
  bool peck = cyc == ModeValue::Peck || cyc == ModeValue::PeckChipBreak;
  if (peck && !haveQ) return error(std::string("Q word missing with ") + lower(code), "cycle-missing-word");
  int repeats = 1;
  if (c.has(Word::L)) {
    double l = c.get(Word::L);
    if (l != std::floor(l) || std::fabs(l) > 1e6) return error("Non integer value for integer", "cycle-bad-repeat");
    repeats = (int)l;
  }
  // Spindle conditions rs274 checks before tapping and boring.
  if (cyc == ModeValue::Tap && st.spindle != 1)
    return error("Spindle not turning clockwise in G84", "cycle-spindle");
  if (cyc == ModeValue::TapLeft && st.spindle != 2)
    return error("Spindle not turning counterclockwise in G74", "cycle-spindle");
  if (cyc == ModeValue::BoreStop && st.spindle == 0) return error("Spindle not turning in G86", "cycle-spindle");
  if ((cyc == ModeValue::BoreFine || cyc == ModeValue::BoreBack) && st.spindle == 0)
    return error(std::string("Spindle not turning in ") + code, "cycle-spindle");
  if (!checkFeed(code)) return false;

  if (!initialLevelValid) {
    initialLevel = st.position[d];  // machine frame
    initialLevelValid = true;
  }
  // The cycle is computed in the offset frame (ExecutorImpl.h) and mapped back per step.
  const AxisVec here = frameIn(st.position);
  AxisVec level = st.position;
  level[d] = initialLevel;
  CycleInput in;
  in.cycle = cyc;
  in.plane = plane();
  in.retractToR = st.retract == ModeValue::RetractR;
  in.incremental = inc;
  in.current = {here[0], here[1], here[2]};
  in.initialLevel = frameIn(level)[d];
  in.sameCycle = !first;
  in.r = inc ? cycleR : cycleR + frameOffset(d);
  in.z = inc ? cycleZ : cycleZ + frameOffset(d);
  in.q = cycleQ;
  in.p = cycleP;
  in.repeats = repeats;
  in.spindle = st.spindle;
  in.orientAngle = machine.controller.boringOrientAngle;
  in.lift = machine.controller.boringLift;
  if (c.has(Word::FanucCycle)) {
    // 808D G73 backs off by the GUD _ZSFR[1] (0 means 1 mm, manual L7686-7689); G84/G74 go back
    // to R, dwell P there too and rapid on (L8662, figure 2-44).
    const double back = machine.controller.chipBreakRetract;
    if (cyc == ModeValue::PeckChipBreak) in.chipBreak = back > 0 ? back : 1.0;
    in.tapOutToR = tapping;
  }
  if (tapping && tapQ) {
    in.tapPecks = machine.controller.peckTapping == "chip-breaking" ? 2 : 3;
    const double d = machine.controller.chipBreakRetract;  // _ZSFR[1]: 0 means 1 mm
    in.tapBack = d > 0 ? d : 1.0;
  }
  for (int i = 0; i < 3; ++i) {
    if (i == d) continue;
    bool has = c.has((Word)i);
    double v = c.get((Word)i) * scale();
    in.target[i] = inc ? (has ? v : 0.0) : (has ? v + frameOffset(i) : here[i]);
  }
  if (c.has(Word::PolarR) || c.has(Word::PolarA)) {
    if (pl != 0) return error("polar coordinates in a canned cycle outside the XY plane are not supported", "unsupported-code");
    in.polar = true;
    in.polarHasR = c.has(Word::PolarR);
    in.polarHasA = c.has(Word::PolarA);
    in.polarR = c.get(Word::PolarR) * scale();
    in.polarA = c.get(Word::PolarA);
    in.origin = {frameOffset(0), frameOffset(1)};
  }
  steps.clear();
  std::string err;
  if (!expandCycle(in, steps, err)) return error(err, "cycle-invalid");
  lastCycle = cyc;
  MotionRecord begin = record(RecordKind::CycleBegin);
  begin.text = std::string("iso.") + code;
  cycleParams(begin, in, steps, {frameOffset(0), frameOffset(1), frameOffset(2)}, cycleZ, cycleR, d);
  emit(begin);
  return runSteps(steps);
}

bool Executor::Impl::cycleFrameOk() {
  if (rotated() && plane() != Plane::XY)
    return error("canned cycles outside the XY plane with a rotated coordinate system are not supported",
                 "unsupported-code");
  if (!pf.linear) return true;
  // A tilted working plane turns the whole cycle rigidly (ExecutorPlane.cpp); a rotation inside it too.
  if (pf.tiltOn && !pf.scaleOn && !pf.mirrorOn()) return true;
  // Only a rotation about the drilling axis keeps the cycle's geometry.
  const auto &m = pf.composite.m;
  const int d = planeAxes(plane()).n;
  bool flip = false;
  if (!frameKeepsPlane(plane(), flip) || flip || m[d][d] != 1 || pf.scaleOn)
    return error("canned cycles under scaling, mirroring or a rotation that tilts the drilling axis are not supported",
                 "unsupported-code");
  return true;
}

bool Executor::Impl::runSteps(const std::vector<CycleStep> &steps) {
  // rs274 runs the holes of a block in exact-path mode and restores the path mode after.
  bool bracketOpen = false;
  double rate = feedMM;  // a step's own feed (vendor cycles) changes the rate for its move
  auto openBracket = [&] {
    MotionRecord r = record(RecordKind::PathMode);
    r.ivalue = 0;
    emit(r);
    bracketOpen = true;
  };
  for (const CycleStep &s : steps) {
    if (!s.preMove && !bracketOpen) openBracket();
    AxisVec to = frameIn(st.position);
    to[0] = s.pos[0], to[1] = s.pos[1], to[2] = s.pos[2];
    to = frameOut(to);
    switch (s.kind) {
    case CycleStepKind::Rapid: moveTo(RecordKind::Rapid, to, !s.preMove); break;
    case CycleStepKind::Feed:
    case CycleStepKind::Arc: {
      if (s.feed == cyclefeed::kRapid) {  // a feed parameter given as FMAX (CycleFeed.h)
        if (s.kind == CycleStepKind::Arc) return error("FMAX as the feed of a cycle's arc: the TNC moves arcs at a feed", "cycle-invalid");
        moveTo(RecordKind::Rapid, to, true);
        break;
      }
      double f = s.feed > 0 ? s.feed : feedMM;
      if (f != rate) {
        MotionRecord r = record(RecordKind::FeedRate);
        r.value = rate = f;
        emit(r);
      }
      if (s.kind == CycleStepKind::Feed) {
        moveTo(RecordKind::Linear, to, true, s.feed);
        break;
      }
      // The centre maps like a point; the frame keeps the plane's normal (cycleFrameOk).
      AxisVec c = frameIn(st.position);
      c[0] = s.centre[0], c[1] = s.centre[1], c[2] = s.centre[2];
      c = frameOut(c);
      Vec3 n = planeNormal(plane());
      if (pf.tiltOn && !tiltedNormal(n)) return false;
      if (!emitArc(to, {c[0], c[1], c[2]}, n, s.ccw ? s.turns : -s.turns, s.feed, true)) return false;
      break;
    }
    case CycleStepKind::Dwell: {
      MotionRecord r = record(RecordKind::Dwell);
      r.value = s.seconds;
      emit(r);
      break;
    }
    case CycleStepKind::SpindleStop:  // the state follows: a later cycle sees the direction it left
      st.spindle = 0;
      emit(record(RecordKind::SpindleStop));
      break;
    case CycleStepKind::SpindleCW:
      st.spindle = 1;
      emit(record(RecordKind::SpindleCW));
      break;
    case CycleStepKind::SpindleCCW:
      st.spindle = 2;
      emit(record(RecordKind::SpindleCCW));
      break;
    case CycleStepKind::SpindleOrient: orientSpindle(s.angle, 2, 0, true); break;
    case CycleStepKind::SpindleSpeed:
      if (s.speed != st.speed) {
        st.speed = s.speed;
        MotionRecord r = record(RecordKind::SpindleSpeed);
        r.value = s.speed;
        emit(r);
      }
      break;
    case CycleStepKind::Coolant: {  // as M7/M8/M9 (Executor.cpp CmdKind::Coolant): mist first
      const bool mist = s.coolant & 2, flood = s.coolant & 1;
      if (s.coolant == 0 || mist) {
        MotionRecord r = record(RecordKind::CoolantMist);
        r.ivalue = st.mist = mist;
        emit(r);
      }
      if (s.coolant == 0 || flood) {
        MotionRecord r = record(RecordKind::CoolantFlood);
        r.ivalue = st.flood = flood;
        emit(r);
      }
      break;
    }
    case CycleStepKind::RigidTap:
      if (!cycleRigidTap(to, s)) return false;
      break;
    case CycleStepKind::Thread:
      if (!s.chain && !threadAllowed("a thread cycle")) return false;
      if (!threadTo(to, s.lead, (ThreadAxis)s.along, s.chain ? ThreadSync::Chain : ThreadSync::Index, s.angle))
        return false;
      break;
    }
  }
  if (rate != feedMM) {
    MotionRecord r = record(RecordKind::FeedRate);
    r.value = feedMM;
    emit(r);
  }
  if (bracketOpen) emit(pathModeRecord());
  emit(record(RecordKind::CycleEnd));
  return true;
}

// A rigid tap step: at the step's speed (the active S restored after it), down and back as one
// tap (the thread records of Sinumerik G331/G332).
bool Executor::Impl::cycleRigidTap(const AxisVec &bottom, const CycleStep &s) {
  const double saved = st.speed;
  auto speed = [&](double rpm) {
    if (rpm == st.speed) return;
    st.speed = rpm;
    MotionRecord r = record(RecordKind::SpindleSpeed);
    r.value = rpm;
    emit(r);
  };
  if (s.speed > 0) speed(s.speed);
  if (!(st.speed > 0)) return error("a rigid tap needs a spindle speed", "thread-spindle");
  const AxisVec from = st.position;
  const ThreadAxis along = (ThreadAxis)planeAxes(plane()).n;
  if (!threadTo(bottom, s.lead, along, ThreadSync::TapIn, 0) || !threadTo(from, s.lead, along, ThreadSync::TapOut, 0))
    return false;
  speed(saved);
  return true;
}

bool Executor::runCycle(const CycleDef &cycle, const CycleArgs &args, const CycleDef *pattern,
                        const CycleArgs *patternArgs, SourceLoc loc) {
  Impl::PlainStateRefresh refresh{*impl_};
  impl_->loc = loc;
  return impl_->runLibraryCycle(&cycle, args, pattern, patternArgs);
}

// An entry's error, named by the entry: entry::unsupported marks a parameter value ncc does not
// honour (unsupported-code), anything else is a wrong call (cycle-invalid).
static bool entryError(Executor::Impl &x, const char *name, std::string err) {
  const bool unsupported = err.compare(0, entry::kUnsupported.size(), entry::kUnsupported) == 0;
  if (unsupported) err.erase(0, entry::kUnsupported.size());
  return x.error(std::string(name) + ": " + err, unsupported ? "unsupported-code" : "cycle-invalid");
}

bool Executor::Impl::runLibraryCycle(const CycleDef *cyc, const CycleArgs &given, const CycleDef *pattern,
                                     const CycleArgs *patternArgs) {
  Impl &x = *this;
  std::string err;
  CycleArgs args = given;  // FU/FZ feeds become mm/min with this call's spindle and tool (CycleFeed.h)
  if (cyc) {
    cyclefeed::Spindle sp{x.st.speed, 0};
    if (auto t = x.machine.toolTable.find(x.st.toolInSpindle); x.st.toolInSpindle > 0 && t != x.machine.toolTable.end())
      sp.teeth = t->second.teeth;
    if (!cyclefeed::resolve(*cyc, args, sp, err)) return entryError(x, cyc->name, std::move(err));
  }
  if ((cyc && !checkCycleArgs(*cyc, args, err)) || (pattern && !checkCycleArgs(*pattern, *patternArgs, err)))
    return x.error(err, "cycle-invalid");
  // A TNC with displayDepthErr on refuses a positive depth in its 2xx cycles (seed002a L1802).
  if (cyc && x.machine.controller.displayDepthErr && std::string_view(cyc->name).substr(0, 5) == "hei.2" &&
      args.has("Q201") && args.get("Q201") > 0)
    return x.error(fmt::format("{}: the depth Q201=+{:g} is positive: the TNC stops with an error (machine parameter "
                               "displayDepthErr, key display_depth_err; without it the cycle pre-positions below the surface)",
                               cyc->name, args.get("Q201")),
                   "positive-depth");
  if (x.st.units != ModeValue::MM) return x.error("library cycles run in mm (G21) only", "unsupported-code");
  if (!x.compForbids("Cannot use canned cycles with cutter compensation on")) return false;
  if (!x.cycleFrameOk()) return false;
  if (x.st.css) return x.error("library cycles under constant surface speed (G96) are not supported", "unsupported-code");
  CycleContext ctx;
  ctx.plane = (int)x.plane();
  AxisVec here = x.programPosition();
  for (int i = 0; i < 3; ++i) ctx.position[i] = here[i];
  ctx.feed = x.st.feedMode == ModeValue::PerMinute ? x.feedMM : 0;
  ctx.feedPerRev = x.st.feedMode == ModeValue::PerRev;
  ctx.spindle = x.st.spindle;
  ctx.speed = x.st.speed;
  if (x.st.toolInSpindle > 0) ctx.toolRadius = x.toolNumberData(x.st.toolInSpindle).radius;
  if (auto t = x.machine.toolTable.find(x.st.toolInSpindle); t != x.machine.toolTable.end())
    ctx.plungeAngle = t->second.plungeAngle, ctx.pointAngle = t->second.pointAngle,
    ctx.cuttingLength = t->second.cuttingLength, ctx.toolWidth = t->second.width;
  // A captured contour belongs to the one cycle after it (CYCLE95's NPP); it was captured in the
  // offset frame (Contour.h), the cycle works in program coordinates (ZX: a = Z, b = X).
  CycleContour kept = std::move(x.keptContour);
  if (x.keptSet) {
    const Pt2 off{x.frameOffset(2), x.frameOffset(0)};
    auto toProgram = [&](Pt2 &p) { p.a -= off.a, p.b -= off.b; };
    toProgram(kept.contour.start);
    for (ContourElem &e : kept.contour.elems) toProgram(e.end), toProgram(e.centre);
    ctx.contour = &kept;
  }
  x.keptSet = false;
  std::vector<CycleStep> steps;
  const char *name = pattern ? pattern->name : cyc->name;
  bool ok = pattern ? expandPattern(*pattern, *patternArgs, cyc, args, ctx, steps, err)
                    : cyc->expand ? cyc->expand(args, ctx, steps, err)
                                  : (err = "a position pattern: give it a cycle to run", false);
  if (!ok) return entryError(x, name, std::move(err));
  for (const CycleStep &s : steps)
    if ((s.kind == CycleStepKind::Feed || s.kind == CycleStepKind::Arc) && s.feed <= 0 && !x.checkFeed(name))
      return false;
  for (CycleStep &s : steps)  // program coordinates -> the offset frame
    for (int i = 0; i < 3; ++i) s.pos[i] += x.frameOffset(i), s.centre[i] += x.frameOffset(i);
  // The bracket names the pattern and the cycle it runs ("sin.HOLES1+sin.CYCLE81"; a pattern
  // alone only positions) with the arguments as given, the pattern's prefixed "p" (both may
  // have a parameter of one name: _DMODE).
  MotionRecord begin = x.record(RecordKind::CycleBegin);
  begin.text = pattern ? std::string(pattern->name) + (cyc ? std::string("+") + cyc->name : "") : cyc->name;
  for (auto &[k, v] : args.text) begin.text += "|" + k + "=" + v;  // STRING arguments after the name
  if (pattern)
    for (auto &[k, v] : patternArgs->text) begin.text += "|p" + k + "=" + v;
  for (auto &[k, v] : args.num) begin.setParam(k, v);
  if (pattern)
    for (auto &[k, v] : patternArgs->num) begin.setParam("p" + k, v);
  // Machine minus program position (mx my mz, each when not 0) under a pure translation, else
  // frame=1: an emitter writing the call back shifts the entry's absolute positions
  // (CycleDef::coords) by it.
  if (x.pf.linear || x.rotated()) begin.setParam("frame", 1);
  else
    for (int i = 0; i < 3; ++i)
      if (double m = x.st.position[i] - here[i]; m != 0) begin.setParam(std::string("m") + (char)('x' + i), m);
  x.emit(begin);
  return x.runSteps(steps);
}

// The `cycle` op (docs/IR.md §5.8): the command's words are the entries' parameters by
// position (passes/CycleOp.h); absent words are omitted arguments.
static bool cycleArgsOf(const MachineCmd &c, const CycleDef &def, int first, CycleArgs &out, std::string &err) {
  auto names = cycleParamNames(def);
  const int textWord = (c.sub >> kCycleTextShift) - 1;  // the STRING argument's word
  for (size_t i = 0; i < names.size(); ++i) {
    Word w = (Word)(first + (int)i);
    if ((int)w == textWord) out.text[std::string(names[i])] = c.text ? c.text : "";
    if (!c.has(w)) continue;
    if (!std::isfinite(c.get(w))) {
      err = std::string(def.name) + " parameter " + std::string(names[i]) + ": invalid number";
      return false;
    }
    out.num[std::string(names[i])] = c.get(w);
  }
  return true;
}

bool Executor::Impl::execCycle(const MachineCmd &c) {
  const auto &lib = cycleLibrary();
  unsigned e = c.sub & 0xff, p = c.sub2 & kCyclePatternMask;
  if (e > lib.size() || p > lib.size()) return error("cycle command names no library entry", "cycle-invalid");
  const CycleDef *entry = e ? &lib[e - 1] : nullptr;
  const CycleDef *pattern = p ? &lib[p - 1] : nullptr;
  CycleArgs args, patternArgs;
  std::string err;
  if ((entry && !cycleArgsOf(c, *entry, 0, args, err)) ||
      (pattern && !cycleArgsOf(c, *pattern, entry ? (int)cycleParamNames(*entry).size() : 0, patternArgs, err)))
    return error(err, "bad-number");
  if (entry && isTransformEntry(*entry)) return execTransform(*entry, args, cycleAction(c.sub2));
  switch (cycleAction(c.sub2)) {
  case CycleAction::Define:
  case CycleAction::Modal:
    storedCycle = {entry, args, cycleAction(c.sub2) == CycleAction::Modal};
    return true;
  case CycleAction::Cancel: storedCycle = {}; return true;
  case CycleAction::Trigger:
    if (!storedCycle.modal) return true;
    return runLibraryCycle(storedCycle.def, storedCycle.args, nullptr, nullptr);
  case CycleAction::Call:  // a pattern without a stored cycle only positions (Sinumerik)
    if (!storedCycle.def && !pattern) return error("no cycle defined to call", "cycle-invalid");
    return runLibraryCycle(storedCycle.def, storedCycle.args, pattern, pattern ? &patternArgs : nullptr);
  case CycleAction::Run: break;
  }
  return runLibraryCycle(entry, args, pattern, pattern ? &patternArgs : nullptr);
}

bool Executor::Impl::modalCycleAfterMove(const MachineCmd &c) {
  if (!storedCycle.modal || !(c.mask & kAxisMask)) return true;
  return runLibraryCycle(storedCycle.def, storedCycle.args, nullptr, nullptr);
}

}  // namespace ncc
