// rs274's G70-G72 cut pattern (TurningRs274.h). Points are complex numbers z + i x (the G18
// contour's a + i b). The steps and their tolerances follow rs274 2.9's behaviour as measured
// against its canonical trace (test/lit/oracle/lathe_g7x*.test): where its moves look odd (the
// first rapid along Z to the profile's first Z, a retract that shrinks on short cuts) they are
// what the machine does under LinuxCNC, so they are reproduced, not improved.
#include "runtime/cycles/TurningRs274.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace ncc {

namespace {
using Cd = std::complex<double>;
constexpr double kTol = 1e-6;
const Cd kJ(0, 1);

struct Refused {
  std::string what;
};

// One profile element from s to e; an arc about c, counter-clockwise in (z, x) (G3) when ccw.
struct Seg {
  bool arc = false;
  bool ccw = false;
  Cd s, e, c;
};

double sizeOf(const Seg &g) { return g.arc ? std::min(std::abs(g.s - g.e), std::abs(g.s - g.c)) : std::abs(g.s - g.e); }

// Running towards -Z without turning back (rs274's tolerances).
bool monotonic(const Seg &g) {
  const double dz = (g.e - g.s).real();
  if (!g.arc) return dz <= 1e-3;
  const double entry = (g.s - g.c).imag(), exit = (g.e - g.c).imag();
  return g.ccw ? entry >= -1e-3 && exit >= -1e-3 && dz <= -1e-3 : entry <= 1e-3 && exit <= 1e-3 && dz <= -1e-3;
}

// The element moved sideways by d (to the left of its direction for a line; an arc's radius grows
// by d when it turns counter-clockwise).
void offset(Seg &g, double d) {
  if (!g.arc) {
    const Cd n = kJ * d * (g.s - g.e) / std::abs(g.s - g.e);
    g.s += n, g.e += n;
    return;
  }
  const double f = (std::abs(g.s - g.c) + (g.ccw ? d : -d)) / std::abs(g.s - g.c);
  g.s = f * (g.s - g.c) + g.c, g.e = f * (g.e - g.c) + g.c;
}

// The mirror images and the quarter turn the profile is normalised with.
enum Mirror { kMirrorZ = 1, kMirrorX = 2, kTurn = 4 };
void mirrorX(Seg &g) { g.s = std::conj(g.s), g.e = std::conj(g.e), g.c = std::conj(g.c), g.ccw = !g.ccw; }
void mirrorZ(Seg &g) { g.s = -std::conj(g.s), g.e = -std::conj(g.e), g.c = -std::conj(g.c), g.ccw = !g.ccw; }
void turn(Seg &g) { g.s *= -kJ, g.e *= -kJ, g.c *= -kJ; }

bool onArc(const Seg &g, Cd p) {
  const double from = std::imag(std::conj(g.s - g.c) * (p - g.c)), to = std::imag(std::conj(g.e - g.c) * (p - g.c));
  return g.ccw ? from >= -kTol && to <= kTol : from <= kTol && to >= -kTol;
}

// The Z values where the element meets the line X = x.
std::vector<double> crossings(const Seg &g, double x) {
  std::vector<double> is;
  if (!g.arc) {
    if (std::min(g.s.imag(), g.e.imag()) > x + kTol || std::max(g.s.imag(), g.e.imag()) < x - kTol) return is;
    if (std::fabs((g.s - g.e).imag()) < kTol) return {g.s.real(), g.e.real()};
    is.push_back((x - g.s.imag()) / (g.e.imag() - g.s.imag()) * (g.e.real() - g.s.real()) + g.s.real());
    return is;
  }
  const double r = std::abs(g.s - g.c);
  double q = -(x - r - g.c.imag()) * (x + r - g.c.imag());
  if (q < -kTol) return is;
  q = std::sqrt(std::max(q, 0.0));
  for (double z : {g.c.real() + q, g.c.real() - q})
    if (onArc(g, Cd(z, x))) is.push_back(z);
  return is;
}

// Where the moves go: mapped back through the normalisation (the mirror and turn state).
struct Out {
  std::vector<ContourElem> &v;
  int state;
  Cd at;  // the last point sent, in the contour's coordinates
  Cd map(Cd p) const {
    switch (state) {
    case 1: return -std::conj(p);
    case 2: return std::conj(p);
    case 3: return -p;
    case 4: return kJ * p;
    case 5: return std::conj(kJ * p);
    case 6: return -std::conj(kJ * p);
    case 7: return -kJ * p;
    default: return p;
    }
  }
  void put(ContourKind k, Cd p, Cd c = 0, bool ccw = false) {
    ContourElem el;
    el.kind = k;
    const Cd q = map(p), cc = map(c);
    el.end = {q.real(), q.imag()}, el.centre = {cc.real(), cc.imag()};
    el.ccw = ccw != (state == 1 || state == 2 || state == 5 || state == 6);
    v.push_back(el);
    at = q;
  }
  void rapid(Cd p) { put(ContourKind::Rapid, p); }
  void line(Cd p) { put(ContourKind::Line, p); }
  // rs274 drops an arc that ends where it starts (within 0.0001).
  void arc(bool ccw, Cd c, Cd p) {
    const Cd q = map(p);
    if (std::fabs(q.real() - at.real()) < 1e-4 && std::fabs(q.imag() - at.imag()) < 1e-4) return;
    put(ContourKind::Arc, p, c, ccw);
  }
  void draw(const Seg &g) { g.arc ? arc(g.ccw, g.c, g.e) : line(g.e); }
};

// The top of a convex arc for a climb that leaves it there.
Cd arcTop(const Seg &g) { return g.e.real() < g.c.real() ? Cd(g.c.real(), g.c.imag() + std::abs(g.s - g.c)) : g.e; }

// Following the element upwards (X growing) from `at`; true when it does not climb from there.
bool climb(const Seg &g, Cd &at, Out &out) {
  if (!g.arc) {
    if (g.e.imag() + kTol < g.s.imag()) return true;
    if (std::abs(at - g.s) > kTol) throw Refused{"How did we get here?"};
    out.line(g.e), at = g.e;
    return false;
  }
  if (!g.ccw) {
    if (at.real() > g.c.real()) return true;
    if (std::abs(at - g.e) > 1e-3) out.arc(false, g.c, g.e);
    at = g.e;
    return false;
  }
  if (at.real() < g.c.real()) return true;
  const Cd top = arcTop(g);
  if (std::abs(at - top) > 1e-3) out.arc(true, g.c, top);
  at = top;
  return true;
}

// G71.1: from the layer's X onto the element and up along it (pockets are not cut).
void climbOnly(const Seg &g, Cd &at, Out &out) {
  if (!g.arc && g.e.imag() < g.s.imag()) return;
  const std::vector<double> is = crossings(g, at.imag());
  if (is.empty()) return;
  if (!g.arc) {
    at.real(is.front());
    out.line(at), out.line(g.e), at = g.e;
    return;
  }
  if (!g.ccw) {
    if (is.back() > g.c.real()) return;
    at.real(is.back());
    out.line(at);
    if (std::abs(at - g.e) > 1e-3) out.arc(false, g.c, g.e);
    at = g.e;
    return;
  }
  if (is.front() < g.c.real()) return;
  at.real(is.front());
  out.line(at);
  const Cd top = arcTop(g);
  if (std::abs(at - top) > 1e-3) out.arc(true, g.c, top);
  at = top;
}

// Down along the element to the layer X = x (or its end); true when it does not go down.
bool dive(const Seg &g, Cd &at, double x, Out &out, bool fast) {
  if (!g.arc) {
    if (g.s.imag() <= g.e.imag() + kTol) return true;
    Cd to = g.e;
    if (x >= g.e.imag()) {
      const std::vector<double> is = crossings(g, x);
      if (is.empty()) throw Refused{"x too large in straight dive"};
      to = Cd(is.front(), x);
    }
    fast ? out.rapid(to) : out.line(to);
    at = to;
    return false;
  }
  if (std::abs(at - g.e) < kTol || (at - g.e).real() <= kTol) {
    at = g.e;
    return false;
  }
  std::vector<double> is = crossings(g, x);
  if (is.empty()) is = crossings(g, x - kTol);
  if (g.ccw) {
    if (at.real() - kTol > g.c.real()) return true;
    const Cd to = is.empty() || is.back() > g.c.real() ? g.e : Cd(is.back(), x);
    out.arc(true, g.c, to), at = to;
    return false;
  }
  if (at.real() <= g.c.real()) return true;  // already climbing
  if (!is.empty() && is.front() < g.c.real()) return false;  // met at the back only: the next layer
  const Cd to = is.empty() ? g.e : Cd(is.front(), x);
  out.arc(false, g.c, to), at = to;
  return false;
}

// P's end and N's start moved to where the two (offset) elements meet.
void meet(Seg &p, Seg &n) {
  Cd is;
  if (!p.arc && !n.arc) {
    const Cd rot = std::conj(n.s - n.e) / std::abs(n.s - n.e);
    const Cd ps = (p.s - n.e) * rot, pe = (p.e - n.e) * rot;
    if ((ps - pe).imag() == 0) throw Refused{"Cannot intersect parallel lines"};
    const double f = ps.imag() / (ps - pe).imag();
    is = (ps + f * (pe - ps)) / rot + n.e;
  } else if (p.arc != n.arc) {  // a line and an arc: the crossing nearer N's start
    if (std::abs(n.s - p.e) < kTol) return;
    const Seg &line = p.arc ? n : p;
    const Seg &arc = p.arc ? p : n;
    const Cd base = line.e;
    const Cd rot = std::conj(line.s - line.e) / std::abs(line.s - line.e);
    const Cd pe = ((p.arc ? p.e : n.e) - base) * rot, pc = (arc.c - base) * rot;
    double b = std::norm(pc - pe) - pc.imag() * pc.imag();
    b = b < 0 ? 0 : std::sqrt(b);
    const Cd s1 = (pc.real() + b) / rot + base, s2 = (pc.real() - b) / rot + base;
    is = std::abs(n.s - s1) < std::abs(n.s - s2) ? s1 : s2;
  } else {
    const double a = std::abs(n.s - n.c), b = std::abs(p.s - p.c), c = std::abs(n.c - p.c);
    const double cosB = (c * c + a * a - b * b) / 2.0 / a / c;
    const Cd rot(cosB, std::sqrt(1 - std::min(cosB * cosB, 1.0)));
    is = rot * (p.c - n.c) / c * a + n.c;
  }
  p.e = n.s = is;
}

struct Profile {
  std::vector<Seg> segs;
  int state = 0;
  double delta = 0.5;
  Cd escape{0.3, 0.3};
  std::vector<Cd> pocketStarts;
  int steps = 0;

  void guard() {
    if (++steps > 1000000) throw Refused{"the cut pattern does not end"};
  }
  void quarterTurn() {
    for (Seg &g : segs) turn(g);
    state ^= kTurn;
  }
  // Mirrored so that the profile runs towards -Z and -X.
  void normalise() {
    const Cd dir = segs.front().e - segs.back().e;
    if (dir.imag() > 0) {
      for (Seg &g : segs) mirrorX(g);
      state ^= kMirrorX;
    }
    if (dir.real() < 0) {
      for (Seg &g : segs) mirrorZ(g);
      state ^= kMirrorZ;
    }
  }
  void requireMonotonic() {
    Seg &f = segs.front();
    if ((f.e - f.s).real() > 0) f.s.real(f.e.real());  // the first move starts at its own Z
    for (const Seg &g : segs)
      if (!monotonic(g)) throw Refused{"Not monotonic"};
  }
  void dropTiny() {
    segs.erase(std::remove_if(segs.begin(), segs.end(), [](const Seg &g) { return sizeOf(g) < 1e-3; }), segs.end());
    if (segs.size() < 2) throw Refused{"the profile is too short"};
  }
  void shift(Cd d) {
    for (Seg &g : segs) g.s += d, g.e += d, g.c += d;
  }
  void addDistance(double distance);
  void pocket(int cycle, Cd at, size_t p, Out &out);
};

// The profile (all but its first element, the approach) offset by `distance` away from the
// material, in steps of at most half the smallest element; convex corners get an arc.
void Profile::addDistance(double distance) {
  const Cd v1 = segs.front().e - segs.front().s, v2 = segs.back().s - segs.front().s;
  if ((v1 / v2).imag() < 0) distance = -distance;
  Seg approach = segs.front();
  segs.erase(segs.begin());
  double done = 0;
  while (done != distance) {
    guard();
    double step = 1e9;
    for (const Seg &g : segs) step = std::min(step, sizeOf(g) / 2);
    step = std::min(step, std::fabs(distance - done));
    if (distance < 0) step = -step;
    for (size_t i = 0; i < segs.size(); ++i) {
      offset(segs[i], step);
      if (sizeOf(segs[i]) < 1e-3) segs.erase(segs.begin() + (long)i--);
    }
    for (size_t i = 0; i + 1 < segs.size(); ++i) {
      if ((segs[i].e - segs[i + 1].s).real() <= 1e-2) continue;
      Seg a = segs[i], b = segs[i + 1];
      offset(a, -step), offset(b, -step);
      Seg corner{true, distance > 0, segs[i].e, segs[i + 1].s, (a.e + b.s) / 2.0};
      segs.insert(segs.begin() + (long)i + 1, corner);
      ++i;
    }
    for (size_t i = 0; i + 1 < segs.size(); ++i) {
      if (!monotonic(segs[i])) {
        if (i == 0) throw Refused{"Not monotonic"};
        segs.erase(segs.begin() + (long)(sizeOf(segs[i]) < sizeOf(segs[i - 1]) ? i : i - 1));
        i = 0;
        if (segs.size() < 2) throw Refused{"Not monotonic"};
      }
      if (sizeOf(segs[i]) < 1e-3) {
        segs.erase(segs.begin() + (long)i);
        i = 0;
        if (segs.size() < 2) throw Refused{"the profile is too short"};
      } else {
        meet(segs[i], segs[i + 1]);
      }
    }
    done += step;
  }
  for (size_t i = 0; i + 1 < segs.size(); ++i) segs[i].e = segs[i + 1].s = (segs[i].e + segs[i + 1].s) / 2.0;
  approach.e = segs.front().s;
  segs.insert(segs.begin(), approach);
}

// Layers from the pocket's start X down by delta, each cut along -Z until it meets the profile,
// then the retract; where the profile climbs again the next pocket begins (G71.1: not cut).
void Profile::pocket(int cycle, Cd at, size_t p, Out &out) {
  double x = pocketStarts.back().imag();
  if (cycle == 2) {  // G71.2: down the profile without cutting the first part
    for (; p < segs.size(); ++p)
      if (dive(segs[p], at, -1e9, out, p == 0)) break;
    cycle = 3;
  }
  while (p < segs.size()) {
    guard();
    while (x - kTol > at.imag()) x -= delta;
    if (dive(segs[p], at, x, out, p == 0)) {
      if (cycle == 1) {
        for (; p < segs.size(); ++p) climbOnly(segs[p], at, out);
        return;
      }
      for (; p < segs.size(); ++p) {
        if (!climb(segs[p], at, out)) continue;
        if (cycle == 3) {
          if (at.imag() > pocketStarts.back().imag() && pocketStarts.size() > 1) pocketStarts.pop_back();
          if (pocketStarts.size() == 1) pocketStarts.push_back(at);
        }
        pocket(cycle, at, p, out);
        return;
      }
      return;
    }
    if (std::fabs(at.imag() - x) > kTol) {  // below this element: the next one
      ++p;
      continue;
    }
    for (size_t ip = p; ip < segs.size(); ++ip) {
      const std::vector<double> is = crossings(segs[ip], at.imag());
      if (is.empty()) continue;
      const double z = ip != p ? is.front() : is.back();
      const double length = std::fabs(z - at.real());
      if (z - kTol > at.real()) continue;  // met behind the start only
      if (length < kTol) {
        if (p == ip) continue;
        if (std::abs(at - segs[ip].s) < kTol) {
          p = ip;
        } else {
          x -= delta;
        }
        break;
      }
      Cd to = at;
      to.real(z);
      out.line(to);
      const double scale = std::min(1.0, length / 2 / escape.real());  // a short cut retracts less
      out.rapid(to + scale * escape);
      out.rapid(at - std::conj(scale * escape));
      p == 0 ? out.rapid(at) : out.line(at);
      x -= delta;
      break;
    }
  }
}

void finishing(Profile &prof, const Rs274Turning &s, Cd start, std::vector<ContourElem> &v) {
  prof.segs.front().s = start;
  Profile probe = prof;
  probe.segs.erase(probe.segs.begin());
  probe.normalise();
  for (const Seg &g : probe.segs)
    if (!monotonic(g)) {
      probe.quarterTurn(), probe.normalise();
      break;
    }
  probe.requireMonotonic();
  if (probe.state & kTurn) prof.quarterTurn();
  prof.normalise();
  prof.dropTiny();
  prof.requireMonotonic();
  Out out{v, prof.state, start};
  for (int pass = (int)s.passes; pass > 0; --pass) {
    Profile path = prof;
    path.addDistance((pass - 1) * (s.d - s.e) / s.passes + s.e);
    out.rapid(path.segs.front().s);
    out.rapid(path.segs.front().e);
    for (size_t k = 1; k < path.segs.size(); ++k) out.draw(path.segs[k]);
  }
}

void roughing(Profile &prof, const Rs274Turning &s, Cd start, std::vector<ContourElem> &v) {
  prof.segs.front().s = start;
  if (s.cycle == 72) prof.quarterTurn();
  prof.normalise();
  prof.dropTiny();
  prof.requireMonotonic();
  prof.addDistance(s.d);
  prof.shift(Cd(s.w, s.u));  // in the normalised frame, as rs274 applies U and W
  Out out{v, prof.state, start};
  prof.delta = std::max(s.i, 2 * kTol);
  prof.escape = s.r * Cd(1, 1);
  const Cd from = prof.segs.front().s;
  out.rapid(from);
  if (prof.segs.back().e.imag() < from.imag()) {
    Cd up = prof.segs.back().e;
    up.imag(from.imag());
    prof.segs.push_back(Seg{false, false, prof.segs.back().e, up, 0});
  }
  prof.pocketStarts.push_back(from);
  prof.pocket(s.sub, from, 0, out);
}
}  // namespace

bool rs274Turning(const Contour &c, const Rs274Turning &s, std::vector<ContourElem> &out, std::string &err) {
  const Cd start(c.start.a, c.start.b);
  // rs274 2.9 (the oracle) takes the profile as read; later LinuxCNC versions also close it to
  // the start X (Z) before the cut.
  Profile prof;
  Cd at = start;
  for (const ContourElem &el : c.elems) {
    const Cd to(el.end.a, el.end.b);
    if (to == at) continue;
    prof.segs.push_back(Seg{el.kind == ContourKind::Arc, el.ccw, at, to, Cd(el.centre.a, el.centre.b)});
    at = to;
  }
  if (prof.segs.size() <= 1) return true;  // rs274 does nothing more
  if (s.i <= 0) {
    err = "G7X error: I must be greater than zero.";
    return false;
  }
  try {
    s.cycle == 70 ? finishing(prof, s, start, out) : roughing(prof, s, start, out);
  } catch (const Refused &r) {
    err = "G7X error: " + r.what;
    return false;
  }
  return true;
}

}  // namespace ncc
