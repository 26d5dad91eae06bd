// The machine passport's motion and interpolator rules (seed 004 §3.3 items 5-6, manual
// L1138-1191) for the word-address writers: rapid legs, the maximum linear increment, arcs
// refused by the machine, quadrant splitting. Every rule changes the blocks, not the path the
// machine cuts: a split move's pieces lie on the source's line or circle, and what cannot be
// written without an approximation is refused (ncc writes no chords).
#include "backends/emit/EmitterImpl.h"

#include <cstdio>

namespace ncc::emit::detail {

namespace {

// The pieces of a split move: the first keeps the source's block number, the last its exact stop.
void markPieces(std::vector<MotionRecord> &pieces, const MotionRecord &r) {
  for (size_t k = 0; k < pieces.size(); ++k) {
    if (k > 0) pieces[k].blockNumber = -1;
    if (k + 1 < pieces.size()) pieces[k].exactStop = false;
  }
  if (!pieces.empty()) pieces.back().exactStop = r.exactStop;
}

std::string lengthText(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

// "Rapid moves along XY together": a rapid that moves the third axis and the plane's axes at once
// becomes two legs. The lone axis moves first when it goes up (away from the work: a retract) and
// last when it goes down, so the tool never travels across the part below its start height.
std::vector<MotionRecord> Emitter::rapidLegs(const MotionRecord &r) const {
  if (r.kind != RecordKind::Rapid || st_.rapidSplit == RapidSplit::Together) return {r};
  static const int kLone[] = {-1, 2, 1, 0};  // xy_then_z: Z alone, xz_then_y: Y, zy_then_x: X
  int lone = kLone[(int)st_.rapidSplit];
  bool loneMoves = r.end[lone] != r.start[lone], othersMove = false;
  for (int i = 0; i < kAxes; ++i)
    if (i != lone && r.end[i] != r.start[i]) othersMove = true;
  if (!loneMoves || !othersMove) return {r};
  std::vector<MotionRecord> legs(2, r);
  bool loneFirst = r.end[lone] > r.start[lone];
  AxisVec corner = r.start;  // after the first leg
  if (loneFirst) {
    corner[lone] = r.end[lone];
  } else {
    corner = r.end;
    corner[lone] = r.start[lone];
  }
  legs[0].end = corner;
  legs[1].start = corner;
  markPieces(legs, r);
  return legs;
}

// "Maximum increment per axis": a straight move longer than the limit on an axis becomes the
// fewest equal parts whose written (rounded) increments all stay within every limit.
bool Emitter::incrementParts(const MotionRecord &r, std::vector<MotionRecord> &parts) {
  parts.assign(1, r);
  const auto &limit = st_.maxIncrement;
  if (limit[0] <= 0 && limit[1] <= 0 && limit[2] <= 0) return true;
  auto writtenAt = [&](int i, double v) { return roundTo(written(i, v), fmt(axisClass(i)).decimals); };
  int64_t n = 1;
  for (int i = 0; i < 3; ++i)
    if (limit[i] > 0) n = std::max<int64_t>(n, (int64_t)std::ceil(std::fabs(written(i, r.end[i]) - written(i, r.start[i])) / limit[i] - 1e-9));
  auto pointAt = [&](int64_t k, int64_t of) {
    AxisVec p = r.end;
    if (k < of)
      for (int i = 0; i < kAxes; ++i) p[i] = r.start[i] + (r.end[i] - r.start[i]) * (double)k / (double)of;
    return p;
  };
  auto fits = [&](int64_t of) {
    AxisVec prev = r.start;
    for (int64_t k = 1; k <= of; ++k) {
      AxisVec p = pointAt(k, of);
      for (int i = 0; i < 3; ++i)
        if (limit[i] > 0 && std::fabs(writtenAt(i, p[i]) - writtenAt(i, prev[i])) > limit[i] + 1e-9) return false;
      prev = p;
    }
    return true;
  };
  const int64_t kMaxParts = 100000;  // more blocks than a control's memory holds
  while (n <= kMaxParts && !fits(n)) ++n;
  if (n > kMaxParts) {
    diags_.error(r.loc, "the [" + st_.section + "] max_increment would split this move into more than " +
                            std::to_string(kMaxParts) + " blocks: " + printMotionRecord(sourceOf(r)),
                 "unsupported-code");
    errors_ = true;
    return false;
  }
  parts.clear();
  AxisVec prev = r.start;
  for (int64_t k = 1; k <= n; ++k) {
    MotionRecord p = r;
    p.start = prev;
    p.end = pointAt(k, n);
    prev = p.end;
    parts.push_back(p);
  }
  markPieces(parts, r);
  return true;
}

// A machine without a circular interpolator, or with a radius limit the arc exceeds: GPP would
// cut chords with the passport's standard tolerance; ncc refuses instead (an approximation the
// program did not ask for is never written silently).
std::string Emitter::arcRefusal(const MotionRecord &r) const {
  if (!st_.arcs) return "the machine has no circular interpolator ([" + st_.section + "] arcs = false) and ncc writes no chords";
  if (st_.maxArcRadius <= 0) return {};
  PlaneAxes pa = planeAxes(r.plane);
  double radius = std::hypot(r.start[pa.a] - r.center[pa.a], r.start[pa.b] - r.center[pa.b]);
  if (radius <= st_.maxArcRadius) return {};
  return "radius " + lengthText(radius) + " mm is above [" + st_.section + "] max_arc_radius = " +
         lengthText(st_.maxArcRadius) + " and ncc writes no chords";
}

// "Split into quadrants": one block per quadrant the arc passes through, ending on the source's
// circle at the quadrant boundaries (the points on the plane's axes through the centre); the axes
// off the plane move in proportion to the angle, as along the helix.
void Emitter::quadrantArcs(const MotionRecord &r) {
  PlaneAxes pa = planeAxes(r.plane);
  bool ccw = r.turns >= 0;
  int n = r.turns == 0 ? 1 : std::abs(r.turns);
  double s[2] = {r.start[pa.a], r.start[pa.b]}, e[2] = {r.end[pa.a], r.end[pa.b]};
  double c[2] = {r.center[pa.a], r.center[pa.b]};
  bool sourceFull = std::hypot(e[0] - s[0], e[1] - s[1]) < 1e-9;
  double total = (n - 1) * 2 * kPi + (sourceFull ? 2 * kPi : sweepAngle(s, e, c, ccw));
  double radius = std::hypot(s[0] - c[0], s[1] - c[1]);
  double a0 = std::atan2(s[1] - c[1], s[0] - c[0]);
  // A boundary within one output unit of arc of either end makes no piece of its own.
  double margin = radius > 0 ? std::pow(10.0, -fmt(WordClass::Axis).decimals) / radius : total;
  const double q = kPi / 2;
  double first = ccw ? (std::floor(a0 / q) + 1) * q : (std::ceil(a0 / q) - 1) * q;
  std::vector<MotionRecord> pieces;
  AxisVec from = r.start;
  for (int k = 0;; ++k) {
    double b = first + (ccw ? k : -k) * q, swept = std::fabs(b - a0);
    if (swept >= total - margin) break;
    if (swept <= margin) continue;
    AxisVec at;
    for (int i = 0; i < kAxes; ++i) at[i] = r.start[i] + (r.end[i] - r.start[i]) * swept / total;
    at[pa.a] = c[0] + radius * std::cos(b);
    at[pa.b] = c[1] + radius * std::sin(b);
    MotionRecord p = r;
    p.start = from;
    p.end = at;
    p.turns = ccw ? 1 : -1;
    pieces.push_back(p);
    from = at;
  }
  MotionRecord last = r;
  last.start = from;
  if (!pieces.empty()) last.turns = ccw ? 1 : -1;
  pieces.push_back(last);
  markPieces(pieces, r);
  for (size_t k = 0; k < pieces.size(); ++k)
    arcBlock(pieces[k], pieces[k].end, 1, pieces.size() == 1 && sourceFull);
}

}  // namespace ncc::emit::detail
