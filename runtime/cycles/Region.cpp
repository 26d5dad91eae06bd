#include "runtime/cycles/Region.h"

#include "runtime/Geometry.h"
#include "runtime/cycles/ClipperPaths.h"
#include "runtime/cycles/Hole.h"
#include "runtime/cycles/Mill.h"
#include "runtime/cycles/Pocket.h"


#include <algorithm>
#include <cmath>

namespace ncc {

namespace {
constexpr double kScale = kClipperScale;
constexpr double kSame = 1e-6;  // mm: two captured points this close are one

bool same(PlanePoint a, PlanePoint b) { return std::hypot(a[0] - b[0], a[1] - b[1]) <= kSame; }

RegionLoop reversed(const RegionLoop &l) {
  RegionLoop r;
  r.start = l.start;
  for (size_t i = l.segs.size(); i-- > 0;)
    r.segs.push_back({i > 0 ? l.segs[i - 1].end : l.start, l.segs[i].arc, l.segs[i].centre, !l.segs[i].ccw});
  return r;
}

// The nearest point of the closed ring `v` to `p`: the index of the edge (v[i], v[i+1]) and the point.
size_t nearestOnRing(const Polygon &v, PlanePoint p, PlanePoint &q) {
  double best = 1e300;
  size_t at = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const PlanePoint a = v[i], b = v[(i + 1) % v.size()];
    const double ux = b[0] - a[0], uy = b[1] - a[1], len2 = ux * ux + uy * uy;
    const double t = len2 > 0 ? std::clamp(((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / len2, 0.0, 1.0) : 0;
    const PlanePoint c{a[0] + t * ux, a[1] + t * uy};
    const double d = std::hypot(c[0] - p[0], c[1] - p[1]);
    if (d < best) best = d, at = i, q = c;
  }
  return at;
}

double distanceTo(const Polygon &v, PlanePoint p) {
  PlanePoint q;
  nearestOnRing(v, p, q);
  return std::hypot(q[0] - p[0], q[1] - p[1]);
}

// Builds the route: pieces visited children first (nearest first), each piece's rings nearest
// first, every ring from its point nearest the tool.
struct Router {
  const std::vector<RingPiece> &pieces;
  const std::vector<Polygon> &walls;
  std::vector<std::vector<int>> children;
  bool ccw;
  double keep;
  PlanePoint here;
  std::vector<RoughPass> &passes;

  void cut(Polygon ring, bool hole) {
    if (hole == ccw) std::reverse(ring.begin(), ring.end());  // rings come counter-clockwise
    PlanePoint q;
    const size_t i = nearestOnRing(ring, here, q);
    if (passes.empty() || !segmentClear(walls, here, q, keep)) passes.emplace_back();
    std::vector<PlanePoint> &path = passes.back().path;
    if (path.empty() || !same(path.back(), q)) path.push_back(q);
    const size_t n = ring.size();
    for (size_t k = 1; k <= n; ++k)
      if (!same(path.back(), ring[(i + k) % n])) path.push_back(ring[(i + k) % n]);
    if (!same(path.back(), q)) path.push_back(q);
    here = q;
  }
  // The next of `from` to visit: the nearest not done (-1: none).
  int nearest(const std::vector<int> &from, const std::vector<bool> &done) const {
    int best = -1;
    double bestD = 1e300;
    for (int k : from)
      if (!done[k]) {
        double d = distanceTo(pieces[k].outer, here);
        if (d < bestD) bestD = d, best = k;
      }
    return best;
  }
  void visit(int k, std::vector<bool> &done) {
    done[k] = true;
    for (int c; (c = nearest(children[k], done)) >= 0;) visit(c, done);
    std::vector<const Polygon *> rings{&pieces[k].outer};
    for (auto &h : pieces[k].holes) rings.push_back(&h);
    std::vector<bool> cut_(rings.size());
    for (size_t left = rings.size(); left > 0; --left) {
      size_t best = 0;
      double bestD = 1e300;
      for (size_t r = 0; r < rings.size(); ++r)
        if (!cut_[r])
          if (double d = distanceTo(*rings[r], here); d < bestD) bestD = d, best = r;
      cut_[best] = true;
      cut(*rings[best], best > 0);
    }
  }
};
}  // namespace

namespace {
// Closed from the start, or the first move only led to the contour's first point (then dropped).
bool closeLoop(RegionLoop &loop, std::string &err) {
  if (loop.segs.empty()) return err = "a region contour needs at least one move", false;
  if (!same(loop.segs.back().end, loop.start)) {
    if (loop.segs.size() < 2 || !same(loop.segs.back().end, loop.segs.front().end))
      return err = "a region contour must be closed: it must end where it begins", false;
    loop.start = loop.segs.front().end;
    loop.segs.erase(loop.segs.begin());
  }
  loop.segs.back().end = loop.start;
  return true;
}

bool loopPolygon(const RegionLoop &loop, bool island, double tol, Polygon &out, std::string &err);

ClipperLib::Paths paths(const std::vector<const Polygon *> &ps) {
  ClipperLib::Paths out;
  for (auto *p : ps) out.push_back(toPath(*p));
  return out;
}
}  // namespace

bool subContour(RegionLoop loop, int side, double tol, SubContour &out, std::string &err) {
  if (side != 1 && side != 2)
    return err = "an SL sub-contour needs RL or RR: with the direction they make it a pocket or an island", false;
  // The manual's example 09 (L10709-L10851) starts its islands in the middle of an edge and ends
  // them at that edge's far corner: the TNC closes them along the first element's line. Only that
  // is closed here; any other end off the first point is an open contour.
  if (loop.segs.size() >= 3 && !same(loop.segs.back().end, loop.start) && !same(loop.segs.back().end, loop.segs[0].end) &&
      !loop.segs[1].arc) {
    const PlanePoint p0 = loop.segs[0].end, p1 = loop.segs[1].end, q = loop.segs.back().end;
    const double ux = p1[0] - p0[0], uy = p1[1] - p0[1], vx = p0[0] - q[0], vy = p0[1] - q[1];
    const double len = std::hypot(ux, uy) * std::hypot(vx, vy);
    if (len > 0 && std::fabs(ux * vy - uy * vx) <= 1e-9 * len && ux * vx + uy * vy > 0) loop.segs.push_back({p0});
  }
  if (!closeLoop(loop, err)) return false;
  const bool ccw = ClipperLib::Area(toPath(contourPolygon({loop.start, loop.segs}, tol))) > 0;
  out.pocket = (side == 1) == ccw;  // the tool inside: left of a counter-clockwise path
  out.start = loop.start;
  out.loop = loop;
  return loopPolygon(loop, !out.pocket, tol, out.poly, err);
}

bool slArea(const std::vector<SubContour> &subs, std::vector<Polygon> &area, std::string &err) {
  std::vector<const Polygon *> pockets, islands;
  for (auto &s : subs) (s.pocket ? pockets : islands).push_back(&s.poly);
  if (pockets.empty()) return err = "the SL contour has no pocket (RL/RR and the direction make every sub-contour an island)", false;
  // The first pocket starting inside another: their intersection (L9140-L9173), else the union.
  ClipperLib::Paths first = paths({pockets[0]}), rest = paths({pockets.begin() + 1, pockets.end()}), a;
  const SubContour &a0 = *std::find_if(subs.begin(), subs.end(), [](const SubContour &s) { return s.pocket; });
  bool inside = false;
  for (auto &p : rest) inside = inside || ClipperLib::PointInPolygon(toClipper(a0.start), p) == 1;
  if (inside && pockets.size() != 2)
    return err = "the first pocket starts inside another: an intersection, which needs exactly two pockets", false;
  a = inside ? clipPaths(ClipperLib::ctIntersection, first, rest) : clipPaths(ClipperLib::ctUnion, first, rest);
  a = clipPaths(ClipperLib::ctDifference, a, paths(islands));
  area.clear();
  for (auto &p : a) area.push_back(fromPath(p));
  if (area.empty()) return err = "the SL contour encloses no area", false;
  return true;
}

bool closedLoop(RegionLoop &loop, std::string &err) { return closeLoop(loop, err); }

bool regionPolygon(RegionLoop loop, bool island, double tol, Polygon &out, std::string &err) {
  out.clear();
  return closeLoop(loop, err) && loopPolygon(loop, island, tol, out, err);
}

namespace {
bool loopPolygon(const RegionLoop &loop, bool island, double tol, Polygon &out, std::string &err) {
  // Sampled with the region on the left (Mill.h contourPolygon): an outline counter-clockwise,
  // an island clockwise.
  Contour c{loop.start, loop.segs};
  Polygon p = contourPolygon(c, tol);
  if (p.size() < 3 && !(loop.segs.size() == 1 && loop.segs[0].arc))
    return err = "a region contour must enclose an area", false;
  if ((ClipperLib::Area(toPath(p)) > 0) == island) p = contourPolygon({loop.start, reversed(loop).segs}, tol);
  ClipperLib::Paths simple;
  ClipperLib::SimplifyPolygon(toPath(p), simple, ClipperLib::pftNonZero);
  if (simple.size() != 1) return err = "a region contour must not cross itself", false;
  if (std::fabs(ClipperLib::Area(simple[0])) < tol * tol * kScale * kScale)
    return err = "a region contour must enclose an area", false;
  out = std::move(p);
  return true;
}
}  // namespace

bool islandInside(const PocketRegion &r, const Polygon &island, double tol) {
  ClipperLib::Clipper c;
  c.AddPath(toPath(island), ClipperLib::ptSubject, true);
  c.AddPath(toPath(r.outline), ClipperLib::ptClip, true);
  ClipperLib::Paths outside, left;
  c.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  // Slivers of the sampling (an island touching an arc of the outline) do not count.
  ClipperLib::ClipperOffset co(2.0, tol * kScale);
  co.AddPaths(outside, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  co.Execute(left, -2 * tol * kScale);
  return left.empty();
}

bool roughingRoute(const ClearingSpec &spec, bool ccw, PlanePoint from, std::vector<RoughPass> &passes,
                   std::vector<Polygon> &walls, std::string &err) {
  passes.clear();
  std::vector<RingPiece> pieces;
  if (!clearingPieces(spec, pieces, walls, err)) return false;
  Router r{pieces, walls, std::vector<std::vector<int>>(pieces.size()), ccw,
           spec.toolRadius + spec.allowance - 1e-9, from, passes};
  std::vector<int> areas;
  for (size_t k = 0; k < pieces.size(); ++k)
    (pieces[k].parent < 0 ? areas : r.children[pieces[k].parent]).push_back((int)k);
  std::vector<bool> done(pieces.size());
  for (int a; (a = r.nearest(areas, done)) >= 0;) r.visit(a, done);
  return true;
}

namespace {
// The roughing route of the job's tool through the region (an outline less islands, or the SL
// contour's area).
bool regionRoute(const PocketRegion &region, const RegionPocketJob &j, std::vector<RoughPass> &passes,
                 std::vector<Polygon> &walls, std::string &err) {
  ClearingSpec s;
  if (!region.formula.empty() ? !formulaArea(region, j.chordTolerance, s.area, err)
                               : !region.subs.empty() && !slArea(region.subs, s.area, err))
    return false;
  s.contour = region.outline, s.islands = region.islands;
  s.toolRadius = j.toolRadius, s.stepover = j.stepover, s.allowance = j.sideAllowance;
  s.chordTolerance = j.chordTolerance, s.margin = kChordSagFactor * j.chordTolerance;
  s.cornerRadius = j.cornerRadius;
  // An SL route starts nearest the first sub-contour's first point, not the tool: cycle 21's holes
  // are then cycle 22's plunge points wherever the tool stands (L9280-L9282).
  const PlaneAxes ax = planeAxes((Plane)j.plane);
  const PlanePoint from = region.subs.empty() ? PlanePoint{j.at[ax.u], j.at[ax.v]} : region.subs[0].start;
  return roughingRoute(s, j.ccw, from, passes, walls, err);
}

bool checkJob(const RegionPocketJob &j, std::string &err) {
  if (!(j.depth > 0)) return err = "the depth must be greater than 0", false;
  if (j.infeed < 0) return err = "the infeed must not be negative", false;
  if (j.clearance < 0) return err = "the set-up clearance must not be negative", false;
  if (j.floorAllowance < 0 || j.floorAllowance >= j.depth)
    return err = "the floor allowance must be at least 0 and less than the depth", false;
  if (j.sideAllowance < 0) return err = "the side allowance must not be negative", false;
  if (j.cornerRadius < 0) return err = "the corner radius must not be negative", false;
  if (j.height < j.surface + j.clearance) return err = "the clearance height lies below the set-up clearance", false;
  return true;
}
}  // namespace

double pilotReentry(double depth) { return depth <= 30 ? 0.6 : std::min(depth / 50, 7.0); }

bool regionPilot(const PocketRegion &region, const RegionPocketJob &j, std::vector<CycleStep> &out,
                 std::string &err) {
  if (!checkJob(j, err)) return false;
  std::vector<RoughPass> passes;
  std::vector<Polygon> walls;
  if (!regionRoute(region, j, passes, walls, err)) return false;
  const PlaneAxes ax = planeAxes((Plane)j.plane);
  const int d = 3 - ax.u - ax.v;
  const double total = j.depth - j.floorAllowance;
  HoleSpec h;
  h.start = j.surface + j.clearance, h.bottom = j.surface - total, h.retract = j.height;
  h.peck = j.infeed > 0 ? j.infeed : total;
  h.peckFromSet = true, h.peckFrom = j.surface;
  h.breaksPerRetract = 0, h.reentry = pilotReentry(total);
  h.feed = h.firstFeed = j.plungeFeed;
  std::array<double, 3> at = j.at;
  for (const RoughPass &p : passes) {
    Mill mill(out, j.plane, {0, 0}, 0, -1, at);
    mill.go(p.path[0], j.height);
    mill.rapid(p.path[0], h.start);
    holeSteps(h, ax.u, ax.v, d, p.path[0][0], p.path[0][1], out);
    at = out.back().pos;
  }
  return true;
}

bool regionPocket(const PocketRegion &region, const RegionPocketJob &j, std::vector<CycleStep> &out,
                  std::string &err) {
  if (!checkJob(j, err)) return false;
  std::vector<RoughPass> passes;
  std::vector<Polygon> walls;
  if (!regionRoute(region, j, passes, walls, err)) return false;
  const double keep = j.toolRadius + j.sideAllowance - 1e-9;
  auto level = [&](double t) { return j.surface - t; };
  const double safe = level(-j.clearance);
  Mill mill(out, j.plane, {0, 0}, 0, -1, j.at);
  mill.go(passes[0].path[0], j.height);
  mill.up(safe);
  double floor = j.done;  // the depth cut so far
  for (double t : entry::infeeds(j.infeed, j.depth - j.floorAllowance)) {
    for (const RoughPass &p : passes) {
      const PlanePoint entry = p.path[0];
      // Across at the set-up clearance over the last level when the move is clear of the walls,
      // else over the surface (islands reach up to it); then down to that clearance over the floor.
      if (mill.here() != entry) {
        if (segmentClear(walls, mill.here(), entry, keep)) {
          mill.up(level(floor - j.clearance));
          mill.rapid(entry, mill.level());
        } else {
          mill.go(entry, safe);
        }
      }
      mill.up(level(floor - j.clearance));
      mill.feed(entry, level(t), j.plungeFeed);
      for (size_t k = 1; k < p.path.size(); ++k) mill.feed(p.path[k], level(t), j.feed);
    }
    floor = t;
  }
  if (j.retractFeed >= 0) mill.feed(mill.here(), j.height, j.retractFeed > 0 ? j.retractFeed : j.feed);
  else mill.up(j.height);
  return true;
}

}  // namespace ncc
