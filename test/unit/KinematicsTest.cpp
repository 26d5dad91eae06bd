// The rotary kinematics library (runtime/Kinematics.h): forward ∘ inverse round trips for each
// chain type, the analytic poses of docs/MACHINE.md, the singular pose, travel limits, the
// choice between the two solutions, unreachable orientations.
#include "runtime/Kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;

namespace {

const std::string kLinear = R"(
[axes.X]
max_velocity = 1000
max_accel = 100
min = -2000
max = 2000
[axes.Y]
max_velocity = 1000
max_accel = 100
min = -2000
max = 2000
[axes.Z]
max_velocity = 1000
max_accel = 100
min = -2000
max = 2000
)";

std::string rotary(const char *name, double lo, double hi) {
  return std::string("[axes.") + name + "]\nmax_velocity = 1000\nmax_accel = 100\nmin = " + std::to_string(lo) +
         "\nmax = " + std::to_string(hi) + "\n";
}

std::string joint(const char *axis, const char *on, const char *dir, const char *center) {
  return std::string("[[kinematics.joints]]\naxis = \"") + axis + "\"\non = \"" + on + "\"\ndirection = " + dir +
         "\ncenter = " + center + "\n";
}

Machine machine(const std::string &text) {
  Machine m;
  std::string err;
  EXPECT_TRUE(Machine::parse("schema = 1\n" + text + kLinear, "k.toml", m, err)) << err;
  return m;
}

// A/C trunnion with the C axis off the A axis (pivot offsets in Y and Z), ISO 841 directions.
Machine trunnion(const char *prefer = "nearest", double aMin = -120, double aMax = 120) {
  return machine(std::string("[kinematics]\ntype = \"table-table\"\nprefer = \"") + prefer + "\"\n" +
                 joint("A", "table", "[-1, 0, 0]", "[0, 10, -300]") + joint("C", "table", "[0, 0, -1]", "[5, 12, 0]") +
                 rotary("A", aMin, aMax) + rotary("C", -1e9, 1e9));
}

// B/C fork head, C carrying B, pivot 180 mm above the gauge point.
Machine forkHead() {
  return machine("[kinematics]\ntype = \"head-head\"\n" + joint("C", "head", "[0, 0, 1]", "[0, 0, 0]") +
                 joint("B", "head", "[0, 1, 0]", "[0, 0, 180]") + rotary("B", -110, 110) + rotary("C", -400, 400));
}

// B head and C table.
Machine headTable() {
  return machine("[kinematics]\ntype = \"head-table\"\n" + joint("B", "head", "[0, 1, 0]", "[3, 0, 150]") +
                 joint("C", "table", "[0, 0, -1]", "[20, -7, -400]") + rotary("B", -100, 100) + rotary("C", -1e9, 1e9));
}

// A 45-degree nutating head: B about (0, 0.7071, 0.7071) under C; the tool reaches the upper
// hemisphere only.
Machine nutator() {
  return machine("[kinematics]\ntype = \"head-head\"\n" + joint("C", "head", "[0, 0, 1]", "[0, 0, 0]") +
                 joint("B", "head", "[0, 0.70710678, 0.70710678]", "[0, 0, 200]") + rotary("B", -1e9, 1e9) +
                 rotary("C", -1e9, 1e9));
}

// A head whose spindle lies along +X at zero: C (head, about Z) swings it, A (table) tilts the part.
Machine horizontalSpindle() {
  return machine("[kinematics]\ntype = \"head-table\"\ntool_axis = [1, 0, 0]\n" +
                 joint("A", "table", "[1, 0, 0]", "[0, 30, -200]") + joint("C", "head", "[0, 0, 1]", "[-120, 0, 0]") +
                 rotary("A", -1e9, 1e9) + rotary("C", -150, 150));
}

void expectNear(const Vec3 &a, const Vec3 &b, double tol, const std::string &what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << what << " [" << i << "]";
}

double angleDiff(double a, double b) { return std::fabs(std::remainder(a - b, 360.0)); }

// forward(q) -> inverse from q gives back q (the nearest solution), and every solution's forward
// gives the pose.
void roundTrips(const Machine &m, int axis1, int axis2, double range1, double range2) {
  Kinematics k(m);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> lin(-200, 200), u(-1, 1);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    AxisVec q{};
    q[0] = lin(rng), q[1] = lin(rng), q[2] = lin(rng);
    q[axis1] = u(rng) * range1, q[axis2] = u(rng) * range2;
    int tilt = m.chain.joints[m.chain.tiltJoint()].axis;
    if (std::fabs(std::remainder(q[tilt], 180.0)) < 1) continue;  // near the singular pose
    double length = 50 + 100 * std::fabs(u(rng));
    ToolPose p = k.forward(q, length);
    EXPECT_NEAR(std::sqrt(dot(p.axis, p.axis)), 1, 1e-12);
    InverseResult r = k.inverse(p, q, length);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_FALSE(r.singular);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.joints()[i], q[i], 1e-8) << "sample " << n;
    for (int i : {axis1, axis2}) EXPECT_NEAR(r.joints()[i], q[i], 1e-8) << "sample " << n;
    for (auto &s : r.solutions) {
      ToolPose back = k.forward(s.joints, length);
      expectNear(back.tip, p.tip, 1e-8, "tip");
      expectNear(back.axis, p.axis, 1e-12, "axis");
    }
    ++checked;
  }
  EXPECT_GT(checked, 250);
}

}  // namespace

TEST(Kinematics, RoundTripTableTable) { roundTrips(trunnion(), 3, 5, 119, 180); }
TEST(Kinematics, RoundTripHeadHead) { roundTrips(forkHead(), 4, 5, 109, 180); }
TEST(Kinematics, RoundTripHeadTable) { roundTrips(headTable(), 4, 5, 99, 180); }
TEST(Kinematics, RoundTripNutatingHead) { roundTrips(nutator(), 4, 5, 180, 180); }
TEST(Kinematics, RoundTripHorizontalSpindle) { roundTrips(horizontalSpindle(), 3, 5, 180, 149); }

// docs/MACHINE.md's worked example: tool axis (0, -sin 30, cos 30) on an A/C trunnion.
TEST(Kinematics, TrunnionAnalytic) {
  Machine m = machine("[kinematics]\ntype = \"table-table\"\n" + joint("A", "table", "[-1, 0, 0]", "[0, 0, -300]") +
                      joint("C", "table", "[0, 0, -1]", "[0, 0, 0]") + rotary("A", -120, 30) + rotary("C", -1e9, 1e9));
  Kinematics k(m);
  InverseResult r = k.inverse({{0, 0, 0}, {0, -0.5, std::sqrt(3) / 2}}, {});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.solutions.size(), 2u);
  EXPECT_EQ(r.chosen, 0);
  const AxisVec &a = r.solutions[0].joints, &b = r.solutions[1].joints;
  EXPECT_NEAR(a[3], 30, 1e-9);
  EXPECT_NEAR(a[5], 0, 1e-9);
  EXPECT_NEAR(a[1], 150, 1e-9);  // the work zero swings up by 300 sin 30 …
  EXPECT_NEAR(a[2], 300 * std::sqrt(3) / 2 - 300, 1e-9);  // … and 300 (1 - cos 30) down
  EXPECT_NEAR(b[3], -30, 1e-9);
  EXPECT_NEAR(angleDiff(b[5], 180), 0, 1e-9);
  EXPECT_NEAR(b[1], -150, 1e-9);
  // The forward transform of the chosen joints is the pose asked for.
  ToolPose p = k.forward(a);
  expectNear(p.tip, {0, 0, 0}, 1e-9, "tip");
  expectNear(p.axis, {0, -0.5, std::sqrt(3) / 2}, 1e-12, "axis");
}

TEST(Kinematics, ForkHeadAnalytic) {
  Kinematics k(forkHead());
  double s = std::sqrt(0.5);
  InverseResult r = k.inverse({{0, 0, 0}, {s, 0, s}}, {}, 100);
  ASSERT_TRUE(r.ok()) << r.error;
  const AxisVec &q = r.joints();
  EXPECT_NEAR(q[4], 45, 1e-9);
  EXPECT_NEAR(q[5], 0, 1e-9);
  // The gauge point sits where the pivot (180 above it) is 280 above the tip along the axis.
  EXPECT_NEAR(q[0], 280 * s, 1e-9);
  EXPECT_NEAR(q[2], 280 * s - 180, 1e-9);
}

// Tool axis along the table's C axis: C may be anything, it keeps its current value.
TEST(Kinematics, SingularKeepsTheFreeJoint) {
  Kinematics k(trunnion());
  AxisVec from{};
  from[5] = 77.5;
  InverseResult r = k.inverse({{1, 2, 3}, {0, 0, 1}}, from);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.singular);
  ASSERT_EQ(r.solutions.size(), 1u);
  EXPECT_NEAR(r.joints()[3], 0, 1e-12);
  EXPECT_DOUBLE_EQ(r.joints()[5], 77.5);
  expectNear(k.forward(r.joints()).tip, {1, 2, 3}, 1e-9, "tip");
  // The fork head: tool axis along C (the head's base joint) with B at zero.
  Kinematics h(forkHead());
  from[5] = -33;
  r = h.inverse({{0, 0, 0}, {0, 0, 1}}, from);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.singular);
  EXPECT_DOUBLE_EQ(r.joints()[5], -33);
  EXPECT_NEAR(r.joints()[4], 0, 1e-12);
}

TEST(Kinematics, LimitsChooseTheOtherSolution) {
  Kinematics k(trunnion("nearest", -120, 30));
  double s = std::sin(40 * M_PI / 180), c = std::cos(40 * M_PI / 180);
  // A = 40 would be nearest (C stays 0), but A stops at 30: A = -40 with C = 180.
  InverseResult r = k.inverse({{0, 0, 0}, {0, -s, c}}, {});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.solutions.size(), 2u);
  EXPECT_EQ(r.solutions[0].problem, "A = 40 is outside its travel -120..30");
  EXPECT_EQ(r.chosen, 1);
  EXPECT_NEAR(r.joints()[3], -40, 1e-9);
  EXPECT_NEAR(angleDiff(r.joints()[5], 180), 0, 1e-9);
  // A tilt of 125 fits neither way.
  s = std::sin(125 * M_PI / 180), c = std::cos(125 * M_PI / 180);
  r = k.inverse({{0, 0, 0}, {0, -s, c}}, {});
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error, "no solution within the travel: A=125 C=0: A = 125 is outside its travel -120..30; A=-125 "
                     "C=-180: A = -125 is outside its travel -120..30");
}

TEST(Kinematics, LinearTravel) {
  Kinematics k(trunnion());
  InverseResult r = k.inverse({{2100, 0, 0}, {0, 0, 1}}, {}, 200);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error, "no solution within the travel: A=0 C=0: X = 2100 is outside its travel -2000..2000");
}

TEST(Kinematics, Preference) {
  double s = std::sqrt(0.5);
  ToolPose pose{{0, 0, 0}, {s, 0, s}};
  for (auto [prefer, b] : {std::pair{"positive", 45.0}, {"negative", -45.0}}) {
    Machine m = forkHead();
    m.chain.prefer = prefer;
    InverseResult r = Kinematics(m).inverse(pose, {});
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r.joints()[4], b, 1e-9) << prefer;
  }
  // Nearest: from B = -40, C = 170 the negative tilt with C = 180 is closer.
  AxisVec from{};
  from[4] = -40, from[5] = 170;
  InverseResult r = Kinematics(forkHead()).inverse(pose, from);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.joints()[4], -45, 1e-9);
  EXPECT_NEAR(r.joints()[5], 180, 1e-9);
}

// An axis without travel limits turns the shortest way from where it is.
TEST(Kinematics, EndlessAxisShortestWay) {
  Kinematics k(trunnion());
  double s = std::sqrt(0.5);
  AxisVec from{};
  from[3] = 40, from[5] = 700;  // C at 700 = 340 + 360
  InverseResult r = k.inverse({{0, 0, 0}, {-s * 0.5, -s * std::sqrt(0.75), s}}, from);
  ASSERT_TRUE(r.ok()) << r.error;
  // The tool leans 30 degrees from -Y towards -X: C = 330 (+ 360), 10 degrees away.
  EXPECT_NEAR(r.joints()[3], 45, 1e-9);
  EXPECT_NEAR(r.joints()[5], 690, 1e-9);
}

TEST(Kinematics, Unreachable) {
  Kinematics k(nutator());
  InverseResult r = k.inverse({{0, 0, 0}, {1, 0, -1}}, {});
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error, "tool axis (0.7071, 0, -0.7071) is out of reach: it makes 135 degrees with the axis of C, the "
                     "chain reaches 0..90");
  r = k.inverse({{0, 0, 0}, {0, 0, 0}}, {});
  EXPECT_EQ(r.error, "tool axis (0, 0, 0) has no direction");
  // Horizontal is the edge of the reach.
  r = k.inverse({{0, 0, 0}, {1, 0, 0}}, {});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_NEAR(std::fabs(r.joints()[4]), 180, 1e-6);
}

TEST(Kinematics, XyzHasAFixedToolAxis) {
  Machine m = machine("");
  Kinematics k(m);
  InverseResult r = k.inverse({{1, 2, 3}, {0, 0, 2}}, {}, 100);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.joints(), (AxisVec{1, 2, 103, 0, 0, 0}));
  r = k.inverse({{1, 2, 3}, {0, 1, 0}}, {});
  EXPECT_EQ(r.error, "tool axis (0, 1, 0) cannot be reached: kinematics \"xyz\" keeps the tool axis at (0, 0, 1)");
  ToolPose p = k.forward({1, 2, 103, 0, 0, 0}, 100);
  expectNear(p.tip, {1, 2, 3}, 0, "tip");
}

// The reader's chain checks (the located messages are in test/lit/kinematics).
TEST(Kinematics, ReaderChecks) {
  auto error = [](const std::string &text) {
    Machine m;
    std::string err;
    EXPECT_FALSE(Machine::parse("schema = 1\n" + text + kLinear, "k.toml", m, err));
    return err;
  };
  std::string ac = rotary("A", -90, 90) + rotary("C", -1e9, 1e9);
  EXPECT_EQ(error("kinematics = \"head-head\"\n"),
            "k.toml:2:14: error: kinematics: \"head-head\" needs its data: write a [kinematics] table with type = "
            "\"head-head\" and its [[kinematics.joints]]");
  EXPECT_EQ(error("[kinematics]\ntype = \"table-table\"\n" + joint("A", "table", "[2, 0, 0]", "[0, 0, 0]") +
                  joint("C", "table", "[0, 0, 1]", "[0, 0, 0]") + ac),
            "k.toml:7:13: error: direction: expected a unit vector, its length is 2");
  EXPECT_EQ(error("[kinematics]\ntype = \"table-table\"\n" + joint("A", "table", "[1, 0, 0]", "[0, 0, 0]") +
                  joint("C", "table", "[-1, 0, 0]", "[0, 0, 0]") + ac),
            "k.toml:12:13: error: joints A and C turn about parallel directions: the chain cannot orient the tool axis");
  EXPECT_EQ(error("[kinematics]\ntype = \"head-table\"\n" + joint("A", "table", "[1, 0, 0]", "[0, 0, 0]") +
                  joint("C", "table", "[0, 0, 1]", "[0, 0, 0]") + ac),
            "k.toml:2:1: error: [kinematics]: type \"head-table\" needs one head and one table joint, got two table "
            "joints");
  // Reading back what the file says.
  Machine m = forkHead();
  EXPECT_EQ(m.kinematics, "head-head");
  ASSERT_EQ(m.chain.joints.size(), 2u);
  EXPECT_EQ(m.chain.joints[0].axis, 5);
  EXPECT_TRUE(m.chain.joints[1].onHead);
  EXPECT_EQ(m.chain.joints[1].center, (std::array<double, 3>{0, 0, 180}));
  EXPECT_EQ(m.chain.tiltJoint(), 1);
  EXPECT_EQ(trunnion().chain.tiltJoint(), 0);
}
