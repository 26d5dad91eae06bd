// The dialect-neutral modal groups and their values. Front ends map their codes onto these
// (ISO G1 -> motion=linear, Sinumerik G1 -> the same); the executor gives them meaning.
#pragma once
#include <cstdint>
#include <string_view>

namespace ncc {

enum class ModeGroup : uint8_t {
  Motion, Plane, Units, Distance, ArcDistance, FeedMode, Retract, PathMode,
  // How a Sinumerik A or C spline begins and ends (G groups 19 and 20: BNAT/BAUTO/BTAN, ENAT/EAUTO/ETAN)
  SplineStart, SplineEnd,
  // A one-block exact stop (Sinumerik G9, group 11): the moves of this block end at rest; the
  // path mode (group 10) stays.
  StopOnce,
  // The system Sinumerik wear values are given in (G group 56, SIN-TOL-09): TOWSTD and the others,
  // which coincide without an orientable toolholder or a kinematic transformation, or TOWWCS.
  WearSystem, Count
};

// Values are unique across groups so a value alone identifies its group.
enum class ModeValue : uint8_t {
  // Motion
  // ArcThrough: an arc through an intermediate point (Sinumerik CIP); ArcTangent: an arc
  // tangent to the path so far (Sinumerik and Heidenhain CT). Both are path motions (group 01).
  Rapid, Linear, ArcCW, ArcCCW, ArcThrough, ArcTangent, CycleOff,
  Drill, DrillDwell, Peck, PeckChipBreak, Tap, TapLeft, BoreFeed, BoreStop, BoreDwell,
  BoreBack, BoreFine,
  // Fanuc's G80 (cycles are group 09, beside group 01): the cycle ends and the G0-G3 mode that
  // was active before it resumes. RS274NGC's G80 is CycleOff: no motion mode until one is given.
  CycleCancel,
  // LinuxCNC splines: G5 cubic and G5.1 quadratic (one block each; the motion mode before them
  // stays), G5.2 NURBS control points, G5.3 NURBS end (runtime/ExecutorMotion.cpp)
  SplineCubic, SplineQuadratic, Nurbs, NurbsEnd,
  // Lathe single cycles (808D system A G90 along Z, G94 along X; runtime/ExecutorTurning.cpp):
  // modal, each move block runs the four-step cycle from the current point.
  TurnAlongZ, TurnAlongX,
  // Thread cutting (runtime/ExecutorThread.cpp): Thread a spindle-synchronised straight move
  // (LinuxCNC G33 K, 808D G32/G33 F Q), RigidTap LinuxCNC G33.1 (down and back), ThreadCycle
  // LinuxCNC's G76 (every parameter in one block), ThreadSingle the lathe's single thread
  // cycle (808D G92/G78, modal like G90), ThreadMulti the lathe's multiple threading cycle
  // (808D G76, one-shot: the motion mode before it stays); ThreadVariable the 808D's G34 (the lead
  // F grows by K every revolution). ThreadLead is Sinumerik G33: the lead I/J/K along X/Y/Z (the
  // thread's main axis), the start angle Q (SF=) modal; TapIn/TapOut Sinumerik G331/G332, a rigid
  // tap into the hole and back out with the spindle in position control (after SPOS).
  Thread, RigidTap, ThreadCycle, ThreadSingle, ThreadMulti, ThreadVariable, ThreadLead, TapIn, TapOut,
  // The lathe's peck cycles (808D G74 along Z, G75 along X, runtime/ExecutorGrooving.cpp):
  // one-shot like ThreadMulti, a block without the end point keeps the retract e.
  PeckAlongZ, PeckAlongX,
  // LinuxCNC straight probing (runtime/ExecutorProbe.cpp, docs/PROBING.md): G38.2 toward the
  // work, stop on contact; G38.3 the same without an error on a miss; G38.4 away from the work,
  // stop on loss of contact; G38.5 the same without an error.
  ProbeToward, ProbeTowardNoError, ProbeAway, ProbeAwayNoError,
  Skip,  // ISO G31 (808D/Fanuc skip): a one-shot probe toward the work, a miss is no error
  // Sinumerik splines (runtime/ExecutorSinSpline.cpp): ASPLINE (Akima), BSPLINE, CSPLINE (cubic);
  // modal, each move block adds a point; the curve is emitted when the spline ends.
  SplineAkima, SplineB, SplineC,
  // Sinumerik POLY: each block a polynomial (or rational) curve of degree <= 5 (ExecutorSinSpline.cpp)
  Poly,
  // Plane
  XY, ZX, YZ,
  // Units
  MM, Inch,
  // Distance / ArcDistance
  Absolute, Incremental, ArcAbsolute, ArcIncremental,
  // FeedMode
  PerMinute, PerRev, InverseTime,
  // Retract (canned cycles)
  RetractInitial, RetractR,
  // PathMode
  ExactPath, ExactStop, Continuous,
  // SplineStart / SplineEnd: zero curvature (the default), from the first/last three points, tangent
  StartNatural, StartAuto, StartTangent, EndNatural, EndAuto, EndTangent,
  // StopOnce
  ExactStopOnce,
  // WearSystem: TOWSTD TOWMCS TOWBCS TOWTCS TOWKCS / TOWWCS
  WearMachine, WearWork,
  Count
};

struct ModeValueInfo {
  ModeValue value;
  ModeGroup group;
  const char *name;  // text IR name, e.g. "linear"
};

const char *modeGroupName(ModeGroup g);
bool modeGroupFromName(std::string_view s, ModeGroup &out);
const ModeValueInfo &modeValueInfo(ModeValue v);
bool modeValueFromName(std::string_view s, ModeValue &out);
inline bool isPathMotion(ModeValue v) { return v <= ModeValue::ArcTangent; }
inline bool isCycleMotion(ModeValue v) { return v >= ModeValue::Drill && v <= ModeValue::BoreFine; }
inline bool isSplineMotion(ModeValue v) { return v >= ModeValue::SplineCubic && v <= ModeValue::NurbsEnd; }
inline bool isTurnCycleMotion(ModeValue v) { return v == ModeValue::TurnAlongZ || v == ModeValue::TurnAlongX; }
inline bool isThreadMotion(ModeValue v) { return v >= ModeValue::Thread && v <= ModeValue::TapOut; }
inline bool isPeckMotion(ModeValue v) { return v == ModeValue::PeckAlongZ || v == ModeValue::PeckAlongX; }
inline bool isSinSplineMotion(ModeValue v) { return v >= ModeValue::SplineAkima && v <= ModeValue::SplineC; }
inline bool isProbeMotion(ModeValue v) { return v >= ModeValue::ProbeToward && v <= ModeValue::Skip; }

}  // namespace ncc
