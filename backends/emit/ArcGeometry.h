// Plane geometry for arc output: which words describe an arc so that the controller, reading
// the rounded numbers back, gets the same arc within the machine's arc tolerance.
#pragma once
#include "backends/emit/WordFormat.h"
#include "ir/MotionIR.h"

namespace ncc::emit {

// Machine axis indices of a plane: first and second in-plane axes (counter-clockwise from first
// to second as seen from the positive normal) and the normal (helix) axis.
struct PlaneAxes {
  int a, b, normal;
};
PlaneAxes planeAxes(Plane p);

// Angle swept from s to e around c, in (0, 2*pi]; equal points sweep a full turn.
double sweepAngle(const double s[2], const double e[2], const double c[2], bool ccw);

struct ArcWords {
  double offset[2] = {0, 0};  // centre minus start (rounded to the centre format), in-plane
  bool useRadius = false;
  double radius = 0;          // signed radius (negative: more than 180 degrees), rounded
};

// s and e are the rounded start and end (in-plane), c the exact centre. The offsets keep the
// exact centre unless the two rounded ends then differ in radius by more than 3/4 of
// `tolerance` (the controller's arc check); then the centre moves towards the perpendicular
// bisector of the rounded chord just enough. Of the output-grid points next to that centre the
// one with the best radius agreement is written. With preferRadius, the R form is used when the
// centre a controller rebuilds from the rounded R is within tolerance/4 of the exact centre and
// the arc is not a full circle.
ArcWords planArc(const double s[2], const double e[2], const double c[2], bool ccw, bool fullCircle,
                 bool preferRadius, const NumberFormat &centerFormat, double tolerance);

}  // namespace ncc::emit
