// Turning contour cycles (runtime/cycles/Turning.h): stock removal on random monotonic contours
// (type I) and contours with pockets (type II) never enters the contour shifted by the allowance
// and leaves at most one layer depth of material above it; pattern repeating shifts the contour
// in equal steps.
// FEATURES: ISO-CYT-04 ISO-CYT-05 ISO-CYT-06
#include "runtime/cycles/Turning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {

ContourElem elem(ContourKind k, Pt2 end, Pt2 centre = {}, bool ccw = false) {
  ContourElem e;
  e.kind = k, e.end = end, e.centre = centre, e.ccw = ccw;
  return e;
}

// An outside-diameter G71 contour in plane coordinates (a = Z, b = X radius): from the start C
// across to A', then towards -Z with X never decreasing (steps, tapers, shoulders).
Contour randomContour(std::mt19937 &rng, double xStart) {
  std::uniform_real_distribution<double> u(0, 1);
  Contour c;
  c.start = {5, xStart};
  double z = 5, x = 5 + 10 * u(rng);
  ContourElem e;
  e.kind = u(rng) < 0.5 ? ContourKind::Rapid : ContourKind::Line;
  e.end = {z, x};
  c.elems.push_back(e);
  int n = 2 + (int)(6 * u(rng));
  for (int i = 0; i < n; ++i) {
    double r = u(rng);
    if (r < 0.25 && x < 40) {  // a quarter arc: an inner fillet (G2) or an outer rounding (G3)
      double rad = 1 + 4 * u(rng);
      bool outer = u(rng) < 0.5;
      Pt2 centre = outer ? Pt2{z - rad, x} : Pt2{z, x + rad};
      z -= rad, x += rad;
      c.elems.push_back(elem(ContourKind::Arc, {z, x}, centre, outer));
      continue;
    }
    if (r < 0.3) z -= 1 + 10 * u(rng);                       // along Z
    else if (r < 0.5) x = std::min(45.0, x + 1 + 6 * u(rng));  // a shoulder
    else z -= 1 + 10 * u(rng), x = std::min(45.0, x + 6 * u(rng));  // a taper
    c.elems.push_back(elem(ContourKind::Line, {z, x}));
  }
  if (z > -1) c.elems.push_back(elem(ContourKind::Line, {z - 2, x}));  // it runs along Z
  return c;
}

// The contour A'..B shifted by d as a polyline, arcs in 200 chords each (inside the arc by < 4e-5 mm).
std::vector<Pt2> polyline(const Contour &c, Pt2 d) {
  std::vector<Pt2> pts{{c.elems[0].end.a + d.a, c.elems[0].end.b + d.b}};
  for (size_t i = 1; i < c.elems.size(); ++i) {
    const ContourElem &e = c.elems[i];
    if (e.kind == ContourKind::Arc) {
      const Pt2 from = c.elems[i - 1].end;
      double a0 = std::atan2(from.b - e.centre.b, from.a - e.centre.a), a1 = std::atan2(e.end.b - e.centre.b, e.end.a - e.centre.a);
      double sweep = a1 - a0;
      if (e.ccw && sweep <= 0) sweep += 2 * M_PI;
      if (!e.ccw && sweep >= 0) sweep -= 2 * M_PI;
      double r = std::hypot(from.a - e.centre.a, from.b - e.centre.b);
      for (int k = 1; k < 200; ++k) {
        double t = a0 + sweep * k / 200;
        pts.push_back({e.centre.a + r * std::cos(t) + d.a, e.centre.b + r * std::sin(t) + d.b});
      }
    }
    pts.push_back({e.end.a + d.a, e.end.b + d.b});
  }
  return pts;
}

// The shifted contour's X at z (the largest where a shoulder stands at z).
double profileX(const std::vector<Pt2> &pts, double z) {
  double best = -1e9;
  for (size_t i = 1; i < pts.size(); ++i) {
    double z0 = pts[i - 1].a, z1 = pts[i].a;
    if (z > std::max(z0, z1) + 1e-9 || z < std::min(z0, z1) - 1e-9) continue;
    double x = std::fabs(z1 - z0) < 1e-12 ? std::max(pts[i - 1].b, pts[i].b)
                                          : pts[i - 1].b + (pts[i].b - pts[i - 1].b) * (z - z0) / (z1 - z0);
    best = std::max(best, x);
  }
  return best;
}

// The contour with its axes swapped (a G71 contour becomes a G72 one): arcs turn the other way.
Contour swapped(const Contour &c) {
  Contour o = c;
  o.start = {c.start.b, c.start.a};
  for (auto &e : o.elems) e.end = {e.end.b, e.end.a}, e.centre = {e.centre.b, e.centre.a}, e.ccw = !e.ccw;
  return o;
}

// Points along a move from `from` (ends included), arcs on their circle.
std::vector<Pt2> movePoints(Pt2 from, const ContourElem &e, int n) {
  std::vector<Pt2> pts;
  double a0 = 0, sweep = 0, rad = 0;
  if (e.kind == ContourKind::Arc) {
    a0 = std::atan2(from.b - e.centre.b, from.a - e.centre.a);
    sweep = std::atan2(e.end.b - e.centre.b, e.end.a - e.centre.a) - a0;
    if (e.ccw && sweep <= 0) sweep += 2 * M_PI;
    if (!e.ccw && sweep >= 0) sweep -= 2 * M_PI;
    rad = std::hypot(from.a - e.centre.a, from.b - e.centre.b);
  }
  for (int k = 0; k <= n; ++k) {
    double t = double(k) / n;
    if (e.kind == ContourKind::Arc)
      pts.push_back({e.centre.a + rad * std::cos(a0 + sweep * t), e.centre.b + rad * std::sin(a0 + sweep * t)});
    else
      pts.push_back({from.a + (e.end.a - from.a) * t, from.b + (e.end.b - from.b) * t});
  }
  return pts;
}

// Layers along the plane's first axis (G71), or, with `swap`, the same cut made along its second
// axis (G72) on the swapped contour, swapped back for the checks.
void randomStockRemoval(bool swap) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const double xStart = 50;
    Contour c = randomContour(rng, xStart);
    StockRemoval s;
    s.cutAxis = 0;
    s.depth = 0.5 + 2.5 * u(rng);
    s.retract = u(rng);
    s.allowance = {0.5 * u(rng), u(rng)};
    std::vector<ContourElem> moves;
    std::string err;
    if (swap) {
      StockRemoval t = s;
      t.cutAxis = 1, t.allowance = {s.allowance.b, s.allowance.a};
      ASSERT_TRUE(stockRemoval(swapped(c), t, moves, err)) << err;
      Contour back;
      back.elems = moves;
      moves = swapped(back).elems;
    } else {
      ASSERT_TRUE(stockRemoval(c, s, moves, err)) << err;
    }
    std::vector<Pt2> prof = polyline(c, s.allowance);  // the shifted contour A'..B
    const double zB = prof.back().a, zA = prof.front().a;
    // Beyond B (towards -Z) the contour's last X holds; before A' nothing is in the way.
    auto limit = [&](double z) { return z < zB ? prof.back().b : z > zA ? -1e9 : profileX(prof, z); };
    Pt2 pos = c.start;
    struct Layer {
      double x, zEnd;
    };
    std::vector<Layer> layers;
    size_t firstProfileMove = moves.size();
    for (size_t m = 0; m < moves.size(); ++m) {
      const ContourElem &e = moves[m];
      // Every move stays out of the shifted contour (sampled inside the move, ends included;
      // an arc of the profile pass lies on it).
      for (auto &pt : movePoints(pos, e, 50)) {
        const double z = pt.a, x = pt.b;
        // At a shoulder the lower side counts (a cut may end against it); near a vertical
        // tangent X changes fast with Z (and the chords of an inner fillet lie outside it): compare
        // within 1e-3 in Z.
        double lim = std::min({limit(z + 1e-3), limit(z), limit(z - 1e-3)});
        EXPECT_GE(x, lim - 1e-4) << "trial " << trial << " move " << m << " enters the contour at Z" << z;
      }
      // Layer cuts: feed moves along -Z at constant X before the profile pass.
      if (e.kind == ContourKind::Line && std::fabs(e.end.b - pos.b) < 1e-12 && e.end.a < pos.a &&
          firstProfileMove == moves.size() && std::fabs(pos.a - c.start.a) < 1e-12)
        layers.push_back({e.end.b, e.end.a});
      else if (e.kind == ContourKind::Line && firstProfileMove == moves.size() && !layers.empty() &&
               std::fabs(pos.a - c.start.a) > 1e-12)
        firstProfileMove = m;
      pos = e.end;
    }
    // Ends at the start point.
    EXPECT_NEAR(pos.a, c.start.a, 1e-9);
    EXPECT_NEAR(pos.b, c.start.b, 1e-9);
    // The layers leave at most one depth of material over the shifted contour (before the
    // profile pass takes the rest): at each Z, the lowest layer that reached it.
    // (Between B and A', not in front of C: the layers start at C's Z, the stock's face side.)
    const double zTop = std::min(zA, c.start.a);
    for (int k = 1; k < 200; ++k) {
      double z = zB + (zTop - zB) * k / 200.0;
      double top = xStart;
      for (auto &l : layers)
        if (l.zEnd <= z + 1e-9) top = std::min(top, l.x);
      EXPECT_LE(top - profileX(prof, z), s.depth + 1e-4) << "trial " << trial << " at Z" << z;
    }
  }
}

}  // namespace

TEST(Turning, StockRemovalRandomContours) { randomStockRemoval(false); }
TEST(Turning, StockRemovalRandomContoursAlongX) { randomStockRemoval(true); }

TEST(Turning, StockRemovalFollowsArcs) {
  // A' (Z0 X10), a quarter arc G3 to (Z-10 X20) about (Z-10 X10), then Z-20: the layer at X15
  // ends where the shifted arc reaches X15.
  Contour c;
  c.start = {2, 30};
  ContourElem a = elem(ContourKind::Rapid, {2, 10}), arc = elem(ContourKind::Arc, {-8, 20}, {-8, 10}, true),
              l = elem(ContourKind::Line, {-20, 20});
  // From (2, 10) the arc about (-8, 10) with radius 10 counter-clockwise in (Z, X) runs to (-8, 20).
  c.elems = {a, arc, l};
  StockRemoval s;
  s.depth = 5, s.retract = 1, s.allowance = {0, 0};
  std::vector<ContourElem> moves;
  std::string err;
  ASSERT_TRUE(stockRemoval(c, s, moves, err)) << err;
  // Layers at X25 and X20 run to the end of the contour (Z-20); X15 meets the arc at
  // Z = -8 + sqrt(100 - 25).
  std::vector<std::pair<double, double>> cuts;
  for (size_t i = 1; i < moves.size(); ++i)
    if (moves[i].kind == ContourKind::Line && moves[i].end.b == moves[i - 1].end.b && moves[i - 1].end.a == 2)
      cuts.push_back({moves[i].end.b, moves[i].end.a});
  ASSERT_EQ(cuts.size(), 3u);
  EXPECT_DOUBLE_EQ(cuts[0].first, 25);
  EXPECT_DOUBLE_EQ(cuts[0].second, -20);
  EXPECT_DOUBLE_EQ(cuts[1].first, 20);
  EXPECT_NEAR(cuts[1].second, -8, 1e-9);
  EXPECT_DOUBLE_EQ(cuts[2].first, 15);
  EXPECT_NEAR(cuts[2].second, -8 + std::sqrt(75.0), 1e-9);
  // The profile pass keeps the arc.
  int arcs = 0;
  for (auto &m : moves) arcs += m.kind == ContourKind::Arc;
  EXPECT_EQ(arcs, 1);
}

TEST(Turning, PatternRepeatSteps) {
  Contour c;
  c.start = {10, 50};
  c.elems = {elem(ContourKind::Rapid, {0, 20}), elem(ContourKind::Line, {-10, 30})};
  PatternRepeat p;
  p.relief = {6, 12};
  p.allowance = {1, 2};
  p.count = 3;
  std::vector<ContourElem> moves;
  std::string err;
  ASSERT_TRUE(patternRepeat(c, p, moves, err)) << err;
  ASSERT_EQ(moves.size(), 9u);
  // Shifts (7, 14), (4, 8), (1, 2); each pass ends back at C.
  EXPECT_DOUBLE_EQ(moves[0].end.a, 7);
  EXPECT_DOUBLE_EQ(moves[0].end.b, 34);
  EXPECT_DOUBLE_EQ(moves[3].end.a, 4);
  EXPECT_DOUBLE_EQ(moves[4].end.b, 38);
  EXPECT_DOUBLE_EQ(moves[7].end.b, 32);
  EXPECT_DOUBLE_EQ(moves[8].end.a, 10);
  EXPECT_DOUBLE_EQ(moves[8].end.b, 50);
}

namespace {

// A G71 type II contour (a = Z, b = X radius): from C to A' moving both axes, then towards -Z
// with X going up and down (pockets): tapers, shoulders both ways, flats, quarter arcs.
Contour randomPocketContour(std::mt19937 &rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Contour c;
  c.start = {5, 50};
  double z = 4 - 2 * u(rng), x = 5 + 10 * u(rng);
  c.elems.push_back(elem(u(rng) < 0.5 ? ContourKind::Rapid : ContourKind::Line, {z, x}));
  int n = 3 + (int)(8 * u(rng));
  for (int i = 0; i < n; ++i) {
    double r = u(rng), rad = 1 + 4 * u(rng);
    bool down = u(rng) < 0.4 && x - rad > 3;
    if (r < 0.2 && (down || x + rad < 45)) {  // a quarter arc up or down, either way round
      double dx = down ? -rad : rad;
      bool alongFirst = u(rng) < 0.5;  // the centre level with the start or with the end
      Pt2 centre = alongFirst ? Pt2{z - rad, x} : Pt2{z, x + dx};
      // From the centre's side: turning from +a towards +b is counter-clockwise.
      bool ccw = alongFirst ? !down : down;
      z -= rad, x += dx;
      c.elems.push_back(elem(ContourKind::Arc, {z, x}, centre, ccw));
      continue;
    }
    if (r < 0.35) z -= 1 + 10 * u(rng);                                 // along Z
    else if (r < 0.5) x = std::clamp(x + (down ? -1 : 1) * (1 + 6 * u(rng)), 3.0, 45.0);  // a shoulder
    else z -= 1 + 10 * u(rng), x = std::clamp(x + (down ? -1 : 1) * 8 * u(rng), 3.0, 45.0);  // a taper
    c.elems.push_back(elem(ContourKind::Line, {z, x}));
  }
  c.elems.push_back(elem(ContourKind::Line, {z - 2, x}));
  return c;
}


// Distance from p to a polyline.
double distance(const std::vector<Pt2> &pts, Pt2 p) {
  double best = 1e18;
  for (size_t i = 1; i < pts.size(); ++i) {
    Pt2 a = pts[i - 1], b = pts[i];
    double dx = b.a - a.a, dy = b.b - a.b, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? std::clamp(((p.a - a.a) * dx + (p.b - a.b) * dy) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(a.a + dx * t - p.a, a.b + dy * t - p.b));
  }
  return best;
}

}  // namespace

// Type II (pockets): no move enters the contour shifted by the allowance, and the layers leave at
// most one depth of material over it everywhere, pockets included.
TEST(Turning, StockRemovalTypeIIPockets) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(0, 1);
  int pockets = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Contour c = randomPocketContour(rng);
    StockRemoval s;
    s.cutAxis = 0;
    s.typeII = true;
    s.depth = 0.5 + 2.5 * u(rng);
    s.retract = u(rng);
    s.allowance = {0.5 * u(rng), 0.5 * u(rng)};
    std::vector<ContourElem> moves;
    std::string err;
    ASSERT_TRUE(stockRemoval(c, s, moves, err)) << "trial " << trial << ": " << err;
    std::vector<Pt2> prof = polyline(c, s.allowance);
    const Pt2 aOff = prof.front();
    const double zB = prof.back().a, zA = aOff.a;
    auto limit = [&](double z) { return z < zB ? prof.back().b : z > zA ? -1e9 : profileX(prof, z); };
    std::vector<Pt2> ext = prof;  // beyond B the contour's last X holds
    ext.push_back({zB - 1000, prof.back().b});
    struct Layer {
      double x, z0, z1;  // z1 < z0
    };
    std::vector<Layer> layers;
    bool finishing = false;
    Pt2 pos = c.start;
    for (size_t m = 0; m < moves.size(); ++m) {
      const ContourElem &e = moves[m];
      for (auto &p : movePoints(pos, e, 50)) {
        // Below the contour and not on it (within 1e-4: a shoulder, a steep arc's chords).
        bool inside = p.b < limit(p.a) - 1e-4 && distance(ext, p) > 1e-4;
        EXPECT_FALSE(inside) << "trial " << trial << " move " << m << " enters the contour at Z" << p.a << " X" << p.b;
      }
      if (!finishing && e.kind == ContourKind::Line && std::fabs(e.end.b - pos.b) < 1e-12 && e.end.a < pos.a)
        layers.push_back({e.end.b, pos.a, e.end.a});
      if (std::fabs(e.end.a - aOff.a) < 1e-9 && std::fabs(e.end.b - aOff.b) < 1e-9) finishing = true;
      pos = e.end;
    }
    EXPECT_TRUE(finishing) << "trial " << trial;
    EXPECT_NEAR(pos.a, c.start.a, 1e-9);
    EXPECT_NEAR(pos.b, c.start.b, 1e-9);
    // Layers that start inside the work (not at C's Z) went down into a pocket.
    for (auto &l : layers) pockets += std::fabs(l.z0 - c.start.a) > 1e-9;
    for (int k = 1; k < 400; ++k) {
      double z = zB + (zA - zB) * k / 400.0;
      double top = c.start.b;
      for (auto &l : layers)
        if (l.z1 <= z + 1e-9 && l.z0 >= z - 1e-9) top = std::min(top, l.x);
      EXPECT_LE(top - profileX(prof, z), s.depth + 1e-4) << "trial " << trial << " at Z" << z;
    }
  }
  EXPECT_GT(pockets, 100);  // the contours do have pockets
}

// Type II names both axes in its first block; without that, a pocket is an error (type I).
TEST(Turning, StockRemovalTypeIRejectsPockets) {
  Contour c;
  c.start = {5, 50};
  c.elems = {elem(ContourKind::Rapid, {5, 10}), elem(ContourKind::Line, {-10, 20}), elem(ContourKind::Line, {-20, 15}),
             elem(ContourKind::Line, {-30, 25})};
  StockRemoval s;
  s.depth = 2, s.retract = 0.5, s.cutName = "Z";
  std::vector<ContourElem> moves;
  std::string err;
  EXPECT_FALSE(stockRemoval(c, s, moves, err));
  EXPECT_NE(err.find("monotonic in both axes (type I"), std::string::npos) << err;
  s.typeII = true;
  moves.clear();
  EXPECT_TRUE(stockRemoval(c, s, moves, err)) << err;
}
