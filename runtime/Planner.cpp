#include "runtime/Planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

namespace ncc {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMinLength = 1e-9;  // mm: shorter moves take no time

// Position and speed after time tau into a velocity change of dv (signed) from vStart.
void changeAt(double vStart, double dv, double a, double j, double tau, double &s, double &v) {
  double sign = dv < 0 ? -1 : 1, adv = std::fabs(dv);
  double tj, ta, apk;
  if (std::isinf(j) || adv >= a * a / j) {
    tj = std::isinf(j) ? 0 : a / j;
    ta = adv / a - tj;
    apk = a;
  } else {
    tj = std::sqrt(adv / j);
    ta = 0;
    apk = j * tj;
  }
  s = 0;
  v = vStart;
  double t1 = std::min(tau, tj);  // jerk rising
  if (tj > 0 && t1 > 0) {
    s += v * t1 + sign * j * t1 * t1 * t1 / 6;
    v += sign * j * t1 * t1 / 2;
  }
  if (tau <= tj) return;
  double t2 = std::min(tau - tj, ta);  // constant acceleration
  if (t2 > 0) {
    s += v * t2 + sign * apk * t2 * t2 / 2;
    v += sign * apk * t2;
  }
  if (tau <= tj + ta || tj <= 0) return;
  double t3 = std::min(tau - tj - ta, tj);  // jerk falling
  s += v * t3 + sign * (apk * t3 * t3 / 2 - j * t3 * t3 * t3 / 6);
  v += sign * (apk * t3 - j * t3 * t3 / 2);
}

double dot(const AxisVec &a, const AxisVec &b) {
  double d = 0;
  for (int i = 0; i < kAxes; ++i) d += a[i] * b[i];
  return d;
}

// min(cap, maxReachableSpeed(v, len)) without solving when the cap is reachable (the common
// case inside a run of moves at feed).
double reachCapped(double v, double len, double cap, double a, double j) {
  if (cap <= v || velocityChangeDistance(v, cap, a, j) <= len) return cap;
  return std::min(cap, maxReachableSpeed(v, len, a, j));
}

AxisVec normalized(AxisVec v) {
  double l = std::sqrt(dot(v, v));
  if (l > 0)
    for (double &x : v) x /= l;
  return v;
}

}  // namespace

double velocityChangeTime(double dv, double a, double j) {
  dv = std::fabs(dv);
  if (dv <= 0) return 0;
  if (std::isinf(j)) return dv / a;
  return dv >= a * a / j ? dv / a + a / j : 2 * std::sqrt(dv / j);
}

double velocityChangeDistance(double v0, double v1, double a, double j) {
  // A symmetric S-curve is point-symmetric about its midpoint: mean speed = (v0 + v1) / 2.
  return 0.5 * (v0 + v1) * velocityChangeTime(v1 - v0, a, j);
}

double maxReachableSpeed(double v, double len, double a, double j) {
  if (len <= 0) return v;
  if (!std::isinf(j)) {
    double dvStar = a * a / j;  // smallest change that reaches full acceleration
    double dStar = (2 * v + dvStar) * a / j;
    if (len <= dStar) {
      // dv = j s^2 where j s^3 + 2 v s = len (increasing, convex for s > 0): Halley steps from
      // an upper bound (each term alone reaching len) converge cubically.
      double s = std::cbrt(len / j);
      if (v > 0) s = std::min(s, len / (2 * v));
      for (int i = 0; i < 40; ++i) {
        double f = j * s * s * s + 2 * v * s - len, d1 = 3 * j * s * s + 2 * v, d2 = 6 * j * s;
        double step = f * d1 / (d1 * d1 - 0.5 * f * d2);
        s -= step;
        if (std::fabs(step) <= 1e-13 * s) break;
      }
      return v + j * s * s;
    }
  }
  double k = std::isinf(j) ? 0 : a * a / j;
  double B = 2 * v + k, C = 2 * v * k - 2 * len * a;  // dv^2 + B dv + C = 0, C < 0
  return v + (-2 * C) / (B + std::sqrt(B * B - 4 * C));
}

VelocityProfile planProfile(double len, double v0, double v1, double vmax, double a, double j) {
  VelocityProfile p;
  p.length = len;
  p.accel = a;
  p.jerk = j;
  v0 = std::min(v0, vmax);
  v1 = std::min(v1, vmax);
  p.v0 = v0;
  p.v1 = v1;
  if (len <= 0) {
    p.vp = std::max(v0, v1);
    return p;
  }
  auto need = [&](double vp) {
    return velocityChangeDistance(v0, vp, a, j) + velocityChangeDistance(vp, v1, a, j);
  };
  double vp = vmax;
  if (need(vmax) > len) {
    double lo = std::max(v0, v1), hi = vmax;
    // Peak of a trapezoid: exact without a jerk limit, an upper estimate with one.
    vp = std::clamp(std::sqrt(std::max(0.0, a * len + 0.5 * (v0 * v0 + v1 * v1))), lo, hi);
    if (!std::isinf(j)) {
      // Safeguarded Newton on the (increasing) distance needed to reach the peak and come back.
      auto slope = [&](double from, double to) {  // d/d(to) of velocityChangeDistance(from, to)
        double dv = to - from, t = velocityChangeTime(dv, a, j);
        double dt = dv >= a * a / j ? 1 / a : (dv > 0 ? 1 / std::sqrt(dv * j) : INFINITY);
        return 0.5 * t + 0.5 * (from + to) * dt;
      };
      for (int i = 0; i < 60; ++i) {
        double f = need(vp) - len;
        if (std::fabs(f) <= 1e-13 * len || hi - lo <= 1e-13 * hi) break;
        (f > 0 ? hi : lo) = vp;
        double next = vp - f / (slope(v0, vp) + slope(v1, vp));
        vp = next > lo && next < hi ? next : 0.5 * (lo + hi);
      }
    }
  }
  p.vp = vp;
  p.tAcc = velocityChangeTime(vp - v0, a, j);
  p.tDec = velocityChangeTime(vp - v1, a, j);
  double rest = len - need(vp);
  if (rest > 0 && vp > 0) p.tCruise = rest / vp;
  return p;
}

void VelocityProfile::at(double t, double &s, double &v) const {
  if (t <= 0) { s = 0; v = v0; return; }
  if (t < tAcc) { changeAt(v0, vp - v0, accel, jerk, t, s, v); return; }
  double sAcc = velocityChangeDistance(v0, vp, accel, jerk);
  if (t < tAcc + tCruise) { s = sAcc + vp * (t - tAcc); v = vp; return; }
  double sd, vd;
  changeAt(vp, v1 - vp, accel, jerk, std::min(t - tAcc - tCruise, tDec), sd, vd);
  s = std::min(length, sAcc + vp * tCruise + sd);
  v = vd;
}

AxisVec PlannedSegment::positionAt(double t) const {
  if (record.kind == RecordKind::Dwell) return record.end;
  double s, v;
  profile.at(t, s, v);
  double f = profile.length > 0 ? std::clamp(s / profile.length, 0.0, 1.0) : 1.0;
  if (record.kind == RecordKind::Arc) return arcPoint(arc, record.start, record.end, f);
  if (spline) {
    Vec3 q = spline->at(s);
    AxisVec p = record.end;
    for (int i = 0; i < 3; ++i) p[i] = f >= 1 ? record.end[i] : q[i];
    return p;
  }
  AxisVec p;
  for (int i = 0; i < kAxes; ++i) p[i] = record.start[i] + (record.end[i] - record.start[i]) * f;
  if (f >= 1) p = record.end;
  return p;
}

Planner::Planner(const Machine &machine)
    : machine_(machine), tolerance_(machine.pathTolerance) {
  size_t n = 2;
  while (n < (size_t)std::max(1, machine.lookahead) + 1) n *= 2;
  ring_.resize(n);
  mask_ = n - 1;
}

// Speed, acceleration and jerk caps of one move from the machine's per-axis limits.
void Planner::limits(Pending &p) const {
  const MotionRecord &r = p.seg.record;
  double feed = r.kind == RecordKind::Rapid ? machine_.rapidFeed : r.feed;
  if (r.kind != RecordKind::Rapid) {
    if (!(feed > 0)) feed = machine_.maxFeed;
    feed = std::min(feed, machine_.maxFeed);
  }
  double v = feed / 60, a = kInf, j = kInf;
  // Fraction of the path speed each axis carries (its worst case over the move).
  AxisVec share{};
  if (p.seg.spline) {
    for (int i = 0; i < 3; ++i) share[i] = p.seg.spline->share[i];
  } else if (r.kind == RecordKind::Arc && p.length > 0) {
    Vec3 s3 = arcAxisShare(p.seg.arc);
    for (int i = 0; i < 3; ++i) share[i] = s3[i];
    for (int i = 3; i < kAxes; ++i) share[i] = std::fabs(r.end[i] - r.start[i]) / p.length;
  } else {
    for (int i = 0; i < kAxes; ++i) share[i] = std::fabs(p.tIn[i]);
  }
  for (int i = 0; i < kAxes; ++i) {
    const AxisLimits &ax = machine_.axes[i];
    if (share[i] < 1e-12 || !ax.present) continue;
    v = std::min(v, ax.maxVelocity / 60 / share[i]);
    a = std::min(a, ax.maxAccel / share[i]);
    if (ax.maxJerk > 0) j = std::min(j, ax.maxJerk / share[i]);
  }
  if (std::isinf(a)) a = 1e6;  // no limiting axis moves: effectively instantaneous
  if (r.kind == RecordKind::Arc) {
    double k = arcCurvature(p.seg.arc);
    const ArcGeometry &g = p.seg.arc;
    double an, jn;
    if (!g.tilted) {
      const PlaneAxes &pa = g.ax;
      an = std::min(machine_.axes[pa.u].maxAccel, machine_.axes[pa.v].maxAccel);
      jn = std::min(machine_.axes[pa.u].maxJerk, machine_.axes[pa.v].maxJerk);
    } else {  // the centripetal acceleration turns through the plane: every axis in it carries it
      an = jn = kInf;
      for (int i = 0; i < 3; ++i)
        if (std::hypot(g.tilted->u[i], g.tilted->v[i]) > 1e-12) {
          an = std::min(an, machine_.axes[i].maxAccel);
          jn = std::min(jn, machine_.axes[i].maxJerk);
        }
    }
    if (k > 0 && an > 0) v = std::min(v, std::sqrt(an / k));                // v^2 / r <= a
    if (k > 0 && jn > 0) v = std::min(v, std::cbrt(jn / (k * k)));           // v^3 / r^2 <= j
  }
  if (p.seg.spline) {  // the same limits at the sharpest point of the curve, from every axis it moves
    double k = p.seg.spline->maxCurvature, an = kInf, jn = kInf;
    for (int i = 0; i < 3; ++i)
      if (share[i] > 1e-12 && machine_.axes[i].present) {
        an = std::min(an, machine_.axes[i].maxAccel);
        if (machine_.axes[i].maxJerk > 0) jn = std::min(jn, machine_.axes[i].maxJerk);
      }
    if (k > 0 && an > 0 && !std::isinf(an)) v = std::min(v, std::sqrt(an / k));
    if (k > 0 && jn > 0 && !std::isinf(jn)) v = std::min(v, std::cbrt(jn / (k * k)));
  }
  p.vmax = v;
  p.accel = a;
  p.jerk = j;
}

// Junction-deviation model: the corner is passed on a virtual circle that stays within the
// tolerance of the corner point, at the speed whose centripetal acceleration is the limit.
double Planner::junctionSpeed(const Pending &prev, const Pending &next) const {
  double cap = std::min(prev.vmax, next.vmax);
  if (prev.stopAfter) return 0;
  double c = dot(prev.nOut, next.nIn);
  if (c >= 1 - 1e-12) return cap;  // tangent
  double delta = pathMode_ == 2 ? tolerance_ : 0;
  double sinHalf = std::sqrt(std::max(0.0, 0.5 * (1 + c)));  // sin of half the inner angle
  if (sinHalf >= 1) return cap;
  double radius = delta * sinHalf / (1 - sinHalf);
  double a = std::min(prev.accel, next.accel);
  return std::min(cap, std::sqrt(a * radius));
}

void Planner::push(const MotionRecord &r) {
  if (count_ == ring_.size()) emitFront();  // cannot happen with the pop below; kept as a guard
  Pending &p = at(count_);
  // Reset in place: cheaper than assigning a temporary (one zeroing, no move, no second destructor).
  p.~Pending();
  new (&p) Pending{};
  p.seg.record = r;
  p.seg.record.text.clear();
  lastPos_ = r.end;
  if (r.kind == RecordKind::Arc) {
    p.seg.arc = arcGeometry(r);
    p.length = p.seg.arc.length;
    Vec3 t0 = arcTangent(p.seg.arc, 0), t1 = arcTangent(p.seg.arc, 1);
    for (int i = 0; i < 3; ++i) p.tIn[i] = t0[i], p.tOut[i] = t1[i];
    if (p.length > 0)
      for (int i = 3; i < kAxes; ++i) p.tIn[i] = p.tOut[i] = (r.end[i] - r.start[i]) / p.length;
  } else if (r.kind == RecordKind::Spline) {
    // One move along the curve's chords (docs/PLANNER.md, "Splines"); the curve data is not kept.
    p.seg.spline.make() = splinePath(r);
    p.seg.record.extra.reset();
    p.length = p.seg.spline->length();
    Vec3 t0 = p.seg.spline->startTangent(), t1 = p.seg.spline->endTangent();
    for (int i = 0; i < 3; ++i) p.tIn[i] = t0[i], p.tOut[i] = t1[i];
  } else {
    p.length = linearLength(r.start, r.end);
    p.tIn = p.tOut = unitDirection(r.start, r.end, p.length);
  }
  if (!std::isfinite(p.length)) p.length = 0;  // absurd coordinates: no time rather than inf/NaN
  p.nIn = normalized(p.tIn);
  p.nOut = normalized(p.tOut);
  p.stopAfter = r.exactStop || pathMode_ == 1;
  Pending *prev = count_ ? &at(count_ - 1) : nullptr;
  if (p.length < kMinLength) {
    // Zero-length move: transparent to the junction between its neighbours.
    p.length = 0;
    p.vmax = prev ? prev->vmax : 0;
    p.accel = prev ? prev->accel : 1;
    p.jerk = prev ? prev->jerk : kInf;
    if (prev) p.tIn = p.tOut = prev->tOut, p.nIn = p.nOut = prev->nOut;
    p.vJunction = prev && !prev->stopAfter ? p.vmax : 0;
  } else {
    limits(p);
    p.vJunction = prev ? junctionSpeed(*prev, p) : 0;
  }
  ++count_;
  stats_.maxQueued = std::max(stats_.maxQueued, count_);
  // Backward pass: the new move must be able to stop at its end; raise earlier entry speeds
  // until one does not change (then none before it can).
  p.vBack = reachCapped(0, p.length, p.vJunction, p.accel, p.jerk);
  for (size_t i = count_ - 1; i-- > 0;) {
    Pending &q = at(i);
    double v = reachCapped(at(i + 1).vBack, q.length, q.vJunction, q.accel, q.jerk);
    if (v <= q.vBack) break;
    q.vBack = v;
  }
  if (p.stopAfter) flush();
  else if (count_ > (size_t)std::max(1, machine_.lookahead)) emitFront();
}

// Forward pass for the front move: accelerate from the committed entry as far as the length and
// the next move's backward limit allow.
void Planner::emitFront() {
  Pending &p = at(0);
  double next = count_ > 1 ? at(1).vBack : 0;
  double v0 = std::min(entry_, p.vmax);
  double v1 = reachCapped(v0, p.length, next, p.accel, p.jerk);
  if (p.length == 0) v1 = std::min(next, v0);
  p.seg.vmax = p.vmax;
  p.seg.profile = planProfile(p.length, v0, v1, p.vmax, p.accel, p.jerk);
  entry_ = v1;
  emit(p.seg);
  head_ = (head_ + 1) & mask_;
  --count_;
  if (count_ == 0) entry_ = 0;
}

void Planner::emit(PlannedSegment &s) {
  s.index = nextIndex_++;
  s.t0 = stats_.totalTime;
  double d = s.duration();
  stats_.totalTime += d;
  switch (s.record.kind) {
  case RecordKind::Rapid: stats_.rapidTime += d; ++stats_.moves; break;
  case RecordKind::Dwell: stats_.dwellTime += d; ++stats_.dwells; break;
  default:
    stats_.feedTime += d;
    ++stats_.moves;
    if (!(s.record.feed > 0)) ++stats_.unfedMoves;
    break;
  }
  for (auto *l : listeners_) l->segment(s);
}

void Planner::flush() {
  while (count_) emitFront();
  entry_ = 0;
}

void Planner::threadError(const MotionRecord &r, std::string msg, const char *rule) {
  if (threadFailed_) return;
  threadErrorRule_ = rule;
  threadFailed_ = true;
  threadErrorLoc_ = r.loc;
  threadErrorMsg_ = std::move(msg);
}

void Planner::thread(const MotionRecord &r) {
  // A new synchronisation starts from rest (the spindle's index is waited for); a chained
  // record joins the thread before it like any path move.
  if (r.sync != ThreadSync::Chain && r.sync != ThreadSync::TapOut) flush();
  if (!spindleOn_ || !(spindleRpm_ > 0)) {
    threadError(r, fmt::format("a thread move needs a turning spindle (speed {} rpm, {})", spindleRpm_,
                               spindleOn_ ? "on" : "stopped"), "thread-spindle");
    push(r);
    inThread_ = true;
    return;
  }
  MotionRecord t = r;
  t.feed = threadPathLead(r) * spindleRpm_;  // the feed follows the spindle, whatever was recorded
  if (threadLeadChange(r) != 0) return variableThread(t);
  if (std::fabs(t.feed - r.feed) > 1e-9 * std::max(1.0, t.feed))
    threadError(r, fmt::format("the thread's feed F{} is not its lead {} mm/rev x the spindle's {} rpm = {} mm/min",
                               r.feed, threadPathLead(r), spindleRpm_, t.feed), "thread-feed");
  push(t);
  inThread_ = true;
  const Pending &p = at(count_ - 1);
  if (p.length > 0 && p.vmax * 60 < t.feed * (1 - 1e-9))
    threadError(r, fmt::format("the thread's feed {} mm/min exceeds what the machine's axes allow on it ({} mm/min)",
                               t.feed, p.vmax * 60), "thread-feed");
}

// A variable lead (808D G34): the speed changes linearly with time (the lead grows by the same
// amount every revolution at a constant spindle speed), from the start lead x S to the end lead
// x S: one constant-acceleration segment, entered at its start speed (the synchronisation).
void Planner::variableThread(const MotionRecord &t) {
  const double len = linearLength(t.start, t.end), ratio = t.value > 0 ? threadPathLead(t) / t.value : 0;
  const double v0 = t.feed / 60, v1 = threadEndLead(t) * ratio * spindleRpm_ / 60;
  if (std::max(v0, v1) * 60 > machine_.maxFeed * (1 + 1e-9))
    threadError(t, fmt::format("the thread's feed reaches {} mm/min, above the machine's max_feed {}", std::max(v0, v1) * 60,
                               machine_.maxFeed), "thread-feed");
  PlannedSegment s;
  s.record = t;
  s.record.text.clear();
  s.vmax = std::max(v0, v1);
  VelocityProfile &p = s.profile;
  p.length = len, p.v0 = v0, p.vp = p.v1 = v1, p.jerk = INFINITY;
  const double tRamp = v0 + v1 > 0 ? 2 * len / (v0 + v1) : 0;
  if (std::fabs(v1 - v0) <= 1e-12 * std::max(1.0, v0)) {
    p.vp = p.v1 = v0, p.tCruise = v0 > 0 ? len / v0 : 0, p.accel = 1;  // no change worth a ramp
  } else {
    p.tAcc = tRamp, p.accel = std::fabs(v1 - v0) / tRamp;
  }
  lastPos_ = t.end;
  inThread_ = true;
  emit(s);
}

void Planner::record(const MotionRecord &r) {
  if (r.kind == RecordKind::Thread) return thread(r);
  if (inThread_ && (r.kind == RecordKind::Rapid || r.kind == RecordKind::Linear || r.kind == RecordKind::Arc ||
                    r.kind == RecordKind::Spline)) {
    flush();  // a thread ends at rest: nothing blends out of it
    inThread_ = false;
  }
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
  case RecordKind::Arc:
  case RecordKind::Spline:
    push(r);
    return;
  case RecordKind::SpindleSpeed:
    spindleRpm_ = r.value;
    return;
  case RecordKind::Dwell: {
    flush();
    PlannedSegment s;
    s.record = r;
    // Dwell records need not carry a position: the machine waits where the last move ended.
    s.record.start = s.record.end = lastPos_;
    s.profile.tCruise = std::isfinite(r.value) && r.value > 0 ? std::min(r.value, 1e9) : 0;
    emit(s);
    return;
  }
  case RecordKind::PathMode:
    pathMode_ = (int)r.ivalue;
    tolerance_ = r.value > 0 ? r.value : machine_.pathTolerance;
    return;
  // Records that stop motion: the machine decelerates to rest before acting on them.
  case RecordKind::SpindleCW:
  case RecordKind::SpindleCCW:
  case RecordKind::SpindleStop:
    spindleOn_ = r.kind != RecordKind::SpindleStop;
    [[fallthrough]];
  case RecordKind::ToolChange:
  case RecordKind::SpindleOrient:
  case RecordKind::OptionalStop:
  case RecordKind::ProgramStop:
  case RecordKind::ProgramEnd:
  case RecordKind::Aux:
    flush();
    ++stats_.stops;
    return;
  default:
    return;
  }
}

bool Planner::finish(Diagnostics &diags) {
  flush();
  if (!finished_)
    for (auto *l : listeners_) l->finished(stats_.totalTime);
  if (threadFailed_ && !finished_) diags.error(threadErrorLoc_, threadErrorMsg_, threadErrorRule_);
  finished_ = true;
  return !threadFailed_;
}

}  // namespace ncc
