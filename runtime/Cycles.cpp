#include "runtime/Cycles.h"
#include "runtime/Geometry.h"

#include <algorithm>

namespace ncc {

namespace {

// Plane axis indices: first and second plane axis, drilling axis.
struct DrillAxes {
  int a1, a2, d;
  const char *name;  // as rs274 names the plane in its messages
};
constexpr DrillAxes kDrillAxes[] = {{0, 1, 2, "xy"}, {2, 0, 1, "xz"}, {1, 2, 0, "yz"}};

struct CycleInfo {
  ModeValue mode;
  const char *code;
};
constexpr CycleInfo kCycles[] = {
    {ModeValue::Drill, "G81"},     {ModeValue::DrillDwell, "G82"},    {ModeValue::Peck, "G83"},
    {ModeValue::PeckChipBreak, "G73"}, {ModeValue::Tap, "G84"},       {ModeValue::TapLeft, "G74"},
    {ModeValue::BoreFeed, "G85"},  {ModeValue::BoreStop, "G86"},      {ModeValue::BoreDwell, "G89"},
    {ModeValue::BoreBack, "G87"},  {ModeValue::BoreFine, "G76"},
};

// The move off the wall of G76/G87: Q along the plane axis the lift setting names (808D _ZSFI[5]:
// 1 +a1, 0 or 2 -a1, 3 +a2, 4 -a2).
void liftShift(const CycleInput &in, double out[3]) {
  static const int kAxis[] = {0, 0, 0, 1, 1};
  static const double kSign[] = {-1, 1, -1, 1, -1};
  int l = in.lift >= 0 && in.lift <= 4 ? in.lift : 0;
  out[0] = out[1] = out[2] = 0;
  out[kAxis[l]] = kSign[l] * in.q;
}

// The hole of an ISO cycle (rs274's expansion): pecks from R by Q (G83 back to R and down to
// `peckClearance` above the last depth, G73 back by peckClearance), dwell P, the exit.
HoleSpec isoHole(const CycleInput &in, double r, double bottom, double clear) {
  HoleSpec h;
  h.start = r, h.bottom = bottom, h.retract = clear;
  h.spindle = in.spindle;
  switch (in.cycle) {
  case ModeValue::DrillDwell: h.dwellBottom = in.p; break;
  case ModeValue::Peck:
  case ModeValue::PeckChipBreak:
    h.peck = in.q;
    h.breaksPerRetract = in.cycle == ModeValue::Peck ? 0 : -1;
    h.chipBreak = h.reentry = in.peckClearance;
    if (in.cycle == ModeValue::PeckChipBreak && in.chipBreak >= 0) h.chipBreak = in.chipBreak;
    break;
  case ModeValue::Tap:
  case ModeValue::TapLeft:
    h.exit = HoleExit::Tap;
    h.dwellBottom = in.p;
    if (in.tapOutToR) h.tapOutToStart = true, h.dwellStart = in.p;
    h.spindle = in.cycle == ModeValue::Tap ? 1 : 2;
    if (in.tapPecks) {
      // The tap stays in its thread: every move in the hole is at the feed, reversed out.
      h.peck = in.q;
      h.breaksPerRetract = in.tapPecks == 2 ? -1 : 0;
      h.chipBreak = h.reentry = in.tapBack;
      h.chipBreakRapid = false;
      h.fullRetractFeed = 0;
    }
    break;
  case ModeValue::BoreFeed: h.exit = HoleExit::Feed, h.exitLevel = r; break;
  case ModeValue::BoreStop: h.exit = HoleExit::SpindleStopRapid, h.dwellBottom = in.p; break;
  case ModeValue::BoreDwell: h.exit = HoleExit::Feed, h.exitLevel = clear, h.exitRapid = false, h.dwellBottom = in.p; break;
  case ModeValue::BoreFine:
    h.exit = HoleExit::OrientShift, h.dwellBottom = in.p, h.orientAngle = in.orientAngle, h.exitLevel = clear;
    liftShift(in, h.shift);
    break;
  default: break;
  }
  return h;
}

// G87: from the initial level, off centre down through the hole to R (the back face), cut up to Z.
bool backBore(const CycleInput &in, const DrillAxes &ax, double r, double top, std::vector<CycleStep> &out,
              std::string &err) {
  const double il = in.initialLevel;
  if (in.retractToR) return err = "G87 back boring returns to the initial level: G99 is not allowed", false;
  if (!(r < top) || !(top < il))
    return err = "G87 needs R (the back face) below Z (the cut's top) below the initial level", false;
  BackBoreSpec b;
  b.start = il, b.bottom = r, b.cutLevel = top;
  b.dwell = in.p > 0 ? in.p : -1;
  b.orientAngle = in.orientAngle;
  b.spindle = in.spindle;
  liftShift(in, b.shift);
  double a1 = in.current[ax.a1], a2 = in.current[ax.a2];
  for (int k = 0; k < in.repeats; ++k) {
    if (in.incremental) a1 += in.target[ax.a1], a2 += in.target[ax.a2];
    else a1 = in.target[ax.a1], a2 = in.target[ax.a2];
    CycleStep st;
    st.pos[ax.a1] = a1, st.pos[ax.a2] = a2, st.pos[ax.d] = std::max(il, in.current[ax.d]);
    out.push_back(st);
    if (st.pos[ax.d] != il) {
      st.pos[ax.d] = il;
      out.push_back(st);
    }
    backBoreSteps(b, ax.a1, ax.a2, ax.d, a1, a2, out);
  }
  return true;
}

}  // namespace

const char *cycleCodeName(ModeValue cycle) {
  for (auto &c : kCycles)
    if (c.mode == cycle) return c.code;
  return "G80";
}

bool expandCycle(const CycleInput &in, std::vector<CycleStep> &out, std::string &err) {
  const DrillAxes &ax = kDrillAxes[(int)in.plane];
  const bool boring = in.cycle == ModeValue::BoreBack || in.cycle == ModeValue::BoreFine;
  if (!isCycleMotion(in.cycle)) {
    err = std::string(cycleCodeName(in.cycle)) + " canned cycle is not supported";
    return false;
  }
  if (in.repeats < 1) {
    err = in.repeats == 0 ? "Cannot do zero repeats of cycle" : "Cannot do negative repeats of cycle";
    return false;
  }
  const double il = in.initialLevel;
  const double r = in.incremental ? il + in.r : in.r;
  const double bottom = in.incremental ? r + in.z : in.z;
  if (boring && in.q < 0) {
    err = std::string("Q (the shift off the wall) must not be negative in ") + cycleCodeName(in.cycle);
    return false;
  }
  if (in.cycle == ModeValue::BoreBack) {
    if (in.polar) return err = "polar hole positions with G87 are not supported", false;
    return backBore(in, ax, r, bottom, out, err);
  }
  if (r < bottom) {
    err = std::string("R less than z in cycle in ") + ax.name + " plane";
    return false;
  }
  bool peck = in.cycle == ModeValue::Peck || in.cycle == ModeValue::PeckChipBreak || in.tapPecks;
  if (peck) {
    if (!(in.q > 0)) {
      err = "Negative or zero q value used";
      return false;
    }
    // A peck count the machine could never finish is a typo; refuse instead of looping.
    if ((r - bottom) / in.q > kMaxPecks) {
      err = "Peck depth Q too small for the hole depth";
      return false;
    }
  }

  std::array<double, 3> pos = in.current;
  if (il < r) {
    // Below the R level: go up to it at the current position first.
    CycleStep st;
    st.kind = CycleStepKind::Rapid;
    st.pos = pos;
    st.pos[ax.d] = r;
    st.preMove = true;
    out.push_back(st);
    pos[ax.d] = r;
  }
  const double clear = in.retractToR ? r : std::max(il, r);
  double level = std::max(pos[ax.d], in.sameCycle ? clear : r);  // height of the move to the hole
  double a1 = in.incremental || in.polar ? in.current[ax.a1] : in.target[ax.a1];
  double a2 = in.incremental || in.polar ? in.current[ax.a2] : in.target[ax.a2];
  for (int k = 0; k < in.repeats; ++k) {
    if (in.polar) {
      double x = a1 - in.origin[0], y = a2 - in.origin[1];
      polarStep(x, y, in.incremental, in.polarHasR, in.polarR, in.polarHasA, in.polarA);
      a1 = x + in.origin[0];
      a2 = y + in.origin[1];
    } else if (in.incremental) {
      a1 += in.target[ax.a1];
      a2 += in.target[ax.a2];
    }
    auto rapid = [&](double z) {
      CycleStep st;
      st.pos[ax.a1] = a1, st.pos[ax.a2] = a2, st.pos[ax.d] = z;
      out.push_back(st);
    };
    rapid(level);
    if (level != r) rapid(r);
    holeSteps(isoHole(in, r, bottom, clear), ax.a1, ax.a2, ax.d, a1, a2, out);
    level = clear;
  }
  return true;
}

}  // namespace ncc
