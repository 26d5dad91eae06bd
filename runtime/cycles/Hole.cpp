#include "runtime/cycles/Hole.h"

#include <algorithm>
#include <cmath>

namespace ncc {

namespace {
class Writer {
public:
  Writer(std::vector<CycleStep> &out, int a1, int a2, int d, double p1, double p2)
      : out_(out), a1_(a1), a2_(a2), d_(d), p1_(p1), p2_(p2) {}
  void rapid(double level) { at(level, nullptr); }
  void feed(double level, double f) { at(level, nullptr, CycleStepKind::Feed, f); }
  void go(double level, bool rapidMove, double f) { rapidMove ? rapid(level) : feed(level, f); }
  void dwell(double s) {
    if (s < 0) return;
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
  // A tap's spindle stops and turns the other way (`reversed`) or back the tapping way.
  void tapTurn(int tapDir, bool reversed) {
    spindle(CycleStepKind::SpindleStop);
    spindleOn((tapDir == 2) != reversed ? 2 : 1);
  }
  void spindleOn(int dir) { spindle(dir == 2 ? CycleStepKind::SpindleCCW : CycleStepKind::SpindleCW); }
  void orient(double angle) {
    CycleStep st;
    st.kind = CycleStepKind::SpindleOrient;
    st.angle = angle;
    out_.push_back(st);
  }
  // A move to `level` at `shift` from the hole centre (nullptr: at the centre).
  void at(double level, const double *shift, CycleStepKind k = CycleStepKind::Rapid, double f = 0) {
    CycleStep st;
    st.kind = k;
    st.pos[a1_] = p1_ + (shift ? shift[0] : 0);
    st.pos[a2_] = p2_ + (shift ? shift[1] : 0);
    st.pos[d_] = level;
    st.feed = f;
    out_.push_back(st);
  }
  // Off the wall at `from` (when the shift moves in the plane), rapid to `to` there, back to the centre.
  void liftOut(double from, double to, const double shift[3], double f = 0) {
    const bool inPlane = shift[0] != 0 || shift[1] != 0;
    if (inPlane) at(from, shift);
    at(to, shift, f > 0 ? CycleStepKind::Feed : CycleStepKind::Rapid, f);
    if (inPlane) at(to, nullptr);
  }

private:
  std::vector<CycleStep> &out_;
  int a1_, a2_, d_;
  double p1_, p2_;
};
}  // namespace

void holeSteps(const HoleSpec &h, int a1, int a2, int d, double p1, double p2, std::vector<CycleStep> &out) {
  Writer w(out, a1, a2, d, p1, p2);
  const double dir = h.bottom < h.start ? -1.0 : 1.0;
  auto above = [&](double level) { return dir < 0 ? level > h.bottom : level < h.bottom; };
  bool first = true;
  const bool tap = h.exit == HoleExit::Tap;
  auto feedTo = [&](double level) {
    w.feed(level, first && h.firstFeed > 0 ? h.firstFeed : h.feed);
    first = false;
  };
  if (h.peck > 0) {
    double cur = h.peckFromSet ? h.peckFrom : h.start, p = h.peck;
    int breaks = 0;
    for (;;) {
      double next = cur + dir * p;
      if (!above(next)) break;
      feedTo(next);
      w.dwell(h.dwellPeck);
      if (tap) w.tapTurn(h.spindle, true);  // out with the spindle reversed
      if (h.breaksPerRetract < 0 || breaks < h.breaksPerRetract) {
        w.go(next - dir * h.chipBreak, h.chipBreakRapid, h.feed);
        if (tap) w.tapTurn(h.spindle, false);
        ++breaks;
      } else {
        w.go(h.start, h.fullRetractFeed < 0, std::max(h.fullRetractFeed, 0.0));
        w.dwell(h.dwellTop);
        if (tap) w.tapTurn(h.spindle, false);
        // A tap goes back in along its thread at the feed; a drill at rapid.
        const double reentry = next - dir * h.reentry;
        if (tap) {
          if ((reentry - h.start) * dir > 0) w.feed(reentry, h.feed);
        } else {
          w.rapid(reentry);
        }
        breaks = 0;
      }
      cur = next;
      if (h.factor > 0) p = std::max(p * h.factor, h.minPeck);
      else if (h.decrement > 0) p = std::max(p - h.decrement, h.minPeck);
    }
  }
  feedTo(h.bottom);
  switch (h.exit) {
  case HoleExit::Rapid:
    w.dwell(h.dwellBottom);
    w.rapid(h.retract);
    break;
  case HoleExit::Feed:
    w.dwell(h.dwellBottom);
    w.feed(h.exitLevel, h.exitFeed);
    if (h.exitRapid) w.rapid(h.retract);
    break;
  case HoleExit::SpindleStopRapid:
    w.dwell(h.dwellBottom);
    w.spindle(CycleStepKind::SpindleStop);
    w.rapid(h.retract);
    w.spindleOn(h.spindle);
    break;
  case HoleExit::OrientShift: {
    w.dwell(h.dwellBottom);
    w.orient(h.orientAngle);
    const double *s = h.shift;
    const bool inPlane = s[0] != 0 || s[1] != 0, lifted = inPlane || s[2] != 0;
    const double liftLevel = h.bottom + s[2];
    if (lifted) w.at(liftLevel, s);
    if (h.exitFeed > 0) w.at(h.exitLevel, s, CycleStepKind::Feed, h.exitFeed);
    else if (h.exitLevel != liftLevel) w.at(h.exitLevel, s);
    if (h.centreAtExit) {
      if (inPlane) w.at(h.exitLevel, nullptr);
      if (h.retract != h.exitLevel) w.rapid(h.retract);
    } else {
      if (h.retract != h.exitLevel) w.at(h.retract, s);
      if (inPlane) w.at(h.retract, nullptr);
    }
    if (h.restart) w.spindleOn(h.spindle);
    break;
  }
  case HoleExit::Tap: {
    // Reverse at the bottom, feed straight out, restore the direction (rs274 order: the dwell
    // comes after the reversal).
    w.tapTurn(h.spindle, true);
    w.dwell(h.dwellBottom);
    w.feed(h.tapOutToStart ? h.start : h.retract, h.exitFeed);
    w.dwell(h.dwellStart);
    w.tapTurn(h.spindle, false);
    if (h.tapOutToStart && h.retract != h.start) w.rapid(h.retract);
    break;
  }
  }
}

void backBoreSteps(const BackBoreSpec &b, int a1, int a2, int d, double p1, double p2, std::vector<CycleStep> &out) {
  Writer w(out, a1, a2, d, p1, p2);
  w.orient(b.orientAngle);
  w.liftOut(b.start, b.bottom, b.shift, b.downFeed);  // down through the hole off centre
  w.spindleOn(b.spindle);
  w.feed(b.cutLevel, b.feed);
  w.dwell(b.dwell);
  if (b.backDown) w.go(b.bottom, !(b.downFeed > 0), b.downFeed);
  w.orient(b.orientAngle);
  w.liftOut(b.backDown ? b.bottom : b.cutLevel, b.retractSet ? b.retract : b.start, b.shift);
  w.spindleOn(b.spindle);
}

}  // namespace ncc
