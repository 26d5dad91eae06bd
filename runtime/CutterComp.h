// Cutter radius compensation (G41/G42, G40) in the XY plane, as LinuxCNC's rs274 computes it (the
// executor hands G18/G19 paths over with their axes turned, ExecutorImpl.h toCompPlane):
// each programmed line or arc is offset by the tool radius to the left (G41) or right (G42) of
// the direction of travel; a convex corner gets an arc of the tool radius around the programmed
// corner, a concave corner is cut at the intersection of the two offset paths, and a turn of
// at most kSmoothTurn radians counts as smooth (no arc, no trimming). The first move after
// G41/G42 (entry) starts at the uncompensated tool position; the move after G40 (exit) is
// straight from the compensated position to the programmed point.
// Output lags one move: a move is emitted once the next one tells how its end is cut. Memory is
// bounded (one pending move), so the executor stays streaming.
#pragma once
#include "ir/MotionIR.h"

#include <string>
#include <vector>

namespace ncc {

struct Point2 {
  double x = 0, y = 0;
};

// One programmed XY path element: a line, or a circular arc around `center` (dir +1 counter-
// clockwise, -1 clockwise).
struct PathElem {
  bool arc = false;
  Point2 start, end, center;
  int dir = 0;
};

// Side of the tool: +1 left (G41), -1 right (G42).
Point2 startTangent(const PathElem &e);  // unit direction of travel at the start
Point2 endTangent(const PathElem &e);    // ... at the end
// Radius of the offset arc (may be <= 0: the tool does not fit inside the arc).
double offsetRadius(const PathElem &e, int side, double r);
// The point at distance r to `side` of the start (end) of `e`, normal to its direction.
Point2 offsetStart(const PathElem &e, int side, double r);
Point2 offsetEnd(const PathElem &e, int side, double r);
// Signed turn from direction t0 to t1 in (-pi, pi]: positive = left (counter-clockwise).
double turnAngle(Point2 t0, Point2 t1);
enum class CornerKind { Smooth, Convex, Concave };
constexpr double kSmoothTurn = 0.05;  // radians; measured on rs274 (0.0499 smooth, 0.0501 not)
// Convex: the tool goes round the outside of the corner (a left-side tool turning right);
// concave: the offset paths cross. Near a reversal (within kSmoothTurn) rs274 goes round, except
// when the deciding arc (the next move if it is an arc, else the pending one) has the tool on
// its outside (`outsideArc`): then turns up to kSmoothTurn past the reversal are concave.
CornerKind cornerKind(double turn, int side, bool outsideArc);
// Where the offset of `a` (near its end) meets the offset of `b` (near its start); the
// intersection nearest to the offset corner points. False when they do not meet.
bool offsetIntersection(const PathElem &a, const PathElem &b, int side, double r, Point2 &out);

// A lathe's imaginary tool tip 0-9 (808D "control point", Fanuc imaginary tool nose number):
// where the point the program and the tool offsets describe lies from the nose centre, in nose
// radii, as (Z, X): the G18 compensation plane's (first, second) axes. Seen with +Z to the right
// and +X up the numbers sit round the centre as  2 6 1 / 7 0 5 / 3 8 4  (rows from +X down);
// 0 and 9 are the centre itself. Out-of-range numbers give the centre.
Point2 noseTipVector(int tip);

class CutterComp {
public:
  explicit CutterComp(MotionSink &out) : out_(out) {}
  bool active() const { return side_ != 0; }
  // G41/G42 with radius r > 0 (mm); `tool` = the current (uncompensated) position.
  // `normalEntry` (the 808D/Fanuc lathe start-up, Fanuc type A): the entry move ends at the
  // next move's offset start point, normal to it, instead of rs274's corner with the next move.
  void start(int side, double r, const AxisVec &tool, bool normalEntry = false);
  // A programmed motion record (Rapid, Linear or Arc in the XY plane; start = programmed start).
  // Returns false on an error (message and rule in error()/rule()); nothing is emitted then.
  bool add(const MotionRecord &programmed);
  // G40 (or program end): emits the pending move ending normal to its end point and stops.
  // The next move (exit) then starts from toolPosition(). With `check` (G40) a pending straight
  // move that runs backwards is an error (false, nothing emitted), as in rs274.
  bool stop(bool check = false);
  // Where the tool really is after stop(); the exit move starts there.
  const AxisVec &toolPosition() const { return tool_; }
  // A record that rs274 queues behind the pending move (dwell, feed, spindle, coolant, comment):
  // held until then, placed at the tool's compensated XY. False when nothing is pending (the
  // caller emits it itself).
  bool hold(const MotionRecord &r);
  const std::string &error() const { return errMsg_; }
  const std::string &rule() const { return errRule_; }

private:
  bool fail(const char *msg, const char *rule);
  void emitPending(Point2 end, bool entryArc);
  void emitCornerArc(const PathElem &next, const MotionRecord &nextRec);
  CornerKind corner(const PathElem &a, const PathElem &b) const;
  void emitAtTool(MotionRecord o);  // a Z move at the tool's compensated XY

  MotionSink &out_;
  int side_ = 0;
  double r_ = 0;
  AxisVec tool_{};      // compensated tool position (end of what was emitted)
  bool entry_ = false;  // the next XY move is the entry move
  bool normalEntry_ = false;
  bool havePending_ = false;
  bool pendingEntry_ = false;  // the pending move is the entry move
  double feed_ = 0;             // of the last feed move (corner arcs are feed moves)
  MotionRecord pending_;
  PathElem pendingElem_;
  static constexpr size_t kMaxHeld = 64;
  std::vector<MotionRecord> held_;  // Z moves and dwells after the pending move
  bool afterZ_ = false;  // a Z move came after lastElem_, the last XY move emitted
  PathElem lastElem_;
  std::string errMsg_, errRule_;
};

}  // namespace ncc
