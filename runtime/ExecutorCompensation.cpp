// Executor: tool length compensation (G43/G44/G49 and their forms) and cutter radius
// compensation on and off (G40/G41/G42) as modal commands; the offset path itself is the
// CutterComp of runtime/CutterComp.*, the Sinumerik edges are in ExecutorSinTool.cpp.
#include "runtime/ExecutorImpl.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

bool Executor::Impl::execToolLength(const MachineCmd &c) {
  if ((ToolLengthForm)c.sub != ToolLengthForm::Table) return offsetToolLength(c, (ToolLengthForm)c.sub);
  ToolData t;
  int h;
  // Sinumerik D<n>: edge n of the tool in the spindle, DL its additive set. `h=0 D=1` is the edge
  // of a tool change: D1 or the tool's only edge, none (as H0) when the spindle is empty.
  const bool changeEdge = c.has(Word::D) && c.has(Word::H);
  if (c.has(Word::D) && !(changeEdge && st.toolInSpindle == 0)) {
    const int d = changeEdge ? offsetEdge(st.toolInSpindle) : (int)c.get(Word::D);
    if (machine.controller.lathe() && comp.active() && d != activeEdge)
      return error("a tool offset change with tool nose radius compensation on is not supported: cancel it with G40 first",
                   "cutcomp-conflict");
    return selectSinEdge(d, c.has(Word::AddOffset) ? c.get(Word::AddOffset) : machine.controller.dlDefault);
  } else if (c.has(Word::AddOffset)) {  // Sinumerik DL=n alone: another set of the active edge
    return selectSinDl(c.get(Word::AddOffset));
  } else {
    // Without H (rs274 G43): the tool in the spindle.
    double hv = c.has(Word::H) ? c.get(Word::H) : st.toolInSpindle;
    if (!offsetData(hv, "H", t)) return false;
    h = (int)hv;
    activeEdge = activeDl = 0;
    toolOffsetY = 0;
  }
  if (machine.controller.lathe() && comp.active() && h != st.toolLengthH)
    return error("a tool offset change with tool nose radius compensation on is not supported: cancel it with G40 first",
                 "cutcomp-conflict");
  toolLength = t.length;
  // A lathe's offset (T0101) also shifts X by the edge's X offset.
  toolOffsetX = h == 0 || !machine.controller.lathe() ? 0 : t.xOffset;
  st.toolLengthH = h;
  MotionRecord r = record(RecordKind::ToolLength);
  r.value = toolLength;
  r.value2 = toolOffsetX;
  r.ivalue = h;
  emit(r);
  if (isoLathe() && st.cutterComp != 0 && !comp.active() && t.radius > 0) return noseCompAfterT();
  return true;
}

bool Executor::Impl::execCutterComp(const MachineCmd &c) {
  if (capture.active && capture.sl) {  // an SL sub-contour: RL/RR say pocket or island (ExecutorRegion.cpp)
    if (c.sub != 0 && capture.side != 0 && c.sub != capture.side)
      return error("an SL sub-contour must keep one side (RL or RR)", "contour-invalid");
    if (c.sub != 0) capture.side = c.sub;
    return true;
  }
  if (corner.active && (comp.active() || c.sub != 0))  // its first move was programmed on the old path
    return error("a chamfer or rounding just before G40, G41 or G42 is not supported", "unsupported-code");
  if (c.sub == 0) {  // G40: the pending move ends normal to its end point; the next one exits
    if (comp.active()) {
      if (!comp.stop(true)) return error(comp.error(), comp.rule());
      compExit = true;
    }
    st.cutterComp = 0;
    return true;
  }
  const bool lathe = isoLathe();
  const bool toolDefault = (c.sub2 & 0x0f) == 1;  // d_default=tool
  const bool normalEntry = lathe || (c.sub2 >> 4) == 1;  // entry=normal (Heidenhain, 808D lathes)
  bool sideSwitch = false;  // the 808D lathe's G41 <-> G42 without G40
  if (st.cutterComp != 0) {
    if (!lathe) return error("Cannot turn cutter radius comp on when on", "cutcomp-already-on");
    if (c.sub == st.cutterComp) return true;  // modal: already on that side
    // The last move on the old side ends normal to its end point; the next starts anew from there.
    sideSwitch = comp.active();
    if (sideSwitch && !comp.stop(true)) return error(comp.error(), comp.rule());
  }
  int side = c.sub;
  ToolData t;
  compEdge = 0;
  if (c.has(Word::R)) {  // rs274 G41.1/G42.1: the block's D diameter and L orientation, no table
    if (!dynamicCompData(c, side, t)) return false;
  } else if (!compToolData(c, lathe, toolDefault, t)) {
    return false;
  }
  double radius = t.radius;
  // Compensation works on the machine path, in the active plane: a mirrored frame swaps the
  // sides (G41 <-> G42, as the 808D manual's table 2-12 says); a frame that tilts the plane is
  // not supported.
  if (radius > 0 && plane() == Plane::YZ && machine.controller.family == "linuxcnc")  // rs274's limit
    return error("Cutter radius compensation allowed only in XY, XZ planes", "cutcomp-plane");
  bool flip = false;
  if (radius > 0 && !frameKeepsPlane(plane(), flip))
    return error("cutter radius compensation under a rotation that tilts its plane is not supported",
                 "unsupported-code");
  compOut.plane = plane();
  compOut.shift = {};
  // rs274 numbers the orientation its own way: G41.1's L always, a tool table's on its machines.
  const bool rs274Tip = c.has(Word::R) || machine.controller.family == "linuxcnc";
  if (radius > 0 && (machine.controller.lathe() || rs274Tip) && !noseTipShift(t, radius, side, rs274Tip)) return false;
  const AxisVec from = sideSwitch ? comp.toolPosition() : compOut.toComp(st.position);
  capture.compOn |= capture.active;
  st.cutterComp = side;
  compExit = false;
  if (radius > 0) comp.start((side == 1) != flip ? 1 : -1, radius, from, normalEntry);
  return true;
}

// G41/G42's tool data: the D word's offset, the T word's on a lathe, the spindle tool's (rs274
// without D) or the active Sinumerik edge's.
bool Executor::Impl::compToolData(const MachineCmd &c, bool lathe, bool toolDefault, ToolData &t) {
  if (lathe && !c.has(Word::D)) cutterD = st.toolLengthH;  // the offset of the T word (T0202: 2)
  else if (c.has(Word::D)) {
    double d = c.get(Word::D);
    if (d < 0 || d != std::floor(d) || d > 1e9)
      return error(std::string(c.sub == 1 ? "G41" : "G42") + " requires D word to be a whole number", "unknown-tool");
    cutterD = (int)d;
  } else if (toolDefault) {
    cutterD = st.toolInSpindle;  // rs274: without D, the radius of the tool in the spindle
  }
  if (!c.has(Word::D) && cutterD == 0)
    warning(lathe ? "tool nose radius compensation without a tool offset (T<tool><offset>): radius 0"
            : toolDefault ? "cutter compensation without a D word and no tool in the spindle: radius 0"
                        : "cutter compensation without a D word: radius 0",
            "cutcomp-without-d");
  if (!offsetData(cutterD, "D", t)) return false;
  if (activeEdge > 0 && toolDefault && !c.has(Word::D)) {  // Sinumerik: the active edge's radius
    compEdge = activeEdge;
    t = edgeData(st.toolInSpindle, compEdge);
    if (!sinRadius(st.toolInSpindle, compEdge, t.radius)) return false;
  }
  return true;
}

// rs274's G41.1/G42.1: radius D/2 in program units (a negative one swaps the side, as rs274
// does), orientation L (0 without it) in rs274's numbering, which only G18 may give 1-8.
bool Executor::Impl::dynamicCompData(const MachineCmd &c, int &side, ToolData &t) {
  const char *code = c.sub == 1 ? "G41.1" : "G42.1";
  t = ToolData{};
  t.radius = c.get(Word::R) * scale();
  if (t.radius < 0) t.radius = -t.radius, side = 3 - side;
  if (c.has(Word::L)) {
    const double o = c.get(Word::L);
    if (std::fabs(o - std::nearbyint(o)) > 1e-4 || std::fabs(o) > 1e9)
      return error(fmt::format("{} needs an integer orientation L", code), "bad-number");
    t.tip = (int)std::nearbyint(o);
    if (plane() != Plane::ZX && t.tip != 0 && t.tip != 9)
      return error(fmt::format("{} with L word, but plane is not G18", code), "cutcomp-plane");
  }
  cutterD = 0;
  return true;
}

}  // namespace ncc
