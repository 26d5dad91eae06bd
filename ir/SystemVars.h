// System variables: controller state a program reads (LinuxCNC's predefined `#<_name>`
// parameters today; Sinumerik `$P_…`/`$AA_…`, Heidenhain FN 18 and 808D `$C_…` map onto the same
// ids as their front ends land). The NC IR names them as System variables (`$_metric`); the
// engines resolve the name to a SysVar once and ask their CmdSink (the executor) for the value
// when the program runs, so both engines read the same state.
#pragma once
#include <cstdint>
#include <string_view>

namespace ncc {

enum class SysVar : uint8_t {
  VersionMajor, VersionMinor, Line, MotionMode, Plane, CutterComp, Metric, Imperial, Absolute,
  Incremental, InverseTime, UnitsPerMinute, UnitsPerRev, CoordSystem, ToolOffset, RetractR,
  RetractOldZ, SpindleRpmMode, SpindleCssMode, IjkAbsolute, LatheDiameter, LatheRadius, SpindleOn,
  SpindleCw, Mist, Flood, SpeedOverride, FeedOverride, AdaptiveFeed, FeedHold, Feed, Rpm, PosX,
  PosY, PosZ, PosA, PosB, PosC, PosU, PosV, PosW, CurrentTool, CurrentPocket, SelectedTool,
  SelectedPocket, RemapLevel, Task, Count
};

// The IR name of a system variable (LinuxCNC's parameter name, e.g. "_metric"); false when
// `name` is none. Names are lower case.
bool sysVarFromName(std::string_view name, SysVar &out);
const char *sysVarName(SysVar v);

}  // namespace ncc
