// Sinumerik groove turning CYCLE930 (SIN-CYC-26, seed000c 19.1.40): rectangular or trapezoidal
// grooves, longitudinal or in a face, outside or inside, with radii or chamfers at their four
// corners, roughed in plunges and/or finished along both flanks, one or several in a row. The
// manual lists the parameters only; the plunges, their order and the finishing passes are ncc's
// model, docs/CYCLES.md "Sinumerik grooves". The plunges peck as the ISO G74/G75 grooves do
// (Grooving.h); the corners are rounded as CYCLE951's (TurnPath.h). ZX plane, program
// coordinates, X a radius (ncc runs Sinumerik in DIAMOF).
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/Grooving.h"
#include "runtime/cycles/TurnPath.h"
#include "runtime/cycles/Turning.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace ncc {

using namespace entry;

namespace {

constexpr double kEps = 1e-9;
constexpr double kMaxPlunges = 100000;  // a groove row that would take longer is an error, not a hang

// _VARI 3rd digit: where the groove lies. Longitudinal grooves plunge along X (outside towards
// the axis, inside away from it) and run their width along Z; face grooves plunge along Z (ncc
// reads "outside" as the front face, plunging towards -Z, "inside" as the back face) and run
// their width along X. The sign says which way the width (and the next grooves) go from the
// reference point.
struct Position {
  bool face;
  int su;  // the width's direction on its axis
  int sv;  // the plunge's direction on the depth axis
};
constexpr Position kPositions[8] = {
    {false, +1, -1},  // 1 longitudinal, outside, +Z
    {true, -1, +1},   // 2 face, inside, -X
    {false, +1, +1},  // 3 longitudinal, inside, +Z
    {true, +1, +1},   // 4 face, inside, +X
    {false, -1, -1},  // 5 longitudinal, outside, -Z
    {true, -1, -1},   // 6 face, outside, -X
    {false, -1, +1},  // 7 longitudinal, inside, -Z
    {true, +1, -1},   // 8 face, outside, +X
};

// A piece of a path in the groove frame.
using Path = std::vector<ContourElem>;

// The half of the groove's contour from the top at one flank down to the bottom, monotonic in u
// (dir +1: flank 1, u grows; -1: flank 2, u falls) and in v (never rising).
struct Half {
  Pt2 start;
  Path elems;
  int dir = 1;
};

// The other coordinate of the element's point (from p, monotonic in both) whose coordinate on
// `axis` (0: u, 1: v) is x: the line's or the arc's point between the element's ends; an element
// along the other axis gives its start.
double pointOn(Pt2 p, const ContourElem &e, int axis, double x) {
  auto on = [](Pt2 q, int ax) { return ax == 0 ? q.a : q.b; };
  const int o = 1 - axis;
  if (std::fabs(on(e.end, axis) - on(p, axis)) < kEps) return on(p, o);
  if (e.kind != ContourKind::Arc)
    return on(p, o) + (on(e.end, o) - on(p, o)) * (x - on(p, axis)) / (on(e.end, axis) - on(p, axis));
  const double r = std::hypot(p.a - e.centre.a, p.b - e.centre.b), dx = x - on(e.centre, axis);
  const double h = std::sqrt(std::max(0.0, r * r - dx * dx));
  const double lo = std::min(on(p, o), on(e.end, o)) - 1e-7, hi = std::max(on(p, o), on(e.end, o)) + 1e-7;
  const double y = on(e.centre, o) + h;
  return y >= lo && y <= hi ? y : on(e.centre, o) - h;
}

// The deepest v the half reaches on its top side of u (-inf: none): how deep a plunge whose side
// is at u may go without cutting into this flank.
double depthAt(const Half &h, double u) {
  double best = -std::numeric_limits<double>::infinity();
  Pt2 p = h.start;
  if (h.dir * (p.a - u) > kEps) return best;
  best = p.b;
  for (const ContourElem &e : h.elems) {
    if (h.dir * (e.end.a - u) <= kEps) {
      best = std::max(best, e.end.b);
    } else {
      best = std::max(best, pointOn(p, e, 0, u));
      break;
    }
    p = e.end;
  }
  return best;
}

// Where the half first reaches depth v.
double crossingAt(const Half &h, double v) {
  Pt2 p = h.start;
  if (p.b >= v - kEps) return p.a;
  for (const ContourElem &e : h.elems) {
    if (e.end.b >= v - kEps) return pointOn(p, e, 1, v);
    p = e.end;
  }
  return p.a;
}

Half shiftedHalf(const Half &h, Pt2 d) {
  Half s = h;
  s.start = {h.start.a + d.a, h.start.b + d.b};
  for (ContourElem &e : s.elems) e = shifted(e, d);
  return s;
}

struct Groove {
  double depth = 0, bottom = 0;     // T1 and B1 (the bottom's width)
  double tan1 = 0, tan2 = 0;        // the flanks' slopes (_ANG1, _ANG2)
  double u1 = 0;                    // flank 1's bottom corner
  Round corner[4];                  // _RCO1 (top, flank 1), _RCI1, _RCI2, _RCO2 (top, flank 2)
};

// The two halves of the finished contour: flank 1 from the top (before corner 1's leg) down to
// the start of corner 3's rounding on the bottom, flank 2 from its top down to the end of corner
// 2's. Together they overlap on the bottom's flat part.
bool halves(const Groove &g, Half &left, Half &right, double &flatFrom, double &flatTo, std::string &err) {
  const Pt2 A{g.u1 - g.depth * g.tan1, 0}, B{g.u1, g.depth}, C{g.u1 + g.bottom, g.depth},
      D{g.u1 + g.bottom + g.depth * g.tan2, 0};
  auto unit = [](Pt2 p, Pt2 q) {
    const double l = std::hypot(q.a - p.a, q.b - p.b);
    return Pt2{(q.a - p.a) / l, (q.b - p.b) / l};
  };
  const double legA = roundLeg(g.corner[0], {1, 0}, unit(A, B)), legB = roundLeg(g.corner[1], unit(A, B), {1, 0});
  const double legC = roundLeg(g.corner[2], unit(D, C), {-1, 0}), legD = roundLeg(g.corner[3], {-1, 0}, unit(D, C));
  flatFrom = B.a + legB, flatTo = C.a - legC;
  if (flatTo - flatFrom < -1e-7)
    return fail(err, fmt::format("the radii or chamfers at the bottom (_RCI1, _RCI2) do not fit its width _WIDG {:g}", g.bottom));
  auto build = [&](Half &h, Pt2 out, Pt2 top, Pt2 bot, Pt2 end, Round rt, Round rb, double leg, int dir) {
    std::vector<Pt2> pts{out, top, bot, end};
    std::vector<Round> rounds{Round{}, rt, rb, Round{}};
    if (leg <= 0) pts.erase(pts.begin()), rounds.erase(rounds.begin());
    if (std::fabs(pts.back().a - pts[pts.size() - 2].a) < kEps) pts.pop_back(), rounds.pop_back();
    h.start = pts[0], h.dir = dir;
    return roundedPath(pts, rounds, h.elems, err);
  };
  return build(left, {A.a - legA, 0}, A, B, {flatTo, g.depth}, g.corner[0], g.corner[1], legA, 1) &&
         build(right, {D.a + legD, 0}, D, C, {flatFrom, g.depth}, g.corner[3], g.corner[2], legD, -1);
}

// Moves in the groove frame for the programmed point, which lies `off` from the corner that
// traces them (u).
void add(Path &p, ContourKind k, Pt2 to) {
  if (k == ContourKind::Rapid && !p.empty() && std::fabs(p.back().end.a - to.a) < kEps && std::fabs(p.back().end.b - to.b) < kEps)
    return;  // already there
  ContourElem e;
  e.kind = k, e.end = to;
  p.push_back(e);
}
void addShifted(Path &p, const Path &elems, double off) {
  for (const ContourElem &e : elems) {
    const ContourElem m = shifted(e, {off, 0});
    if (m.kind == ContourKind::Line && std::fabs(m.end.a - p.back().end.a) < kEps && std::fabs(m.end.b - p.back().end.b) < kEps)
      continue;  // the line up to a corner's leg that starts where the pass does
    p.push_back(m);
  }
}

// CYCLE930(_SPD, _SPL, _WIDG, _WIDG2, _DIAG, _DIAG2, _STA, _ANG1, _ANG2, _RCO1, _RCI1, _RCI2,
// _RCO2, _FAL, _IDEP1, _SDIS, _VARI, _DN, _NUM, _DBH, _FF1, _NR, _FALX, _FALZ, _DMODE, _AMODE)
bool sinCycle930(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (sinPlane(a, ctx) != 1) return unsupported(err, "grooves outside the turning plane G18 are not supported");
  for (const char *k : {"_SPD", "_SPL", "_WIDG", "_DIAG", "_VARI"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  const double vari = a.get("_VARI"), amode = a.get("_AMODE");
  if (vari != std::floor(vari) || vari < 0 || vari >= 100000)
    return fail(err, "_VARI must be a whole number of at most five digits");
  const int machining = digit(vari, 2), where = digit(vari, 3), refBottom = digit(vari, 4), separate = digit(vari, 5);
  if (digit(vari, 1) != 0) return fail(err, "_VARI 1st digit is reserved: it must be 0");
  if (machining < 1 || machining > 3)
    return fail(err, "_VARI 2nd digit must be 1 (roughing), 2 (finishing) or 3 (roughing and finishing)");
  if (where < 1 || where > 8) return fail(err, "_VARI 3rd digit (the groove's position) must be 1-8");
  if (refBottom > 1) return fail(err, "_VARI 4th digit must be 0 (reference point at the top) or 1 (at the bottom)");
  if (separate > 1) return fail(err, "_VARI 5th digit must be 0 (allowance U parallel to the contour) or 1 (UX and UZ)");
  for (int d = 1; d <= 7; ++d)
    if (digit(amode, d) > 1) return fail(err, fmt::format("_AMODE digit {} must be 0 or 1", d));
  const int nr = (int)a.get("_NR");
  if (nr != a.get("_NR") || nr < 0 || nr > 2)
    return fail(err, "_NR must be 0 (90-degree flanks), 1 (inclined flanks with radii/chamfers) or 2 (as 1 on a taper)");
  const double sta = a.get("_STA");
  if (sta < -180 || sta > 180) return fail(err, "_STA (slope angle) must lie between -180 and 180 degrees");
  if (nr == 2 && sta != 0)
    return unsupported(err, fmt::format("_NR 2 with _STA {:g}: grooves on a taper are not supported (the insert "
                                        "would have to plunge at an angle to its sides)",
                                        sta));
  if (a.get("_DN") != 0)
    return unsupported(err, fmt::format("_DN {:g}: the grooving tool's second cutting edge (a D change inside the cycle) "
                                        "is not supported: give 0; ncc cuts the far flank with the width of the tool",
                                        a.get("_DN")));
  const double width = ctx.toolWidth;
  if (!(width > 0))
    return unsupported(err, "the active tool has no width: CYCLE930 plunges a grooving insert of the tool's `width` "
                            "(a tools entry of the machine file)");
  const bool rough = machining != 2, finish = machining != 1;
  if (finish && ctx.toolRadius > 0)
    return unsupported(err, "finishing (_VARI 2nd digit 2, 3) with a tool nose radius is not supported: ncc traces the "
                            "insert's sharp corners (give the grooving tool radius 0)");
  const Position pos = kPositions[where - 1];
  Groove g;
  g.bottom = a.get("_WIDG");
  if (!(g.bottom > 0)) return fail(err, "_WIDG (the groove's width at the bottom) must be greater than 0");
  // The depth: absolute and longitudinal, the other level's diameter; else incremental.
  const double x0 = a.get("_SPD") / 2, z0 = a.get("_SPL"), ref = pos.face ? z0 : x0;
  const bool absolute = digit(amode, 2) == 0 && !pos.face;
  if (absolute) {
    const double other = a.get("_DIAG") / 2;
    g.depth = refBottom ? pos.sv * (ref - other) : pos.sv * (other - ref);
    if (!(g.depth > kEps))
      return fail(err, fmt::format("_DIAG {:g} (the diameter at the groove's {}) does not lie {} the reference point X0 {:g}",
                                   a.get("_DIAG"), refBottom ? "top" : "bottom",
                                   (pos.sv < 0) != (refBottom == 1) ? "below" : "above", a.get("_SPD")));
  } else {
    g.depth = a.get("_DIAG");
    if (!(g.depth > 0)) return fail(err, "_DIAG (the groove's depth, incremental) must be greater than 0");
  }
  static const char *const kCorner[] = {"_RCO1", "_RCI1", "_RCI2", "_RCO2"};
  if (nr > 0) {
    const double a1 = a.get("_ANG1"), a2 = a.get("_ANG2");
    if (!(a1 >= 0 && a1 < 90) || !(a2 >= 0 && a2 < 90))
      return fail(err, "the flank angles _ANG1 and _ANG2 must lie in 0 <= angle < 90 degrees");
    g.tan1 = std::tan(a1 * M_PI / 180), g.tan2 = std::tan(a2 * M_PI / 180);
    for (int i = 0; i < 4; ++i) {
      g.corner[i].size = a.get(kCorner[i]);
      g.corner[i].chamfer = digit(amode, 4 + i) == 1;
      if (g.corner[i].size < 0) return fail(err, std::string(kCorner[i]) + " (radius or chamfer) must not be negative");
    }
  }
  g.u1 = refBottom ? 0 : g.depth * g.tan1;
  GrooveFrame f;
  f.face = pos.face, f.su = pos.su, f.sv = pos.sv;
  f.w0 = pos.face ? x0 : z0;
  f.d0 = refBottom ? ref - pos.sv * g.depth : ref;
  Half left, right;
  double flatFrom = 0, flatTo = 0;
  if (!halves(g, left, right, flatFrom, flatTo, err)) return false;
  if (flatTo - flatFrom < width - 1e-7)
    return fail(err, fmt::format("the tool (width {:g}) is wider than the groove's flat bottom ({:g})", width,
                                 flatTo - flatFrom));
  // The allowances roughing leaves: along the width (Z longitudinal, X face) and the depth.
  double au = 0, av = 0;
  if (rough) {
    const double fal = a.get("_FAL"), falx = a.get("_FALX"), falz = a.get("_FALZ");
    if (fal < 0 || falx < 0 || falz < 0) return fail(err, "the finishing allowances _FAL, _FALX and _FALZ must not be negative");
    if (separate) {
      au = pos.face ? falx : falz, av = pos.face ? falz : falx;
    } else {
      // U parallel to the contour is the same shift on 90-degree flanks without corners.
      const bool square = g.tan1 == 0 && g.tan2 == 0 && std::all_of(g.corner, g.corner + 4, [](const Round &r) { return r.size == 0; });
      if (fal > 0 && !square)
        return unsupported(err, fmt::format("_FAL {:g}: an allowance parallel to inclined flanks or rounded corners is not "
                                            "supported: give _FALX/_FALZ (_VARI 5th digit 1)",
                                            fal));
      au = av = fal;
    }
  }
  double idep = a.get("_IDEP1"), sdis = a.get("_SDIS");
  if (idep < 0) return fail(err, "_IDEP1 (depth per plunge) must not be negative");
  if (sdis < 0) return fail(err, "_SDIS (safety clearance) must not be negative");
  if (sdis == 0) sdis = 1;  // [model] as CYCLE951: 1 mm
  const double grooves = a.get("_NUM");
  if (grooves != std::floor(grooves) || grooves < 0 || grooves > 1e6)
    return fail(err, "_NUM (number of grooves) must be a whole number from 0 to a million");
  const int num = std::max(1, (int)grooves);
  const double dbh = a.get("_DBH");
  if (num > 1 && !(dbh > 0)) return fail(err, "_DBH (distance between the grooves) must be greater than 0 for several grooves");
  // The programmed point is the insert's corner towards -Z (longitudinal) or -X (face): u of the
  // corner at the groove's lower u (flank 1's side) plus this.
  const double progOff = pos.su > 0 ? 0 : width;
  // Roughing plunges, the insert spanning [s, s + width]: over the bottom of the groove less its
  // allowances in equal steps of at most the width, then out over each sloping flank a width at
  // a time while a plunge still cuts; each plunge as deep as both flanks allow. In the order of
  // u: from flank 1 to flank 2.
  Path one;  // the moves of one groove, its programmed point in the groove frame
  if (rough) {
    const Half l = shiftedHalf(left, {au, -av}), r = shiftedHalf(right, {-au, -av});
    const double bottom = g.depth - av;
    if (!(bottom > kEps)) return fail(err, "the finishing allowance leaves nothing to rough");
    if (crossingAt(r, 0) - crossingAt(l, 0) < width - 1e-7)
      return fail(err, fmt::format("the tool (width {:g}) is wider than the groove less its allowances ({:g})", width,
                                   crossingAt(r, 0) - crossingAt(l, 0)));
    double sL = crossingAt(l, bottom), sR = crossingAt(r, bottom) - width;
    if (sR < sL) sL = sR = (sL + sR) / 2;  // the allowances leave a bottom narrower than the insert
    std::vector<double> at;
    auto cuts = [&](double s) { return std::min(depthAt(l, s), depthAt(r, s + width)) > kEps; };
    for (double s = sL - width; cuts(s) && at.size() < kMaxPlunges; s -= width) at.insert(at.begin(), s);
    const double steps = std::ceil((sR - sL) / width - 1e-9);
    if (steps > kMaxPlunges) return fail(err, "the groove would take too many plunges");
    for (int i = 0; i <= steps; ++i) at.push_back(steps > 0 ? sL + (sR - sL) * i / steps : sL);
    for (double s = sR + width; cuts(s) && at.size() < 2 * kMaxPlunges; s += width) at.push_back(s);
    for (double s : at) {
      const double d = std::min(depthAt(l, s), depthAt(r, s + width));
      const double u = s + progOff;
      add(one, ContourKind::Rapid, {u, -sdis});
      add(one, ContourKind::Line, {u, 0});
      PeckGroove pk;
      pk.start = {0, u}, pk.end = {d, u};
      pk.peck = idep > 0 ? idep : d;
      pk.retract = sdis;
      std::vector<ContourElem> pecks;
      if (!peckGrooves(pk, pecks, err)) return false;
      pecks.pop_back();  // its rapid back to the top: out to the safety level instead
      for (const ContourElem &e : pecks) add(one, e.kind, {e.end.b, e.end.a});
      add(one, ContourKind::Rapid, {u, -sdis});
    }
  }
  // Finishing: flank 1 with the near corner from its top down and along the bottom until the far
  // corner reaches the bottom's end; out; flank 2 with the far corner from its top down to the
  // bottom; out.
  if (finish) {
    Path lp = left.elems, rp = right.elems;
    lp.back().end.a = flatTo - width;
    if (std::fabs(lp.back().end.a - (lp.size() > 1 ? lp[lp.size() - 2].end.a : left.start.a)) < kEps) lp.pop_back();
    rp.pop_back();  // the bottom is done: flank 2 ends at its bottom corner
    const double lu = left.start.a + progOff, ru = right.start.a - width + progOff;
    add(one, ContourKind::Rapid, {lu, -sdis});
    add(one, ContourKind::Line, {lu, 0});
    addShifted(one, lp, progOff);
    add(one, ContourKind::Rapid, {one.back().end.a, -sdis});
    add(one, ContourKind::Rapid, {ru, -sdis});
    add(one, ContourKind::Line, {ru, 0});
    addShifted(one, rp, progOff - width);
    add(one, ContourKind::Rapid, {one.back().end.a, -sdis});
  }
  // The row: each groove _DBH further along the width; to the first at the safety level, depth
  // axis first.
  if ((double)num * (double)one.size() > 1e6)
    return fail(err, fmt::format("_NUM {} grooves would make more than a million moves", num));
  std::vector<ContourElem> moves;
  const Pt2 here{ctx.position[2], ctx.position[0]};
  f.approach(here, {one.front().end.a, -sdis}, moves);
  for (int k = 0; k < num; ++k)
    for (const ContourElem &m : one) moves.push_back(f.toPlane(m, k * dbh));
  contourSteps(moves, here, ctx.position[1], std::fabs(a.get("_FF1")), 0, 0, out);
  return true;
}

const CycleDef kEntries[] = {
    {"sin.CYCLE930",
     "_SPD _SPL _WIDG _WIDG2 _DIAG _DIAG2 _STA _ANG1 _ANG2 _RCO1 _RCI1 _RCI2 _RCO2 _FAL _IDEP1 _SDIS _VARI _DN _NUM "
     "_DBH _FF1 _NR _FALX _FALZ _DMODE _AMODE",
     "Sinumerik groove", sinCycle930, nullptr, nullptr},
};

}  // namespace

void addSinGrooveEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kEntries) out.push_back(d);
}

}  // namespace ncc
