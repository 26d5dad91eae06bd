// Spindle speed: S, and constant surface speed (CSS: ISO G96/G97, LinuxCNC G96 D S / G97) with
// its spindle-speed limit (808D/Fanuc lathe G50 S in system A, G92 S in B; LinuxCNC G96 D).
//
// Under CSS the S value is a surface speed (m/min, ft/min in inch) and the spindle turns at
// rpm = 1000 S / (2 pi r), r the tool's distance from the spindle axis: machine X minus the
// program's X zero (work offset, G92, G52 and the tool's X offset, as LinuxCNC's css origin),
// capped by the limit and the machine's max_spindle_speed. Records: SpindleMode (mode, limit,
// origin) then SpindleSpeed (m/min under CSS). A feed per revolution then varies along a move
// that changes X: the move's feed is its mean path speed, so the planner's times are right.
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"

#include <cmath>
#include <limits>

namespace ncc {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kCssPieces = 64;  // midpoint rule over a move: 1/rpm is linear in X between kinks
}  // namespace

void Executor::Impl::spindleModeRecord(int mode) {
  MotionRecord r = record(RecordKind::SpindleMode);
  r.ivalue = mode;
  r.value = st.speedLimit;
  r.value2 = cssOriginNoted = cssOrigin();
  emit(r);
}

// CmdKind::Speed: sub 0 S only, 1 G97 (rpm), 2 G96 (CSS); w[D] the limit (0 clears it); sub2 what
// a G97 without S does after CSS: 0 keep the speed reached (808D manual: "the last speed G96
// reached"), 1 an error (LinuxCNC keeps adjusting the speed until the next S or M3/M4).
bool Executor::Impl::execSpeed(const MachineCmd &c) {
  bool hasS = c.has(Word::S);
  double s = c.get(Word::S);
  if (hasS && s < 0) return error("Negative spindle speed", "bad-speed");
  if (c.has(Word::D) && !(c.get(Word::D) >= 0)) return error("the spindle-speed limit must not be negative", "bad-speed");
  if (c.sub == 2 && !hasS) return error("S word missing with G96 (the surface speed)", "missing-word");
  const bool wasCss = st.css;
  if (c.sub == 1 && !hasS && wasCss && st.spindle != 0) {
    if (c.sub2 == 1)
      return error("G97 without S after G96: LinuxCNC keeps adjusting the spindle speed until the next S or M3/M4; "
                   "program G97 S<rpm>", "unsupported-code");
    s = cssRpm(st.position[0]);  // the speed reached at the current position
    if (!std::isfinite(s))
      return error("G97 without S at the spindle axis: the speed G96 reached there is unbounded (no G50 S, G92 S, "
                   "G96 D or max_spindle_speed)", "bad-speed");
    hasS = true;
  }
  if (c.has(Word::D)) st.speedLimit = c.get(Word::D);
  if (c.sub) st.css = c.sub == 2;
  if (c.sub || c.has(Word::D)) spindleModeRecord(st.css ? 1 : 0);
  if (!hasS) return true;
  st.speed = s;
  MotionRecord r = record(RecordKind::SpindleSpeed);
  r.value = s;
  if (st.css && c.sub != 1) {
    st.surface = s * (st.units == ModeValue::Inch ? 0.3048 : 1.0);  // ft/min -> m/min
    r.value = st.surface;
  }
  emit(r);
  return true;
}

double Executor::Impl::cssRpm(double machineX) const {
  double limit = kInf;
  if (st.speedLimit > 0) limit = st.speedLimit;
  if (machine.maxSpindleSpeed > 0) limit = std::min(limit, machine.maxSpindleSpeed);
  double r = std::fabs(machineX - cssOrigin());
  double rpm = r > 0 ? st.surface * 1000 / (2 * M_PI * r) : kInf;
  return std::min(rpm, limit);
}

double Executor::Impl::cssFeed(const MotionRecord &r) const {
  ArcGeometry g;
  double len = 0;
  if (r.kind == RecordKind::Arc) {
    g = arcGeometry(r);
    len = g.length;
  } else {
    len = linearLength(r.start, r.end);
  }
  // At the spindle axis without any limit the speed has no bound: so has the feed there.
  if (!std::isfinite(cssRpm(r.start[0])) || !std::isfinite(cssRpm(r.end[0]))) return NAN;
  if (!(len > 0)) return feedMM * cssRpm(r.end[0]);
  double time = 0;  // minutes per mm of feed per rev: sum of ds / rpm
  for (int i = 0; i < kCssPieces; ++i) {
    double t = (i + 0.5) / kCssPieces;
    double x = r.kind == RecordKind::Arc ? arcPoint(g, r.start, r.end, t)[0] : r.start[0] + (r.end[0] - r.start[0]) * t;
    time += len / kCssPieces / cssRpm(x);
  }
  return time > 0 ? len / time * feedMM : 0;
}

bool Executor::Impl::cssBeforeMove(const MotionRecord &r) {
  if (!st.css) return true;
  if (std::isnan(r.feed))
    return error("feed per revolution at the spindle axis (X0) under G96 without a spindle-speed limit: the speed "
                 "has no bound there (program G50 S / G92 S or G96 D, or set the machine's max_spindle_speed)",
                 "bad-speed");
  if (linearFrame())
    return error("constant surface speed (G96) under a rotation, scaling or mirror is not supported", "unsupported-code");
  if (cssOrigin() != cssOriginNoted) spindleModeRecord(2);  // the program's X zero moved
  return true;
}

}  // namespace ncc
