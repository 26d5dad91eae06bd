// Milling paths of the clearing entries (Pocket.h and the entry files) in an element's own frame: a
// contour as lines and exact arcs, and a writer that places local points (the element's centre
// at the origin, its first axis along x) in the working plane, rotated about the origin, and
// appends CycleSteps at levels on the tool axis.
#pragma once
#include "runtime/cycles/Clearing.h"
#include "runtime/cycles/Step.h"

#include <vector>

namespace ncc {

// A closed tool path from `start`: lines and arcs (PathSeg, Clearing.h), each to its `end`; the
// last ends at `start`.
struct Contour {
  PlanePoint start{};
  std::vector<PathSeg> segs;
};

// A rectangle of half-sides a x b about the origin with corners rounded by rc (0 <= rc <=
// min(a, b)), counter-clockwise from the middle of the +x side (a, 0).
Contour roundedRect(double a, double b, double rc);
// A circle of radius r about the origin, counter-clockwise from (r, 0).
Contour circleContour(double r);
// The contour turned half a turn about the origin (a rounded rectangle then starts at (-a, 0)).
Contour halfTurn(Contour c);
// The contour as a polygon within `tol` of it that takes in nothing beyond it (the region lies
// left of the contour): chords inside counter-clockwise arcs, tangents outside clockwise ones.
Polygon contourPolygon(const Contour &c, double tol);
// The turn of arc segment `s` from `from` in its direction, (0, 2 pi] (an end on the start: a
// full turn).
double arcSweep(PlanePoint from, const PathSeg &s);

class Mill {
public:
  // `dir`: the sign of the tool-axis direction into the material (levels deeper have
  // (level - surface) * dir > 0).
  Mill(std::vector<CycleStep> &out, int plane, PlanePoint origin, double degrees, double dir, std::array<double, 3> at);
  void rapid(PlanePoint p, double level);
  void feed(PlanePoint p, double level, double f);
  // `turns` > 1: whole extra turns (a helix down).
  void arc(PlanePoint end, PlanePoint centre, bool ccw, double level, double f, int turns = 1);
  // Rapid to p at `level` without a diagonal through material: up first, across, then down.
  void go(PlanePoint p, double level);
  // Rapid along the tool axis to `level` where the tool is (nothing when it is there).
  void up(double level) {
    if (level != level_) rapid(here_, level);
  }
  // Once round a contour at `level` (reversed when !ccw: the same track the other way).
  void run(const Contour &c, bool ccw, double level, double f);
  // Round a clearing ring at `level`, starting at its corner nearest the tool, linked there at
  // the feed (clockwise when !ccw).
  void ring(const Polygon &p, bool ccw, double level, double f);
  // The corner of `p` nearest the tool, where ring() starts.
  PlanePoint ringStart(const Polygon &p) const;
  PlanePoint here() const { return here_; }
  double level() const { return level_; }
  // Rapid to a position in program coordinates (the call position), up first.
  void goProgram(const std::array<double, 3> &p);

private:
  std::array<double, 3> place(PlanePoint p, double level) const;
  void step(CycleStepKind k, PlanePoint p, double level, double f);
  std::vector<CycleStep> &out_;
  int u_, v_, n_;
  PlanePoint origin_;
  double c_, s_, dir_;
  PlanePoint here_{};
  double level_ = 0;
};

}  // namespace ncc
