// Machine description: axes and their limits, controller profile, kinematics, offsets, tools
// and the emitters' settings. A versioned TOML file (schema 1, see docs/MACHINE.md); the default
// 3-axis mill is embedded in the binary so `ncc run prog.nc` needs no set-up.
#pragma once
#include "ir/ModeTable.h"
#include "ir/MotionIR.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ncc {

struct AxisLimits {
  bool present = false;
  bool rotary = false;
  std::string name;        // the controller's name of the axis; empty: its letter (Machine::axisName)
  double maxVelocity = 0;  // mm/min (deg/min)
  double maxAccel = 0;     // mm/s^2
  double maxJerk = 0;      // mm/s^3
  double minPos = -1e9, maxPos = 1e9;  // soft limits, machine coordinates
};

// What a T, H or D number stands for today: its tool's edge 1 (or only edge), geometry + wear.
struct ToolData {
  double length = 0;  // mm
  double radius = 0;  // mm
  double xOffset = 0; // mm, lathe X offset (a radius: machine X), geometry plus wear
  int tip = 0;         // lathe imaginary tool tip 0-9 (docs/MACHINE.md "Lathes"), for TNRC
};

// One cutting edge (Sinumerik D number, Heidenhain/Fanuc offset) of a tool.
struct ToolEdge {
  double length = 0, radius = 0;          // mm, geometry
  double lengthWear = 0, radiusWear = 0;  // mm, added to the geometry
  double xOffset = 0, xWear = 0;          // mm, lathe X offset (radius, machine X) and its wear
  int tip = 0;                            // lathe imaginary tool tip 0-9 (0 and 9: the nose centre)
  // Sinumerik edge data (docs/SINUMERIK.md "Tool offsets"): $TC_DP1 the tool type (1xx/2xx
  // milling and drilling, 400-599 turning and grinding; 0 none), lengths 2 and 3 ($TC_DP4/5) and
  // their wear ($TC_DP13/14), the base dimensions of lengths 1-3 ($TC_DP21-23). `length`,
  // `radius` and their wear are $TC_DP3, $TC_DP6, $TC_DP12, $TC_DP15; `tip` is $TC_DP2.
  int type = 0;
  double length2 = 0, length3 = 0, length2Wear = 0, length3Wear = 0;
  double base1 = 0, base2 = 0, base3 = 0;
  // The additive offsets of DL sets 1..6 for lengths 1-3 and the radius: wear $TC_SCPxy and
  // setup values $TC_ECPxy, [x - 1][y - 3] (programs write them; the machine file has none).
  double sumWear[6][4] = {}, sumSetup[6][4] = {};
};

struct Tool {
  std::string name;
  int teeth = 0;  // cutting edges (the TNC's CUT): Heidenhain FZ feeds per tooth (0: not given)
  std::map<int, ToolEdge> edges;  // by D number
  // Heidenhain TOOL.T data the machining cycles read (docs/MACHINE.md "[[tools]]"), 0 = not
  // given: ANGLE, the largest plunge angle (degrees from the plane) of helical and reciprocating
  // plunges; T-ANGLE, the point angle of a drill or centring tool (degrees, the full angle);
  // LCUTS, the cutting length (mm).
  double plungeAngle = 0, pointAngle = 0, cuttingLength = 0;
  // A grooving tool's insert width (mm; Sinumerik Operate's plate width), 0 = not given: the
  // grooving cycles (CYCLE930) step their plunges by it and cut the far flank with its far corner.
  double width = 0;
};

// When a work offset written by a program (LinuxCNC #5221, Fanuc #5221, Sinumerik $P_UIFR)
// takes effect for the active system: at once (Fanuc); when a G54… is next programmed, the
// active one included (Sinumerik settable frames); when another system is selected or at reset
// (LinuxCNC, whose G54 in G54 "continues to use the same coordinate system"). G10 L2/L20 of the
// active system applies its table at once in every profile.
enum class OffsetWrite : uint8_t { Immediate, OnSelect, OnChange };
// When a tool offset a program writes (G10 L1/L10-L13, Fanuc #2001…, NC IR `$_tool_data`,
// later Sinumerik $TC_DP…) takes effect for the offset in use (the active G43 H, the D of cutter
// compensation): at the next H/D/T selection (Sinumerik; Fanuc with parameters EVO/EVR = 0;
// rs274), or at once, from the next block (Fanuc EVO/EVR = 1).
enum class ToolWrite : uint8_t { OnSelect, Immediate };

// The controller profile: data for the dialect front ends (docs/MACHINE.md says which are used).
struct Controller {
  std::string family = "iso";        // iso fanuc linuxcnc sinumerik heidenhain cldata
  std::string model;                 // free text, e.g. "840D sl"
  std::string kind = "mill";         // "mill" or "lathe" (turning G codes, T0101, G18 plane)
  std::string gcodeSystem = "A";     // Fanuc lathe G-code system A, B or C
  // The mode a Sinumerik program file (.mpf/.spf) starts in (808D MD: ISO as the default mode):
  // "siemens" (G290) or "iso" (G291). Both modes switch with G290/G291 inside programs.
  std::string startMode = "siemens";
  bool lathe() const { return kind == "lathe"; }
  std::string plane = "G17";         // start-up plane G17, G18, G19
  bool diameterProgramming = false;  // lathe: X words are diameters
  // Modal groups M2/M30 reset; without the key, rs274's set (G92, units and tool length stay).
  std::vector<std::string> reset = {"work_offset", "plane", "feed_mode", "distance", "motion",
                                    "feed",        "spindle", "coolant", "cutter_comp"};
  int rParams = 100;                 // Sinumerik R0..R(n-1)
  int qParams = 2000;                // Heidenhain Q0..Q(n-1)
  // TNC machine parameter displayDepthErr (201003): a positive depth Q201 in a 2xx cycle is an
  // error (true, the TNC's default) or runs with the pre-positioning inverted (false).
  bool displayDepthErr = true;
  double realTolerance = 1e-12;      // Sinumerik: relative tolerance of REAL = and <>
  // ISO G51 scaling (808D MD22914 $MC_AXES_SCALE_ENABLE, MD22910 weighting): false = one factor
  // P for all axes, true = per-axis factors I J K (a negative one mirrors); factor x weighting.
  bool axesScaleEnable = false;
  double scaleWeighting = 0.001;
  // A G or M code that calls a program instead ("M6" -> O9001): Fanuc parameters 6050-6089,
  // 808D MD10814-MD10817 (frontend/iso/README.md "Macro calls by code").
  struct MacroCall {
    std::string program;
    // "macro": the block's addresses are arguments (as G65: #1-#33, 808D $C_ variables);
    // "subprogram": the program runs on the caller's variables after the block (as M98).
    std::string kind = "macro";
    bool operator==(const MacroCall &) const = default;
  };
  std::map<std::string, MacroCall> macroCalls;  // by code: "M6", "G100", "G65.1"
  // The modal state at program start, besides `plane` (key `startup`, G codes): one code per
  // group, e.g. LinuxCNC's stand-alone G80 and G99. Groups not named start as ncc's default
  // (G0 G90 G91.1 G94 G98 G21 G64).
  std::vector<ModeValue> startup;
  // Key offset_write: "immediate", "on-select", "on-change"; empty = the family's (linuxcnc:
  // on-change, sinumerik and heidenhain: on-select, others: immediate).
  std::string offsetWrite;
  OffsetWrite offsetWritePolicy() const;
  // The length unit of offsets, G92 values and reference points as programs read and write
  // them (LinuxCNC #5161-#5390: the machine's LINEAR_UNITS; stand-alone rs274: inch).
  std::string parameterUnits = "mm";
  // The Heidenhain probe table tchprobe.tp of the touch probe (docs/PROBING.md "Heidenhain touch-
  // probe cycles"): F probing feed, FMAX feed between the points, DIST the longest probing path,
  // SET_UP the clearance added to Q320, F_PREPOS "machine" (FMAX_MACHINE: pre-position at rapid)
  // or "probe" (FMAX_PROBE: at FMAX).
  double probeFeed = 100, probeFmax = 5000, probeDist = 10, probeSetUp = 2;
  std::string probePrepos = "machine";
  // Oriented spindle stops the program does not give an angle for (808D SD43240 $SA_M19_SPOS for
  // M19; the GUD _ZSFR[2] of the G76/G87 boring cycles) and the side the boring tool moves off
  // the wall (_ZSFI[5]: 1 +a1, 0 or 2 -a1, 3 +a2, 4 -a2 of the plane's axes, e.g. +X -X +Y -Y in G17).
  double m19Angle = 0;
  double boringOrientAngle = 0;
  int boringLift = 0;
  // The retract e after each peck of the lathe's G74/G75 until a program gives `G74 R` (808D GUD
  // _ZSFI[29]), mm. 1 mm as the 808D's milling peck retract _ZSFR[1] takes for 0.
  double peckRetract = 1.0;
  // Peck tapping of the milling G84/G74 with Q (808D GUD _ZSFI[1]): "off" (Q in a tapping block
  // is an error), "chip-breaking" (_ZSFI[1] = 2: back by chipBreakRetract after each infeed) or
  // "chip-removal" (_ZSFI[1] = 3: back to R after each infeed). chipBreakRetract is the GUD
  // _ZSFR[1] in mm; 0 takes the 808D's 1 mm.
  std::string peckTapping = "off";
  double chipBreakRetract = 0;
  // Key tool_write: "on-select" (default) or "immediate".
  std::string toolWrite = "on-select";
  ToolWrite toolWritePolicy() const { return toolWrite == "immediate" ? ToolWrite::Immediate : ToolWrite::OnSelect; }
  // Key offset_memory: which Fanuc Custom Macro B variables read and write the tool offsets
  // (#2001…, #10001…): "none" (they are errors) or "C" (H and D, geometry and wear apart).
  std::string offsetMemory = "none";
  // Key offset_numbers: the edge each ISO H/D offset number addresses (808D `$TC_DPH[t, d]`,
  // "ISO_H"): number -> (tool, edge). Empty: number n is tool n's edge 1 or only edge.
  std::map<int, std::pair<int, int>> offsetNumbers;
  // Sinumerik tool offset setting data (docs/SINUMERIK.md "Tool offsets"): SD42900
  // $SC_MIRROR_TOOL_LENGTH, SD42910 $SC_MIRROR_TOOL_WEAR, SD42920 $SC_WEAR_SIGN_CUTPOS, SD42930
  // $SC_WEAR_SIGN, SD42940 $SC_TOOL_LENGTH_CONST (0: the lengths follow the plane), and the DL set
  // an edge selection activates (MD20272 $MC_SUMCORR_DEFAULT, 0 none).
  bool mirrorToolLength = false, mirrorToolWear = false, wearSignCutpos = false, wearSign = false;
  int toolLengthConst = 0;
  int dlDefault = 0;
  // Sinumerik frames (docs/SINUMERIK.md "Frame chain"): MD28081 $MC_MM_NUM_BASE_FRAMES (channel
  // base frames), the NCU-global base frames (MD18602), MD24002 $MC_CHBFRAME_RESET_MASK (the
  // base frames that enter the total base frame after reset: both masks, as the manual says) and
  // MD20110 $MC_RESET_MODE_MASK (bits 0, 5, 14: which frames are active after reset, i.e. when a
  // run starts).
  int baseFrames = 1, ncBaseFrames = 0;
  // MD28080 $MC_MM_NUM_USER_FRAMES: the settable frames $P_UIFR[0 … n-1] (G500, G54…G57,
  // G505…); ncc's default 10 keeps G505…G509, which it always had.
  int settableFrames = 10;
  int baseFrameMask = 0xff;
  int resetModeMask = 0x4021;
};

// One rotary joint of a kinematic chain ([[kinematics.joints]], docs/MACHINE.md "Kinematics").
// Positive joint values turn the moving part (the table with the workpiece, or the head with the
// spindle) right-handed about `direction`.
struct RotaryJoint {
  int axis = -1;                          // machine axis index (A B C: 3..5)
  bool onHead = false;                    // turns the spindle (head) or the workpiece (table)
  std::array<double, 3> direction{0, 0, 1};  // unit vector, machine axes, all joints at zero
  // A point of the rotation axis with all joints at zero: table joints in machine coordinates,
  // head joints relative to the spindle gauge point (the head pivot).
  std::array<double, 3> center{};
};

// The rotary chain of a machine (`kinematics` other than "xyz"): two joints, listed from the
// machine base outward on each side (the joint that carries the other first).
struct KinematicChain {
  std::vector<RotaryJoint> joints;
  std::array<double, 3> toolAxis{0, 0, 1};  // tip -> spindle with the joints at zero
  std::string prefer = "nearest";           // nearest, positive, negative (sign of the tilt joint)
  // The joint next to the tool on the path tool -> workpiece (the outer head joint, else the
  // first table joint): it tilts the tool axis away from `toolAxis`.
  int tiltJoint() const;
};

// One problem of a machine description; line 0 = not located (an unreadable file).
struct MachineError {
  uint32_t line = 0, col = 0;
  std::string message;
};

struct ProbeResults;  // runtime/ProbeResults.h

struct Machine {
  std::string name = "default-mill";
  std::string dialect = "iso";           // controller dialect of the machine
  std::array<AxisLimits, kAxes> axes{};
  // xyz (X Y Z are the tool position, A B C turn on their own), table-table, head-table or
  // head-head; the rotary chain's data in `chain` (runtime/Kinematics.h uses it).
  std::string kinematics = "xyz";
  KinematicChain chain;
  Controller controller;
  double rapidFeed = 10000;              // mm/min, path rapid speed cap
  double maxFeed = 5000;                 // mm/min, programmed feed cap
  double maxSpindleSpeed = 0;            // rpm, the spindle's top speed (0: not limited); caps
                                         // constant surface speed (G96)
  double arcTolerance = 0.002;           // mm: arc start/end radius mismatch allowed
  double pathTolerance = 0.01;           // mm: corner blending tolerance in continuous mode
  int lookahead = 64;                    // planner window in moves
  // How a number without a decimal point is read: "calculator" (X1000 = 1000 mm), "is-b"
  // (x 0.001), "is-c" (x 0.0001).
  std::string decimalMode = "calculator";
  // The settable work offsets 1..99, machine mm: G54..G59.3 are 1..9; the 808D's G54 P1…P93 are
  // 7..99 (key g54p; its first three share the slots of LinuxCNC's G59.1-G59.3, as Sinumerik's
  // G507-G599 do).
  static constexpr int kWorkOffsets = 99;
  std::array<AxisVec, kWorkOffsets> workOffsets{};
  // The stored Sinumerik base frames $P_CHBFR[n] and $P_NCBFR[n] (offsets, machine mm).
  std::array<AxisVec, 8> chanBaseFrames{}, ncBaseFrames{};
  // The stored Sinumerik settable frames past G509: n -> $P_UIFR[n] (G5nn, n 10..99), offsets.
  std::map<int, AxisVec> settableFrames;
  AxisVec home1{}, home2{};              // G28 / G30 reference positions, machine mm
  std::map<int, Tool> toolTable;         // every tool with its name and edges
  std::map<int, ToolData> tools;         // by T/H/D number: edge 1 of toolTable (see ToolData)
  // Tool numbers 1..freeTools are valid even when the table lacks them (zero length and
  // radius), as in rs274's stand-alone set-up; any other number must be in the table (when
  // the machine has one).
  int freeTools = 0;
  // The tool data of number n (0 = no tool: zero data), or null when n is not a valid tool.
  const ToolData *findTool(int n) const;
  // The controller's name of axis i (its `name`, else its letter X..W).
  std::string axisName(int i) const;
  // The axis a controller name stands for (-1: none): a described axis's name, or the letter of
  // a described axis that has no other name.
  int axisByName(std::string_view name) const;
  // Adds tool n with the one edge d = 1 to both tables (machines built in code: the executor
  // reads edges from toolTable, findTool reads tools).
  void addTool(int n, const ToolEdge &edge);
  // The [emit.NAME] tables as text, section "emit.NAME", nested keys dotted ("format.X"), for
  // the emitters, which check their own keys.
  std::map<std::string, std::map<std::string, std::string>> sections;
  // Where each of those values stands in the file (line, column; keys as in `sections`), and the
  // SourceManager id the driver registered the file under (0: none), so that the emitters'
  // checks of their keys point at the value.
  std::map<std::string, std::map<std::string, std::pair<uint32_t, uint32_t>>> sectionPositions;
  uint32_t sourceFile = 0;
  // What the simulated probe meets (the driver's --probe-results, docs/PROBING.md); null: a probe
  // move is an error.
  std::shared_ptr<const ProbeResults> probeResults;

  std::string get(const std::string &section, const std::string &key, const std::string &def = "") const;

  static const Machine &builtinDefault();
  // The text of the embedded default description (`ncc machine --print-default`).
  static const char *builtinDefaultText();
  // Parses description text; on failure, every problem found, in file order.
  static bool parse(const std::string &text, const std::string &name, Machine &out, std::vector<MachineError> &errors);
  // NAME is "default" or a path to a description file.
  static bool load(const std::string &nameOrPath, Machine &out, std::vector<MachineError> &errors);
  // The same with the problems as text, one "name:line:col: error: message" line each.
  static bool parse(const std::string &text, const std::string &name, Machine &out, std::string &err);
  static bool load(const std::string &nameOrPath, Machine &out, std::string &err);
};

}  // namespace ncc
