// Rotary kinematics of a machine (its `[kinematics]` chain, docs/MACHINE.md "Kinematics"):
// forward (axis positions -> tool tip and tool axis in the workpiece frame) and inverse (tip
// and tool axis -> axis positions, both solutions of the two-joint problem) transforms, for the
// later TCP modes (Sinumerik TRAORI, Heidenhain M128/TCPM) and the CLData front end. The
// executor does not use it yet (docs/PIPELINE.md "Kinematics").
//
// Frames: machine coordinates X Y Z are the spindle gauge point relative to the table with every
// joint at zero; the workpiece frame turns with the table joints and equals the machine frame
// when they are zero. The tool axis points from the tip into the spindle; the tip lies
// `toolLength` from the gauge point along it.
#pragma once
#include "runtime/Frame.h"
#include "runtime/Geometry.h"
#include "runtime/Machine.h"

#include <string>
#include <vector>

namespace ncc {

struct ToolPose {
  Vec3 tip{};          // tool tip, workpiece frame, mm
  Vec3 axis{0, 0, 1};  // unit tool axis (tip -> spindle), workpiece frame
};

// One set of axis positions reaching a pose; `problem` says why it cannot be used (empty: it can).
struct JointSolution {
  AxisVec joints{};
  std::string problem;  // e.g. "A = 40 is beyond max 30"
};

struct InverseResult {
  std::vector<JointSolution> solutions;  // one or two, tilt joint's positive solution first
  int chosen = -1;                       // index into solutions; -1 with `error` set
  bool singular = false;                 // the tool axis lies along the free joint (kept)
  std::string error;
  bool ok() const { return chosen >= 0; }
  const AxisVec &joints() const { return solutions[chosen].joints; }
};

class Kinematics {
public:
  // Keeps a copy of the machine's chain and travel. `xyz` machines have no joints: the tool axis
  // is fixed (0, 0, 1).
  explicit Kinematics(const Machine &m);

  ToolPose forward(const AxisVec &joints, double toolLength = 0) const;
  // For fixed rotary joints: the rigid map from a tool tip in the workpiece frame to the gauge
  // point in machine X Y Z (forward's X Y Z -> tip, inverted; the tilted working plane,
  // runtime/ExecutorPlane.cpp). Its linear part is the identity unless a table joint is turned.
  Affine tipToMachine(const AxisVec &joints, double toolLength = 0) const;
  // The head's axes seen from the workpiece at these joints (columns: the machine X Y Z carried
  // by the head joints, then back through the table joints): PLANE AXIAL's working plane.
  Affine orientation(const AxisVec &joints) const;
  // `current`: the axis positions now; the solution nearest them (or of the preferred tilt sign)
  // is chosen, the free joint keeps its value at a singular pose, and axes outside the chain
  // keep theirs. `target.axis` need not be unit length, but must not be zero.
  InverseResult inverse(const ToolPose &target, const AxisVec &current, double toolLength = 0) const;

private:
  Vec3 carryHead(const AxisVec &joints, Vec3 v, bool point) const;
  Vec3 carryTable(const AxisVec &joints, Vec3 v, bool point, bool inverse) const;
  // Sets the joint values of `s` and checks them and the linear axes against the travel.
  void place(JointSolution &s, const double raw[2], const AxisVec &current, const ToolPose &target,
             double toolLength) const;

  std::string type_;
  KinematicChain chain_;
  std::array<AxisLimits, kAxes> axes_;
};

}  // namespace ncc
