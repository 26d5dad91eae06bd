// The pocket, stud, slot and face entries of the cycle library: each maps its manual's parameter
// list onto the milling options (MillJob, modelled on the Heidenhain 25x parameters) and a shape (the finished wall as a
// Contour, Mill.h); roughing clears the region ring by ring (clearingRings, Clearing.h), the
// finishing passes cut the wall with exact arcs. docs/CYCLES.md lists the entries and marks
// the geometry the manuals show only in figures "[model]".
#include "runtime/Geometry.h"
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/Hole.h"
#include "runtime/cycles/Mill.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

// Chords of the roughing rings stay within this of the true arcs (mm).
constexpr double kChordTolerance = 0.001;

// The depths below the surface of successive infeeds of at most `step` down to `total`.
std::vector<double> infeeds(double step, double total) {
  std::vector<double> out;
  if (!(step > 0) || step >= total) return {total};
  for (double t = step; t < total - 1e-9; t += step) out.push_back(t);
  out.push_back(total);
  return out;
}

PlanePoint rot90(PlanePoint p) { return {-p[1], p[0]}; }
PlanePoint along(PlanePoint p, PlanePoint d, double k) { return {p[0] + k * d[0], p[1] + k * d[1]}; }

// How the tool goes down to a level at the plunge point: at the feed (Heidenhain Q366 0,
// Sinumerik _VARI 2nd digit 1), at rapid into a pre-drilled hole (Sinumerik 0), on a helix of
// `helixRadius` about the point with `helixPitch` per turn (Sinumerik 2).
enum class Plunge : uint8_t { Vertical, Rapid, Helix };

// ---- The options every pocket, slot and stud shares, named after the Heidenhain 25x parameters
// (seed002a "Pocket / stud / slot cycles: shared semantics"); the Sinumerik entries fill them from
// their own.
struct MillJob {
  HeiLevels lv;                   // zsc, z2 (the end), dir
  double surface = 0, depth = 0;  // Q203; |Q201|
  double infeed = 0;              // Q202
  double sideAllowance = 0, floorAllowance = 0, finishInfeed = 0;  // Q368 Q369 Q338
  double clearance = 0;           // |Q200|
  double plungeFeed = 0, millFeed = 0, finishFeed = 0;  // Q206 Q207 Q385 (0: Q207)
  int op = 0;                     // Q215: 0 rough and finish, 1 rough, 2 finish
  bool wallPass = false, floorPass = false;  // the finishing passes to run
  Plunge plunge = Plunge::Vertical;
  double helixRadius = 0, helixPitch = 0;
  double stepover = 0;            // Q370 x tool radius
  double r = 0;                   // tool radius
  bool ccw = true;                // the direction round a pocket's wall (studs: the other)
  std::array<double, 3> call{};   // where the cycle was called
  // The tool-axis level `t` below the surface (negative: above).
  double level(double t) const { return surface + lv.dir * t; }
  bool roughing() const { return op != 2; }
  bool finishing() const { return op != 1; }
};

bool param(const CycleArgs &a, const char *k, double lo, double hi, double &out, std::string &err, double def = 0) {
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

// False with err empty when the depth is 0 (the TNC does not run the cycle).
bool heiMill(const CycleArgs &a, const CycleContext &ctx, double minOverlap, MillJob &m, std::string &err) {
  err.clear();
  if (!heiLevels(a, m.lv, err)) return false;
  if (a.get("Q201") == 0) return false;
  if (!toolRadius(ctx, m, err)) return false;
  m.surface = a.get("Q203"), m.depth = std::fabs(a.get("Q201"));
  m.clearance = std::fabs(a.get("Q200"));
  double climb, overlap;
  if (!position(a, "Q215", 2, m.op, err)) return false;
  if (!(a.get("Q202") > 0)) return fail(err, "Q202 (plunging depth) must be greater than 0");
  m.infeed = a.get("Q202");
  if (m.depth / m.infeed > kMaxPecks) return fail(err, "Q202 (plunging depth) too small");
  if (!(a.get("Q207") > 0)) return fail(err, "Q207 (milling feed) must be greater than 0");
  m.plungeFeed = a.get("Q206"), m.millFeed = a.get("Q207");
  m.finishFeed = a.get("Q385") > 0 ? a.get("Q385") : m.millFeed;
  if (!param(a, "Q368", 0, 99999.9999, m.sideAllowance, err) || !param(a, "Q369", 0, 99999.9999, m.floorAllowance, err) ||
      !param(a, "Q338", 0, 99999.9999, m.finishInfeed, err) || !param(a, "Q370", minOverlap, 1.9999, overlap, err, 1) ||
      !param(a, "Q351", -1, 1, climb, err, 1))
    return false;
  if (m.floorAllowance >= m.depth) return fail(err, "Q369 (floor allowance) must be less than the depth Q201");
  if (m.finishInfeed > 0 && m.depth / m.finishInfeed > kMaxPecks) return fail(err, "Q338 (finishing infeed) too small");
  if (climb != std::floor(climb)) return fail(err, "Q351 must be +1 (climb), -1 (up-cut) or 0");
  // Helical and reciprocating plunges follow the tool table's plunge angle ANGLE, which the tool
  // data does not hold; the manual makes vertical plunging mandatory without it.
  if (a.get("Q366") != 0)
    return fail(err, "Q366 = " + std::to_string((int)a.get("Q366")) +
                         " (helical or reciprocating plunge) needs the tool's plunge angle (tool table ANGLE), which "
                         "ncc's tool data does not hold: program Q366=0");
  if (a.get("Q439") != 0)
    return fail(err, "Q439 (feed referred to the cutting edge) is not supported: program Q439=0 (tool centre path)");
  m.stepover = overlap * m.r;
  // Q351 is given for M3: climb milling runs a pocket's wall counter-clockwise; M4 reverses it.
  m.ccw = (climb != -1) == (ctx.spindle != 2);
  m.call = ctx.position;
  m.wallPass = m.finishing() && m.sideAllowance > 0;  // the manual: only with an allowance
  m.floorPass = m.finishing() && m.floorAllowance > 0;
  return true;
}

// Down to the level `t` below the surface at `at` (the tool is over it, above the level).
// [model] A helix starts `helixRadius` off the point in the milling direction's sense, turns down
// at `helixPitch` per turn, then once round flat at the level.
void plunge(const MillJob &m, PlanePoint at, double t, Mill &mill) {
  switch (m.plunge) {
  case Plunge::Vertical: mill.feed(at, m.level(t), m.plungeFeed); return;
  case Plunge::Rapid: mill.up(m.level(t)); return;
  case Plunge::Helix: break;
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

// A wall the finishing passes cut: the tool-centre path (a closed contour round the element,
// counter-clockwise from `start`), its outward normal there (away from the element's middle), the
// largest radius of the arcs onto and off it, and which side of it the material to finish lies
// (`inside`: a pocket's wall; else a stud's).
struct FinishPath {
  Contour path;
  PlanePoint normal{1, 0};
  double room = 0;
  bool inside = true;
};

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

// A pocket in its own frame (centre at the origin): the finished wall and the pass that finishes
// it.
struct PocketShape {
  Contour wall;
  FinishPath finish;
  PlanePoint home{0, 0};  // where the tool plunges and returns between levels
};

bool rings(const MillJob &m, const PocketShape &p, double allowance, std::vector<Polygon> &out, std::string &err) {
  ClearingSpec s;
  s.contour = contourPolygon(p.wall, kChordTolerance);
  s.toolRadius = m.r, s.stepover = m.stepover, s.allowance = allowance, s.chordTolerance = kChordTolerance;
  return clearingRings(s, out, err);
}

// Heidenhain 251/252/253 (seed002a L5830-5886, L6143-6241, L6454-6496): roughing level by level
// (plunge at the centre, rings from the middle to the wall less the allowances, up by Q200 and back
// to the centre at rapid), then the walls (finishWalls), then the floor from the middle out.
bool heiPocket(const MillJob &m, const PocketShape &p, Mill &mill, std::string &err) {
  const PlanePoint centre = p.home;
  const double roughDepth = m.depth - m.floorAllowance;
  if (m.roughing()) {
    std::vector<Polygon> rough;
    if (!rings(m, p, m.sideAllowance, rough, err)) return false;
    mill.go(centre, m.lv.zsc);
    for (double t : infeeds(m.infeed, roughDepth)) {
      plunge(m, centre, t, mill);
      for (const Polygon &ring : rough) mill.ring(ring, m.ccw, m.level(t), m.millFeed);
      mill.up(m.level(t - m.clearance));
      mill.go(centre, m.level(t - m.clearance));
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

// The end of every Heidenhain 25x cycle: up to the 2nd set-up clearance, then over the call
// position (the pockets' start position).
void heiEnd(const MillJob &m, int plane, Mill &mill) {
  std::array<double, 3> end = m.call;
  end[planeAxes((Plane)plane).n] = m.lv.z2;
  mill.goProgram(end);
}

// The writer for an element whose centre lies `offset` from the tool (or from `about`) in the
// element's own frame, the element turned by `degrees` about that point, in `plane` (default the
// active one).
Mill placed(std::vector<CycleStep> &out, const CycleContext &ctx, const MillJob &m, PlanePoint offset, double degrees,
            int plane = -1, const PlanePoint *about = nullptr) {
  if (plane < 0) plane = ctx.plane;
  const PlaneAxes ax = planeAxes((Plane)plane);
  const PlanePoint ref = about ? *about : PlanePoint{ctx.position[ax.u], ctx.position[ax.v]};
  double s, c;
  sinCosDegrees(degrees, s, c);
  PlanePoint origin{ref[0] + c * offset[0] - s * offset[1], ref[1] + s * offset[0] + c * offset[1]};
  return Mill(out, plane, origin, degrees, m.lv.dir, ctx.position);
}

// The corner Q367 puts at the tool (1 lower left … 4 upper left) as a multiple of the half sides.
constexpr double kCorner[5][2] = {{0, 0}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

bool hei251(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  double L = a.get("Q218"), W = a.get("Q219"), rc = a.get("Q220");
  int pos;
  if (!(L > 0) || !(W > 0)) return fail(err, "Q218 and Q219 (side lengths) must be greater than 0");
  if (!position(a, "Q367", 4, pos, err)) return false;
  if (rc == 0) rc = m.r;  // the manual: 0 means the tool radius
  if (rc < m.r) return fail(err, "Q220 (corner radius) is smaller than the tool radius: the tool cannot cut the corners");
  if (2 * rc > std::min(L, W)) return fail(err, "Q220 (corner radius) is larger than half the shorter side");
  if (2 * (m.r + m.sideAllowance) >= std::min(L, W))
    return fail(err, "the tool with the side allowance Q368 does not fit into the pocket");
  PocketShape p;
  p.wall = roundedRect(L / 2, W / 2, rc);
  double a2 = L / 2 - m.r, b2 = W / 2 - m.r;
  p.finish.path = roundedRect(a2, b2, rc - m.r);
  p.finish.room = std::min(a2, b2) / 2;
  // Q367 places the pocket's corner at the tool; Q224 turns the pocket about the tool.
  Mill mill = placed(out, ctx, m, {-kCorner[(int)pos][0] * L / 2, -kCorner[(int)pos][1] * W / 2}, a.get("Q224"));
  if (!heiPocket(m, p, mill, err)) return false;
  heiEnd(m, ctx.plane, mill);
  return true;
}

bool hei252(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.1, m, err)) return err.empty();
  double d = a.get("Q223");
  if (!(d > 0)) return fail(err, "Q223 (pocket diameter) must be greater than 0");
  if (2 * (m.r + m.sideAllowance) >= d) return fail(err, "the tool with the side allowance Q368 does not fit into the pocket");
  PocketShape p;
  p.wall = circleContour(d / 2);
  p.finish.path = circleContour(d / 2 - m.r);
  p.finish.room = (d / 2 - m.r) / 2;
  Mill mill = placed(out, ctx, m, {0, 0}, 0);
  if (!heiPocket(m, p, mill, err)) return false;
  heiEnd(m, ctx.plane, mill);
  return true;
}

// Q367 of 253: the tool at the middle, the left end, the left arc's centre, the right arc's
// centre, the right end; the slot's centre from the tool in slot lengths (x L/2, x W/2 on x).
constexpr double kSlotEnd[5][2] = {{0, 0}, {1, 0}, {1, -1}, {-1, 1}, {-1, 0}};

// A slot as wide as the tool: the tool-centre path is the centre line (a line or an arc between
// the ends' centres; seed002a L6563-6567: roughing only), the tool lifted out of the slot after
// every infeed.
void heiSlotLine(const MillJob &m, const Contour &line, Mill &mill) {
  auto pass = [&](double t, double f) {
    mill.go(line.start, m.lv.zsc);
    mill.feed(line.start, m.level(t), m.plungeFeed);
    mill.run(line, true, m.level(t), f);
    mill.up(m.lv.zsc);
  };
  if (m.roughing())
    for (double t : infeeds(m.infeed, m.depth - m.floorAllowance)) pass(t, m.millFeed);
  if (m.floorPass) pass(m.depth, m.finishFeed);
}

// A straight slot L x W about the origin along x: along its centre line when as wide as the tool
// (no allowance), else a pocket with round ends whose wall is finished from the left arc
// (seed002a L6486), counter-clockwise from its apex.
bool straightSlot(const MillJob &m, double L, double W, const char *allowance, Mill &mill, std::string &err) {
  if (m.sideAllowance == 0 && std::fabs(W - 2 * m.r) < 1e-9) {
    heiSlotLine(m, {{-(L - W) / 2, 0}, {{{(L - W) / 2, 0}, false, {}, true}}}, mill);
    return true;
  }
  if (2 * (m.r + m.sideAllowance) >= W) return fail(err, fmt::format("the tool with the {} does not fit into the slot", allowance));
  PocketShape p;
  p.wall = roundedRect(L / 2, W / 2, W / 2);
  p.finish.path = halfTurn(roundedRect(L / 2 - m.r, W / 2 - m.r, W / 2 - m.r));
  p.finish.normal = {-1, 0};
  p.finish.room = (W / 2 - m.r) / 2;
  return heiPocket(m, p, mill, err);
}

bool hei253(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  double L = a.get("Q218"), W = a.get("Q219");
  int pos;
  if (!(L > 0) || !(W > 0)) return fail(err, "Q218 (slot length) and Q219 (slot width) must be greater than 0");
  if (W > L) return fail(err, "Q219 (slot width) is larger than Q218 (slot length, the longer side)");
  if (!position(a, "Q367", 4, pos, err)) return false;
  // Q367 puts an end or an arc's centre at the tool; Q374 turns the slot about the tool.
  Mill mill = placed(out, ctx, m, {kSlotEnd[pos][0] * L / 2 + kSlotEnd[pos][1] * W / 2, 0}, a.get("Q374"));
  if (!straightSlot(m, L, W, "side allowance Q368", mill, err)) return false;
  // The end: the 2nd set-up clearance over the slot's centre (the start when Q367 is 0).
  mill.up(m.lv.z2);
  mill.go({0, 0}, m.lv.z2);
  return true;
}

// ---- Heidenhain 254 circular slot (seed002a L6718-7030): a slot along an arc of diameter Q375
// from the polar angle Q376 through Q248, Q219 wide, machined as 253 (a pocket; plunge in the
// middle of the centre line), repeated Q377 times turned by Q378 about the circle's centre.
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

// `count` slots W wide along arcs of radius rp about `centre`, each through `sweepDeg` from
// `first` + i x `step` degrees, each from where the last left the tool, up to the end level
// (lv.z2) after each; as wide as the tool (no allowance): along the centre arc.
bool arcSlots(const MillJob &m, int plane, PlanePoint centre, double rp, double W, double sweepDeg, double first,
              double step, int count, const char *allowance, std::vector<CycleStep> &out, std::string &err) {
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
  std::array<double, 3> at = m.call;
  for (int i = 0; i < count; ++i) {
    for (auto it = out.rbegin(); it != out.rend(); ++it)  // where the last slot left the tool
      if (it->kind == CycleStepKind::Rapid || it->kind == CycleStepKind::Feed || it->kind == CycleStepKind::Arc) {
        at = it->pos;
        break;
      }
    Mill mill(out, plane, centre, first + i * step, m.lv.dir, at);
    if (line) {
      heiSlotLine(m, {{rp, 0}, {{{rp * std::cos(sweep), rp * std::sin(sweep)}, true, {0, 0}, true}}}, mill);
    } else if (!heiPocket(m, p, mill, err)) {
      return false;
    }
    mill.up(m.lv.z2);
  }
  return true;
}

bool hei254(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  const double W = a.get("Q219"), rp = a.get("Q375") / 2, start = a.get("Q376"), step = a.get("Q378");
  double sweepDeg, reps;
  int pos;
  if (!(W > 0) || !(rp > 0)) return fail(err, "Q219 (slot width) and Q375 (pitch circle diameter) must be greater than 0");
  if (!param(a, "Q248", 0, 360, sweepDeg, err) || !param(a, "Q377", 1, 99999, reps, err, 1) || !position(a, "Q367", 3, pos, err))
    return false;
  if (reps != std::floor(reps)) return fail(err, "Q377 (repetitions) must be a whole number");
  if (!(sweepDeg > 0) || sweepDeg >= 360) return fail(err, "Q248 (angular length) must lie between 0 and 360 (a closed ring is not a slot)");
  if (W / 2 >= rp) return fail(err, "the slot reaches the circle's centre: Q219 must be less than Q375");
  // The circle's centre: Q216/Q217 (Q367 0), else back from the tool, which is at the start end
  // (1), the middle (2) or the far end (3) of the centre line [model: the ends in angle order].
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  PlanePoint centre{a.get("Q216"), a.get("Q217")};
  if (pos > 0) {
    double s, c;
    sinCosDegrees(start + (pos - 1) * sweepDeg / 2, s, c);
    centre = {ctx.position[ax.u] - rp * c, ctx.position[ax.v] - rp * s};
  }
  return arcSlots(m, ctx.plane, centre, rp, W, sweepDeg, start, step, (int)reps, "side allowance Q368", out, err);
}

// ---- studs (256, 257): laps round the stud from the blank inward.
// The stud in its own frame: its outline offset outward by d (a tool-centre lap, counter-clockwise
// from the +x side), how far from the stud the blank reaches at most, and the approach point.
struct StudShape {
  Contour (*lap)(const StudShape &, double d);
  double a = 0, b = 0, rc = 0;  // half sides and corner radius (a circle: a = b = rc = radius)
  double reach = 0;
  PlanePoint approach{};
};
Contour rectLap(const StudShape &s, double d) { return roundedRect(s.a + d, s.b + d, s.rc + d); }
Contour circleLap(const StudShape &s, double d) { return circleContour(s.a + d); }

// The laps' tool-centre distances from the stud, outermost first: the innermost leaves
// `allowance`, the outermost reaches the blank's farthest point, evenly at most a stepover apart
// (seed002a L7034-7081: further laps "with constant lateral step").
std::vector<double> lapOffsets(const MillJob &m, const StudShape &s, double allowance) {
  const double inner = m.r + allowance, outer = std::max(inner, s.reach - m.r);
  int n = (int)std::ceil((outer - inner) / m.stepover - 1e-9);
  std::vector<double> out;
  for (int k = n; k > 0; --k) out.push_back(inner + (outer - inner) * k / n);
  out.push_back(inner);
  return out;
}

// Heidenhain 256/257: each level from the approach point outside the blank (plunge there at Q206),
// in to the outermost lap, the laps inward at Q207, back out to the approach point; then the wall
// (finishWalls, from outside) and the floor; the end at the 2nd set-up clearance there.
// [model] The moves onto the laps and back out are straight and radial, the laps concentric.
void heiStud(const MillJob &m, const StudShape &s, Mill &mill) {
  const bool ccw = !m.ccw;  // climb milling on an outer wall runs clockwise with M3
  const double roughDepth = m.depth - m.floorAllowance;
  auto laps = [&](double level, double allowance, double f) {
    for (double d : lapOffsets(m, s, allowance)) {
      Contour lap = s.lap(s, d);
      mill.feed(lap.start, level, f);
      mill.run(lap, ccw, level, f);
    }
    mill.feed(s.approach, level, f);
  };
  if (m.roughing()) {
    mill.go(s.approach, m.lv.zsc);
    for (double t : infeeds(m.infeed, roughDepth)) {
      mill.feed(s.approach, m.level(t), m.plungeFeed);
      laps(m.level(t), m.sideAllowance, m.millFeed);
    }
  }
  if (m.wallPass)
    finishWalls(m, {s.lap(s, m.r), {1, 0}, m.sideAllowance + m.clearance, false}, ccw, mill);
  if (m.floorPass) {
    mill.go(s.approach, m.level(roughDepth - m.clearance));
    mill.feed(s.approach, m.level(m.depth), m.plungeFeed);
    laps(m.level(m.depth), 0, m.finishFeed);
  }
  mill.up(m.lv.z2);
}

bool hei256(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.1, m, err)) return err.empty();
  double L = a.get("Q218"), W = a.get("Q219"), BL = a.get("Q424"), BW = a.get("Q425"), rc = a.get("Q220");
  int pos;
  if (!(L > 0) || !(W > 0)) return fail(err, "Q218 and Q219 (side lengths) must be greater than 0");
  if (!(BL > L) || !(BW > W)) return fail(err, "the blank Q424 x Q425 must be larger than the stud Q218 x Q219");
  if (rc < 0) return fail(err, "Q220 < 0 (chamfered corners) is not supported: program a corner radius");
  if (2 * rc > std::min(L, W)) return fail(err, "Q220 (corner radius) is larger than half the shorter side");
  if (!position(a, "Q367", 4, pos, err)) return false;
  if (a.get("Q437") != 0) return fail(err, "Q437 1-4 (approach at a corner, spiralling in) is not supported: program Q437=0");
  StudShape s{rectLap, L / 2, W / 2, rc};
  // The farthest blank point is a corner: its distance from the rounded stud.
  double qx = BL / 2 - (L / 2 - rc), qy = BW / 2 - (W / 2 - rc);
  s.reach = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) - rc;
  s.approach = {BL / 2 + m.r + 2, 0};  // 2 mm outside the blank, right of the stud (Q437 0)
  Mill mill = placed(out, ctx, m, {-kCorner[pos][0] * L / 2, -kCorner[pos][1] * W / 2}, a.get("Q224"));
  heiStud(m, s, mill);
  return true;
}

bool hei257(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  double d = a.get("Q223"), blank = a.get("Q222"), angle = a.has("Q376") ? a.get("Q376") : -1;
  if (!(d > 0)) return fail(err, "Q223 (finished diameter) must be greater than 0");
  if (!(blank > d)) return fail(err, "Q222 (blank diameter) must be larger than Q223");
  if (angle != -1 && (angle < 0 || angle > 359.9999)) return fail(err, "Q376 must be -1 or lie in 0 … 359.9999");
  StudShape s{circleLap, d / 2, d / 2, d / 2};
  s.reach = (blank - d) / 2;
  s.approach = {blank / 2 + m.r + 2, 0};
  // [model] Q376 -1 (the controller's optimum) approaches at 0 degrees.
  Mill mill = placed(out, ctx, m, {0, 0}, angle < 0 ? 0 : angle);
  heiStud(m, s, mill);
  return true;
}

// ---- Sinumerik POCKET3 and POCKET4 (seed000c 19.1.5, 19.1.6). The manual lists the parameters
// only: the motion is the shared pocket's (heiPocket) [model], from over the pocket's centre at
// the retraction plane _RTP, back up to it at the end.
// The parameter names of the Sinumerik milling cycles (POCKET3/4 write _RTP, SLOT1 RTP …); null:
// the cycle has none (its default applies).
struct SinNames {
  const char *rtp, *rfp, *sdis, *mid, *fal, *fald, *ffp1, *ffd, *cdir, *vari, *helixRadius, *helixPitch;
  bool slotDepth;  // _DP absolute / _DPR relative by _AMODE (SLOT1, LONGHOLE), else _DP by _AMODE
};
constexpr SinNames kPocketNames{"_RTP", "_RFP", "_SDIS", "_MID", "_FAL", "_FALD", "_FFP1", "_FFD",
                                "_CDIR", "_VARI", "_RAD1", "_DP1", false};
constexpr SinNames kSlotNames{"RTP", "RFP", "SDIS", "_MID", "_FAL", "_FALD", "FFP1", "FFD",
                              "CDIR", "VARI", "_STA2", "_DP1", true};
constexpr SinNames kLongholeNames{"RTP", "_RFP", "SDIS", "MID", nullptr, nullptr, "FFP1", "FFD",
                                  nullptr, nullptr, nullptr, nullptr, true};

double get(const CycleArgs &a, const char *k) { return k ? a.get(k) : 0; }

bool sinPocketJob(const CycleArgs &a, const CycleContext &ctx, const SinNames &n, MillJob &m, std::string &err) {
  for (const char *k : {n.rtp, n.rfp, n.mid, n.ffp1, n.ffd})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (!toolRadius(ctx, m, err)) return false;
  // The depth: POCKET3/4 _DP absolute, or (_AMODE 1st digit 1) below the reference plane; the
  // slots _DP absolute (2) or _DPR below it (1), 0: _DPR when given.
  const double rfp = a.get(n.rfp);
  const int mode = digit(a.get("_AMODE"), 1);
  bool below = n.slotDepth ? mode == 1 || (mode == 0 && a.has("_DPR")) : mode == 1;
  const char *depthKey = n.slotDepth && below ? "_DPR" : "_DP";
  if (!a.has(depthKey)) return fail(err, std::string(depthKey) + " (depth) is required");
  const double bottom = below ? rfp - a.get(depthKey) : a.get(depthKey);
  if (bottom == rfp) return fail(err, fmt::format("the depth lies on the reference plane {}", n.rfp));
  m.lv.dir = bottom < rfp ? -1 : 1;
  m.surface = rfp, m.depth = std::fabs(bottom - rfp);
  m.clearance = std::fabs(get(a, n.sdis));
  m.lv.zsc = rfp - m.lv.dir * m.clearance;
  m.lv.z2 = a.get(n.rtp);
  if ((m.lv.z2 - m.lv.zsc) * m.lv.dir > 0)
    return fail(err, fmt::format("the retraction plane {} lies below the safety level {} + {}", n.rtp, n.rfp, n.sdis));
  if (!(a.get(n.mid) > 0)) return fail(err, fmt::format("{} (maximum depth infeed) must be greater than 0", n.mid));
  if (m.depth / a.get(n.mid) > kMaxPecks) return fail(err, fmt::format("{} (maximum depth infeed) too small", n.mid));
  m.infeed = m.finishInfeed = a.get(n.mid);  // [model] the walls are finished in the same infeeds
  if ((n.fal && !param(a, n.fal, 0, 1e5, m.sideAllowance, err)) || (n.fald && !param(a, n.fald, 0, 1e5, m.floorAllowance, err)))
    return false;
  if (m.floorAllowance >= m.depth) return fail(err, fmt::format("{} (depth allowance) must be less than the depth", n.fald));
  if (!(a.get(n.ffp1) > 0) || !(a.get(n.ffd) > 0)) return fail(err, fmt::format("{} and {} (feeds) must be greater than 0", n.ffp1, n.ffd));
  m.millFeed = m.finishFeed = a.get(n.ffp1), m.plungeFeed = a.get(n.ffd);
  // CDIR 0 climb, 1 conventional (for M3; M4 reverses), 2 G2, 3 G3.
  const double cdir = get(a, n.cdir);
  if (cdir != 0 && cdir != 1 && cdir != 2 && cdir != 3)
    return fail(err, fmt::format("{} must be 0 (climb), 1 (conventional), 2 (G2) or 3 (G3)", n.cdir));
  m.ccw = cdir == 3 || (cdir < 2 && (cdir == 0) == (ctx.spindle != 2));
  m.stepover = m.r;  // [model] the slots name no plane infeed: a tool radius (POCKET3/4: _MIDA)
  m.call = ctx.position;
  if (!n.vari) {  // LONGHOLE: roughing only, its own infeed types
    m.op = 1;
    return true;
  }
  // VARI 1st digit: 1 roughing, 2 finishing (wall and floor), 4 wall finishing, 5 chamfering.
  switch (digit(a.get(n.vari), 1)) {
  case 1: m.op = 1; break;
  case 2: m.op = 2, m.wallPass = m.floorPass = true; break;
  case 4: m.op = 2, m.wallPass = true; break;
  case 5: return fail(err, fmt::format("{} 5 (chamfering) needs the tool's point angle: not supported", n.vari));
  default: return fail(err, fmt::format("{} 1st digit must be 1 (roughing), 2 (finishing), 4 (edge finishing) or 5 (chamfering)", n.vari));
  }
  // 2nd digit: 0 pre-drilled (down at rapid), 1 vertical at the depth feed, 2 helix, 3 oscillating.
  switch (digit(a.get(n.vari), 2)) {
  case 0: m.plunge = Plunge::Rapid; break;
  case 1: m.plunge = Plunge::Vertical; break;
  case 2:
    m.plunge = Plunge::Helix, m.helixRadius = a.get(n.helixRadius), m.helixPitch = a.get(n.helixPitch);
    if (!(m.helixRadius > 0) || !(m.helixPitch > 0))
      return fail(err, fmt::format("a helical plunge needs {} (radius) and {} (pitch) greater than 0", n.helixRadius, n.helixPitch));
    if (m.depth / m.helixPitch > kMaxPecks) return fail(err, fmt::format("{} (helix pitch) too small", n.helixPitch));
    break;
  default: return fail(err, fmt::format("{} 2nd digit 3 (oscillating plunge) is not supported", n.vari));
  }
  return true;
}

// The reference point of a Sinumerik element: (ka, kb) when programmed, else (null) the tool's
// position, so that MCALL with a position pattern puts one at each position [model].
const PlanePoint *reference(const CycleArgs &a, const char *ka, const char *kb, PlanePoint &out) {
  if (!a.has(ka) && !a.has(kb)) return nullptr;
  out = {a.get(ka), a.get(kb)};
  return &out;
}

// POCKET3/4: _MIDA, mm or (_AMODE 2nd digit 1) percent of the tool diameter, 0: 80 % of it; no
// pre-machined pockets.
bool sinPlaneInfeed(const CycleArgs &a, MillJob &m, std::string &err) {
  double mida = a.get("_MIDA");
  if (digit(a.get("_AMODE"), 2) == 1) mida *= 2 * m.r / 100;
  m.stepover = mida > 0 ? mida : 1.6 * m.r;
  if (mida < 0 || m.stepover > 2 * m.r) return fail(err, "_MIDA (plane infeed) must lie between 0 and the tool diameter");
  if (digit(a.get("_GMODE"), 5) == 2 || a.get("_AP1") != 0 || a.get("_AP2") != 0 || a.get("_AD") != 0)
    return fail(err, "machining a pre-machined pocket (_AP1 _AP2 _AD, _GMODE 5th digit 2) is not supported");
  return true;
}

// Pocket, then up to _RTP where the tool is.
bool sinPocket(const MillJob &m, const PocketShape &p, Mill &mill, std::string &err) {
  mill.go({0, 0}, m.lv.z2);
  if (!heiPocket(m, p, mill, err)) return false;
  mill.up(m.lv.z2);
  return true;
}

// _GMODE 4th digit: 0, 1 the reference point is the centre; 2-5 a corner, the pocket running
// +/-_LENG, +/-_WID from it: the centre from the corner in half sides.
constexpr double kSinCorner[6][2] = {{0, 0}, {0, 0}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};

bool sinPocket3(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!sinPocketJob(a, ctx, kPocketNames, m, err) || !sinPlaneInfeed(a, m, err)) return false;
  const double L = std::fabs(a.get("_LENG")), W = std::fabs(a.get("_WID")), rc = a.get("_CRAD");
  const int dim = digit(a.get("_GMODE"), 4);
  if (!(L > 0) || !(W > 0)) return fail(err, "_LENG and _WID (pocket length and width) must not be 0");
  if (rc < m.r) return fail(err, "_CRAD (corner radius) is smaller than the tool radius: the tool cannot cut the corners");
  if (2 * rc > std::min(L, W)) return fail(err, "_CRAD (corner radius) is larger than half the shorter side");
  if (2 * (m.r + m.sideAllowance) >= std::min(L, W)) return fail(err, "the tool with the allowance _FAL does not fit into the pocket");
  if (dim > 5) return fail(err, "_GMODE 4th digit must be 0 … 5");
  PocketShape p;
  p.wall = roundedRect(L / 2, W / 2, rc);
  p.finish.path = roundedRect(L / 2 - m.r, W / 2 - m.r, rc - m.r);
  p.finish.room = std::min(L / 2 - m.r, W / 2 - m.r) / 2;
  PlanePoint about;
  Mill mill = placed(out, ctx, m, {kSinCorner[dim][0] * L / 2, kSinCorner[dim][1] * W / 2}, a.get("_STA"),
                     sinPlane(a, ctx), reference(a, "_PA", "_PO", about));
  return sinPocket(m, p, mill, err);
}

bool sinPocket4(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!sinPocketJob(a, ctx, kPocketNames, m, err) || !sinPlaneInfeed(a, m, err)) return false;
  // _CDIAM: a radius (_DMODE 3rd digit 0, compatibility) or a diameter (1).
  const double d = digit(a.get("_DMODE"), 3) == 1 ? a.get("_CDIAM") : 2 * a.get("_CDIAM");
  if (!(d > 0)) return fail(err, "_CDIAM (pocket diameter) must be greater than 0");
  if (digit(a.get("_VARI"), 4) == 1) return fail(err, "_VARI 4th digit 1 (helical machining of the depth) is not supported");
  if (2 * (m.r + m.sideAllowance) >= d) return fail(err, "the tool with the allowance _FAL does not fit into the pocket");
  PocketShape p;
  p.wall = circleContour(d / 2);
  p.finish.path = circleContour(d / 2 - m.r);
  p.finish.room = (d / 2 - m.r) / 2;
  PlanePoint about;
  Mill mill = placed(out, ctx, m, {0, 0}, 0, sinPlane(a, ctx), reference(a, "_PA", "_PO", about));
  return sinPocket(m, p, mill, err);
}

// ---- Heidenhain 232 face milling (seed002b 3.6, L13993-14300): lines across a rectangle from the
// start point (Q225, Q226), Q218 along the first axis (its sign the direction of the first cut),
// Q219 across (its sign the direction of the first stepover); levels from the surface Q227 down
// to Q386, equal infeeds of at most Q202, the last removing Q369 at Q385. The digest's [model]
// for the line ends and spacing: lines R (tool radius) in from the sides, equally spaced at most
// Q370 x R apart; cuts start R + Q357 beside the surface and end as far beyond it (Q389 0, 2) or
// R inside its edge (Q389 1).
bool hei232(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"Q225", "Q226", "Q227", "Q386", "Q218", "Q219", "Q202", "Q207"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  MillJob m;
  if (!toolRadius(ctx, m, err)) return false;
  const double top = a.get("Q227"), end = a.get("Q386"), depth = top - end;
  if (depth == 0) return true;  // the TNC does not run the cycle
  if (depth < 0) return fail(err, "Q386 (end point in the tool axis) lies above the surface Q227");
  int strategy;
  double allowance, overlap;
  if (!position(a, "Q389", 2, strategy, err) || !param(a, "Q369", 0, 99999.9999, allowance, err) ||
      !param(a, "Q370", 0.1, 1.9999, overlap, err, 1))
    return false;
  if (allowance >= depth) return fail(err, "Q369 (floor allowance) must be less than the depth Q227 - Q386");
  const double L = a.get("Q218"), W = a.get("Q219"), maxInfeed = a.get("Q202"), r = m.r;
  if (L == 0 || W == 0) return fail(err, "Q218 and Q219 (side lengths) must not be 0");
  if (!(maxInfeed > 0)) return fail(err, "Q202 (maximum plunging depth) must be greater than 0");
  if (depth / maxInfeed > kMaxPecks) return fail(err, "Q202 (maximum plunging depth) too small");
  const double millFeed = a.get("Q207"), finishFeed = a.get("Q385") > 0 ? a.get("Q385") : millFeed;
  const double posFeed = a.get("Q253");
  if (!(millFeed > 0) || !(posFeed > 0)) return fail(err, "Q207 and Q253 (feeds) must be greater than 0");
  const double clearance = std::fabs(a.get("Q200")), side = std::fabs(a.get("Q357"));
  m.lv.dir = -1;  // the face lies below the surface along the tool axis
  m.surface = top;
  // Levels: equal infeeds down to Q386 + Q369, then Q369 at the finishing feed.
  std::vector<std::pair<double, double>> levels;  // depth below Q227, feed
  const int n = (int)std::ceil((depth - allowance) / maxInfeed - 1e-9);
  for (int i = 1; i <= n; ++i) levels.push_back({(depth - allowance) * i / n, millFeed});
  if (allowance > 0) levels.push_back({depth, finishFeed});
  // Lines across: R in from each side, equally spaced at most Q370 x R; one in the middle when
  // the width is at most the tool's diameter.
  const double s1 = L > 0 ? 1 : -1, s2 = W > 0 ? 1 : -1, x0 = a.get("Q225"), y0 = a.get("Q226");
  std::vector<double> lines;
  if (std::fabs(W) <= 2 * r) {
    lines.push_back(y0 + W / 2);
  } else {
    int k = (int)std::ceil((std::fabs(W) - 2 * r) / (overlap * r) - 1e-9);
    for (int i = 0; i <= k; ++i) lines.push_back(y0 + s2 * r + (W - 2 * s2 * r) * i / k);
  }
  const double outside = x0 - s1 * (r + side), beyond = x0 + L + s1 * (r + side);
  const double farEnd = strategy == 1 ? x0 + L - s1 * r : beyond, nearEnd = strategy == 1 ? x0 + s1 * r : outside;
  Mill mill(out, ctx.plane, {0, 0}, 0, m.lv.dir, ctx.position);
  const double z2 = top + std::max(clearance, std::fabs(a.get("Q204")));
  mill.go({outside, lines[0]}, z2);
  mill.up(top + clearance);
  bool forward = true;  // the order of the lines on this level
  for (size_t li = 0; li < levels.size(); ++li) {
    const double z = m.level(levels[li].first), f = levels[li].second;
    for (size_t i = 0; i < lines.size(); ++i) {
      const double y = lines[forward ? i : lines.size() - 1 - i];
      if (strategy == 2) {  // each line from the start side: over at Q253 above the level, down, across
        if (i > 0 || li > 0) {
          mill.up(z + clearance);
          mill.feed({outside, y}, z + clearance, posFeed);
        }
        mill.feed({outside, y}, z, posFeed);
        mill.feed({beyond, y}, z, f);
        continue;
      }
      // Meander: down at the end of the line before (or the start), across, the next line back.
      if (i == 0) {
        mill.feed(mill.here(), z, posFeed);
      } else {
        mill.feed({mill.here()[0], y}, z, strategy == 1 ? f : posFeed);
      }
      const bool towardFar = std::fabs(mill.here()[0] - farEnd) > std::fabs(mill.here()[0] - nearEnd);
      mill.feed({towardFar ? farEnd : nearEnd, y}, z, f);
    }
    forward = !forward;  // the next level runs the lines back (seed002b L14043-14049)
  }
  mill.up(z2);
  return true;
}

// ---- Sinumerik SLOT1 and LONGHOLE (seed000c 19.1.7, 19.1.9): one slot (NUM 1; more with MCALL
// and a position pattern), LENG long, WID wide (LONGHOLE: as wide as the tool), about the
// reference point (_CPA, _CPO) turned by STA1, as 253 [model]. _GMODE 4th digit: the reference
// point is the centre (0), the left arc's centre (1), the right arc's (2), the left end (3), the
// right end (4).
constexpr int kSinSlotRef[5] = {0, 2, 3, 1, 4};  // as 253's Q367

bool sinSlot(const CycleArgs &a, const CycleContext &ctx, const SinNames &n, double W, std::vector<CycleStep> &out,
             std::string &err) {
  MillJob m;
  PlanePoint about;
  if (!sinPocketJob(a, ctx, n, m, err)) return false;
  const double L = a.get("LENG");
  const int ref = digit(a.get("_GMODE"), 4);
  if (a.has("NUM") && a.get("NUM") != 1)
    return fail(err, "NUM must be 1: several slots are programmed with MCALL and a position pattern");
  if (!(L > 0) || !(W > 0)) return fail(err, "LENG (length) and WID (width) must be greater than 0");
  if (W > L) return fail(err, "the slot is wider than long");
  if (ref > 4) return fail(err, "_GMODE 4th digit must be 0 … 4");
  const int pos = kSinSlotRef[ref];
  Mill mill = placed(out, ctx, m, {kSlotEnd[pos][0] * L / 2 + kSlotEnd[pos][1] * W / 2, 0}, a.get("STA1"),
                     sinPlane(a, ctx), reference(a, "_CPA", "_CPO", about));
  mill.go({0, 0}, m.lv.z2);
  if (!straightSlot(m, L, W, "allowance _FAL", mill, err)) return false;
  mill.up(m.lv.z2);
  return true;
}

bool sinSlot1(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  return sinSlot(a, ctx, kSlotNames, a.get("WID"), out, err);
}

bool sinLonghole(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  // _VARI 1st digit: 1 (or 0) vertical at FFD, 3 oscillating.
  if (digit(a.get("_VARI"), 1) == 3) return fail(err, "_VARI 3 (oscillating infeed) is not supported");
  if (digit(a.get("_VARI"), 1) > 1) return fail(err, "_VARI 1st digit must be 1 (vertical) or 3 (oscillating)");
  return sinSlot(a, ctx, kLongholeNames, 2 * ctx.toolRadius, out, err);
}

// ---- Sinumerik SLOT2 (seed000c 19.1.8): NUM slots AFSL degrees long, WID wide, on the circle
// of radius RAD about (_CPA, _CPO), the first from STA1, the next INDA further (full circle:
// 360 / NUM), each as hei.254's [model], up to RTP between them (straight, VARI 2nd digit 0).
constexpr SinNames kSlot2Names{"RTP", "RFP", "SDIS", "_MID", "_FAL", nullptr, "FFP1", "FFD",
                               "CDIR", nullptr, nullptr, nullptr, true};

bool sinSlot2(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!sinPocketJob(a, ctx, kSlot2Names, m, err)) return false;
  // VARI 1st digit: 0 complete, 1 roughing, 2 finishing (wall and floor), 3 edge finishing, 5 chamfer.
  const double vari = a.get("VARI");
  switch (digit(vari, 1)) {
  case 0: m.op = 0, m.wallPass = m.sideAllowance > 0; break;
  case 1: m.op = 1; break;
  case 2: m.op = 2, m.wallPass = m.floorPass = true; break;
  case 3: m.op = 2, m.wallPass = true; break;
  case 5: return fail(err, "VARI 5 (chamfering) needs the tool's point angle: not supported");
  default: return fail(err, "VARI 1st digit must be 0 (complete), 1 (roughing), 2 (finishing), 3 (edge finishing) or 5 (chamfering)");
  }
  if (digit(vari, 2) == 1) return fail(err, "VARI 2nd digit 1 (positioning between the slots on the circle) is not supported");
  int n;
  const double num = a.get("NUM"), width = a.get("WID"), rad = a.get("RAD"), afsl = a.get("AFSL");
  if (!(num >= 1) || num != std::floor(num) || num > 99999) return fail(err, "NUM must be a count 1..99999");
  n = (int)num;
  if (!(width > 0) || !(rad > 0)) return fail(err, "WID (slot width) and RAD (circle radius) must be greater than 0");
  if (!(afsl > 0) || afsl >= 360) return fail(err, "AFSL (the slots' angle) must lie between 0 and 360");
  // 4th digit: 1 full circle, 2 pitch circle, 0 (compatibility): INDA 0 is the full circle.
  const int form = digit(vari, 4);
  const double inda = form == 1 || (form == 0 && a.get("INDA") == 0) ? 360.0 / n : a.get("INDA");
  if (n > 1 && std::fabs(inda) < afsl) return fail(err, "the slots overlap: AFSL is larger than the angle INDA between them");
  PlanePoint about{a.get("_CPA"), a.get("_CPO")};
  if (!a.has("_CPA") && !a.has("_CPO")) {
    const PlaneAxes ax = planeAxes((Plane)sinPlane(a, ctx));
    about = {ctx.position[ax.u], ctx.position[ax.v]};
  }
  return arcSlots(m, sinPlane(a, ctx), about, rad, width, afsl, a.get("STA1"), inda, n, "allowance _FAL", out, err);
}

const CycleDef kClearingEntries[] = {
    {"hei.251", "Q215 Q218 Q219 Q220 Q368 Q224 Q367 Q207 Q351 Q201 Q202 Q369 Q206 Q338 Q200 Q203 Q204 Q370 Q366 Q385 Q439",
     "Heidenhain rectangular pocket", hei251, nullptr},
    {"hei.252", "Q215 Q223 Q368 Q207 Q351 Q201 Q202 Q369 Q206 Q338 Q200 Q203 Q204 Q370 Q366 Q385 Q439",
     "Heidenhain circular pocket", hei252, nullptr},
    {"hei.253", "Q215 Q218 Q219 Q368 Q374 Q367 Q207 Q351 Q201 Q202 Q369 Q206 Q338 Q200 Q203 Q204 Q366 Q385 Q439",
     "Heidenhain slot milling", hei253, nullptr},
    {"hei.254",
     "Q215 Q219 Q368 Q375 Q367 Q216 Q217 Q376 Q248 Q378 Q377 Q207 Q351 Q201 Q202 Q369 Q206 Q338 Q200 Q203 Q204 Q366 "
     "Q385 Q439",
     "Heidenhain circular slot", hei254, nullptr},
    {"hei.256", "Q218 Q424 Q219 Q425 Q220 Q368 Q224 Q367 Q207 Q351 Q201 Q202 Q206 Q200 Q203 Q204 Q370 Q437 Q215 Q369 Q338 Q385",
     "Heidenhain rectangular stud", hei256, nullptr},
    {"hei.232", "Q389 Q225 Q226 Q227 Q386 Q218 Q219 Q202 Q369 Q370 Q207 Q385 Q253 Q200 Q357 Q204",
     "Heidenhain face milling", hei232, nullptr},
    {"sin.POCKET3",
     "_RTP _RFP _SDIS _DP _LENG _WID _CRAD _PA _PO _STA _MID _FAL _FALD _FFP1 _FFD _CDIR _VARI _MIDA _AP1 _AP2 _AD _RAD1 _DP1 "
     "_UMODE _FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik rectangular pocket", sinPocket3, nullptr},
    {"sin.POCKET4",
     "_RTP _RFP _SDIS _DP _CDIAM _PA _PO _MID _FAL _FALD _FFP1 _FFD _CDIR _VARI _MIDA _AP1 _AD _RAD1 _DP1 _UMODE _FS _ZFS "
     "_GMODE _DMODE _AMODE",
     "Sinumerik circular pocket", sinPocket4, nullptr},
    {"sin.SLOT1",
     "RTP RFP SDIS _DP _DPR NUM LENG WID _CPA _CPO RAD STA1 INDA FFD FFP1 _MID CDIR _FAL VARI _MIDF FFP2 SSF _FALD _STA2 "
     "_DP1 _UMODE _FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik longitudinal slot", sinSlot1, nullptr},
    {"sin.SLOT2",
     "RTP RFP SDIS _DP _DPR NUM AFSL WID _CPA _CPO RAD STA1 INDA FFD FFP1 _MID CDIR _FAL VARI _MIDF FFP2 SSF _FFCP _UMODE "
     "_FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik circumferential slots", sinSlot2, nullptr},
    {"sin.LONGHOLE",
     "RTP _RFP SDIS _DP _DPR NUM LENG _CPA _CPO RAD STA1 INDA FFD FFP1 MID _VARI _UMODE _GMODE _DMODE _AMODE",
     "Sinumerik elongated hole", sinLonghole, nullptr},
    {"hei.257", "Q223 Q222 Q368 Q207 Q351 Q201 Q202 Q206 Q200 Q203 Q204 Q370 Q376 Q215 Q369 Q338 Q385",
     "Heidenhain circular stud", hei257, nullptr},
};

}  // namespace

void addClearingEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kClearingEntries) out.push_back(d);
}

}  // namespace ncc
