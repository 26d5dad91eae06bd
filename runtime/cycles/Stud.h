// The stud (spigot) engine the Heidenhain (256-258, ClearingEntries.cpp) and Sinumerik (CYCLE76,
// CYCLE77, CYCLE79, SinSpigotEntries.cpp) entries share: laps round the stud from the blank
// inward, level by level, then the wall and the floor (docs/CYCLES.md "Heidenhain studs").
#pragma once
#include "runtime/cycles/Pocket.h"

#include <vector>

namespace ncc::entry {

// The stud in its own frame: its outline offset outward by d (a tool-centre lap, counter-clockwise
// from the +x side), how far from the stud the blank reaches at most, and the approach point.
struct StudShape {
  Contour (*lap)(const StudShape &, double d);
  double a = 0, b = 0, rc = 0;  // half sides and corner radius (a circle: a = b = rc = radius;
                                // a polygon: a = the apothem)
  double reach = 0;
  PlanePoint approach{};
  int corners = 0;              // a regular polygon's
};
Contour rectLap(const StudShape &s, double d);
Contour circleLap(const StudShape &s, double d);
// A regular polygon (apothem a, corners rounded by rc) offset by d, its first side's outward
// normal along +x: from that side's middle, each side then the arc round the next corner.
Contour polygonLap(const StudShape &s, double d);

// How far a rectangular blank (half sides ba x bb) reaches beyond the rounded stud s at most:
// from its corner.
double rectReach(const StudShape &s, double ba, double bb);

// Each level from the approach point outside the blank (plunge there at the plunge feed), in to
// the outermost lap, the laps inward at the milling feed, back out to the approach point; then the
// wall (finishWalls, from outside) and the floor; the end at m.lv.z2 there.
void millStud(const MillJob &m, const StudShape &s, Mill &mill);

}  // namespace ncc::entry
