// FEATURES: HEI-POC-01 HEI-POC-02 HEI-POC-03 HEI-POC-04 HEI-POC-05 HEI-POC-06 HEI-POC-07 HEI-POC-08 HEI-POC-09 SIN-CYC-19 SIN-CYC-20 HEI-SPC-10 HEI-SPC-12 HEI-SPC-13
// The pocket, slot and stud entries of the cycle library (runtime/cycles/ClearingEntries.cpp, SinClearingEntries.cpp)
// checked by geometry: the tool-centre path they produce is sampled, and (1) the tool never cuts
// into the finished part (beyond a pocket's wall, into a stud; less the side allowance when only
// roughing), (2) at the final depth every point of the region to clear lies within one tool
// radius of the path: no material left standing.
#include "runtime/cycles/Clearing.h"
#include "runtime/cycles/Library.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>

using namespace ncc;

namespace {
struct Sample {
  double x, y, z;
};

// Points along the moves every `step` mm (rapids included: they must not cut either).
std::vector<Sample> samplePath(const std::vector<CycleStep> &steps, std::array<double, 3> at, double step = 0.05) {
  std::vector<Sample> out;
  for (const CycleStep &s : steps) {
    if (s.kind == CycleStepKind::Rapid || s.kind == CycleStepKind::Feed) {
      double len = std::sqrt(std::pow(s.pos[0] - at[0], 2) + std::pow(s.pos[1] - at[1], 2) + std::pow(s.pos[2] - at[2], 2));
      int n = std::max(1, (int)std::ceil(len / step));
      for (int i = 0; i <= n; ++i) {
        double t = (double)i / n;
        out.push_back({at[0] + t * (s.pos[0] - at[0]), at[1] + t * (s.pos[1] - at[1]), at[2] + t * (s.pos[2] - at[2])});
      }
    } else if (s.kind == CycleStepKind::Arc) {
      double cx = s.centre[0], cy = s.centre[1];
      double r = std::hypot(at[0] - cx, at[1] - cy), r1 = std::hypot(s.pos[0] - cx, s.pos[1] - cy);
      EXPECT_NEAR(r, r1, 1e-6) << "an arc's end is not on its circle";
      double a0 = std::atan2(at[1] - cy, at[0] - cx), a1 = std::atan2(s.pos[1] - cy, s.pos[0] - cx);
      double sweep = s.ccw ? a1 - a0 : a0 - a1;
      if (std::hypot(s.pos[0] - at[0], s.pos[1] - at[1]) < 1e-9) sweep = 2 * M_PI;
      else if (sweep <= 0) sweep += 2 * M_PI;
      int n = std::max(1, (int)std::ceil(sweep * r / step));
      for (int i = 0; i <= n; ++i) {
        double t = (double)i / n, a = a0 + (s.ccw ? 1 : -1) * t * sweep;
        out.push_back({cx + r * std::cos(a), cy + r * std::sin(a), at[2] + t * (s.pos[2] - at[2])});
      }
    } else {
      continue;
    }
    at = s.pos;
  }
  return out;
}

// Signed distance to a rectangle of half sides a x b with corners rounded by rc, centred at the
// origin (negative inside).
double roundedBox(double x, double y, double a, double b, double rc) {
  double qx = std::fabs(x) - (a - rc), qy = std::fabs(y) - (b - rc);
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - rc;
}

// roundedBox about (cx, cy), turned by `radians`.
std::function<double(double, double)> turnedBox(double cx, double cy, double radians, double a, double b, double rc) {
  const double c = std::cos(radians), s = std::sin(radians);
  return [=](double x, double y) {
    double dx = x - cx, dy = y - cy;
    return roundedBox(c * dx + s * dy, -s * dx + c * dy, a, b, rc);
  };
}

// What the cycle machines: `wall` is the signed distance to the finished part's wall, negative
// where the material to clear is (inside a pocket, outside a stud); `blank` (a stud's) is
// negative inside the blank. The box bounds the sampling.
struct Pocket {
  std::function<double(double, double)> wall;
  double xmin, xmax, ymin, ymax;
  std::function<double(double, double)> blank = [](double, double) { return -1.0; };
};

// Runs the entry and checks the wall and the coverage. `keep`: the material the pass leaves
// on the wall (the side allowance when only roughing); `bottom`: the final level.
void checkPocket(const char *entry, const CycleArgs &args, const CycleContext &ctx, const Pocket &p, double keep,
                 double bottom, double surface) {
  SCOPED_TRACE(entry);
  const CycleDef *d = findCycle(entry);
  ASSERT_NE(d, nullptr);
  std::vector<CycleStep> steps;
  std::string err;
  ASSERT_TRUE(d->expand(args, ctx, steps, err)) << err;
  std::vector<Sample> path = samplePath(steps, ctx.position);
  const double r = ctx.toolRadius;
  // (1) Below the surface the tool stays inside the wall less `keep` (chords sag inward only).
  double worst = -1e9;
  for (const Sample &s : path)
    if (s.z < surface) worst = std::max(worst, p.wall(s.x, s.y) + r + keep);
  EXPECT_LE(worst, 1e-6) << "the tool cuts " << worst << " mm beyond the wall";
  // (2) At the final depth every point of the region to clear is within a radius of the path.
  // The floor's samples in cells of a tool radius: a point's reach is in its 3 x 3 cells.
  std::map<std::pair<long, long>, std::vector<Sample>> cells;
  auto cell = [&](double v) { return (long)std::floor(v / r); };
  for (const Sample &s : path)
    if (std::fabs(s.z - bottom) < 1e-9) cells[{cell(s.x), cell(s.y)}].push_back(s);
  ASSERT_FALSE(cells.empty());
  int points = 0, missed = 0;
  double worstGap = 0;
  for (double x = p.xmin; x <= p.xmax; x += 0.25)
    for (double y = p.ymin; y <= p.ymax; y += 0.25) {
      if (p.wall(x, y) > -keep - 1e-3 || p.blank(x, y) > 0) continue;  // not to clear (or its edge)
      ++points;
      double best = 1e18;
      for (long i = cell(x) - 1; i <= cell(x) + 1; ++i)
        for (long j = cell(y) - 1; j <= cell(y) + 1; ++j)
          if (auto it = cells.find({i, j}); it != cells.end())
            for (const Sample &s : it->second) best = std::min(best, std::hypot(s.x - x, s.y - y));
      worstGap = std::max(worstGap, best - r);
      if (best > r + 0.03) ++missed;  // sampling 0.05 mm plus chords 0.001 mm
    }
  EXPECT_GT(points, 100);
  EXPECT_EQ(missed, 0) << "material left standing: up to " << worstGap << " mm out of the tool's reach";
}

CycleArgs args(std::initializer_list<std::pair<const char *, double>> kv) {
  CycleArgs a;
  for (auto &[k, v] : kv) a.num[k] = v;
  return a;
}

CycleContext at(double x, double y, double z, double toolRadius) {
  CycleContext c;
  c.position = {x, y, z};
  c.toolRadius = toolRadius;
  c.spindle = 1;
  return c;
}
}  // namespace

TEST(ClearingEntries, RectangularPocketRoughAndFinish) {
  // 60 x 30, corners = tool radius (Q220 0), allowances finished away: the whole pocket.
  CycleArgs a = args({{"Q215", 0}, {"Q218", 60}, {"Q219", 30}, {"Q220", 0}, {"Q368", 0.4}, {"Q207", 500},
                      {"Q201", -8}, {"Q202", 3}, {"Q369", 0.2}, {"Q206", 150}, {"Q200", 2}, {"Q203", 0},
                      {"Q204", 20}, {"Q370", 1.2}});
  Pocket p{[](double x, double y) { return roundedBox(x - 10, y - 5, 30, 15, 5); }, -21, 41, -11, 21};
  checkPocket("hei.251", a, at(10, 5, 50, 5), p, 0, -8, 0);
}

TEST(ClearingEntries, RectangularPocketRotatedFromCornerUpCut) {
  // Tool at the lower-left corner (Q367 1), pocket turned 30 degrees about it, up-cut, corner
  // radius 7 with a 3 mm tool, wide stepover (Q370 1.9: the rings' corners would leave material).
  CycleArgs a = args({{"Q215", 0}, {"Q218", 50}, {"Q219", 24}, {"Q220", 7}, {"Q368", 0.5}, {"Q224", 30},
                      {"Q367", 1}, {"Q207", 500}, {"Q351", -1}, {"Q201", -5}, {"Q202", 5}, {"Q369", 0.3},
                      {"Q206", 150}, {"Q338", 2}, {"Q200", 2}, {"Q203", 1}, {"Q204", 10}, {"Q370", 1.9}});
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double cx = 25 * c - 12 * s, cy = 25 * s + 12 * c;  // the centre from the corner
  Pocket p{turnedBox(cx, cy, M_PI / 6, 25, 12, 7), -15, 40, -5, 45};
  checkPocket("hei.251", a, at(0, 0, 30, 3), p, 0, -4, 1);
}

TEST(ClearingEntries, RectangularPocketRoughingLeavesTheAllowance) {
  // Roughing only: the walls keep Q368, the floor Q369; corners 6 >= tool radius + allowance.
  CycleArgs a = args({{"Q215", 1}, {"Q218", 40}, {"Q219", 40}, {"Q220", 6}, {"Q368", 1}, {"Q207", 500},
                      {"Q201", -6}, {"Q202", 4}, {"Q369", 0.5}, {"Q206", 150}, {"Q200", 2}, {"Q203", 0},
                      {"Q370", 1.5}});
  Pocket p{[](double x, double y) { return roundedBox(x, y, 20, 20, 6); }, -21, 21, -21, 21};
  checkPocket("hei.251", a, at(0, 0, 10, 4), p, 1, -5.5, 0);
}

TEST(ClearingEntries, CircularPocket) {
  CycleArgs a = args({{"Q215", 0}, {"Q223", 50}, {"Q368", 0.5}, {"Q207", 500}, {"Q201", -12}, {"Q202", 5},
                      {"Q369", 0.2}, {"Q206", 150}, {"Q338", 6}, {"Q200", 2}, {"Q203", 0}, {"Q204", 20},
                      {"Q370", 1.9}, {"Q385", 300}});
  Pocket p{[](double x, double y) { return std::hypot(x - 5, y + 5) - 25; }, -21, 31, -31, 21};
  checkPocket("hei.252", a, at(5, -5, 40, 6), p, 0, -12, 0);
}

TEST(ClearingEntries, CircularPocketUnderM4RunsTheOtherWay) {
  CycleArgs a = args({{"Q215", 2}, {"Q223", 30}, {"Q368", 0.5}, {"Q207", 500}, {"Q201", -5}, {"Q202", 5},
                      {"Q206", 150}, {"Q200", 2}, {"Q203", 0}});
  CycleContext ctx = at(0, 0, 10, 5);
  std::vector<CycleStep> m3, m4;
  std::string err;
  ASSERT_TRUE(findCycle("hei.252")->expand(a, ctx, m3, err)) << err;
  ctx.spindle = 2;
  ASSERT_TRUE(findCycle("hei.252")->expand(a, ctx, m4, err)) << err;
  int arcs = 0;
  for (size_t i = 0; i < m3.size(); ++i)
    if (m3[i].kind == CycleStepKind::Arc) {
      ++arcs;
      EXPECT_TRUE(m3[i].ccw);  // climb in a pocket with M3: counter-clockwise
      EXPECT_FALSE(m4[i].ccw);
    }
  EXPECT_EQ(arcs, 3);  // onto the wall, the wall, off it
}

TEST(Clearing, WideStepoverShrinksToLeaveNothing) {
  // Rings 9.5 apart with a radius-5 tool would leave material between their sharp corners.
  ClearingSpec s;
  s.contour = {{0, 0}, {60, 0}, {60, 60}, {0, 60}};
  s.toolRadius = 5, s.stepover = 9.5;
  std::vector<Polygon> rings;
  std::string err;
  ASSERT_TRUE(clearingRings(s, rings, err)) << err;
  for (double x = 5; x <= 55; x += 0.5)
    for (double y = 5; y <= 55; y += 0.5) {
      double best = 1e18;
      for (auto &ring : rings)
        for (size_t i = 0; i < ring.size(); ++i) {
          auto &p = ring[i], &q = ring[(i + 1) % ring.size()];
          double dx = q[0] - p[0], dy = q[1] - p[1], l2 = dx * dx + dy * dy;
          double t = l2 > 0 ? std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / l2, 0.0, 1.0) : 0;
          best = std::min(best, std::hypot(p[0] + t * dx - x, p[1] + t * dy - y));
        }
      ASSERT_LE(best, 5 + 1e-3) << "at " << x << "," << y;
    }
}

TEST(ClearingEntries, SlotFromTheLeftArcTurned) {
  // 60 x 14 slot, the tool (radius 3) at the left arc's centre (Q367 2), turned 45 degrees.
  CycleArgs a = args({{"Q215", 0}, {"Q218", 60}, {"Q219", 14}, {"Q368", 0.3}, {"Q374", 45}, {"Q367", 2},
                      {"Q207", 500}, {"Q201", -6}, {"Q202", 2}, {"Q369", 0.2}, {"Q206", 150}, {"Q338", 3},
                      {"Q200", 2}, {"Q203", 0}, {"Q204", 10}});
  // The centre: half the length less half the width along 45 degrees.
  Pocket p{turnedBox(23 * std::cos(M_PI / 4), 23 * std::sin(M_PI / 4), M_PI / 4, 30, 7, 7), -10, 45, -10, 45};
  checkPocket("hei.253", a, at(0, 0, 20, 3), p, 0, -6, 0);
}

TEST(ClearingEntries, SlotAsWideAsTheTool) {
  // Q219 = the tool diameter: one pass along the centre line per level, lifted out after each.
  CycleArgs a = args({{"Q215", 1}, {"Q218", 40}, {"Q219", 8}, {"Q207", 500}, {"Q201", -6}, {"Q202", 3},
                      {"Q206", 150}, {"Q200", 2}, {"Q203", 0}});
  Pocket p{[](double x, double y) { return roundedBox(x, y, 20, 4, 4); }, -21, 21, -5, 5};
  checkPocket("hei.253", a, at(0, 0, 20, 4), p, 0, -6, 0);
}

TEST(ClearingEntries, RectangularStud) {
  // Stud 40 x 20 (corners 2) in a 60 x 34 blank, turned 20 degrees, allowances finished away.
  CycleArgs a = args({{"Q218", 40}, {"Q424", 60}, {"Q219", 20}, {"Q425", 34}, {"Q220", 2}, {"Q368", 0.5},
                      {"Q224", 20}, {"Q207", 500}, {"Q201", -5}, {"Q202", 3}, {"Q206", 150}, {"Q200", 2},
                      {"Q203", 0}, {"Q204", 20}, {"Q370", 1.6}, {"Q215", 0}, {"Q369", 0.2}, {"Q338", 0}});
  auto stud = turnedBox(0, 0, M_PI / 9, 20, 10, 2);
  Pocket p{[=](double x, double y) { return -stud(x, y); }, -35, 35, -30, 30, turnedBox(0, 0, M_PI / 9, 30, 17, 0)};
  checkPocket("hei.256", a, at(0, 0, 30, 4), p, 0, -5, 0);
}

TEST(ClearingEntries, RectangularStudRoughingFromACorner) {
  // Roughing only, the tool at the stud's upper right corner (Q367 3): the allowance stays.
  CycleArgs a = args({{"Q218", 30}, {"Q424", 50}, {"Q219", 30}, {"Q425", 50}, {"Q368", 1}, {"Q367", 3},
                      {"Q207", 500}, {"Q201", -4}, {"Q202", 4}, {"Q206", 150}, {"Q200", 2}, {"Q203", 0},
                      {"Q215", 1}});
  Pocket p{[](double x, double y) { return -roundedBox(x + 15, y + 15, 15, 15, 0); }, -41, 11, -41, 11,
           [](double x, double y) { return std::max(std::fabs(x + 15), std::fabs(y + 15)) - 25; }};
  checkPocket("hei.256", a, at(0, 0, 30, 5), p, 1, -4, 0);
}

TEST(ClearingEntries, CircularStud) {
  CycleArgs a = args({{"Q223", 30}, {"Q222", 56}, {"Q368", 0.4}, {"Q207", 500}, {"Q351", -1}, {"Q201", -6},
                      {"Q202", 3}, {"Q206", 150}, {"Q200", 2}, {"Q203", 0}, {"Q204", 10}, {"Q370", 1.2},
                      {"Q376", 135}, {"Q215", 0}, {"Q369", 0.2}, {"Q338", 3}});
  Pocket p{[](double x, double y) { return 15 - std::hypot(x - 10, y); }, -20, 40, -30, 30,
           [](double x, double y) { return std::hypot(x - 10, y) - 28; }};
  checkPocket("hei.257", a, at(10, 0, 30, 5), p, 0, -6, 0);
}

TEST(ClearingEntries, SinumerikPocket3RoughWithHelixThenFinish) {
  // POCKET3 from its lower left corner (_GMODE 4th digit 2) turned 15 degrees: roughing with a
  // helical plunge, then finishing (_VARI 2) removes _FAL and _FALD.
  CycleArgs rough = args({{"_RTP", 10}, {"_RFP", 0}, {"_SDIS", 2}, {"_DP", -6}, {"_LENG", 50}, {"_WID", 30},
                          {"_CRAD", 6}, {"_PA", 5}, {"_PO", 5}, {"_STA", 15}, {"_MID", 2.5}, {"_FAL", 0.4},
                          {"_FALD", 0.2}, {"_FFP1", 400}, {"_FFD", 100}, {"_VARI", 21}, {"_MIDA", 7},
                          {"_RAD1", 3}, {"_DP1", 1.5}, {"_GMODE", 2000}});
  CycleArgs finish = rough;
  finish.num["_VARI"] = 12;
  const double c = std::cos(M_PI / 12), s = std::sin(M_PI / 12);
  Pocket p{turnedBox(5 + 25 * c - 15 * s, 5 + 25 * s + 15 * c, M_PI / 12, 25, 15, 6), -30, 40, -5, 50};
  checkPocket("sin.POCKET3", rough, at(0, 0, 20, 4), p, 0.4, -5.8, 0);
  checkPocket("sin.POCKET3", finish, at(0, 0, 20, 4), p, 0, -6, 0);
}

TEST(ClearingEntries, SinumerikPocket4) {
  // _CDIAM a diameter (_DMODE 3rd digit 1), pre-drilled (_VARI 2nd digit 0), conventional.
  CycleArgs a = args({{"_RTP", 10}, {"_RFP", 1}, {"_SDIS", 1}, {"_DP", 5}, {"_CDIAM", 36}, {"_PA", -10},
                      {"_PO", 0}, {"_MID", 5}, {"_FFP1", 400}, {"_FFD", 100}, {"_CDIR", 1}, {"_VARI", 1},
                      {"_MIDA", 90}, {"_DMODE", 100}, {"_AMODE", 11}});
  Pocket p{[](double x, double y) { return std::hypot(x + 10, y) - 18; }, -29, 9, -19, 19};
  checkPocket("sin.POCKET4", a, at(0, 0, 20, 5), p, 0, -4, 1);
}

TEST(ClearingEntries, FaceMillingCoversTheSurface) {
  // 232 meander (Q389 0) and one-way (2) over 47 x -23 from (5, 5), and 233 the same surface by
  // its upper left corner (Q367 4) with the lines along Y (Q350 2): the whole face at Q386, never
  // below it.
  for (int run = 0; run < 4; ++run) {
    const int strategy = run % 2 == 0 ? 0 : 2;
    SCOPED_TRACE(run);
    CycleArgs a = args({{"Q389", (double)strategy}, {"Q225", 5}, {"Q226", 5}, {"Q227", 3}, {"Q386", 0},
                        {"Q218", 47}, {"Q219", -23}, {"Q202", 1.2}, {"Q369", 0.3}, {"Q370", 1.7}, {"Q207", 500},
                        {"Q385", 300}, {"Q253", 2000}, {"Q200", 2}, {"Q357", 2}, {"Q204", 10}});
    const char *entry = run < 2 ? "hei.232" : "hei.233";
    if (run >= 2) {
      a.num.erase("Q225"), a.num.erase("Q226");
      a.num["Q350"] = 2, a.num["Q367"] = 4, a.num["Q215"] = 0;
    }
    const CycleContext ctx = run < 2 ? at(0, 0, 30, 6) : at(5, 5, 30, 6);
    std::vector<CycleStep> steps;
    std::string err;
    ASSERT_TRUE(findCycle(entry)->expand(a, ctx, steps, err)) << err;
    std::vector<Sample> path = samplePath(steps, ctx.position);
    std::vector<Sample> face;
    for (const Sample &q : path) {
      EXPECT_GE(q.z, -1e-9);
      if (std::fabs(q.z) < 1e-9) face.push_back(q);
    }
    for (double x = 5; x <= 52; x += 0.5)
      for (double y = -18; y <= 5; y += 0.5) {
        double best = 1e18;
        for (const Sample &q : face) best = std::min(best, std::hypot(q.x - x, q.y - y));
        ASSERT_LE(best, 6 + 0.03) << "at " << x << "," << y;
      }
  }
}

// Signed distance to a slot along the arc of radius rp about (cx, cy) from `from` through `sweep`
// degrees, w wide.
std::function<double(double, double)> arcSlot(double cx, double cy, double rp, double from, double sweep, double w) {
  return [=](double x, double y) {
    double dx = x - cx, dy = y - cy;
    double a = std::atan2(dy, dx) * 180 / M_PI - from;
    a = std::fmod(std::fmod(a, 360) + 360, 360);
    if (a <= sweep) return std::fabs(std::hypot(dx, dy) - rp) - w / 2;
    double best = 1e18;
    for (double e : {from, from + sweep})
      best = std::min(best, std::hypot(dx - rp * std::cos(e * M_PI / 180), dy - rp * std::sin(e * M_PI / 180)));
    return best - w / 2;
  };
}

TEST(ClearingEntries, CircularSlotRepeated) {
  // Two slots 16 wide on a 60 mm circle about (10, 5), 100 degrees long from 20, the second turned
  // by 180: each the whole slot, the tool never beyond its wall.
  CycleArgs a = args({{"Q215", 0}, {"Q219", 16}, {"Q368", 0.4}, {"Q375", 60}, {"Q367", 0}, {"Q216", 10}, {"Q217", 5},
                      {"Q376", 20}, {"Q248", 100}, {"Q378", 180}, {"Q377", 2}, {"Q207", 500}, {"Q201", -4},
                      {"Q202", 2}, {"Q369", 0.2}, {"Q206", 150}, {"Q338", 0}, {"Q200", 2}, {"Q203", 0}, {"Q204", 10}});
  auto one = arcSlot(10, 5, 30, 20, 100, 16), two = arcSlot(10, 5, 30, 200, 100, 16);
  Pocket p{[=](double x, double y) { return std::min(one(x, y), two(x, y)); }, -30, 50, -35, 45};
  checkPocket("hei.254", a, at(0, 0, 20, 3), p, 0, -4, 0);
}

TEST(ClearingEntries, CircularSlotFromItsStartAsWideAsTheTool) {
  // Q367 1: the tool at the start end's centre, the circle's centre 25 back along 30 degrees; the
  // slot as wide as the tool: the centre arc itself.
  CycleArgs a = args({{"Q215", 1}, {"Q219", 8}, {"Q375", 50}, {"Q367", 1}, {"Q376", 30}, {"Q248", 60}, {"Q207", 500},
                      {"Q201", -3}, {"Q202", 3}, {"Q206", 150}, {"Q200", 2}, {"Q203", 0}});
  const double cx = -25 * std::cos(M_PI / 6), cy = -25 * std::sin(M_PI / 6);
  Pocket p{arcSlot(cx, cy, 25, 30, 60, 8), -30, 30, -30, 30};
  checkPocket("hei.254", a, at(0, 0, 20, 4), p, 0, -3, 0);
}

TEST(ClearingEntries, SinumerikSlot1RoughThenFinish) {
  // SLOT1 50 x 14 from its right end (_GMODE 4th digit 4) at (40, 10) turned 30 degrees, helix
  // plunge; then finishing (VARI 2).
  CycleArgs rough = args({{"RTP", 10}, {"RFP", 0}, {"SDIS", 2}, {"_DPR", 5}, {"LENG", 50}, {"WID", 14}, {"_CPA", 40},
                          {"_CPO", 10}, {"STA1", 30}, {"FFD", 100}, {"FFP1", 400}, {"_MID", 2}, {"_FAL", 0.4},
                          {"_FALD", 0.2}, {"VARI", 21}, {"_STA2", 2}, {"_DP1", 1}, {"_GMODE", 4000}});
  CycleArgs finish = rough;
  finish.num["VARI"] = 12;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  Pocket p{turnedBox(40 - 25 * c, 10 - 25 * s, M_PI / 6, 25, 7, 7), -10, 50, -20, 30};
  checkPocket("sin.SLOT1", rough, at(0, 0, 20, 3), p, 0.4, -4.8, 0);
  checkPocket("sin.SLOT1", finish, at(0, 0, 20, 3), p, 0, -5, 0);
}

TEST(ClearingEntries, SinumerikLonghole) {
  CycleArgs a = args({{"RTP", 10}, {"_RFP", 0}, {"SDIS", 2}, {"_DP", -5}, {"LENG", 30}, {"_CPA", 0}, {"_CPO", 0},
                      {"STA1", 45}, {"FFD", 100}, {"FFP1", 400}, {"MID", 2.5}, {"_VARI", 1}, {"_GMODE", 1000}});
  const double c = std::cos(M_PI / 4);
  Pocket p{turnedBox(11 * c, 11 * c, M_PI / 4, 15, 4, 4), -10, 30, -10, 30};
  checkPocket("sin.LONGHOLE", a, at(0, 0, 20, 4), p, 0, -5, 0);
}

TEST(ClearingEntries, SinumerikSlot2) {
  // Three 50-degree slots 10 wide on a 25 mm radius about (5, -5), complete (rough, then the wall).
  CycleArgs a = args({{"RTP", 10}, {"RFP", 0}, {"SDIS", 2}, {"_DP", -4}, {"NUM", 3}, {"AFSL", 50}, {"WID", 10},
                      {"_CPA", 5}, {"_CPO", -5}, {"RAD", 25}, {"STA1", 30}, {"INDA", 0}, {"FFD", 100},
                      {"FFP1", 400}, {"_MID", 2}, {"_FAL", 0.3}, {"VARI", 0}});
  auto s1 = arcSlot(5, -5, 25, 30, 50, 10), s2 = arcSlot(5, -5, 25, 150, 50, 10), s3 = arcSlot(5, -5, 25, 270, 50, 10);
  Pocket p{[=](double x, double y) { return std::min({s1(x, y), s2(x, y), s3(x, y)}); }, -30, 40, -40, 30};
  checkPocket("sin.SLOT2", a, at(0, 0, 20, 3), p, 0, -4, 0);
}

TEST(ClearingEntries, PolygonStud) {
  // A hexagon on a 40 mm circumscribed circle (Q573 1), first corner at 10 degrees, corners
  // rounded 2, from a 52 mm blank about (5, 5): never into the stud, nothing left of the blank.
  CycleArgs a = args({{"Q573", 1}, {"Q571", 40}, {"Q222", 52}, {"Q572", 6}, {"Q224", 10}, {"Q220", 2}, {"Q368", 0.5},
                      {"Q207", 500}, {"Q201", -4}, {"Q202", 2}, {"Q206", 150}, {"Q200", 2}, {"Q203", 0},
                      {"Q204", 10}, {"Q370", 1.3}, {"Q215", 0}, {"Q369", 0.2}, {"Q338", 2}});
  // Signed distance to the rounded hexagon: the shrunk hexagon's distance less the rounding.
  std::vector<std::array<double, 2>> corners;
  const double apothem = 20 * std::cos(M_PI / 6), shrunk = (apothem - 2) / std::cos(M_PI / 6);
  for (int k = 0; k < 6; ++k) {
    double t = (10 + 60 * k) * M_PI / 180;
    corners.push_back({5 + shrunk * std::cos(t), 5 + shrunk * std::sin(t)});
  }
  auto stud = [=](double x, double y) {
    double best = 1e18, inside = -1e18;
    for (int k = 0; k < 6; ++k) {
      auto &p = corners[k], &q = corners[(k + 1) % 6];
      double dx = q[0] - p[0], dy = q[1] - p[1], l2 = dx * dx + dy * dy;
      double t = std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / l2, 0.0, 1.0);
      best = std::min(best, std::hypot(p[0] + t * dx - x, p[1] + t * dy - y));
      double nx = dy / std::sqrt(l2), ny = -dx / std::sqrt(l2);  // outward (corners counter-clockwise)
      inside = std::max(inside, (x - p[0]) * nx + (y - p[1]) * ny);
    }
    return (inside <= 0 ? inside : best) - 2;
  };
  Pocket p{[=](double x, double y) { return -stud(x, y); }, -22, 32, -22, 32,
           [](double x, double y) { return std::hypot(x - 5, y - 5) - 26; }};
  checkPocket("hei.258", a, at(5, 5, 30, 4), p, 0, -4, 0);
}
