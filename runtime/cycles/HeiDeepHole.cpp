// Heidenhain 204 BACK BORING, 205 UNIVERSAL PECKING and 241 SINGLE-LIP DEEP-HOLE DRILLING
// (seed002a 4.7, 4.8, 4.10, L2589-L3752). docs/CYCLES.md "Heidenhain deep holes and back boring".
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/HeiDrill.h"
#include "runtime/cycles/Hole.h"
#include "runtime/Geometry.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

bool need(const CycleArgs &a, std::initializer_list<const char *> ks, std::string &err) {
  for (const char *k : ks)
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  return true;
}

bool notNegative(const CycleArgs &a, std::initializer_list<const char *> ks, std::string &err) {
  for (const char *k : ks)
    if (a.get(k) < 0) return fail(err, fmt::format("{} must not be negative", k));
  return true;
}

// 204 BACK BORING (L2589-L2771): rapid to the set-up clearance, oriented stop at Q336, off centre
// by Q251 (Q214 1 -main axis, 2 -secondary, 3 +main, 4 +secondary), down through the hole at Q253
// until the edge is Q200 below the lower face (the tool's length is to the bar's bottom, the edge
// Q252 above it: L2649-L2654), back to the centre, spindle on, up at Q254 to the counterbore
// depth Q249 above the lower face, dwell Q255; [model] back down at Q253 to where it cut from,
// oriented stop, off centre, rapid to the 2nd set-up clearance (when larger), back to the centre,
// the spindle on again as before.
bool hei204(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (!need(a, {"Q200", "Q249", "Q250", "Q251", "Q252", "Q253", "Q254", "Q203", "Q214"}, err) ||
      !notNegative(a, {"Q200", "Q204", "Q255"}, err))
    return false;
  if (a.get("Q249") == 0) return true;  // depth 0: the TNC does not run the cycle
  if (a.get("Q249") < 0)
    return fail(err, "Q249 < 0 (a counterbore towards the tool's minus direction) is not simulated yet");
  for (const char *k : {"Q250", "Q251", "Q252"})
    if (!(a.get(k) > 0)) return fail(err, fmt::format("{} must be greater than 0", k));
  const int q214 = (int)a.get("Q214");
  if (q214 < 1 || q214 > 4 || q214 != a.get("Q214")) return fail(err, "Q214 (disengaging direction) must be 1..4");
  if (!(a.get("Q253") > 0) || !(a.get("Q254") > 0)) return fail(err, "Q253 and Q254 (feeds) must be greater than 0");
  if (ctx.spindle == 0) return fail(err, "204 needs the spindle turning (M3/M4) before the cycle");
  const double s = a.get("Q203"), lower = s - a.get("Q250"), edge = a.get("Q252");
  BackBoreSpec b;
  b.start = s + a.get("Q200");
  b.bottom = lower - a.get("Q200") - edge;
  b.cutLevel = lower + a.get("Q249") - edge;
  if (b.cutLevel >= s - edge)
    return fail(err, "Q249 (counterbore depth) must be less than the material thickness Q250");
  b.downFeed = a.get("Q253"), b.backDown = true;
  b.retractSet = true, b.retract = s + std::max(a.get("Q200"), a.get("Q204"));
  b.feed = a.get("Q254");
  b.dwell = a.get("Q255") > 0 ? a.get("Q255") : -1;
  b.orientAngle = a.get("Q336");
  b.spindle = ctx.spindle;
  static const int kAxis[] = {0, 0, 1, 0, 1};
  static const double kSign[] = {0, -1, -1, 1, 1};
  b.shift[kAxis[q214]] = a.get("Q251") * kSign[q214];
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  CycleStep up;
  up.pos = ctx.position, up.pos[ax.n] = b.start;
  out.push_back(up);
  backBoreSteps(b, ax.u, ax.v, ax.n, ctx.position[ax.u], ctx.position[ax.v], out);
  return true;
}

// A dwell of `seconds` (none when not above 0).
void dwell(std::vector<CycleStep> &out, double seconds) {
  if (!(seconds > 0)) return;
  CycleStep st;
  st.kind = CycleStepKind::Dwell;
  st.seconds = seconds;
  out.push_back(st);
}

// The deepened start of 205 and 241 (L3003-L3195): the drilling starts min(0.2 x Q379, Q200)
// above it, chips are removed min(0.8 x Q379, Q200) above it; without Q379 both at the set-up
// clearance.
struct DeepStart {
  double feedFrom, removal;  // depths from the surface (negative: above it)
};
DeepStart deepStart(const CycleArgs &a) {
  const double q379 = a.get("Q379"), q200 = a.get("Q200");
  if (!(q379 > 0)) return {-q200, -q200};
  return {q379 - std::min(0.2 * q379, q200), q379 - std::min(0.8 * q379, q200)};
}

struct DeepLevels {
  HeiLevels l;
  double surface;
};

// The levels of 205 and 241 (heiLevels), Q379 within the depth, the Q253 pre-positioning feed.
bool deepLevels(const CycleArgs &a, DeepLevels &d, std::string &err) {
  if (!heiLevels(a, d.l, err) || !notNegative(a, {"Q200", "Q204", "Q379", "Q202", "Q205", "Q212", "Q211"}, err))
    return false;
  d.surface = a.get("Q203");
  if (a.get("Q379") >= std::fabs(a.get("Q201")) && a.get("Q201") != 0)
    return fail(err, "Q379 (deepened starting point) must lie above the depth Q201");
  if (a.get("Q379") > 0 && !(a.get("Q253") > 0)) return fail(err, "Q253 (pre-positioning feed) must be greater than 0");
  return true;
}

// 205 UNIVERSAL PECKING (L2772-L3196): rapid to the set-up clearance; with Q379 at Q253 to the
// drilling start over the deepened start; infeeds of Q202 from there, each Q212 less down to Q205;
// chip breaks every Q257 (back Q256 at rapid) or, without them, after each infeed a rapid to the
// chip-removal position and back to the advance stop distance over the depth reached (Q258 for
// the first re-entry to Q259 for the last, evenly between); dwell Q211, out at Q208 (0: Q206) to
// the set-up clearance, rapid to the 2nd.
bool hei205(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  DeepLevels d;
  if (!deepLevels(a, d, err) || !notNegative(a, {"Q258", "Q259", "Q257", "Q256"}, err)) return false;
  if (a.get("Q201") == 0) return true;
  if (a.get("Q395") != 0) return fail(err, "Q395 = 1 (depth to the cylindrical part) needs the tool's point angle: not supported");
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  Mill m(out, ctx.plane, {ctx.position[ax.u], ctx.position[ax.v]}, 0, d.l.dir, ctx.position);
  PeckPlan p;
  p.surface = d.surface, p.dir = d.l.dir;
  const DeepStart ds = deepStart(a);
  m.up(d.l.zsc);
  if (a.get("Q379") > 0) m.feed({0, 0}, p.level(ds.feedFrom), a.get("Q253"));
  p.start = a.get("Q379"), p.depth = std::fabs(a.get("Q201"));
  p.infeed = a.get("Q202"), p.decrement = a.get("Q212"), p.minInfeed = a.get("Q205");
  p.chipEvery = a.get("Q257"), p.chipBack = a.get("Q256");
  p.removal = ds.removal, p.advFirst = a.get("Q258"), p.advLast = a.get("Q259");
  p.feed = a.get("Q206");
  if (!peckDrill(m, p, err)) return false;
  dwell(out, a.get("Q211"));
  m.feed({0, 0}, d.l.zsc, a.get("Q208") > 0 ? a.get("Q208") : p.feed);
  m.up(d.l.z2);
  return true;
}

void step(std::vector<CycleStep> &out, CycleStepKind k, double speed = 0, uint8_t coolant = 0) {
  CycleStep st;
  st.kind = k, st.speed = speed, st.coolant = coolant;
  out.push_back(st);
}

// Q426 3 M3, 4 M4, 5 stopped (the spindle direction entering and leaving the hole).
CycleStepKind spindleKind(int m) {
  return m == 3 ? CycleStepKind::SpindleCW : m == 4 ? CycleStepKind::SpindleCCW : CycleStepKind::SpindleStop;
}

// Q429/Q430: the coolant M functions ncc knows (M7 mist, M8 flood, M9 off); 0 none.
bool coolantM(const CycleArgs &a, const char *k, bool on, int &bits, std::string &err) {
  const double m = a.get(k);
  bits = m == 7 ? 2 : m == 8 ? 1 : 0;
  if (m == 0 || (on ? (m == 7 || m == 8) : m == 9)) return true;
  return fail(err, fmt::format("{}=M{:g}: a machine's own coolant function is not simulated ({} takes {})", k, m, k,
                               on ? "M7 or M8" : "M9"));
}

// 241 SINGLE-LIP DEEP-HOLE DRILLING (L3330-L3752): rapid to the set-up clearance; the spindle as
// Q426 at Q427 (entering); with Q379 at Q253 to the drilling start over the deepened start
// (205's rule); coolant M(Q429); [model] the spindle at Q428 in the direction it had before the
// cycle (M3 when it stood); drilling at Q206 in infeeds of Q202 (each Q212 less down to Q205),
// each ended by the dwell Q211 (the manual's steps 4-6 repeat the dwell with each infeed), the
// feed times Q401 % beyond the depth Q435; at the depth coolant M(Q430), the spindle as Q426 at
// Q427; out at Q208 (0: Q206) to the chip-removal position of 205's rule (the set-up clearance
// without Q379), rapid to the 2nd set-up clearance. The spindle stays at Q427 after the cycle [model] (L3366-L3369 set it at the depth).
bool hei241(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  DeepLevels d;
  if (!deepLevels(a, d, err) || !notNegative(a, {"Q427", "Q428", "Q435"}, err)) return false;
  if (a.get("Q201") == 0) return true;
  const double q426 = a.has("Q426") ? a.get("Q426") : 3, q401 = a.has("Q401") ? a.get("Q401") : 100;
  if (q426 != 3 && q426 != 4 && q426 != 5) return fail(err, "Q426 (spindle direction in and out) must be 3, 4 or 5");
  if (!(q401 > 0) || q401 > 100) return fail(err, "Q401 (feed factor) must be greater than 0 and at most 100");
  int on = 0, off = 0;
  if (!coolantM(a, "Q429", true, on, err) || !coolantM(a, "Q430", false, off, err)) return false;
  const double depth = std::fabs(a.get("Q201")), slow = a.get("Q435");
  if (slow >= depth) return fail(err, "Q435 (dwell depth) must be less than the depth Q201");
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  Mill m(out, ctx.plane, {ctx.position[ax.u], ctx.position[ax.v]}, 0, d.l.dir, ctx.position);
  const DeepStart ds = deepStart(a);
  const auto level = [&](double dd) { return d.surface + d.l.dir * dd; };
  m.up(d.l.zsc);
  const double inSpeed = a.has("Q427") && a.get("Q427") > 0 ? a.get("Q427") : ctx.speed;
  step(out, spindleKind((int)q426));
  if (q426 != 5) step(out, CycleStepKind::SpindleSpeed, inSpeed);
  if (a.get("Q379") > 0) m.feed({0, 0}, level(ds.feedFrom), a.get("Q253"));
  if (a.get("Q429") != 0) step(out, CycleStepKind::Coolant, 0, (uint8_t)on);
  step(out, ctx.spindle == 2 ? CycleStepKind::SpindleCCW : CycleStepKind::SpindleCW);
  step(out, CycleStepKind::SpindleSpeed, a.get("Q428") > 0 ? a.get("Q428") : ctx.speed);
  // The infeeds' ends as 205's, without chip breaks or retracts between them.
  const double feed = a.get("Q206");
  std::vector<double> ends;
  if (!infeedEnds(a.get("Q379"), depth, a.get("Q202"), a.get("Q212"), a.get("Q205"), ends, err)) return false;
  double at = a.get("Q379");
  for (double end : ends) {
    if (slow > 0 && at < slow && end > slow) m.feed({0, 0}, level(slow), feed);
    m.feed({0, 0}, level(end), slow > 0 && end > slow ? feed * q401 / 100 : feed);
    dwell(out, a.get("Q211"));
    at = end;
  }
  if (a.get("Q430") != 0) step(out, CycleStepKind::Coolant, 0, (uint8_t)off);
  step(out, spindleKind((int)q426));
  if (q426 != 5) step(out, CycleStepKind::SpindleSpeed, inSpeed);
  m.feed({0, 0}, level(ds.removal), a.get("Q208") > 0 ? a.get("Q208") : feed);
  m.up(d.l.z2);
  return true;
}

const CycleDef kDeepHoleEntries[] = {
    {"hei.204", "Q200 Q249 Q250 Q251 Q252 Q253 Q254 Q255 Q203 Q204 Q214 Q336", "Heidenhain back boring", hei204, nullptr},
    {"hei.205", "Q200 Q201 Q206 Q202 Q203 Q204 Q212 Q205 Q258 Q259 Q257 Q256 Q211 Q379 Q253 Q208 Q395",
     "Heidenhain universal pecking", hei205, nullptr},
    {"hei.241", "Q200 Q201 Q206 Q211 Q203 Q204 Q379 Q253 Q208 Q426 Q427 Q428 Q429 Q430 Q435 Q401 Q202 Q212 Q205",
     "Heidenhain single-lip deep-hole drilling", hei241, nullptr},
};

}  // namespace

void addHeiDeepHoleEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kDeepHoleEntries) out.push_back(d);
}

}  // namespace ncc
