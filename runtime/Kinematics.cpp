// Forward and inverse transforms of a two-joint rotary chain (runtime/Kinematics.h). Joints
// compose as a product of exponentials: each joint turns about its axis as given with every
// joint at zero, the outer joint of a side first. The orientation problem of every chain type
// is the same one, Rot(a, φa) p = Rot(b, φb) q (Paden-Kahan subproblem 2), with a the tilt
// joint and p the tool axis at zero, b the other joint and q the requested tool axis.
#include "runtime/Kinematics.h"

#include "runtime/Frame.h"

#include <cmath>
#include <cstdio>

namespace ncc {

namespace {

constexpr const char *kAxisNames = "XYZABC";
constexpr double kPi = 3.14159265358979323846;
// Below this |u x v| two unit vectors count as parallel (a joint along the tool axis: singular).
constexpr double kParallel = 1e-9;
// Tolerance of the reachability test (squared sine, ~1e-6 rad) and of joint limits (degrees).
constexpr double kReach = 1e-12, kLimitSlack = 1e-9;

Vec3 scaled(const Vec3 &v, double k) { return {v[0] * k, v[1] * k, v[2] * k}; }
Vec3 minus(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double length(const Vec3 &v) { return std::sqrt(dot(v, v)); }
double degrees(double rad) { return rad * 180 / kPi; }
double angleBetween(const Vec3 &u, const Vec3 &v) { return degrees(std::acos(std::fmax(-1, std::fmin(1, dot(u, v))))); }

// (-180, 180]
double wrap(double deg) {
  double r = std::remainder(deg, 360.0);
  return r == -180 ? 180 : r;
}

// Up to 4 decimals, trailing zeros dropped, no "-0".
std::string text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string vecText(const Vec3 &v) { return "(" + text(v[0]) + ", " + text(v[1]) + ", " + text(v[2]) + ")"; }

// The angle (radians, right-handed about unit k) that turns u into v, both seen along k.
double angleAbout(const Vec3 &k, const Vec3 &u, const Vec3 &v) {
  Vec3 up = minus(u, scaled(k, dot(k, u))), vp = minus(v, scaled(k, dot(k, v)));
  return std::atan2(dot(k, cross(up, vp)), dot(up, vp));
}

Vec3 turn(const RotaryJoint &j, double deg, const Vec3 &v, bool point) {
  Affine r = Affine::rotation(j.direction, deg, j.center);
  return point ? r.apply(v) : r.applyLinear(v);
}

// raw + 360 k inside the axis's travel, the k nearest `current`; false (out = the nearest to
// `current` of all) when no k fits.
bool placeAngle(double raw, double current, const AxisLimits &a, double &out) {
  double k = std::round((current - raw) / 360);
  double kMin = std::ceil((a.minPos - kLimitSlack - raw) / 360), kMax = std::floor((a.maxPos + kLimitSlack - raw) / 360);
  out = raw + 360 * k;
  if (kMin > kMax) return false;
  out = raw + 360 * std::fmin(std::fmax(k, kMin), kMax);
  return true;
}

std::string axisName(int i) { return std::string(1, kAxisNames[i]); }

}  // namespace

Kinematics::Kinematics(const Machine &m) : type_(m.kinematics), chain_(m.chain), axes_(m.axes) {}

Vec3 Kinematics::carryHead(const AxisVec &q, Vec3 v, bool point) const {
  for (auto j = chain_.joints.rbegin(); j != chain_.joints.rend(); ++j)
    if (j->onHead) v = turn(*j, q[j->axis], v, point);
  return v;
}

// Workpiece frame -> machine frame (outer joint first), or back (inverse: base joint first).
Vec3 Kinematics::carryTable(const AxisVec &q, Vec3 v, bool point, bool inverse) const {
  int n = (int)chain_.joints.size();
  for (int k = 0; k < n; ++k) {
    const RotaryJoint &j = chain_.joints[inverse ? k : n - 1 - k];
    if (!j.onHead) v = turn(j, inverse ? -q[j.axis] : q[j.axis], v, point);
  }
  return v;
}

ToolPose Kinematics::forward(const AxisVec &q, double toolLength) const {
  const Vec3 &t0 = chain_.toolAxis;
  Vec3 tip = carryHead(q, scaled(t0, -toolLength), true);
  for (int i = 0; i < 3; ++i) tip[i] += q[i];
  return {carryTable(q, tip, true, true), carryTable(q, carryHead(q, t0, false), false, true)};
}

Affine Kinematics::tipToMachine(const AxisVec &q, double toolLength) const {
  Affine a;
  Vec3 offset = carryHead(q, scaled(chain_.toolAxis, -toolLength), true);
  Vec3 o = carryTable(q, {0, 0, 0}, true, false);
  for (int j = 0; j < 3; ++j) {
    Vec3 e{};
    e[j] = 1;
    Vec3 col = carryTable(q, e, false, false);
    for (int i = 0; i < 3; ++i) a.m[i][j] = col[i];
  }
  for (int i = 0; i < 3; ++i) a.t[i] = o[i] - offset[i];
  return a;
}

Affine Kinematics::orientation(const AxisVec &q) const {
  Affine a;
  for (int j = 0; j < 3; ++j) {
    Vec3 e{};
    e[j] = 1;
    Vec3 col = carryTable(q, carryHead(q, e, false), false, true);
    for (int i = 0; i < 3; ++i) a.m[i][j] = col[i];
  }
  return a;
}

void Kinematics::place(JointSolution &s, const double raw[2], const AxisVec &current, const ToolPose &target,
                       double toolLength) const {
  s.joints = current;
  auto problem = [&](const std::string &p) { s.problem += (s.problem.empty() ? "" : "; ") + p; };
  auto travel = [&](int i) { return " is outside its travel " + text(axes_[i].minPos) + ".." + text(axes_[i].maxPos); };
  for (size_t k = 0; k < chain_.joints.size(); ++k) {
    int i = chain_.joints[k].axis;
    if (!placeAngle(raw[k], current[i], axes_[i], s.joints[i])) problem(axisName(i) + " = " + text(s.joints[i]) + travel(i));
  }
  // The gauge point: the tip carried into the machine frame, less the head's offset of the tip.
  Vec3 tip = carryTable(s.joints, target.tip, true, false);
  Vec3 offset = carryHead(s.joints, scaled(chain_.toolAxis, -toolLength), true);
  for (int i = 0; i < 3; ++i) {
    double v = tip[i] - offset[i];
    s.joints[i] = std::fabs(v) < 1e-12 ? 0 : v;
    const AxisLimits &a = axes_[i];
    if (!a.present && std::fabs(v) > 1e-9) problem("it needs " + axisName(i) + " = " + text(v) + ", the machine has no " + axisName(i) + " axis");
    else if (a.present && (v < a.minPos - 1e-9 || v > a.maxPos + 1e-9)) problem(axisName(i) + " = " + text(v) + travel(i));
  }
}

InverseResult Kinematics::inverse(const ToolPose &target, const AxisVec &current, double toolLength) const {
  InverseResult r;
  double len = length(target.axis);
  if (!(len > 0) || !std::isfinite(len)) {
    r.error = "tool axis " + vecText(target.axis) + " has no direction";
    return r;
  }
  ToolPose goal{target.tip, scaled(target.axis, 1 / len)};
  const Vec3 &t0 = chain_.toolAxis;
  std::vector<std::array<double, 2>> raws;  // joint values in chain order, degrees
  if (chain_.joints.size() != 2) {          // xyz: the tool axis is fixed
    if (length(cross(goal.axis, t0)) > kParallel || dot(goal.axis, t0) < 0) {
      r.error = "tool axis " + vecText(goal.axis) + " cannot be reached: kinematics \"" + type_ +
                "\" keeps the tool axis at " + vecText(t0);
      return r;
    }
    raws.push_back({0, 0});
  } else {
    // q = Rt^T Rh t0 (Rt, Rh: the table and head rotations, base joint first), rewritten as
    // Rot(a, φa) t0 = Rot(b, φb) q: table-table R1^T t0 = R2 q, head-table Rh t0 = Rt q,
    // head-head R2 t0 = R1^T q. So a table joint on the tool side (a) and a head joint on the
    // workpiece side (b) enter with their angle negated.
    int ia = chain_.tiltJoint(), ib = 1 - ia;
    const RotaryJoint &ja = chain_.joints[ia], &jb = chain_.joints[ib];
    const Vec3 &a = ja.direction, &b = jb.direction, &p = t0, &q = goal.axis;
    double sa = ja.onHead ? 1 : -1, sb = jb.onHead ? -1 : 1;
    double ab = dot(a, b), den = 1 - ab * ab, ap = dot(a, p), bq = dot(b, q);
    double alpha = (ap - ab * bq) / den, beta = (bq - ab * ap) / den;
    double g2 = (1 - alpha * alpha - beta * beta - 2 * alpha * beta * ab) / den;
    if (g2 < -kReach) {
      // The tilt cone (half angle ∠(a, t0) about a) holds the axes whose angle to b runs
      // from |∠(a, b) - ∠(a, t0)| to ∠(a, b) + ∠(a, t0), folded at 180.
      double ang = angleBetween(a, b), tilt = angleBetween(a, p), far = ang + tilt;
      r.error = "tool axis " + vecText(goal.axis) + " is out of reach: it makes " + text(angleBetween(b, q)) +
                " degrees with the axis of " + axisName(jb.axis) + ", the chain reaches " + text(std::fabs(ang - tilt)) +
                ".." + text(far <= 180 ? far : 360 - far);
      return r;
    }
    r.singular = length(cross(b, q)) < kParallel;
    double g = r.singular ? 0 : std::sqrt(std::fmax(0, g2));  // singular: one solution
    Vec3 w = cross(a, b);
    for (double sign : {1.0, -1.0}) {
      if (sign < 0 && g == 0) break;
      Vec3 z{};
      for (int i = 0; i < 3; ++i) z[i] = alpha * a[i] + beta * b[i] + sign * g * w[i];
      std::array<double, 2> raw{};
      raw[ia] = wrap(sa * degrees(angleAbout(a, p, z)));
      // Singular: any value of b gives this axis; the joint stays where it is.
      raw[ib] = r.singular ? wrap(current[jb.axis]) : wrap(sb * degrees(angleAbout(b, q, z)));
      raws.push_back(raw);
    }
    // The positive tilt first, so the order does not depend on the sign of g.
    if (raws.size() == 2 && raws[1][ia] > raws[0][ia]) std::swap(raws[0], raws[1]);
  }
  for (auto &raw : raws) {
    JointSolution s;
    place(s, raw.data(), current, goal, toolLength);
    r.solutions.push_back(s);
  }
  // The usable solution the preference ranks first: the tilt sign (prefer = positive/negative),
  // then the rotary distance from the current position.
  int tilt = chain_.joints.empty() ? -1 : chain_.joints[chain_.tiltJoint()].axis;
  auto rank = [&](const JointSolution &s) {
    double distance = 0, signMiss = 0;
    for (auto &j : chain_.joints) distance += std::fabs(s.joints[j.axis] - current[j.axis]);
    if (tilt >= 0 && chain_.prefer != "nearest") {
      double t = wrap(s.joints[tilt]);
      signMiss = chain_.prefer == "positive" ? t < 0 : t > 0;
    }
    return std::pair{signMiss, distance};
  };
  for (size_t i = 0; i < r.solutions.size(); ++i)
    if (r.solutions[i].problem.empty() && (r.chosen < 0 || rank(r.solutions[i]) < rank(r.solutions[r.chosen])))
      r.chosen = (int)i;
  if (r.chosen < 0) {
    r.error = "no solution within the travel:";
    for (auto &s : r.solutions) {
      std::string at;
      for (auto &j : chain_.joints) at += (at.empty() ? "" : " ") + axisName(j.axis) + "=" + text(s.joints[j.axis]);
      r.error += (&s == &r.solutions[0] ? " " : "; ") + (at.empty() ? "" : at + ": ") + s.problem;
    }
  }
  return r;
}

}  // namespace ncc
