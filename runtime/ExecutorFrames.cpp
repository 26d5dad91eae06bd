// FRAME-valued system variables (ir/SystemVars.h: `_pframe`, `_iframe`, `_actframe`,
// `_uifr[n]`): the executor's frame chain read and written as FRAME values (ir/FrameValue.h),
// so a Sinumerik program's $P_PFRAME = CTRANS(…) : CROT(…) lands on the same slots as ISO
// G52/G68/G51. Frame lengths are in the program's unit at the time of the read or write (inch
// under G70/G20); rotary axes in degrees.
//
// What maps exactly:
//  - the programmable frame: any frame of X Y Z (rotation, scale, mirror, offsets) and offsets
//    of A B C; it replaces every programmable slot (G52 G68 G51 G51.1);
//  - a settable frame (a work offset system) and the active one: offsets and a rotation about Z,
//    which is what a work offset holds (G10 L2 R).
//  - the Sinumerik base frames ($P_CHBFR[n] stored, $P_CHBFRAME[n] active, the NCU-global
//    $P_NCBFR[n] / $P_NCBFRAME[n], the masks choosing the total base frame $P_ACTBFRAME) and the
//    system frames $P_PARTFRAME $P_SETFRAME $P_EXTFRAME (outside the base frames) and
//    $P_TOOLFRAME $P_WPFRAME $P_TRAFRAME (between the settable and the programmable frame):
//    offsets (coarse and fine) and a rotation about Z, folded with the active settable frame into
//    the work offset and XY rotation the motion applies (updateChain);
//  - $P_ISO1FRAME … $P_ISO4FRAME, $P_GFRAME, $P_CYCFRAME (frames of functions ncc does not have):
//    the identity, and only the identity can be written.
// Anything else (a settable or base frame with another rotation, a scale or a mirror, fine offsets
// in a settable frame, a scaled or mirrored rotary axis, a rotation in an NCU-global frame) is an
// error, never an approximation.
#include "runtime/ExecutorImpl.h"
#include "ir/Value.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

namespace {
// The frame x_parent = t + m · x_child of X Y Z with rotary offsets `rot` (mm and degrees), in
// program units.
FrameValue frameOf(const double m[3][3], const Vec3 &t, const double *rot, double unit) {
  FrameValue f;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) f.L[i][j] = m[i][j];
    f.coarse[i] = t[i] / unit;
    f.coarse[3 + i] = rot ? rot[i] : 0;
  }
  return f;
}

// A work offset system's frame: its offsets and its rotation about Z.
FrameValue workOffsetFrame(const AxisVec &offset, double rotation, double unit) {
  double R[3][3];
  frameRotation(0, 0, rotation, R);
  return frameOf(R, {offset[0], offset[1], offset[2]}, &offset[3], unit);
}

bool rotaryPlain(const FrameValue &f, std::string &err, const char *what) {
  for (int i = 0; i < 3; ++i)
    if (f.rotary[i] != 1) {
      err = fmt::format("{}: scaling or mirroring the rotary axis {} is not supported", what, frameAxisName(3 + i));
      return false;
    }
  return true;
}

// The rotation about Z (degrees) of a frame whose matrix is one; false with `err` otherwise.
bool zRotation(const FrameValue &f, double &rotation, std::string &err, const char *what, const char *kind) {
  if (!rotaryPlain(f, err, what)) return false;
  rotation = std::atan2(f.L[1][0], f.L[0][0]) * 180 / M_PI;
  double R[3][3];
  frameRotation(0, 0, rotation, R);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(R[i][j] - f.L[i][j]) > 1e-12) {
        err = fmt::format("{}: {} holds offsets and a rotation about Z only (a work offset); this one "
                          "rotates about X or Y, scales or mirrors",
                          what, kind);
        return false;
      }
  if (std::fabs(rotation) < 1e-12) rotation = 0;
  return true;
}

// The offsets and Z rotation of a frame that a work offset can hold; false with `err` otherwise.
bool asWorkOffset(const FrameValue &f, double unit, AxisVec &offset, double &rotation, std::string &err,
                  const char *what) {
  for (int i = 0; i < kFrameAxes; ++i)
    if (f.fine[i] != 0) {
      err = fmt::format("{}: fine offsets (FI, CFINE) of a settable frame are not supported", what);
      return false;
    }
  if (!zRotation(f, rotation, err, what, "a settable frame")) return false;
  for (int i = 0; i < kFrameAxes; ++i) offset[i] = f.coarse[i] * (i < 3 ? unit : 1.0);
  return true;
}

// A frame's lengths (X Y Z offsets) times k: program units <-> mm.
FrameValue scaledFrame(FrameValue f, double k) {
  for (int i = 0; i < 3; ++i) f.coarse[i] *= k, f.fine[i] *= k;
  return f;
}

// A link of the chain as the motion applies it: offsets, then a rotation about Z (mm, degrees).
struct ZLink {
  AxisVec o{};
  double rot = 0;
};
ZLink zLink(const FrameValue &f) {
  ZLink z;
  for (int i = 0; i < kFrameAxes; ++i) z.o[i] = f.offset(i);
  z.rot = std::atan2(f.L[1][0], f.L[0][0]) * 180 / M_PI;
  if (std::fabs(z.rot) < 1e-12) z.rot = 0;
  return z;
}
// outer : inner, which is again offsets and a rotation about Z.
ZLink chainLinks(const ZLink &outer, const ZLink &inner) {
  ZLink z = outer;
  double r = outer.rot * M_PI / 180, c = std::cos(r), s = std::sin(r);
  for (int i = 0; i < kAxes; ++i) z.o[i] += inner.o[i];
  if (outer.rot != 0) {
    z.o[0] = outer.o[0] + inner.o[0] * c - inner.o[1] * s;
    z.o[1] = outer.o[1] + inner.o[0] * s + inner.o[1] * c;
  }
  z.rot = outer.rot + inner.rot;
  return z;
}

// The system frames by variable, in the manual's chain order; the slot in Impl::systemFrames, or -1
// for the frames ncc keeps as the identity.
struct SystemFrameInfo {
  SysVar var;
  int slot;
};
constexpr SystemFrameInfo kSystemFrameInfo[] = {
    {SysVar::PartFrame, Executor::Impl::PartFrame}, {SysVar::SetFrame, Executor::Impl::SetFrame},
    {SysVar::ExtFrame, Executor::Impl::ExtFrame},   {SysVar::Iso1Frame, -1},
    {SysVar::Iso2Frame, -1},                        {SysVar::Iso3Frame, -1},
    {SysVar::GFrame, -1},                           {SysVar::ToolFrame, Executor::Impl::ToolFrame},
    {SysVar::WpFrame, Executor::Impl::WpFrame},     {SysVar::TraFrame, Executor::Impl::TraFrame},
    {SysVar::Iso4Frame, -1},                        {SysVar::CycFrame, -1},
};
const SystemFrameInfo *systemFrameInfo(SysVar v) {
  for (auto &i : kSystemFrameInfo)
    if (i.var == v) return &i;
  return nullptr;
}
bool baseFamily(SysFamily f) { return f >= SysFamily::ChBfr && f <= SysFamily::NcBframe; }
bool ncuFamily(SysFamily f) { return f == SysFamily::NcBfr || f == SysFamily::NcBframe; }
}  // namespace

void Executor::Impl::startFrames() {
  const Controller &c = machine.controller;
  for (int i = 0; i < c.baseFrames; ++i) base.chStored[i] = workOffsetFrame(machine.chanBaseFrames[i], 0, 1);
  for (int i = 0; i < c.ncBaseFrames; ++i) base.ncStored[i] = workOffsetFrame(machine.ncBaseFrames[i], 0, 1);
  base.chMask = base.ncMask = c.baseFrameMask;
  // MD20110: bit 0 keeps the frames over a reset, bit 14 the base frame, bit 5 the settable one.
  bool keep = c.resetModeMask & 1;
  if (keep && (c.resetModeMask & (1 << 14))) activateBaseFrames();
  applyWorkOffset();
  if (machine.dialect == "sinumerik" && !(keep && (c.resetModeMask & (1 << 5)))) selectNoSettableFrame();
}

void Executor::Impl::selectNoSettableFrame() {
  g5xActive = {}, g5xRotActive = 0;
  settableFrameWritten = noSettableFrame = true;
  updateChain();
}

FrameValue Executor::Impl::totalBaseFrame() const {
  FrameValue t;
  const Controller &c = machine.controller;
  for (int i = 0; i < c.ncBaseFrames; ++i)
    if (base.ncMask >> i & 1) t = frameChain(t, base.ncActive[i]);
  for (int i = 0; i < c.baseFrames; ++i)
    if (base.chMask >> i & 1) t = frameChain(t, base.chActive[i]);
  return t;
}

// Work offset and rotation of outside : settable : inside. A chain of identities leaves the
// settable frame's values exactly as they are.
void Executor::Impl::updateChain() {
  ZLink z;
  auto add = [&](const FrameValue &f) {
    if (!f.identity()) z = chainLinks(z, zLink(f));
  };
  for (int s : {PartFrame, SetFrame, ExtFrame}) add(systemFrames[s]);
  add(totalBaseFrame());
  z = z.rot == 0 && z.o == AxisVec{} ? ZLink{g5xActive, g5xRotActive} : chainLinks(z, ZLink{g5xActive, g5xRotActive});
  for (int s : {ToolFrame, WpFrame, TraFrame}) add(systemFrames[s]);
  chainOffset = z.o, chainRot = z.rot;
}

bool Executor::Impl::writeBaseMask(SysVar v, double value, std::string &err) {
  if (!(value >= 0 && value <= 255 && value == std::floor(value))) {
    err = fmt::format("system variable '${}': {} is not a mask of base frames 0..7 (0..255)", sysVarName(v), numberText(value));
    return false;
  }
  (v == SysVar::ChBfrMask ? base.chMask : base.ncMask) = (int)value;
  updateChain();
  noteFrame(v == SysVar::ChBfrMask ? "$P_CHBFRMASK" : "$P_NCBFRMASK");
  return true;
}

FrameValue Executor::Impl::programmableFrame() const {
  if (pfValue.set && pf.sameTransform(pfValue.composite, pfValue.local))
    return pfValue.frame;  // as written (with its coarse/fine split)
  return frameOf(pf.composite.m, pf.composite.t, &pf.local[3], scale());
}

bool Executor::readFrame(const SysRef &ref, FrameValue &out, std::string &err) const {
  const Impl &x = *impl_;
  double u = x.scale();
  SysVarInfo info = sysVarInfo(ref.var);
  if (info.family == SysFamily::UserFrame) {
    if (!x.haveSettableFrame(ref, err)) return false;
    out = info.system == 0 ? FrameValue{} : workOffsetFrame(x.g5x[info.system - 1], x.g5xRotation[info.system - 1], u);
    return true;
  }
  if (baseFamily(info.family)) {
    const FrameValue *f = x.baseFrame(ref, err);
    if (!f) return false;
    out = scaledFrame(*f, 1 / u);
    return true;
  }
  if (const SystemFrameInfo *s = systemFrameInfo(ref.var)) {
    out = s->slot < 0 ? FrameValue{} : scaledFrame(x.systemFrames[s->slot], 1 / u);
    return true;
  }
  switch (ref.var) {
  case SysVar::PFrame: out = x.programmableFrame(); return true;
  case SysVar::IFrame: out = workOffsetFrame(x.g5xActive, x.g5xRotActive, u); return true;
  case SysVar::ActBFrame: out = scaledFrame(x.totalBaseFrame(), 1 / u); return true;
  case SysVar::ActFrame: {  // the manual's chain, G92 before the programmable frame (the tool is not part of it)
    FrameValue g92, t;
    for (int i = 0; i < kFrameAxes; ++i) g92.coarse[i] = x.g92[i] / (i < 3 ? u : 1.0);
    for (int s : {Impl::PartFrame, Impl::SetFrame, Impl::ExtFrame}) t = frameChain(t, x.systemFrames[s]);
    t = frameChain(scaledFrame(frameChain(t, x.totalBaseFrame()), 1 / u), workOffsetFrame(x.g5xActive, x.g5xRotActive, u));
    for (int s : {Impl::ToolFrame, Impl::WpFrame, Impl::TraFrame}) t = frameChain(t, scaledFrame(x.systemFrames[s], 1 / u));
    out = frameChain(t, frameChain(g92, x.programmableFrame()));
    return true;
  }
  default: err = fmt::format("system variable '${}' is not a frame", sysRefText(ref)); return false;
  }
}

bool Executor::writeFrame(const SysRef &ref, const FrameValue &f, SourceLoc loc, std::string &err) {
  Impl &x = *impl_;
  Impl::PlainStateRefresh refresh{x};
  x.loc = loc;
  double u = x.scale();
  std::string what = "$" + sysRefText(ref);
  SysVarInfo info = sysVarInfo(ref.var);
  if (!sysVarWritable(ref.var)) {
    err = fmt::format("system variable '{}' is read-only", what);
    return false;
  }
  if (baseFamily(info.family) || systemFrameInfo(ref.var)) return x.writeChainFrame(ref, f, u, what, err);
  if (ref.var == SysVar::PFrame) {
    if (x.comp.active()) {
      err = "cannot change the programmable frame with cutter radius comp on";
      return false;
    }
    if (!rotaryPlain(f, err, what.c_str())) return false;
    ProgrammableFrame &pf = x.pf;
    pf.clearMirror(), pf.clearScale(), pf.clearRotation();
    // The matrix in the rotation slot, the offsets in the local shift.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) pf.rotation[0].m[i][j] = f.L[i][j];
    pf.rotationLevels = pf.rotation[0].linearIdentity() ? 0 : 1;
    for (int i = 0; i < kFrameAxes; ++i) pf.local[i] = f.offset(i) * (i < 3 ? u : 1.0);
    pf.update();
    x.pfValue = {true, f, pf.composite, pf.local};
    x.noteFrame("$P_PFRAME");
    return true;
  }
  AxisVec offset{};
  double rotation = 0;
  if (!asWorkOffset(f, u, offset, rotation, err, what.c_str())) return false;
  if (ref.var == SysVar::IFrame) {  // the active settable frame: now, the table unchanged
    x.g5xActive = offset, x.g5xRotActive = rotation;
    x.settableFrameWritten = true;
    x.updateChain();
    x.noteFrame("$P_IFRAME");
    return true;
  }
  if (!x.haveSettableFrame(ref, err)) return false;
  if (info.system == 0) {
    err = fmt::format("system variable '{}': settable frame 0 (G500) is the zero frame in ncc", what);
    return false;
  }
  x.g5x[info.system - 1] = offset, x.g5xRotation[info.system - 1] = rotation;
  // As a written work offset: the active system changes now only where the controller says.
  if (info.system == x.st.workOffset && x.offsetWrite == OffsetWrite::Immediate) {
    x.applyWorkOffset();
    x.noteFrame("offset write");
  }
  return true;
}

// $P_UIFR[n] of a settable frame the machine has; false with the manual's alarm otherwise.
bool Executor::Impl::haveSettableFrame(const SysRef &ref, std::string &err) const {
  int n = sysVarInfo(ref.var).system;
  if (n < settableFrames()) return true;
  err = fmt::format("system variable '${}': frame: instruction not permitted: the machine has {} settable frames "
                    "$P_UIFR[0…{}] (settable_frames, MD28080)",
                    sysRefText(ref), settableFrames(), settableFrames() - 1);
  return false;
}

// $P_CHBFR[n] … $P_NCBFRAME[n]: the frame, or null with `err` for a base frame the machine
// does not have (the manual's alarm "Frame: instruction not permitted").
const FrameValue *Executor::Impl::baseFrame(const SysRef &ref, std::string &err) const {
  SysVarInfo info = sysVarInfo(ref.var);
  bool ncu = ncuFamily(info.family);
  int count = ncu ? machine.controller.ncBaseFrames : machine.controller.baseFrames;
  if (info.system >= count) {
    err = fmt::format("system variable '${}': frame: instruction not permitted: the machine has {} {} base frame{} ({})",
                      sysRefText(ref), count, ncu ? "NCU-global" : "channel", count == 1 ? "" : "s",
                      ncu ? "nc_base_frames" : "base_frames");
    return nullptr;
  }
  auto &list = info.family == SysFamily::ChBfr    ? base.chStored
               : info.family == SysFamily::ChBframe ? base.chActive
               : info.family == SysFamily::NcBfr    ? base.ncStored
                                                    : base.ncActive;
  return &list[info.system];
}

// A base frame or a system frame: offsets and a rotation about Z (none in an NCU-global one).
// The active ones act at once; the stored ones at the next G500, G54….
bool Executor::Impl::writeChainFrame(const SysRef &ref, const FrameValue &f, double u, const std::string &what,
                                     std::string &err) {
  SysVarInfo info = sysVarInfo(ref.var);
  const SystemFrameInfo *s = systemFrameInfo(ref.var);
  if (s && s->slot < 0) {
    if (f.identity()) return true;
    err = fmt::format("system variable '{}': the system frame of a function ncc does not have (ISO dialect, grinding, "
                      "cycles) is the identity; ncc does not model another one",
                      what);
    return false;
  }
  double rotation = 0;
  if (!zRotation(f, rotation, err, what.c_str(), s ? "a system frame" : "a base frame")) return false;
  if (ncuFamily(info.family) && rotation != 0) {  // alarm 18310, manual L13154-L13207
    err = fmt::format("system variable '{}': frame: rotation not allowed (an NCU-global frame has no geometric coupling "
                      "between the axes)",
                      what);
    return false;
  }
  FrameValue *target = s ? &systemFrames[s->slot] : const_cast<FrameValue *>(baseFrame(ref, err));
  if (!target) return false;
  *target = scaledFrame(f, u);
  if (info.family == SysFamily::ChBfr || info.family == SysFamily::NcBfr) return true;  // stored: at G500, G54…
  updateChain();
  noteFrame(what.c_str());
  return true;
}

}  // namespace ncc
