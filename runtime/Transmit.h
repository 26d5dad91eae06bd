// The kinematic transformations of a mill-turn machine with a C axis on the spindle (docs/
// PIPELINE.md "Kinematic transformations"): the face-end (polar) transformation — Sinumerik
// TRANSMIT, ISO G12.1 — and the cylinder-surface transformation — Sinumerik TRACYL, ISO G07.1.
// One core for every dialect: while one is active the executor computes in a Cartesian system
// (the basic coordinate system, BCS), and TransformSink turns each record into machine axes
// X (a radius), C (degrees, continuous) and Z.
//
//   face:      BCS x, y on the face, z along the spindle   ->  X = ±hypot(x, y), C = atan2(y, x)
//   cylinder:  BCS x the radius, y the arc length on the    ->  X = x, C = y / (d/2) in degrees
//              reference diameter d, z along the spindle
//
// A straight line or an arc of the BCS is a curve in machine axes. The trace holds straight
// machine-axis moves, so a path is split into pieces whose machine-axis straight line stays
// within the machine's chordal tolerance ([transform] tolerance) of the exact path, as a
// controller's interpolator does; where the machine path is straight (a radial line on the face,
// any line on the cylinder) it is one piece.
#pragma once
#include "ir/MotionIR.h"

#include <functional>
#include <string>
#include <vector>

namespace ncc {

struct CycleDef;
class Diagnostics;

enum class TransformKind : uint8_t { None, Face, Cylinder };

struct TransformSetup {
  TransformKind kind = TransformKind::None;
  int rotary = 5;            // machine axis index of the spindle's rotary axis (C)
  double radius = 0;         // cylinder: the reference radius d/2, mm
  double tolerance = 0.001;  // chordal tolerance, mm
};

// Where the face transformation's machine X is: +r, or -r past the pole (the tool on the other
// side of the centre, C half a turn from the point's angle). A line through the pole flips it
// (the rotary axis stays, X passes zero: the manual's "movement through the pole", L15888).
struct FaceState {
  int side = 1;
};

// A BCS point as machine axes, C continuous with `prev`'s (the nearest equivalent angle). At
// the pole (face, r below kPoleEps) C keeps its value.
AxisVec transformToMachine(const TransformSetup &s, const AxisVec &bcs, const AxisVec &prev, const FaceState &fs);
// A machine position as a BCS point.
AxisVec transformToBcs(const TransformSetup &s, const AxisVec &machine);
constexpr double kPoleEps = 1e-7;  // mm: a point this close to the face's centre is at the pole

// The machine positions of a path, from its start (`startMachine`) to its end, each piece a
// straight machine-axis move within the tolerance. `curve(t)` is the BCS point at t in [0, 1];
// `deviation(p, t0, t1)` the distance of BCS point p from the exact path between t0 and t1;
// `pieces` equal parts are taken first (an arc: one per quarter turn).
// False with `err` when the path cannot be followed (an arc through the pole, a piece that does
// not converge).
using TransformCurve = std::function<AxisVec(double t)>;
using TransformDeviation = std::function<double(const AxisVec &p, double t0, double t1)>;
bool splitTransformed(const TransformSetup &s, const FaceState &fs, const AxisVec &startMachine,
                      const TransformCurve &curve, const TransformDeviation &deviation, int pieces,
                      std::vector<AxisVec> &out, std::string &err);

// The records of the transformation: every position in machine axes, each path split into
// straight machine moves. An error (a record kind it cannot follow) is reported once into the
// diagnostics and `failed` is set; the executor stops at the command.
class TransformSink final : public MotionSink {
public:
  TransformSink(MotionSink &out, Diagnostics &diags) : out_(out), diags_(diags) {}
  // Starts at machine position `machine`; returns the BCS position there.
  AxisVec begin(const TransformSetup &s, const AxisVec &machine);
  const TransformSetup &setup() const { return s_; }
  const AxisVec &machinePosition() const { return pos_; }
  bool failed = false;
  void record(const MotionRecord &r) override;

private:
  bool fail(const MotionRecord &r, std::string msg);
  void emitPieces(const MotionRecord &r, const std::vector<AxisVec> &pts);
  bool line(const MotionRecord &r);
  bool arc(const MotionRecord &r);
  MotionSink &out_;
  Diagnostics &diags_;
  TransformSetup s_;
  FaceState fs_;
  AxisVec pos_{};
};

// The library entries that select and end a transformation (`cycle entry="trf.TRANSMIT"`): the
// executor runs them itself (Executor::Impl::execTransform), their expand step is never called.
void addTransformEntries(std::vector<CycleDef> &out);
bool isTransformEntry(const CycleDef &def);

}  // namespace ncc
