// The kinematic transformations in the executor (runtime/Transmit.h, docs/PIPELINE.md
// "Kinematic transformations"): the library entries trf.TRANSMIT, trf.TRACYL and trf.TRAFOOF
// select and end one; while one is active every command passes transformCommand, which checks
// what the manuals forbid, turns the ISO programs' rotary-axis word into the surface coordinate
// and runs it. Positions are then BCS (Cartesian) positions; the TransformSink between the
// executor and the sinks writes machine axes.
#include "runtime/ExecutorImpl.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {

// The machine's [transform] data (docs/MACHINE.md "[transform]").
int rotaryAxisOf(const Machine &m) {
  std::string a = m.get("transform", "rotary_axis", "C");
  return a == "A" ? 3 : a == "B" ? 4 : 5;
}

std::string axisLetter(int i) { return std::string(1, kAxisLetters[i]); }

}  // namespace

bool Executor::Impl::execTransform(const CycleDef &def, const CycleArgs &args, CycleAction action) {
  const std::string name = def.name + 4;  // TRANSMIT TRACYL TRAFOOF
  const bool iso = args.get("ISO") != 0;
  if (action != CycleAction::Run) return error(name + " is not a machining cycle (it cannot be stored or called)", "cycle-invalid");
  // The manual's conditions at selection and deselection (808D L16129-L16160, ISO L1484-1515).
  const char *what = name == "TRAFOOF" ? (iso ? "switching the transformation off" : "TRAFOOF") : nullptr;
  std::string code = iso ? (name == "TRANSMIT" ? "G12.1" : name == "TRACYL" ? "G07.1" : trfMode.name) : name;
  if (!what) what = code.c_str();
  if (capture.active) return error(fmt::format("{} inside the contour of a cycle is not supported", what), "unsupported-code");
  if (comp.active() || compExit)
    return error(fmt::format("{} needs cutter radius compensation off (G40 and a move after it)", what), "cutcomp-conflict");
  if (corner.active || corner.requested || sinSpline.open || nurbs.open)
    return error(fmt::format("{} must not follow a chamfer, rounding or an open spline sequence", what), "transform");
  // The manual switches the programmable frame off at selection and TRAFOOF (L16148, L16188):
  // ncc does not (the frame stays in the Cartesian system), so one that is active is an error.
  bool frame = pf.linear;
  for (double v : pf.local) frame = frame || v != 0;
  if (frame && (name != "TRAFOOF" || route.transform))
    return error(fmt::format("{} with a programmable frame active (TRANS, ROT, SCALE, MIRROR, G52, G68, G51): the "
                             "control would switch it off, ncc does not; cancel it before",
                             what),
                 "transform");
  if (name == "TRAFOOF") return transformOff();

  const int rot = rotaryAxisOf(machine);
  const AxisLimits &ax = machine.axes[rot];
  if (!ax.present || !ax.rotary || !machine.axes[0].present || !machine.axes[2].present || machine.kinematics != "xyz")
    return error(fmt::format("{} needs a mill-turn machine: linear X and Z and a rotary {} axis on the spindle "
                             "(machine '{}' has {}; docs/MACHINE.md \"[transform]\")",
                             what, axisLetter(rot), machine.name,
                             machine.kinematics != "xyz" ? "a rotary head or table chain"
                             : !ax.present               ? fmt::format("no {} axis", axisLetter(rot))
                             : !ax.rotary                ? fmt::format("a linear {} axis", axisLetter(rot))
                                                         : "no X or Z axis"),
                 "transform");
  if (args.has("AXIS") && (int)args.get("AXIS") != rot)
    return error(fmt::format("{}: the machine's transformation turns {} ([transform] rotary_axis), not {}", what,
                             axisLetter(rot), axisLetter((int)args.get("AXIS"))),
                 "transform");
  if (args.has("N") && args.get("N") != 1 && args.get("N") != 2)
    return error(fmt::format("{}: data block {} does not exist (1 or 2)", what, args.get("N")), "bad-number");
  if (st.css) return error(fmt::format("{} with constant surface speed (G96) is not simulated", what), "unsupported-code");
  if (machine.axes[1].present && st.position[1] != 0)
    return error(fmt::format("{} needs the machine's Y axis at 0 (it is at {})", what, st.position[1]), "transform");
  TransformSetup s;
  s.rotary = rot;
  s.tolerance = std::stod(machine.get("transform", "tolerance", "0.001"));
  if (name == "TRACYL") {
    s.kind = TransformKind::Cylinder;
    if (!args.has("D") || !(args.get("D") > 0))
      return error(fmt::format("{} needs the cylinder's {} (greater than 0)", what, iso ? "radius" : "reference diameter"),
                   "bad-number");
    s.radius = args.get("D") * scale() / 2;
    if (args.has("K") && args.get("K") != 0)
      return error("TRACYL with groove-wall offset (k = 1, transformation type 514 or 513 with OFFN) is not simulated",
                   "unsupported-code");
  } else {
    s.kind = TransformKind::Face;
  }
  // Selecting one deselects the active one (L15461).
  if (route.transform && !transformOff()) return false;
  trfMode.iso = iso;
  trfMode.name = iso ? (s.kind == TransformKind::Face ? "G12.1" : "G07.1") : (s.kind == TransformKind::Face ? "TRANSMIT" : "TRACYL");
  trfMode.missingAxes = missingAxes;
  missingAxes &= ~wordBit(Word::Y);  // the BCS Y is the virtual (face) or peripheral (cylinder) axis
  st.position = trf.begin(s, st.position);
  route.transform = &trf;
  trf.failed = false;
  if (iso) {  // the transformation's plane until it ends: X-C on the face, Z-C on the cylinder
    trfMode.plane = st.plane;
    MachineCmd m;
    m.kind = CmdKind::Mode;
    m.loc = loc;
    m.modes[m.nmodes++] = s.kind == TransformKind::Face ? ModeValue::XY : ModeValue::YZ;
    if (!execMode(m)) return false;
  }
  return true;
}

bool Executor::Impl::transformOff() {
  if (!route.transform) return true;  // TRAFOOF with none active: nothing to do
  route.transform = nullptr;
  st.position = trf.machinePosition();
  missingAxes = trfMode.missingAxes;
  if (trfMode.iso && st.plane != trfMode.plane) {
    MachineCmd m;
    m.kind = CmdKind::Mode;
    m.loc = loc;
    m.modes[m.nmodes++] = trfMode.plane;
    if (!execMode(m)) return false;
  }
  return true;
}

bool Executor::Impl::transformCommand(const MachineCmd &c) {
  const TransformSetup &s = trf.setup();
  const char *name = trfMode.name;
  const Word rotWord = (Word)s.rotary;
  switch (c.kind) {
  case CmdKind::Home:
  case CmdKind::MachineMove:
    return error(fmt::format("{} is not allowed while {} is active (switch it off first)",
                             c.kind == CmdKind::Home ? "a reference point return" : "a move in machine coordinates", name),
                 "transform");
  case CmdKind::Cycle: {
    unsigned e = c.sub & 0xff;
    const auto &lib = cycleLibrary();
    if (e && e <= lib.size() && isTransformEntry(lib[e - 1])) break;
    return error(fmt::format("library cycles are not simulated while {} is active", name), "unsupported-code");
  }
  case CmdKind::Mode:
    if (trfMode.iso)
      for (int i = 0; i < c.nmodes; ++i)
        if (modeValueInfo(c.modes[i]).group == ModeGroup::Plane && c.modes[i] != st.plane)
          return error(fmt::format("a plane selection (G17-G19) is not allowed while {} is active", name), "transform");
    break;
  case CmdKind::Frame:
  case CmdKind::WorkOffset:
  case CmdKind::SetOffset:
    // The ISO manual (L5636-5650): mirror, scaling, rotation and the work offsets before G07.1.
    if (trfMode.iso)
      return error(fmt::format("{} is not allowed while {} is active: program it before", 
                               c.kind == CmdKind::Frame ? "a frame (G51, G51.1, G68, G52)" : "a work offset change", name),
                   "transform");
    break;
  default: break;
  }
  MachineCmd m = c;
  if (c.kind == CmdKind::Move) {
    if (c.has(rotWord) && !trfMode.iso)
      return error(fmt::format("{} is the rotary axis of the active {}: program X, Y and Z", axisLetter(s.rotary), name),
                   "transform");
    if (c.has(rotWord)) {  // ISO: the rotary axis word is the surface coordinate Y
      if (c.has(Word::Y)) return error(fmt::format("Y and {} in one block under {}", axisLetter(s.rotary), name), "transform");
      double v = c.get(rotWord);
      // G07.1: C in degrees on the cylinder of the programmed radius; G12.1: C a length.
      if (s.kind == TransformKind::Cylinder) v = v / 180 * M_PI * s.radius / scale();
      m.mask &= ~wordBit(rotWord);
      m.w[(int)rotWord] = 0;
      m.set(Word::Y, v);
      const uint16_t rb = (uint16_t)wordBit(rotWord), yb = (uint16_t)wordBit(Word::Y);
      if (m.sub & rb) m.sub = (uint16_t)((m.sub & ~rb) | yb);
      if (m.sub2 & rb) m.sub2 = (uint16_t)((m.sub2 & ~rb) | yb);
    }
    if (trfMode.iso && s.kind == TransformKind::Cylinder) {
      if (c.has(Word::I) || c.has(Word::J) || c.has(Word::K))
        return error("an arc under G07.1 is programmed with its radius R, not with I J K", "transform");
      if (st.motion == ModeValue::Rapid && (m.has(Word::Y) || m.has(Word::Z)))
        return error("G00 under G07.1 moves only axes outside the cylinder plane: Z and C need G01", "transform");
    }
  }
  trfMode.inner = true;
  bool ok = execCommand(m);
  trfMode.inner = false;
  if (trf.failed) return false;
  if (ok && st.css) return error(fmt::format("constant surface speed (G96) is not simulated while {} is active", name), "unsupported-code");
  // M2/M30 end the transformation (a reset: 808D L1414, L1468).
  if (ok && c.kind == CmdKind::Stop && st.ended) return transformOff();
  return ok;
}

}  // namespace ncc
