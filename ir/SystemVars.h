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
  SelectedPocket, RemapLevel, Task, G92On, CoordSystemNumber, ToolDiameter, ToolLengthH, CutterD, Count
};

// Indexed families after the named variables (ids from SysVar::Count on): work offsets of
// systems 1..9 (X Y Z A B C and the XY rotation R), the G92 offsets, reference points 1 and 2,
// the machine position and the tool offsets (X Y Z A B C). Offsets and reference points are in
// machine units (mm); positions in program units.
enum class SysFamily : uint8_t { None, WorkOffset, G92, Home1, Home2, MachinePos, ToolOffset };
struct SysVarInfo {
  SysFamily family = SysFamily::None;
  int system = 0;  // WorkOffset: 1..9
  int axis = 0;    // 0..5 X..C, 6 = R (WorkOffset)
};
SysVarInfo sysVarInfo(SysVar v);
// Numbered parameters that are plain storage, not controller state: LinuxCNC #0-#5000 and
// #5599-#5601; Fanuc Macro B #0-#33 and #100-#999. The ISO front end (constant #n) and the
// NGC_PARAMETER / MACRO_VARIABLE builtins (computed #[n]) ask these.
inline bool plainNgcParameter(double n) { return (n >= 0 && n < 5001) || (n >= 5599 && n < 5602); }
inline bool plainMacroVariable(double n) { return (n >= 0 && n < 34) || (n >= 100 && n < 1000); }
// The id of a family member; SysVar::Count when out of range.
SysVar sysVarOf(SysFamily f, int system, int axis);
constexpr int kSysVarIds = (int)SysVar::Count + 9 * 7 + 5 * 6;

// The IR name of a system variable (LinuxCNC's parameter name, e.g. "_metric"); false when
// `name` is none. Names are lower case.
bool sysVarFromName(std::string_view name, SysVar &out);
const char *sysVarName(SysVar v);

}  // namespace ncc
