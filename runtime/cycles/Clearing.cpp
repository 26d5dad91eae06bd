#include "runtime/cycles/Clearing.h"

#include "runtime/cycles/ClipperPaths.h"

#include <algorithm>
#include <cmath>

namespace ncc {

namespace {
constexpr double kScale = kClipperScale;

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


// The ring `d` in from the region's walls; the first (`first`) with its convex corners rounded
// to the corner radius (an opening: in by d + radius, out by the radius).
ClipperLib::Paths ringAt(const ClipperLib::Paths &region, double d, bool first, const ClearingSpec &s) {
  if (!first || !(s.cornerRadius > 0)) return offset(region, -d, s.chordTolerance);
  ClipperLib::Paths in = offset(region, -(d + s.cornerRadius), s.chordTolerance);
  return in.empty() ? in : offset(in, s.cornerRadius, s.chordTolerance);
}

// The region (the contour less the islands, whatever their orientation: the islands all turn
// one way so that overlapping ones merge) and the offsets of its rings, from the wall inward.
bool ringLevels(const ClearingSpec &s, ClipperLib::Paths &region, std::vector<double> &ds,
                std::vector<ClipperLib::Paths> &levels, std::string &err) {
  if (s.area.empty() && s.contour.size() < 3) return err = "a clearing region needs at least three corners", false;
  if (!(s.toolRadius > 0) || !(s.stepover > 0) || s.stepover > 2 * s.toolRadius + 1e-12)
    return err = "the stepover must be greater than 0 and at most the tool diameter", false;
  if (!(s.chordTolerance > 0)) return err = "the chord tolerance must be greater than 0", false;
  ClipperLib::Clipper c;
  region.clear();
  if (!s.area.empty()) {
    for (auto &p : s.area) c.AddPath(toPath(p), ClipperLib::ptSubject, true);
    c.Execute(ClipperLib::ctUnion, region, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  } else {
    ClipperLib::Path outer = toPath(s.contour);
    if (!ClipperLib::Orientation(outer)) ClipperLib::ReversePath(outer);
    c.AddPath(outer, ClipperLib::ptSubject, true);
    for (auto &i : s.islands) {
      ClipperLib::Path p = toPath(i);
      if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
      c.AddPath(p, ClipperLib::ptClip, true);
    }
    c.Execute(ClipperLib::ctDifference, region, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  }
  if (region.empty()) return err = "the islands cover the whole region", false;
  // No ring lies deeper than half the narrower side of the bounding box: refuse a stepover that
  // would need more rings than any machine runs before offsetting that often.
  const ClipperLib::IntRect box = c.GetBounds();
  if (std::min(box.right - box.left, box.bottom - box.top) / kScale / 2 / s.stepover > 20000)
    return err = "too many clearing rings (stepover far too small)", false;
  // First ring: the tool touching the walls (plus the allowance); then inward by the stepover
  // until nothing is left. Each offset is taken from the region, so errors do not accumulate.
  // A stepover wider than the radius can leave material between the sharp corners of two rings
  // or in the middle: then the stepover shrinks until the rings reach everything.
  double step = s.stepover;
  for (int attempt = 0;; ++attempt) {
    levels.clear(), ds.clear();
    double d = s.toolRadius + s.allowance + s.margin;
    for (;; d += step) {
      ClipperLib::Paths ring = ringAt(region, d, levels.empty(), s);
      if (ring.empty()) break;
      levels.push_back(std::move(ring)), ds.push_back(d);
      if (levels.size() > 100000) return err = "too many clearing rings (stepover far too small)", false;
    }
    if (levels.empty()) return err = "the tool does not fit into the region", false;
    // The middle beyond the last ring: a ring every tool radius while some is left.
    for (d += s.toolRadius - step;; d += s.toolRadius) {
      ClipperLib::Paths ring = offset(region, -d, s.chordTolerance);
      if (ring.empty()) break;
      levels.push_back(std::move(ring)), ds.push_back(d);
    }
    // Rings at most a radius apart reach every point between them (a point's distance to the
    // ring further out is at most its depth beyond it): only wider steps need the check.
    if (step <= s.toolRadius || !leavesMaterial(levels, s)) return true;
    if (attempt == 30) return err = "the clearing rings leave material standing", false;
    step *= 0.85;
  }
}

// Point-to-segment distance squared.
double distance2(PlanePoint p, PlanePoint a, PlanePoint b) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], len2 = ux * ux + uy * uy;
  double t = len2 > 0 ? ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = a[0] + t * ux - p[0], dy = a[1] + t * uy - p[1];
  return dx * dx + dy * dy;
}
// Whether segments ab and cd cross (touching counts).
bool crosses(PlanePoint a, PlanePoint b, PlanePoint c, PlanePoint d) {
  auto side = [](PlanePoint o, PlanePoint p, PlanePoint q) {
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
  };
  const double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) && ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0) &&
         std::min(a[0], b[0]) <= std::max(c[0], d[0]) && std::min(c[0], d[0]) <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= std::max(c[1], d[1]) && std::min(c[1], d[1]) <= std::max(a[1], b[1]);
}
}  // namespace

bool clearingRings(const ClearingSpec &s, std::vector<Polygon> &rings, std::string &err) {
  rings.clear();
  ClipperLib::Paths region;
  std::vector<double> ds;
  std::vector<ClipperLib::Paths> levels;
  if (!ringLevels(s, region, ds, levels, err)) return false;
  for (size_t k = levels.size(); k-- > 0;)
    for (auto &p : levels[k]) {
      if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);  // islands' rings too: ccw
      rings.push_back(fromPath(p));
    }
  return true;
}

bool clearingPieces(const ClearingSpec &s, std::vector<RingPiece> &pieces, std::vector<Polygon> &walls,
                    std::string &err) {
  pieces.clear(), walls.clear();
  ClipperLib::Paths region;
  std::vector<double> ds;
  std::vector<ClipperLib::Paths> levels;
  if (!ringLevels(s, region, ds, levels, err)) return false;
  for (auto &p : region) walls.push_back(fromPath(p));
  // Each level again as a tree (outer rings and their holes); a piece's parent is the piece of
  // the level before whose area holds its first corner.
  std::vector<ClipperLib::Path> outers;  // pieces' outer rings, as Clipper paths, by index
  std::vector<std::vector<ClipperLib::Path>> holes;
  size_t levelStart = 0;
  for (double d : ds) {
    ClipperLib::PolyTree tree;  // the level's rings as outer rings and their holes
    if (d == ds[0] && s.cornerRadius > 0) {
      ClipperLib::ClipperOffset co(2.0, s.chordTolerance * kScale);
      co.AddPaths(offset(region, -(d + s.cornerRadius), s.chordTolerance), ClipperLib::jtRound,
                  ClipperLib::etClosedPolygon);
      co.Execute(tree, s.cornerRadius * kScale);
    } else {
      ClipperLib::ClipperOffset co(2.0, s.chordTolerance * kScale);
      co.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
      co.Execute(tree, -d * kScale);
    }
    const size_t first = pieces.size();
    for (ClipperLib::PolyNode *n = tree.GetFirst(); n; n = n->GetNext()) {
      if (n->IsHole()) continue;
      RingPiece piece;
      ClipperLib::Path o = n->Contour;
      if (!ClipperLib::Orientation(o)) ClipperLib::ReversePath(o);
      piece.outer = fromPath(o);
      std::vector<ClipperLib::Path> hs;
      for (ClipperLib::PolyNode *h : n->Childs) {
        ClipperLib::Path p = h->Contour;
        hs.push_back(p);
        if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
        piece.holes.push_back(fromPath(p));
      }
      for (size_t k = levelStart; k < first && !o.empty(); ++k) {
        if (ClipperLib::PointInPolygon(o[0], outers[k]) == 0) continue;
        bool inHole = false;
        for (auto &h : holes[k]) inHole = inHole || ClipperLib::PointInPolygon(o[0], h) == 1;
        if (!inHole) {
          piece.parent = (int)k;
          break;
        }
      }
      pieces.push_back(std::move(piece));
      outers.push_back(std::move(o));
      holes.push_back(std::move(hs));
    }
    levelStart = first;
  }
  return true;
}

bool segmentClear(const std::vector<Polygon> &walls, PlanePoint a, PlanePoint b, double distance) {
  const double d2 = distance * distance;
  for (const Polygon &w : walls)
    for (size_t i = 0; i < w.size(); ++i) {
      const PlanePoint c = w[i], d = w[(i + 1) % w.size()];
      if (crosses(a, b, c, d) || distance2(c, a, b) < d2 || distance2(d, a, b) < d2 || distance2(a, c, d) < d2 ||
          distance2(b, c, d) < d2)
        return false;
    }
  return true;
}

}  // namespace ncc
