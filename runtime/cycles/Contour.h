// A captured contour (runtime/ExecutorContour.cpp): the path of a block range that ran into a
// capture instead of the machine, as lines and arcs in the coordinates of the active plane, for
// the consumers that work from a contour (ISO G70-G73, runtime/cycles/Turning.h; Sinumerik
// CYCLE95, SinTurning.cpp, through `use=keep`; Heidenhain SL cycles). Plane coordinates: `a` is the plane's first axis,
// `b` its second (G17: X Y, G18: Z X, G19: Y Z), mm in the executor's offset frame (the machine
// frame while only translations are active; a diameter-programmed X is a radius here).
#pragma once
#include "ir/Diagnostics.h"

#include <cstdint>
#include <vector>

namespace ncc {

struct Pt2 {
  double a = 0, b = 0;
};

enum class ContourKind : uint8_t { Rapid, Line, Arc };

// One element from the previous element's end (or the contour's start) to `end`. Arcs turn
// counter-clockwise in (a, b) when `ccw` (G18: a = Z, b = X, so G3 seen from +Y). `feed` is the
// captured element's rate (mm/min, 0 for rapids); a consumer's own moves use 0: the modal feed.
struct ContourElem {
  ContourKind kind = ContourKind::Line;
  Pt2 end;
  Pt2 centre;
  bool ccw = false;
  double feed = 0;
  SourceLoc loc;
};

struct Contour {
  Pt2 start;  // where the tool stood when the capture began
  std::vector<ContourElem> elems;
};

// The contour a library cycle cuts from (CycleContext::contour, Sinumerik CYCLE95): a type of its
// own for Library.h, whose users may also see the milling paths' Contour (Mill.h).
struct CycleContour {
  Contour contour;
};

}  // namespace ncc
