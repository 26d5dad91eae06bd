// Lathe path pieces the Sinumerik turning cycles share (SinTurning.cpp: CYCLE951, CYCLE95;
// SinGroove.cpp: CYCLE930; SinUndercut.cpp: CYCLE940): a polyline with rounded or chamfered
// corners, and contour moves turned into cycle steps. Plane coordinates as Contour.h (G18: a = Z,
// b = X as a radius).
#pragma once
#include "runtime/cycles/Contour.h"
#include "runtime/cycles/Step.h"

#include <string>
#include <vector>

namespace ncc {

// A corner of a contour: a radius (tangent arc) or a chamfer (equal legs along both edges).
struct Round {
  double size = 0;
  bool chamfer = false;
};

// The length a corner takes from each of its two edges: a chamfer its size, a radius
// size * tan(turn / 2) for the turn between the unit directions din and dout (0 for no turn).
double roundLeg(const Round &r, Pt2 din, Pt2 dout);

// The polyline pts with corner i (1 … n-2) rounded by rounds[i]: lines and tangent arcs from
// pts[0] to pts.back(). Each corner takes its leg (roundLeg) from both edges; together they must
// fit each edge (else false with `err`).
bool roundedPath(const std::vector<Pt2> &pts, const std::vector<Round> &rounds, std::vector<ContourElem> &out,
                 std::string &err);

// The own frame of a groove (CYCLE930) or an undercut (CYCLE940): u along its width, v its
// depth from the surface (v = 0) into the material. Longitudinal: the width along Z, the depth
// along X; a face groove the other way round. su, sv: the directions of u and v on their axes.
struct GrooveFrame {
  bool face = false;
  int su = 1, sv = -1;
  double w0 = 0;  // u = 0 on the width axis (Z longitudinal, X radius face)
  double d0 = 0;  // v = 0 on the depth axis (X radius longitudinal, Z face)
  Pt2 at(Pt2 uv) const {
    const double w = w0 + su * uv.a, d = d0 + sv * uv.b;
    return face ? Pt2{d, w} : Pt2{w, d};
  }
  // An element of the frame, `du` further along u, in the plane; a reflection turns arcs.
  ContourElem toPlane(const ContourElem &e, double du) const {
    ContourElem p = e;
    p.end = at({e.end.a + du, e.end.b});
    if (e.kind == ContourKind::Arc) {
      p.centre = at({e.centre.a + du, e.centre.b});
      p.ccw = e.ccw != ((face ? -1 : 1) * su * sv < 0);
    }
    p.feed = 0;
    return p;
  }
  // The cycles' approach from the plane point `from` towards the frame point `to`: a rapid along
  // the depth axis to its level (none when there); the move across is the cycle's first.
  void approach(Pt2 from, Pt2 to, std::vector<ContourElem> &out) const;
};

// The cycle's steps from contour moves (ZX plane: a = Z, b = X, y the Y the steps keep):
// rapids, feeds at `feed` (0: the modal feed) split every `dam` of path with a dwell of `dt`
// seconds (chip breaking; 0: whole), arcs.
void contourSteps(const std::vector<ContourElem> &moves, Pt2 from, double y, double feed, double dam, double dt,
                  std::vector<CycleStep> &out);

}  // namespace ncc
