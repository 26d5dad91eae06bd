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
// Type II (pockets): p never decreases, q may go both ways; a layer then cuts every stretch where
// the contour lies deeper than the layer, pockets from above (docs/CYCLES.md [model]).
namespace {

// The shifted contour A'-B in the canonical view, with what the layers need of it.
struct Profile {
  const std::vector<ContourElem> &elems;
  Pt2 start;  // A' shifted
  int ca, da;
  double sp, sq;
  double P(const Pt2 &x) const { return sp * at(x, ca); }
  double Q(const Pt2 &x) const { return sq * at(x, da); }
  // q of the contour at p (the first element reaching p).
  double qAt(double p) const {
    Pt2 from = start;
    for (auto &e : elems) {
      double other = 0;
      if (crossing(from, e, ca, sp * p, other)) return sq * other;
      from = e.end;
    }
    return Q(elems.back().end);
  }
  // The p of every crossing of the depth q, in path order.
  std::vector<double> crossings(double q) const {
    std::vector<double> out;
    Pt2 from = start;
    for (auto &e : elems) {
      std::vector<Pt2> pts = samples(from, e);
      for (size_t i = 1; i < pts.size(); ++i) {
        double q0 = Q(pts[i - 1]), q1 = Q(pts[i]);
        if ((q0 - q) * (q1 - q) > 0 || q0 == q1) continue;
        // On the element itself (exact for arcs): the crossing between the two samples.
        ContourElem part = e;
        part.end = pts[i];
        double other = 0;
        if (crossing(pts[i - 1], part, da, sq * q, other)) out.push_back(sp * other);
      }
      from = e.end;
    }
    return out;
  }
  // The smallest q of the contour over p in [lo, hi]: the ends and each element's extreme
  // points (its ends; an arc's points where it runs along the cut) within the range.
  double minQ(double lo, double hi) const {
    const double pS = P(start), pE = P(elems.back().end);  // before A' nothing is in the way
    lo = std::clamp(lo, pS, pE), hi = std::clamp(hi, pS, pE);
    double m = std::min(qAt(lo), qAt(hi));
    Pt2 from = start;
    for (auto &e : elems) {
      std::vector<Pt2> cand{from, e.end};
      if (e.kind == ContourKind::Arc) {
        double a0, sweep;
        arcAngles(from, e, a0, sweep);
        double r = std::hypot(from.a - e.centre.a, from.b - e.centre.b);
        for (double t : {0.0, M_PI / 2, M_PI, 3 * M_PI / 2}) {
          double d = sweep > 0 ? t - a0 : a0 - t;
          d = std::fmod(d, 2 * M_PI);
          if (d < 0) d += 2 * M_PI;
          if (d <= std::fabs(sweep)) cand.push_back({e.centre.a + r * std::cos(t), e.centre.b + r * std::sin(t)});
        }
      }
      for (auto &c : cand)
        if (P(c) >= lo - kEps && P(c) <= hi + kEps) m = std::min(m, Q(c));
      from = e.end;
    }
    return m;
  }
};

}  // namespace

bool stockRemoval(const Contour &c, const StockRemoval &s, std::vector<ContourElem> &out, std::string &err) {
  const int ca = s.cutAxis, da = 1 - s.cutAxis;
  if (s.depth <= 0) return err = "the depth of cut must be greater than 0", false;
  if (s.retract < 0) return err = "the retract amount must not be negative", false;
  if (c.elems.size() < 2) return err = "the contour needs at least two moves (to A' and on to B)", false;
  const ContourElem &first = c.elems.front();
  if (first.kind == ContourKind::Arc) return err = "the first contour block must be G00 or G01", false;
  if (!s.typeII && std::fabs(at(first.end, ca) - at(c.start, ca)) > 1e-6)
    return err = std::string("the first contour block moves along ") + s.cutName +
                 ": that is type II, whose first block names both axes", false;
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
  const Profile pr{prof, aOff, ca, da, sp, sq};
  auto P = [&](const Pt2 &x) { return pr.P(x); };
  auto Q = [&](const Pt2 &x) { return pr.Q(x); };
  {
    Pt2 from = aOff;
    for (auto &e : prof) {
      std::vector<Pt2> pts = samples(from, e);
      for (size_t i = 1; i < pts.size(); ++i) {
        if (P(pts[i]) < P(pts[i - 1]) - 1e-7)
          return err = std::string("the contour from A' to B must be monotonic along ") + s.cutName, false;
        if (!s.typeII && Q(pts[i]) > Q(pts[i - 1]) + 1e-7)
          return err = "the contour from A' to B must be monotonic in both axes (type I; type II, with pockets, "
                       "names both axes in its first block)", false;
      }
      from = e.end;
    }
  }
  const double pC = P(c.start), qC = Q(c.start), qA = Q(aOff), pS = P(aOff), pE = P(bOff);
  const double qTop = pr.minQ(pS, pE);  // the contour's highest point
  if (qC >= qA - kEps) return err = "the start point is not outside the contour's start A' (with the allowance)", false;
  if (s.typeII && qC >= qTop - kEps) return err = "the start point is not outside the contour (with the allowance)", false;
  if (pE <= pC + kEps) return err = "the contour (with the allowance) does not reach beyond the start point", false;
  double qMax = qA;  // the deepest layer must stay above the deepest point
  {
    Pt2 from = aOff;
    for (auto &e : prof) {
      for (auto &x : samples(from, e)) qMax = std::max(qMax, Q(x));
      from = e.end;
    }
  }
  auto point = [&](double p, double q) { return make(ca, sp * p, sq * q); };
  Pt2 pos = c.start;
  auto move = [&](ContourKind k, double p, double q) {
    ContourElem e;
    e.kind = k;
    e.end = point(p, q);
    out.push_back(e);
    pos = e.end;
  };
  const ContourKind infeed = first.kind;  // G00 or G01 from C to A', so are the layer infeeds
  std::vector<double> levels{qC};  // cleared depths: the start level, then each layer's
  // The deepest cleared level that passes over the contour between lo and hi.
  auto travel = [&](double lo, double hi) {
    double top = pr.minQ(std::min(lo, hi), std::max(lo, hi)), best = qC;
    for (double l : levels)
      if (l < top - 1e-6) best = std::max(best, l);
    return best;
  };
  const double qBase = std::isnan(s.layersFrom) ? qC : sq * s.layersFrom;
  if (qBase < qC - kEps) return err = "the layers would begin before the start point", false;
  double qNow = qC;  // across the layers, where the tool is
  for (int k = 1;; ++k) {
    const double q = qBase + k * s.depth;
    if (q >= qMax - kEps) break;
    // The stretches of this layer where the contour lies deeper than it.
    std::vector<double> cuts = pr.crossings(q);
    std::vector<double> br{pS};
    for (double x : cuts)
      if (x > pS + kEps && x < pE - kEps) br.push_back(x);
    br.push_back(pE);
    std::vector<std::pair<double, double>> spans;
    for (size_t i = 1; i < br.size(); ++i) {
      if (br[i] - br[i - 1] <= kEps || pr.qAt((br[i] + br[i - 1]) / 2) <= q + kEps) continue;
      if (!spans.empty() && std::fabs(spans.back().second - br[i - 1]) <= kEps) spans.back().second = br[i];
      else spans.push_back({br[i - 1], br[i]});
    }
    bool pocket = false, cut = false;
    for (auto &[a, b] : spans) {
      double from = a;
      if (a <= pS + kEps) {  // from the start side, as type I
        if (b <= pC + kEps) continue;
        move(infeed, pC, q);
        from = pC;
      } else {  // a pocket: over the contour at a cleared level, down at its edge
        double t = travel(P(pos), a);
        move(ContourKind::Rapid, P(pos), t);
        move(ContourKind::Rapid, a, t);
        if (q - s.depth > t + kEps) move(ContourKind::Rapid, a, q - s.depth);
        move(ContourKind::Line, a, q);
        pocket = true;
      }
      move(ContourKind::Line, b, q);
      cut = true;
      double back = std::min(s.retract, b - from);
      move(ContourKind::Rapid, b - back, q - s.retract);  // 45 degrees out of the material
    }
    levels.push_back(q);
    if (!cut) continue;
    qNow = pocket ? travel(pC, P(pos)) : q - s.retract;
    if (pocket) move(ContourKind::Rapid, P(pos), qNow);
    move(ContourKind::Rapid, pC, qNow);
  }
  // The pass along the shifted contour: type I to A' across the layers as programmed (G00/G01;
  // along the cut by the allowance first when that is backwards, else after); type II from C
  // along the first block's line. Then A'-B at feed.
  if (s.typeII) {
    move(ContourKind::Rapid, pC, qC);
    move(infeed, pS, qA);
  } else if (pS < pC) {
    move(ContourKind::Rapid, pS, qNow);
    move(infeed, pS, qA);
  } else {
    move(infeed, pC, qA);
    move(infeed, pS, qA);
  }
  for (auto &e : prof) {
    ContourElem m = e;
    m.feed = 0;
    out.push_back(m);
  }
  // Out of the material across the layers (above the contour's highest point), back along the
  // cut, to C.
  double qOut = std::min(qC, qTop) - s.retract;
  move(ContourKind::Rapid, pE, qOut);
  move(ContourKind::Rapid, pC, qOut);
  move(ContourKind::Rapid, pC, qC);
  // Drop moves of no length (an allowance of 0 or a retract of 0 repeat points).
  std::vector<ContourElem> kept;
  Pt2 at0 = c.start;
  for (auto &e : out) {
    if (e.kind != ContourKind::Arc && std::fabs(e.end.a - at0.a) < kEps && std::fabs(e.end.b - at0.b) < kEps) continue;
    kept.push_back(e);
    at0 = e.end;
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
