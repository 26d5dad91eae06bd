// The milling engine the pocket, slot and face entries share (ClearingEntries.cpp: Heidenhain,
// SinClearingEntries.cpp: Sinumerik): the options of a job (MillJob, named after the Heidenhain
// 25x parameters), pockets cleared ring by ring (clearingRings) with their walls finished on
// exact arcs, slots along a line or an arc, and the parameter helpers the entries read with.
#pragma once
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/Mill.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ncc::entry {

// How the tool goes down to a level at the plunge point: at the feed (Heidenhain Q366 0,
// Sinumerik _VARI 2nd digit 1), at rapid into a pre-drilled hole (Sinumerik 0), on a helix of
// `helixRadius` about the point with `helixPitch` per turn (Sinumerik 2, Heidenhain Q366 1), to
// and fro along `ramp` no steeper than `rampAngle` (Heidenhain Q366 2, slots 1 and 2).
enum class Plunge : uint8_t { Vertical, Rapid, Helix, Reciprocate };

// The track of a reciprocating plunge in the element's frame: a line from `a` to `b`, or an arc
// about `centre` (counter-clockwise from a to b when `ccw`), `length` long.
struct Ramp {
  PlanePoint a{}, b{};
  bool arc = false;
  PlanePoint centre{};
  bool ccw = true;
  double length = 0;
};

// ---- The options every pocket, slot and stud shares, named after the Heidenhain 25x parameters
// (seed002a "Pocket / stud / slot cycles: shared semantics"); the Sinumerik entries fill them from
// their own.
struct MillJob {
  HeiLevels lv;                   // zsc, z2 (the end), dir
  double surface = 0, depth = 0;  // Q203; |Q201|
  double infeed = 0;              // Q202
  double sideAllowance = 0, floorAllowance = 0, finishInfeed = 0;  // Q368 Q369 Q338
  double clearance = 0;           // |Q200|
  double plungeFeed = 0, millFeed = 0, finishFeed = 0;  // Q206 Q207 Q385 (0: Q207)
  int op = 0;                     // Q215: 0 rough and finish, 1 rough, 2 finish
  bool wallPass = false, floorPass = false;  // the finishing passes to run
  Plunge plunge = Plunge::Vertical;
  double helixRadius = 0, helixPitch = 0;
  Ramp ramp;                      // Reciprocate: the track (set by the element's shape)
  double rampAngle = 0;           // Reciprocate: the steepest slope, degrees (the tool's ANGLE)
  double stepover = 0;            // Q370 x tool radius
  double r = 0;                   // tool radius
  bool ccw = true;                // the direction round a pocket's wall (studs: the other)
  std::array<double, 3> call{};   // where the cycle was called
  // The tool-axis level `t` below the surface (negative: above).
  double level(double t) const { return surface + lv.dir * t; }
  bool roughing() const { return op != 2; }
  bool finishing() const { return op != 1; }
};

// A wall the finishing passes cut: the tool-centre path (a closed contour round the element,
// counter-clockwise from `start`), its outward normal there (away from the element's middle), the
// largest radius of the arcs onto and off it, and which side of it the material to finish lies
// (`inside`: a pocket's wall; else a stud's).
struct FinishPath {
  Contour path;
  PlanePoint normal{1, 0};
  double room = 0;
  bool inside = true;
};

// A pocket in its own frame (centre at the origin): the finished wall and the pass that finishes
// it.
struct PocketShape {
  Contour wall;
  FinishPath finish;
  PlanePoint home{0, 0};  // where the tool plunges and returns between levels
};

// Q367 of 253: the tool at the middle, the left end, the left arc's centre, the right arc's
// centre, the right end; the slot's centre from the tool in slot lengths (x L/2, x W/2 on x).
inline constexpr double kSlotEnd[5][2] = {{0, 0}, {1, 0}, {1, -1}, {-1, 1}, {-1, 0}};

// The plunges Q366 selects (seed002a: 251 L6093-6113, 252 L6398-6410, 253 L6640-6648, 254
// L6992-7003) with the tool's ANGLE: m.plunge and the helix (Heidenhain helices have the tool
// radius, so they cut a bore of twice the tool diameter) or the ramp's angle; `helix` is whether
// Q366 1 is a helix (251, 252) or, as 2, a reciprocating plunge (253, 254); `maxQ366` the
// largest value the cycle knows.
bool heiPlunge(const CycleArgs &a, const CycleContext &ctx, bool helix, int maxQ366, MillJob &m, std::string &err);
// The track of a reciprocating plunge along x about the origin, centred, for a pocket whose tool
// centre can move `room` either way: as long as one infeed plus the set-up clearance at the
// ANGLE, at least twice the tool diameter (seed002a L6108-6111), at most 2 x room.
bool centredRamp(MillJob &m, double room, std::string &err);
// False with an error when the helix of a Q366 1 plunge does not fit `room` (the distance from
// the plunge point to the nearest wall, less the side allowance).
bool helixFits(const MillJob &m, double room, std::string &err);

// The depths below the surface of successive infeeds of at most `step` down to `total`.
std::vector<double> infeeds(double step, double total);
// A number parameter within [lo, hi] (absent: def); false with err set.
bool param(const CycleArgs &a, const char *k, double lo, double hi, double &out, std::string &err, double def = 0);
// A choice 0 … hi (Q215, Q367 …).
bool position(const CycleArgs &a, const char *k, int hi, int &out, std::string &err);
// The active tool's radius into m.r; without one an error.
bool toolRadius(const CycleContext &ctx, MillJob &m, std::string &err);
// The writer for an element whose centre lies `offset` from the tool (or from `about`) in the
// element's own frame, the element turned by `degrees` about that point, in `plane` (default the
// active one).
Mill placed(std::vector<CycleStep> &out, const CycleContext &ctx, const MillJob &m, PlanePoint offset, double degrees,
            int plane = -1, const PlanePoint *about = nullptr);
// The walls in Q338 infeeds on exact arcs.
void finishWalls(const MillJob &m, const FinishPath &f, bool ccw, Mill &mill);
// Roughing, the walls and the floor of a pocket (Heidenhain 251-254, Sinumerik POCKET3/4, slots).
bool millPocket(const MillJob &m, const PocketShape &p, Mill &mill, std::string &err);
// A slot as wide as the tool along its centre line `line`.
void slotLine(const MillJob &m, const Contour &line, Mill &mill);
// A straight slot L x W about the origin along x (`allowance` names the side allowance in errors).
bool straightSlot(const MillJob &m, double L, double W, const char *allowance, Mill &mill, std::string &err);
// `count` slots W wide along arcs of radius rp about `centre` from `first` + i x `step` degrees.
bool arcSlots(const MillJob &m, int plane, PlanePoint centre, double rp, double W, double sweepDeg, double first,
              double step, int count, const char *allowance, std::vector<CycleStep> &out, std::string &err);

}  // namespace ncc::entry
