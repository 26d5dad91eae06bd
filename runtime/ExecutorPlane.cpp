// The tilted working plane (Heidenhain cycle 19 and PLANE; docs/HEIDENHAIN.md "Tilted working
// plane"): `frame slot=tilt` (ir/FrameTilt.h) sets the programmable frame's outermost slot, a
// rotation R about the datum active at the definition, whose columns are the tilted X Y Z in the
// untilted workpiece system. Program points, arcs and the machining cycles then work in the
// tilted X Y Z and reach the machine through R.
//
// On a machine with a rotary chain ([kinematics], runtime/Kinematics.h) the last step of the
// frame chain becomes the chain itself while the tilt is on: the tool tip in the workpiece frame
// goes to machine X Y Z through the joints of the position (tool length along the actual tool
// axis, a turned table carrying the workpiece), which is what the TNC's tilting function does.
// TURN positions the rotary axes by Kinematics::inverse (the tool axis R·Z); STAY only tilts the
// coordinates, and Q120-Q122 (_plane_a.._plane_c) give the positions the program moves to itself.
// On a machine without a chain the tilt is the coordinate rotation alone, the tool along Z.
#include "runtime/ExecutorImpl.h"
#include "ir/FrameTilt.h"
#include "ir/Mat3.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

namespace {

using M3 = double[3][3];

Vec3 unit(const Vec3 &v) {
  double n = std::sqrt(dot(v, v));
  return {v[0] / n, v[1] / n, v[2] / n};
}
double length(const Vec3 &v) { return std::sqrt(dot(v, v)); }

// R from its columns (the tilted X Y Z).
void fromColumns(const Vec3 &x, const Vec3 &y, const Vec3 &z, M3 r) {
  for (int i = 0; i < 3; ++i) r[i][0] = x[i], r[i][1] = y[i], r[i][2] = z[i];
}

void mul(const M3 a, const M3 b, M3 out) {
  double t[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = t[i][j];
}

// The right-handed turn by `deg` about the machine axis `axis` (0 X, 1 Y, 2 Z).
void axisTurn(int axis, double deg, M3 r) {
  Vec3 u{};
  u[axis] = 1;
  Affine a = Affine::rotation(u, deg, {0, 0, 0});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a.m[i][j];
}

// R = turn(a0, d0) · turn(a1, d1) · turn(a2, d2).
void turns(int a0, double d0, int a1, double d1, int a2, double d2, M3 r) {
  double t0[3][3], t1[3][3], t2[3][3];
  axisTurn(a0, d0, t0), axisTurn(a1, d1, t1), axisTurn(a2, d2, t2);
  mul(t0, t1, r);
  mul(r, t2, r);
}

// The plane of directions x (its X) and a second direction in it (`inPlane`, on the +Y side):
// Z = x × inPlane; false when they are parallel.
bool frameOf(const Vec3 &x, const Vec3 &inPlane, M3 r) {
  Vec3 z = cross(x, inPlane);
  if (length(x) < 1e-12 || length(z) < 1e-9 * length(x) * length(inPlane)) return false;
  Vec3 ux = unit(x), uz = unit(z);
  fromColumns(ux, cross(uz, ux), uz, r);
  return true;
}

bool identity(const M3 r) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(r[i][j] - (i == j ? 1.0 : 0.0)) > 1e-12) return false;
  return true;
}

const char *const kFormName[] = {"", "SPATIAL", "PROJECTED", "EULER", "VECTOR", "POINTS", "RELATIV", "AXIAL"};

}  // namespace

AxisVec Executor::Impl::tiltOut(AxisVec m) const {
  for (int i = 0; i < kAxes; ++i) m[i] += chainOffset[i];
  Vec3 tip = kinematics->tipToMachine(m, toolLength).apply({m[0], m[1], m[2]});
  for (int i = 0; i < 3; ++i) m[i] = tip[i];
  return m;
}

AxisVec Executor::Impl::tiltIn(const AxisVec &machinePos) const {
  AxisVec f = machinePos;
  Vec3 tip = kinematics->tipToMachine(machinePos, toolLength).inverse().apply({f[0], f[1], f[2]});
  for (int i = 0; i < 3; ++i) f[i] = tip[i];
  for (int i = 0; i < kAxes; ++i) f[i] -= chainOffset[i];
  return f;
}

Affine Executor::Impl::outLinear() const {
  if (!tiltMapped()) return pf.composite;
  Affine table = kinematics->tipToMachine(st.position, toolLength);
  table.t = {};
  Affine l = pf.composite;
  l.t = {};
  l = l.then(table);
  // Directions only (an arc's plane and normal): the table's turn leaves rounding of 1e-16 where
  // a machine axis is meant, which would make a plane arc a tilted one.
  for (auto &row : l.m)
    for (double &v : row)
      for (double exact : {-1.0, 0.0, 1.0})
        if (std::fabs(v - exact) < 1e-12) v = exact;
  return l;
}

bool Executor::Impl::tiltedNormal(Vec3 &n, const MachineCmd *arc) {
  n = unit(outLinear().applyLinear(planeNormal(plane())));
  if (!tiltMapped()) return true;
  for (auto &j : machine.chain.joints)  // the chain's map changes along the arc: no arc then
    if (arc && arc->has((Word)j.axis))
      return error(fmt::format("an arc that turns the rotary axis {} in the tilted working plane: the tip would not "
                               "follow a circle",
                               kWordKeys[j.axis]),
                   "unsupported-code");
  return true;
}

bool Executor::Impl::planeJoint(int i, double &out, std::string &err) const {
  if (!planeJointsProblem.empty()) {
    err = fmt::format("Q{} (the {} position of the tilted working plane) is not known: {}", 120 + i, "ABC"[i],
                      planeJointsProblem);
    return false;
  }
  out = planeJoints[3 + i];
  return true;
}

bool Executor::Impl::execTilt(const MachineCmd &c) {
  const bool set = (c.sub2 & 0x0f) == (uint8_t)FrameAction::Set;
  const TiltForm form = tiltForm(c.sub2);
  const TiltMove how = tiltMove(c.sub2);
  const char *what = set ? kFormName[(int)form] : "RESET";
  auto get = [&](Word w) { return c.get(w); };
  auto len = [&](Word w) { return c.get(w) * scale(); };
  // The TNC's order (L13192-L13204): datum shift, tilt, rotation; reset the other way round. ncc
  // keeps the mirror, rotation and axis scaling inside the tilt, so they must not be active when
  // it changes, nor a shift made in the tilted system (the pivot would change its meaning).
  if (comp.active())  // the compensation works on the machine path: its plane would tilt under it
    return error(fmt::format("PLANE {} / cycle 19 with radius compensation (RL/RR) on: program R0 before", what),
                 "cutcomp-conflict");
  const bool involved = pf.tiltOn || set;
  if (involved && (pf.mirrorOn() || pf.rotationLevels || pf.copyOn ||
      (pf.scaleOn && !(pf.scaleFactors[0] == pf.scaleFactors[1] && pf.scaleFactors[1] == pf.scaleFactors[2]))))
    return error(fmt::format("PLANE {} / cycle 19 while a mirror (8), rotation (10) or axis-specific scaling (26) is "
                             "active: the TNC's order is datum shift, tilt, then rotation, reset in reverse (L13192)",
                             what),
                 "frame-conflict");
  if (pf.tiltOn && (pf.local[0] != pf.tiltPivot[0] || pf.local[1] != pf.tiltPivot[1] || pf.local[2] != pf.tiltPivot[2]))
    return error(fmt::format("PLANE {} / cycle 19 while a datum shift (7) made in the tilted system is active: reset it "
                             "first (the reverse order of L13192)",
                             what),
                 "frame-conflict");
  const bool chain = !machine.chain.joints.empty();
  if (chain && !kinematics) kinematics.emplace(machine);
  double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (set) switch (form) {
    case TiltForm::Spatial: turns(2, get(Word::C), 1, get(Word::B), 0, get(Word::A), r); break;  // A, then B, then C (L13007)
    case TiltForm::Euler: turns(2, get(Word::A), 0, get(Word::B), 2, get(Word::C), r); break;
    case TiltForm::Projected: {  // the plane's traces in ZX (PROPR) and YZ (PROMIN), then ROT about its Z
      double sa, ca, sb, cb;
      sinCosDegrees(get(Word::A), sa, ca);
      sinCosDegrees(get(Word::B), sb, cb);
      if (!frameOf({ca, 0, -sa}, {0, cb, sb}, r))
        return error("PLANE PROJECTED: the projection angles give no plane", "frame-invalid");
      double rot[3][3];
      axisTurn(2, get(Word::C), rot);
      mul(r, rot, r);
      break;
    }
    case TiltForm::Vector: {  // base vector BX BY BZ (the tilted X, made normal to N), normal NX NY NZ
      Vec3 b{get(Word::I), get(Word::J), get(Word::K)}, n{get(Word::X), get(Word::Y), get(Word::Z)};
      if (length(n) < 1e-12 || length(b) < 1e-12)
        return error("PLANE VECTOR: the base vector and the normal vector must not be zero", "frame-invalid");
      if (!frameOf(b, cross(n, b), r))
        return error("PLANE VECTOR: the base vector lies along the normal vector", "frame-invalid");
      break;
    }
    case TiltForm::Points: {  // P1 -> P2 the tilted X, P3 on its +Y side
      Vec3 p1{len(Word::X), len(Word::Y), len(Word::Z)}, p2{len(Word::I), len(Word::J), len(Word::K)},
          p3{len(Word::U), len(Word::V), len(Word::W)};
      Vec3 x{p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]}, y{p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
      if (!frameOf(x, y, r)) return error("PLANE POINTS: the three points lie on a line (or two coincide)", "frame-invalid");
      break;
    }
    case TiltForm::Relative: {  // about the active plane's own axis
      int axis = c.has(Word::A) ? 0 : c.has(Word::B) ? 1 : 2;
      double inc[3][3];
      axisTurn(axis, get((Word)(3 + axis)), inc);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = pf.tiltMatrix[i][j];
      mul(r, inc, r);
      break;
    }
    case TiltForm::Axial: {  // the orientation the chain takes at these rotary positions
      if (!chain)
        return error(fmt::format("PLANE AXIAL needs the machine's rotary kinematics ([kinematics]); machine '{}' has none",
                                 machine.name),
                     "machine-kinematics");
      AxisVec q = st.position;
      for (int i = 3; i < 6; ++i)
        if (c.has((Word)i)) q[i] = get((Word)i);
      Affine o = kinematics->orientation(q);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = o.m[i][j];
      break;
    }
    default: return error("frame slot=tilt action=set needs tilt=<form>", "bad-command");
    }
  // Cycle 19 (and PLANE … with all angles 0 written as RESET) cancels with the identity.
  const bool on = set && !identity(r);
  // The rotary positions of the plane: Q120-Q122, and TURN's target.
  planeJoints = st.position;
  planeJointsProblem.clear();
  Vec3 toolAxis{r[0][2], r[1][2], r[2][2]};
  if (!chain) {
    for (int i = 3; i < 6; ++i) planeJoints[i] = 0;
    if (on) planeJointsProblem = fmt::format("machine '{}' has no rotary kinematics ([kinematics])", machine.name);
  } else if (form == TiltForm::Axial) {
    for (int i = 3; i < 6; ++i)
      if (c.has((Word)i)) planeJoints[i] = get((Word)i);
  } else {
    // Only the rotary axes matter here (the tip is no position): among the solutions whose rotary
    // values are in their travel, SEQ+ / SEQ- take the sign of the tilt joint, else the
    // machine's `prefer` does (the TNC: the shorter way from the current position, L13004).
    InverseResult inv = kinematics->inverse({Vec3{}, toolAxis}, st.position, 0);
    const auto &joints = machine.chain.joints;
    const int tilt = joints[machine.chain.tiltJoint()].axis;
    const std::string &prefer = machine.chain.prefer;
    int pick = -1;
    double best = 0;
    for (size_t k = 0; k < inv.solutions.size(); ++k) {
      const AxisVec &q = inv.solutions[k].joints;
      bool ok = true;
      double distance = 0;
      for (auto &j : joints) {
        ok &= q[j.axis] >= machine.axes[j.axis].minPos - 1e-9 && q[j.axis] <= machine.axes[j.axis].maxPos + 1e-9;
        distance += std::fabs(q[j.axis] - st.position[j.axis]);
      }
      double sign = std::remainder(q[tilt], 360.0);
      double want = c.has(Word::Q) ? get(Word::Q) : prefer == "positive" ? 1 : prefer == "negative" ? -1 : 0;
      if (c.has(Word::Q) && (want > 0 ? sign < -1e-9 : sign > 1e-9)) ok = false;
      double score = distance + (want != 0 && sign * want < -1e-9 ? 1e6 : 0);
      if (ok && (pick < 0 || score < best)) pick = (int)k, best = score;
    }
    if (pick < 0)
      return error(fmt::format("PLANE {} / cycle 19: the machine cannot reach this orientation{}: {}", what,
                               c.has(Word::Q) ? (get(Word::Q) > 0 ? " with SEQ+" : " with SEQ-") : "",
                               inv.solutions.empty() ? inv.error : "no solution with its rotary axes within their travel"),
                   "machine-kinematics");
    planeJoints = inv.solutions[pick].joints;
    for (int i = 0; i < 3; ++i) planeJoints[i] = st.position[i];
    for (double &v : planeJoints) v = std::fabs(v) < 1e-9 ? 0.0 : v;  // no -0 from the solver
  }
  if (c.has(Word::E) && get(Word::E) != 0)
    return error("PLANE … TABLE ROT is not simulated yet (ncc turns the coordinates: COORD ROT)", "unsupported-code");
  if (how != TiltMove::Stay && !chain)
    return error(fmt::format("PLANE {} {}: machine '{}' has no rotary kinematics ([kinematics]) to position", what,
                             how == TiltMove::Turn ? "TURN" : "MOVE", machine.name),
                 "machine-kinematics");
  // Positioning first (with the old plane), then the new plane: the retract MB runs along the
  // tool axis as it is, the rotary move keeps the machine's linear axes (TURN).
  if (how != TiltMove::Stay) {
    const double L = toolLength;
    Affine a = kinematics->tipToMachine(st.position, L);
    ToolPose now = kinematics->forward(st.position, L);
    if (c.has(Word::H) || c.has(Word::P)) {  // MB: along the tool axis, away from the workpiece
      Vec3 d = unit(a.applyLinear(now.axis));
      double mb = c.has(Word::P) ? 1e300 : len(Word::H), room = 1e300;
      for (int i = 0; i < 3; ++i) {
        const AxisLimits &lim = machine.axes[i];
        if (std::fabs(d[i]) < 1e-12) continue;
        double t = d[i] > 0 ? (lim.maxPos - st.position[i]) / d[i] : (lim.minPos - st.position[i]) / d[i];
        room = std::min(room, t);
      }
      if (c.has(Word::P) && room > 1e8)
        return error("MBMAX: the machine's axes have no travel limits to retract to", "machine-kinematics");
      if (mb > room + 1e-9)
        return error(fmt::format("MB{}: the retract leaves the travel (room {:.4f} mm)", mb / scale(), room), "machine-kinematics");
      if (mb > 0) {
        AxisVec to = st.position;
        for (int i = 0; i < 3; ++i) to[i] += std::min(mb, room) * d[i];
        if (!moveTo(RecordKind::Rapid, to, true)) return false;
      }
    }
    AxisVec to = st.position;
    for (auto &j : machine.chain.joints) to[j.axis] = planeJoints[j.axis];
    if (how == TiltMove::Move) {
      // MOVE keeps the point DIST above the tip fixed on the workpiece: the linear axes follow the
      // rotation on a curve, not a straight line of the axes. Only when they need not move at all
      // is that exactly the rotary move.
      now = kinematics->forward(st.position, L);
      double dist = c.has(Word::R) ? len(Word::R) : 0;
      ToolPose after = kinematics->forward(to, L);
      Vec3 pivot{}, tip{};
      for (int i = 0; i < 3; ++i) pivot[i] = now.tip[i] + dist * now.axis[i];
      for (int i = 0; i < 3; ++i) tip[i] = pivot[i] - dist * after.axis[i];
      Vec3 m = kinematics->tipToMachine(to, L).apply(tip);
      for (int i = 0; i < 3; ++i)
        if (std::fabs(m[i] - st.position[i]) > 1e-9)
          return error(fmt::format("PLANE {} MOVE (and cycle 19 with F/ABST): the linear axes would follow the rotation on "
                                   "a curve ({} {:.4f} -> {:.4f}), which ncc does not trace; use TURN or STAY",
                                   what, kWordKeys[i], st.position[i], m[i]),
                       "unsupported-code");
    }
    bool rapid = !c.has(Word::F);
    auto rate = [&](double f) {  // the positioning feed is the block's own: the modal one comes back
      MotionRecord fr = record(RecordKind::FeedRate);
      fr.value = f;
      emit(fr);
    };
    if (to != st.position) {
      if (!rapid) rate(len(Word::F));
      if (!moveTo(rapid ? RecordKind::Rapid : RecordKind::Linear, to, true, rapid ? 0 : len(Word::F))) return false;
      if (!rapid) rate(feedMM);
    }
  }
  if (!on) {
    pf.clearTilt();
  } else {
    pf.tiltOn = true;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) pf.tiltMatrix[i][j] = r[i][j];
    pf.tiltPivot = {pf.local[0], pf.local[1], pf.local[2]};
    Affine t;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) t.m[i][j] = r[i][j];
    Vec3 rp = t.applyLinear(pf.tiltPivot);
    for (int i = 0; i < 3; ++i) t.t[i] = pf.tiltPivot[i] - rp[i];
    pf.tilt = t;
  }
  pf.update();
  noteFrame(on ? "tilt" : "tilt reset");
  return true;
}

}  // namespace ncc
