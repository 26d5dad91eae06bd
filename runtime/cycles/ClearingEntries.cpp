// The Heidenhain pocket, slot, stud and face entries of the cycle library (seed002a 251-257,
// seed002b 232): each maps its parameter list onto a MillJob and a shape for the shared milling
// engine (Pocket.h); studs and face milling have their own paths here. docs/CYCLES.md lists the
// entries and marks the geometry the manuals show only in figures "[model]".
#include "runtime/Geometry.h"
#include "runtime/cycles/Hole.h"
#include "runtime/cycles/Pocket.h"
#include "runtime/cycles/Stud.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

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
  // The control shortens the infeed to the tool's cutting length LCUTS (seed002a L5919-5925).
  m.infeed = ctx.cuttingLength > 0 ? std::min(a.get("Q202"), ctx.cuttingLength) : a.get("Q202");
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

// The end of every Heidenhain 25x cycle: up to the 2nd set-up clearance, then over the call
// position (the pockets' start position).
void heiEnd(const MillJob &m, int plane, Mill &mill) {
  std::array<double, 3> end = m.call;
  end[planeAxes((Plane)plane).n] = m.lv.z2;
  mill.goProgram(end);
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
  // Q366 1 a helix about the centre, 2 to and fro along Q218 (the tool's centre reaches L/2 - R -
  // Q368 either way).
  if (!heiPlunge(a, ctx, true, 2, m, err) || !helixFits(m, std::min(L, W) / 2 - m.sideAllowance, err) ||
      !centredRamp(m, L / 2 - m.r - m.sideAllowance, err))
    return false;
  PocketShape p;
  p.wall = roundedRect(L / 2, W / 2, rc);
  double a2 = L / 2 - m.r, b2 = W / 2 - m.r;
  p.finish.path = roundedRect(a2, b2, rc - m.r);
  p.finish.room = std::min(a2, b2) / 2;
  // Q367 places the pocket's corner at the tool; Q224 turns the pocket about the tool.
  Mill mill = placed(out, ctx, m, {-kCorner[(int)pos][0] * L / 2, -kCorner[(int)pos][1] * W / 2}, a.get("Q224"));
  if (!millPocket(m, p, mill, err)) return false;
  heiEnd(m, ctx.plane, mill);
  return true;
}

bool hei252(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.1, m, err)) return err.empty();
  double d = a.get("Q223");
  if (!(d > 0)) return fail(err, "Q223 (pocket diameter) must be greater than 0");
  if (2 * (m.r + m.sideAllowance) >= d) return fail(err, "the tool with the side allowance Q368 does not fit into the pocket");
  // 252 knows Q366 0 and 1 (a helix); its vertical plunge wants a tool whose ANGLE is 0 or 90
  // (seed002a L6398-6404).
  if (!heiPlunge(a, ctx, true, 1, m, err) || !helixFits(m, d / 2 - m.sideAllowance, err)) return false;
  if (a.get("Q366") == 0 && ctx.plungeAngle != 0 && ctx.plungeAngle != 90)
    return fail(err, fmt::format("Q366 = 0 (vertical plunge) wants a tool whose plunge angle ANGLE is 0 or 90, not {}",
                                 ctx.plungeAngle));
  PocketShape p;
  p.wall = circleContour(d / 2);
  p.finish.path = circleContour(d / 2 - m.r);
  p.finish.room = (d / 2 - m.r) / 2;
  Mill mill = placed(out, ctx, m, {0, 0}, 0);
  if (!millPocket(m, p, mill, err)) return false;
  heiEnd(m, ctx.plane, mill);
  return true;
}

bool hei253(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  double L = a.get("Q218"), W = a.get("Q219");
  int pos;
  if (!(L > 0) || !(W > 0)) return fail(err, "Q218 (slot length) and Q219 (slot width) must be greater than 0");
  if (W > L) return fail(err, "Q219 (slot width) is larger than Q218 (slot length, the longer side)");
  if (!position(a, "Q367", 4, pos, err)) return false;
  // Q366 1 and 2: to and fro along the slot's centre line (seed002a L6471-6474, L6644-6648).
  if (!heiPlunge(a, ctx, false, 2, m, err)) return false;
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
  // Q366 1 and 2: to and fro along the slot's centre arc (seed002a L6736-6739: the process; the
  // parameter text's "helical" for 1 and 2, L6992-6996, contradicts it and 253).
  if (!heiPlunge(a, ctx, false, 2, m, err)) return false;
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

// ---- studs (256, 257, 258): the stud engine (Stud.h).
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
  s.reach = rectReach(s, BL / 2, BW / 2);
  s.approach = {BL / 2 + m.r + 2, 0};  // 2 mm outside the blank, right of the stud (Q437 0)
  Mill mill = placed(out, ctx, m, {-kCorner[pos][0] * L / 2, -kCorner[pos][1] * W / 2}, a.get("Q224"));
  millStud(m, s, mill);
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
  millStud(m, s, mill);
  return true;
}

// 258 (seed002a L7540-7809): a regular polygon of Q572 corners on the reference circle Q571
// (circumscribed, Q573 1: corners on it; inscribed, 0: sides touching it), its first corner at
// Q224, corners rounded by Q220, cut from a round blank Q222 as 256/257 [model: the approach 2 mm
// outside the blank on the first side's normal].
bool hei258(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!heiMill(a, ctx, 0.0001, m, err)) return err.empty();
  const double ref = a.get("Q571"), blank = a.get("Q222"), rc = a.get("Q220"), q573 = a.get("Q573");
  const double n = a.get("Q572");
  if (!(n >= 3 && n <= 30) || n != std::floor(n)) return fail(err, "Q572 (number of corners) must be 3 … 30");
  if (q573 != 0 && q573 != 1) return fail(err, "Q573 must be 0 (inscribed) or 1 (circumscribed)");
  if (!(ref > 0)) return fail(err, "Q571 (reference circle diameter) must be greater than 0");
  if (rc < 0) return fail(err, "Q220 < 0 (chamfered corners) is not supported: program a corner radius");
  StudShape s{polygonLap, 0, 0, rc};
  s.corners = (int)n;
  s.a = q573 == 1 ? ref / 2 * std::cos(M_PI / n) : ref / 2;  // the apothem
  if (rc > s.a) return fail(err, "Q220 (corner radius) is larger than the polygon's inscribed circle");
  if (!(blank / 2 > s.a)) return fail(err, "Q222 (blank diameter) must be larger than the polygon");
  s.reach = blank / 2 - s.a;  // the blank's farthest point lies off the middle of a side
  s.approach = {blank / 2 + m.r + 2, 0};
  Mill mill = placed(out, ctx, m, {0, 0}, a.get("Q224") - 180 / n);
  millStud(m, s, mill);
  return true;
}

// ---- Heidenhain 232 and 233 face milling (seed002b 3.6, L13993-14300; seed002a L7810-8244):
// lines across a rectangle from a start corner, `length` along the milling direction (its sign
// the direction of the first cut), `width` across (its sign the direction of the first
// stepover); levels from the surface down to the end, equal infeeds of at most Q202, the last
// removing Q369 at Q385. The digest's [model] for the line ends and spacing: lines R (tool
// radius) in from the sides, equally spaced at most Q370 x R apart; cuts start R + Q357 beside the
// surface and end as far beyond it (outside) or R inside its edge.
struct Face {
  PlanePoint corner{};       // the start corner (the first axis along the milling direction)
  bool acrossY = false;      // 233 Q350 2: the lines run along the second axis
  double length = 0, width = 0, top = 0, end = 0, allowance = 0, maxInfeed = 0, overlap = 1;
  double millFeed = 0, finishFeed = 0, posFeed = 0, clearance = 0, side = 0, z2 = 0;
  bool meander = true;       // else every line from the start side
  bool edge = false;         // the cuts end R inside the edge (232 Q389 1, 233 Q389 1 and 3)
  bool returnRapid = false;  // one-way lines: back at rapid (233), else at Q253 (232)
  bool rough = true, finish = true;  // 233 Q215
};

bool faceMill(const Face &f, const CycleContext &ctx, MillJob &m, std::vector<CycleStep> &out, std::string &err) {
  const double depth = f.top - f.end, r = m.r, L = f.length, W = f.width;
  if (depth < 0) return fail(err, "Q386 (end point in the tool axis) lies above the surface Q227");
  if (f.allowance >= depth) return fail(err, "Q369 (floor allowance) must be less than the depth Q227 - Q386");
  if (L == 0 || W == 0) return fail(err, "Q218 and Q219 (side lengths) must not be 0");
  if (!(f.maxInfeed > 0)) return fail(err, "Q202 (maximum plunging depth) must be greater than 0");
  if (depth / f.maxInfeed > kMaxPecks) return fail(err, "Q202 (maximum plunging depth) too small");
  if (!(f.millFeed > 0) || !(f.posFeed > 0)) return fail(err, "Q207 and Q253 (feeds) must be greater than 0");
  m.lv.dir = -1;  // the face lies below the surface along the tool axis
  m.surface = f.top;
  // Levels: equal infeeds down to Q386 + Q369, then Q369 at the finishing feed.
  std::vector<std::pair<double, double>> levels;  // depth below the surface, feed
  const int n = (int)std::ceil((depth - f.allowance) / f.maxInfeed - 1e-9);
  if (f.rough)
    for (int i = 1; i <= n; ++i) levels.push_back({(depth - f.allowance) * i / n, f.millFeed});
  if (f.finish && f.allowance > 0) levels.push_back({depth, f.finishFeed});
  if (levels.empty()) return true;
  // Lines across: R in from each side, equally spaced at most Q370 x R; one in the middle when
  // the width is at most the tool's diameter. (a, b): along the lines, across them.
  const double s1 = L > 0 ? 1 : -1, s2 = W > 0 ? 1 : -1, a0 = f.corner[0], b0 = f.corner[1];
  std::vector<double> lines;
  if (std::fabs(W) <= 2 * r) {
    lines.push_back(b0 + W / 2);
  } else {
    int k = (int)std::ceil((std::fabs(W) - 2 * r) / (f.overlap * r) - 1e-9);
    for (int i = 0; i <= k; ++i) lines.push_back(b0 + s2 * r + (W - 2 * s2 * r) * i / k);
  }
  const double outside = a0 - s1 * (r + f.side), beyond = a0 + L + s1 * (r + f.side);
  const double farEnd = f.edge ? a0 + L - s1 * r : beyond, nearEnd = f.edge ? a0 + s1 * r : outside;
  auto at = [&](double a, double b) { return f.acrossY ? PlanePoint{b, a} : PlanePoint{a, b}; };
  Mill mill(out, ctx.plane, {0, 0}, 0, m.lv.dir, ctx.position);
  double cur = outside;  // where the tool is along the lines
  mill.go(at(outside, lines[0]), f.z2);
  mill.up(f.top + f.clearance);
  bool forward = true;  // the order of the lines on this level
  for (size_t li = 0; li < levels.size(); ++li) {
    const double z = m.level(levels[li].first), feed = levels[li].second;
    for (size_t i = 0; i < lines.size(); ++i) {
      const double b = lines[forward ? i : lines.size() - 1 - i];
      if (!f.meander) {  // each line from the start side: over above the level, down, across
        if (i > 0 || li > 0) {
          mill.up(z + f.clearance);
          if (f.returnRapid) mill.rapid(at(outside, b), z + f.clearance);
          else mill.feed(at(outside, b), z + f.clearance, f.posFeed);
        }
        mill.feed(at(outside, b), z, f.posFeed);
        mill.feed(at(f.edge ? farEnd : beyond, b), z, feed);
        continue;
      }
      // Meander: down at the end of the line before (or the start), across, the next line back.
      if (i == 0) mill.feed(mill.here(), z, f.posFeed);
      else mill.feed(at(cur, b), z, f.edge ? feed : f.posFeed);
      cur = std::fabs(cur - farEnd) > std::fabs(cur - nearEnd) ? farEnd : nearEnd;
      mill.feed(at(cur, b), z, feed);
    }
    forward = !forward;  // the next level runs the lines back (seed002b L14043-14049)
  }
  mill.up(f.z2);
  return true;
}

// Both cycles' shared parameters: Q227 Q386 Q369 Q202 Q370 Q207 Q385 Q253 Q200 Q357 Q204.
bool faceParams(const CycleArgs &a, const CycleContext &ctx, Face &f, MillJob &m, std::string &err) {
  for (const char *k : {"Q227", "Q386", "Q218", "Q219", "Q202", "Q207"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (!toolRadius(ctx, m, err)) return false;
  if (!param(a, "Q369", 0, 99999.9999, f.allowance, err) || !param(a, "Q370", 0.1, 1.9999, f.overlap, err, 1)) return false;
  f.top = a.get("Q227"), f.end = a.get("Q386"), f.maxInfeed = a.get("Q202");
  f.length = a.get("Q218"), f.width = a.get("Q219");
  f.millFeed = a.get("Q207"), f.finishFeed = a.get("Q385") > 0 ? a.get("Q385") : f.millFeed;
  f.posFeed = a.get("Q253");
  f.clearance = std::fabs(a.get("Q200")), f.side = std::fabs(a.get("Q357"));
  f.z2 = f.top + std::max(f.clearance, std::fabs(a.get("Q204")));
  return true;
}

bool hei232(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"Q225", "Q226"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  Face f;
  MillJob m;
  int strategy;
  if (!faceParams(a, ctx, f, m, err) || !position(a, "Q389", 2, strategy, err)) return false;
  if (f.top == f.end) return true;  // the TNC does not run the cycle
  f.corner = {a.get("Q225"), a.get("Q226")};
  f.meander = strategy != 2, f.edge = strategy == 1;
  return faceMill(f, ctx, m, out, err);
}

// 233: as 232, the surface placed by Q367 (-1: its corner at the tool, Q218/Q219 signed as 232's;
// 0: its centre, 1-4: a corner as 251's, the sides then positive), the lines along the first
// (Q350 1) or the second axis (2), Q215 roughing and/or the Q369 finishing level, Q389 3 one way
// ending at the edge. Limits (Q347-Q349) and the spiral (Q389 4): errors.
bool hei233(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  Face f;
  MillJob m;
  int strategy, op, pos = 0;
  if (!faceParams(a, ctx, f, m, err) || !position(a, "Q389", 4, strategy, err) || !position(a, "Q215", 2, op, err))
    return false;
  if (strategy == 4) return fail(err, "Q389 4 (spiral from outside in) is not supported");
  if (ctx.cuttingLength > 0) f.maxInfeed = std::min(f.maxInfeed, ctx.cuttingLength);  // LCUTS (seed002a L7975-7979)
  for (const char *k : {"Q347", "Q348", "Q349"})
    if (a.get(k) != 0) return fail(err, std::string(k) + " (a limited side) is not supported: program 0");
  const double dirAxis = a.has("Q350") ? a.get("Q350") : 1;
  if (dirAxis != 1 && dirAxis != 2) return fail(err, "Q350 (milling direction) must be 1 or 2");
  if (a.get("Q367") != -1 && !position(a, "Q367", 4, pos, err)) return err.empty() ? fail(err, "Q367 must be -1 … 4") : false;
  if (f.top == f.end) return true;
  f.acrossY = dirAxis == 2;
  f.meander = strategy < 2, f.edge = strategy == 1 || strategy == 3, f.returnRapid = true;
  f.rough = op != 2, f.finish = op != 1;
  // Q218 runs along the first axis, Q219 along the second, whichever way the lines go.
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  const PlanePoint tool{ctx.position[ax.u], ctx.position[ax.v]};
  double q218 = a.get("Q218"), q219 = a.get("Q219");
  PlanePoint corner = tool;
  if (a.get("Q367") != -1) {
    q218 = std::fabs(q218), q219 = std::fabs(q219);
    corner = {tool[0] + (kCorner[pos][0] == 0 ? -q218 / 2 : kCorner[pos][0] < 0 ? 0 : -q218),
              tool[1] + (kCorner[pos][1] == 0 ? -q219 / 2 : kCorner[pos][1] < 0 ? 0 : -q219)};
  }
  f.corner = f.acrossY ? PlanePoint{corner[1], corner[0]} : corner;
  f.length = f.acrossY ? q219 : q218, f.width = f.acrossY ? q218 : q219;
  return faceMill(f, ctx, m, out, err);
}

// CYCLE61 (seed000c §19.1.11) on the face engine: the rectangle from corner (_PA, _PO) to
// (_LENG, _WID) (_AMODE 4th/5th digit 0: incremental lengths, 1: the absolute corner), levels
// from _RFP down to _DP (1st digit 0 abs, 1 below _RFP) in equal infeeds of at most _MID, the
// last leaving _FALD; lines at most _MIDA apart (2nd digit 1: % of the tool diameter) along the
// 1st (_VARI 2nd digit 1, 3) or 2nd axis (2, 4), one way (1, 2; back at rapid, lifted) or
// meander (3, 4); _VARI 1st digit 1 roughs, 2 removes _FALD. [model] as 232: the lines R in
// from the sides, the cuts from R + _SDIS outside to as far beyond; everything at _FFP1.
// Limited sides (_LIM) and a plane of its own (_DMODE) are errors.
bool sinCycle61(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"_RTP", "_RFP", "_DP", "_PA", "_PO", "_LENG", "_WID", "_MID", "_MIDA", "_FFP1", "_VARI"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (a.get("_LIM") != 0) return fail(err, "_LIM (a limited side) is not supported: program 0");
  if (digit(a.get("_DMODE"), 1) != 0) return fail(err, "_DMODE 1st digit (a plane of the cycle's own) is not supported");
  const double am = a.get("_AMODE"), vari = a.get("_VARI");
  const int op = digit(vari, 1), way = digit(vari, 2);
  if (op != 1 && op != 2) return fail(err, "_VARI 1st digit must be 1 (roughing) or 2 (finishing)");
  if (way < 1 || way > 4) return fail(err, "_VARI 2nd digit (milling direction) must be 1 … 4");
  Face f;
  MillJob m;
  if (!toolRadius(ctx, m, err)) return false;
  f.top = a.get("_RFP");
  f.end = digit(am, 1) == 1 ? f.top - std::fabs(a.get("_DP")) : a.get("_DP");
  f.clearance = f.side = std::fabs(a.get("_SDIS"));
  f.z2 = a.get("_RTP");
  if (f.end > f.top) return fail(err, "_DP (finished-part height) lies above the blank _RFP");
  if (f.z2 < f.top + f.clearance) return fail(err, "the retraction plane _RTP lies below _RFP + _SDIS");
  f.allowance = a.get("_FALD");
  if (f.allowance < 0 || (f.allowance >= f.top - f.end && f.end < f.top))
    return fail(err, "_FALD (finishing allowance) must be 0 or more and less than the depth");
  f.maxInfeed = a.get("_MID");
  if (!(f.maxInfeed > 0)) return fail(err, "_MID (maximum depth infeed) must be greater than 0");
  const double mida = digit(am, 2) == 1 ? a.get("_MIDA") / 100 * 2 * m.r : a.get("_MIDA");
  if (!(mida > 0)) return fail(err, "_MIDA (maximum plane infeed) must be greater than 0");
  f.overlap = mida / m.r;
  f.millFeed = f.finishFeed = f.posFeed = a.get("_FFP1");
  if (!(f.millFeed > 0)) return fail(err, "_FFP1 (machining feed) must be greater than 0");
  const PlanePoint c1{a.get("_PA"), a.get("_PO")};
  const double l1 = digit(am, 4) == 1 ? a.get("_LENG") - c1[0] : a.get("_LENG");
  const double l2 = digit(am, 5) == 1 ? a.get("_WID") - c1[1] : a.get("_WID");
  if (l1 == 0 || l2 == 0) return fail(err, "the rectangle has no area (_LENG, _WID)");
  f.acrossY = way == 2 || way == 4;
  f.corner = f.acrossY ? PlanePoint{c1[1], c1[0]} : c1;
  f.length = f.acrossY ? l2 : l1, f.width = f.acrossY ? l1 : l2;
  f.meander = way >= 3, f.returnRapid = true;
  f.rough = op == 1, f.finish = op == 2;
  if (f.top == f.end) return true;
  return faceMill(f, ctx, m, out, err);
}

const CycleDef kClearingEntries[] = {
    {"hei.258", "Q573 Q571 Q222 Q572 Q224 Q220 Q368 Q207 Q351 Q201 Q202 Q206 Q200 Q203 Q204 Q370 Q215 Q369 Q338 Q385",
     "Heidenhain polygon stud", hei258, nullptr},
    {"sin.CYCLE61", "_RTP _RFP _SDIS _DP _PA _PO _LENG _WID _MID _MIDA _FALD _FFP1 _VARI _LIM _DMODE _AMODE",
     "Sinumerik face milling", sinCycle61, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v"},
    {"hei.232", "Q389 Q225 Q226 Q227 Q386 Q218 Q219 Q202 Q369 Q370 Q207 Q385 Q253 Q200 Q357 Q204",
     "Heidenhain face milling", hei232, nullptr},
    {"hei.233",
     "Q215 Q389 Q350 Q218 Q219 Q227 Q386 Q369 Q202 Q370 Q207 Q385 Q253 Q357 Q200 Q204 Q347 Q348 Q349 Q220 Q368 Q338 Q367",
     "Heidenhain face milling with direction", hei233, nullptr},
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
    {"hei.257", "Q223 Q222 Q368 Q207 Q351 Q201 Q202 Q206 Q200 Q203 Q204 Q370 Q376 Q215 Q369 Q338 Q385",
     "Heidenhain circular stud", hei257, nullptr},
};

}  // namespace

void addClearingEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kClearingEntries) out.push_back(d);
}

}  // namespace ncc
