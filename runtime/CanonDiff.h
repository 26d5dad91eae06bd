// Compares two canonical traces in LinuxCNC rs274's text format (rs274's own output, or ncc's
// CanonTraceWriter) at one of two levels:
//  * machine: replays the state commands (USE_LENGTH_UNITS, SET_G5X_OFFSET, SET_G92_OFFSET,
//    SET_XY_ROTATION, USE_TOOL_LENGTH_OFFSET, SELECT_PLANE) and compares only the motion
//    (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, STRAIGHT_PROBE, RIGID_TAP, DWELL) in machine mm,
//    composed as LinuxCNC does: add G92, rotate XY, add G5x, add the tool offset.
//  * program: the lines as printed, without the sequence and N columns and without the
//    interpreter's own `COMMENT("interpreter: ...")`, numbers compared with the tolerance.
// Native streaming parser: million-line traces compare in well under a second.
#pragma once
#include <string>
#include <string_view>

namespace ncc {

enum class CanonDiffLevel : unsigned char { Machine, Program };

struct CanonDiffOptions {
  using Level = CanonDiffLevel;
  Level level = Level::Machine;
  double tolerance = 1e-4;       // program units (machine level: x25.4 while in inch units)
  bool ignoreComments = false;   // program level: also drop every COMMENT and MESSAGE line
};

// Returns true when the traces match. `report` gets a one-line summary on a match, or the first
// difference with the line numbers and texts of both sides.
bool canonDiff(std::string_view a, std::string_view b, const CanonDiffOptions &opts, std::string &report);

}  // namespace ncc
