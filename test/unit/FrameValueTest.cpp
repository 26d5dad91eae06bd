// FRAME values (ir/FrameValue.h): chaining is composition, the inverse undoes a frame, and the
// component form reads back what built the frame.
#include "ir/FrameValue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

using namespace ncc;

namespace {
void applyFrame(const FrameValue &f, const double *x, double *out) {
  for (int i = 0; i < 3; ++i) out[i] = f.offset(i) + f.L[i][0] * x[0] + f.L[i][1] * x[1] + f.L[i][2] * x[2];
  for (int i = 0; i < 3; ++i) out[3 + i] = f.offset(3 + i) + f.rotary[i] * x[3 + i];
}

FrameValue randomFrame(std::mt19937 &rng, bool uniformScale) {
  std::uniform_real_distribution<double> ang(-179, 179), off(-100, 100), sc(0.5, 2);
  FrameParts p;
  p.rt[0] = ang(rng), p.rt[1] = ang(rng) / 2, p.rt[2] = ang(rng);
  double s = sc(rng);
  for (int i = 0; i < kFrameAxes; ++i) {
    p.tr[i] = off(rng), p.fi[i] = off(rng) / 100;
    p.sc[i] = uniformScale && i < 3 ? s : sc(rng);
  }
  p.mi[rng() % 3] = rng() % 2;
  p.mi[3 + rng() % 3] = rng() % 2;
  return frameCompose(p);
}
}  // namespace

TEST(FrameValue, ChainIsComposition) {
  std::mt19937 rng(7);
  for (int n = 0; n < 200; ++n) {
    FrameValue a = randomFrame(rng, false), b = randomFrame(rng, false);
    double x[6] = {1.5, -2, 3, 10, 20, 30}, bx[6], abx[6], chained[6];
    applyFrame(b, x, bx);
    applyFrame(a, bx, abx);
    applyFrame(frameChain(a, b), x, chained);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(abx[i], chained[i], 1e-9);
  }
}

TEST(FrameValue, InverseUndoes) {
  std::mt19937 rng(11);
  for (int n = 0; n < 200; ++n) {
    FrameValue f = randomFrame(rng, false);
    double x[6] = {4, 5, -6, 1, 2, 3}, y[6], back[6];
    applyFrame(f, x, y);
    applyFrame(frameInverse(f), y, back);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], x[i], 1e-9);
  }
}

TEST(FrameValue, ComponentsReadBack) {
  std::mt19937 rng(3);
  for (int n = 0; n < 500; ++n) {
    FrameValue f = randomFrame(rng, true);
    FrameParts p;
    std::string err;
    ASSERT_TRUE(frameDecompose(f, p, err)) << err;
    FrameValue g = frameCompose(p);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(g.L[i][j], f.L[i][j], 1e-9);
    for (int i = 0; i < kFrameAxes; ++i) {
      EXPECT_EQ(p.tr[i], f.coarse[i]);
      EXPECT_EQ(p.fi[i], f.fine[i]);
    }
    // The angle ranges of the manual: X and Z within ±180, Y within ±90.
    EXPECT_LE(std::fabs(p.rt[0]), 180);
    EXPECT_LE(std::fabs(p.rt[1]), 90);
    EXPECT_LE(std::fabs(p.rt[2]), 180);
  }
}

TEST(FrameValue, WrittenComponentsReadBackExactly) {
  FrameParts p;
  p.rt[0] = 10, p.rt[1] = 20, p.rt[2] = 30;
  p.sc[0] = p.sc[1] = p.sc[2] = 2;
  p.mi[1] = true;
  FrameParts q;
  std::string err;
  ASSERT_TRUE(frameDecompose(frameCompose(p), q, err));
  EXPECT_EQ(q.rt[0], 10);
  EXPECT_EQ(q.rt[1], 20);
  EXPECT_EQ(q.rt[2], 30);
  EXPECT_EQ(q.sc[0], 2);
  EXPECT_FALSE(q.mi[0]);
  EXPECT_TRUE(q.mi[1]);
  EXPECT_FALSE(q.mi[2]);
}

TEST(FrameValue, GimbalLockGoesToZ) {
  FrameParts p;
  p.rt[1] = 90, p.rt[2] = 40;
  FrameParts q;
  std::string err;
  ASSERT_TRUE(frameDecompose(frameCompose(p), q, err));
  EXPECT_EQ(q.rt[0], 0);
  EXPECT_EQ(q.rt[1], 90);
  EXPECT_EQ(q.rt[2], 40);
}

TEST(FrameValue, UnequalScaleWithRotationHasNoComponents) {
  FrameParts s, r;
  s.sc[0] = 2;
  r.rt[2] = 30;
  FrameParts q;
  std::string err;
  EXPECT_FALSE(frameDecompose(frameChain(frameCompose(s), frameCompose(r)), q, err));
  EXPECT_NE(err.find("unequal scale"), std::string::npos);
  // CROT : CSCALE is R · S, the component form itself.
  ASSERT_TRUE(frameDecompose(frameChain(frameCompose(r), frameCompose(s)), q, err));
  EXPECT_EQ(q.rt[2], 30);
  EXPECT_EQ(q.sc[0], 2);
}

TEST(FrameValue, QuarterTurnsAreExact) {
  double R[3][3];
  frameRotation(0, 0, 90, R);
  EXPECT_EQ(R[0][0], 0);
  EXPECT_EQ(R[0][1], -1);
  EXPECT_EQ(R[1][0], 1);
  frameRotation(-270, 0, 0, R);  // sin(-270°) = 1
  EXPECT_EQ(R[1][1], 0);
  EXPECT_EQ(R[2][1], 1);
  EXPECT_EQ(R[1][2], -1);
}

TEST(FrameValue, PoolInternsEqualFrames) {
  FramePool pool;
  FrameParts p;
  p.tr[0] = 5;
  double a, b, c;
  std::string err;
  ASSERT_TRUE(pool.intern(frameCompose(p), a, err));
  ASSERT_TRUE(pool.intern(frameCompose(p), b, err));
  ASSERT_TRUE(pool.intern(FrameValue{}, c, err));
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  EXPECT_TRUE(pool.get(c).identity());
  EXPECT_EQ(pool.get(a).coarse[0], 5);
  EXPECT_EQ(frameText(pool.get(a)), "TR X5");
}

// ROTS/AROTS/CROTS (SIN-FRM-31): the solid-angle rotation against the definition (Siemens K2,
// "Frame rotations with solid angles"): for two angles at the first axis f and the second s of a
// plane (X Y, Y Z, Z X; third t), the new f is f turned about s by the angle at s (so it stays in
// the old f-t plane), the new plane also holds s turned about f by the angle at f, and the
// result is a proper rotation. One angle is the plain rotation about its axis.
TEST(FrameValue, SolidAnglesFollowTheDefinition) {
  auto axisTurn = [](int axis, double deg, int v, double out[3]) {  // e_v turned about `axis`
    double a[3] = {}, R[3][3];
    a[axis] = deg;
    frameRotation(a[0], a[1], a[2], R);
    for (int i = 0; i < 3; ++i) out[i] = R[i][v];
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ang(-85, 85);
  for (int f = 0; f < 3; ++f) {
    int s = (f + 1) % 3, t = (f + 2) % 3;
    for (int n = 0; n < 50; ++n) {
      bool given[3] = {};
      double angle[3] = {}, R[3][3];
      given[f] = given[s] = true;
      angle[f] = ang(rng), angle[s] = ang(rng);
      std::string err;
      ASSERT_TRUE(frameSolidRotation(given, angle, R, err)) << err;
      for (int i = 0; i < 3; ++i)  // orthonormal
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(R[0][i] * R[0][j] + R[1][i] * R[1][j] + R[2][i] * R[2][j], i == j ? 1 : 0, 1e-12);
      double det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) - R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
                   R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
      EXPECT_NEAR(det, 1, 1e-12);
      double fTurned[3], sTurned[3];
      axisTurn(s, angle[s], f, fTurned);
      axisTurn(f, angle[f], s, sTurned);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(R[i][f], fTurned[i], 1e-12) << "new first axis, f=" << f;
      EXPECT_NEAR(R[s][f], 0, 1e-12);  // in the old f-t plane
      double normalDotS = R[0][t] * sTurned[0] + R[1][t] * sTurned[1] + R[2][t] * sTurned[2];
      EXPECT_NEAR(normalDotS, 0, 1e-12) << "the plane holds s turned about f";
    }
  }
  // ROTS X30 Y45 by hand: new X (cos45, 0, -sin45), the plane's normal ∝ X' × (0, cos30, sin30).
  bool xy[3] = {true, true, false};
  double a[3] = {30, 45, 0}, R[3][3];
  std::string err;
  ASSERT_TRUE(frameSolidRotation(xy, a, R, err));
  double c45 = std::sqrt(0.5), c30 = std::sqrt(3) / 2, n[3] = {c45 * c30, -c45 * 0.5, c45 * c30};
  double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  EXPECT_NEAR(R[0][0], c45, 1e-12);
  EXPECT_NEAR(R[1][0], 0, 1e-12);
  EXPECT_NEAR(R[2][0], -c45, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(R[i][2], n[i] / len, 1e-12);
  // One angle: ROT about that axis.
  for (int k = 0; k < 3; ++k) {
    bool one[3] = {};
    double ang1[3] = {}, Q[3][3], P[3][3];
    one[k] = true, ang1[k] = 37;
    ASSERT_TRUE(frameSolidRotation(one, ang1, Q, err));
    frameRotation(ang1[0], ang1[1], ang1[2], P);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(Q[i][j], P[i][j], 1e-15);
  }
  bool all[3] = {true, true, true};
  EXPECT_FALSE(frameSolidRotation(all, a, R, err));
  double right[3] = {90, 90, 0};
  EXPECT_FALSE(frameSolidRotation(xy, right, R, err));
}
