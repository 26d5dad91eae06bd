// System variables: controller state a program reads (LinuxCNC's predefined `#<_name>`
// parameters today; Sinumerik `$P_…`/`$AA_…`, Heidenhain FN 18 and 808D `$C_…` map onto the same
// ids as their front ends land). The NC IR names them as System variables (`$_metric`); the
// engines resolve the name to a SysVar once and ask their CmdSink (the executor) for the value
// when the program runs, so both engines read the same state.
//
// Ids are 16 bits: the named variables, then the members of the small indexed families (work
// offsets, axes), then one id per field of the tool data. Tool data is addressed by tool and
// edge numbers too (up to 99999 each), far too many for ids: those two travel beside the id in
// a SysRef, the one form both engines hand the executor.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace ncc {

enum class SysVar : uint16_t {
  VersionMajor, VersionMinor, Line, MotionMode, Plane, CutterComp, Metric, Imperial, Absolute,
  Incremental, InverseTime, UnitsPerMinute, UnitsPerRev, CoordSystem, ToolOffset, RetractR,
  RetractOldZ, SpindleRpmMode, SpindleCssMode, IjkAbsolute, LatheDiameter, LatheRadius, SpindleOn,
  SpindleCw, Mist, Flood, SpeedOverride, FeedOverride, AdaptiveFeed, FeedHold, Feed, Rpm, PosX,
  PosY, PosZ, PosA, PosB, PosC, PosU, PosV, PosW, CurrentTool, CurrentPocket, SelectedTool,
  SelectedPocket, RemapLevel, Task, G92On, CoordSystemNumber, ToolDiameter, ToolLengthH, CutterD,
  // Sinumerik: the status of the last DELDL (0 done, -1 not or not completely).
  DeldlStatus,
  // The last probe's result (LinuxCNC #5061-#5069: where it stopped, X Y Z A B C U V W in the work
  // coordinates and units of its block; #5070: 1 when it tripped), docs/PROBING.md.
  ProbeX, ProbeY, ProbeZ, ProbeA, ProbeB, ProbeC, ProbeU, ProbeV, ProbeW, ProbeTripped,
  // Frames (FRAME values, ir/FrameValue.h): the programmable frame (Sinumerik $P_PFRAME), the
  // active settable frame ($P_IFRAME), the whole chain without the tool ($P_ACTFRAME, read-only).
  PFrame, IFrame, ActFrame,
  // Sinumerik base frames (docs/SINUMERIK.md "Frame chain"): the total base frame ($P_ACTBFRAME,
  // read-only) and the masks choosing the members that enter it ($P_CHBFRMASK, $P_NCBFRMASK);
  // the system frames of the chain, outer ones first ($P_PARTFRAME … $P_GFRAME).
  ActBFrame, ChBfrMask, NcBfrMask, PartFrame, SetFrame, ExtFrame, Iso1Frame, Iso2Frame, Iso3Frame, GFrame,
  ToolFrame, WpFrame, TraFrame, Iso4Frame, CycFrame,
  // The rotary-axis positions of the tilted working plane (Heidenhain Q120-Q122 after cycle 19 and
  // PLANE … STAY, runtime/ExecutorPlane.cpp), degrees.
  PlaneA, PlaneB, PlaneC, Count
};

// Indexed families after the named variables (ids from SysVar::Count on): work offsets of
// systems 1..9 (X Y Z A B C and the XY rotation R), the G92 offsets, reference points 1 and 2,
// the machine position and the tool offsets (X Y Z A B C), then the tool data fields. Offsets,
// reference points and tool data are in parameter units (mm); positions in program units.
enum class SysFamily : uint8_t {
  None, WorkOffset, G92, Home1, Home2, MachinePos, ToolOffset, ToolData, UserFrame,
  // Sinumerik base frames n = 0..7: the channel's stored ($P_CHBFR[n]) and active
  // ($P_CHBFRAME[n]) ones, the NCU-global stored ($P_NCBFR[n]) and active ($P_NCBFRAME[n]) ones.
  ChBfr, ChBframe, NcBfr, NcBframe,
  // Sinumerik contour tables (CONTPRON, CONTDCON, CALCDAT …, runtime/ExecutorContourTable.cpp):
  // `$_sin_table[i, j]`, row i, column j of the table the last one built (read-only; one id, the
  // indices travel in the SysRef's tool and edge as tool data's do).
  SinTable
};
struct SysVarInfo {
  SysFamily family = SysFamily::None;
  int system = 0;  // WorkOffset: 1..9
  int axis = 0;    // 0..5 X..C, 6 = R (WorkOffset); ToolData: the field (ToolField)
};
// The fields of `$_tool_data[t, d, k]` (k), what the machine's [[tools]] edges hold: geometry
// and wear of length 1 and radius, then the Sinumerik edge data (docs/SINUMERIK.md "Tool
// offsets": $TC_DP1 type, DP2 cutting edge position, DP4/5 lengths 2 and 3, DP13/14 their wear,
// DP21-23 the base dimensions), then the additive offsets $TC_SCPxy (wear) and $TC_ECPxy (setup)
// of DL set x = 1..6 for parameter y = 3..6 (lengths 1-3, radius): field kToolSumFields + (x-1)*4
// + (y-3), the setup values kToolSetupFields + the same.
enum class ToolField : uint8_t {
  Length, Radius, LengthWear, RadiusWear, Type, CutPos, Length2, Length3, Length2Wear, Length3Wear, Base1, Base2,
  Base3, Count
};
constexpr int kDlSets = 6, kDlParams = 4;  // DL 1..6; parameters DP3 DP4 DP5 DP6
constexpr int kToolSumFields = (int)ToolField::Count;
constexpr int kToolSetupFields = kToolSumFields + kDlSets * kDlParams;
constexpr int kToolFields = kToolSetupFields + kDlSets * kDlParams;
constexpr int kMaxToolNumber = 99999;  // T and D numbers of the machine file
SysVarInfo sysVarInfo(SysVar v);
// Numbered parameters (#5221, #2001) map onto these ids through ir/SystemParams.h.
// No system variable: what the lookups below return for an id out of range (family members
// start at SysVar::Count, so Count itself is the first work offset).
constexpr SysVar kNoSysVar = (SysVar)0xffff;
// The id of a family member (ToolData: axis = the field); kNoSysVar when out of range.
SysVar sysVarOf(SysFamily f, int system, int axis);
constexpr int kToolDataIds = (int)SysVar::Count + 9 * 7 + 5 * 6;  // the first tool data field
// The stored settable frames `$_uifr[n]` (Sinumerik $P_UIFR[n]): n = 0 (G500) .. 99, the work
// offset systems G54 … G57, G505 … G599 (system n's offsets and XY rotation); how many a machine
// has is its settable_frames (MD28080).
constexpr int kUserFrames = 100;
constexpr int kUserFrameIds = kToolDataIds + kToolFields;
// The base frames of the four families ChBfr … NcBframe, 8 each (MD28081 and the NCU-global
// count at most 8), system = the index.
constexpr int kBaseFrames = 8;
constexpr int kBaseFrameIds = kUserFrameIds + kUserFrames;
constexpr int kSinTableId = kBaseFrameIds + 4 * kBaseFrames;  // `$_sin_table[i, j]`
constexpr int kSinTableRows = 131072, kSinTableColumns = 32;   // the indices it takes (17 bits: SysRef)
constexpr int kSysVarIds = kSinTableId + 1;
static_assert(kSysVarIds < (int)kNoSysVar);

// What an engine reads or writes: the id and, for tool data, the tool and the edge (edge 0: the
// tool is an H/D offset number, the edge it addresses: tool n's edge 1 or only edge, or the
// machine's offset_numbers; docs/MACHINE.md).
struct SysRef {
  SysVar var = kNoSysVar;
  int32_t tool = 0, edge = 0;
};
// Compiled code carries a SysRef as one double (exact: 16 + 17 + 17 bits); runtime/ncrt.
double sysRefNumber(SysRef r);
SysRef sysRefFromNumber(double n);

// Indexed access: a family's base name with run-time indices, `$_work_offset[s, a]` (system s
// 1..9, axis a 0..5 = X..C or 6 = the XY rotation R) and `$_g92[a]`, `$_home1[a]`, `$_home2[a]`,
// `$_abs[a]`, `$_tool_offsets[a]` (a 0..5; `$_tool_offset` is LinuxCNC's "length offset on"),
// `$_tool_data[t, d, k]` (tool 1..99999, edge 0..99999 with 0 = t is an offset number, field 0..kToolFields-1).
// An index of an axis family may be an axis symbol (X … C), resolved when the program is
// compiled (axisIndex). Returns the number of indices the family takes, 0 when `name` is not a family.
int sysFamilyFromName(std::string_view name, SysFamily &out);
const char *sysFamilyName(SysFamily f);
// The member at run-time indices (i = the system for work offsets, else the axis; tool data:
// tool i, edge j, field k); var = kNoSysVar when an index is out of range or not an integer.
// The message for that case, shared by the engines.
SysRef sysVarAt(SysFamily f, double i, double j, double k);
std::string sysVarIndexMessage(std::string_view name, SysFamily f, double i, double j, double k);
// The axis index of an axis name used as an index (X Y Z A B C -> 0..5), -1 for any other name.
int axisIndex(std::string_view name);

// Writes: the ids a program may assign (work offsets with their rotation, G92 offsets, the
// reference points, tool data). The executor decides when a written work offset or tool edge
// takes effect (the controller's `offset_write` and `tool_write`, docs/MACHINE.md).
bool sysVarWritable(SysVar v);
bool sysFamilyWritable(SysFamily f);
// Variables whose values are FRAMEs (engines read and write them with CmdSink::readFrame/writeFrame).
bool sysVarIsFrame(SysVar v);
inline bool sysFamilyIsFrame(SysFamily f) {
  return f == SysFamily::UserFrame || (f >= SysFamily::ChBfr && f <= SysFamily::NcBframe);
}
// The same by IR name (`_pframe`, the family `_uifr`), for the static types of sema and the JIT.
bool sysVarNameIsFrame(std::string_view name);

// The IR name of a system variable (LinuxCNC's parameter name, e.g. "_metric"); false when
// `name` is none (tool data has no flat names: it needs a tool and an edge). Names are lower case.
bool sysVarFromName(std::string_view name, SysVar &out);
const char *sysVarName(SysVar v);
// How messages name a reference: the name, or tool data with its indices ("_tool_data[1, 2, 0]").
std::string sysRefText(const SysRef &r);

}  // namespace ncc
