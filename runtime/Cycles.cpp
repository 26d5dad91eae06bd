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

// Collects the steps of one hole at (a1, a2) in the plane.
class HoleWriter {
public:
  HoleWriter(std::vector<CycleStep> &out, const DrillAxes &ax, double a1, double a2)
      : out_(out), ax_(ax), a1_(a1), a2_(a2) {}
  void rapid(double level) { move(CycleStepKind::Rapid, level); }
  void feed(double level) { move(CycleStepKind::Feed, level); }
  void dwell(double s) {
    CycleStep st;
    st.kind = CycleStepKind::Dwell;
    st.seconds = s;
    out_.push_back(st);
  }
  void spindle(CycleStepKind k) {
    CycleStep st;
    st.kind = k;
    out_.push_back(st);
  }

private:
  void move(CycleStepKind k, double level) {
    CycleStep st;
    st.kind = k;
    st.pos[ax_.a1] = a1_;
    st.pos[ax_.a2] = a2_;
    st.pos[ax_.d] = level;
    out_.push_back(st);
  }
  std::vector<CycleStep> &out_;
  const DrillAxes &ax_;
  double a1_, a2_;
};

CycleStepKind spindleStep(int dir) {
  return dir == 2 ? CycleStepKind::SpindleCCW : CycleStepKind::SpindleCW;
}

// Pecking infeed shared by G83 (back to R between pecks, then down to just above the previous
// depth) and G73 (a short chip-breaking retract only).
void pecks(HoleWriter &h, const CycleInput &in, double r, double bottom, bool toR) {
  for (double depth = r - in.q; depth > bottom; depth -= in.q) {
    h.feed(depth);
    if (toR) h.rapid(r);
    h.rapid(depth + in.peckClearance);
  }
  h.feed(bottom);
}

// The motion at one hole after reaching the R level.
void holeBody(HoleWriter &h, const CycleInput &in, double r, double bottom, double clear) {
  switch (in.cycle) {
  case ModeValue::Drill:
    h.feed(bottom);
    h.rapid(clear);
    break;
  case ModeValue::DrillDwell:
    h.feed(bottom);
    h.dwell(in.p);
    h.rapid(clear);
    break;
  case ModeValue::Peck:
  case ModeValue::PeckChipBreak:
    pecks(h, in, r, bottom, in.cycle == ModeValue::Peck);
    h.rapid(clear);
    break;
  case ModeValue::Tap:
  case ModeValue::TapLeft: {
    // Reverse at the bottom, feed straight out to the clear level, restore the direction.
    bool right = in.cycle == ModeValue::Tap;
    h.feed(bottom);
    h.spindle(CycleStepKind::SpindleStop);
    h.spindle(right ? CycleStepKind::SpindleCCW : CycleStepKind::SpindleCW);
    h.dwell(in.p);
    h.feed(clear);
    h.spindle(CycleStepKind::SpindleStop);
    h.spindle(right ? CycleStepKind::SpindleCW : CycleStepKind::SpindleCCW);
    break;
  }
  case ModeValue::BoreFeed:
    h.feed(bottom);
    h.feed(r);
    h.rapid(clear);
    break;
  case ModeValue::BoreStop:
    h.feed(bottom);
    h.dwell(in.p);
    h.spindle(CycleStepKind::SpindleStop);
    h.rapid(clear);
    h.spindle(spindleStep(in.spindle));
    break;
  case ModeValue::BoreDwell:
    h.feed(bottom);
    h.dwell(in.p);
    h.feed(clear);
    break;
  default:
    break;
  }
}

}  // namespace

const char *cycleCodeName(ModeValue cycle) {
  for (auto &c : kCycles)
    if (c.mode == cycle) return c.code;
  return "G80";
}

bool expandCycle(const CycleInput &in, std::vector<CycleStep> &out, std::string &err) {
  const DrillAxes &ax = kDrillAxes[(int)in.plane];
  if (in.cycle == ModeValue::BoreBack || in.cycle == ModeValue::BoreFine || !isCycleMotion(in.cycle)) {
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
  if (r < bottom) {
    err = std::string("R less than z in cycle in ") + ax.name + " plane";
    return false;
  }
  bool peck = in.cycle == ModeValue::Peck || in.cycle == ModeValue::PeckChipBreak;
  if (peck) {
    if (!(in.q > 0)) {
      err = "Negative or zero q value used";
      return false;
    }
    // A peck count the machine could never finish is a typo; refuse instead of looping.
    if ((r - bottom) / in.q > 1e6) {
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
    HoleWriter h(out, ax, a1, a2);
    h.rapid(level);
    if (level != r) h.rapid(r);
    holeBody(h, in, r, bottom, clear);
    level = clear;
  }
  return true;
}

}  // namespace ncc
