// FK free contour programming: the plane geometry of FL/FLT/FC/FCT elements, solved when the
// program is read. Each element's line or circle (its "carrier") must follow from its own data
// and its start point (when that is known); an element whose end its data leave open ends where
// the next element's carrier meets it. Every way the contour may go is kept (a hypothesis) until
// FSELECT picks one or the data rule the others out (docs/HEIDENHAIN.md "FK").
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace ncc::hei::fk {

struct Pt {
  double x = 0, y = 0;
};

// One FK block's data, all absolute and in the working plane (the parser converts polar values
// about FPOL). Optional words are absent when not written.
struct Data {
  bool arc = false;      // FC/FCT (else FL/FLT)
  bool tangent = false;  // FCT/FLT: tangent to the element before
  int dr = 0;            // FC: +1 counter-clockwise, -1 clockwise
  std::optional<double> x, y, len, an, r, cx, cy, d;
  std::optional<Pt> pd;      // PDX PDY: the point whose distance D from the element is given
  std::vector<Pt> through;   // P1…P3: points on the line or circle
};

// A line (a point on it and its unit direction; `fixed`: the direction of travel is known) or a
// circle (centre, radius, turn direction).
struct Carrier {
  bool arc = false;
  Pt p, d;
  bool fixed = false;
  Pt c;
  double r = 0;
  int dr = 0;
};

// A solved element: which FK element of the chain (its index), its carrier and end points.
struct Element {
  size_t index = 0;
  Carrier k;
  Pt start, end;
};

// One way the contour may go so far.
struct Hyp {
  std::vector<Element> done;     // solved elements not yet handed on
  std::optional<Element> open;   // the last element when its end is still free (end unset)
  Pt at;                         // … else where the contour stands
  std::optional<Pt> heading;     // … and its direction there (known after a line or FK element)
};

// The hypotheses element `index` with data `e` makes of `h`, in ncc's order (docs); none: `why`
// says what does not fit. `undetermined` is set when the element's carrier does not follow
// from its data (ncc does not look further ahead) or it is tangent to a direction not known.
std::vector<Hyp> extend(const Hyp &h, const Data &e, size_t index, std::string &why, bool &undetermined);

// Unit direction of travel at the end of a solved element.
Pt endHeading(const Element &e);

// Intersections used by the solver, exposed for tests. Line (p, unit d) with circle: ordered by
// the line parameter, farthest along d first. Circle with circle: the one left of c1→c2 first.
std::vector<Pt> lineCircle(Pt p, Pt d, Pt c, double r);
std::vector<Pt> circleCircle(Pt c1, double r1, Pt c2, double r2);

}  // namespace ncc::hei::fk
