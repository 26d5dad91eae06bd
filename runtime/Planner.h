// Trajectory core v2: turns the Motion IR stream into a time-parameterised path.
//
// Each move gets a speed cap (programmed feed or rapid_feed, per-axis max_velocity projected on
// the move direction, centripetal limits on arcs) and path acceleration/jerk limits (per-axis
// limits projected on the direction). Junctions get a speed limit from a junction-deviation
// model checked against every axis' limits on the virtual corner arc; exact stop and stopping
// records force zero. Moves whose junctions do not limit speed form runs that are planned as one
// jerk-limited ramp, so acceleration carries across their boundaries. A streaming look-ahead
// window (Machine::lookahead moves, ring buffers) runs the backward pass incrementally and
// commits a run's ramp when its first move leaves, so memory is bounded by the window (see
// docs/PLANNER.md for the approximations).
#pragma once
#include "ir/MotionIR.h"
#include "runtime/Geometry.h"
#include "runtime/Machine.h"

#include <cstdint>
#include <vector>

namespace ncc {

// Velocity over a ramp: S-curve change rampV0 -> rampVp, cruise at rampVp, S-curve change
// rampVp -> rampV1. A ramp covers a run of moves planned as one (docs/PLANNER.md "Runs"); each
// move is a slice of it: [tBegin, tBegin + tSpan] of the ramp's time, from distance sBegin.
// Speeds in mm/s (deg/s for rotary-only moves), jerk = +inf means a trapezoid.
struct VelocityProfile {
  double rampLength = 0, rampV0 = 0, rampVp = 0, rampV1 = 0;
  double accel = 0, jerk = 0;
  double tAcc = 0, tCruise = 0, tDec = 0;  // phases of the ramp
  double tBegin = 0, tSpan = 0, sBegin = 0;  // this segment's slice of the ramp
  double length = 0;                       // of this segment
  double v0 = 0, vp = 0, v1 = 0;           // this segment's entry, highest and exit speeds
  double duration() const { return tSpan; }
  double rampDuration() const { return tAcc + tCruise + tDec; }
  // Distance travelled, speed and path acceleration at time t of this segment (clamped to
  // [0, duration]).
  void at(double t, double &s, double &v) const;
  void at(double t, double &s, double &v, double &a) const;
  // The same over the whole ramp, and the ramp time at which distance s is reached.
  void rampAt(double t, double &s, double &v, double &a) const;
  double rampTimeAt(double s) const;
  // Makes this segment the whole ramp.
  void whole();
  // Makes this segment the slice [sFrom, sTo] of the ramp starting at ramp time tFrom with
  // speed vFrom (the previous slice's end); returns the slice's end time.
  double slice(double sFrom, double sTo, double tFrom, double vFrom);
};

// Closed forms of a symmetric jerk-limited velocity change (|dv| >= a^2/j reaches a, otherwise a
// triangular acceleration); exposed for the tests.
double velocityChangeTime(double dv, double accel, double jerk);
double velocityChangeDistance(double v0, double v1, double accel, double jerk);
// Highest speed reachable from v (accelerating, or by symmetry the highest entry speed that can
// still slow down to v) within distance len.
double maxReachableSpeed(double v, double len, double accel, double jerk);
// Ramp of length len entered at v0 and left at v1 (both must be <= vmax and reachable from
// each other within len; the planner guarantees it); the segment is the whole ramp.
VelocityProfile planProfile(double len, double v0, double v1, double vmax, double accel, double jerk);

// One planned move (or dwell), handed to listeners in time order.
struct PlannedSegment {
  MotionRecord record;    // Rapid, Linear, Arc, Spline or Dwell
  ArcGeometry arc;        // valid for arcs
  CopyPtr<SplinePath> spline;  // splines: the curve by arc length (null otherwise)
  uint64_t index = 0;     // 0-based count of segments
  double t0 = 0;          // start time, s
  double vmax = 0;        // speed cap of the move, mm/s
  VelocityProfile profile;
  double duration() const { return profile.duration(); }
  double length() const { return profile.length; }
  // Machine position at time t after the segment start.
  AxisVec positionAt(double t) const;
};

class PlanListener {
public:
  virtual ~PlanListener() = default;
  virtual void segment(const PlannedSegment &s) = 0;
  virtual void finished(double totalTime) {}
};

struct PlannerStats {
  uint64_t moves = 0, dwells = 0, stops = 0;
  uint64_t unfedMoves = 0;        // feed moves with no feed (planned at max_feed)
  double totalTime = 0;           // s
  double rapidTime = 0, feedTime = 0, dwellTime = 0;
  size_t maxQueued = 0;           // high-water mark of the look-ahead window
  uint64_t runs = 0;              // ramps planned (runs of moves, docs/PLANNER.md "Runs")
};

class Planner : public MotionSink {
public:
  explicit Planner(const Machine &machine);
  void addListener(PlanListener *l) { listeners_.push_back(l); }
  void record(const MotionRecord &r) override;
  // Plans the rest of the window (stopping at the end) and tells listeners the total time.
  bool finish(Diagnostics &diags) override;
  void flush();
  double totalTime() const { return stats_.totalTime; }
  const PlannerStats &stats() const { return stats_; }

private:
  struct Pending {
    PlannedSegment seg;
    double length = 0, vmax = 0, accel = 0, jerk = 0;
    AxisVec tIn{}, tOut{};  // tangents (per mm of length) at the start and the end
    AxisVec nIn{}, nOut{};  // the same normalised, for corner angles
    double vJunction = 0;   // entry speed limit from the junction with the previous move
    double cornerRadius = 0;  // of the junction's virtual arc, mm (inf: tangent)
    bool stopAfter = false;
  };
  // Moves joined by junctions that do not limit speed, planned as one ramp (docs/PLANNER.md
  // "Runs"): acceleration carries across the junctions inside a run.
  struct Run {
    size_t moves = 0;          // moves of the run still in the window
    size_t total = 0;          // moves that joined it
    double length = 0, vmax = 0, accel = 0, jerk = 0;
    double vJunction = 0;      // entry speed limit
    double vBack = 0;          // backward pass: highest entry speed that can still stop in time
    bool stopAfter = false;    // ends at rest
    bool committed = false;    // ramp planned, moves leaving; nothing joins any more
    VelocityProfile ramp;
    double sDone = 0, tDone = 0, vDone = 0;  // where the next move's slice starts
  };
  void push(const MotionRecord &r);
  // Thread records (docs/PLANNER.md "Threads"): the feed is lead x spindle speed, never
  // blended into the moves around them and never capped; what breaks that is an error.
  void thread(const MotionRecord &r);
  void variableThread(const MotionRecord &t);
  void threadError(const MotionRecord &r, std::string msg, const char *rule);
  void limits(Pending &p) const;
  double junctionSpeed(const Pending &prev, const Pending &next, double &radius) const;
  double cornerSpeed(const AxisVec &from, const AxisVec &to, double cosTurn, double radius) const;
  bool joins(const Run &run, const Pending &p) const;
  void addToRuns(const Pending &p);
  void commit(Run &r);
  void emitFront();
  void emit(PlannedSegment &s);
  Pending &at(size_t i) { return ring_[(head_ + i) & mask_]; }
  Run &run(size_t i) { return runs_[(runHead_ + i) & mask_]; }

  const Machine &machine_;
  std::vector<PlanListener *> listeners_;
  std::vector<Pending> ring_;
  std::vector<Run> runs_;     // runs of the moves in the window, same ring size
  size_t head_ = 0, count_ = 0, mask_ = 0;  // ring size is a power of two
  size_t runHead_ = 0, runCount_ = 0;
  size_t runMax_ = 1;         // moves per run: half the window, so a run can commit while
                              // the other half still says how it must end
  double entry_ = 0;          // committed entry speed of the front run
  double minVel_ = 0, minAccel_ = 0, minJerk_ = 0;  // smallest limits of the present axes
  int pathMode_ = 2;          // 0 exact path, 1 exact stop, 2 continuous
  double tolerance_;          // corner deviation budget, mm
  uint64_t nextIndex_ = 0;
  AxisVec lastPos_{};         // end of the last move, where dwells happen
  bool finished_ = false;
  PlannerStats stats_;
  double spindleRpm_ = 0;      // the last spindle_speed record
  bool spindleOn_ = false;     // spindle_cw / spindle_ccw seen since the last stop
  bool spindlePositioned_ = false;  // spindle_orient since the last spindle_cw/ccw/stop (a G331 tap may run)
  bool inThread_ = false;      // the last move pushed was a thread record
  bool threadFailed_ = false;  // the first thread error, reported by finish()
  SourceLoc threadErrorLoc_;
  std::string threadErrorMsg_;
  const char *threadErrorRule_ = "";
};

}  // namespace ncc
