// Plane geometry of the Sinumerik contour functions (SIN-CON-03, -05; docs/SINUMERIK.md "Contour
// tables"), shared by both engines as the builtins SIN_INTERSEC and SIN_CALCDAT (ir/Builtins.cpp)
// and by the executor's tables.
#pragma once

namespace ncc {

// A contour element in plane coordinates (abscissa, ordinate): a line, or an arc about the
// centre (clockwise or counter-clockwise) from the start to the end (start == end: a full circle).
struct ContourElement {
  int kind = 1;  // 0 G0, 1 G1 (lines), 2 G2, 3 G3 (arcs)
  double xs = 0, ys = 0, xe = 0, ye = 0, cx = 0, cy = 0;
};
// The point where two elements meet (each bounded by its start and end); when they meet twice,
// the one reached first along `a`. False when they do not meet in one point (parallel or
// overlapping lines, concentric arcs count as not meeting).
bool intersectElements(const ContourElement &a, const ContourElement &b, double &x, double &y);
// The circle through three points; false when two coincide or they lie on a line.
bool circleThrough(const double p[3][2], double &cx, double &cy, double &r);
// CALCDAT: three points, or four (the four triples' centres averaged, the radius the root of
// the sum of the squared radii times 0.5: docs/SINUMERIK.md); false as circleThrough is for any triple.
bool circleOfPoints(const double (*p)[2], int n, double &cx, double &cy, double &r);

extern "C" {
// SIN_INTERSEC(k, mode, code1, xs1, ys1, xe1, ye1, cx1, cy1, code2, …): k 0 the abscissa, 1 the
// ordinate, 2 the status (1 found, 0 not); NaN for a mode other than 0/1 or a code that is no
// element (its last digit 0-3).
double ncc_builtin_sin_intersec(const double *a);
// SIN_CALCDAT(k, n, x1, y1, … xn, yn): k 0/1 the centre, 2 the radius, 3 the status (1/0).
double ncc_builtin_sin_calcdat(const double *a);
}

}  // namespace ncc
