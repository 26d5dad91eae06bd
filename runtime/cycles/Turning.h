// Turning cycles that work from a captured contour (runtime/cycles/Contour.h): stock removal in
// layers (ISO G71 along Z, G72 along X) and pattern repeating (G73). Pure geometry: the executor
// (runtime/ExecutorContour.cpp) captures the contour and emits the moves these return.
#pragma once
#include "runtime/cycles/Contour.h"

#include <cmath>
#include <string>

namespace ncc {

// Stock removal, type I: the contour's first element moves from the start point C only across
// the layers (to A'), the rest (A' to B) is monotonic in both axes. Type II: see `typeII`. Layers parallel to the cut
// axis, `depth` apart, from C towards A', each cut until it meets the contour A'-B shifted by
// `allowance`; each layer retracts by `retract` at 45 degrees and returns at rapid. Then one pass
// along the shifted contour, and back to C.
struct StockRemoval {
  int cutAxis = 0;   // 0: layers along the plane's first axis (G18: Z, G71), 1: its second (X, G72)
  double depth = 0;  // layer depth (mm, > 0)
  double retract = 0;
  Pt2 allowance;     // finishing allowance, signed as programmed (the shift of the contour)
  const char *cutName = "the cut axis";  // for messages ("Z")
  // Type II (the first contour block names both axes): the contour may have pockets across the
  // layers (not monotonic in the other axis); it must still run one way along the cut.
  bool typeII = false;
  // The level the layers count from, on the axis across the layers (plane coordinates): the
  // layers lie `depth`, 2 `depth` … beyond it. NaN: the start point's level (ISO G71/G72).
  // Sinumerik CYCLE95 counts from the contour's top so that equal layers end on its bottom.
  double layersFrom = std::nan("");
};
bool stockRemoval(const Contour &c, const StockRemoval &s, std::vector<ContourElem> &out, std::string &err);

// Pattern repeating: the contour `count` times, the first shifted by relief + allowance, each
// next one closer by relief / (count - 1), the last by the allowance; rapid back to C after each.
struct PatternRepeat {
  Pt2 relief;
  Pt2 allowance;
  int count = 1;
};
bool patternRepeat(const Contour &c, const PatternRepeat &s, std::vector<ContourElem> &out, std::string &err);

// The contour shifted by d (arcs keep their radius: their centres shift too).
ContourElem shifted(const ContourElem &e, Pt2 d);

}  // namespace ncc
