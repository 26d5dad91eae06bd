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
// Anything else (a settable frame with another rotation, a scale or a mirror, fine offsets in a
// settable frame, a scaled or mirrored rotary axis) is an error, never an approximation.
#include "runtime/ExecutorImpl.h"

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

// The offsets and Z rotation of a frame that a work offset can hold; false with `err` otherwise.
bool asWorkOffset(const FrameValue &f, double unit, AxisVec &offset, double &rotation, std::string &err,
                  const char *what) {
  if (!rotaryPlain(f, err, what)) return false;
  for (int i = 0; i < kFrameAxes; ++i)
    if (f.fine[i] != 0) {
      err = fmt::format("{}: fine offsets (FI, CFINE) of a settable frame are not supported", what);
      return false;
    }
  rotation = std::atan2(f.L[1][0], f.L[0][0]) * 180 / M_PI;
  double R[3][3];
  frameRotation(0, 0, rotation, R);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(R[i][j] - f.L[i][j]) > 1e-12) {
        err = fmt::format("{}: a settable frame holds offsets and a rotation about Z only (a work offset); this one "
                          "rotates about X or Y, scales or mirrors",
                          what);
        return false;
      }
  if (std::fabs(rotation) < 1e-12) rotation = 0;
  for (int i = 0; i < kFrameAxes; ++i) offset[i] = f.coarse[i] * (i < 3 ? unit : 1.0);
  return true;
}
}  // namespace

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
    out = info.system == 0 ? FrameValue{} : workOffsetFrame(x.g5x[info.system - 1], x.g5xRotation[info.system - 1], u);
    return true;
  }
  switch (ref.var) {
  case SysVar::PFrame: out = x.programmableFrame(); return true;
  case SysVar::IFrame: out = workOffsetFrame(x.g5xActive, x.g5xRotActive, u); return true;
  case SysVar::ActFrame: {  // settable : G92 : programmable (the tool is not part of it)
    FrameValue g92;
    for (int i = 0; i < kFrameAxes; ++i) g92.coarse[i] = x.g92[i] / (i < 3 ? u : 1.0);
    out = frameChain(workOffsetFrame(x.g5xActive, x.g5xRotActive, u), frameChain(g92, x.programmableFrame()));
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
    x.noteFrame("$P_IFRAME");
    return true;
  }
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

}  // namespace ncc
