// Sinumerik stock removal on the lathe (SIN-CYC-25): CYCLE951, the simple turning cut (seed000c
// 19.1.42), and CYCLE95, stock removal along a named contour (19.1.28). The manual gives the parameters only; the corner's geometry and the cuts are ncc's
// model, docs/CYCLES.md "Sinumerik stock removal". The cycle builds the finished contour of the
// corner (with its radii and chamfers) and hands it to the stock removal of the ISO G71/G72
// consumers (runtime/cycles/Turning.h): one generator for the layers, the 45-degree lift and the
// pass along the contour. Lathe geometry in the ZX plane, program coordinates, x a radius (ncc
// runs Sinumerik in DIAMOF): absolute X values of the cycle are diameters, incremental ones radii.
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/TurnPath.h"
#include "runtime/cycles/Turning.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

constexpr double kEps = 1e-9;
constexpr double kMaxLayers = 10000;  // a tiny _MID for a large corner is an error, not a hang

// A point of the plane: a = Z, b = X (radius), as Contour.h.
Pt2 minus(Pt2 p, Pt2 q) { return {p.a - q.a, p.b - q.b}; }
double length(Pt2 d) { return std::hypot(d.a, d.b); }
Pt2 unit(Pt2 d) {
  const double l = length(d);
  return {d.a / l, d.b / l};
}

// The corner in its own frame: u along the part from the free face (Z0) inwards, w across from
// the finished edge X1 outwards to the blank's edge X0 (H). sz, sx map it to Z and X: front (the
// face towards +Z) sz = +1, back -1; outside (the blank's edge at the larger X) sx = +1, inside -1.
struct Corner {
  double z0 = 0, x0 = 0, x1 = 0;  // the face, the blank's edge and the finished edge (radius)
  double sz = 1, sx = 1;
  Pt2 at(double u, double w) const { return {z0 - sz * u, x1 + sx * w}; }
};

// The intermediate point M (_NR 2) in the corner frame from _ZPD/_ZPL as _DMODE 2nd digit says:
// the first edge runs from (0, 0) at angle a1 to the Z axis, the second to (u3, H) at angle a2 to
// the X axis; both angles open the corner towards the material (0: the 90-degree corner).
bool intermediate(const CycleArgs &a, const Corner &k, double u3, double H, Pt2 &m, std::string &err) {
  const int form = digit(a.get("_DMODE"), 2);
  const double amode = a.get("_AMODE");
  if (form > 5) return fail(err, "_DMODE 2nd digit (input form of the intermediate point) must be 0-5");
  // Which of _ZPD/_ZPL hold a position and which an angle.
  const bool xIsAngle = form == 3 || form == 4 || form == 5, zIsAngle = form == 1 || form == 2 || form == 5;
  const double a1 = form == 1 || form == 3 || form == 5 ? (form == 1 ? a.get("_ZPL") : a.get("_ZPD")) : 0;
  const double a2 = form == 2 || form == 4 ? (form == 2 ? a.get("_ZPL") : a.get("_ZPD")) : form == 5 ? a.get("_ZPL") : 0;
  for (double ang : {a1, a2})
    if (!(ang > -90 && ang < 90)) return fail(err, "the angles of the edges must lie between -90 and 90 degrees");
  const double t1 = std::tan(a1 * M_PI / 180), t2 = std::tan(a2 * M_PI / 180);
  double u = 0, w = 0;
  if (!xIsAngle) {  // Xm: absolute diameter or (1st digit 1) a radius from X0
    const double x = digit(amode, 1) == 1 ? k.x0 + a.get("_ZPD") : a.get("_ZPD") / 2;
    w = k.sx * (x - k.x1);
  }
  if (!zIsAngle) {  // Zm: absolute or (2nd digit 1) from Z0
    const double z = digit(amode, 2) == 1 ? k.z0 + a.get("_ZPL") : a.get("_ZPL");
    u = k.sz * (k.z0 - z);
  }
  switch (form) {
  case 1:  // Xm, a1: on the first edge
    if (std::fabs(t1) < kEps) return fail(err, "the first edge at 0 degrees meets no Xm: give Zm");
    u = w / t1;
    break;
  case 2:  // Xm, a2: on the second edge
    u = u3 - t2 * (H - w);
    break;
  case 3:  // a1, Zm
    w = t1 * u;
    break;
  case 4:  // a2, Zm
    if (std::fabs(t2) < kEps) return fail(err, "the second edge at 0 degrees meets no Zm: give Xm");
    w = H - (u3 - u) / t2;
    break;
  case 5:  // a1, a2: where the edges meet
    if (std::fabs(1 - t1 * t2) < 1e-9) return fail(err, "the edges at angles _ZPD and _ZPL do not meet (parallel)");
    w = t1 * (u3 - t2 * H) / (1 - t1 * t2);
    u = u3 - t2 * (H - w);
    break;
  default: break;
  }
  if (u < -1e-7 || u > u3 + 1e-7 || w < -1e-7 || w > H + 1e-7)
    return fail(err, "the intermediate point lies outside the rectangle of the start and end point: the corner "
                     "would have an undercut");
  m = {u, w};
  return true;
}

// CYCLE951(_SPD, _SPL, _EPD, _EPL, _ZPD, _ZPL, _LAGE, _MID, _FALX, _FALZ, _VARI, _RF1, _RF2, _RF3,
// _SDIS, _FF1, _NR, _DMODE, _AMODE)
bool sinCycle951(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (sinPlane(a, ctx) != 1) return unsupported(err, "stock removal outside the turning plane G18 is not supported");
  for (const char *k : {"_SPD", "_SPL", "_EPD", "_EPL"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  const double amode = a.get("_AMODE"), vari = a.get("_VARI");
  for (int d : {1, 2, 3, 4, 5, 6, 7})
    if (digit(amode, d) > 1) return fail(err, fmt::format("_AMODE digit {} must be 0 or 1", d));
  const int lage = (int)a.get("_LAGE");
  if (lage != a.get("_LAGE") || lage < 0 || lage > 3)
    return fail(err, "_LAGE must be 0 (outside, back), 1 (outside, front), 2 (inside, back) or 3 (inside, front)");
  const int direction = digit(vari, 1), machining = digit(vari, 2);
  if (direction < 1 || direction > 2) return fail(err, "_VARI 1st digit must be 1 (longitudinal) or 2 (transverse)");
  if (machining < 1 || machining > 2) return fail(err, "_VARI 2nd digit must be 1 (roughing) or 2 (finishing)");
  if (vari >= 100) return fail(err, "_VARI digits 3-5 are reserved: they must be 0");
  const int nr = (int)a.get("_NR");
  if (nr != a.get("_NR") || nr < 0 || nr > 2)
    return fail(err, "_NR must be 0 (90-degree corner), 1 (90 degrees with radii/chamfers) or 2 (any angle)");
  Corner k;
  k.sx = lage < 2 ? 1 : -1;
  k.sz = lage % 2 == 1 ? 1 : -1;
  k.z0 = a.get("_SPL");
  k.x0 = a.get("_SPD") / 2;
  k.x1 = digit(amode, 3) == 1 ? k.x0 + a.get("_EPD") : a.get("_EPD") / 2;
  const double z1 = digit(amode, 4) == 1 ? k.z0 + a.get("_EPL") : a.get("_EPL");
  const double u3 = k.sz * (k.z0 - z1), H = k.sx * (k.x0 - k.x1);
  static const char *const kLage[] = {"outside, back: X1 < X0 and Z1 > Z0", "outside, front: X1 < X0 and Z1 < Z0",
                                      "inside, back: X1 > X0 and Z1 > Z0", "inside, front: X1 > X0 and Z1 < Z0"};
  if (!(u3 > kEps) || !(H > kEps))
    return fail(err, fmt::format("the end point does not lie where _LAGE {} machines ({})", lage, kLage[lage]));
  Pt2 m{u3, 0};  // the corner point: the 90-degree corner or the intermediate point
  if (nr == 2 && !intermediate(a, k, u3, H, m, err)) return false;
  // Corners 1-3: the face edge, the corner point, the blank's edge; radii or chamfers (_NR 1, 2).
  Round r[3];
  static const char *const kRf[] = {"_RF1", "_RF2", "_RF3"};
  for (int i = 0; i < 3 && nr > 0; ++i) {
    r[i].size = a.get(kRf[i]);
    r[i].chamfer = digit(amode, 5 + i) == 1;
    if (r[i].size < 0) return fail(err, std::string(kRf[i]) + " (radius or chamfer) must not be negative");
  }
  // The finished contour from the face to the blank's edge: up the face to corner 1 (X1 at the
  // face), the first edge to M, the second to corner 3 (X0 at Z1), on along the blank's edge.
  // Corners 1 and 3 take their legs from the face and from the blank's edge beyond the corner.
  std::vector<Pt2> path{{0, 0}, m, {u3, H}};
  std::vector<Round> rounds{r[0], r[1], r[2]};
  for (size_t i : {2, 0})  // M on corner 1 or 3: no edge there (its own radius goes with it)
    if (std::hypot(path[1].a - path[i].a, path[1].b - path[i].b) < kEps) {
      if (r[1].size > 0) return fail(err, "the intermediate point lies on a corner: it takes no radius or chamfer _RF2");
      path.erase(path.begin() + 1), rounds.erase(rounds.begin() + 1);
      break;
    }
  const double e1 = roundLeg(r[0], {0, 1}, unit(minus(path[1], path[0])));
  const double e3 = roundLeg(r[2], unit(minus(path.back(), path[path.size() - 2])), {1, 0});
  path.insert(path.begin(), Pt2{0, -e1}), rounds.insert(rounds.begin(), Round{});
  path.push_back({u3 + e3, H}), rounds.push_back(Round{});
  if (e1 <= 0) path.erase(path.begin()), rounds.erase(rounds.begin());
  if (e3 <= 0) path.pop_back(), rounds.pop_back();
  const bool facing = direction == 2;
  double sdis = std::fabs(a.get("_SDIS"));
  if (sdis == 0) sdis = 1;  // [model] as CYCLE99 and CYCLE98's 0: 1 mm
  // Start C: before the face at the blank's edge (longitudinal) or beyond the blank's edge at the
  // face (transverse); the first contour element runs from C across the layers to the lead-in A'.
  Contour c;
  std::vector<Pt2> lead;
  if (!facing) {
    c.start = k.at(-sdis, H);
    lead = {k.at(-sdis, path.front().b)};
  } else {
    std::reverse(path.begin(), path.end());
    std::reverse(rounds.begin(), rounds.end());
    c.start = k.at(0, H + sdis);
    lead = {k.at(path.front().a, H + sdis)};
  }
  std::vector<Pt2> pts;
  for (const Pt2 &p : path) pts.push_back(k.at(p.a, p.b));
  ContourElem first;
  first.kind = ContourKind::Rapid;
  first.end = lead[0];
  c.elems.push_back(first);
  pts.insert(pts.begin(), lead[0]);
  rounds.insert(rounds.begin(), Round{});
  std::vector<ContourElem> profile;
  if (!roundedPath(pts, rounds, profile, err)) return false;
  c.elems.insert(c.elems.end(), profile.begin(), profile.end());
  // Roughing: layers to the finishing allowance (towards the material: outwards and towards the
  // face), equal depths of at most _MID; finishing: the contour itself, no layers.
  StockRemoval s;
  s.cutAxis = facing ? 1 : 0;
  s.cutName = facing ? "X" : "Z";
  s.retract = sdis;
  double ux = 0, uz = 0;
  if (machining == 1) {
    ux = a.get("_FALX"), uz = a.get("_FALZ");
    if (ux < 0 || uz < 0) return fail(err, "the finishing allowances _FALX and _FALZ must not be negative");
    s.allowance = {k.sz * uz, k.sx * ux};
    // The whole depth: from the blank's edge (face) to the deepest point of the contour plus the
    // allowance, in the fewest equal layers of at most _MID.
    const double total = facing ? path.front().a - uz : H + e1 - ux;
    if (!(total > kEps)) return fail(err, "the finishing allowance leaves nothing to rough");
    const double mid = a.get("_MID");
    if (!(mid > 0)) return fail(err, "_MID (maximum depth infeed) must be greater than 0");
    if (total / mid > kMaxLayers) return fail(err, "_MID (maximum depth infeed) is too small for the corner");
    s.depth = total / std::ceil(total / mid - 1e-9);
  } else {
    s.depth = 1e9;  // one pass along the contour
  }
  std::vector<ContourElem> moves;
  if (!stockRemoval(c, s, moves, err)) return false;
  // Into the plane's steps: in from the approach point (start + _SDIS in both axes), out to it.
  const Pt2 approach = k.at(-sdis, H + sdis);
  const double y = ctx.position[1], feed = std::fabs(a.get("_FF1"));
  auto step = [&](CycleStepKind kind, Pt2 p) {
    CycleStep st;
    st.kind = kind;
    st.pos = {p.b, y, p.a};
    if (kind != CycleStepKind::Rapid) st.feed = feed;
    out.push_back(st);
    return &out.back();
  };
  step(CycleStepKind::Rapid, approach);
  step(CycleStepKind::Rapid, c.start);
  for (const ContourElem &e : moves) {
    if (e.kind != ContourKind::Arc) {
      step(e.kind == ContourKind::Rapid ? CycleStepKind::Rapid : CycleStepKind::Feed, e.end);
      continue;
    }
    CycleStep *st = step(CycleStepKind::Arc, e.end);
    st->centre = {e.centre.b, y, e.centre.a};
    st->ccw = e.ccw;
  }
  // The generator ends with a rapid down to C: end at the approach point instead.
  if (out.size() > 2 && std::fabs(out.back().pos[0] - c.start.b) < 1e-7 && std::fabs(out.back().pos[2] - c.start.a) < 1e-7)
    out.pop_back();
  if (std::fabs(out.back().pos[0] - approach.b) > 1e-7 || std::fabs(out.back().pos[2] - approach.a) > 1e-7)
    step(CycleStepKind::Rapid, approach);
  return true;
}

// ---- CYCLE95: stock removal along a named contour ----

// The contour reversed: from its end back to its start (arcs turn the other way).
Contour reversed(const Contour &c) {
  Contour r;
  r.start = c.elems.back().end;
  for (size_t i = c.elems.size(); i-- > 0;) {
    ContourElem e = c.elems[i];
    e.end = i > 0 ? c.elems[i - 1].end : c.start;
    if (e.kind == ContourKind::Arc) e.ccw = !e.ccw;
    r.elems.push_back(e);
  }
  return r;
}

// The largest value of `sign` x coordinate `axis` (0 a = Z, 1 b = X) over the contour: its ends
// and the arcs' quadrant points.
double outermost(const Contour &c, int axis, double sign) {
  auto val = [&](Pt2 p) { return sign * (axis == 0 ? p.a : p.b); };
  double best = val(c.start);
  Pt2 from = c.start;
  for (const ContourElem &e : c.elems) {
    best = std::max(best, val(e.end));
    if (e.kind == ContourKind::Arc) {
      const double r = std::hypot(from.a - e.centre.a, from.b - e.centre.b);
      const double a0 = std::atan2(from.b - e.centre.b, from.a - e.centre.a);
      double sweep = std::atan2(e.end.b - e.centre.b, e.end.a - e.centre.a) - a0;
      if (e.ccw && sweep <= 0) sweep += 2 * M_PI;
      if (!e.ccw && sweep >= 0) sweep -= 2 * M_PI;
      for (int q = 0; q < 4; ++q) {
        double d = std::fmod((e.ccw ? 1 : -1) * (q * M_PI / 2 - a0), 2 * M_PI);
        if (d < 0) d += 2 * M_PI;
        if (d <= std::fabs(sweep)) best = std::max(best, val({e.centre.a + r * std::cos(q * M_PI / 2), e.centre.b + r * std::sin(q * M_PI / 2)}));
      }
    }
    from = e.end;
  }
  return best;
}

// CYCLE95(NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, _VARI, DT, DAM, _VRT, _GMODE, _DMODE): the
// contour NPP (captured by the front end, CycleContext::contour) roughed in paraxial layers by the
// ISO G71/G72 generator and/or finished along the contour.
bool sinCycle95(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (sinPlane(a, ctx) != 1) return unsupported(err, "stock removal outside the turning plane G18 is not supported");
  if (digit(a.get("_DMODE"), 4) == 1)
    return unsupported(err, "the contour named in CYCLE62 (_DMODE 4th digit 1) is not supported: name it in NPP");
  if (!ctx.contour) return fail(err, "no contour: CYCLE95 cuts the contour NPP names (a subprogram or a section \"START:END\")");
  const double vari = a.get("_VARI");
  const int kind = (int)std::fmod(vari, 100), retract = digit(vari, 3);
  if (vari != std::floor(vari) || kind < 1 || kind > 12)
    return fail(err, "_VARI 1st and 2nd digits must be 1-12 (roughing, finishing, complete; longitudinal or transverse; outside or inside)");
  if (retract > 2 || vari >= 1000) return fail(err, "_VARI 3rd digit must be 0, 1 or 2 (the retract)");
  if (retract == 2)
    return unsupported(err, "_VARI 3rd digit 2 (retract only to the previous cutting point, residual corners) is not supported");
  const bool transverse = (kind - 1) % 2 == 1, inside = (kind - 1) % 4 >= 2;
  const int stage = (kind - 1) / 4;  // 0 roughing, 1 finishing, 2 complete
  const bool rough = stage != 1, finish = stage != 0;
  if (a.get("FAL") != 0)
    return unsupported(err, "a finishing allowance parallel to the contour (FAL) is not supported: give FALX and FALZ");
  const double falz = a.get("FALZ"), falx = a.get("FALX"), dt = a.get("DT"), dam = a.get("DAM");
  if (falz < 0 || falx < 0) return fail(err, "the finishing allowances FALZ and FALX must not be negative");
  if (dt < 0 || dam < 0) return fail(err, "DT (dwell) and DAM (interval of the feed interruptions) must not be negative");
  if (a.get("_GMODE") != 0 && a.get("_GMODE") != 1) return fail(err, "_GMODE must be 0 or 1");
  double vrt = a.get("_VRT");
  if (vrt < 0) return fail(err, "_VRT (retract distance) must not be negative");
  if (vrt == 0) vrt = 1;  // the manual: 0 is 1 mm
  if (finish && ctx.toolRadius > 0)
    return unsupported(err, "finishing (_VARI 5-12) runs with tool nose radius compensation, which ncc does not apply in "
                            "the cycle: finish with a tool of radius 0");
  // The contour: its first move brings the tool to the contour's start point; the rest is it.
  const Contour &src = ctx.contour->contour;
  if (src.elems.size() < 2) return fail(err, "the contour needs a start point and at least one element after it");
  Contour c;
  c.start = src.elems[0].end;
  c.elems.assign(src.elems.begin() + 1, src.elems.end());
  for (const ContourElem &e : c.elems)
    if (e.kind == ContourKind::Rapid) return fail(err, "the contour moves at rapid (G0) after its start point");
  // Cut along Z towards -Z (longitudinal) or along X towards the axis (transverse outside) or
  // away from it (inside); the layers come in from the material's side: +X outside, -X inside
  // (longitudinal), +Z (transverse). The contour runs in the cutting direction.
  const int ca = transverse ? 1 : 0, da = 1 - ca;
  const double cutSign = transverse ? (inside ? 1 : -1) : -1, side = transverse ? 1 : (inside ? -1 : 1);
  auto at = [](Pt2 p, int axis) { return axis == 0 ? p.a : p.b; };
  const double run = at(c.elems.back().end, ca) - at(c.start, ca);
  if (std::fabs(run) < kEps) return fail(err, std::string("the contour does not run along ") + (ca == 0 ? "Z" : "X"));
  if (run * cutSign < 0) c = reversed(c);
  // The allowance towards the material: +FALZ along Z, FALX outwards (outside) or inwards.
  const Pt2 allowance{falz, (inside ? -1 : 1) * falx};
  const double allowCut = ca == 0 ? falz : falx, allowAcross = da == 0 ? falz : falx;
  const double top = side * outermost(c, da, side);  // the contour's outermost level (the blank)
  // Start point C: _VRT beyond the allowance over the top and before the contour's start.
  auto point = [&](double cut, double across) { return ca == 0 ? Pt2{cut, across} : Pt2{across, cut}; };
  const Pt2 C = point(at(c.start, ca) - cutSign * (allowCut + vrt), top + side * (allowAcross + vrt));
  const Pt2 lead = point(at(C, ca), at(c.start, da));
  const double y = ctx.position[1], ff1 = std::fabs(a.get("FF1")), ff3 = std::fabs(a.get("FF3"));
  CycleStep in;
  in.pos = {C.b, y, C.a};
  out.push_back(in);
  if (rough) {
    // C, across to the lead point before the contour's start, along to it, the contour.
    Contour job;
    job.start = C;
    ContourElem toLead;
    toLead.kind = ContourKind::Rapid, toLead.end = lead;
    ContourElem toStart;
    toStart.end = c.start;
    job.elems = {toLead, toStart};
    job.elems.insert(job.elems.end(), c.elems.begin(), c.elems.end());
    StockRemoval s;
    s.cutAxis = ca, s.cutName = ca == 0 ? "Z" : "X";
    s.retract = vrt;
    s.allowance = allowance;
    // [model] the blank reaches the contour's top: the layers count from there, in equal depths
    // of at most MID down to the deepest point plus the allowance.
    s.layersFrom = top;
    const double total = side * top + outermost(c, da, -side) - allowAcross;
    const double mid = a.get("MID");
    if (!(mid > 0)) return fail(err, "MID (maximum depth infeed) must be greater than 0");
    if (!(total > kEps)) return fail(err, "the finishing allowance leaves nothing to rough");
    if (total / mid > kMaxLayers) return fail(err, "MID (maximum depth infeed) is too small for the contour");
    s.depth = total / std::ceil(total / mid - 1e-9);
    std::vector<ContourElem> moves;
    if (!stockRemoval(job, s, moves, err)) {
      if (err.find("monotonic") != std::string::npos)
        return unsupported(err, std::string("contours with undercuts are not supported: the contour must run monotonic along ") +
                                    (ca == 0 ? "Z and X" : "X and Z") + " (FF2 is not used)");
      return false;
    }
    contourSteps(moves, C, y, ff1, dam, dt, out);
  }
  if (finish) {
    // From C across to the lead point, along to the contour's start, the contour at FF3, out
    // across to C's level and back to C.
    std::vector<ContourElem> moves;
    ContourElem e;
    e.kind = ContourKind::Rapid, e.end = lead;
    moves.push_back(e);
    e.kind = ContourKind::Line, e.end = c.start;
    moves.push_back(e);
    moves.insert(moves.end(), c.elems.begin(), c.elems.end());
    for (ContourElem &m : moves) m.feed = 0;
    e.kind = ContourKind::Rapid, e.end = point(at(c.elems.back().end, ca), at(C, da));
    moves.push_back(e);
    e.end = C;
    moves.push_back(e);
    contourSteps(moves, C, y, ff3, 0, 0, out);
  }
  return true;
}

const CycleDef kEntries[] = {
    {"sin.CYCLE951",
     "_SPD _SPL _EPD _EPL _ZPD _ZPL _LAGE _MID _FALX _FALZ _VARI _RF1 _RF2 _RF3 _SDIS _FF1 _NR _DMODE _AMODE",
     "Sinumerik stock removal (corner)", sinCycle951, nullptr, "_SPD:d _SPL:u _EPD:d _EPL:u _ZPD:d _ZPL:u"},
    {"sin.CYCLE95", "NPP MID FALZ FALX FAL FF1 FF2 FF3 _VARI DT DAM _VRT _GMODE _DMODE", "Sinumerik stock removal along a contour",
     sinCycle95, nullptr, nullptr, "NPP", "NPP"},
};

}  // namespace

void addSinTurningEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kEntries) out.push_back(d);
}

}  // namespace ncc
