// The cycle library: every vendor cycle as a thin entry that maps its parameter list onto the
// shared pieces (hole strategies in Hole.h, pattern walkers in Pattern.h, clearing in
// Clearing.h). A front end lowers `CYCLE83(…)`, `CYCL DEF 200 …` or a CLData cycle record onto an
// entry by name (`sin.CYCLE83`, `hei.200`); the executor runs it (Executor::runCycle), and
// `ncc cycle NAME K=V…` runs one alone. docs/CYCLES.md lists the entries.
#pragma once
#include "ir/CycleCatalog.h"
#include "runtime/cycles/Hole.h"
#include "runtime/cycles/Pattern.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

struct CycleContour;  // runtime/cycles/Contour.h

// A cycle's arguments by parameter name (positional calls are mapped to names by the front end
// from the entry's parameter list). Omitted parameters are absent, not 0.
struct CycleArgs {
  std::map<std::string, double> num;
  std::map<std::string, std::string> text;  // STRING parameters (Sinumerik _HIDE)
  bool has(const std::string &k) const { return num.count(k) != 0; }
  double get(const std::string &k, double def = 0) const {
    auto it = num.find(k);
    return it == num.end() ? def : it->second;
  }
};

// Where the cycle runs: program coordinates (mm, the active frame's), the plane, the modal
// feed and spindle.
struct CycleContext {
  int plane = 0;                    // 0 XY (drill along Z), 1 ZX (along Y), 2 YZ (along X)
  std::array<double, 3> position{};  // X Y Z
  double feed = 0;                  // mm/min (0 = none programmed)
  int spindle = 0;                  // 0 stop, 1 cw, 2 ccw
  double speed = 0;                 // rpm
  double toolRadius = 0;            // mm, the active tool's (0: no tool or no radius)
  // The active tool's table data (Tool in runtime/Machine.h; 0: not given): the largest plunge
  // angle ANGLE and the point angle T-ANGLE in degrees, the cutting length LCUTS in mm.
  double plungeAngle = 0, pointAngle = 0, cuttingLength = 0;
  double toolWidth = 0;  // a grooving insert's width in mm (Tool::width; 0: not given)
  bool feedPerRev = false;  // G95 (feed per revolution) is active
  // The contour captured for this cycle (CycleDef::contour): ZX plane coordinates, x a radius;
  // null when none was captured.
  const CycleContour *contour = nullptr;
};

struct CycleDef {
  const char *name;    // "sin.CYCLE81", "hei.200"
  const char *params;  // the positional parameter names, space-separated
  const char *what;
  // A machining cycle: appends its steps (program coordinates) at ctx.position.
  bool (*expand)(const CycleArgs &args, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err);
  // A position pattern: the positions in the plane, in the order they are visited.
  bool (*positions)(const CycleArgs &args, std::vector<PlanePoint> &out, std::string &err);
  // The parameters that are absolute positions, "NAME:axis …" (n the drilling axis, u v the
  // plane's first and second, d a diameter along v: the turning cycles' X), valid while no mode parameter (a name with MODE, _AXN) is set:
  // an emitter that writes the call back in another frame shifts them (docs/EMIT.md "Cycles").
  // Null: the call cannot be written back (its expanded moves are).
  const char *coords = nullptr;
  // The STRING parameters, space-separated (HOLES1's _HIDE); the others take numbers. A name
  // with a `~` before it is one for the control's input screens only (CYCLE99's thread table
  // _PTAB): the front end accepts and drops it.
  const char *strings = nullptr;
  // The STRING parameter that names the contour the cycle cuts from (CYCLE95's NPP): the front
  // end captures it before the call, the executor hands it over in CycleContext::contour.
  const char *contour = nullptr;
};

// The entries of each file of the library (Library.cpp: holes and patterns, ClearingEntries.cpp:
// Heidenhain pockets, slots, studs, faces, SinClearingEntries.cpp: Sinumerik pockets and slots);
// cycleLibrary() is all of them.
void addHoleEntries(std::vector<CycleDef> &out);
void addClearingEntries(std::vector<CycleDef> &out);
void addSinClearingEntries(std::vector<CycleDef> &out);
void addSinSpigotEntries(std::vector<CycleDef> &out);  // SinSpigotEntries.cpp: CYCLE76, 77, 79
void addSinThreadMillEntries(std::vector<CycleDef> &out);  // SinThreadMill.cpp: CYCLE70
void addSinDrillThreadEntries(std::vector<CycleDef> &out);  // SinDrillThread.cpp: CYCLE78
void addHeiPatternEntries(std::vector<CycleDef> &out);  // HeiPatternDef.cpp
void addHeiThreadMillEntries(std::vector<CycleDef> &out);  // HeiThreadMill.cpp: 262-267
void addHeiDeepHoleEntries(std::vector<CycleDef> &out);    // HeiDeepHole.cpp: 204, 205, 241
void addSinThreadEntries(std::vector<CycleDef> &out);      // SinThread.cpp: CYCLE98, CYCLE99
void addSinTurningEntries(std::vector<CycleDef> &out);     // SinTurning.cpp: CYCLE951, CYCLE95
void addSinGrooveEntries(std::vector<CycleDef> &out);       // SinGroove.cpp: CYCLE930
void addSinUndercutEntries(std::vector<CycleDef> &out);     // SinUndercut.cpp: CYCLE940
const std::vector<CycleDef> &cycleLibrary();
const CycleDef *findCycle(std::string_view name);

// A position pattern with the hole cycle run at each position (Sinumerik MCALL + HOLES1,
// Heidenhain CYCL DEF 200 + CYCL DEF 220 …); without a hole (Sinumerik only) rapids to each.
bool expandPattern(const CycleDef &pattern, const CycleArgs &patternArgs, const CycleDef *hole, CycleArgs holeArgs,
                   const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err);

// Heidenhain CYCL CALL PAT (HeiPatternDef.cpp): the PATTERN DEF / point-table patterns
// ("hei.PATTERN.…") and their walk, which expandPattern hands them to.
bool isCallPatPattern(const CycleDef &pattern);
bool walkCallPat(const CycleDef &pattern, const CycleArgs &patternArgs, const CycleDef &hole, const CycleArgs &holeArgs,
                 const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err);

// The front ends' view of an entry (ir/CycleCatalog.h; the driver passes this to them).
bool cycleSignature(std::string_view name, CycleSignature &out);

// The entry's positional parameter names, in order; the position of `name` among them (-1 none).
std::vector<std::string_view> cycleParamNames(const CycleDef &def);
int cycleParamIndex(const CycleDef &def, std::string_view name);

// Checks args against the entry's parameter list: unknown names are errors.
bool checkCycleArgs(const CycleDef &def, const CycleArgs &args, std::string &err);

}  // namespace ncc
