#include "runtime/cycles/Turning.h"

#include <algorithm>
#include <cmath>

namespace ncc {

namespace {

constexpr double kEps = 1e-9;

double at(const Pt2 &p, int axis) { return axis == 0 ? p.a : p.b; }
Pt2 make(int axis, double along, double across) {  // `along` on `axis`, `across` on the other
  return axis == 0 ? Pt2{along, across} : Pt2{across, along};
}
Pt2 plus(Pt2 p, Pt2 d) { return {p.a + d.a, p.b + d.b}; }

// Angles of an arc element from `from`: start angle and signed sweep (no full circles: a
// contour element that ends where it starts has no extent).
void arcAngles(const Pt2 &from, const ContourElem &e, double &a0, double &sweep) {
  a0 = std::atan2(from.b - e.centre.b, from.a - e.centre.a);
  double a1 = std::atan2(e.end.b - e.centre.b, e.end.a - e.centre.a);
  sweep = a1 - a0;
  if (e.ccw && sweep <= 0) sweep += 2 * M_PI;
  if (!e.ccw && sweep >= 0) sweep -= 2 * M_PI;
}

// Points along an element (both ends included), enough to check monotonicity of an arc.
std::vector<Pt2> samples(const Pt2 &from, const ContourElem &e) {
  if (e.kind != ContourKind::Arc) return {from, e.end};
  double a0, sweep;
  arcAngles(from, e, a0, sweep);
  double r = std::hypot(from.a - e.centre.a, from.b - e.centre.b);
  std::vector<Pt2> pts;
  const int n = 64;
  for (int i = 0; i <= n; ++i) {
    double t = a0 + sweep * i / n;
    pts.push_back(i == n ? e.end : Pt2{e.centre.a + r * std::cos(t), e.centre.b + r * std::sin(t)});
  }
  return pts;
}

// The first point of the element from `from` whose coordinate on `axis` is `v`, as the
// coordinate on the other axis; false when the element does not reach v.
bool crossing(const Pt2 &from, const ContourElem &e, int axis, double v, double &other) {
  const int o = 1 - axis;
  if (e.kind != ContourKind::Arc) {
    double s = at(from, axis), t = at(e.end, axis);
    if (std::fabs(t - s) < kEps) {
      if (std::fabs(v - s) > kEps) return false;
      other = at(from, o);
      return true;
    }
    double u = (v - s) / (t - s);
    if (u < -kEps || u > 1 + kEps) return false;
    other = at(from, o) + (at(e.end, o) - at(from, o)) * u;
    return true;
  }
  double a0, sweep;
  arcAngles(from, e, a0, sweep);
  double r = std::hypot(from.a - e.centre.a, from.b - e.centre.b);
  double k = (v - at(e.centre, axis)) / r;
  if (k < -1 - kEps || k > 1 + kEps) return false;
  k = std::clamp(k, -1.0, 1.0);
  // axis a: cos(t) = k; axis b: sin(t) = k.
  double base = axis == 0 ? std::acos(k) : std::asin(k);
  double cands[2] = {axis == 0 ? base : base, axis == 0 ? -base : M_PI - base};
  double best = -1;
  for (double t : cands) {
    double d = sweep > 0 ? t - a0 : a0 - t;  // distance along the sweep
    d = std::fmod(d, 2 * M_PI);
    if (d < -kEps) d += 2 * M_PI;
    if (d > std::fabs(sweep) + 1e-12) continue;
    if (best < 0 || d < best) {
      best = d;
      double ang = a0 + (sweep > 0 ? d : -d);
      other = at(e.centre, o) + r * (o == 0 ? std::cos(ang) : std::sin(ang));
    }
  }
  return best >= 0;
}

}  // namespace

ContourElem shifted(const ContourElem &e, Pt2 d) {
  ContourElem s = e;
  s.end = plus(e.end, d);
  s.centre = plus(e.centre, d);
  return s;
}

// Canonical view: p runs along the cut (the direction the contour A'-B progresses), q into the
// material (from C towards A'). Type I: along A'-B, p never decreases and q never increases.
bool stockRemoval(const Contour &c, const StockRemoval &s, std::vector<ContourElem> &out, std::string &err) {
  const int ca = s.cutAxis, da = 1 - s.cutAxis;
  if (s.depth <= 0) return err = "the depth of cut must be greater than 0", false;
  if (s.retract < 0) return err = "the retract amount must not be negative", false;
  if (c.elems.size() < 2) return err = "the contour needs at least two moves (to A' and on to B)", false;
  const ContourElem &first = c.elems.front();
  if (first.kind == ContourKind::Arc) return err = "the first contour block must be G00 or G01", false;
  if (std::fabs(at(first.end, ca) - at(c.start, ca)) > 1e-6)
    return err = std::string("the first contour block moves along ") + s.cutName +
                 ": type II contours (pockets) are not supported, only type I", false;
  const double sq = at(first.end, da) > at(c.start, da) ? 1 : -1;
  if (std::fabs(at(first.end, da) - at(c.start, da)) < 1e-6)
    return err = "the first contour block does not move across the layers (the start point is on the contour)", false;
  // The finished contour A'-B, shifted by the allowance.
  std::vector<ContourElem> prof;
  for (size_t i = 1; i < c.elems.size(); ++i) prof.push_back(shifted(c.elems[i], s.allowance));
  const Pt2 aOff = plus(first.end, s.allowance), bOff = prof.back().end;
  if (std::fabs(at(bOff, ca) - at(aOff, ca)) < 1e-6)
    return err = std::string("the contour from A' to B does not run along ") + s.cutName, false;
  const double sp = at(bOff, ca) > at(aOff, ca) ? 1 : -1;
  auto P = [&](const Pt2 &x) { return sp * at(x, ca); };
  auto Q = [&](const Pt2 &x) { return sq * at(x, da); };
  {
    Pt2 from = aOff;
    for (auto &e : prof) {
      std::vector<Pt2> pts = samples(from, e);
      for (size_t i = 1; i < pts.size(); ++i)
        if (P(pts[i]) < P(pts[i - 1]) - 1e-7 || Q(pts[i]) > Q(pts[i - 1]) + 1e-7)
          return err = "the contour from A' to B must be monotonic in both axes (type I)", false;
      from = e.end;
    }
  }
  const double pC = P(c.start), qC = Q(c.start), qA = Q(aOff);
  if (qC >= qA - kEps) return err = "the start point is not outside the contour's start A' (with the allowance)", false;
  if (P(bOff) <= pC + kEps) return err = "the contour (with the allowance) does not reach beyond the start point", false;
  auto point = [&](double p, double q) { return make(ca, sp * p, sq * q); };
  auto move = [&](ContourKind k, double p, double q) {
    ContourElem e;
    e.kind = k;
    e.end = point(p, q);
    out.push_back(e);
  };
  const ContourKind infeed = first.kind;  // G00 or G01 from C to A', so are the layer infeeds
  double qNow = qC;  // across the layers, where the tool is
  for (int k = 1;; ++k) {
    double q = qC + k * s.depth;
    if (q >= qA - kEps) break;
    // Where the layer meets the shifted contour: the first crossing of q after A'.
    double pEnd = P(bOff);
    Pt2 from = aOff;
    for (auto &e : prof) {
      double other = 0;
      if (crossing(from, e, da, sq * q, other)) {
        pEnd = sp * other;
        break;
      }
      from = e.end;
    }
    if (pEnd <= pC + kEps) continue;  // the contour is not beyond the start at this depth
    move(infeed, pC, q);
    move(ContourKind::Line, pEnd, q);
    double back = std::min(s.retract, pEnd - pC);
    move(ContourKind::Rapid, pEnd - back, q - s.retract);  // 45 degrees out of the material
    move(ContourKind::Rapid, pC, q - s.retract);
    qNow = q - s.retract;
  }
  // The pass along the shifted contour: to A' (across the layers as programmed, G00/G01; along
  // the cut by the allowance first when that is backwards, else after), then A'-B at feed.
  if (P(aOff) < pC) {
    move(ContourKind::Rapid, P(aOff), qNow);
    move(infeed, P(aOff), qA);
  } else {
    move(infeed, pC, qA);
    move(infeed, P(aOff), qA);
  }
  for (auto &e : prof) {
    ContourElem m = e;
    m.feed = 0;
    out.push_back(m);
  }
  // Out of the material across the layers, back along the cut, to C.
  double qOut = std::min(qC, Q(bOff)) - s.retract;
  move(ContourKind::Rapid, P(bOff), qOut);
  move(ContourKind::Rapid, pC, qOut);
  move(ContourKind::Rapid, pC, qC);
  // Drop moves of no length (an allowance of 0 or a retract of 0 repeat points).
  std::vector<ContourElem> kept;
  Pt2 pos = c.start;
  for (auto &e : out) {
    if (e.kind != ContourKind::Arc && std::fabs(e.end.a - pos.a) < kEps && std::fabs(e.end.b - pos.b) < kEps) continue;
    kept.push_back(e);
    pos = e.end;
  }
  out = std::move(kept);
  return true;
}

bool patternRepeat(const Contour &c, const PatternRepeat &s, std::vector<ContourElem> &out, std::string &err) {
  if (s.count < 1) return err = "the number of divisions must be at least 1", false;
  if (c.elems.empty()) return err = "the contour has no moves", false;
  for (int j = 1; j <= s.count; ++j) {
    double f = s.count == 1 ? 0.0 : double(s.count - j) / (s.count - 1);
    Pt2 d = {s.allowance.a + s.relief.a * f, s.allowance.b + s.relief.b * f};
    for (auto &e : c.elems) {
      ContourElem m = shifted(e, d);
      m.feed = 0;
      out.push_back(m);
    }
    ContourElem back;
    back.kind = ContourKind::Rapid;
    back.end = c.start;
    out.push_back(back);
  }
  return true;
}

}  // namespace ncc
