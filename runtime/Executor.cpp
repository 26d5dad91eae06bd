// Executor: command dispatch, modal state, work offsets and program stops. Motion lives in
// ExecutorMotion.cpp, tool data and system variables in ExecutorState.cpp, compensation in
// ExecutorCompensation.cpp. The semantics follow LinuxCNC's rs274 at machine level (the oracle).
#include "runtime/ExecutorImpl.h"
#include "ir/FrameTilt.h"
#include "runtime/Geometry.h"
#include "runtime/WorkOffsetCode.h"

#include "ir/Value.h"

#include <cassert>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

static void rotateXY(AxisVec &p, double degrees) {
  double r = degrees * M_PI / 180, c = std::cos(r), s = std::sin(r);
  double x = p[0] * c - p[1] * s, y = p[0] * s + p[1] * c;
  p[0] = x, p[1] = y;
}

AxisVec Executor::Impl::frameIn(const AxisVec &m) const {
  if (!linearFrame()) return m;
  AxisVec f;
  const AxisVec &o = chainOffset;
  if (tiltMapped()) f = tiltIn(m);  // the tilt on a chain: the tool length along the tool axis
  else
    for (int i = 0; i < kAxes; ++i) f[i] = m[i] - o[i] - toolOffset(i);
  if (rotated()) rotateXY(f, -rotation());
  if (!pf.linear) return f;
  for (int i = 0; i < kAxes; ++i) f[i] -= g92[i];
  return pf.in(f);
}

AxisVec Executor::Impl::frameOut(const AxisVec &f) const {
  if (!linearFrame()) return f;
  AxisVec m = f;
  if (pf.linear) {
    m = pf.out(f);
    for (int i = 0; i < kAxes; ++i) m[i] += g92[i];
  }
  if (rotated()) rotateXY(m, rotation());
  if (tiltMapped()) return tiltOut(m);
  const AxisVec &o = chainOffset;
  for (int i = 0; i < kAxes; ++i) m[i] += o[i] + toolOffset(i);
  return m;
}

void Executor::Impl::noteFrame(const char *what) {
  auto toMachine = [&](double x, double y, double z) {
    AxisVec p{};
    p[0] = x, p[1] = y, p[2] = z;
    for (int i = 0; i < kAxes; ++i) p[i] += frameOffset(i);  // A B C U V W too: their shift
    AxisVec m = frameOut(p);
    for (int i = 0; i < kAxes; ++i) m[i] -= toolOffset(i);
    return m;
  };
  AxisVec o = toMachine(0, 0, 0), ex = toMachine(1, 0, 0), ey = toMachine(0, 1, 0), ez = toMachine(0, 0, 1);
  FrameMatrix f;
  for (int i = 0; i < 3; ++i) {
    f[i * 4 + 0] = ex[i] - o[i];
    f[i * 4 + 1] = ey[i] - o[i];
    f[i * 4 + 2] = ez[i] - o[i];
    f[i * 4 + 3] = o[i];
  }
  AxisShift shift;
  for (size_t i = 0; i < shift.size(); ++i) shift[i] = o[3 + i];  // machine A B C U V W of work 0
  const int selection = offsetSelection();
  if (f == lastFrame && shift == lastShift && selection == lastSelection) return;
  lastFrame = f, lastShift = shift, lastSelection = selection;
  MotionRecord r = record(RecordKind::FrameChange);
  r.text = what;
  setFrameMatrix(r, f);
  setAxisShift(r, shift);
  setWorkOffsetSelection(r, selection);
  emit(r);
}

bool Executor::Impl::orientSpindle(double angle, int way, double wait, bool inCycle) {
  if (way < 0 || way > 2) return error("bad spindle orientation way", "bad-command");
  if (!std::isfinite(angle) || !(wait >= 0)) return error("bad spindle orientation angle or wait", "bad-command");
  MotionRecord r = record(RecordKind::SpindleOrient);
  r.value = angle, r.ivalue = way, r.value2 = wait;
  if (!inCycle) st.spindle = 0, spindlePositioned = true;  // oriented = stopped: M3/M4 start it again
  emit(r);
  return true;
}

bool Executor::Impl::frameForbids(const char *what) {
  if (!pf.linear) return true;
  return error(std::string(what) + " is not allowed while a programmable rotation, scaling or mirror (G68, G51, "
                                   "G51.1) is active",
               "frame-conflict");
}

bool Executor::Impl::frameKeepsPlane(Plane pl, bool &flip) const {
  flip = false;
  if (!linearFrame()) return true;
  if (rotated()) return pl == Plane::XY;  // rs274's Rz (pf is never linear with it: no G68 in .ngc)
  const PlaneAxes ax = planeAxes(pl);
  const int a1 = ax.u, a2 = ax.v, d = ax.n;
  const Affine out = outLinear();
  const auto &m = out.m;
  if (m[d][a1] != 0 || m[d][a2] != 0 || m[a1][d] != 0 || m[a2][d] != 0) return false;
  double n1 = m[a1][a1] * m[a1][a1] + m[a2][a1] * m[a2][a1], n2 = m[a1][a2] * m[a1][a2] + m[a2][a2] * m[a2][a2];
  double dot = m[a1][a1] * m[a1][a2] + m[a2][a1] * m[a2][a2];
  if (std::fabs(n1 - n2) > 1e-12 * std::max(n1, n2) || std::fabs(dot) > 1e-12 * std::max(n1, n2)) return false;
  flip = m[a1][a1] * m[a2][a2] - m[a1][a2] * m[a2][a1] < 0;
  return true;
}

AxisVec Executor::Impl::target(const MachineCmd &c) const {
  // Axes without a word keep their program position (under a rotation that moves X and Y).
  // Without a rotation, mirror or scaling the offset frame is the machine's: no mapping.
  const bool linear = linearFrame();
  AxisVec t = linear ? frameIn(st.position) : st.position;
  const bool inc = st.distance == ModeValue::Incremental;
  // A move's own absolute/incremental axes (sub/sub2, MachineCmd.h) override the mode.
  const uint16_t incAxes = c.kind == CmdKind::Move ? c.sub : c.kind == CmdKind::Home ? c.sub2 : 0,
                 absAxes = c.kind == CmdKind::Move ? c.sub2 : 0;
  // axisScale and frameOffset per axis, their cases decided once per move (the same sums).
  const double unit = scale(), xUnit = axisScale(0);
  const bool shifted = !pf.linear, allOffsets = shifted && !rotated();
  for (WordMask m = c.mask & kAxisMask; m; m &= m - 1) {  // X Y Z A B C U V W are the first words
    const int i = __builtin_ctzll(m);
    const double v = c.w[i] * (i == 0 ? xUnit : isLengthAxis(i) ? unit : 1.0);
    const bool axisInc = (incAxes >> i) & 1 ? true : (absAxes >> i) & 1 ? false : inc;
    const double off = !shifted ? 0.0 : allOffsets ? offset(i) : g92[i] + pf.local[i];
    const double prog = axisInc ? t[i] - off + v : v;
    t[i] = prog + off;
  }
  if (c.mask & (wordBit(Word::PolarR) | wordBit(Word::PolarA))) {  // X and Y from @ ^ (exec rejects X/Y with them)
    double x = t[0] - frameOffset(0), y = t[1] - frameOffset(1);
    polarStep(x, y, inc, c.has(Word::PolarR), c.get(Word::PolarR) * scale(), c.has(Word::PolarA),
              c.get(Word::PolarA));
    t[0] = x + frameOffset(0);
    t[1] = y + frameOffset(1);
  }
  if (linear) t = frameOut(t);
  // A block of rotary words only keeps the linear axes where they are: the TNC's tilting
  // compensation acts on an axis when that axis moves (L13010), not through the rotary move.
  if (tiltMapped() && !(c.mask & 7u))
    for (int i = 0; i < 3; ++i) t[i] = st.position[i];
  return t;
}

bool Executor::Impl::checkAxisWords(const MachineCmd &c) {
  // Without a described axis set (machines built in code) X Y Z A B C are taken as present.
  if (!(c.mask & missingAxes)) return true;
  for (int i = 0; i < kAxes; ++i)
    if (c.mask & missingAxes & wordBit((Word)i))
      return error(std::string(kWordKeys[i]) + " word used, but the machine has no " + kWordKeys[i] +
                       " axis",
                   "unknown-axis");
  return true;
}

MotionRecord Executor::Impl::pathModeRecord() const {
  MotionRecord r = record(RecordKind::PathMode);
  r.ivalue = st.pathMode == ModeValue::ExactPath ? 0 : st.pathMode == ModeValue::ExactStop ? 1 : 2;
  if (st.pathMode == ModeValue::Continuous) {
    r.value = pathTolerance;
    r.value2 = naiveTolerance;
  }
  return r;
}

// G0/G1 repeated (a loop's every iteration, every line of a flat program): with that mode in
// force and nothing execMode's Motion case resets still set, the command changes nothing.
bool Executor::Impl::modeRepeats(const MachineCmd &c) const {
  return c.nmodes == 1 && c.modes[0] == st.motion && (st.motion == ModeValue::Linear || st.motion == ModeValue::Rapid) &&
         st.pathMotion == st.motion && !nurbs.open && !initialLevelValid && lastCycle == ModeValue::CycleOff;
}

bool Executor::Impl::execMode(const MachineCmd &c) {
  if (modeRepeats(c)) return true;
  for (unsigned i = 0; i < c.nmodes && i < kMaxModes; ++i) {
    ModeValue v = c.modes[i];
    switch (modeValueInfo(v).group) {
    case ModeGroup::Motion:
      if (v == ModeValue::CycleCancel) v = st.pathMotion;
      if (isPathMotion(v)) st.pathMotion = v;
      if (nurbs.open && v != ModeValue::Nurbs && v != ModeValue::NurbsEnd)
        return error("a G5.2 NURBS must be ended with G5.3 before another motion (rs274 would drop its control points)",
                     "spline-invalid");
      if (v == ModeValue::NurbsEnd && !nurbsEnd()) return false;
      if (sinSpline.open && v != sinSpline.kind && !sinSplineEnd()) return false;
      if (v == ModeValue::SplineCubic || v == ModeValue::SplineQuadratic) splineReturn = st.motion;
      if ((v == ModeValue::ThreadMulti || isPeckMotion(v)) && st.motion != v) threadReturn = st.motion;  // one-shot
      if (v != st.motion) turnSet = false;  // a new G90/G94 run takes its words afresh
      st.motion = v;
      if (!isCycleMotion(v)) {
        // Leaving the cycles: the next cycle takes a new initial level.
        initialLevelValid = false;
        lastCycle = ModeValue::CycleOff;
      }
      break;
    case ModeGroup::Plane: {
      if (v != st.plane) cornerFlush("the plane changes");
      if (comp.active() && v != st.plane)
        return error("Cannot change planes with cutter radius compensation on", "cutcomp-conflict");
      st.plane = v;
      MotionRecord r = record(RecordKind::Plane);
      r.ivalue = (int64_t)plane();
      emit(r);
      if (!sinPlaneChanged()) return false;
      break;
    }
    case ModeGroup::Units: st.units = v; break;
    case ModeGroup::SplineStart: st.splineStart = v; break;
    case ModeGroup::SplineEnd: st.splineEnd = v; break;
    case ModeGroup::WearSystem: st.wearSystem = v; break;
    case ModeGroup::Distance: st.distance = v; break;
    case ModeGroup::ArcDistance: st.arcDistance = v; break;
    case ModeGroup::Retract: st.retract = v; break;
    case ModeGroup::FeedMode: {
      st.feedMode = v;
      MotionRecord r = record(RecordKind::FeedMode);
      r.ivalue = v == ModeValue::PerRev ? 1 : v == ModeValue::InverseTime ? 2 : 0;
      emit(r);
      break;
    }
    case ModeGroup::PathMode: {
      st.pathMode = v;
      if (v == ModeValue::Continuous) {
        // G64 P<path tolerance> Q<naive-CAM tolerance>; Q defaults to P (rs274).
        double p = c.has(Word::P) ? c.get(Word::P) : 0, q = c.has(Word::Q) ? c.get(Word::Q) : p;
        if (p < 0 || q < 0) return error("G64 tolerances must not be negative", "bad-number");
        pathTolerance = p * scale();
        naiveTolerance = q * scale();
      }
      emit(pathModeRecord());
      break;
    }
    case ModeGroup::StopOnce:
      // G9 with a chamfer, rounding or cutter compensation would have to stop at a point the
      // executor builds later; refused rather than stopped at the wrong place.
      if (comp.active() || corner.active || corner.requested)
        return error("a one-block exact stop (G9) with cutter compensation or a chamfer/rounding is not supported",
                     "unsupported-code");
      stopOnce = true;
      break;
    default: break;
    }
  }
  return true;
}

bool Executor::Impl::execSetOffset(const MachineCmd &c) {
  auto kind = (SetOffsetKind)c.sub;
  if (kind >= SetOffsetKind::ToolSet) return execToolOffset(c);
  switch (kind) {
  case SetOffsetKind::G92Cancel:  // all axes, or those named (Fanuc G92.1 X0 Y0); G52 too
    if (!frameForbids("G92.1")) return false;
    for (int i = 0; i < kAxes; ++i) {
      if ((c.mask & kAxisMask) && !c.has((Word)i)) continue;
      if (c.has((Word)i) && c.get((Word)i) != 0) return error("G92.1 axis values must be 0", "bad-number");
      g92[i] = g92Saved[i] = pf.local[i] = 0;
    }
    g92On = false;
    pf.update();
    return true;
  case SetOffsetKind::G52:  // rs274: the named axes' G92 offsets (one register for G52 and G92)
    for (int i = 0; i < kAxes; ++i)
      if (c.has((Word)i)) g92[i] = g92Saved[i] = c.get((Word)i) * axisScale(i);
    g92On = true;
    return true;
  case SetOffsetKind::G92Suspend: g92 = {}, g92On = false; return true;
  case SetOffsetKind::G92Restore: g92 = g92Saved, g92On = true; return true;
  case SetOffsetKind::StoreHome1: home[0] = st.position; return true;
  case SetOffsetKind::StoreHome2: home[1] = st.position; return true;
  default: break;
  }
  if (kind == SetOffsetKind::G92) {
    // The current position becomes the programmed one: G92 absorbs the difference, and the
    // local shift (G52) of the named axes (Fanuc; rs274 has no separate one).
    if (!frameForbids("G92")) return false;
    AxisVec f = frameIn(st.position);
    for (int i = 0; i < kAxes; ++i)
      if (c.has((Word)i)) {
        pf.local[i] = 0;
        double before = rotated() ? f[i] : st.position[i] - chainOffset[i] - toolOffset(i);
        g92[i] = before - c.get((Word)i) * axisScale(i);
      }
    g92Saved = g92;
    g92On = true;
    pf.update();
    return true;
  }
  double p = c.get(Word::P);
  int n = p >= 0 && p <= 9 ? (int)p : -1;
  if (!c.has(Word::P) || n < 0 || p != n)
    return error("G10 needs a coordinate system number P0 to P9", "bad-offset-index");
  if (n == 0) n = st.workOffset;
  AxisVec &sys = g5x[n - 1];
  if (kind == SetOffsetKind::G10L2) {
    for (int i = 0; i < kAxes; ++i)
      if (c.has((Word)i)) sys[i] = c.get((Word)i) * axisScale(i);  // the origin in machine coordinates
    if (c.has(Word::R)) g5xRotation[n - 1] = c.get(Word::R);      // the system's XY rotation
    if (n == st.workOffset) applyWorkOffset();  // with any written values of the system (rs274)
    return true;
  }
  if (!frameForbids("G10 L20")) return false;
  // L20: the current position gets program value v in system n; the other axes keep their
  // program position there (under the system's rotation, an X word moves the origin in Y too).
  double rot = g5xRotation[n - 1];
  if (rot == 0) {
    for (int i = 0; i < kAxes; ++i)
      if (c.has((Word)i))
        sys[i] = st.position[i] - g92[i] - pf.local[i] - toolOffset(i) - c.get((Word)i) * axisScale(i);
    if (n == st.workOffset) applyWorkOffset();
    return true;
  }
  AxisVec rel;  // machine position less tool length and the system's origin
  for (int i = 0; i < kAxes; ++i) rel[i] = st.position[i] - toolOffset(i) - sys[i];
  AxisVec q = rel;
  rotateXY(q, -rot);  // program + G92 in system n
  for (int i = 0; i < kAxes; ++i)
    if (c.has((Word)i)) q[i] = c.get((Word)i) * axisScale(i) + g92[i] + pf.local[i];
  rotateXY(q, rot);
  for (int i = 0; i < kAxes; ++i) sys[i] = st.position[i] - toolOffset(i) - q[i];
  if (n == st.workOffset) applyWorkOffset();
  return true;
}

namespace {
// The modal groups a controller may reset at M2/M30 (machine key [controller] reset) and what
// resetting each means. The names are the machine file's (docs/MACHINE.md).
struct ResetGroup {
  const char *name;  // bit i of Impl::resetMask is kResetGroups[i]
  void (*reset)(Executor::Impl &x);
};
using X = Executor::Impl;
const ResetGroup kResetGroups[] = {
    {"motion", [](X &x) { x.st.motion = ModeValue::Linear; }},
    {"plane", [](X &x) { x.st.plane = ModeValue::XY; }},
    {"distance", [](X &x) { x.st.distance = ModeValue::Absolute; }},
    {"feed_mode", [](X &x) { x.st.feedMode = ModeValue::PerMinute; }},
    {"units", [](X &x) { x.st.units = ModeValue::MM; }},
    {"cutter_comp", [](X &x) { x.st.cutterComp = 0; }},
    {"tool_length", [](X &x) { x.toolLength = x.toolOffsetY = 0, x.st.toolLengthH = 0, x.activeEdge = x.activeDl = 0; }},
    {"work_offset", [](X &x) { x.st.workOffset = 1, x.applyWorkOffset(); }},
    {"g92", [](X &x) { x.g92 = {}, x.g92On = false; }},
    {"feed", [](X &x) { x.st.feed = x.feedMM = 0; }},
    {"spindle", [](X &x) { x.st.spindle = 0, x.st.css = false, x.st.speedLimit = 0; }},
    {"coolant", [](X &x) { x.st.flood = x.st.mist = false; }},
    {"path_mode", [](X &x) { x.st.pathMode = ModalState{}.pathMode; }},
    {"rotation", [](X &x) { x.pf.clearRotation(), x.pf.update(); }},
    {"scaling", [](X &x) { x.pf.clearScale(), x.pf.update(); }},
    {"mirror", [](X &x) { x.pf.clearMirror(), x.pf.update(); }},
    {"local_offset", [](X &x) { x.pf.local = {}, x.pf.update(); }},
};
}  // namespace

uint32_t resetGroupMask(const std::vector<std::string> &groups) {
  uint32_t mask = 0;
  for (auto &name : groups)
    for (size_t i = 0; i < std::size(kResetGroups); ++i)
      if (name == kResetGroups[i].name) mask |= 1u << i;
  return mask;
}

bool Executor::Impl::execFrame(const MachineCmd &c) {
  auto slot = (FrameSlot)c.sub;
  bool set = (c.sub2 & 0x0f) == (uint8_t)FrameAction::Set;
  bool combine = c.sub2 & kFrameCombine;
  if (c.sub == kFrameSlotCopy) return execCopyFrame(c, c.sub2 & 0x0f);
  if (c.sub == kFrameSlotTilt) return execTilt(c);
  if (comp.active()) return error("Cannot change the programmable frame with cutter radius comp on", "cutcomp-conflict");
  const AxisVec program = programPosition();
  auto word = [&](int axis, double def) { return c.has((Word)axis) ? c.get((Word)axis) * axisScale(axis) : def; };
  // U V W shift with G52; rotation, scaling and mirroring act on X Y Z only.
  if (slot != FrameSlot::Local && (c.has(Word::U) || c.has(Word::V) || c.has(Word::W)))
    return error("rotation, scaling and mirroring take no U V W words", "frame-invalid");
  switch (slot) {
  case FrameSlot::Local:  // G52: the named axes' shift (G52 X0 Y0 cancels); cancel = all
    if (!pf.onlyTilt() && !frameForbids("G52")) return false;  // under the tilt alone: along its axes
    for (int i = 0; i < kAxes; ++i)
      if (!set || c.has((Word)i)) pf.local[i] = set ? c.get((Word)i) * axisScale(i) : 0;
    break;
  case FrameSlot::Rotation: {
    if (!set) {
      pf.clearRotation();
      break;
    }
    if (!combine && (pf.scaleOn || pf.mirrorOn()))
      return error("G68 together with scaling or mirroring (G51, G51.1) is not supported", "unsupported-code");
    bool axisForm = c.sub2 & kFrameFormAxis;
    const PlaneAxes ax = planeAxes(plane());
    double angle = c.has(Word::R) ? c.get(Word::R) : 0;  // R omitted: SD42150, 0 by default
    Vec3 axis{}, centre{};
    if (axisForm) {  // 3-D: about I J K through X Y Z (absolute, omitted = 0), R absolute
      axis = {c.get(Word::I), c.get(Word::J), c.get(Word::K)};
      if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0)
        return error("G68 rotation vector I0 J0 K0 (808D alarm 12560: value outside the allowed limits)",
                     "frame-invalid");
      for (int i = 0; i < 3; ++i) centre[i] = word(i, 0);
    } else {  // 2-D: about the plane's normal through the plane-axis words (omitted: here)
      if (c.has((Word)ax.n))
        return error(std::string("G68 in the ") + kWordKeys[ax.u] + kWordKeys[ax.v] + " plane takes no " +
                         kWordKeys[ax.n] + " word (a 3-D rotation needs I J K)",
                     "frame-invalid");
      axis[ax.n] = 1;
      centre = {program[0], program[1], program[2]};
      centre[ax.u] = word(ax.u, program[ax.u]);
      centre[ax.v] = word(ax.v, program[ax.v]);
      if (st.distance == ModeValue::Incremental && pf.rotationLevels > 0)  // R relative to what?
        return error("an incremental G68 R while a rotation is active is not supported: cancel it with G69 first",
                     "unsupported-code");
    }
    if (pf.rotationLevels == 2)
      return error("a third G68 rotation (two are active; cancel them with G69)", "frame-invalid");
    // A G68 while one is active is the second level, in the rotated system (808D 2.4.1.10).
    int level = pf.rotationLevels;
    pf.rotation[level] = Affine::rotation(axis, angle, centre);
    pf.rotationLevels = level + 1;
    break;
  }
  case FrameSlot::Scale: {
    if (!set) {
      pf.clearScale();
      break;
    }
    if (!combine && (pf.rotationLevels || pf.mirrorOn()))
      return error("G51 together with a rotation or mirror (G68, G51.1) is not supported", "unsupported-code");
    // A G51 while scaling is on replaces it (the manual's example 2-20 does so).
    Vec3 f{c.has(Word::I) ? c.get(Word::I) : 1, c.has(Word::J) ? c.get(Word::J) : 1,
           c.has(Word::K) ? c.get(Word::K) : 1};
    for (int i = 0; i < 3; ++i)
      if (f[i] == 0 || std::fabs(f[i]) > 1e6) return error("G51 scale factor 0 or out of range", "frame-invalid");
    pf.scaleOn = true;
    pf.scaleFactors = f;
    pf.scaleCentre = {word(0, 0), word(1, 0), word(2, 0)};  // absolute; omitted = workpiece zero
    break;
  }
  case FrameSlot::Mirror: {
    if (!set) {  // G50.1 X Y Z: those axes; no axis word: all
      bool any = c.mask & 7u;
      for (int i = 0; i < 3; ++i)
        if (!any || c.has((Word)i)) pf.mirrorAxes[i] = 0, pf.mirrorAt[i] = 0;
      break;
    }
    if (!combine && (pf.rotationLevels || pf.scaleOn))
      return error("G51.1 together with a rotation or scaling (G68, G51) is not supported", "unsupported-code");
    if (st.distance == ModeValue::Incremental)
      return error("G51.1 mirror positions are absolute: program it in G90", "frame-invalid");
    for (int i = 3; i < kAxes; ++i)
      if (c.has((Word)i)) return error("G51.1 mirrors X, Y and Z only", "frame-invalid");
    if (!(c.mask & 7u)) return error("G51.1 needs the mirror position of an axis (X, Y or Z)", "missing-word");
    for (int i = 0; i < 3; ++i)
      if (c.has((Word)i)) pf.mirrorAxes[i] = 1, pf.mirrorAt[i] = c.get((Word)i) * axisScale(i);
    break;
  }
  default: return error("bad frame slot", "bad-command");
  }
  pf.update();
  return true;
}

bool Executor::Impl::execStop(const MachineCmd &c) {
  switch ((StopKind)c.sub) {
  case StopKind::Program: emit(record(RecordKind::ProgramStop)); break;
  case StopKind::Optional: emit(record(RecordKind::OptionalStop)); break;
  case StopKind::End:
  case StopKind::EndRewind: {
    if (nurbs.open)
      return error("a G5.2 NURBS must be ended with G5.3 before the program ends (rs274 would drop its control points)",
                   "spline-invalid");
    if (sinSpline.open && !sinSplineEnd()) return false;
    cornerFlush("no move follows");
    comp.stop();  // flush the pending compensated move
    compExit = false;
    MotionRecord r = record(RecordKind::ProgramEnd);
    r.ivalue = (StopKind)c.sub == StopKind::EndRewind ? 30 : 2;
    emit(r);
    // What M2/M30 reset: the machine's [controller] reset list (rs274's set by default).
    for (size_t i = 0; i < std::size(kResetGroups); ++i)
      if (resetMask & (1u << i)) kResetGroups[i].reset(*this);
    initialLevelValid = false;
    lastCycle = ModeValue::CycleOff;
    st.ended = true;
    break;
  }
  }
  return true;
}

Executor::Executor(const Machine &machine, MotionSink &sink, Diagnostics &diags)
    : impl_(new Impl(machine, sink, diags)) {
  // Program start: machine zero, whatever offsets the machine description holds, the
  // controller's start-up modes.
  impl_->st.position = {};
  MachineCmd modes;
  modes.kind = CmdKind::Mode;
  const Controller &ctl = machine.controller;
  if (ctl.plane != "G17") modes.modes[modes.nmodes++] = ctl.plane == "G18" ? ModeValue::ZX : ModeValue::YZ;
  for (ModeValue m : ctl.startup)
    if (modes.nmodes < kMaxModes) modes.modes[modes.nmodes++] = m;
  if (modes.nmodes) impl_->execMode(modes);
  impl_->noteFrame("start");  // a machine whose G54 offset is not zero
  impl_->plainState = impl_->plainStateNow();
}

Executor::~Executor() { delete impl_; }

void Executor::setLintRun(bool on) { impl_->lintRun = on; }

uint64_t Executor::blockCount() const { return impl_->blocks; }

const ModalState &Executor::state() const { return impl_->st; }

// A mode without words that is in force does nothing in exec but set the location.
bool Executor::execMode(const MachineCmd *last, uint64_t blocks, const MachineCmd &mode) {
  if (blocks && !execBlocks(*last, blocks)) return false;
  Impl &x = *impl_;
  if (mode.mask != 0 || !x.modeRepeats(mode)) return exec(mode);
  x.loc = mode.loc.valid() ? mode.loc : x.blockLoc;
  return true;
}

// The waiting blocks, a mode in force, then the move: the calls the three commands would make
// to exec, less the mode's when it repeats (its location is replaced by the move's at once).
bool Executor::execMove(const MachineCmd *last, uint64_t blocks, const MachineCmd *mode, const MachineCmd &move) {
  if (blocks && !execBlocks(*last, blocks)) return false;
  if (mode && (mode->mask != 0 || !impl_->modeRepeats(*mode)) && !exec(*mode)) return false;
  return exec(move);
}

// The blocks before `last` only count: a block that follows a block sees no frame change.
bool Executor::execBlocks(const MachineCmd &last, uint64_t count) {
  if (count > 1) {
    impl_->curBlockFrame = false;
    impl_->blocks += count - 1;
  }
  return count == 0 || exec(last);
}

// No motion mode but G0/G1 and nothing in force that reshapes or holds a move (plainState).
bool Executor::Impl::plainStateNow() const {
  if (st.motion != ModeValue::Linear && st.motion != ModeValue::Rapid) return false;
  if (st.motion == ModeValue::Linear && !(feedMM > 0)) return false;  // checkFeed's error
  return !(st.feedMode == ModeValue::InverseTime || st.css || st.ended || pf.linear || rotated() || poly.outside ||
           corner.active || corner.requested || comp.active() || compExit || sinSpline.open || storedCycle.modal ||
           tapOpen || capture.table || route.transform);
}

// Here, not in ExecutorMotion.cpp with plainMove: exec inlines it.
bool Executor::Impl::plainMoveFits(const MachineCmd &c) const {
  const WordMask axes = c.mask & kAxisMask;
  if (c.kind != CmdKind::Move || !axes || axes != c.mask || c.sub || c.sub2 || (c.mask & missingAxes)) return false;
  assert(plainState == plainStateNow());  // a state change that missed its PlainStateRefresh
  if (!plainState || stopOnce) return false;  // G9 ends with its block: checked here
  for (WordMask m = axes; m; m &= m - 1)  // exec's check: a bad number gets its diagnostic there
    if (!std::isfinite(c.w[__builtin_ctzll(m)])) return false;
  return true;
}

bool Executor::exec(const MachineCmd &c) {
  Impl &x = *impl_;
  x.loc = c.loc.valid() ? c.loc : x.blockLoc;
  // The flat path's commands first (issue 6): a block start or a mode without words needs none
  // of the word checks below, a plain G0/G1 skips the general motion machinery.
  if (!c.mask && c.kind == CmdKind::Block) return x.beginBlock(c);
  if (!c.mask && c.kind == CmdKind::Mode && x.modeRepeats(c)) return true;
  if (x.plainMoveFits(c)) {
    x.plainMove(c);
    return true;
  }
  Impl::PlainStateRefresh refresh{x};
  return !c.mask && c.kind == CmdKind::Mode && !x.route.transform ? x.execMode(c) : x.execCommand(c);
}

// Every other command (out of line: the fast paths above stay a small function).
bool Executor::Impl::execCommand(const MachineCmd &c) {
  Impl &x = *this;
  if (x.route.transform && !x.trfMode.inner) return x.transformCommand(c);  // ExecutorTransform.cpp
  if (c.kind == CmdKind::Cycle) return x.execCycle(c);  // its words are parameters, not axes
  // Never let NaN or infinity reach positions: a diagnostic instead.
  for (WordMask m = c.mask; m; m &= m - 1) {  // only the words present (all 64 bits)
    int i = __builtin_ctzll(m);
    if (i < kWords && !std::isfinite(c.w[i]))
      return x.error(std::string("invalid number in ") + kWordKeys[i] + " word", "bad-number");
  }
  bool motion = c.kind == CmdKind::Move || c.kind == CmdKind::Home || c.kind == CmdKind::MachineMove;
  // (The lathe's G10 P X Z R U W C words are tool offsets, not axes.)
  bool axisWords = motion || (c.kind == CmdKind::SetOffset && c.sub != (uint16_t)SetOffsetKind::LatheTool);
  if (axisWords && !x.checkAxisWords(c)) return false;
  if (c.has(Word::PolarR) || c.has(Word::PolarA)) {
    for (Word w : {Word::X, Word::Y})  // rs274's messages
      if (c.has(w))
        return x.error(std::string("Cannot specify both polar coordinate and ") + kWordKeys[(int)w] + " word",
                       "polar-with-xy");
  }
  if (motion && x.st.ended && !x.warnedAfterEnd) {
    x.warnedAfterEnd = true;
    x.warning("motion after the end of the program (M2/M30)", "code-after-end");
  }
  switch (c.kind) {
  case CmdKind::Block: return x.beginBlock(c);
  case CmdKind::Message:
    if (c.sub == (uint8_t)MessageKind::Abort)  // LinuxCNC (ABORT,…): the run stops here
      return x.error(c.text ? c.text : "", "abort");
    if (c.sub == (uint8_t)MessageKind::NotSimulated) {  // a run stops; lint goes on past it
      if (!x.lintRun) return x.error(c.text ? c.text : "", "not-simulated");
      x.diags.note(x.loc, std::string(c.text ? c.text : "") + ": ncc run stops here", "not-simulated");
      return true;
    }
    if (c.sub == (uint8_t)MessageKind::Print) {  // LinuxCNC (PRINT,…): to stderr, not the trace
      std::fprintf(stderr, "%s\n", c.text ? c.text : "");
      return true;
    }
    [[fallthrough]];
  case CmdKind::Comment: {
    MotionRecord r = x.record(c.kind == CmdKind::Comment ? RecordKind::Comment : RecordKind::Message);
    if (c.text) r.text = c.text;
    x.emit(r);
    return true;
  }
  case CmdKind::Mode: return x.execMode(c);
  case CmdKind::Feed: {
    double f = c.get(Word::F);
    if (f < 0) return x.error("Negative feed rate", "bad-feed");
    x.st.feed = f;
    x.feedInBlock = true;
    x.feedMM = x.st.feedMode == ModeValue::InverseTime ? f : f * x.scale();
    if (x.st.feedMode == ModeValue::InverseTime) return true;  // a rate record per move instead
    MotionRecord r = x.record(RecordKind::FeedRate);
    r.value = x.feedMM;
    x.emit(r);
    return true;
  }
  case CmdKind::Speed: return x.execSpeed(c);
  case CmdKind::ToolSelect: {
    double t = c.get(Word::T);
    if (!x.checkTool(t, "T")) return false;
    x.st.toolSelected = (int)t;
    MotionRecord r = x.record(RecordKind::ToolSelect);
    r.ivalue = (int64_t)t;
    x.emit(r);
    return true;
  }
  case CmdKind::ToolChange: {
    if (c.has(Word::Q)) return x.setToolNumber(c.get(Word::Q));
    x.st.toolInSpindle = x.st.toolSelected;
    x.st.spindle = 0;  // the change stops the spindle
    MotionRecord r = x.record(RecordKind::ToolChange);
    r.ivalue = x.st.toolInSpindle;
    x.emit(r);
    return true;
  }
  case CmdKind::Spindle: {
    static const RecordKind kinds[] = {RecordKind::SpindleStop, RecordKind::SpindleCW, RecordKind::SpindleCCW};
    if (c.sub == 3)  // without an angle: the machine's M19 position (808D SD43240)
      return x.orientSpindle(c.has(Word::R) ? c.get(Word::R) : x.machine.controller.m19Angle, c.sub2,
                             c.has(Word::Q) ? c.get(Word::Q) : 0);
    if (c.sub > 2) return x.error("bad spindle command", "bad-command");
    x.st.spindle = c.sub;
    x.spindlePositioned = false;  // back to speed control
    x.emit(x.record(kinds[c.sub]));
    return true;
  }
  case CmdKind::Coolant: {
    // rs274 order: mist before flood (M9 prints MIST_OFF then FLOOD_OFF).
    if (c.sub2 & 2) {
      x.st.mist = c.sub & 2;
      MotionRecord r = x.record(RecordKind::CoolantMist);
      r.ivalue = x.st.mist;
      x.emit(r);
    }
    if (c.sub2 & 1) {
      x.st.flood = c.sub & 1;
      MotionRecord r = x.record(RecordKind::CoolantFlood);
      r.ivalue = x.st.flood;
      x.emit(r);
    }
    return true;
  }
  case CmdKind::Dwell: {
    double p = c.get(Word::P);
    if (p < 0) return x.error("Dwell time must not be negative", "bad-dwell");
    if (x.tapOpen)  // the trace's RIGID_TAP is one record down and back: nothing fits between
      return x.error("a dwell between G331 and G332 is not supported (the tap is one record down and back)",
                     "unsupported-code");
    MotionRecord r = x.record(RecordKind::Dwell);
    r.value = p;
    x.emit(r);  // with compensation on it waits for the pending move
    return true;
  }
  case CmdKind::Move:
    if (x.capture.table) x.sinTableNote();  // a contour table notes each move's modes
    return x.execMove(c) && x.modalCycleAfterMove(c);
  case CmdKind::Home: x.curBlockFrame = true; return x.execHome(c);
  case CmdKind::Contour: return x.execContour(c);
  case CmdKind::MachineMove: return x.execMachineMove(c);
  case CmdKind::ToolLength: return x.execToolLength(c);
  case CmdKind::CutterComp: return x.execCutterComp(c);
  case CmdKind::Frame: {
    // FrameSlot order; set, cancel (ISO names: the only dialect with frame ops so far).
    static const char *kSlots[][2] = {{"G52", "G52"}, {"G68", "G69"}, {"G51", "G50"}, {"G51.1", "G50.1"},
                                      {"G72.x copy", "G72.x end"}};
    if (!x.execFrame(c)) return false;
    x.curBlockFrame = true;
    x.noteFrame(c.sub < 5 ? kSlots[c.sub][(c.sub2 & 0x0f) == (uint8_t)FrameAction::Cancel ? 1 : 0] : "frame");
    return true;
  }
  case CmdKind::WorkOffset: {
    if (c.sub == 0) {  // Sinumerik G500: no settable frame; the stored base frames become active
      x.activateBaseFrames();
      x.selectNoSettableFrame();
      x.curBlockFrame = true;
      x.noteFrame("G500");
      return true;
    }
    if (c.sub < 1 || c.sub > (x.machine.dialect == "sinumerik" ? x.settableFrames() - 1 : Machine::kWorkOffsets)) {
      if (x.machine.dialect != "sinumerik") return x.error("bad work offset number", "bad-offset-index");
      return x.error(fmt::format("{}: the machine has {} settable frames, G500 … {} (settable_frames, MD28080)",
                                 workOffsetCode(c.sub, OffsetCodes::Sinumerik), x.settableFrames(),
                                 workOffsetCode(x.settableFrames() - 1, OffsetCodes::Sinumerik)),
                     "bad-offset-index");
    }
    x.activateBaseFrames();  // Sinumerik G54…: the stored base frames too (manual L12337-L12345)
    // The ISO manuals forbid it under G68/G51/G51.1; Sinumerik frames are independent members of
    // one chain (a settable frame under the programmable one), so G54… under $P_PFRAME is fine.
    if (c.sub != x.st.workOffset && x.machine.dialect != "sinumerik" && !x.frameForbids("changing the work offset"))
      return false;
    // LinuxCNC re-reads the tables only when the system changes; Sinumerik on every G54….
    bool apply = c.sub != x.st.workOffset || x.offsetWrite != OffsetWrite::OnChange;
    x.st.workOffset = c.sub;
    if (apply) x.applyWorkOffset();
    else x.updateChain();
    x.curBlockFrame = true;
    // ISO slots 7..9 keep LinuxCNC's names: both G59.1 and the 808D's G54 P1 select them.
    x.noteFrame(workOffsetCode(c.sub, x.machine.dialect == "sinumerik" ? OffsetCodes::Sinumerik
                                      : c.sub <= 9                     ? OffsetCodes::LinuxCnc
                                                                       : OffsetCodes::Iso808)
                    .c_str());
    return true;
  }
  case CmdKind::SetOffset: {
    static const char *kKinds[] = {"G92", "G92.1", "G10 L2", "G10 L20", "G92.2", "G92.3", "G28.1", "G30.1", "G52"};
    if (!x.execSetOffset(c)) return false;
    x.curBlockFrame = true;
    x.noteFrame(c.sub < 9 ? kKinds[c.sub] : "offset");
    return true;
  }
  case CmdKind::Stop:
    if (!x.execStop(c)) return false;
    if (x.st.ended) x.noteFrame("reset");
    return true;
  case CmdKind::Aux: {
    MotionRecord r = x.record(RecordKind::Aux);
    double p = c.get(Word::P);
    if (std::fabs(p) > 1e15) return x.error("aux code out of range", "bad-number");
    if (p != std::trunc(p)) return x.error("aux code must be an integer", "bad-number");
    if (c.has(Word::E)) return x.ioCode((int)p, c);  // LinuxCNC M62-M68: a channel
    r.ivalue = (int64_t)p;
    r.text = std::string(1, c.sub ? (char)c.sub : 'M');
    x.emit(r);
    return true;
  }
  default: return x.error("unknown machine command", "bad-command");
  }
}

// LinuxCNC M62-M65 (digital) and M67/M68 (analog outputs): records the canonical trace prints as
// rs274 does; M66 L0 reads an input at once, which changes nothing ncc models (its result #5399
// is not provided). rs274 rounds the channel number.
bool Executor::Impl::ioCode(int code, const MachineCmd &c) {
  double channel = std::floor(c.get(Word::E) + 0.5);
  if (!(channel >= 0 && channel < 1e9))
    return error(fmt::format("M{} needs a non-negative {} number", code, code == 66 ? "input" : "output"), "bad-number");
  if (code == 66) return true;
  MotionRecord r = record(code <= 65 ? RecordKind::DigitalOutput : RecordKind::AnalogOutput);
  r.ivalue = (int64_t)channel;
  r.value = code <= 65 ? (code % 2 == 0 ? 1.0 : 0.0) : c.get(Word::Q);
  r.value2 = code == 62 || code == 63 || code == 67 ? 1 : 0;  // synchronized with the next move
  emit(r);
  return true;
}

bool Executor::saveModal() {
  impl_->savedModal.push_back({impl_->st, impl_->pathTolerance, impl_->naiveTolerance, impl_->pf, impl_->pfValue});
  return true;
}

// The groups that differ, as one mode command: the executor's own handling (checks, records)
// applies, and nothing is recorded when nothing changed. Sinumerik restores the modal G
// functions only (the F value stays as the subprogram left it); the work offset group (G54…)
// is one of them, and the programmable frame comes back as Siemens does by default (a TRANS in
// a SAVE subprogram ends with it; the machine data that changes this is not modelled).
bool Executor::restoreModal(SourceLoc loc) {
  if (impl_->savedModal.empty()) return true;
  Impl &x = *impl_;
  Impl::PlainStateRefresh refresh{x};
  const Impl::SavedModal &s = x.savedModal.back();
  x.loc = loc;
  if (!x.pf.sameTransform(s.pf.composite, s.pf.local)) {
    if (x.comp.active())
      return x.error("the return from a SAVE subprogram restores the programmable frame: not with cutter radius "
                     "comp on",
                     "cutcomp-conflict");
    x.pf = s.pf, x.pfValue = s.pfValue;
    x.noteFrame("SAVE");
  }
  if (s.st.workOffset != x.st.workOffset) {  // as a G54… would: the table's values now
    x.st.workOffset = s.st.workOffset;
    x.applyWorkOffset();
    x.noteFrame("SAVE");
  }
  return restoreModes(loc);
}

bool Executor::restoreModes(SourceLoc loc) {
  Impl::SavedModal s = impl_->savedModal.back();
  impl_->savedModal.pop_back();
  const ModalState &now = impl_->st;
  MachineCmd c;
  c.kind = CmdKind::Mode;
  c.loc = loc;
  const ModeValue saved[] = {s.st.motion, s.st.plane, s.st.units, s.st.distance, s.st.arcDistance, s.st.feedMode,
                             s.st.retract, s.st.pathMode};
  const ModeValue cur[] = {now.motion, now.plane, now.units, now.distance, now.arcDistance, now.feedMode,
                           now.retract, now.pathMode};
  for (unsigned i = 0; i < 8 && c.nmodes < kMaxModes; ++i)
    if (saved[i] != cur[i] || (i == 7 && (s.pathTolerance != impl_->pathTolerance ||
                                          s.naiveTolerance != impl_->naiveTolerance)))
      c.modes[c.nmodes++] = saved[i];
  if (s.st.pathMode == ModeValue::Continuous) {  // G64 P Q in the restored program units
    double unit = s.st.units == ModeValue::Inch ? 25.4 : 1.0;
    c.set(Word::P, s.pathTolerance / unit);
    c.set(Word::Q, s.naiveTolerance / unit);
  }
  return !c.nmodes || exec(c);
}

bool Executor::finish(bool ranToEnd) {
  Impl &x = *impl_;
  Impl::PlainStateRefresh refresh{x};
  if (ranToEnd && x.sinSpline.open && !x.sinSplineEnd()) return false;
  if (ranToEnd) x.cornerFlush("no move follows");
  x.comp.stop();
  if (x.capture.active) {  // its records never reached the sinks
    x.route.capture = nullptr;
    x.diags.error(x.capture.loc, "the program ended inside the contour of this cycle", "contour-invalid");
    return false;
  }
  // A run stopped by an error did not reach its end: no warning about how it ends.
  if (ranToEnd && !x.st.ended) x.diags.warning(x.blockLoc, "program ends without M2 or M30", "missing-program-end");
  if (ranToEnd) x.probeResultsUnused();
  return true;
}

}  // namespace ncc
