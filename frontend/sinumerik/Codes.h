// The Sinumerik tables: every G code of the 60 G groups (generated from the operator table,
// GCodeTable.inc) with what ncc does with it, the addresses, the system variables ncc provides
// and the predefined functions. Lowering reads these tables instead of chains of ifs.
#pragma once
#include "ir/ModeTable.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace ncc::sin {

// What lowering does with a G code.
enum class GAct : uint8_t {
  Unsupported,   // changes the motion in a way ncc does not model: an unsupported-code error
  Default,       // the group's initial setting, which is what ncc models: nothing to do
  Mode,          // a mode op (mode holds the value)
  Dwell,         // G4
  WorkOffset,    // G500, G54-G57, G505-G599 (arg: index)
  MachineCoord,  // G53, G153, SUPA: the block's move in machine coordinates
  CutterComp,    // G40/G41/G42 (arg: 0 off, 1 left, 2 right)
  Frame,         // TRANS ROT SCALE MIRROR and their additive forms (arg: FrameKind)
  Units,         // G70/G71/G700/G710 (arg: 0 mm, 1 inch, 2 G70 refused: its feed stays metric)
  Pole,          // G110/G111/G112 (arg: 0 last position, 1 workpiece origin, 2 last pole)
  SpindleMode,   // G96 G961 G962 G97 G971 G972 (arg: SpindleModeArg): constant cutting speed on/off
  Smoothing,     // G641 G642 G643 G645: continuous path rounded within a distance or tolerance (arg 1: ADIS)
  FloatTap,      // G63: tapping with a compensating chuck, one G1 block at the programmed F
};

// G group 15's constant-cutting-speed codes: the spindle mode and the feed type they set.
struct SpindleModeArg {
  bool css;           // G96 G961 G962: S is the cutting speed (m/min)
  ModeValue feed;     // the feed type they set (Count: unchanged, G962 G972)
};
const SpindleModeArg &spindleModeArg(int arg);

enum class FrameKind : uint8_t { Trans, Rot, Scale, Mirror, SolidRot };

struct GCode {
  const char *name;     // upper case: G1, G500, TRANS, CIP
  int group;            // G group 1..62
  int modality;         // 0 modal, 1 non-modal, 2 either
  bool isDefault;       // the group's initial setting
  const char *meaning;  // from the operator table
};

struct GInfo {
  const GCode *code = nullptr;
  GAct act = GAct::Unsupported;
  ModeValue mode = ModeValue::Count;
  int arg = 0;
  bool additive = false;  // ATRANS AROT ASCALE AMIRROR
};

// Null code when `name` (upper case) is no G code of the table.
GInfo findGCode(std::string_view name);
const GCode *gcodeTable(size_t &count);

// Addresses of a block (X10, CR=5, I1=AC(3)).
enum class Addr : uint8_t {
  Axis,     // X Y Z A B C U V W
  Center,   // I J K
  Via,      // I1 J1 K1 (CIP's intermediate point)
  Radius,   // CR
  Opening,  // AR (the opening angle of an arc, degrees)
  Turns,    // TURN (extra full turns of a helix)
  Polar,    // AP RP (polar angle and radius about the pole)
  Corner,   // CHF (chamfer length), CHR (chamfer legs), RND (rounding)
  SplinePoint,  // PW (a BSPLINE point's weight), SD (the BSPLINE's degree), PL (POLY's parameter interval)
  Feed, Speed, Tool, Edge, Misc, G,
  StartAngle,  // SF: a thread's start angle (modal)
  SpeedLimit,  // LIMS: the spindle speed limit of constant cutting speed
  Smoothing,   // ADIS ADISPOS CTOL: the rounding distance / contour tolerance of G641-G645
  Refused,  // an address ncc knows but does not simulate (AR, AP, RP, CHR, RNDM, TURN, OFFN, SF, LIMS …)
  None
};
struct AddrInfo {
  const char *name;
  Addr kind;
  const char *why = nullptr;  // Refused: what it does
};
const AddrInfo *findAddress(std::string_view name);

// A Sinumerik system variable ncc provides: the NC IR System name and how many indices it takes.
struct SysMap {
  const char *name;       // upper case without '$': P_UIFR
  const char *irName;     // NC IR name without '$': _uifr
  int indices;            // 0, 1 (axis or number) or 2
  int toolField = -1;     // $TC_DPn: the field k of $_tool_data[t, d, k]
  int fixedIndex = -1;    // $P_UBFR, $P_BFRAME: the member 0 of $_chbfr / $_chbframe
};
const SysMap *findSystemVar(std::string_view name);
// $TC_SCPxy / $TC_ECPxy: the tool data field (>= 0), -2 a parameter ncc does not keep, -1 another name.
int findToolSumVar(std::string_view name);

// A predefined function: its NC IR builtin and how its arguments are read.
struct FnMap {
  const char *name;    // Sinumerik name
  const char *irName;  // NC IR builtin
  bool axisArgs;       // CTRANS(X, 10 …): odd arguments are axis names, passed as strings
};
const FnMap *findFunction(std::string_view name);

}  // namespace ncc::sin
