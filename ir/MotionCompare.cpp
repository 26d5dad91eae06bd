#include "ir/MotionCompare.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

static bool isPath(const MotionRecord &r) { return isMoveRecord(r.kind) || r.kind == RecordKind::Dwell; }

// A straight move within `limit` on every axis. Zero-length ones carry no path: translators may
// drop them. Short ones (a few output units) are what a translator's rounding makes of a
// sub-resolution move: it may drop it, keep it, or keep it one unit long.
static bool isShortMove(const MotionRecord &r, double limit) {
  if (r.kind != RecordKind::Rapid && r.kind != RecordKind::Linear) return false;
  for (int i = 0; i < kAxes; ++i)
    if (std::fabs(r.end[i] - r.start[i]) > limit) return false;
  return true;
}

static double linearDistance(const MotionRecord &r) {
  double d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += (r.end[i] - r.start[i]) * (r.end[i] - r.start[i]);
  return std::sqrt(d2);
}

// In-plane axes of an untilted arc's plane (counter-clockwise from the first to the second).
static void arcAxes(Plane p, int &a, int &b) {
  static const int kAxesOf[3][2] = {{0, 1}, {2, 0}, {1, 2}};
  a = kAxesOf[(int)p][0];
  b = kAxesOf[(int)p][1];
}

// Angle an untilted arc sweeps, counting its full turns.
static double arcSweep(const MotionRecord &r) {
  int a, b;
  arcAxes(r.plane, a, b);
  const double twoPi = 2 * 3.14159265358979323846;
  double as = std::atan2(r.start[b] - r.center[b], r.start[a] - r.center[a]);
  double ae = std::atan2(r.end[b] - r.center[b], r.end[a] - r.center[a]);
  double d = r.turns >= 0 ? ae - as : as - ae;
  while (d <= 1e-12) d += twoPi;
  int n = r.turns == 0 ? 1 : std::abs(r.turns);
  return (n - 1) * twoPi + d;
}

// y is a piece of x that ends before x does: on x's segment (a straight move in parts), inside
// x's box (rapid legs), or on x's circle in x's direction (an arc in parts).
static bool isPieceOf(const MotionRecord &x, const MotionRecord &y, const PathCompareOptions &opts, double *along = nullptr) {
  if (x.kind != y.kind) return false;
  if (opts.compareFeed && x.kind != RecordKind::Rapid && std::fabs(x.feed - y.feed) > 1e-6 * std::max(1.0, std::fabs(x.feed)))
    return false;
  const double tol = opts.tolerance;
  if (x.kind == RecordKind::Rapid && opts.rapidLegs) {
    for (int k = 0; k < kAxes; ++k)
      if (y.end[k] < std::min(x.start[k], x.end[k]) - tol || y.end[k] > std::max(x.start[k], x.end[k]) + tol) return false;
    return true;
  }
  if (x.kind == RecordKind::Rapid || x.kind == RecordKind::Linear) {
    double len2 = 0, t = 0;
    for (int k = 0; k < kAxes; ++k) {
      double d = x.end[k] - x.start[k];
      len2 += d * d;
      t += (y.end[k] - x.start[k]) * d;
    }
    if (len2 <= 0) return false;
    t /= len2;
    if (t <= 0 || t >= 1) return false;
    for (int k = 0; k < kAxes; ++k)
      if (std::fabs(x.start[k] + (x.end[k] - x.start[k]) * t - y.end[k]) > tol) return false;
    if (along) *along = t;
    return true;
  }
  if (x.kind != RecordKind::Arc || x.tiltedArc() || y.tiltedArc() || x.plane != y.plane || (x.turns >= 0) != (y.turns >= 0))
    return false;
  int a, b;
  arcAxes(x.plane, a, b);
  if (std::fabs(x.center[a] - y.center[a]) > tol || std::fabs(x.center[b] - y.center[b]) > tol) return false;
  double rx = std::hypot(x.start[a] - x.center[a], x.start[b] - x.center[b]);
  return std::fabs(std::hypot(y.end[a] - x.center[a], y.end[b] - x.center[b]) - rx) <= tol;
}

// The machine state a cutting move runs with: the tool in the spindle, the spindle's direction
// and speed (with its CSS mode), the coolant. Where translators place the commands between two
// moves is theirs to choose; the state each move runs in is not.
struct MachineState {
  long tool = -1;  // none loaded yet
  int spindle = 0;  // 0 stopped, 1 cw, 2 ccw
  double speed = 0;
  int speedMode = 0;  // SpindleMode ivalue
  bool flood = false, mist = false;

  void apply(const MotionRecord &r) {
    switch (r.kind) {
    case RecordKind::ToolChange: tool = r.ivalue; break;
    case RecordKind::SpindleSpeed: speed = r.value; break;
    case RecordKind::SpindleCW: spindle = 1; break;
    case RecordKind::SpindleCCW: spindle = 2; break;
    case RecordKind::SpindleStop: case RecordKind::SpindleOrient: spindle = 0; break;
    case RecordKind::SpindleMode: speedMode = (int)r.ivalue; break;
    case RecordKind::CoolantFlood: flood = r.ivalue != 0; break;
    case RecordKind::CoolantMist: mist = r.ivalue != 0; break;
    default: break;
    }
  }
  // What differs, empty when nothing does. The speed counts only while the spindle turns.
  std::string diff(const MachineState &o) const {
    if (tool != o.tool) return fmt::format("tools differ (T{} vs T{})", tool, o.tool);
    static const char *kSpindle[] = {"stopped", "cw", "ccw"};
    if (spindle != o.spindle) return fmt::format("spindle states differ ({} vs {})", kSpindle[spindle], kSpindle[o.spindle]);
    if (spindle && (speedMode != o.speedMode || std::fabs(speed - o.speed) > 1e-6 * std::max(1.0, std::fabs(speed))))
      return fmt::format("spindle speeds differ (S{} vs S{})", speed, o.speed);
    if (flood != o.flood || mist != o.mist) return "coolant states differ";
    return {};
  }
};

struct PathMove {
  const MotionRecord *r;
  MachineState state;
};

static std::vector<PathMove> pathOf(const std::vector<MotionRecord> &v) {
  std::vector<PathMove> out;
  MachineState s;
  for (auto &r : v) {
    s.apply(r);
    if (isPath(r) && !isShortMove(r, 1e-9)) out.push_back({&r, s});
  }
  return out;
}

bool comparePaths(const std::vector<MotionRecord> &a, const std::vector<MotionRecord> &b,
                  const PathCompareOptions &opts, std::string &report) {
  auto pa = pathOf(a), pb = pathOf(b);
  auto where = [](const MotionRecord &r) { return fmt::format("line {}: {}", r.loc.line, printMotionRecord(r)); };
  // Where one side has a short move the other lacks, it is skipped: the next end point is
  // compared absolutely, so what skipped moves add up to still counts.
  const double shortMove = 2 * opts.tolerance;
  size_t i = 0, j = 0;
  double pieceSweep = 0;  // what the pieces of the current arc of `a` have swept so far
  double pieceAlong = 0;  // how far along the current straight move of `a` its pieces have come (0..1)
  while (i < pa.size() && j < pb.size()) {
    const MotionRecord &x = *pa[i].r, &y = *pb[j].r;
    std::string why;
    // A piece of a split move runs in the machine state of the move it is part of.
    std::string stateWhy =
        !opts.compareState || x.kind == RecordKind::Rapid ? std::string() : pa[i].state.diff(pb[j].state);
    bool sameState = stateWhy.empty();
    if (pieceSweep > 0 && x.kind == RecordKind::Arc && sameState && isPieceOf(x, y, opts)) {
      // The last piece of a split arc: the pieces together sweep what the arc does.
      double swept = pieceSweep + arcSweep(y), want = arcSweep(x);
      bool ends = true;
      for (int k = 0; k < kAxes; ++k) ends &= std::fabs(x.end[k] - y.end[k]) <= opts.tolerance;
      if (ends && std::fabs(swept - want) < 1e-6) {
        pieceSweep = 0;
        ++i, ++j;
        continue;
      }
      if (swept < want - 1e-9 && !ends) {
        pieceSweep = swept;
        ++j;
        continue;
      }
    }
    if (x.kind != y.kind) why = "kinds differ";
    for (int k = 0; k < kAxes && why.empty(); ++k)
      if (std::fabs(x.end[k] - y.end[k]) > opts.tolerance) why = fmt::format("end points differ in {}", kAxisLetters[k]);
    if (why.empty() && x.kind == RecordKind::Arc) {
      // Only the centre's position in the arc plane shapes the path: its component along the
      // axis is a front end's convention (a helix's start or end height), so it is not compared.
      auto nx = x.arcNormal(), ny = y.arcNormal();
      double d[3], along = 0;
      for (int k = 0; k < 3; ++k) along += (d[k] = x.center[k] - y.center[k]) * nx[k];
      for (int k = 0; k < 3 && why.empty(); ++k)
        if (std::fabs(d[k] - along * nx[k]) > opts.tolerance) why = "arc centres differ";
      if (why.empty() && (x.turns != y.turns || x.plane != y.plane)) why = "arc direction, turns or plane differ";
      for (int k = 0; k < 3 && why.empty(); ++k)
        if (std::fabs(nx[k] - ny[k]) > 1e-9) why = "arc plane normals differ";
    }
    if (why.empty() && x.kind == RecordKind::Spline) {
      const SplineData &sx = x.spline(), &sy = y.spline();
      auto near = [&](double u, double v) { return std::fabs(u - v) <= opts.tolerance; };
      // Weights and knots have no unit: relative, within what a printed 9-decimal value keeps.
      auto same = [](const std::vector<double> &u, const std::vector<double> &v, size_t n) {
        for (size_t i = 0; i < n; ++i) {
          double a = u.empty() ? 1 : u[i], b = v.empty() ? 1 : v[i];
          if (std::fabs(a - b) > 1e-8 * std::max(1.0, std::fabs(a))) return false;
        }
        return true;
      };
      if (sx.degree != sy.degree || sx.points.size() != sy.points.size() || !same(sx.weights, sy.weights, sx.count()) ||
          sx.knots.size() != sy.knots.size() || !same(sx.knots, sy.knots, sx.knots.size()))
        why = "spline degree, control point count, weights or knots differ";
      for (size_t i = 0; i < sx.points.size() && why.empty(); ++i)
        for (int k = 0; k < 3; ++k)
          if (!near(sx.points[i][k], sy.points[i][k])) why = "spline control points differ";
    }
    if (why.empty() && x.kind == RecordKind::Dwell && std::fabs(x.value - y.value) > 1e-6) why = "dwell times differ";
    if (why.empty() && x.kind == RecordKind::Thread) {
      // A lead written with fewer digits is the same thread while the drift it adds over the
      // move (length / lead revolutions of it) stays within the position tolerance.
      double lx = threadPathLead(x), ly = threadPathLead(y), len = linearDistance(x);
      if (!(lx > 0) || std::fabs(lx - ly) * len / lx > opts.tolerance) why = "thread leads differ";
      else if (x.sync != y.sync || std::fabs(x.value2 - y.value2) > 1e-6) why = "thread start angles or synchronisation differ";
      else if (std::fabs(threadEndLead(x) - threadEndLead(y)) * len / lx > opts.tolerance) why = "thread lead changes differ";
    }
    if (why.empty() && x.kind == RecordKind::Probe) {
      const ProbeData &px = x.probe(), &py = y.probe();
      for (int k = 0; k < kAxes && why.empty(); ++k)
        if (std::fabs(px.target[k] - py.target[k]) > opts.tolerance) why = fmt::format("probe targets differ in {}", kAxisLetters[k]);
      if (why.empty() && (px.signal != py.signal || px.missIsError != py.missIsError || px.tripped != py.tripped))
        why = "probe signal, miss rule or trip differ";
    }
    // A thread's feed follows from its lead, its slope and the spindle speed (compared above and
    // in the state): a written end point rounded to the axis format changes it a little.
    if (why.empty() && opts.compareFeed && x.kind != RecordKind::Rapid && x.kind != RecordKind::Dwell &&
        x.kind != RecordKind::Thread && std::fabs(x.feed - y.feed) > 1e-6 * std::max(1.0, std::fabs(x.feed)))
      why = "feeds differ";
    if (why.empty()) why = stateWhy;
    if (why.empty()) { ++i, ++j, pieceSweep = pieceAlong = 0; continue; }
    double along = 0;
    if (pieceSweep == 0 && sameState && isPieceOf(x, y, opts, &along)) {
      // A piece of a split move: the rest follow on the same line (forwards) or circle.
      if (x.kind == RecordKind::Arc) {
        pieceSweep = arcSweep(y);
        if (pieceSweep >= arcSweep(x) - 1e-9) pieceSweep = 0;
        else { ++j; continue; }
      } else if (along == 0 || along > pieceAlong) {
        pieceAlong = along;
        ++j;
        continue;
      }
    }
    if (isShortMove(x, shortMove)) { ++i; continue; }
    if (isShortMove(y, shortMove)) { ++j; continue; }
    report = fmt::format("paths differ at motion {}: {}\n  first:  {}\n  second: {}", i + 1, why, where(x), where(y));
    return false;
  }
  while (i < pa.size() && isShortMove(*pa[i].r, shortMove)) ++i;
  while (j < pb.size() && isShortMove(*pb[j].r, shortMove)) ++j;
  if (i != pa.size() || j != pb.size()) {
    report = fmt::format("paths differ in length: {} vs {} motions", pa.size(), pb.size());
    return false;
  }
  return true;
}

}  // namespace ncc
