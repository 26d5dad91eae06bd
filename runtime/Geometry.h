// Move geometry shared by the planner, the samplers and the plot: lengths, arc sweep, points
// and tangents along a move. Arcs are circular in their plane (G17 XY, G18 ZX, G19 YZ, or a
// tilted plane given by its normal) with an optional linear (helical) component along the normal; rotary axes and any other axis
// move linearly with the arc parameter. A start/end radius mismatch (within arc_tolerance) is
// absorbed by letting the radius vary linearly along the sweep (a short spiral).
#pragma once
#include "ir/MotionIR.h"

#include <array>
#include <vector>

namespace ncc {

using Vec3 = std::array<double, 3>;

// Indices of the plane's first axis, second axis and normal (helix) axis, chosen so that a
// positive angle is counter-clockwise seen from the positive normal (right-handed):
// XY -> (X, Y, Z), ZX -> (Z, X, Y), YZ -> (Y, Z, X).
struct PlaneAxes {
  int u, v, n;
};
PlaneAxes planeAxes(Plane p);

// sin and cos of an angle in degrees, exact at multiples of 90 degrees (a G68 R90 maps X10 to
// Y10, not to Y10 plus 6e-16; a hole at 90 degrees has X exactly on the centre).
void sinCosDegrees(double degrees, double &s, double &c);
double dot(const Vec3 &a, const Vec3 &b);
Vec3 cross(const Vec3 &a, const Vec3 &b);

// The plane of an arc in a tilted plane (MotionRecord::tiltedArc): plane coordinates are taken
// along the orthonormal frame u (centre to start), v = n x u, n (the normal), about the centre
// `c`; `n0` is the start's height above the centre.
struct TiltedFrame {
  Vec3 c{}, u{}, v{}, n{};
  double n0 = 0;
};

struct ArcGeometry {
  PlaneAxes ax{0, 1, 2};       // principal planes: the axes; unused when tilted
  // Tilted plane: its frame (then cu = cv = 0 and startAngle = 0). Null, so no cost in size or
  // copies, for the principal planes.
  CopyPtr<TiltedFrame> tilted;
  double cu = 0, cv = 0;       // centre in plane coordinates
  double r0 = 0, r1 = 0;       // start and end radius
  double startAngle = 0;       // radians, atan2(v - cv, u - cu) at the start
  double sweep = 0;            // signed radians, + counter-clockwise, includes full turns
  double helix = 0;            // travel along the normal axis
  double length = 0;           // path length in mm (linear axes XYZ)
};

// Sweep from start/end/centre/turns: turns > 0 counter-clockwise, < 0 clockwise, |turns| - 1
// extra full turns (0 is read as 1). Start == end gives a full circle.
ArcGeometry arcGeometry(const AxisVec &start, const AxisVec &end, const Vec3 &center, Plane plane,
                        int turns);
// The same about a unit normal in any direction (turns > 0: counter-clockwise seen from its tip).
ArcGeometry tiltedArcGeometry(const AxisVec &start, const AxisVec &end, const Vec3 &center, const Vec3 &normal,
                              int turns);
// Either, as the record says (a tilted arc when it has a normal of its own).
ArcGeometry arcGeometry(const MotionRecord &r);
// How much of the path speed axis i (0..2) can carry on the arc at most, per unit of path
// speed: planar part on the plane axes plus the helix part on the normal.
Vec3 arcAxisShare(const ArcGeometry &g);

// Length of a straight move: the XYZ distance, or, for a rotary-only move, the rotary distance
// (degrees) so that feed-rate timing stays meaningful.
double linearLength(const AxisVec &start, const AxisVec &end);

// rs274 (2.9): an R-form arc whose radius falls short of half the chord by more than this is
// "Arc radius too small to reach end point"; less, and it runs as a half circle. Measured on
// rs274 in both units: 0.0012 mm and 0.00005 inch (0.00127 mm) pass, 0.0013 mm and 0.00006 inch
// fail. Used by the executor and by lint's static check.
constexpr double kArcRadiusSlackMM = 0.00128;

// RS274NGC polar coordinates (`@` radius, `^` angle in degrees) about the program origin: moves
// the point (x, y), given relative to that origin. Absolute: a missing word keeps the point's
// own radius or angle; incremental: the words are added to them (rs274's find_ends).
void polarStep(double &x, double &y, bool incremental, bool hasRadius, double radius, bool hasAngle,
               double degrees);

// Point at parameter s in [0, 1] (fraction of the sweep, which is also the fraction of length).
AxisVec arcPoint(const ArcGeometry &g, const AxisVec &start, const AxisVec &end, double s);
// Unit tangent (XYZ) in the direction of travel at parameter s.
Vec3 arcTangent(const ArcGeometry &g, double s);
// Curvature (1/mm) of the helix, using the mean radius: r / (r^2 + c^2), c = helix / sweep.
double arcCurvature(const ArcGeometry &g);
// Axis-aligned bounds of the arc (XYZ), exact for circular arcs (quadrant crossings included).
void arcBounds(const ArcGeometry &g, const AxisVec &start, const AxisVec &end, Vec3 &lo, Vec3 &hi);

// The curve of a Spline record (ir/MotionIR.h SplineData), evaluated by de Boor's algorithm on
// homogeneous control points (exact for NURBS).
class SplineCurve {
public:
  explicit SplineCurve(const MotionRecord &r);
  double u0() const { return knots_.front(); }
  double u1() const { return knots_.back(); }
  Vec3 at(double u) const;
  // Calls out(p, u) for points p = at(u) along the curve after the start (the last one exactly
  // the record's end) such that no chord strays more than `tol` from the curve (checked at the quarter points
  // of every chord, spans split at least 4 times and at most 2^14 times, and at most 2^16 chords
  // in all, which bounds the work and memory for absurd curves).
  template <class F> void flatten(double tol, F &&out) const {
    for (size_t k = 0; k + 1 < knots_.size(); ++k) {
      double a = knots_[k], b = knots_[k + 1];
      if (!(b > a)) continue;
      Vec3 p = at(a);
      for (int i = 1; i <= 4; ++i) {
        double u = a + (b - a) * i / 4;
        Vec3 q = at(u);
        refine(a + (b - a) * (i - 1) / 4, p, u, q, tol, 0, out);
        p = q;
      }
    }
  }

private:
  template <class F> void refine(double ua, const Vec3 &pa, double ub, const Vec3 &pb, double tol, int depth, F &out) const {
    double um = 0.5 * (ua + ub);
    if (depth < maxDepth_ && chordError(ua, pa, ub, pb) > tol) {
      Vec3 pm = at(um);
      refine(ua, pa, um, pm, tol, depth + 1, out);
      refine(um, pm, ub, pb, tol, depth + 1, out);
      return;
    }
    out(ub >= u1() ? end_ : pb, ub);
  }
  double chordError(double ua, const Vec3 &pa, double ub, const Vec3 &pb) const;
  int degree_;
  std::vector<std::array<double, 4>> cp_;  // w*x, w*y, w*z, w
  std::vector<double> knots_;
  Vec3 end_;
  int maxDepth_ = 12;  // halvings of each quarter span
};
// A spline as the planner moves along it: its chords within kSplineTolerance, by arc length.
struct SplinePath {
  std::vector<Vec3> pts;     // the start, then the chords' ends (the last one the record's end)
  std::vector<double> cum;   // curve length at each point (cum[0] = 0): each chord's arc by
                             // Richardson on its halves, so the length is exact to O(chord^5)
  Vec3 share{};              // the largest |direction component| of any chord, per axis
  double maxCurvature = 0;   // 1/mm: the largest 2 sin(turn / 2) / mean chord length at a joint
  double length() const { return cum.back(); }
  Vec3 at(double s) const;   // the point at path length s (clamped)
  Vec3 startTangent() const, endTangent() const;  // unit, along the first and the last chord
};
SplinePath splinePath(const MotionRecord &r);
// Chord tolerance of the flattened curve wherever a spline is sampled (planner, summary, plot).
constexpr double kSplineTolerance = 0.001;  // mm
// Length of a spline record's curve (splinePath's).
double splineLength(const MotionRecord &r);
// Axis-aligned bounds (XYZ) of a spline's curve (its flattening).
void splineBounds(const MotionRecord &r, Vec3 &lo, Vec3 &hi);

// Unit direction of a straight move in the 6-axis space the planner limits (XYZ in mm, rotary
// in degrees, scaled by the move length); zero for zero-length moves.
AxisVec unitDirection(const AxisVec &start, const AxisVec &end, double length);

}  // namespace ncc
