// Region pockets (runtime/cycles/Region.h) checked by geometry on random pockets with islands:
// every move below the surface is measured against the edges, and no point of it brings the tool into an island or
// through the outline (by more than 1e-6 mm); at the last level the cutting moves sweep all of
// the region less the islands that the tool can reach (a Clipper area test). Also the closing
// and sampling of captured loops, the errors, and the Heidenhain SL sub-contours (pocket or island,
// union, difference, intersection).
#include "runtime/cycles/ClipperPaths.h"
#include "runtime/cycles/Region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {
constexpr double kScale = kClipperScale;

double segDistance(PlanePoint p, PlanePoint a, PlanePoint b) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], len2 = ux * ux + uy * uy;
  const double t = len2 > 0 ? std::clamp(((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / len2, 0.0, 1.0) : 0;
  return std::hypot(a[0] + t * ux - p[0], a[1] + t * uy - p[1]);
}
// The least distance between the move a-b and the polygon's edges (0 when they cross).
double moveDistance(const Polygon &poly, PlanePoint a, PlanePoint b) {
  auto cross = [](PlanePoint o, PlanePoint p, PlanePoint q) { return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]); };
  double d = 1e300;
  for (size_t i = 0; i < poly.size(); ++i) {
    const PlanePoint c = poly[i], e = poly[(i + 1) % poly.size()];
    if ((cross(c, e, a) > 0) != (cross(c, e, b) > 0) && (cross(a, b, c) > 0) != (cross(a, b, e) > 0)) return 0;
    d = std::min({d, segDistance(a, c, e), segDistance(b, c, e), segDistance(c, a, b), segDistance(e, a, b)});
  }
  return d;
}
bool inside(const Polygon &poly, PlanePoint p) {
  return ClipperLib::PointInPolygon(toClipper(p), toPath(poly)) != 0;
}

Polygon regular(PlanePoint c, double r, int n, double phase) {
  Polygon p;
  for (int i = 0; i < n; ++i)
    p.push_back({c[0] + r * std::cos(phase + 2 * M_PI * i / n), c[1] + r * std::sin(phase + 2 * M_PI * i / n)});
  return p;
}

struct Case {
  PocketRegion region;
  RegionPocketJob job;
};

// Runs the job and checks it; false when the tool does not fit (nothing to check).
bool check(const Case &c, const std::string &what) {
  std::vector<CycleStep> steps;
  std::string err;
  if (!regionPocket(c.region, c.job, steps, err)) {
    EXPECT_TRUE(err.find("does not fit") != std::string::npos || err.find("cover") != std::string::npos) << what << ": " << err;
    return false;
  }
  const RegionPocketJob &j = c.job;
  const double keep = j.toolRadius + j.sideAllowance - 1e-6;
  const double last = j.surface - (j.depth - j.floorAllowance);
  std::array<double, 3> at = j.at;
  ClipperLib::Paths cuts;  // the cutting moves at the last level
  bool inRun = false;
  for (const CycleStep &s : steps) {
    EXPECT_NE(s.kind, CycleStepKind::Arc) << what;
    // Below the surface (at either end): both ends in the region and the whole move at least
    // the tool radius plus the allowance off every edge.
    const PlanePoint a{at[0], at[1]}, b{s.pos[0], s.pos[1]};
    if (std::min(at[2], s.pos[2]) < j.surface - 1e-9) {
      bool ok = inside(c.region.outline, a) && inside(c.region.outline, b) && moveDistance(c.region.outline, a, b) >= keep;
      if (!ok) ADD_FAILURE() << what << ": the tool leaves the outline between " << a[0] << " " << a[1] << " and " << b[0] << " " << b[1];
      for (const Polygon &isl : c.region.islands)
        if (ok && (inside(isl, a) || moveDistance(isl, a, b) < keep)) {
          ADD_FAILURE() << what << ": the tool enters an island between " << a[0] << " " << a[1] << " and " << b[0] << " " << b[1];
          ok = false;
        }
      if (!ok) return false;
    }
    // Runs of cutting moves as polylines (one open path each).
    const bool cutting = s.kind == CycleStepKind::Feed && std::fabs(s.pos[2] - last) < 1e-9 && std::fabs(at[2] - last) < 1e-9;
    if (cutting && !inRun) cuts.push_back(toPath(Polygon{a}));
    if (cutting) cuts.back().push_back(toPath(Polygon{b})[0]);
    inRun = cutting;
    at = s.pos;
  }
  EXPECT_NEAR(at[2], j.height, 1e-9) << what << ": the end is not at the clearance height";
  // What the tool can reach: the region less the islands, opened by the tool (less the allowance).
  ClipperLib::Clipper cl;
  cl.AddPath(toPath(c.region.outline), ClipperLib::ptSubject, true);
  for (const Polygon &isl : c.region.islands) {
    ClipperLib::Path p = toPath(isl);
    if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    cl.AddPath(p, ClipperLib::ptClip, true);
  }
  ClipperLib::Paths region, core, reach, swept, rest, left;
  cl.Execute(ClipperLib::ctDifference, region, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  const double tol = 0.005;  // coarser than the rings': the swept area's arcs are chords inside it
  auto offset = [&](const ClipperLib::Paths &in, double by, ClipperLib::EndType end, ClipperLib::Paths &out) {
    ClipperLib::ClipperOffset co(2.0, tol * kScale);
    co.AddPaths(in, ClipperLib::jtRound, end);
    co.Execute(out, by * kScale);
  };
  const double d = j.toolRadius + j.sideAllowance + kChordSagFactor * j.chordTolerance;
  offset(region, -d, ClipperLib::etClosedPolygon, core);
  offset(core, d, ClipperLib::etClosedPolygon, reach);
  offset(cuts, j.toolRadius + j.sideAllowance, ClipperLib::etOpenRound, swept);
  ClipperLib::Clipper diff;
  diff.AddPaths(reach, ClipperLib::ptSubject, true);
  diff.AddPaths(swept, ClipperLib::ptClip, true);
  diff.Execute(ClipperLib::ctDifference, rest, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  offset(rest, -5 * tol, ClipperLib::etClosedPolygon, left);
  double area = 0;
  for (auto &p : left) area += std::fabs(ClipperLib::Area(p)) / (kScale * kScale);
  EXPECT_TRUE(left.empty()) << what << ": material left standing, " << area << " mm2";
  return true;
}
}  // namespace

TEST(Region, RandomIslandPocketsStayOffTheIslandsAndClearTheRest) {
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int k = 0; k < 30; ++k) {
    Case c;
    c.region.plane = 0;
    // A star-shaped outline about the origin.
    const int n = 5 + (int)(u(rng) * 6);
    for (int i = 0; i < n; ++i) {
      double a = 2 * M_PI * (i + 0.3 * u(rng)) / n, r = 30 + 25 * u(rng);
      c.region.outline.push_back({r * std::cos(a), r * std::sin(a)});
    }
    if (k % 2) std::reverse(c.region.outline.begin(), c.region.outline.end());
    for (int i = 0, m = 1 + (int)(u(rng) * 3); i < m; ++i) {
      Polygon isl = regular({-15 + 30 * u(rng), -15 + 30 * u(rng)}, 3 + 7 * u(rng), 3 + (int)(u(rng) * 6), u(rng));
      if (i % 2) std::reverse(isl.begin(), isl.end());
      if (islandInside(c.region, isl, kRegionChordTolerance)) c.region.islands.push_back(isl);
    }
    RegionPocketJob &j = c.job;
    j.at = {100 * u(rng) - 50, 100 * u(rng) - 50, 50};
    j.toolRadius = 1 + 4 * u(rng);
    j.stepover = j.toolRadius * (0.6 + 1.3 * u(rng));
    j.sideAllowance = u(rng) < 0.5 ? 0 : u(rng);
    j.surface = 0, j.depth = 6, j.infeed = 2.5, j.floorAllowance = 0.5, j.clearance = 2, j.height = 20;
    j.ccw = k % 3 != 0;
    checked += check(c, "case " + std::to_string(k));
    if (HasFailure()) return;
  }
  EXPECT_GT(checked, 20);
}

// Two islands that leave two areas, joined only by a passage narrower than the tool: each area is
// roughed on its own, the tool lifting over the islands in between.
TEST(Region, SeparateAreasAreCutOneAfterTheOther) {
  Case c;
  c.region.plane = 0;
  c.region.outline = {{0, 0}, {100, 0}, {100, 40}, {0, 40}};
  c.region.islands = {{{45, 2}, {55, 2}, {55, 38}, {45, 38}}};  // gaps of 2 mm above and below
  RegionPocketJob &j = c.job;
  j.at = {0, 0, 50};
  j.toolRadius = 3, j.stepover = 4, j.surface = 0, j.depth = 2, j.clearance = 2, j.height = 20;
  ASSERT_TRUE(check(c, "two areas"));
  std::vector<CycleStep> steps;
  std::string err;
  ASSERT_TRUE(regionPocket(c.region, j, steps, err)) << err;
  // One plunge per area; between them the tool is up at the set-up clearance over the surface.
  int plunges = 0, lifts = 0;
  for (size_t i = 1; i < steps.size(); ++i) {
    if (steps[i].kind == CycleStepKind::Feed && steps[i].pos[2] < steps[i - 1].pos[2] - 1e-9) ++plunges;
    if (steps[i].kind == CycleStepKind::Rapid && steps[i - 1].pos[2] == 2 && steps[i].pos[2] == 2 &&
        (steps[i].pos[0] - 50) * (steps[i - 1].pos[0] - 50) < 0)
      ++lifts;
  }
  EXPECT_EQ(plunges, 2);
  EXPECT_EQ(lifts, 1);
}

TEST(Region, LoopsCloseAndSampleOnTheSafeSide) {
  Polygon p;
  std::string err;
  // A circle of radius 10 as one arc (the first move leads to it): an outline's polygon lies
  // inside it, an island's outside.
  RegionLoop circle{{0, 0}, {{{10, 0}, false, {}, true}, {{10, 0}, true, {0, 0}, true}}};
  ASSERT_TRUE(regionPolygon(circle, false, 0.001, p, err)) << err;
  for (auto &q : p) EXPECT_LE(std::hypot(q[0], q[1]), 10 + 1e-9);
  EXPECT_GT(ClipperLib::Area(toPath(p)), 0);
  ASSERT_TRUE(regionPolygon(circle, true, 0.001, p, err)) << err;
  for (size_t i = 0; i < p.size(); ++i)
    EXPECT_GE(segDistance({0, 0}, p[i], p[(i + 1) % p.size()]), 10 - 1e-9);
  EXPECT_LT(ClipperLib::Area(toPath(p)), 0);
  // Open, crossing itself.
  RegionLoop open{{0, 0}, {{{10, 0}, false, {}, true}, {{10, 10}, false, {}, true}}};
  EXPECT_FALSE(regionPolygon(open, false, 0.001, p, err));
  EXPECT_EQ(err, "a region contour must be closed: it must end where it begins");
  RegionLoop bow{{0, 0}, {{{10, 10}, false, {}, true}, {{10, 0}, false, {}, true}, {{0, 10}, false, {}, true}, {{0, 0}, false, {}, true}}};
  EXPECT_FALSE(regionPolygon(bow, false, 0.001, p, err));
  EXPECT_EQ(err, "a region contour must not cross itself");
}

TEST(Region, Errors) {
  PocketRegion r;
  r.plane = 0;
  r.outline = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
  EXPECT_FALSE(islandInside(r, {{15, 5}, {25, 5}, {25, 10}, {15, 10}}, 0.001));
  EXPECT_TRUE(islandInside(r, {{5, 5}, {10, 5}, {10, 10}, {5, 10}}, 0.001));
  RegionPocketJob j;
  j.toolRadius = 11, j.stepover = 5, j.depth = 2, j.height = 10;
  std::vector<CycleStep> steps;
  std::string err;
  EXPECT_FALSE(regionPocket(r, j, steps, err));
  EXPECT_EQ(err, "the tool does not fit into the region");
  j.toolRadius = 3;
  j.floorAllowance = 2;
  EXPECT_FALSE(regionPocket(r, j, steps, err));
  EXPECT_EQ(err, "the floor allowance must be at least 0 and less than the depth");
}

namespace {
// A square loop from the tool at the origin: to (x0, y0), then round the square of side s
// (clockwise when `cw`), ending `short_` edges early.
RegionLoop squareLoop(double x0, double y0, double s, bool cw, bool short_ = false) {
  RegionLoop l;
  l.start = {-50, -50};
  std::vector<PlanePoint> pts = cw ? std::vector<PlanePoint>{{x0, y0 + s}, {x0 + s, y0 + s}, {x0 + s, y0}, {x0, y0}}
                                   : std::vector<PlanePoint>{{x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}, {x0, y0}};
  l.segs.push_back({{x0, y0}, false, {}, true});
  for (size_t i = 0; i + (short_ ? 1 : 0) < pts.size(); ++i) l.segs.push_back({pts[i], false, {}, true});
  return l;
}
double areaOf(const std::vector<Polygon> &ps) {
  double a = 0;
  for (auto &p : ps) a += ClipperLib::Area(toPath(p)) / (kScale * kScale);
  return a;
}
}  // namespace

// FEATURES: HEI-SL-02
// SL sub-contours (the manual's L8853-L8860 and L9022-L9173): RR clockwise and RL
// counter-clockwise are pockets, the other two islands; pockets unite, islands subtract, the first
// pocket starting inside the second intersects with it.
TEST(Region, SlSubContours) {
  SubContour s;
  std::string err;
  ASSERT_TRUE(subContour(squareLoop(0, 0, 10, true), 2, 0.001, s, err)) << err;
  EXPECT_TRUE(s.pocket);
  EXPECT_TRUE(subContour(squareLoop(0, 0, 10, true), 1, 0.001, s, err) && !s.pocket);
  EXPECT_TRUE(subContour(squareLoop(0, 0, 10, false), 1, 0.001, s, err) && s.pocket);
  EXPECT_TRUE(subContour(squareLoop(0, 0, 10, false), 2, 0.001, s, err) && !s.pocket);
  EXPECT_FALSE(subContour(squareLoop(0, 0, 10, true), 0, 0.001, s, err));
  // A square ending at its last corner is open; ending on the first element's line it closes
  // (a mid-edge start, as the manual's example 09).
  EXPECT_FALSE(subContour(squareLoop(0, 0, 10, true, true), 2, 0.001, s, err));
  RegionLoop mid;
  mid.start = {-50, -50};
  for (PlanePoint p : std::vector<PlanePoint>{{0, 5}, {0, 10}, {10, 10}, {10, 0}, {0, 0}}) mid.segs.push_back({p, false, {}, true});
  ASSERT_TRUE(subContour(mid, 2, 0.001, s, err)) << err;
  EXPECT_NEAR(ClipperLib::Area(toPath(s.poly)) / (kScale * kScale), 100, 1e-6);
  EXPECT_EQ(s.start, (PlanePoint{0, 5}));

  SubContour a, b, island;
  ASSERT_TRUE(subContour(squareLoop(0, 0, 10, true), 2, 0.001, a, err));
  ASSERT_TRUE(subContour(squareLoop(5, 0, 10, true), 2, 0.001, b, err));   // starts on A's bottom edge: not inside
  ASSERT_TRUE(subContour(squareLoop(2, 2, 2, true), 1, 0.001, island, err));
  std::vector<Polygon> area;
  ASSERT_TRUE(slArea({a, b}, area, err)) << err;
  EXPECT_NEAR(areaOf(area), 150, 1e-6);  // union
  ASSERT_TRUE(slArea({a, b, island}, area, err)) << err;
  EXPECT_NEAR(areaOf(area), 146, 1e-6);  // less the island
  SubContour inner;
  ASSERT_TRUE(subContour(squareLoop(6, 2, 10, true), 2, 0.001, inner, err));  // starts inside A
  ASSERT_TRUE(slArea({inner, a}, area, err)) << err;
  EXPECT_NEAR(areaOf(area), 32, 1e-6);  // intersection 4 x 8
  EXPECT_FALSE(slArea({inner, a, b}, area, err));
  EXPECT_FALSE(slArea({island}, area, err));
}
