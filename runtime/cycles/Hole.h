// Hole strategies shared by every drilling cycle: ISO G73-G89 (runtime/Cycles.cpp), Sinumerik
// CYCLE81-CYCLE89 and Heidenhain 200-205 (runtime/cycles/Library.cpp) describe one hole as a
// HoleSpec; holeSteps turns it into elementary steps along the drilling axis.
#pragma once
#include "runtime/cycles/Step.h"

#include <vector>

namespace ncc {

// What happens after the bottom of the hole.
enum class HoleExit : uint8_t {
  Rapid,            // rapid to `retract`
  Feed,             // feed to `exitLevel` at exitFeed, then (exitRapid) rapid to `retract` (G85, G89, 201)
  SpindleStopRapid, // spindle stop, rapid to `retract`, spindle on again (G86)
  Tap,              // spindle reverse, feed to `retract`, spindle forward again (G84, G74)
  OrientShift,      // oriented stop at `orientAngle`, a rapid by `shift` off the wall, out to
                    // `exitLevel` (at `exitFeed`, 0 rapid) and `retract`, back to the centre at
                    // `exitLevel` (`centreAtExit`) or at `retract`, spindle on again unless
                    // `restart` is false (808D/Fanuc G76, Sinumerik CYCLE86, Heidenhain 202)
};

struct HoleSpec {
  // Levels on the drilling axis, absolute. Feeding starts at `start`; depth runs from start
  // toward bottom (either direction).
  double start = 0, bottom = 0, retract = 0;
  // Infeed: one pass when peck <= 0. Otherwise pecks of `peck`, each following one smaller by
  // `decrement` (or multiplied by `factor` when factor > 0) but not below `minPeck`.
  double peck = 0, decrement = 0, factor = 0, minPeck = 0;
  // Where the first peck is measured from when not `start` (Heidenhain: the surface).
  bool peckFromSet = false;
  double peckFrom = 0;
  // After each peck: a chip break (back by chipBreak, rapid or at the feed) or a full retract to
  // `start`, a dwell there, and a rapid back to `reentry` above the last depth. breaksPerRetract:
  // -1 always chip break, 0 always full retract, n: n chip breaks, then a full retract.
  // With the Tap exit (808D peck tapping) the spindle reverses for each way out and turns the
  // tapping way again before the next infeed, and the way back in is at the feed.
  int breaksPerRetract = 0;
  double chipBreak = 0;
  bool chipBreakRapid = true;
  double reentry = 0;
  double fullRetractFeed = -1;  // < 0: rapid; 0: the programmed feed; > 0: mm/min
  // Dwells in seconds; < 0: none (ISO writes a 0 s dwell where the cycle has one).
  double dwellPeck = -1;        // at each peck depth
  double dwellTop = -1;         // at `start` after a full retract
  double dwellBottom = -1;      // at the bottom (tapping: after the reversal)
  // Tap exit: reversed out to `start` only, `dwellStart` there, the tapping way again, then a
  // rapid to `retract` (808D/Fanuc G84/G74); false: reversed out to `retract` (rs274).
  bool tapOutToStart = false;
  double dwellStart = -1;
  double feed = 0, firstFeed = 0;  // 0: the programmed feed
  HoleExit exit = HoleExit::Rapid;
  double exitLevel = 0, exitFeed = 0;
  bool exitRapid = true;
  int spindle = 1;  // direction before the cycle (1 cw, 2 ccw): G86 restart, tapping
  double orientAngle = 0;        // OrientShift: the spindle angle that turns the edge off the wall
  double shift[3] = {0, 0, 0};   // OrientShift: the move off the wall along a1, a2 and the drilling axis
  bool centreAtExit = false, restart = true;
};

// Back boring (808D/Fanuc G87, Heidenhain 204): at the `start` level above the hole the spindle
// stops at `orientAngle` and the tool moves off centre by `shift`, goes down through the hole at
// rapid (`downFeed` > 0: at that feed) to `bottom` (the back face, below), returns to the centre,
// starts the spindle (`spindle`) and cuts back up to `cutLevel` at `feed`, dwells, (`backDown`:
// goes back down to `bottom` at `downFeed`), stops oriented again, moves off centre and rapids out
// to `start` (`retract` when set), back to the centre, spindle on again.
struct BackBoreSpec {
  double start = 0, bottom = 0, cutLevel = 0;
  double downFeed = 0;  // 0: rapid
  bool backDown = false;
  bool retractSet = false;
  double retract = 0;
  double feed = 0;     // 0: the programmed feed
  double dwell = -1;   // seconds at cutLevel (< 0: none)
  double orientAngle = 0;
  double shift[3] = {0, 0, 0};  // the third (drilling axis) is not used
  int spindle = 1;     // 1 cw, 2 ccw
};
void backBoreSteps(const BackBoreSpec &b, int a1, int a2, int d, double p1, double p2, std::vector<CycleStep> &out);

// Appends the steps of one hole at plane position (p1, p2): axes a1, a2 in the plane and d the
// drilling axis (indices into X Y Z). Starts with the feed from `start`; the caller positions.
void holeSteps(const HoleSpec &h, int a1, int a2, int d, double p1, double p2, std::vector<CycleStep> &out);

// Largest number of pecks a hole may need; more is a typo (peck depth far too small).
constexpr double kMaxPecks = 1e6;

}  // namespace ncc
