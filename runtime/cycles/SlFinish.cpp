#include "runtime/cycles/SlFinish.h"

#include "runtime/cycles/ArcRegion.h"
#include "runtime/cycles/Mill.h"
#include "runtime/cycles/Pocket.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
constexpr double kTwoPi = 6.283185307179586;

PlanePoint pp(Point2 p) { return {p.x, p.y}; }
Point2 add(Point2 a, Point2 d, double k) { return {a.x + k * d.x, a.y + k * d.y}; }
double dist(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The turn of an arc from start to end in its direction, (0, 2 pi] (an end on the start: a full turn).
double sweep(const PathElem &e) {
  double a0 = std::atan2(e.start.y - e.center.y, e.start.x - e.center.x);
  double a1 = std::atan2(e.end.y - e.center.y, e.end.x - e.center.x);
  double s = (a1 - a0) * e.dir;
  while (s <= 1e-12) s += kTwoPi;
  while (s > kTwoPi + 1e-12) s -= kTwoPi;
  return s;
}

PathElem line(Point2 a, Point2 b) { return {false, a, b, {}, 0}; }

std::vector<PathElem> reversedPath(const std::vector<PathElem> &p) {
  std::vector<PathElem> r;
  for (size_t i = p.size(); i-- > 0;) r.push_back({p[i].arc, p[i].end, p[i].start, p[i].center, -p[i].dir});
  return r;
}

// The tool-centre path of an open contour (TrainJob): each element offset, convex corners an
// arc about the programmed corner, concave ones trimmed where the offsets meet. An element the
// trimming turns round (the tool too big for it) is an error: the path would cut into the contour.
bool trainPath(const std::vector<PathElem> &e, int side, double r, double ext, std::vector<PathElem> &out,
               std::string &err) {
  out.clear();
  auto offset = [&](size_t i, PathElem &o) {
    o = e[i];
    o.start = offsetStart(e[i], side, r), o.end = offsetEnd(e[i], side, r);
    if (e[i].arc && offsetRadius(e[i], side, r) <= 1e-9)
      return err = fmt::format("the tool (radius plus Q3 {:g}) does not fit inside contour element {} (an arc)", r, i + 1), false;
    return true;
  };
  std::vector<PathElem> off(e.size());
  for (size_t i = 0; i < e.size(); ++i)
    if (!offset(i, off[i])) return false;
  if (ext > 0) out.push_back(line(add(off[0].start, startTangent(e[0]), -ext), off[0].start));
  std::vector<CornerKind> corner(e.size());  // at the end of element i
  for (size_t i = 0; i + 1 < e.size() && r > 0; ++i) {  // r 0 (cycle 270's R0): the contour itself
    const PathElem &a = e[i], &b = e[i + 1];
    const PathElem &decides = b.arc ? b : a;  // rs274's rule near a reversal (CutterComp.h)
    corner[i] = cornerKind(turnAngle(endTangent(a), startTangent(b)), side, decides.arc && side * decides.dir < 0);
    if (corner[i] != CornerKind::Concave) continue;
    Point2 p;
    if (!offsetIntersection(a, b, side, r, p))
      return err = fmt::format("the offsets of contour elements {} and {} do not meet (the tool is too big)", i + 1, i + 2), false;
    off[i].end = off[i + 1].start = p;
  }
  for (size_t i = 0; i < e.size(); ++i) {
    // Trimmed the wrong way round: the element is shorter than the tool needs.
    const PathElem &o = off[i], &p = e[i];
    const bool reversed = o.arc ? sweep(o) > sweep(p) + 1e-9
                                : (o.end.x - o.start.x) * (p.end.x - p.start.x) + (o.end.y - o.start.y) * (p.end.y - p.start.y) <= 0;
    if (reversed) return err = fmt::format("contour element {} is too short for the tool (radius plus Q3 {:g})", i + 1, r), false;
    out.push_back(o);
    if (i + 1 < e.size() && dist(o.end, off[i + 1].start) > 1e-9)
      out.push_back(corner[i] == CornerKind::Convex ? PathElem{true, o.end, off[i + 1].start, e[i].end, -side}
                                                    : line(o.end, off[i + 1].start));
  }
  if (ext > 0) out.push_back(line(out.back().end, add(out.back().end, endTangent(e.back()), ext)));
  return true;
}

// Cycle 270's approach before the path and departure after it (TrainJob), on the tool's side n.
void addApproach(std::vector<PathElem> &path, int side, const TrainJob &j) {
  if (j.approach == 0) return;
  auto normal = [&](Point2 d) { return side >= 0 ? Point2{-d.y, d.x} : Point2{d.y, -d.x}; };
  auto leg = [&](Point2 at, Point2 d, int way) -> PathElem {  // way -1: into `at`, +1: out of it
    const Point2 n = normal(d);
    if (j.approach == 2) return way < 0 ? line(add(at, d, -j.distance), at) : line(at, add(at, d, j.distance));
    if (j.approach == 3) return way < 0 ? line(add(at, n, j.distance), at) : line(at, add(at, n, j.distance));
    const Point2 c = add(at, n, j.radius);
    const int dir = side >= 0 ? 1 : -1;  // the centre left of the motion: counter-clockwise
    const double a = way * dir * j.angle * kTwoPi / 360, ux = at.x - c.x, uy = at.y - c.y;
    const Point2 p{c.x + ux * std::cos(a) - uy * std::sin(a), c.y + ux * std::sin(a) + uy * std::cos(a)};
    return way < 0 ? PathElem{true, p, at, c, dir} : PathElem{true, at, p, c, dir};
  };
  const PathElem in = leg(path.front().start, startTangent(path.front()), -1);
  const PathElem out = leg(path.back().end, endTangent(path.back()), 1);
  path.insert(path.begin(), in);
  path.push_back(out);
}

void runPath(Mill &mill, const std::vector<PathElem> &path, double level, double f) {
  for (const PathElem &s : path)
    s.arc ? mill.arc(pp(s.end), pp(s.center), s.dir > 0, level, f) : mill.feed(pp(s.end), level, f);
}
}  // namespace

bool contourTrain(const std::vector<PathElem> &elems, const TrainJob &j, std::vector<CycleStep> &out, std::string &err) {
  if (elems.empty()) return err = "the contour has no element after its first point", false;
  if (!(j.depth > 0)) return err = "the depth must be greater than 0", false;
  if (j.offset <= 0 && j.side != 0) return err = "the tool radius plus the side allowance Q3 must be greater than 0", false;
  if (j.height < j.surface) return err = "the clearance height Q7 lies below the surface Q5", false;
  std::vector<PathElem> fwd, rev;
  if (!trainPath(elems, j.side, j.offset, j.extension, fwd, err)) return false;
  if (!trainPath(reversedPath(elems), -j.side, j.offset, j.extension, rev, err)) return false;
  addApproach(fwd, j.side, j), addApproach(rev, -j.side, j);
  auto level = [&](double t) { return j.surface - t; };
  Mill mill(out, j.plane, {0, 0}, 0, -1, j.at);
  double cut = 0;  // the depth cut so far
  bool forward = j.forward;
  const std::vector<double> levels = entry::infeeds(j.infeed, j.depth);
  for (size_t k = 0; k < levels.size(); ++k) {
    const std::vector<PathElem> &path = forward ? fwd : rev;
    const PlanePoint start = pp(path.front().start);
    if (k == 0 || !j.alternate) {  // over the start at the clearance height, at rapid down to the cut depth
      mill.go(start, j.height);
      mill.rapid(start, level(cut));
    }
    mill.feed(start, level(levels[k]), j.plungeFeed);
    runPath(mill, path, level(levels[k]), j.feed);
    cut = levels[k];
    if (j.alternate) forward = !forward;
  }
  mill.up(j.height);
  return true;
}

namespace {
Point2 xy(PlanePoint p) { return {p[0], p[1]}; }

// A captured sub-contour as exact elements (its zero-length lines dropped).
ArcLoop arcLoop(const RegionLoop &l) {
  ArcLoop out;
  Point2 from = xy(l.start);
  for (const PathSeg &s : l.segs) {
    const Point2 to = xy(s.end);
    if (s.arc) out.push_back({true, from, to, xy(s.centre), s.ccw ? 1 : -1});
    else if (dist(from, to) > 1e-9) out.push_back(line(from, to));
    from = to;
  }
  return out;
}

// The SL contour's region from its sub-contours, by the rule slArea applies to their polygons.
ArcRegion arcRegion(const std::vector<SubContour> &subs) {
  ArcRegion r;
  const SubContour *first = nullptr;
  for (const SubContour &s : subs) {
    (s.pocket ? r.pockets : r.islands).push_back(arcLoop(s.loop));
    if (s.pocket && !first) first = &s;
  }
  for (size_t k = 1; k < r.pockets.size(); ++k) r.intersect = r.intersect || insideLoop(r.pockets[k], xy(first->start));
  return r;
}

// The approach radius that fits: the tool radius, halved until the half circle through the start
// and its diameter lie where the tool centre may be (0: none fits, a vertical plunge).
double approachRadius(const ToolCentreRegion &centres, Point2 s, Point2 d, Point2 n, double r) {
  for (int tries = 0; tries < 7; ++tries, r /= 2) {
    const Point2 c = add(s, n, r);
    bool fits = true;
    for (int k = 1; k < 24 && fits; ++k) {  // the half circle from C - r d through S to C + r d, and C - r d … C + r d
      const double a = kTwoPi / 2 * k / 24;
      const Point2 onArc = add(add(c, d, -r * std::cos(a)), n, -r * std::sin(a));
      fits = centres.contains(onArc) && centres.contains(add(c, d, r * (2.0 * k / 24 - 1)));
    }
    if (fits && centres.contains(add(c, d, -r)) && centres.contains(add(c, d, r))) return r;
  }
  return 0;
}

double elemLength(const PathElem &e) { return e.arc ? dist(e.start, e.center) * sweep(e) : dist(e.start, e.end); }

// The middle of an element, and the element split there.
Point2 middle(const PathElem &e) {
  if (!e.arc) return {(e.start.x + e.end.x) / 2, (e.start.y + e.end.y) / 2};
  const double a = std::atan2(e.start.y - e.center.y, e.start.x - e.center.x) + e.dir * sweep(e) / 2;
  const double r = dist(e.start, e.center);
  return {e.center.x + r * std::cos(a), e.center.y + r * std::sin(a)};
}

// A wall's start: the middle of its longest straight element (a clean tangent; none: of its
// longest arc), of equal ones the nearest `here`; the distance to it and the element's index.
std::pair<double, size_t> wallStart(const ArcLoop &ring, PlanePoint here) {
  auto straight = [](const PathElem &e) { return !e.arc; };
  const bool lines = std::any_of(ring.begin(), ring.end(), straight);
  double longest = 0;
  for (const PathElem &e : ring)
    if (!lines || !e.arc) longest = std::max(longest, elemLength(e));
  std::pair<double, size_t> best{1e300, 0};
  for (size_t i = 0; i < ring.size(); ++i) {
    if ((lines && ring[i].arc) || elemLength(ring[i]) < longest - 1e-6) continue;
    const Point2 m = middle(ring[i]);
    const double d = std::hypot(m.x - here[0], m.y - here[1]);
    if (d < best.first - 1e-9) best = {d, i};
  }
  return best;
}

// The ring from the middle of element k round to it again; arcs over a half turn cut in two at
// their middle, so that no arc move ends near its start (where a full circle and a sliver of
// one are told apart by rounding).
ArcLoop fromMiddle(const ArcLoop &ring, size_t k) {
  const PathElem &e = ring[k];
  const Point2 m = middle(e);
  ArcLoop turned{{e.arc, m, e.end, e.center, e.dir}}, out;
  for (size_t i = 1; i < ring.size(); ++i) turned.push_back(ring[(k + i) % ring.size()]);
  turned.push_back({e.arc, e.start, m, e.center, e.dir});
  for (const PathElem &t : turned) {
    if (t.arc && sweep(t) > kTwoPi / 2) {
      const Point2 h = middle(t);
      out.push_back({true, t.start, h, t.center, t.dir});
      out.push_back({true, h, t.end, t.center, t.dir});
    } else {
      out.push_back(t);
    }
  }
  return out;
}
}  // namespace

bool sideFinish(const PocketRegion &region, const SideFinishJob &j, std::vector<CycleStep> &out, std::string &err) {
  if (!(j.depth > 0)) return err = "the depth must be greater than 0", false;
  if (j.infeed < 0) return err = "the infeed must not be negative", false;
  if (j.clearance < 0) return err = "the set-up clearance must not be negative", false;
  if (j.height < j.surface + j.clearance) return err = "the clearance height lies below the set-up clearance", false;
  if (region.subs.empty()) return err = "side finishing needs an SL contour", false;
  // The polygons' boolean only checks the contour as cycles 21-23 do (the same messages); the walls
  // come from the exact elements.
  std::vector<Polygon> area;
  const bool formula = !region.formula.empty();
  if (!(formula ? formulaArea(region, kRegionChordTolerance, area, err) : slArea(region.subs, area, err))) return false;
  ArcRegion exact = arcRegion(region.subs);  // a formula's captures are all pockets: one loop each, in order
  if (formula && !buildFormula(region.formula, exact.formula, err)) return false;
  std::vector<ArcLoop> boundary, walls;
  if (!regionBoundary(exact, boundary, err)) return false;
  const ToolCentreRegion centres{exact, boundary, j.toolRadius + j.finishAllowance};
  if (!toolCentreBoundary(centres, walls, err)) return false;
  if (walls.empty())
    return err = fmt::format("the tool (its radius plus Q14: {:g}) does not fit into the contour", centres.d), false;
  // The walls have the region on their left: counter-clockwise outer walls and clockwise islands'
  // are climb milling with M3; up-cut runs them the other way round.
  if (!j.ccw)
    for (ArcLoop &w : walls) w = reversedPath(w);
  auto level = [&](double t) { return j.surface - t; };
  const std::vector<double> levels = entry::infeeds(j.infeed, j.depth);
  Mill mill(out, j.plane, {0, 0}, 0, -1, j.at);
  std::vector<bool> done(walls.size());
  for (size_t left = walls.size(); left > 0; --left) {
    // The wall whose start is nearest the tool next.
    size_t best = 0, bestElem = 0;
    double bestD = 1e300;
    for (size_t w = 0; w < walls.size(); ++w) {
      if (done[w]) continue;
      const auto [d, i] = wallStart(walls[w], mill.here());
      if (d < bestD - 1e-9) bestD = d, best = w, bestElem = i;
    }
    done[best] = true;
    const ArcLoop ring = fromMiddle(walls[best], bestElem);
    const Point2 S = ring.front().start, d = startTangent(ring.front());
    // The free side (the region's inside) lies left of a climb ring, right of an up-cut one.
    const Point2 nrm = j.ccw ? Point2{-d.y, d.x} : Point2{d.y, -d.x};
    const double rho = approachRadius(centres, S, d, nrm, j.toolRadius);
    const Point2 C = add(S, nrm, rho), P0 = add(C, d, -rho), P1 = add(C, d, rho);
    mill.go(pp(P0), j.height);
    mill.rapid(pp(P0), level(-j.clearance));
    double cut = 0;
    for (double t : levels) {
      // The helix starts Q6/25 above the level, at most the level's own infeed (L9708-L9712).
      const double h = rho > 0 ? std::min(j.clearance / 25, t - cut) : 0;
      if (mill.here() != pp(P0)) mill.feed(pp(P0), mill.level(), j.feed);
      mill.feed(pp(P0), level(t) + h, j.plungeFeed);
      if (rho > 0) mill.arc(pp(S), pp(C), j.ccw, level(t), j.feed);
      runPath(mill, ring, level(t), j.feed);
      if (rho > 0) mill.arc(pp(P1), pp(C), j.ccw, level(t) + h, j.feed);
      cut = t;
    }
    mill.up(j.height);
  }
  return true;
}

}  // namespace ncc
