// The stud engine (Stud.h): laps round a stud from the blank inward (Heidenhain 256-258,
// Sinumerik CYCLE76, CYCLE77, CYCLE79).
#include "runtime/cycles/Stud.h"

#include <algorithm>
#include <cmath>

namespace ncc::entry {

Contour rectLap(const StudShape &s, double d) { return roundedRect(s.a + d, s.b + d, s.rc + d); }
Contour circleLap(const StudShape &s, double d) { return circleContour(s.a + d); }

Contour polygonLap(const StudShape &s, double d) {
  const int n = s.corners;
  const double rho = s.rc + d, circum = (s.a - s.rc) / std::cos(M_PI / n);  // the rounding centres'
  auto polar = [](double r, double t) { return PlanePoint{r * std::cos(t), r * std::sin(t)}; };
  Contour c;
  c.start = {s.a - s.rc + rho, 0};
  for (int k = 0; k < n; ++k) {
    const PlanePoint centre = polar(circum, M_PI / n + k * 2 * M_PI / n);
    const PlanePoint from = polar(rho, k * 2 * M_PI / n), to = polar(rho, (k + 1) * 2 * M_PI / n);
    c.segs.push_back({{centre[0] + from[0], centre[1] + from[1]}, false, {}, true});
    c.segs.push_back({{centre[0] + to[0], centre[1] + to[1]}, true, centre, true});
  }
  c.segs.push_back({c.start, false, {}, true});
  return c;
}

double rectReach(const StudShape &s, double ba, double bb) {
  const double qx = ba - (s.a - s.rc), qy = bb - (s.b - s.rc);
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) - s.rc;
}

namespace {

// The laps' tool-centre distances from the stud, outermost first: the innermost leaves
// `allowance`, the outermost reaches the blank's farthest point, evenly at most a stepover apart
// (seed002a L7034-7081: further laps "with constant lateral step").
std::vector<double> lapOffsets(const MillJob &m, const StudShape &s, double allowance) {
  const double inner = m.r + allowance, outer = std::max(inner, s.reach - m.r);
  int n = (int)std::ceil((outer - inner) / m.stepover - 1e-9);
  std::vector<double> out;
  for (int k = n; k > 0; --k) out.push_back(inner + (outer - inner) * k / n);
  out.push_back(inner);
  return out;
}

}  // namespace

// [model] The moves onto the laps and back out are straight and radial, the laps concentric.
void millStud(const MillJob &m, const StudShape &s, Mill &mill) {
  const bool ccw = !m.ccw;  // climb milling on an outer wall runs clockwise with M3
  const double roughDepth = m.depth - m.floorAllowance;
  auto laps = [&](double level, double allowance, double f) {
    for (double d : lapOffsets(m, s, allowance)) {
      Contour lap = s.lap(s, d);
      mill.feed(lap.start, level, f);
      mill.run(lap, ccw, level, f);
    }
    mill.feed(s.approach, level, f);
  };
  if (m.roughing()) {
    mill.go(s.approach, m.lv.zsc);
    for (double t : infeeds(m.infeed, roughDepth)) {
      mill.feed(s.approach, m.level(t), m.plungeFeed);
      laps(m.level(t), m.sideAllowance, m.millFeed);
    }
  }
  if (m.wallPass)
    finishWalls(m, {s.lap(s, m.r), {1, 0}, m.sideAllowance + m.clearance, false}, ccw, mill);
  if (m.floorPass) {
    mill.go(s.approach, m.level(roughDepth - m.clearance));
    mill.feed(s.approach, m.level(m.depth), m.plungeFeed);
    laps(m.level(m.depth), 0, m.finishFeed);
  }
  mill.up(m.lv.z2);
}

}  // namespace ncc::entry
