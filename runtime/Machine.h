// Machine description: axes and their limits, controller settings, offsets, tools and the
// emitter's word formats. A data file (INI-like, see docs/MACHINE.md); the default 3-axis mill
// is embedded in the binary so `ncc run prog.nc` needs no set-up.
#pragma once
#include "ir/MotionIR.h"

#include <map>
#include <string>

namespace ncc {

struct AxisLimits {
  bool present = false;
  bool rotary = false;
  double maxVelocity = 0;  // mm/min (deg/min)
  double maxAccel = 0;     // mm/s^2
  double maxJerk = 0;      // mm/s^3
  double minPos = -1e9, maxPos = 1e9;  // soft limits, machine coordinates
};

struct ToolData {
  double length = 0;  // mm
  double radius = 0;  // mm
};

struct Machine {
  std::string name = "default-mill";
  std::string dialect = "iso";           // controller dialect of the machine
  std::array<AxisLimits, kAxes> axes{};
  double rapidFeed = 10000;              // mm/min, path rapid speed cap
  double maxFeed = 5000;                 // mm/min, programmed feed cap
  double arcTolerance = 0.002;           // mm: arc start/end radius mismatch allowed
  double pathTolerance = 0.01;           // mm: corner blending tolerance in continuous mode
  int lookahead = 64;                    // planner window in moves
  // How a number without a decimal point is read: "calculator" (X1000 = 1000 mm), "is-b"
  // (x 0.001), "is-c" (x 0.0001).
  std::string decimalMode = "calculator";
  std::array<AxisVec, 9> workOffsets{};  // G54..G59.3, machine mm
  AxisVec home1{}, home2{};              // G28 / G30 reference positions, machine mm
  std::map<int, ToolData> tools;
  // Tool numbers 1..freeTools are valid even when the table lacks them (zero length and
  // radius), as in rs274's stand-alone set-up; any other number must be in the table (when
  // the machine has one).
  int freeTools = 0;
  // The tool data of number n (0 = no tool: zero data), or null when n is not a valid tool.
  const ToolData *findTool(int n) const;
  // Every section and key of the file as written, for consumers with their own settings
  // (emitters read [emit.iso], [emit.sinumerik]).
  std::map<std::string, std::map<std::string, std::string>> sections;

  std::string get(const std::string &section, const std::string &key, const std::string &def = "") const;

  static const Machine &builtinDefault();
  // The text of the embedded default description (`ncc machine --print-default`).
  static const char *builtinDefaultText();
  // Parses description text; errors name the line.
  static bool parse(const std::string &text, const std::string &name, Machine &out, std::string &err);
  // NAME is "default" or a path to a description file.
  static bool load(const std::string &nameOrPath, Machine &out, std::string &err);
};

}  // namespace ncc
