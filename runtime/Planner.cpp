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
  size_t window = (size_t)std::max(1, machine.lookahead);
  size_t n = 2;
  while (n < window + 1) n *= 2;
  ring_.resize(n);
  runs_.resize(n);
  mask_ = n - 1;
  runMax_ = std::max<size_t>(1, window / 2);
  minVel_ = minAccel_ = minJerk_ = kInf;
  for (const AxisLimits &ax : machine.axes) {
    if (!ax.present) continue;
    minVel_ = std::min(minVel_, ax.maxVelocity / 60);
    minAccel_ = std::min(minAccel_, ax.maxAccel);
    if (ax.maxJerk > 0) minJerk_ = std::min(minJerk_, ax.maxJerk);
  }
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
// tolerance of the corner point, at the highest speed every axis can follow on it.
double Planner::junctionSpeed(const Pending &prev, const Pending &next, double &radius) const {
  double cap = std::min(prev.vmax, next.vmax);
  radius = kInf;
  if (prev.stopAfter) return 0;
  double c = dot(prev.nOut, next.nIn);
  if (c >= 1 - 1e-12) return cap;  // tangent
  double delta = pathMode_ == 2 ? tolerance_ : 0;
  double sinHalf = std::sqrt(std::max(0.0, 0.5 * (1 + c)));  // sin of half the inner angle
  if (sinHalf >= 1) return cap;
  radius = delta * sinHalf / (1 - sinHalf);
  if (!(radius > 0)) return 0;
  // No axis carries more than the whole path speed, acceleration or jerk: when the smallest
  // axis limits allow the cap, every axis does (the common case of gentle corners).
  if (cap <= minVel_ && cap * cap <= minAccel_ * radius && cap * cap * cap <= minJerk_ * radius * radius) return cap;
  return std::min(cap, cornerSpeed(prev.nOut, next.nIn, c, radius));
}

namespace {

// Largest |f| over [0, T] of f(phi) = A cos(phi - phi0), given its values and slopes at both ends
// and its amplitude (T < pi: at most one extremum inside, where the slope changes sign).
double sinusoidMax(double f0, double d0, double fT, double dT, double amp) {
  return d0 * dT <= 0 ? amp : std::max(std::fabs(f0), std::fabs(fT));
}

}  // namespace

// On the virtual arc from direction `from` to `to` (unit vectors, cosine c of the turn) with
// radius R, the direction at turn angle phi is t = cos(phi) from + sin(phi) q, the centripetal
// acceleration v^2/R along dt/dphi and the jerk v^3/R^2 along -t. Each axis gets the largest
// component of each over the turn: v <= max_velocity / |t_i|, v^2 / R <= max_accel / |t'_i|,
// v^3 / R^2 <= max_jerk / |t_i|.
double Planner::cornerSpeed(const AxisVec &from, const AxisVec &to, double c, double radius) const {
  double sinT = std::sqrt(std::max(0.0, 1 - c * c)), v = kInf, accel = kInf, jerk = kInf;
  for (int i = 0; i < kAxes; ++i) {
    const AxisLimits &ax = machine_.axes[i];
    if (!ax.present) continue;
    double shareV = 1, shareA = 1;  // a near-reversal: the direction sweeps every axis
    if (sinT > 1e-9) {
      double p = from[i], q = (to[i] - c * from[i]) / sinT, amp = std::sqrt(p * p + q * q);
      double gEnd = -p * sinT + q * c;  // t'_i at the end of the turn
      shareV = sinusoidMax(p, q, to[i], gEnd, amp);
      shareA = sinusoidMax(q, -p, gEnd, -to[i], amp);
    }
    if (shareV > 1e-12) {
      v = std::min(v, ax.maxVelocity / 60 / shareV);
      if (ax.maxJerk > 0) jerk = std::min(jerk, ax.maxJerk / shareV);
    }
    if (shareA > 1e-12) accel = std::min(accel, ax.maxAccel / shareA);
  }
  v = std::min(v, std::sqrt(accel * radius));
  return std::isinf(jerk) ? v : std::min(v, std::cbrt(jerk * radius * radius));
}

void Planner::push(const MotionRecord &r) {
  // The slot is reused as it is: every field the move needs is set below (a full reset of the
  // slot cost more than the rest of planning a straight move).
  Pending &p = at(count_);
  p.seg.record = r;
  p.seg.record.text.clear();
  p.seg.spline.reset();
  lastPos_ = r.end;
  if (r.kind == RecordKind::Arc) {
    p.seg.arc = arcGeometry(r);
    p.length = p.seg.arc.length;
    Vec3 t0 = arcTangent(p.seg.arc, 0), t1 = arcTangent(p.seg.arc, 1);
    p.tIn = p.tOut = AxisVec{};
    for (int i = 0; i < 3; ++i) p.tIn[i] = t0[i], p.tOut[i] = t1[i];
    if (p.length > 0)
      for (int i = 3; i < kAxes; ++i) p.tIn[i] = p.tOut[i] = (r.end[i] - r.start[i]) / p.length;
  } else if (r.kind == RecordKind::Spline) {
    // One move along the curve's chords (docs/PLANNER.md, "Splines"); the curve data is not kept.
    p.seg.spline.make() = splinePath(r);
    p.seg.record.extra.reset();
    p.length = p.seg.spline->length();
    Vec3 t0 = p.seg.spline->startTangent(), t1 = p.seg.spline->endTangent();
    p.tIn = p.tOut = AxisVec{};
    for (int i = 0; i < 3; ++i) p.tIn[i] = t0[i], p.tOut[i] = t1[i];
  } else {
    p.length = linearLength(r.start, r.end);
    p.tIn = p.tOut = unitDirection(r.start, r.end, p.length);
  }
  if (!std::isfinite(p.length)) p.length = 0;  // absurd coordinates: no time rather than inf/NaN
  p.nIn = normalized(p.tIn);
  p.nOut = r.kind == RecordKind::Linear || r.kind == RecordKind::Rapid ? p.nIn : normalized(p.tOut);
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
    p.cornerRadius = kInf;
  } else {
    limits(p);
    p.vJunction = prev ? junctionSpeed(*prev, p, p.cornerRadius) : 0;
  }
  bool joined = prev && !prev->stopAfter && runCount_ && joins(run(runCount_ - 1), p);
  ++count_;
  stats_.maxQueued = std::max(stats_.maxQueued, count_);
  if (!joined) {
    Run &n = run(runCount_++);
    n = Run{};
    n.vmax = p.vmax;
    n.accel = p.accel;
    n.jerk = p.jerk;
    n.vJunction = p.vJunction;
  }
  addToRuns(p);
  if (p.stopAfter) flush();
  else if (count_ > (size_t)std::max(1, machine_.lookahead)) emitFront();
}

// A move joins the open run when its junction does not limit speed, it has the run's speed cap,
// its acceleration and jerk limits are within 10 % of the run's (the run takes the smallest),
// the corner can turn the carried acceleration within the axes' jerk, and joining does not
// lower the run's backward limit (which earlier decisions rely on).
bool Planner::joins(const Run &run, const Pending &p) const {
  if (run.committed || run.total >= runMax_) return false;
  if (p.length == 0) return true;
  if (run.length == 0 || std::fabs(p.vmax - run.vmax) > 1e-9 * run.vmax || p.vJunction < p.vmax * (1 - 1e-12))
    return false;
  if (p.accel < 0.9 * run.accel || run.accel < 0.9 * p.accel) return false;
  if (std::isinf(p.jerk) != std::isinf(run.jerk) || p.jerk < 0.9 * run.jerk || run.jerk < 0.9 * p.jerk) return false;
  double a = std::min(run.accel, p.accel), j = std::min(run.jerk, p.jerk);
  // Path acceleration carried through the corner turns with the direction: over the virtual
  // arc (time R Theta / v) every axis' share of it changes at up to a v / R.
  if (a * p.vmax > minJerk_ * p.cornerRadius) return false;
  return reachCapped(0, run.length + p.length, run.vJunction, a, j) >= run.vBack;
}

// Adds the move just queued to the last run and runs the backward pass: the last run must be
// able to stop at its end; earlier entry limits rise until one does not change (then none
// before it can: every change only raises them).
void Planner::addToRuns(const Pending &p) {
  Run &last = run(runCount_ - 1);
  ++last.moves;
  ++last.total;
  last.length += p.length;
  last.accel = std::min(last.accel, p.accel);
  last.jerk = std::min(last.jerk, p.jerk);
  last.stopAfter = p.stopAfter;
  last.vBack = reachCapped(0, last.length, last.vJunction, last.accel, last.jerk);
  for (size_t i = runCount_ - 1; i-- > 0;) {
    Run &q = run(i);
    if (q.committed) break;
    double v = reachCapped(run(i + 1).vBack, q.length, q.vJunction, q.accel, q.jerk);
    if (v <= q.vBack) break;
    q.vBack = v;
  }
}

// Forward pass for the front run: accelerate from the committed entry as far as its length and
// the next run's backward limit allow, as one ramp.
void Planner::commit(Run &r) {
  double next = runCount_ > 1 ? run(1).vBack : 0;
  double v0 = std::min(entry_, r.vmax);
  double v1 = r.length == 0 ? std::min(next, v0) : reachCapped(v0, r.length, next, r.accel, r.jerk);
  r.ramp = planProfile(r.length, v0, v1, r.vmax, r.accel, r.jerk);
  r.committed = true;
  r.sDone = r.tDone = 0;
  r.vDone = r.ramp.rampV0;
  entry_ = v1;
  ++stats_.runs;
}

// The front move leaves the window with its slice of its run's ramp.
void Planner::emitFront() {
  Pending &p = at(0);
  Run &r = run(0);
  if (!r.committed) commit(r);
  double sTo = r.moves == 1 ? r.length : std::min(r.length, r.sDone + p.length);
  p.seg.vmax = p.vmax;
  p.seg.profile = r.ramp;
  r.tDone = p.seg.profile.slice(r.sDone, sTo, r.tDone, r.vDone);
  r.vDone = p.seg.profile.v1;
  r.sDone = sTo;
  emit(p.seg);
  head_ = (head_ + 1) & mask_;
  --count_;
  if (--r.moves == 0) {
    runHead_ = (runHead_ + 1) & mask_;
    --runCount_;
  }
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
  // A Sinumerik G331/G332 tap turns the spindle in position control (after SPOS): not "on".
  const bool tap = r.sync == ThreadSync::TapIn || r.sync == ThreadSync::TapOut;
  if (!(spindleOn_ || (tap && spindlePositioned_)) || !(spindleRpm_ > 0)) {
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
  p.rampLength = len, p.rampV0 = v0, p.rampVp = p.rampV1 = v1, p.jerk = INFINITY;
  const double tRamp = v0 + v1 > 0 ? 2 * len / (v0 + v1) : 0;
  if (std::fabs(v1 - v0) <= 1e-12 * std::max(1.0, v0)) {
    p.rampVp = p.rampV1 = v0, p.tCruise = v0 > 0 ? len / v0 : 0, p.accel = 1;  // no change worth a ramp
  } else {
    p.tAcc = tRamp, p.accel = std::fabs(v1 - v0) / tRamp;
  }
  p.whole();
  lastPos_ = t.end;
  inThread_ = true;
  emit(s);
}

void Planner::record(const MotionRecord &r) {
  if (r.kind == RecordKind::Thread) return thread(r);
  if (inThread_ && isMoveRecord(r.kind)) {
    flush();  // a thread ends at rest: nothing blends out of it
    inThread_ = false;
  }
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
  case RecordKind::Arc:
  case RecordKind::Spline:
  case RecordKind::Probe:  // a straight feed; its exact_stop ends it at rest
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
    s.profile.whole();
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
    spindlePositioned_ = false;
    [[fallthrough]];
  case RecordKind::ToolChange:
  case RecordKind::SpindleOrient:
    if (r.kind == RecordKind::SpindleOrient) spindlePositioned_ = true;
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
