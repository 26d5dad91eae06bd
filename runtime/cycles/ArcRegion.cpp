#include "runtime/cycles/ArcRegion.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>

namespace ncc {

namespace {
constexpr double kTwoPi = 6.283185307179586;
constexpr double kProbe = 1e-5;  // mm: a piece's sides are tested this far off it
constexpr double kJoin = 1e-6;   // mm: piece ends this close are one point
constexpr double kSplit = 1e-7;  // mm: split points this close on an element are one
constexpr double kTouch = 1e-9;  // mm: curves this near to touching meet (a tangent point)

Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
Point2 operator*(double k, Point2 a) { return {k * a.x, k * a.y}; }
double dotP(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
double crossP(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
double norm(Point2 a) { return std::hypot(a.x, a.y); }
Point2 leftOf(Point2 t) { return {-t.y, t.x}; }
Point2 direction(Point2 a) {
  const double l = norm(a);
  return l > 0 ? (1 / l) * a : Point2{};
}

double radiusOf(const PathElem &e) { return norm(e.start - e.center); }
double angleOf(Point2 v) { return std::atan2(v.y, v.x); }

// The turn of an arc from its start to its end in its direction, (0, 2 pi]: an end on the start
// is a full circle.
double sweepOf(const PathElem &e) {
  if (norm(e.end - e.start) == 0) return kTwoPi;
  double s = (angleOf(e.end - e.center) - angleOf(e.start - e.center)) * e.dir;
  while (s <= 1e-12) s += kTwoPi;
  while (s > kTwoPi) s -= kTwoPi;
  return s;
}

double lengthOf(const PathElem &e) { return e.arc ? radiusOf(e) * sweepOf(e) : norm(e.end - e.start); }

// The point a fraction t of the way along e (the ends exactly at 0 and 1).
Point2 pointAt(const PathElem &e, double t) {
  if (t <= 0) return e.start;
  if (t >= 1) return e.end;
  if (!e.arc) return e.start + t * (e.end - e.start);
  const double a = angleOf(e.start - e.center) + e.dir * t * sweepOf(e), r = radiusOf(e);
  return e.center + Point2{r * std::cos(a), r * std::sin(a)};
}

// Where p lies along e as a fraction (arcs: by its angle, in a window of a full turn centred on
// the middle of the arc, so points a little before the start or past the end keep their order).
double fractionOf(const PathElem &e, Point2 p) {
  if (!e.arc) {
    const Point2 u = e.end - e.start;
    return dotP(p - e.start, u) / dotP(u, u);
  }
  const double sweep = sweepOf(e);
  double rel = (angleOf(p - e.center) - angleOf(e.start - e.center)) * e.dir;
  while (rel < sweep / 2 - kTwoPi / 2) rel += kTwoPi;
  while (rel >= sweep / 2 + kTwoPi / 2) rel -= kTwoPi;
  return rel / sweep;
}

Point2 tangentAt(const PathElem &e, Point2 p) {
  return e.arc ? e.dir * direction(leftOf(p - e.center)) : direction(e.end - e.start);
}

double distanceToElem(const PathElem &e, Point2 p) {
  const double t = fractionOf(e, p);
  if (t >= 0 && t <= 1) return e.arc ? std::fabs(norm(p - e.center) - radiusOf(e)) : norm(pointAt(e, t) - p);
  return std::min(norm(p - e.start), norm(p - e.end));
}

// Where the full lines and circles of a and b meet (at most two points; a tangent point once).
int curvesMeet(const PathElem &a, const PathElem &b, Point2 out[2]) {
  if (!a.arc && !b.arc) {
    const Point2 u = a.end - a.start, v = b.end - b.start;
    const double den = crossP(u, v);
    if (std::fabs(den) <= 1e-12 * norm(u) * norm(v)) return 0;  // parallel: overlaps come from the ends
    out[0] = a.start + (crossP(b.start - a.start, v) / den) * u;
    return 1;
  }
  if (a.arc != b.arc) {
    const PathElem &l = a.arc ? b : a, &c = a.arc ? a : b;
    const Point2 w = direction(l.end - l.start);
    const Point2 foot = l.start + dotP(c.center - l.start, w) * w;
    // Tangent within kTouch: one point (the square root would turn rounding into two points apart).
    const double h = norm(c.center - foot), r = radiusOf(c);
    if (h > r + kTouch) return 0;
    if (h >= r - kTouch) return out[0] = foot, 1;
    const double k = std::sqrt(r * r - h * h);
    out[0] = foot - k * w, out[1] = foot + k * w;
    return 2;
  }
  const double dc = norm(b.center - a.center), ra = radiusOf(a), rb = radiusOf(b);
  if (dc < 1e-12 || dc > ra + rb + kTouch || dc < std::fabs(ra - rb) - kTouch) return 0;  // concentric: overlaps from the ends
  const Point2 u = (1 / dc) * (b.center - a.center);
  if (dc >= ra + rb - kTouch) return out[0] = a.center + ra * u, 1;                          // touching outside
  if (dc <= std::fabs(ra - rb) + kTouch) return out[0] = a.center + (ra > rb ? ra : -ra) * u, 1;  // touching inside
  const double along = (ra * ra - rb * rb + dc * dc) / (2 * dc), h = std::sqrt(std::max(0.0, ra * ra - along * along));
  const Point2 m = a.center + along * u;
  out[0] = m + h * leftOf(u), out[1] = m - h * leftOf(u);
  return 2;
}

// A candidate element and where it is split.
struct Candidate {
  PathElem e;
  double length;
  std::vector<std::pair<double, Point2>> splits;  // fraction, point
  bool has(Point2 p) const { return distanceToElem(e, p) <= kSplit; }
  void splitAt(Point2 p) {
    const double t = fractionOf(e, p);
    if (t * length > kSplit && (1 - t) * length > kSplit && has(p)) splits.push_back({t, p});
  }
};

bool sameElem(const PathElem &a, const PathElem &b) {
  return a.arc == b.arc && norm(a.start - b.start) <= kJoin && norm(a.end - b.end) <= kJoin &&
         (!a.arc || (a.dir == b.dir && norm(a.center - b.center) <= kJoin));
}

PathElem reversedElem(const PathElem &e) { return {e.arc, e.end, e.start, e.center, -e.dir}; }

// Splits the candidates where they meet and keeps the pieces `side` says bound the region (+1 as
// they run, -1 turned round, 0 not), given a point of the piece and the unit normal to its left;
// a piece kept twice (two candidates along one another) once, both when kept both ways round (the
// region is no wider than a line there).
std::vector<PathElem> keptPieces(std::vector<Candidate> &cs, const std::function<int(Point2, Point2)> &side) {
  for (size_t i = 0; i < cs.size(); ++i)
    for (size_t k = i + 1; k < cs.size(); ++k) {
      Point2 meet[2];
      const int n = curvesMeet(cs[i].e, cs[k].e, meet);
      for (int m = 0; m < n; ++m)
        if (cs[i].has(meet[m]) && cs[k].has(meet[m])) cs[i].splitAt(meet[m]), cs[k].splitAt(meet[m]);
      // Ends on the other element: overlaps along one line or circle, and touching ends.
      for (Point2 p : {cs[k].e.start, cs[k].e.end}) cs[i].splitAt(p);
      for (Point2 p : {cs[i].e.start, cs[i].e.end}) cs[k].splitAt(p);
    }
  std::vector<PathElem> kept;
  for (size_t i = 0; i < cs.size(); ++i) {
    Candidate &c = cs[i];
    std::sort(c.splits.begin(), c.splits.end(), [](auto &a, auto &b) { return a.first < b.first; });
    std::vector<std::pair<double, Point2>> at{{0.0, c.e.start}};
    for (auto &s : c.splits)
      if ((s.first - at.back().first) * c.length > kSplit) at.push_back(s);
    at.push_back({1.0, c.e.end});
    if (at.size() > 2 && (1 - at[at.size() - 2].first) * c.length <= kSplit) at.erase(at.end() - 2);
    for (size_t k = 0; k + 1 < at.size(); ++k) {
      const PathElem p{c.e.arc, at[k].second, at[k + 1].second, c.e.center, c.e.dir};
      // Tested off the middle: a probe on an edge the region has on both sides (two pockets side
      // by side) would be in neither; such edges meet the pieces at round fractions if at all.
      const Point2 mid = pointAt(c.e, at[k].first + 0.4637 * (at[k + 1].first - at[k].first));
      const int way = side(mid, leftOf(tangentAt(c.e, mid)));
      if (way == 0) continue;
      const PathElem piece = way > 0 ? p : reversedElem(p);
      if (std::none_of(kept.begin(), kept.end(), [&](const PathElem &q) { return sameElem(q, piece); })) kept.push_back(piece);
    }
  }
  std::vector<PathElem> once;
  for (const PathElem &e : kept)
    if (std::none_of(kept.begin(), kept.end(), [&](const PathElem &q) { return sameElem(q, reversedElem(e)); })) once.push_back(e);
  return once;
}

// The region lies on exactly one side of the piece through p (tested kProbe to each side).
std::function<int(Point2, Point2)> probeSides(const std::function<bool(Point2)> &inside) {
  return [inside](Point2 p, Point2 n) {
    const bool left = inside(p + kProbe * n), right = inside(p - kProbe * n);
    return left == right ? 0 : left ? 1 : -1;
  };
}

// Whether b goes on along a's line or circle (pieces of one element, or a contour element the
// program wrote in two).
bool joins(const PathElem &a, const PathElem &b) {
  if (a.arc != b.arc || a.dir != b.dir) return false;
  if (a.arc) return norm(a.center - b.center) <= kSplit && std::fabs(radiusOf(a) - radiusOf(b)) <= kSplit;
  const Point2 u = a.end - a.start, v = b.end - b.start;
  return dotP(u, v) > 0 && std::fabs(crossP(u, v)) <= 1e-12 * norm(u) * norm(v);
}

// How the path turns from a into b: by the angle of their tangents, then (tangent) by curvature.
std::pair<double, double> turnInto(const PathElem &a, const PathElem &b) {
  return {turnAngle(endTangent(a), startTangent(b)), b.arc ? b.dir / radiusOf(b) : 0.0};
}

// Links the pieces into loops, at a point where several go on the one turning furthest left (the
// region on the left stays on one side: loops that touch at a point stay two); pieces that go on
// along one line or circle joined again, each element starting where the one before ends.
bool linkLoops(const std::vector<PathElem> &pieces, std::vector<ArcLoop> &out, std::string &err) {
  out.clear();
  std::vector<bool> used(pieces.size());
  for (size_t first = 0; first < pieces.size(); ++first) {
    if (used[first]) continue;
    used[first] = true;
    std::vector<PathElem> loop{pieces[first]};
    for (;;) {
      const PathElem &cur = loop.back();
      int best = -1;
      std::pair<double, double> bestTurn{};
      for (size_t k = 0; k < pieces.size(); ++k) {
        if ((used[k] && k != first) || norm(pieces[k].start - cur.end) > kJoin) continue;
        const auto turn = turnInto(cur, pieces[k]);
        if (best < 0 || turn > bestTurn) best = (int)k, bestTurn = turn;
      }
      if (best < 0)
        return err = fmt::format("the walls do not close near ({:.4f}, {:.4f}) (a degenerate contour)", cur.end.x, cur.end.y),
               false;
      if (best == (int)first) break;
      used[best] = true;
      loop.push_back(pieces[best]);
    }
    // A piece shorter than kJoin is a gap the ends of its neighbours close.
    std::erase_if(loop, [](const PathElem &e) { return lengthOf(e) <= kJoin; });
    if (loop.empty()) continue;
    ArcLoop joined;
    for (size_t k = 0; k < loop.size(); ++k) {
      if (k > 0 && joins(loop[k - 1], loop[k])) joined.back().end = loop[k].end;
      else joined.push_back(loop[k]);
    }
    if (joined.size() > 1 && joins(loop.back(), loop.front())) {
      joined.front().start = joined.back().start;
      joined.pop_back();
    }
    for (size_t k = 0; k < joined.size(); ++k) joined[k].start = joined[(k + joined.size() - 1) % joined.size()].end;
    out.push_back(std::move(joined));
  }
  return true;
}

// Whether p lies in the circular segment between an arc and its chord (a full circle: its disc).
bool inSegment(const PathElem &e, Point2 p) {
  if (norm(p - e.center) >= radiusOf(e)) return false;
  if (norm(e.end - e.start) == 0) return true;
  const Point2 chord = e.end - e.start;
  return (crossP(chord, pointAt(e, 0.5) - e.start) > 0) == (crossP(chord, p - e.start) > 0);
}
}  // namespace

bool insideLoop(const ArcLoop &loop, Point2 p) {
  // The angle each element turns through seen from p: an arc's is its chord's, a full turn more
  // (in its direction) when p lies between the arc and the chord, and a half turn the way round
  // the arc goes when p lies on the chord.
  double turn = 0;
  for (const PathElem &e : loop) {
    const Point2 a = e.start - p, b = e.end - p;
    const double c = crossP(a, b), d = dotP(a, b);
    if (e.arc && std::fabs(c) <= 1e-12 * norm(a) * norm(b) && d < 0)
      turn += crossP(e.end - e.start, pointAt(e, 0.5) - e.start) > 0 ? -kTwoPi / 2 : kTwoPi / 2;
    else
      turn += std::atan2(c, d) + (e.arc && inSegment(e, p) ? e.dir * kTwoPi : 0);
  }
  return std::lround(turn / kTwoPi) != 0;
}

bool ArcRegion::contains(Point2 p) const {
  auto in = [&](const ArcLoop &l) { return insideLoop(l, p); };
  if (formula.root >= 0) return formulaContains(formula, [&](int k) { return in(pockets[k]); });
  const bool pocket = intersect ? std::all_of(pockets.begin(), pockets.end(), in) : std::any_of(pockets.begin(), pockets.end(), in);
  return pocket && std::none_of(islands.begin(), islands.end(), in);
}

bool regionBoundary(const ArcRegion &region, std::vector<ArcLoop> &out, std::string &err) {
  std::vector<Candidate> cs;
  for (const auto *loops : {&region.pockets, &region.islands})
    for (const ArcLoop &l : *loops)
      for (const PathElem &e : l)
        if (lengthOf(e) > kSplit) cs.push_back({e, lengthOf(e), {}});
  return linkLoops(keptPieces(cs, probeSides([&](Point2 p) { return region.contains(p); })), out, err);
}

double distanceTo(const std::vector<ArcLoop> &loops, Point2 p) {
  double best = 1e300;
  for (const ArcLoop &l : loops)
    for (const PathElem &e : l) best = std::min(best, distanceToElem(e, p));
  return best;
}

bool ToolCentreRegion::contains(Point2 p) const { return region.contains(p) && distanceTo(boundary, p) >= d - 1e-9; }

bool toolCentreBoundary(const ToolCentreRegion &centres, std::vector<ArcLoop> &out, std::string &err) {
  const double d = centres.d;
  std::vector<Candidate> cs;
  auto add = [&](const PathElem &e) {
    if (lengthOf(e) > kSplit) cs.push_back({e, lengthOf(e), {}});
  };
  for (const ArcLoop &l : centres.boundary)
    for (size_t i = 0; i < l.size(); ++i) {
      const PathElem &e = l[i], &next = l[(i + 1) % l.size()];
      // The region is on the left: the tool centre d to the left (an arc the tool is inside of
      // shrinks, and vanishes when the tool does not fit in it).
      if (!e.arc || offsetRadius(e, 1, d) > kSplit) add({e.arc, offsetStart(e, 1, d), offsetEnd(e, 1, d), e.center, e.dir});
      // A right turn is a corner the tool goes round (a reversal may be either: the pieces decide).
      const double turn = turnAngle(endTangent(e), startTangent(next));
      if (turn < -1e-9 || std::fabs(turn) > kTwoPi / 2 - 1e-9) add({true, offsetEnd(e, 1, d), offsetStart(next, 1, d), e.end, -1});
    }
  // Every candidate point is d from the element it comes from, with the tool-centre region on its
  // left: a piece stays where no other part of the boundary is nearer (to within kTouch; a test
  // to each side would misjudge offsets that meet at a very small angle) and it is in the region.
  auto side = [&](Point2 p, Point2) { return centres.region.contains(p) && distanceTo(centres.boundary, p) >= d - kTouch ? 1 : 0; };
  return linkLoops(keptPieces(cs, side), out, err);
}

}  // namespace ncc
