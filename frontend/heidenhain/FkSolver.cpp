// The FK solver (FkSolver.h): carriers from an element's data, where consecutive carriers meet,
// and where an element ends. The orders in which solutions are numbered for FSELECT are ncc's
// (a TNC shows its solutions on the screen; their numbering is not documented): they are chosen
// so that the manual's example (L10684-L10704) draws the pocket its text describes.
#include "frontend/heidenhain/FkSolver.h"

#include <algorithm>
#include <cmath>

namespace ncc::hei::fk {

namespace {
constexpr double kEps = 1e-4;   // data agree when within this (mm): values have 3-4 decimals
constexpr double kSame = 1e-7;  // two solutions closer than this are one
constexpr double kPi = 3.14159265358979323846;

Pt operator+(Pt a, Pt b) { return {a.x + b.x, a.y + b.y}; }
Pt operator-(Pt a, Pt b) { return {a.x - b.x, a.y - b.y}; }
Pt operator*(double s, Pt a) { return {s * a.x, s * a.y}; }
double dot(Pt a, Pt b) { return a.x * b.x + a.y * b.y; }
double norm(Pt a) { return std::hypot(a.x, a.y); }
Pt unit(Pt a) { return (1 / norm(a)) * a; }
Pt left(Pt a) { return {-a.y, a.x}; }
Pt polar(double deg) { return {std::cos(deg * kPi / 180), std::sin(deg * kPi / 180)}; }
bool same(Pt a, Pt b, double tol = kEps) { return norm(a - b) < tol; }

// Unit tangent of travel on a circle at p.
Pt arcHeading(const Carrier &k, Pt p) {
  Pt radial = unit(p - k.c);
  return k.dr > 0 ? left(radial) : -1 * left(radial);
}
double lineDistance(const Carrier &k, Pt q) { return std::fabs(dot(q - k.p, left(k.d))); }
bool onCarrier(const Carrier &k, Pt q) {
  return k.arc ? std::fabs(norm(q - k.c) - k.r) < kEps : lineDistance(k, q) < kEps;
}
// The carrier's distance from a point, as D (PDX PDY D) gives it.
double distance(const Carrier &k, Pt q) { return k.arc ? std::fabs(norm(q - k.c) - k.r) : lineDistance(k, q); }

// Angle swept from a to b about c in direction dr, in [0, 2π).
double sweep(Pt c, Pt a, Pt b, int dr) {
  double s = std::atan2((b - c).y, (b - c).x) - std::atan2((a - c).y, (a - c).x);
  if (dr < 0) s = -s;
  while (s < 0) s += 2 * kPi;
  while (s >= 2 * kPi) s -= 2 * kPi;
  return s;
}

Carrier line(Pt p, Pt d, bool fixed) { return Carrier{.arc = false, .p = p, .d = d, .fixed = fixed, .c = {}, .r = 0, .dr = 0}; }

void addUnique(std::vector<Pt> &v, Pt p) {
  for (Pt &q : v)
    if (same(p, q, kSame)) return;
  v.push_back(p);
}

// The points the element passes through: its start (when known), its end (X and Y), P1…P3.
std::vector<Pt> throughPoints(const Data &e, const std::optional<Pt> &start) {
  std::vector<Pt> pts;
  if (start) pts.push_back(*start);
  if (e.x && e.y) pts.push_back({*e.x, *e.y});
  for (Pt p : e.through) pts.push_back(p);
  return pts;
}

// Lines from the data: a known direction and a point or the distance D from PD (the line with
// PD on its left first), or two points, or a point and D from PD (the two tangents to the circle
// of radius D about PD, the one turned clockwise from the way to PD first).
std::vector<Carrier> lines(const Data &e, const std::vector<Pt> &pts, std::optional<Pt> dir, bool &undetermined) {
  std::vector<Carrier> out;
  if (dir) {
    if (!pts.empty()) out.push_back(line(pts[0], *dir, true));
    else if (e.pd && e.d) {
      Pt n = left(*dir);
      out.push_back(line(*e.pd - *e.d * n, *dir, true));
      if (*e.d > 0) out.push_back(line(*e.pd + *e.d * n, *dir, true));
    } else undetermined = true;
    return out;
  }
  for (size_t k = 1; k < pts.size(); ++k)
    if (!same(pts[k], pts[0])) return {line(pts[0], unit(pts[k] - pts[0]), false)};
  if (pts.size() == 1 && e.pd && e.d) {
    Pt v = *e.pd - pts[0];
    double l = norm(v);
    if (l < *e.d - kEps) return {};
    double a = std::asin(std::min(1.0, *e.d / l));
    for (double turn : {-a, a}) {
      Pt u = unit(v);
      Pt d{u.x * std::cos(turn) - u.y * std::sin(turn), u.x * std::sin(turn) + u.y * std::cos(turn)};
      out.push_back(line(pts[0], d, false));
      if (a == 0) break;
    }
    return out;
  }
  undetermined = true;
  return out;
}

Carrier circle(Pt c, double r, int dr) { return Carrier{.arc = true, .p = {}, .d = {}, .fixed = false, .c = c, .r = r, .dr = dr}; }

// Circles from the data: the centre (CCX CCY) and R, a point or D from PD; a tangent start and R,
// another point, CCX or CCY; R and two points (the shorter arc between them first); R, one
// centre coordinate and a point (the other coordinate ascending); three points.
std::vector<Carrier> circles(const Data &e, const std::vector<Pt> &pts, const std::optional<Pt> &start,
                             const std::optional<Pt> &tangent, bool &undetermined) {
  std::vector<Carrier> out;
  auto add = [&](Pt c, double r) {
    if (r > kSame) out.push_back(circle(c, r, e.dr));
  };
  if (e.cx && e.cy) {
    Pt c{*e.cx, *e.cy};
    if (e.r) add(c, *e.r);
    else if (!pts.empty()) add(c, norm(pts[0] - c));
    else if (e.pd && e.d) {
      add(c, norm(c - *e.pd) - *e.d);
      add(c, norm(c - *e.pd) + *e.d);
    } else undetermined = true;
  } else if (e.tangent && start && tangent) {
    Pt n = e.dr > 0 ? left(*tangent) : -1 * left(*tangent);  // towards the centre
    std::optional<double> r = e.r;
    for (size_t k = 1; !r && k < pts.size(); ++k) {
      Pt q = pts[k] - *start;
      if (std::fabs(dot(q, n)) > kSame) r = dot(q, q) / (2 * dot(q, n));
    }
    if (!r && e.cx && std::fabs(n.x) > kSame) r = (*e.cx - start->x) / n.x;
    if (!r && e.cy && std::fabs(n.y) > kSame) r = (*e.cy - start->y) / n.y;
    if (r) add(*start + *r * n, *r);
    else undetermined = true;
  } else if (e.r && pts.size() >= 2) {
    Pt chord = pts[1] - pts[0];
    double half = norm(chord) / 2, h2 = *e.r * *e.r - half * half;
    if (half < kSame || h2 < -kEps) return out;
    Pt m = pts[0] + 0.5 * chord, off = std::sqrt(std::max(0.0, h2)) * left(unit(chord));
    add(e.dr > 0 ? m + off : m - off, *e.r);
    if (h2 > kSame) add(e.dr > 0 ? m - off : m + off, *e.r);
  } else if (e.r && (e.cx || e.cy) && !pts.empty()) {
    bool knowX = e.cx.has_value();
    double known = knowX ? *e.cx : *e.cy, gap = known - (knowX ? pts[0].x : pts[0].y);
    double k2 = *e.r * *e.r - gap * gap, other = knowX ? pts[0].y : pts[0].x;
    if (k2 < -kEps) return out;
    double h = std::sqrt(std::max(0.0, k2));
    for (double o : {other - h, other + h}) {
      add(knowX ? Pt{known, o} : Pt{o, known}, *e.r);
      if (h < kSame) break;
    }
  } else if (pts.size() >= 3) {
    Pt a = pts[0], b = pts[1], c = pts[2];
    double den = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    if (std::fabs(den) < kSame) return out;
    double a2 = dot(a, a), b2 = dot(b, b), c2 = dot(c, c);
    Pt m{(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / den,
         (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / den};
    add(m, norm(a - m));
  } else {
    undetermined = true;
  }
  return out;
}

// Every carrier the element's data allow, checked against all of its data.
std::vector<Carrier> carriers(const Data &e, const std::optional<Pt> &start, const std::optional<Pt> &tangent,
                              bool &undetermined) {
  std::vector<Pt> pts = throughPoints(e, start);
  std::vector<Carrier> cands;
  if (e.arc) {
    cands = circles(e, pts, start, tangent, undetermined);
  } else {
    std::optional<Pt> dir;
    if (e.an) dir = polar(*e.an);
    if (e.tangent && tangent) {
      if (dir && !same(*dir, *tangent)) return {};
      dir = tangent;
    }
    cands = lines(e, pts, dir, undetermined);
  }
  std::vector<Carrier> out;
  for (const Carrier &k : cands) {
    bool fits = true;
    for (Pt p : pts) fits = fits && onCarrier(k, p);
    if (e.pd && e.d) fits = fits && std::fabs(distance(k, *e.pd) - *e.d) < kEps;
    if (k.arc) {
      if (e.r) fits = fits && std::fabs(k.r - *e.r) < kEps;
      if (e.cx) fits = fits && std::fabs(k.c.x - *e.cx) < kEps;
      if (e.cy) fits = fits && std::fabs(k.c.y - *e.cy) < kEps;
      if (e.tangent && start && tangent) fits = fits && same(arcHeading(k, *start), *tangent);
    } else if (e.an) {
      fits = fits && same(k.d, polar(*e.an));
    }
    if (fits) out.push_back(k);
  }
  return out;
}

std::vector<Pt> meet(const Carrier &a, const Carrier &b) {
  if (!a.arc && !b.arc) {
    double den = a.d.x * b.d.y - a.d.y * b.d.x;
    if (std::fabs(den) < kSame) return {};
    Pt w = b.p - a.p;
    double t = (w.x * b.d.y - w.y * b.d.x) / den;
    return {a.p + t * a.d};
  }
  if (!a.arc) return lineCircle(a.p, a.d, b.c, b.r);
  if (!b.arc) return lineCircle(b.p, b.d, a.c, a.r);
  return circleCircle(a.c, a.r, b.c, b.r);
}

// Whether an element may end at q: a circle anywhere (back at its start: a full circle, which
// counts as a solution), a line not where it starts and, when its direction is known, ahead.
bool canEnd(const Carrier &k, Pt start, Pt q) {
  if (k.arc) return true;
  return !same(q, start) && (!k.fixed || dot(q - start, k.d) > 0);
}

// Where the element on k that starts at s ends, from its data (none given: left open).
std::vector<std::optional<Pt>> ends(const Data &e, const Carrier &k, Pt s) {
  std::vector<std::optional<Pt>> out;
  std::vector<Pt> cands;
  if (e.x && e.y) {
    Pt q{*e.x, *e.y};
    if (onCarrier(k, q) && canEnd(k, s, q)) out.push_back(q);
    return out;
  }
  if (e.x || e.y) {  // the carrier meets the line X = x (Y = y)
    Carrier axis = line(e.x ? Pt{*e.x, 0} : Pt{0, *e.y}, e.x ? Pt{0, 1} : Pt{1, 0}, false);
    cands = meet(k, axis);
    if (k.arc)  // the first one reached first
      std::sort(cands.begin(), cands.end(), [&](Pt a, Pt b) { return sweep(k.c, s, a, k.dr) < sweep(k.c, s, b, k.dr); });
  } else if (e.len && !k.arc) {
    cands.push_back(s + *e.len * k.d);
  } else {
    out.push_back(std::nullopt);
    return out;
  }
  for (Pt q : cands)
    if (canEnd(k, s, q)) out.push_back(q);
  return out;
}
}  // namespace

std::vector<Pt> lineCircle(Pt p, Pt d, Pt c, double r) {
  double t0 = dot(c - p, d);
  Pt foot = p + t0 * d;
  double h2 = r * r - dot(c - foot, c - foot);
  if (h2 < -kEps * r) return {};
  double h = std::sqrt(std::max(0.0, h2));
  std::vector<Pt> out;
  addUnique(out, p + (t0 + h) * d);
  addUnique(out, p + (t0 - h) * d);
  return out;
}

std::vector<Pt> circleCircle(Pt c1, double r1, Pt c2, double r2) {
  double dist = norm(c2 - c1);
  if (dist < kSame) return {};
  double a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist), h2 = r1 * r1 - a * a;
  if (h2 < -kEps * r1) return {};
  Pt u = unit(c2 - c1), m = c1 + a * u, off = std::sqrt(std::max(0.0, h2)) * left(u);
  std::vector<Pt> out;
  addUnique(out, m + off);
  addUnique(out, m - off);
  return out;
}

Pt endHeading(const Element &e) {
  if (e.k.arc) return arcHeading(e.k, e.end);
  return e.k.fixed ? e.k.d : unit(e.end - e.start);
}

std::vector<Hyp> extend(const Hyp &h, const Data &e, size_t index, std::string &why, bool &undetermined) {
  std::vector<Hyp> out;
  undetermined = false;
  auto grow = [&](Hyp base, const Carrier &k, Pt s) {
    for (const std::optional<Pt> &q : ends(e, k, s)) {
      Hyp n = base;
      Element el{index, k, s, q.value_or(Pt{})};
      if (q) {
        n.done.push_back(el);
        n.at = *q;
        n.heading = endHeading(el);
        n.open.reset();
      } else {
        n.open = el;
      }
      out.push_back(std::move(n));
    }
  };
  if (h.open) {
    if (e.tangent) {
      why = "it is tangential to an element whose end is still open";
      undetermined = true;
      return out;
    }
    for (const Carrier &k : carriers(e, std::nullopt, std::nullopt, undetermined))
      for (Pt j : meet(h.open->k, k)) {
        if (!canEnd(h.open->k, h.open->start, j)) continue;
        Hyp base = h;
        Element prev = *h.open;
        prev.end = j;
        base.done.push_back(prev);
        base.open.reset();
        grow(std::move(base), k, j);
      }
    if (undetermined) why = "its data do not fix its " + std::string(e.arc ? "circle" : "line") + " while the element before is open";
  } else {
    if (e.tangent && !h.heading) {
      why = "the direction of the element before is not known when the program is read";
      undetermined = true;
      return out;
    }
    for (const Carrier &k : carriers(e, h.at, h.heading, undetermined)) grow(h, k, h.at);
    if (undetermined) why = "its data do not fix its " + std::string(e.arc ? "circle" : "line");
  }
  if (out.empty() && why.empty()) why = "its data admit no solution";
  return out;
}

}  // namespace ncc::hei::fk
