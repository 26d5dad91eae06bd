// The per-controller output table: everything that differs between ISO and Sinumerik output is
// data here (defaults in ControllerTable.cpp), overridable by the machine description's
// [emit.iso] / [emit.sinumerik] keys. docs/EMIT.md lists every key.
#pragma once
#include "backends/emit/Emitter.h"
#include "backends/emit/WordFormat.h"

#include <array>
#include <string>
#include <vector>

namespace ncc::emit {

// Numeric word classes sharing one format.
enum class WordClass : uint8_t { Axis, Rotary, Center, Feed, Speed, Dwell, Count };

// G/M codes the emitter writes, one per event.
enum class Code : uint8_t {
  Rapid, Linear, ArcCW, ArcCCW, Dwell, ExactStopOnce,
  PlaneXY, PlaneZX, PlaneYZ,
  PerMinute, PerRev, InverseTime,
  ExactPath, ExactStop, Continuous,
  SpindleCW, SpindleCCW, SpindleStop,
  FloodOn, MistOn, CoolantOff,
  ToolChange, ProgramStop, OptionalStop, EndM2, EndM30,
  Count
};

enum class ArcStyle : uint8_t { IJK, R };
enum class HelixTurns : uint8_t { Word, Split };
enum class CommentStyle : uint8_t { Paren, Semicolon };
enum class MessageStyle : uint8_t { ParenMsg, MsgCall, Comment };  // Comment: "; MSG text" (NC-200)
// Arc centres: `Incremental` I J K = centre minus start on the axes' own letters (ISO, Sinumerik);
// `AbsolutePlane` I J = the centre's absolute coordinates on the plane's abscissa and ordinate,
// whatever the axes are called (NC-200, seed 003 L736: `G3 U-10 V0 I0 J0` in the plane U,V).
enum class CenterStyle : uint8_t { Incremental, AbsolutePlane };
enum class Numbering : uint8_t { Off, Renumber, Source };
// Rapid moves along several axes (seed 004 §3.3 "Motions"): all together, or the plane's two
// axes together and the third one on its own (xy_then_z: X Y together, Z alone).
enum class RapidSplit : uint8_t { Together, XYThenZ, XZThenY, ZYThenX };

struct ControllerStyle {
  Target target = Target::ISO;
  std::string section;  // "emit.iso"
  std::array<NumberFormat, (size_t)WordClass::Count> formats{};
  std::array<std::string, (size_t)Code::Count> codes{};

  ArcStyle arcStyle = ArcStyle::IJK;
  HelixTurns helixTurns = HelixTurns::Split;
  std::string radiusWord = "R";  // R form radius address (Sinumerik "CR=")
  std::string turnsWord = "P";   // multi-turn helix address (Sinumerik "TURN=")
  int turnsOffset = 0;           // written value = full turns + 1 - turnsOffset (TURN= counts extra turns)

  std::string dwellWord = "X";   // address of the dwell time
  double dwellScale = 1;         // seconds -> written unit (1000 for milliseconds)

  int toolDigits = 0;            // T01 when 2
  std::string toolOffsetWord;    // written with the tool change (Sinumerik "D0")

  CommentStyle commentStyle = CommentStyle::Paren;
  MessageStyle messageStyle = MessageStyle::ParenMsg;

  Numbering numbering = Numbering::Off;
  int64_t blockStart = 10, blockStep = 10;
  int blockEvery = 1;            // number every Nth block only
  int blockDigits = 0;
  std::string separator = " ";
  std::string endOfBlock;        // e.g. ";" (Fanuc EOB style)
  std::string lineEnding = "\n";

  std::vector<std::string> programHeader;  // verbatim first lines ("%")
  std::vector<std::string> programFooter;  // verbatim last lines ("%")
  bool programNumber = false;    // O0001 line
  int programNumberDigits = 4;
  std::vector<std::string> setup;  // set-up blocks after the header, each a list of words
  Plane setupPlane = Plane::XY;    // the plane the set-up blocks select

  // A lathe program (machine [controller] kind = "lathe", docs/EMIT.md "Lathes"): X words are
  // diameters (xScale 2) under diameter programming; ISO writes T<tt>00, the thread code and the
  // block that limits the spindle speed under G96 of the machine's G-code system.
  bool lathe = false;
  double xScale = 1;
  std::string threadCode;       // ISO lathe: G32 (system A) / G33 (B)
  std::string speedLimitCode;   // ISO lathe: G50 (A) / G92 (B), with S

  // Arc and plane rules of targets whose manuals say less than ISO's (NC-200, Nc200Table.cpp).
  CenterStyle centerStyle = CenterStyle::Incremental;
  bool planeOwnBlock = false;   // the plane code stands in a block of its own ("(DPI,Z,X)")
  bool helixAllowed = true;     // false: an arc that moves the plane's normal axis is refused
  double maxArcSweep = 0;       // degrees; longer arcs (full circles too) are split into equal pieces (0: never)
  std::string toolSuffix;       // after the tool number: NC-200 ".0" (T5.0: tool 5, offset 0)
  std::string unverifiedNote;   // a header comment that the output was never read back (no front end)
  // Passport rules of the motions and interpolators (seed 004 §3.3 items 5-6; docs/EMIT.md
  // "Passport"). Each changes the blocks, never the path: a split move ends where the source's
  // did and its pieces lie on the source's line or arc; what cannot be written exactly is refused.
  std::array<double, 3> maxIncrement{};  // X Y Z: longer straight moves become equal parts; 0 = unlimited
  RapidSplit rapidSplit = RapidSplit::Together;
  bool arcs = true;              // the circular interpolator exists (else every arc is refused)
  bool arcQuadrants = false;     // an arc crossing a quadrant boundary is split there
  double maxArcRadius = 0;       // larger arcs are refused; 0 = unlimited
  bool motionModal = true;       // G0/G1/G2/G3 only when it changes (the passport's modal flag)
};

// The Balt-System NC-200 defaults (Nc200Table.cpp, seed 003) and a lathe's changes to them.
ControllerStyle nc200Style();
bool applyNc200Lathe(const Machine &m, ControllerStyle &style, Diagnostics &diags);

// Defaults of a controller (before the machine description is applied).
ControllerStyle defaultStyle(Target t);

// A lathe machine's changes to the defaults (set-up blocks, feed-mode codes of its G-code system,
// diameters); nothing for a mill. False (reported) when the lathe's output cannot be written.
bool applyLathe(const Machine &m, ControllerStyle &style, Diagnostics &diags);

// Applies the machine's [emit.<target>] section over the defaults. Unknown keys warn, bad values
// are errors; returns false when an error was reported.
bool applyMachineSection(const Machine &m, ControllerStyle &style, Diagnostics &diags);

}  // namespace ncc::emit
