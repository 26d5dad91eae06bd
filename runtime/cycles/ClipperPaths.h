// Polygons to and from Clipper's integer paths (the clearing code, region pockets and their
// tests): 1e-6 mm resolution keeps rounding far below any machine's.
#pragma once
#include "runtime/cycles/Clearing.h"

#include <polyclipping/clipper.hpp>

#include <cmath>

namespace ncc {

constexpr double kClipperScale = 1e6;

inline ClipperLib::IntPoint toClipper(PlanePoint q) {
  return {(ClipperLib::cInt)std::llround(q[0] * kClipperScale), (ClipperLib::cInt)std::llround(q[1] * kClipperScale)};
}

inline ClipperLib::Path toPath(const Polygon &p) {
  ClipperLib::Path out;
  for (auto &q : p) out.push_back(toClipper(q));
  return out;
}

// A boolean of two path sets, each filled by the non-zero rule (the region pockets, the contour
// formulas).
inline ClipperLib::Paths clipPaths(ClipperLib::ClipType op, const ClipperLib::Paths &a, const ClipperLib::Paths &b) {
  ClipperLib::Clipper c;
  c.AddPaths(a, ClipperLib::ptSubject, true);
  c.AddPaths(b, ClipperLib::ptClip, true);
  ClipperLib::Paths out;
  c.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

inline Polygon fromPath(const ClipperLib::Path &p) {
  Polygon out;
  for (auto &q : p) out.push_back({q.X / kClipperScale, q.Y / kClipperScale});
  return out;
}

}  // namespace ncc
