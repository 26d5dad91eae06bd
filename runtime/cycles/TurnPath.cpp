#include "runtime/cycles/TurnPath.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
Pt2 minus(Pt2 p, Pt2 q) { return {p.a - q.a, p.b - q.b}; }
Pt2 along(Pt2 p, Pt2 d, double t) { return {p.a + d.a * t, p.b + d.b * t}; }
double length(Pt2 d) { return std::hypot(d.a, d.b); }
Pt2 unit(Pt2 d) {
  const double l = length(d);
  return {d.a / l, d.b / l};
}
}  // namespace

void GrooveFrame::approach(Pt2 from, Pt2 to, std::vector<ContourElem> &out) const {
  const Pt2 target = at(to);
  ContourElem e;
  e.kind = ContourKind::Rapid;
  e.end = face ? Pt2{target.a, from.b} : Pt2{from.a, target.b};
  if (std::fabs(e.end.a - from.a) > 1e-9 || std::fabs(e.end.b - from.b) > 1e-9) out.push_back(e);
}

double roundLeg(const Round &r, Pt2 din, Pt2 dout) {
  if (r.size <= 0) return 0;
  const double turn = std::acos(std::clamp(din.a * dout.a + din.b * dout.b, -1.0, 1.0));
  if (turn < 1e-9) return 0;  // a straight point has no corner to round
  return r.chamfer ? r.size : r.size * std::tan(turn / 2);
}

bool roundedPath(const std::vector<Pt2> &pts, const std::vector<Round> &rounds, std::vector<ContourElem> &out,
                 std::string &err) {
  const size_t n = pts.size();
  std::vector<double> cut(n, 0.0);  // the length taken from each side of corner i
  for (size_t i = 1; i + 1 < n; ++i)
    cut[i] = roundLeg(rounds[i], unit(minus(pts[i], pts[i - 1])), unit(minus(pts[i + 1], pts[i])));
  for (size_t i = 0; i + 1 < n; ++i)
    if (cut[i] + cut[i + 1] > length(minus(pts[i + 1], pts[i])) + 1e-7) {
      err = fmt::format("a radius or chamfer does not fit its edge (edge length {:g})", length(minus(pts[i + 1], pts[i])));
      return false;
    }
  auto line = [&](Pt2 to) {
    ContourElem e;
    e.end = to;
    out.push_back(e);
  };
  for (size_t i = 1; i < n; ++i) {
    const Pt2 din = unit(minus(pts[i], pts[i - 1]));
    if (cut[i] <= 0 || i + 1 == n) {
      line(pts[i]);
      continue;
    }
    const Pt2 dout = unit(minus(pts[i + 1], pts[i]));
    const Pt2 t1 = along(pts[i], din, -cut[i]), t2 = along(pts[i], dout, cut[i]);
    line(t1);
    if (rounds[i].chamfer) {
      line(t2);
      continue;
    }
    // The centre lies on the inner side of the turn, a radius from the first tangent point.
    const bool left = din.a * dout.b - din.b * dout.a > 0;
    const Pt2 normal = left ? Pt2{-din.b, din.a} : Pt2{din.b, -din.a};
    ContourElem arc;
    arc.kind = ContourKind::Arc;
    arc.end = t2;
    arc.centre = along(t1, normal, rounds[i].size);
    arc.ccw = left;
    out.push_back(arc);
  }
  return true;
}

void contourSteps(const std::vector<ContourElem> &moves, Pt2 from, double y, double feed, double dam, double dt,
                  std::vector<CycleStep> &out) {
  for (const ContourElem &e : moves) {
    CycleStep st;
    st.pos = {e.end.b, y, e.end.a};
    if (e.kind == ContourKind::Rapid) {
      out.push_back(st);
    } else if (e.kind == ContourKind::Arc) {
      st.kind = CycleStepKind::Arc, st.feed = feed;
      st.centre = {e.centre.b, y, e.centre.a};
      st.ccw = e.ccw;
      out.push_back(st);
    } else {
      const double len = std::hypot(e.end.a - from.a, e.end.b - from.b);
      const int pieces = dam > 0 ? std::max(1, (int)std::ceil(len / dam - 1e-9)) : 1;
      for (int i = 1; i <= pieces; ++i) {
        CycleStep f;
        f.kind = CycleStepKind::Feed, f.feed = feed;
        const double t = (double)i / pieces;
        f.pos = {from.b + (e.end.b - from.b) * t, y, from.a + (e.end.a - from.a) * t};
        out.push_back(f);
        if (i < pieces && dt > 0) {
          CycleStep d;
          d.kind = CycleStepKind::Dwell, d.seconds = dt;
          out.push_back(d);
        }
      }
    }
    from = e.end;
  }
}

}  // namespace ncc
