#include "runtime/cycles/Pocket.h"

#include "runtime/Geometry.h"
#include "runtime/cycles/Hole.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc::entry {

namespace {
// Chords of the roughing rings stay within this of the true arcs (mm).
constexpr double kChordTolerance = 0.001;

PlanePoint rot90(PlanePoint p) { return {-p[1], p[0]}; }
PlanePoint along(PlanePoint p, PlanePoint d, double k) { return {p[0] + k * d[0], p[1] + k * d[1]}; }

// Plunges steeper than this many helix turns or ramp strokes per level are refused (ANGLE too
// small for the element).
constexpr double kMaxStrokes = 10000;

// The largest drop of one plunge: an infeed (or the floor allowance) plus the set-up clearance.
double maxDrop(const MillJob &m) { return std::min(m.infeed > 0 ? m.infeed : m.depth, m.depth) + m.clearance; }

// Along the ramp to its end `toB` (else back to a) at `level`.
void rampStroke(const Ramp &k, bool toB, double level, double f, Mill &mill) {
  const PlanePoint to = toB ? k.b : k.a;
  if (k.arc) mill.arc(to, k.centre, k.ccw == toB, level, f);
  else mill.feed(to, level, f);
}

// From over the ramp's end a down to the level `t` below the surface in the fewest equal strokes
// to and fro no steeper than the ramp angle, at the plunging feed; true when it ends at b.
bool rampDown(const MillJob &m, double t, Mill &mill) {
  const double from = (mill.level() - m.surface) * m.lv.dir, drop = t - from;
  if (mill.here() != m.ramp.a) mill.rapid(m.ramp.a, mill.level());
  const int n = std::max(1, (int)std::ceil(drop / (m.ramp.length * std::tan(m.rampAngle * M_PI / 180)) - 1e-9));
  for (int i = 1; i <= n; ++i) rampStroke(m.ramp, i % 2 == 1, m.level(from + drop * i / n), m.plungeFeed, mill);
  return n % 2 == 1;
}

// Down to the level `t` below the surface at `at` (the tool is over it, above the level).
// [model] A helix starts `helixRadius` off the point in the milling direction's sense, turns down
// at `helixPitch` per turn, then once round flat at the level. A reciprocating plunge starts at
// the ramp's end a, runs to and fro in the fewest equal strokes no steeper than `rampAngle`, then
// once more along the ramp flat at the level (the wedge the last stroke left).
void plunge(const MillJob &m, PlanePoint at, double t, Mill &mill) {
  switch (m.plunge) {
  case Plunge::Vertical: mill.feed(at, m.level(t), m.plungeFeed); return;
  case Plunge::Rapid: mill.up(m.level(t)); return;
  case Plunge::Helix: break;
  case Plunge::Reciprocate: rampStroke(m.ramp, !rampDown(m, t, mill), m.level(t), m.plungeFeed, mill); return;
  }
  const double drop = t - (mill.level() - m.surface) * m.lv.dir, turns = drop / m.helixPitch;
  const double whole = std::floor(turns + 1e-9), part = turns - whole;
  const PlanePoint start{at[0] + m.helixRadius, at[1]};
  mill.rapid(start, mill.level());
  if (drop > 0) {
    double angle = (m.ccw ? 1 : -1) * part * 2 * M_PI;
    PlanePoint end{at[0] + m.helixRadius * std::cos(angle), at[1] + m.helixRadius * std::sin(angle)};
    if (part < 1e-9) end = start;
    mill.arc(end, at, m.ccw, m.level(t), m.plungeFeed, part < 1e-9 ? (int)whole : (int)whole + 1);
  }
  mill.arc(mill.here(), at, m.ccw, m.level(t), m.plungeFeed);
}

// The ramp of a reciprocating plunge, checked: a track the tool can run, not too many strokes.
bool setRamp(MillJob &m, const Ramp &k, std::string &err) {
  if (m.plunge != Plunge::Reciprocate) return true;
  if (!(k.length > 1e-6)) return fail(err, "the slot is as long as it is wide: it has no centre line for the reciprocating plunge");
  if (maxDrop(m) / (k.length * std::tan(m.rampAngle * M_PI / 180)) > kMaxStrokes)
    return fail(err, fmt::format("the tool's plunge angle ANGLE {} is too small for the reciprocating plunge", m.rampAngle));
  m.ramp = k;
  return true;
}

bool rings(const MillJob &m, const PocketShape &p, double allowance, std::vector<Polygon> &out, std::string &err) {
  ClearingSpec s;
  s.contour = contourPolygon(p.wall, kChordTolerance);
  s.toolRadius = m.r, s.stepover = m.stepover, s.allowance = allowance, s.chordTolerance = kChordTolerance;
  return clearingRings(s, out, err);
}

// The slot in the frame of its circle, from angle 0 to `sweep`: the outline at `inset` from the
// wall (0: the wall, r: the tool-centre path), counter-clockwise from the middle of the outer arc.
Contour arcSlot(double rp, double w, double sweep, double inset) {
  const double ro = rp + w / 2 - inset, ri = rp - w / 2 + inset, mid = sweep / 2;
  auto polar = [](double r, double a) { return PlanePoint{r * std::cos(a), r * std::sin(a)}; };
  Contour c;
  c.start = polar(ro, mid);
  c.segs.push_back({polar(ro, sweep), true, {0, 0}, true});
  if (ro > ri) c.segs.push_back({polar(ri, sweep), true, polar(rp, sweep), true});  // the end, round
  c.segs.push_back({polar(ri, 0), true, {0, 0}, false});
  if (ro > ri) c.segs.push_back({polar(ro, 0), true, polar(rp, 0), true});
  c.segs.push_back({c.start, true, {0, 0}, true});
  return c;
}

}  // namespace

// The depths below the surface of successive infeeds of at most `step` down to `total`.
std::vector<double> infeeds(double step, double total) {
  std::vector<double> out;
  if (!(step > 0) || step >= total) return {total};
  for (double t = step; t < total - 1e-9; t += step) out.push_back(t);
  out.push_back(total);
  return out;
}

bool heiPlunge(const CycleArgs &a, const CycleContext &ctx, bool helix, int maxQ366, MillJob &m, std::string &err) {
  int q366;
  if (!position(a, "Q366", maxQ366, q366, err)) return false;
  m.plunge = Plunge::Vertical;
  if (q366 == 0) return true;  // straight down whatever the tool's ANGLE
  const double angle = ctx.plungeAngle;
  const char *what = helix && q366 == 1 ? "helical" : "reciprocating";
  if (!(angle > 0))
    return fail(err, fmt::format("Q366 = {} ({} plunge) needs the tool's plunge angle ANGLE: the tool table gives none "
                                 "(plunge_angle in the machine's tool table; 0 is an error, as on the control)",
                                 q366, what));
  if (angle >= 90) return true;  // [choice] ANGLE 90: straight down (as cycle 22, L9422)
  if (helix && q366 == 1) {
    m.plunge = Plunge::Helix;
    m.helixRadius = m.r;
    m.helixPitch = 2 * M_PI * m.r * std::tan(angle * M_PI / 180);
    if (maxDrop(m) / m.helixPitch > kMaxStrokes)
      return fail(err, fmt::format("the tool's plunge angle ANGLE {} is too small for the helical plunge", angle));
    return true;
  }
  m.plunge = Plunge::Reciprocate;
  m.rampAngle = angle;
  return true;
}

bool centredRamp(MillJob &m, double room, std::string &err) {
  if (m.plunge != Plunge::Reciprocate) return true;
  if (2 * room < 4 * m.r - 1e-9)
    return fail(err, fmt::format("the reciprocating plunge's stroke of at least twice the tool diameter, {}, does not fit "
                                 "into the pocket",
                                 4 * m.r));
  const double want = std::max(4 * m.r, maxDrop(m) / std::tan(m.rampAngle * M_PI / 180));
  const double len = std::min(want, 2 * room);
  return setRamp(m, {{-len / 2, 0}, {len / 2, 0}, false, {}, true, len}, err);
}

bool helixFits(const MillJob &m, double room, std::string &err) {
  if (m.plunge != Plunge::Helix || room >= 2 * m.r - 1e-9) return true;
  return fail(err, fmt::format("the helical plunge's helix cuts a bore of twice the tool diameter, {}, which does not fit "
                               "into the pocket",
                               4 * m.r));
}

bool param(const CycleArgs &a, const char *k, double lo, double hi, double &out, std::string &err, double def) {
  out = a.has(k) ? a.get(k) : def;
  if (out < lo || out > hi) return fail(err, fmt::format("{} must lie in {} … {}", k, lo, hi));
  return true;
}

// A choice 0 … hi (Q215, Q367 …); false with err set when out of range.
bool position(const CycleArgs &a, const char *k, int hi, int &out, std::string &err) {
  double v;
  if (!param(a, k, 0, hi, v, err)) return false;
  if (v != std::floor(v)) return fail(err, fmt::format("{} must be 0 … {}", k, hi));
  out = (int)v;
  return true;
}

bool toolRadius(const CycleContext &ctx, MillJob &m, std::string &err) {
  if (!(ctx.toolRadius > 0))
    return fail(err, "needs the active tool's radius (a tool with a radius in the tool table; ncc cycle --tool-radius)");
  m.r = ctx.toolRadius;
  return true;
}

// The walls in Q338 infeeds (0: one at the full depth) at Q385: rapid over a point off the wall,
// plunge at Q206, onto the wall on a quarter arc, once round, off it on the mirrored quarter, up by
// Q200. [model] The arcs have the radius Q368 + Q200 (at most `room`) and touch the path at its
// start; between passes the tool crosses over the roughed floor, not through the floor allowance.
void finishWalls(const MillJob &m, const FinishPath &f, bool ccw, Mill &mill) {
  const double roughDepth = m.depth - m.floorAllowance;
  const double rho = std::min(m.sideAllowance + m.clearance, f.room);
  const PlanePoint at = f.path.start, n = f.inside ? f.normal : PlanePoint{-f.normal[0], -f.normal[1]};
  const PlanePoint t = ccw ? rot90(f.normal) : PlanePoint{-rot90(f.normal)[0], -rot90(f.normal)[1]};  // travel at `at`
  // The arcs' centre lies off the wall on the side away from the material: they turn as the
  // path does about a pocket, the other way about a stud.
  const bool arcCcw = ccw == f.inside;
  const PlanePoint q = along(at, n, -rho), from = along(q, t, -rho), to = along(q, t, rho);
  double link = -m.clearance;
  for (double s : infeeds(m.finishInfeed, m.depth)) {
    mill.go(from, m.level(link));
    mill.feed(from, m.level(s), m.plungeFeed);
    if (rho > 0) mill.arc(at, q, arcCcw, m.level(s), m.finishFeed);
    mill.run(f.path, ccw, m.level(s), m.finishFeed);
    if (rho > 0) mill.arc(to, q, arcCcw, m.level(s), m.finishFeed);
    link = std::min(s, roughDepth) - m.clearance;
    mill.up(m.level(link));
  }
}

// Heidenhain 251/252/253 (seed002a L5830-5886, L6143-6241, L6454-6496): roughing level by level
// (plunge at the centre, rings from the middle to the wall less the allowances, up by Q200 and back
// to the centre at rapid), then the walls (finishWalls), then the floor from the middle out.
bool millPocket(const MillJob &m, const PocketShape &p, Mill &mill, std::string &err) {
  const PlanePoint centre = p.home;
  const double roughDepth = m.depth - m.floorAllowance;
  if (m.roughing()) {
    std::vector<Polygon> rough;
    if (!rings(m, p, m.sideAllowance, rough, err)) return false;
    // Links stay at the level only when clear of the wall (Region.h's rule; a circular slot's
    // inner wall is concave), as close as the rings' own chords come; else over the surface.
    const std::vector<Polygon> walls{contourPolygon(p.wall, kChordTolerance)};
    const double keep = m.r + m.sideAllowance - kChordSagFactor * kChordTolerance;
    auto clear = [&](PlanePoint to) { return segmentClear(walls, mill.here(), to, keep); };
    mill.go(centre, m.lv.zsc);
    double floor = -m.clearance;  // the depth already cut at the plunge points (above: the clearance)
    for (double t : infeeds(m.infeed, roughDepth)) {
      plunge(m, centre, t, mill);
      for (const Polygon &ring : rough) {
        if (const PlanePoint s = mill.ringStart(ring); !clear(s)) {
          mill.go(s, m.level(-m.clearance));
          mill.up(m.level(std::max(floor, 0.0) - m.clearance));
          mill.feed(s, m.level(t), m.plungeFeed);
        }
        mill.ring(ring, m.ccw, m.level(t), m.millFeed);
      }
      mill.up(m.level(t - m.clearance));
      if (!clear(centre)) mill.up(m.level(-m.clearance));
      mill.go(centre, m.level(t - m.clearance));
      floor = t;
    }
  }
  if (m.wallPass) finishWalls(m, p.finish, m.ccw, mill);
  if (m.floorPass) {
    // The walls are finished (or have no allowance): rings out to the wall itself.
    std::vector<Polygon> floor;
    if (!rings(m, p, 0, floor, err)) return false;
    mill.go(centre, m.level(roughDepth - m.clearance));
    plunge(m, centre, m.depth, mill);
    for (const Polygon &ring : floor) mill.ring(ring, m.ccw, m.level(m.depth), m.finishFeed);
    mill.up(m.level(m.depth - m.clearance));
  }
  return true;
}

Mill placed(std::vector<CycleStep> &out, const CycleContext &ctx, const MillJob &m, PlanePoint offset, double degrees,
            int plane, const PlanePoint *about) {
  if (plane < 0) plane = ctx.plane;
  const PlaneAxes ax = planeAxes((Plane)plane);
  const PlanePoint ref = about ? *about : PlanePoint{ctx.position[ax.u], ctx.position[ax.v]};
  double s, c;
  sinCosDegrees(degrees, s, c);
  PlanePoint origin{ref[0] + c * offset[0] - s * offset[1], ref[1] + s * offset[0] + c * offset[1]};
  return Mill(out, plane, origin, degrees, m.lv.dir, ctx.position);
}

// A slot as wide as the tool: the tool-centre path is the centre line (a line or an arc between
// the ends' centres; seed002a L6563-6567: roughing only), the tool lifted out of the slot after
// every infeed.
// A reciprocating plunge ramps along the line itself from the set-up clearance over the last
// level cut [model], and the pass runs back from the end the ramp reached.
void slotLine(const MillJob &m, const Contour &line, Mill &mill) {
  double floor = -m.clearance;  // the depth already cut
  auto pass = [&](double t, double f) {
    mill.go(line.start, m.lv.zsc);
    bool forward = true;
    if (m.plunge == Plunge::Reciprocate) {
      mill.up(m.level(std::max(floor, 0.0) - m.clearance));
      forward = !rampDown(m, t, mill);
    } else {
      mill.feed(line.start, m.level(t), m.plungeFeed);
    }
    mill.run(line, forward, m.level(t), f);
    mill.up(m.lv.zsc);
    floor = t;
  };
  if (m.roughing())
    for (double t : infeeds(m.infeed, m.depth - m.floorAllowance)) pass(t, m.millFeed);
  if (m.floorPass) pass(m.depth, m.finishFeed);
}

namespace {
// The ramp of a slot: its centre line between the ends' centres (seed002a L6477: "from the left
// end along the middle of the slot").
Ramp lineRamp(const Contour &line) {
  const PathSeg &s = line.segs[0];
  double len = std::hypot(s.end[0] - line.start[0], s.end[1] - line.start[1]);
  if (s.arc) len = std::hypot(line.start[0] - s.centre[0], line.start[1] - s.centre[1]) * arcSweep(line.start, s);
  return {line.start, s.end, s.arc, s.centre, s.ccw, len};
}
}  // namespace

// A straight slot L x W about the origin along x: along its centre line when as wide as the tool
// (no allowance), else a pocket with round ends whose wall is finished from the left arc
// (seed002a L6486), counter-clockwise from its apex.
bool straightSlot(const MillJob &job, double L, double W, const char *allowance, Mill &mill, std::string &err) {
  MillJob m = job;
  const Contour centreLine{{-(L - W) / 2, 0}, {{{(L - W) / 2, 0}, false, {}, true}}};
  if (!setRamp(m, lineRamp(centreLine), err)) return false;
  if (m.sideAllowance == 0 && std::fabs(W - 2 * m.r) < 1e-9) {
    slotLine(m, centreLine, mill);
    return true;
  }
  if (2 * (m.r + m.sideAllowance) >= W) return fail(err, fmt::format("the tool with the {} does not fit into the slot", allowance));
  PocketShape p;
  p.wall = roundedRect(L / 2, W / 2, W / 2);
  p.finish.path = halfTurn(roundedRect(L / 2 - m.r, W / 2 - m.r, W / 2 - m.r));
  p.finish.normal = {-1, 0};
  p.finish.room = (W / 2 - m.r) / 2;
  return millPocket(m, p, mill, err);
}

// `count` slots W wide along arcs of radius rp about `centre`, each through `sweepDeg` from
// `first` + i x `step` degrees, each from where the last left the tool, up to the end level
// (lv.z2) after each; as wide as the tool (no allowance): along the centre arc.
bool arcSlots(const MillJob &job, int plane, PlanePoint centre, double rp, double W, double sweepDeg, double first,
              double step, int count, const char *allowance, std::vector<CycleStep> &out, std::string &err) {
  MillJob m = job;
  if (W / 2 >= rp) return fail(err, "the slot reaches the circle's centre: it is wider than the circle's diameter");
  const bool line = m.sideAllowance == 0 && std::fabs(W - 2 * m.r) < 1e-9;
  if (!line && 2 * (m.r + m.sideAllowance) >= W)
    return fail(err, fmt::format("the tool with the {} does not fit into the slot", allowance));
  const double sweep = sweepDeg * M_PI / 180;
  PocketShape p;
  p.wall = arcSlot(rp, W, sweep, 0);
  p.finish.path = arcSlot(rp, W, sweep, m.r);
  p.finish.normal = {std::cos(sweep / 2), std::sin(sweep / 2)};
  p.finish.room = (W / 2 - m.r) / 2;
  p.home = {rp * std::cos(sweep / 2), rp * std::sin(sweep / 2)};
  const Contour centreLine{{rp, 0}, {{{rp * std::cos(sweep), rp * std::sin(sweep)}, true, {0, 0}, true}}};
  if (!setRamp(m, lineRamp(centreLine), err)) return false;
  std::array<double, 3> at = m.call;
  for (int i = 0; i < count; ++i) {
    for (auto it = out.rbegin(); it != out.rend(); ++it)  // where the last slot left the tool
      if (it->kind == CycleStepKind::Rapid || it->kind == CycleStepKind::Feed || it->kind == CycleStepKind::Arc) {
        at = it->pos;
        break;
      }
    Mill mill(out, plane, centre, first + i * step, m.lv.dir, at);
    if (line) {
      slotLine(m, centreLine, mill);
    } else if (!millPocket(m, p, mill, err)) {
      return false;
    }
    mill.up(m.lv.z2);
  }
  return true;
}

}  // namespace ncc::entry
