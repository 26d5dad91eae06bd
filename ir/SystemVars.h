// System variables: controller state a program reads (LinuxCNC's predefined `#<_name>`
// parameters today; Sinumerik `$P_…`/`$AA_…`, Heidenhain FN 18 and 808D `$C_…` map onto the same
// ids as their front ends land). The NC IR names them as System variables (`$_metric`); the
// engines resolve the name to a SysVar once and ask their CmdSink (the executor) for the value
// when the program runs, so both engines read the same state.
#pragma once
#include <cstdint>
#include <string>
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
// No system variable: what the lookups below return for an id out of range (family members
// start at SysVar::Count, so Count itself is the first work offset).
constexpr SysVar kNoSysVar = (SysVar)0xff;
// The id of a family member; kNoSysVar when out of range.
SysVar sysVarOf(SysFamily f, int system, int axis);
constexpr int kSysVarIds = (int)SysVar::Count + 9 * 7 + 5 * 6;
static_assert(kSysVarIds < (int)kNoSysVar);

// Indexed access: a family's base name with run-time indices, `$_work_offset[s, a]` (system s
// 1..9, axis a 0..5 = X..C or 6 = the XY rotation R) and `$_g92[a]`, `$_home1[a]`, `$_home2[a]`,
// `$_abs[a]`, `$_tool_offsets[a]` (a 0..5; `$_tool_offset` is LinuxCNC's "length offset on").
// An index may be an axis symbol (X … C), resolved when the program is compiled (axisIndex).
// Returns the number of indices the family takes, 0 when `name` is not a family.
int sysFamilyFromName(std::string_view name, SysFamily &out);
// The member at run-time indices (i = the system for work offsets, else the axis); kNoSysVar
// when an index is out of range or not an integer. The message for that case, shared by the engines.
SysVar sysVarAt(SysFamily f, double i, double j);
std::string sysVarIndexMessage(std::string_view name, SysFamily f, double i, double j);
// The axis index of an axis name used as an index (X Y Z A B C -> 0..5), -1 for any other name.
int axisIndex(std::string_view name);

// Writes: the ids a program may assign (work offsets with their rotation, G92 offsets, the
// reference points). The executor decides when a written work offset takes effect (the
// controller's `offset_write`, docs/MACHINE.md).
bool sysVarWritable(SysVar v);

// The IR name of a system variable (LinuxCNC's parameter name, e.g. "_metric"); false when
// `name` is none. Names are lower case.
bool sysVarFromName(std::string_view name, SysVar &out);
const char *sysVarName(SysVar v);

}  // namespace ncc
