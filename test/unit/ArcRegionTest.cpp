// Exact regions of lines and arcs (runtime/cycles/ArcRegion.h), checked on random SL contours:
// pockets of rectangles and circles (united, or two intersected), islands of squares, triangles
// and circles. The tool-centre walls must lie exactly the distance d off the region's boundary
// (every point of every wall element, within 1e-7 mm) and inside the region, and must enclose
// exactly the points of the region at least d from its boundary (random points: the walls'
// winding number is 1 where the distance is d + 1e-6 or more, 0 where it is d - 1e-6 or less).
#include "runtime/cycles/ArcRegion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {
PathElem line(double ax, double ay, double bx, double by) { return {false, {ax, ay}, {bx, by}, {}, 0}; }

ArcLoop rectangle(double x0, double y0, double x1, double y1) {
  return {line(x0, y0, x1, y0), line(x1, y0, x1, y1), line(x1, y1, x0, y1), line(x0, y1, x0, y0)};
}
ArcLoop circle(double cx, double cy, double r, int dir) { return {{true, {cx + r, cy}, {cx + r, cy}, {cx, cy}, dir}}; }
ArcLoop triangle(double cx, double cy, double r, double phase) {
  ArcLoop l;
  for (int k = 0; k < 3; ++k) {
    const double a0 = phase + k * 2.0943951023931953, a1 = a0 + 2.0943951023931953;
    l.push_back(line(cx + r * std::cos(a0), cy + r * std::sin(a0), cx + r * std::cos(a1), cy + r * std::sin(a1)));
  }
  return l;
}
ArcLoop reversed(const ArcLoop &l) {
  ArcLoop r;
  for (size_t i = l.size(); i-- > 0;) r.push_back({l[i].arc, l[i].end, l[i].start, l[i].center, -l[i].dir});
  return r;
}

// Points along an element (its ends included).
std::vector<Point2> along(const PathElem &e, int n) {
  std::vector<Point2> out;
  double sweep = 0, a0 = 0, r = 0;
  if (e.arc) {
    a0 = std::atan2(e.start.y - e.center.y, e.start.x - e.center.x), r = std::hypot(e.start.x - e.center.x, e.start.y - e.center.y);
    sweep = (std::atan2(e.end.y - e.center.y, e.end.x - e.center.x) - a0) * e.dir;
    while (sweep <= 1e-12) sweep += 2 * M_PI;
  }
  for (int k = 0; k <= n; ++k) {
    const double t = double(k) / n;
    if (e.arc) out.push_back({e.center.x + r * std::cos(a0 + e.dir * t * sweep), e.center.y + r * std::sin(a0 + e.dir * t * sweep)});
    else out.push_back({e.start.x + t * (e.end.x - e.start.x), e.start.y + t * (e.end.y - e.start.y)});
  }
  return out;
}

// The walls' winding number about p: counter-clockwise loops count +1, clockwise ones -1.
int winding(const std::vector<ArcLoop> &loops, Point2 p) {
  int w = 0;
  for (const ArcLoop &l : loops) {
    double area = 0;
    for (const PathElem &e : l) {
      const std::vector<Point2> q = along(e, 64);
      for (size_t k = 0; k + 1 < q.size(); ++k) area += q[k].x * q[k + 1].y - q[k + 1].x * q[k].y;
    }
    if (insideLoop(l, p)) w += area > 0 ? 1 : -1;
  }
  return w;
}
}  // namespace

TEST(ArcRegion, TwoCirclesLessTwoIslands) {
  // The manual's example C21: the walls of the union, 6 off, meet round the cusps on arcs about them.
  ArcRegion r;
  r.pockets = {circle(35, 50, 25, -1), circle(65, 50, 25, -1)};
  r.islands = {{line(27, 50, 27, 58), line(27, 58, 43, 58), line(43, 58, 43, 42), line(43, 42, 27, 42), line(27, 42, 27, 50)},
               {line(65, 42, 57, 42), line(57, 42, 65, 58), line(65, 58, 73, 42), line(73, 42, 65, 42)}};
  std::vector<ArcLoop> b, w;
  std::string err;
  ASSERT_TRUE(regionBoundary(r, b, err)) << err;
  ASSERT_TRUE(toolCentreBoundary({r, b, 6}, w, err)) << err;
  ASSERT_EQ(w.size(), 3u);
  ASSERT_EQ(w[0].size(), 4u);
  EXPECT_NEAR(w[0][1].center.x, 50, 1e-12);
  EXPECT_NEAR(w[0][1].center.y, 30, 1e-12);
  EXPECT_EQ(w[0][1].dir, -1);
  EXPECT_NEAR(w[0][1].start.x, 46.4, 1e-9);
  EXPECT_NEAR(w[0][1].start.y, 34.8, 1e-9);
  EXPECT_EQ(w[1].size(), 8u);  // the square's edge the program wrote in two is one wall element
}

// Random contours; with `grid` their corners, centres and sizes on a coarse grid (steps of 10
// and 3.33 mm), so that edges run along one another, pockets touch and circles touch lines.
void randomContours(bool grid) {
  std::mt19937 rng(grid ? 25 : 24);
  std::uniform_real_distribution<double> uniform(0, 1);
  auto u = [&](std::mt19937 &g) { return grid ? std::round(uniform(g) * 6) / 6 : uniform(g); };
  int checked = 0;
  for (int round = 0; round < 120; ++round) {
    ArcRegion r;
    const int pockets = 1 + (int)(u(rng) * 3);
    for (int k = 0; k < pockets; ++k) {
      const double x = 20 + 60 * u(rng), y = 20 + 60 * u(rng);
      ArcLoop l = u(rng) < 0.5 ? circle(x, y, 10 + 20 * u(rng), 1) : rectangle(x - 10 - 20 * u(rng), y - 10 - 20 * u(rng), x + 10 + 20 * u(rng), y + 10 + 20 * u(rng));
      r.pockets.push_back(u(rng) < 0.5 ? l : reversed(l));  // either direction
    }
    r.intersect = pockets == 2 && u(rng) < 0.3;
    const int islands = (int)(u(rng) * 4);
    for (int k = 0; k < islands; ++k) {
      const double x = 20 + 60 * u(rng), y = 20 + 60 * u(rng), s = 2 + 8 * u(rng);
      const double pick = u(rng);
      r.islands.push_back(pick < 0.33 ? circle(x, y, s, -1) : pick < 0.66 ? rectangle(x - s, y - s, x + s, y + s) : triangle(x, y, s, 6.3 * u(rng)));
    }
    const double d = 1 + 6 * uniform(rng);
    std::vector<ArcLoop> b, w;
    std::string err;
    ASSERT_TRUE(regionBoundary(r, b, err)) << "round " << round << ": " << err;
    ASSERT_TRUE(toolCentreBoundary({r, b, d}, w, err)) << "round " << round << ": " << err;
    for (const ArcLoop &l : w)
      for (size_t i = 0; i < l.size(); ++i) {
        const PathElem &e = l[i];
        ASSERT_LE(std::hypot(e.start.x - l[(i + l.size() - 1) % l.size()].end.x, e.start.y - l[(i + l.size() - 1) % l.size()].end.y), 1e-9);
        for (Point2 p : along(e, 16)) {
          ASSERT_NEAR(distanceTo(b, p), d, 1e-7) << "round " << round << " at " << p.x << " " << p.y;
          // (A wall may start on an edge two pockets share, where contains() says neither.)
          auto near = [&](double dx, double dy) { return r.contains({p.x + dx, p.y + dy}); };
          ASSERT_TRUE(near(0, 0) || near(1e-6, 0) || near(-1e-6, 0) || near(0, 1e-6) || near(0, -1e-6) || distanceTo(b, p) < 1e-6);
        }
      }
    for (int k = 0; k < 400; ++k) {
      const Point2 p{-20 + 140 * u(rng), -20 + 140 * u(rng)};
      const double dist = distanceTo(b, p);
      if (std::fabs(dist - d) < 1e-6) continue;
      const bool in = r.contains(p) && dist > d;
      ASSERT_EQ(winding(w, p), in ? 1 : 0) << "round " << round << " at " << p.x << " " << p.y;
      checked += in;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ArcRegion, ManyShortLines) {
  // A wavy pocket of 400 short lines (a CAM polyline) round a round island: neighbouring offsets
  // meet at very small angles, where a test a hair to each side of a piece cannot tell.
  ArcRegion r;
  ArcLoop l;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n, r0 = 40 + 3 * std::sin(7 * a0), r1 = 40 + 3 * std::sin(7 * a1);
    l.push_back(line(r0 * std::cos(a0), r0 * std::sin(a0), r1 * std::cos(a1), r1 * std::sin(a1)));
  }
  l.back().end = l.front().start;
  r.pockets = {l};
  r.islands = {circle(0, 0, 5, -1)};
  std::vector<ArcLoop> b, w;
  std::string err;
  ASSERT_TRUE(regionBoundary(r, b, err)) << err;
  ASSERT_TRUE(toolCentreBoundary({r, b, 4}, w, err)) << err;
  ASSERT_EQ(w.size(), 2u);
  for (const ArcLoop &loop : w)
    for (const PathElem &e : loop)
      for (Point2 p : along(e, 4)) ASSERT_NEAR(distanceTo(b, p), 4, 1e-7);
}

TEST(ArcRegion, RandomContoursWallsExact) { randomContours(false); }
TEST(ArcRegion, GridContoursWallsExact) { randomContours(true); }
