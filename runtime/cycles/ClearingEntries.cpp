// The pocket, stud, slot and face entries of the cycle library: each maps its manual's parameter
// list onto the Heidenhain 25x milling options (HeiMill) and a shape (the finished wall as a
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

// ---- Heidenhain 25x: the parameters every pocket, slot and stud cycle shares (seed002a
// "Pocket / stud / slot cycles: shared semantics").
struct HeiMill {
  HeiLevels lv;
  double surface = 0, depth = 0;  // Q203; |Q201|
  double infeed = 0;              // Q202
  double sideAllowance = 0, floorAllowance = 0, finishInfeed = 0;  // Q368 Q369 Q338
  double clearance = 0;           // |Q200|
  double plungeFeed = 0, millFeed = 0, finishFeed = 0;  // Q206 Q207 Q385 (0: Q207)
  int op = 0;                     // Q215: 0 rough and finish, 1 rough, 2 finish
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

// False with err empty when the depth is 0 (the TNC does not run the cycle).
bool heiMill(const CycleArgs &a, const CycleContext &ctx, double minOverlap, HeiMill &m, std::string &err) {
  err.clear();
  if (!heiLevels(a, m.lv, err)) return false;
  if (a.get("Q201") == 0) return false;
  if (!(ctx.toolRadius > 0))
    return fail(err, "needs the active tool's radius (a tool with a radius in the tool table; ncc cycle --tool-radius)");
  m.r = ctx.toolRadius;
  m.surface = a.get("Q203"), m.depth = std::fabs(a.get("Q201"));
  m.clearance = std::fabs(a.get("Q200"));
  double op, climb, overlap;
  if (!param(a, "Q215", 0, 2, op, err) || op != std::floor(op)) return err.empty() ? fail(err, "Q215 must be 0, 1 or 2") : false;
  m.op = (int)op;
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
  return true;
}

// A pocket in its own frame (centre at the origin): the finished wall and the tool-centre path
// that finishes it, which starts at the middle of a side with outward normal `normal`; `room`
// bounds the radius of the arcs onto and off it.
struct PocketShape {
  Contour wall, finish;
  PlanePoint normal{1, 0};
  double room = 0;
};

bool rings(const HeiMill &m, const PocketShape &p, double allowance, std::vector<Polygon> &out, std::string &err) {
  ClearingSpec s;
  s.contour = contourPolygon(p.wall, kChordTolerance);
  s.toolRadius = m.r, s.stepover = m.stepover, s.allowance = allowance, s.chordTolerance = kChordTolerance;
  return clearingRings(s, out, err);
}

// Heidenhain 251/252 (seed002a L5830-5886, L6143-6241): roughing level by level (plunge at the
// centre, rings from the middle to the wall less the allowances, up by Q200 and back to the centre
// at rapid), then the walls in Q338 infeeds (onto and off the wall on quarter arcs), then the floor
// from the middle out; the tool ends at the 2nd set-up clearance above the call position.
bool heiPocket(const HeiMill &m, const PocketShape &p, Mill &mill, std::string &err) {
  const PlanePoint centre{0, 0};
  const double roughDepth = m.depth - m.floorAllowance;
  if (m.roughing()) {
    std::vector<Polygon> rough;
    if (!rings(m, p, m.sideAllowance, rough, err)) return false;
    mill.go(centre, m.lv.zsc);
    for (double t : infeeds(m.infeed, roughDepth)) {
      mill.feed(centre, m.level(t), m.plungeFeed);
      for (const Polygon &ring : rough) mill.ring(ring, m.ccw, m.level(t), m.millFeed);
      mill.up(m.level(t - m.clearance));
      mill.go(centre, m.level(t - m.clearance));
    }
  }
  if (m.finishing() && m.sideAllowance > 0) {
    // [model] onto the wall on a quarter arc of radius Q368 + Q200 (at most `room`), tangent at the
    // path's start, and off it on the mirrored quarter.
    const double rho = std::min(m.sideAllowance + m.clearance, p.room);
    const PlanePoint at = p.finish.start, n = p.normal;
    const PlanePoint t = m.ccw ? rot90(n) : PlanePoint{-rot90(n)[0], -rot90(n)[1]};
    const PlanePoint q = along(at, n, -rho), from = along(q, t, -rho), to = along(q, t, rho);
    // Between passes the tool crosses over the roughed floor, not through the floor allowance.
    double link = -m.clearance;
    for (double s : infeeds(m.finishInfeed, m.depth)) {
      mill.go(from, m.level(link));
      mill.feed(from, m.level(s), m.plungeFeed);
      if (rho > 0) mill.arc(at, q, m.ccw, m.level(s), m.finishFeed);
      mill.run(p.finish, m.ccw, m.level(s), m.finishFeed);
      if (rho > 0) mill.arc(to, q, m.ccw, m.level(s), m.finishFeed);
      link = std::min(s, roughDepth) - m.clearance;
      mill.up(m.level(link));
    }
  }
  if (m.finishing() && m.floorAllowance > 0) {
    // The walls are finished (or have no allowance): rings out to the wall itself.
    std::vector<Polygon> floor;
    if (!rings(m, p, 0, floor, err)) return false;
    mill.go(centre, m.level(roughDepth - m.clearance));
    mill.feed(centre, m.level(m.depth), m.plungeFeed);
    for (const Polygon &ring : floor) mill.ring(ring, m.ccw, m.level(m.depth), m.finishFeed);
    mill.up(m.level(m.depth - m.clearance));
  }
  return true;
}

// The end of every Heidenhain 25x cycle: up to the 2nd set-up clearance, then over the call
// position (the pockets' start position).
void heiEnd(const HeiMill &m, int plane, Mill &mill) {
  std::array<double, 3> end = m.call;
  end[planeAxes((Plane)plane).n] = m.lv.z2;
  mill.goProgram(end);
}

// The corner Q367 puts at the tool (1 lower left … 4 upper left) as a multiple of the half sides.
constexpr double kCorner[5][2] = {{0, 0}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

bool hei251(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HeiMill m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  double L = a.get("Q218"), W = a.get("Q219"), rc = a.get("Q220"), pos;
  if (!(L > 0) || !(W > 0)) return fail(err, "Q218 and Q219 (side lengths) must be greater than 0");
  if (!param(a, "Q367", 0, 4, pos, err) || pos != std::floor(pos)) return err.empty() ? fail(err, "Q367 must be 0 … 4") : false;
  if (rc == 0) rc = m.r;  // the manual: 0 means the tool radius
  if (rc < m.r) return fail(err, "Q220 (corner radius) is smaller than the tool radius: the tool cannot cut the corners");
  if (2 * rc > std::min(L, W)) return fail(err, "Q220 (corner radius) is larger than half the shorter side");
  if (2 * (m.r + m.sideAllowance) >= std::min(L, W))
    return fail(err, "the tool with the side allowance Q368 does not fit into the pocket");
  PocketShape p;
  p.wall = roundedRect(L / 2, W / 2, rc);
  double a2 = L / 2 - m.r, b2 = W / 2 - m.r;
  p.finish = roundedRect(a2, b2, rc - m.r);
  p.room = std::min(a2, b2) / 2;
  // Q367 places the pocket's corner at the tool; Q224 turns the pocket about the tool.
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  double s, c, angle = a.get("Q224");
  sinCosDegrees(angle, s, c);
  double du = -kCorner[(int)pos][0] * L / 2, dv = -kCorner[(int)pos][1] * W / 2;
  PlanePoint origin{ctx.position[ax.u] + c * du - s * dv, ctx.position[ax.v] + s * du + c * dv};
  Mill mill(out, ctx.plane, origin, angle, m.lv.dir, ctx.position);
  if (!heiPocket(m, p, mill, err)) return false;
  heiEnd(m, ctx.plane, mill);
  return true;
}

bool hei252(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HeiMill m;
  if (!heiMill(a, ctx, 0.1, m, err)) return err.empty();
  double d = a.get("Q223");
  if (!(d > 0)) return fail(err, "Q223 (pocket diameter) must be greater than 0");
  if (2 * (m.r + m.sideAllowance) >= d) return fail(err, "the tool with the side allowance Q368 does not fit into the pocket");
  PocketShape p;
  p.wall = circleContour(d / 2);
  p.finish = circleContour(d / 2 - m.r);
  p.room = (d / 2 - m.r) / 2;
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  Mill mill(out, ctx.plane, {ctx.position[ax.u], ctx.position[ax.v]}, 0, m.lv.dir, ctx.position);
  if (!heiPocket(m, p, mill, err)) return false;
  heiEnd(m, ctx.plane, mill);
  return true;
}

const CycleDef kClearingEntries[] = {
    {"hei.251", "Q215 Q218 Q219 Q220 Q368 Q224 Q367 Q207 Q351 Q201 Q202 Q369 Q206 Q338 Q200 Q203 Q204 Q370 Q366 Q385 Q439",
     "Heidenhain rectangular pocket", hei251, nullptr},
    {"hei.252", "Q215 Q223 Q368 Q207 Q351 Q201 Q202 Q369 Q206 Q338 Q200 Q203 Q204 Q370 Q366 Q385 Q439",
     "Heidenhain circular pocket", hei252, nullptr},
};

}  // namespace

void addClearingEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kClearingEntries) out.push_back(d);
}

}  // namespace ncc
