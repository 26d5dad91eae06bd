// The dialect-neutral modal groups and their values. Front ends map their codes onto these
// (ISO G1 -> motion=linear, Sinumerik G1 -> the same); the executor gives them meaning.
#pragma once
#include <cstdint>
#include <string_view>

namespace ncc {

enum class ModeGroup : uint8_t {
  Motion, Plane, Units, Distance, ArcDistance, FeedMode, Retract, PathMode, Count
};

// Values are unique across groups so a value alone identifies its group.
enum class ModeValue : uint8_t {
  // Motion
  Rapid, Linear, ArcCW, ArcCCW, CycleOff,
  Drill, DrillDwell, Peck, PeckChipBreak, Tap, TapLeft, BoreFeed, BoreStop, BoreDwell,
  BoreBack, BoreFine,
  // LinuxCNC splines: G5 cubic and G5.1 quadratic (one block each; the motion mode before them
  // stays), G5.2 NURBS control points, G5.3 NURBS end (runtime/ExecutorMotion.cpp)
  SplineCubic, SplineQuadratic, Nurbs, NurbsEnd,
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
inline bool isCycleMotion(ModeValue v) { return v >= ModeValue::Drill && v <= ModeValue::BoreFine; }
inline bool isSplineMotion(ModeValue v) { return v >= ModeValue::SplineCubic && v <= ModeValue::NurbsEnd; }

}  // namespace ncc
