// The ISO G- and M-code tables: what each code means and which modal group it belongs to.
// Lowering is driven by these tables, not by if-chains over code numbers.
#pragma once
#include "ir/ModeTable.h"

#include <cstdint>

namespace ncc::iso {

// What lowering does with a G code.
enum class GKind : uint8_t {
  Mode,          // a mode op: group + value from the table
  Dwell,         // G4
  SetOffset,     // arg: 0 G10, 1 G92, 2 G92.1, 3 G92.2, 4 G92.3, 5 G28.1, 6 G30.1 (kSetOffsetKinds)
  Home,          // G28 (ref 1) / G30 (ref 2, or P)
  MachineCoord,  // G53
  CutterComp,    // G40 / G41 / G42 (arg: 0 off, 1 left, 2 right)
  ToolLength,    // G43 (arg 1) / G49 (arg 0); LinuxCNC G43.1 (arg 2, axis words) / G43.2 (arg 3, H or axis words)
  WorkOffset,    // G54..G59.3 (arg: index)
  MacroCall,     // G65
  ModalMacro,    // G66 (arg 0: set a modal macro call, after each move) / G67 (arg 1: cancel)
  SubCall,       // G05 P<program> L<count>: subprogram call (808D); G05 without P, P0, P01 ignored
  ContourCopy,   // 808D G72.1 (arg 1: rotational) / G72.2 (arg 2: linear) contour repetition (LowerCopy.cpp)
  Frame,         // G52 (local shift), G68/G69 (rotation), G51/G50 (scaling), G51.1/G50.1 (mirror); arg 1 on, 0 off
  TurnCycle,     // G70-G73 multiple repetitive turning cycles (arg: the A-system code)
  SpindleMode,   // G96 (arg 2: constant surface speed) / G97 (arg 1: constant rpm)
  Transform,     // 808D G12.1 (arg 1) / G13.1 (arg 0) face-end, G07.1 (arg 2) cylinder transformation (LowerTransform.cpp)
  NoOp,          // cancels a function ncc does not model and is always off (G15, G291)
  Unsupported,   // known code that is not lowered yet: error with the description
};

// Conflict groups: two codes of one group in a block are an error.
enum class GGroup : uint8_t {
  NonModal, Motion, Plane, Distance, ArcDistance, FeedMode, Units, CutterComp, ToolLength, Retract,
  WorkOffset, PathMode, Spindle, Polar, Scaling, Mirror, MacroModal, Rotation, Language, Count
};
const char *gGroupName(GGroup g);

struct GCodeInfo {
  int32_t code10;   // code times ten: G92.1 = 921
  GKind kind;
  GGroup group;
  ModeValue mode;   // for GKind::Mode
  int arg;          // kind specific (see GKind)
  const char *what; // description (used in messages)
};

// Null when the code is unknown.
const GCodeInfo *findGCode(int32_t code10);
// A lathe's code (808D turning tables, G-code system 'A' or 'B'): null when the code is not a
// turning code of that system (G43; G91 in system A …).
const GCodeInfo *findTurningGCode(int32_t code10, char system);
// The RS274NGC meaning of a code whose number means something else in findGCode's (808D) table.
const GCodeInfo *findRs274GCode(int32_t code10);

// The parameter words a canned cycle reads besides X Y Z R F and the repeat count (K/L):
// e.g. "P" or "PQ". A word the cycle does not read is an unused word (an error).
const char *cycleParamWords(ModeValue cycle, bool rs274);

// M codes with a built-in meaning; every other integer M is an `aux`.
// ToolNumber: LinuxCNC M61 Q; Io: LinuxCNC M62-M68 (digital and analog outputs, M66 input).
enum class MKind : uint8_t { Stop, ToolChange, ToolNumber, Spindle, Coolant, Call, Return, Aux, Io, Unsupported };
enum class MGroup : uint8_t { None, Stop, ToolChange, Spindle, Coolant, Sub, Io };

struct MCodeInfo {
  int32_t code;
  MKind kind;
  MGroup group;
  int arg;          // Stop: StopKind; Spindle: 0 stop 1 cw 2 ccw; Coolant: 7 mist 8 flood 9 off
  const char *what;  // Unsupported: what the code does (for the message)
  bool rs274Only;    // the meaning is LinuxCNC's; elsewhere the code is an aux code
  // No default member initializers: always aggregate-initialized (omitted members are zero), and
  // a lowered block's unused M slots then cost nothing.
};
// Returns the built-in meaning, or an Aux entry for any other code.
MCodeInfo findMCode(int32_t code, bool rs274);

}  // namespace ncc::iso
