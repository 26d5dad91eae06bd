#include "runtime/cycles/Grooving.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
constexpr double kMaxMoves = 1e6;  // a runaway cycle (a tiny peck over a long way) is an error
constexpr double kEps = 1e-9;      // mm: a remainder below this is the end point itself

double sign(double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }
}  // namespace

bool peckGrooves(const PeckGroove &g, std::vector<ContourElem> &out, std::string &err) {
  const double depth = std::fabs(g.end.a - g.start.a), width = std::fabs(g.end.b - g.start.b);
  if (depth <= kEps) return err = "the end point has no depth along the pecks (it is the start's)", false;
  if (!(g.peck > 0)) return err = "the depth per peck must be greater than 0", false;
  if (width > kEps && !(g.shift > 0)) return err = "the shift between grooves must be greater than 0", false;
  if (g.retract < 0 || g.relief < 0) return err = "the retract and the relief must not be negative", false;
  const double grooves = width > kEps ? std::ceil(width / g.shift - kEps) + 1 : 1;
  const double pecks = std::ceil(depth / g.peck - kEps);
  if (grooves * (2 * pecks + 3) > kMaxMoves)
    return err = fmt::format("the cycle would make about {:.0f} moves ({:.0f} grooves of {:.0f} pecks)",
                             grooves * (2 * pecks + 3), grooves, pecks), false;
  const double sa = sign(g.end.a - g.start.a), sb = sign(g.end.b - g.start.b);
  auto move = [&](ContourKind k, double a, double b) {
    ContourElem e;
    e.kind = k, e.end = {a, b};
    out.push_back(e);
  };
  Pt2 at = g.start;
  auto go = [&](ContourKind k, double a, double b) {
    if (a == at.a && b == at.b) return;
    move(k, a, b), at = {a, b};
  };
  for (double k = 0; k < grooves; ++k) {
    const double b = k + 1 >= grooves ? g.end.b : g.start.b + sb * k * g.shift;
    go(ContourKind::Rapid, g.start.a, b);  // across to the groove (nothing for the first)
    for (double reached = g.start.a;;) {
      double next = reached + sa * g.peck;
      if (sa * (next - g.end.a) >= -kEps) next = g.end.a;
      go(ContourKind::Line, next, b);
      if (next == g.end.a) break;
      double back = next - sa * g.retract;
      if (sa * (back - g.start.a) < 0) back = g.start.a;
      go(ContourKind::Rapid, back, b);
      reached = next;
    }
    double relieved = b;
    if (k > 0 && g.relief > 0) {
      relieved = b - sb * g.relief;
      if (sb * (relieved - g.start.b) < 0) relieved = g.start.b;
    }
    go(ContourKind::Rapid, g.end.a, relieved);
    go(ContourKind::Rapid, g.start.a, relieved);
  }
  go(ContourKind::Rapid, g.start.a, g.start.b);
  return true;
}

}  // namespace ncc
