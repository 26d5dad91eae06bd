// Contour formulas (runtime/cycles/ContourFormula.h, Region.h formulaArea): the steps' tree, its
// errors, and the Clipper region of two circles under each operator checked against the exact
// predicate at random points (away from the circles by more than the sampling tolerance).
#include "runtime/cycles/ContourFormula.h"
#include "runtime/cycles/ClipperPaths.h"
#include "runtime/cycles/Region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {
using S = FormulaStep;

// A full circle as a captured loop: the first move leads to its first point (dropped on closing).
RegionLoop circle(double cx, double cy, double r, bool ccw) {
  RegionLoop l;
  l.start = {0, 0};
  l.segs.push_back({{cx + r, cy}, false, {}, false});
  l.segs.push_back({{cx + r, cy}, true, {cx, cy}, ccw});
  return l;
}

bool inArea(const std::vector<Polygon> &area, double x, double y) {
  int w = 0;
  for (const Polygon &p : area) {
    const int in = ClipperLib::PointInPolygon(toClipper({x, y}), toPath(p));
    if (in) w += ClipperLib::Orientation(toPath(p)) ? 1 : -1;
  }
  return w > 0;
}
}  // namespace

TEST(ContourFormula, StepsMakeTheTree) {
  ContourFormula f;
  std::string err;
  // QC1, QC2 declared; QC10 = QC1 \ QC2; QC11 = QC10 | QC1
  const std::vector<S> steps = {{S::Declare, 1, 0}, {S::Declare, 2, 1}, {S::Push, 1}, {S::Push, 2}, {S::Apply, 4},
                                {S::Store, 10}, {S::Push, 10}, {S::Push, 1}, {S::Apply, 1}, {S::Store, 11}};
  ASSERT_TRUE(buildFormula(steps, f, err)) << err;
  auto at = [&](bool a, bool b) { return formulaContains(f, [&](int k) { return k == 0 ? a : b; }); };
  EXPECT_TRUE(at(true, false));
  EXPECT_TRUE(at(true, true));  // the union with QC1 puts back what QC2 took
  EXPECT_FALSE(at(false, true));
  EXPECT_FALSE(at(false, false));
}

TEST(ContourFormula, Errors) {
  ContourFormula f;
  std::string err;
  EXPECT_FALSE(buildFormula({{S::Declare, 1, 0}, {S::Push, 2}}, f, err));
  EXPECT_NE(err.find("QC2"), std::string::npos);
  EXPECT_FALSE(buildFormula({{S::Declare, 1, 0}, {S::Push, 1}, {S::Apply, 1}}, f, err));
  EXPECT_FALSE(buildFormula({{S::Declare, 1, 0}}, f, err));
  EXPECT_NE(err.find("no contour formula"), std::string::npos);
  EXPECT_FALSE(buildFormula({{S::Declare, 1, 0}, {S::Push, 1}, {S::Push, 1}, {S::Store, 3}}, f, err));
}

TEST(ContourFormula, ClipperRegionMatchesThePredicate) {
  const double tol = kRegionChordTolerance;
  PocketRegion r;
  r.plane = 0;
  std::string err;
  for (auto [c, ccw] : {std::pair{RegionLoop{circle(35, 50, 25, false)}, false}, {circle(65, 50, 25, true), true}}) {
    SubContour s;
    ASSERT_TRUE(formulaOperand(c, tol, s, err)) << err;
    r.formula.push_back({S::Declare, (int)r.subs.size() + 1, (int)r.subs.size()});
    r.subs.push_back(s);
  }
  const std::vector<S> declared = r.formula;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(0, 100), uy(15, 85);
  for (int op = 1; op <= 4; ++op) {
    r.formula = declared;
    r.formula.insert(r.formula.end(), {{S::Push, 1}, {S::Push, 2}, {S::Apply, op}, {S::Store, 10}});
    std::vector<Polygon> area;
    ASSERT_TRUE(formulaArea(r, tol, area, err)) << err;
    ContourFormula f;
    ASSERT_TRUE(buildFormula(r.formula, f, err));
    int checked = 0;
    for (int k = 0; k < 4000; ++k) {
      const double x = ux(rng), y = uy(rng);
      const double da = std::hypot(x - 35, y - 50) - 25, db = std::hypot(x - 65, y - 50) - 25;
      if (std::fabs(da) < 10 * tol || std::fabs(db) < 10 * tol) continue;  // the sampling's band
      const bool want = formulaContains(f, [&](int s) { return (s == 0 ? da : db) < 0; });
      EXPECT_EQ(inArea(area, x, y), want) << "operator " << op << " at " << x << "," << y;
      ++checked;
    }
    EXPECT_GT(checked, 3900);
  }
}
