// Heidenhain thread milling 262, 263, 264, 265, 267 (seed002a 5.5-5.10, L4552-L5624): a thread
// helix on the tool-centre circle, entered and left on tangential half circles, with the
// countersinking and drilling steps of 263-267. docs/CYCLES.md "Heidenhain thread milling" gives
// the model and what the manual leaves open.
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/HeiDrill.h"
#include "runtime/cycles/Mill.h"
#include "runtime/cycles/ThreadMill.h"
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

// The machining direction (L4627-L4640, L4875-L4893): the sign of the first non-zero depth in
// the manual's order; depths of other signs are refused (the manual's collision warning).
bool depthSign(const CycleArgs &a, std::initializer_list<const char *> depths, double &dir, std::string &err) {
  const char *first = nullptr;
  for (const char *k : depths) {
    if (a.get(k) == 0) continue;
    if (!first) {
      first = k, dir = a.get(k) < 0 ? -1 : 1;
    } else if ((a.get(k) < 0 ? -1 : 1) != dir) {
      return fail(err, fmt::format("{} and {} have different signs: every depth of the cycle takes the same sign", first, k));
    }
  }
  return true;
}

bool positive(const CycleArgs &a, const char *k, double &v, std::string &err, const char *what) {
  v = a.get(k);
  if (!(v > 0)) return fail(err, fmt::format("{} ({}) must be greater than 0", k, what));
  return true;
}

// The parts every thread cycle shares: levels, pitch, the tool-centre circle, the feeds.
// `outside`: 267; `depths`: the depths that set the direction, in the manual's order.
bool threadSetup(const CycleArgs &a, const CycleContext &ctx, bool outside, std::initializer_list<const char *> depths,
                 Thread &t, std::string &err) {
  if (!need(a, {"Q335", "Q239", "Q201", "Q200", "Q203", "Q207", "Q253"}, err)) return false;
  if (!depthSign(a, depths, t.dir, err)) return false;
  for (const char *k : {"Q200", "Q204", "Q357", "Q359", "Q202", "Q257", "Q256", "Q258"})
    if (a.get(k) < 0) return fail(err, fmt::format("{} must not be negative", k));
  t.surface = a.get("Q203");
  t.zsc = t.surface - t.dir * a.get("Q200");
  t.z2 = t.surface - t.dir * std::max(a.get("Q200"), a.get("Q204"));
  if (!positive(a, "Q335", t.radius, err, "nominal diameter")) return false;
  t.radius /= 2;
  t.pitch = std::fabs(a.get("Q239"));
  if (a.get("Q201") != 0 && (t.pitch == 0 || t.pitch > 99.9999))
    return fail(err, "Q239 (thread pitch) must be non-zero and at most 99.9999 in size");
  if (!(ctx.toolRadius > 0)) return fail(err, "thread milling needs the tool's radius (a tool with a radius in the spindle)");
  t.centre = outside ? t.radius + ctx.toolRadius : t.radius - ctx.toolRadius;
  if (!(t.centre > 1e-9)) return fail(err, "Q335 (nominal diameter) is not larger than the tool's diameter");
  const double q351 = a.get("Q351");
  if (q351 != 0 && q351 != 1 && q351 != -1) return fail(err, "Q351 (climb or up-cut) must be +1, 0 or -1");
  // Climb milling with M3 (L4565-L4610): counter-clockwise inside a bore, clockwise round a stud.
  t.ccw = (q351 >= 0) != outside;
  if (!positive(a, "Q207", t.mill, err, "milling feed") || !positive(a, "Q253", t.pre, err, "pre-positioning feed"))
    return false;
  t.approach = a.get("Q512") > 0 ? a.get("Q512") : t.mill;
  return true;
}

// Cycles 262, 263, 264, 267 run only with right-hand rotating tools (L4563-L4565).
bool rightHandTool(const CycleContext &ctx, std::string &err) {
  if (ctx.spindle == 2) return fail(err, "this cycle runs only with a right-hand rotating tool (M3), not M4");
  return true;
}

// The helix moves out of the material (bottom up) when its turning sense and the thread's hand
// lift it against the depth (the manual's table L4565-L4610: a right-hand helix rises turning
// counter-clockwise about the tool axis).
bool bottomUp(const Thread &t, double q239) {
  const double rise = (q239 > 0) == t.ccw ? 1 : -1;  // along the tool axis (+n)
  return rise == -t.dir;
}

// A half circle along the radius at `angle` between `from` and `to` (the start point's radius and
// a circle's): tangent there to that circle about the origin and turning with it, which from a
// start point inside the circle is the same way round, from one outside the other way.
void halfCircle(Mill &m, const Thread &t, double from, double to, double angle, double level, double f) {
  const double c = std::cos(angle), s = std::sin(angle), mid = (from + to) / 2;
  const double ring = from == t.start ? to : from;
  m.arc({to * c, to * s}, {mid * c, mid * s}, t.start < ring ? t.ccw : !t.ccw, level, f);
}

// Once round the circle of radius `r` about the origin at `level`: in from the start point on a
// half circle, round, back on the other half (263-267 countersinking, uncompensated, L4840-L4848).
void countersinkCircle(Mill &m, const Thread &t, double r, double level, double f) {
  if (r <= 0 || r == t.start) {
    if (r > 0) m.arc({r, 0}, {0, 0}, t.ccw, level, f);
    return;
  }
  halfCircle(m, t, t.start, r, 0, level, f);
  m.arc({r, 0}, {0, 0}, t.ccw, level, f);
  halfCircle(m, t, r, t.start, 0, level, f);
}

// The thread between the surface and the depth L by Q355 (L4745-L4752): 0 one helix at the
// depth, 1 one helix over the whole length, k > 1 helices of one turn, each shifted k pitches;
// bottom up from the depth or top down from the surface as the direction rules say.
void threadHelices(Mill &m, const Thread &t, double q239, double length, int perStep) {
  const bool up = bottomUp(t, q239);
  if (perStep == 1) {
    up ? helix(m, t, length, 0) : helix(m, t, 0, length);
    return;
  }
  const double shift = perStep * t.pitch;
  const int n = perStep == 0 ? 1 : std::max(1, (int)std::ceil(length / shift - 1e-9));
  for (int k = 0; k < n; ++k) {
    const double deep = length - (up ? k : n - 1 - k) * shift;
    up ? helix(m, t, deep, deep - t.pitch) : helix(m, t, deep - t.pitch, deep);
  }
}

bool perStep(const CycleArgs &a, int &k, std::string &err) {
  const double v = a.get("Q355");
  if (v < 0 || v > 99999 || v != std::floor(v)) return fail(err, "Q355 (threads per step) must be a whole number 0..99999");
  k = (int)v;
  return true;
}

Mill holeMill(const CycleContext &ctx, const Thread &t, std::vector<CycleStep> &out) {
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  return Mill(out, ctx.plane, {ctx.position[ax.u], ctx.position[ax.v]}, 0, t.dir, ctx.position);
}

// The front countersink of 263-267 (Q358 depth, Q359 the tool centre's offset): to the depth at
// `feed`, round at Q254.
bool frontCountersink(const CycleArgs &a, Mill &m, const Thread &t, double feed, std::string &err) {
  if (a.get("Q358") == 0) return true;
  double q254;
  if (!positive(a, "Q254", q254, err, "countersinking feed")) return false;
  m.feed({t.start, 0}, t.level(std::fabs(a.get("Q358"))), feed);
  countersinkCircle(m, t, a.get("Q359"), m.level(), q254);
  return true;
}

// The thread depth at least a third of the pitch short of the hole's (L4894-L4896, L5098-L5100).
bool thirdOfPitch(const CycleArgs &a, const Thread &t, std::string &err) {
  if (a.get("Q356") == 0 || a.get("Q201") == 0) return true;
  if (std::fabs(a.get("Q201")) > std::fabs(a.get("Q356")) - t.pitch / 3 + 1e-9)
    return fail(err, "Q201 (thread depth) must be at least a third of the pitch less than Q356");
  return true;
}

// 262 THREAD MILLING (L4656-L4816).
bool hei262(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  Thread t;
  int k;
  if (!threadSetup(a, ctx, false, {"Q201"}, t, err) || !perStep(a, k, err) || !rightHandTool(ctx, err)) return false;
  if (a.get("Q201") == 0) return true;  // the TNC does not run the cycle
  Mill m = holeMill(ctx, t, out);
  m.up(t.zsc);
  threadHelices(m, t, a.get("Q239"), std::fabs(a.get("Q201")), k);
  m.up(t.z2);
  return true;
}

// 263 THREAD MILLING/COUNTERSINKING (L4817-L5019), its first operation: countersinking at Q356
// on the core diameter (Q253 to Q200 short of the depth, Q254 on; with Q357 at Q253 straight to
// it), in on a half circle, round, back.
bool sink263(const CycleArgs &a, const CycleContext &ctx, Mill &m, const Thread &t, std::string &err) {
  const double sink = std::fabs(a.get("Q356"));
  if (sink == 0) return true;
  double q254;
  if (!positive(a, "Q254", q254, err, "countersinking feed")) return false;
  if (t.pitch == 0) return fail(err, "Q239 (thread pitch) must not be 0: the core diameter follows from it");
  // [model] the core diameter of ISO 68-1: D - 1.0825 P (5/8 of the fundamental triangle, twice).
  const double core = t.radius - 0.54127 * t.pitch - ctx.toolRadius;
  if (!(core > 1e-9)) return fail(err, "the tool does not fit the thread's core diameter (Q335 - 1.0825 x Q239)");
  if (a.get("Q357") > 0) {
    m.feed({0, 0}, t.level(sink), t.pre);  // clear of the wall: straight to the depth (L4833-L4836)
  } else {
    m.feed({0, 0}, t.level(sink - a.get("Q200")), t.pre);
    m.feed({0, 0}, t.level(sink), q254);
  }
  countersinkCircle(m, t, core, m.level(), q254);
  return true;
}

// 264 THREAD DRILLING/MILLING (L5020-L5255), its first operation: drilling to Q356 in infeeds
// of Q202 from the surface, chip breaks every Q257 (back Q256 at rapid) or, without them, after
// each infeed a rapid to the set-up clearance and back to Q258 above the depth reached.
bool drill264(const CycleArgs &a, const CycleContext &, Mill &m, const Thread &t, std::string &err) {
  const double depth = std::fabs(a.get("Q356"));
  if (depth == 0) return true;
  PeckPlan p;
  if (!positive(a, "Q206", p.feed, err, "plunging feed")) return false;
  p.surface = t.surface, p.dir = t.dir, p.depth = depth, p.infeed = a.get("Q202");
  p.chipEvery = a.get("Q257"), p.chipBack = a.get("Q256");
  p.removal = -a.get("Q200"), p.advFirst = p.advLast = a.get("Q258");
  return peckDrill(m, p, err);
}

// 263 and 264: the first operation, the front countersink, one thread turn at the depth.
using HoleOp = bool (*)(const CycleArgs &, const CycleContext &, Mill &, const Thread &, std::string &);
bool holeThread(const CycleArgs &a, const CycleContext &ctx, HoleOp first, std::vector<CycleStep> &out, std::string &err) {
  Thread t;
  if (!threadSetup(a, ctx, false, {"Q201", "Q356", "Q358"}, t, err) || !rightHandTool(ctx, err) ||
      !thirdOfPitch(a, t, err))
    return false;
  Mill m = holeMill(ctx, t, out);
  m.up(t.zsc);
  if (!first(a, ctx, m, t, err) || !frontCountersink(a, m, t, t.pre, err)) return false;
  if (a.get("Q201") != 0) threadHelices(m, t, a.get("Q239"), std::fabs(a.get("Q201")), 0);
  m.up(t.z2);
  return true;
}

bool hei263(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  return holeThread(a, ctx, sink263, out, err);
}

bool hei264(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  return holeThread(a, ctx, drill264, out, err);
}

// 265 HELICAL THREAD DRILLING/MILLING (L5256-L5426): always from the surface into the material
// (L5322-L5327), so the helix turns as the hand says (right-hand: clockwise down); the front
// countersink before (Q360 0, to the depth at Q254) or after the thread (1, at Q253). Both tool
// hands run (L4566).
bool hei265(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  Thread t;
  if (!threadSetup(a, ctx, false, {"Q201", "Q358"}, t, err)) return false;
  const double q360 = a.get("Q360");
  if (q360 != 0 && q360 != 1) return fail(err, "Q360 (countersinking before or after) must be 0 or 1");
  t.ccw = (a.get("Q239") > 0) == (t.dir > 0);
  Mill m = holeMill(ctx, t, out);
  m.up(t.zsc);
  if (q360 == 0 && !frontCountersink(a, m, t, a.get("Q254"), err)) return false;
  if (a.get("Q201") != 0) helix(m, t, 0, std::fabs(a.get("Q201")));
  if (q360 == 1 && !frontCountersink(a, m, t, t.pre, err)) return false;
  m.up(t.z2);
  return true;
}

// 267 OUTSIDE THREAD MILLING (L5427-L5624): from the stud's centre along the main axis to the
// start point (thread radius + tool radius + pitch, [model]), the front countersink from there,
// the helices as 262's on the outside, back to the start point over the stud.
bool hei267(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  Thread t;
  int k;
  if (!threadSetup(a, ctx, true, {"Q201", "Q358"}, t, err) || !perStep(a, k, err) || !rightHandTool(ctx, err))
    return false;
  if (t.pitch == 0) return fail(err, "Q239 (thread pitch) must not be 0: the start point follows from it");
  t.start = t.centre + t.pitch;
  Mill m = holeMill(ctx, t, out);
  m.up(t.zsc);
  m.rapid({t.start, 0}, t.zsc);
  if (!frontCountersink(a, m, t, t.pre, err)) return false;
  if (a.get("Q201") != 0) threadHelices(m, t, a.get("Q239"), std::fabs(a.get("Q201")), k);
  m.up(t.z2);
  if (m.here() != PlanePoint{t.start, 0}) m.rapid({t.start, 0}, t.z2);
  return true;
}

}  // namespace

// One helix from depth `from` to depth `to`: along the axis at Q253 to the starting plane, the
// compensating move, the tangential approach (a helical half circle climbing with the helix's
// slope), |to - from| / pitch turns at the milling feed (referred to the cutting edge: the
// tool-centre feed is Q207 x centre / radius, L4613-L4618), the tangential departure back to the
// start point's radius at Q512.
void entry::helix(Mill &m, const Thread &t, double from, double to) {
  const double way = to > from ? 1 : -1, rho = std::fabs(t.centre - t.start) / 2;
  const double lead = t.pitch * rho / (2 * t.centre);  // the half circle's share of the depth
  const PlanePoint start{t.start, 0};
  auto pre = [&](double level) { t.pre > 0 ? m.feed(start, level, t.pre) : m.rapid(start, level); };
  if (m.level() != t.level(from)) pre(t.level(from));
  pre(t.level(from - way * lead));
  halfCircle(m, t, t.start, t.centre, 0, t.level(from), t.approach);
  const double turns = std::fabs(to - from) / t.pitch, whole = std::floor(turns + 1e-9), part = turns - whole;
  const double angle = part < 1e-9 ? 0 : (t.ccw ? 1 : -1) * part * 2 * M_PI;
  m.arc({t.centre * std::cos(angle), t.centre * std::sin(angle)}, {0, 0}, t.ccw, t.level(to),
        t.mill * t.centre / t.radius, part < 1e-9 ? (int)whole : (int)whole + 1);
  halfCircle(m, t, t.centre, t.start, angle, t.level(to + way * lead), t.approach);
}

namespace {

const CycleDef kThreadMillEntries[] = {
    {"hei.262", "Q335 Q239 Q201 Q355 Q253 Q351 Q200 Q203 Q204 Q207 Q512", "Heidenhain thread milling", hei262, nullptr},
    {"hei.263", "Q335 Q239 Q201 Q356 Q253 Q351 Q200 Q357 Q358 Q359 Q203 Q204 Q254 Q207 Q512",
     "Heidenhain thread milling/countersinking", hei263, nullptr},
    {"hei.264", "Q335 Q239 Q201 Q356 Q253 Q351 Q202 Q258 Q257 Q256 Q358 Q359 Q200 Q203 Q204 Q206 Q207 Q512",
     "Heidenhain thread drilling/milling", hei264, nullptr},
    {"hei.265", "Q335 Q239 Q201 Q253 Q358 Q359 Q360 Q200 Q203 Q204 Q254 Q207",
     "Heidenhain helical thread drilling/milling", hei265, nullptr},
    {"hei.267", "Q335 Q239 Q201 Q355 Q253 Q351 Q200 Q358 Q359 Q203 Q204 Q254 Q207 Q512",
     "Heidenhain outside thread milling", hei267, nullptr},
};

}  // namespace

void addHeiThreadMillEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kThreadMillEntries) out.push_back(d);
}

}  // namespace ncc
