// The elementary steps every library cycle expands into (program coordinates, mm); the executor
// turns them into Motion IR records (Executor::Impl::runSteps, runtime/ExecutorCycle.cpp).
#pragma once
#include <array>
#include <cstdint>

namespace ncc {

// RigidTap: a tap without a compensating chuck (Sinumerik CYCLE84's G331/G332), spindle-
// synchronised down to `pos` along the drilling axis and back to where it began (two Motion IR
// thread records, sync tap_in / tap_out); the spindle is in position control (an orient before).
// SpindleSpeed: the spindle speed becomes `speed` (Heidenhain 241's entry and drilling speeds);
// Coolant: `coolant` bit 1 flood, bit 2 mist on (0: both off), as M8, M7, M9.
// Thread: a spindle-synchronised move to `pos` with `lead` mm/rev along `along` (0 X, 2 Z); a new
// synchronisation at the start angle `angle` (degrees), or (`chain`) continuing the thread
// move before it (Sinumerik CYCLE98/CYCLE99, runtime/cycles/SinTurning.cpp).
enum class CycleStepKind : uint8_t {
  Rapid, Feed, Arc, Dwell, SpindleStop, SpindleCW, SpindleCCW, SpindleOrient, RigidTap, SpindleSpeed, Coolant, Thread
};

struct CycleStep {
  CycleStepKind kind = CycleStepKind::Rapid;
  std::array<double, 3> pos{};  // X Y Z target of Rapid/Feed/Arc
  double seconds = 0;           // Dwell
  double feed = 0;              // Feed, Arc: mm/min, 0 = the programmed feed
  double angle = 0;             // SpindleOrient: degrees (the shortest way); Thread: the start angle
  double lead = 0;              // RigidTap: mm per spindle revolution along the drilling axis; Thread: the lead
  uint8_t along = 2;            // Thread: the axis the lead is measured along (0 X, 2 Z)
  bool chain = false;           // Thread: continues the thread move before it
  double speed = 0;             // RigidTap: the tapping speed, rpm (0: the active S); SpindleSpeed: rpm
  uint8_t coolant = 0;          // Coolant: 1 flood, 2 mist, 0 off
  // Arc: an exact circular move in the active plane about `centre` (its drilling-axis coordinate
  // is ignored), counter-clockwise about the plane's normal when `ccw`; the drilling-axis
  // coordinate may change on the way (a helix). An end equal to the start is a full circle;
  // `turns` > 1 adds whole turns (helical plunges).
  std::array<double, 3> centre{};
  bool ccw = true;
  int turns = 1;
  // The move to the R level made before the holes when the initial level is below R: rs274
  // makes it outside the exact-path bracket of the holes.
  bool preMove = false;
};

}  // namespace ncc
