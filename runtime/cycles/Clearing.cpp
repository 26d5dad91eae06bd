#include "runtime/cycles/Clearing.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>

namespace ncc {

namespace {
// Clipper works on integers: 1e-6 mm resolution keeps rounding far below any machine's.
constexpr double kScale = 1e6;

ClipperLib::Path toPath(const Polygon &p) {
  ClipperLib::Path out;
  for (auto &q : p) out.push_back({(ClipperLib::cInt)std::llround(q[0] * kScale), (ClipperLib::cInt)std::llround(q[1] * kScale)});
  return out;
}

Polygon fromPath(const ClipperLib::Path &p) {
  Polygon out;
  for (auto &q : p) out.push_back({q.X / kScale, q.Y / kScale});
  return out;
}

ClipperLib::Paths offset(const ClipperLib::Paths &region, double by, double tol) {
  ClipperLib::ClipperOffset co(2.0, tol * kScale);
  co.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::Paths out;
  co.Execute(out, by * kScale);
  return out;
}
// Whether the tool, run along the rings, leaves material it could reach: the first ring's area
// widened by the radius less what the rings sweep, ignoring slivers of a few chord tolerances.
bool leavesMaterial(const std::vector<ClipperLib::Paths> &levels, const ClearingSpec &s) {
  ClipperLib::Paths reach = offset(levels[0], s.toolRadius, s.chordTolerance), swept, rest;
  ClipperLib::ClipperOffset co(2.0, s.chordTolerance * kScale);
  for (auto &l : levels) co.AddPaths(l, ClipperLib::jtRound, ClipperLib::etClosedLine);
  co.Execute(swept, s.toolRadius * kScale);
  ClipperLib::Clipper c;
  c.AddPaths(reach, ClipperLib::ptSubject, true);
  c.AddPaths(swept, ClipperLib::ptClip, true);
  c.Execute(ClipperLib::ctDifference, rest, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return !offset(rest, -5 * s.chordTolerance, s.chordTolerance).empty();
}
}  // namespace

bool clearingRings(const ClearingSpec &s, std::vector<Polygon> &rings, std::string &err) {
  rings.clear();
  if (s.contour.size() < 3) return err = "a clearing region needs at least three corners", false;
  if (!(s.toolRadius > 0) || !(s.stepover > 0) || s.stepover > 2 * s.toolRadius + 1e-12)
    return err = "the stepover must be greater than 0 and at most the tool diameter", false;
  if (!(s.chordTolerance > 0)) return err = "the chord tolerance must be greater than 0", false;
  // The region: the contour less the islands, whatever their orientation.
  ClipperLib::Clipper c;
  ClipperLib::Path outer = toPath(s.contour);
  if (!ClipperLib::Orientation(outer)) ClipperLib::ReversePath(outer);
  c.AddPath(outer, ClipperLib::ptSubject, true);
  for (auto &i : s.islands) {
    ClipperLib::Path p = toPath(i);
    c.AddPath(p, ClipperLib::ptClip, true);
  }
  ClipperLib::Paths region;
  c.Execute(ClipperLib::ctDifference, region, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  if (region.empty()) return err = "the islands cover the whole region", false;
  // First ring: the tool touching the walls (plus the allowance); then inward by the stepover
  // until nothing is left. Each offset is taken from the region, so errors do not accumulate.
  // A stepover wider than the radius can leave material between the sharp corners of two rings
  // or in the middle: then the stepover shrinks until the rings reach everything.
  std::vector<ClipperLib::Paths> levels;
  double step = s.stepover;
  for (int attempt = 0;; ++attempt) {
    levels.clear();
    double d = s.toolRadius + s.allowance;
    for (;; d += step) {
      ClipperLib::Paths ring = offset(region, -d, s.chordTolerance);
      if (ring.empty()) break;
      levels.push_back(std::move(ring));
      if (levels.size() > 100000) return err = "too many clearing rings (stepover far too small)", false;
    }
    if (levels.empty()) return err = "the tool does not fit into the region", false;
    // The middle beyond the last ring: a ring every tool radius while some is left.
    for (d += s.toolRadius - step;; d += s.toolRadius) {
      ClipperLib::Paths ring = offset(region, -d, s.chordTolerance);
      if (ring.empty()) break;
      levels.push_back(std::move(ring));
    }
    if (!leavesMaterial(levels, s)) break;
    if (attempt == 30) return err = "the clearing rings leave material standing", false;
    step *= 0.85;
  }
  for (size_t k = levels.size(); k-- > 0;)
    for (auto &p : levels[k]) {
      if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);  // islands' rings too: ccw
      rings.push_back(fromPath(p));
    }
  return true;
}

}  // namespace ncc
