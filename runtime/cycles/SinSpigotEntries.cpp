// The Sinumerik spigot entries of the cycle library (seed000c 19.1.17 CYCLE76 rectangular spigot,
// 19.1.18 CYCLE77 circular spigot, 19.1.20 CYCLE79 multi-edge): the manual lists their parameters
// only, so each maps them onto a MillJob (SinMill.h, as the pockets) and a stud for the stud engine
// the Heidenhain 256-258 use (Stud.h) [model], docs/CYCLES.md "Sinumerik spigots".
#include "runtime/cycles/SinMill.h"
#include "runtime/cycles/Stud.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

constexpr SinNames kSpigotNames{"_RTP", "_RFP", "_SDIS", "_MID", "_FAL", "_FALD", "_FFP1", "_FFD",
                                "_CDIR", nullptr, nullptr, nullptr, kDepthSpigot};
// CYCLE79 has no depth feed: it plunges at _FFP1 [model].
constexpr SinNames kPolygonNames{"_RTP", "_RFP", "_SDIS", "_MID", "_FAL", "_FALD", "_FFP1", "_FFP1",
                                 "_CDIR", nullptr, nullptr, nullptr, kDepthDP};

// What the three share: _CDIR 0 climb, 1 conventional; _VARI 1st digit 1 roughing (to the
// allowances), 2 finishing (the wall always, the floor when _FALD leaves one), 3 edge finishing
// (CYCLE79 only), 5 chamfering (an error: it needs the tool's point angle); _GMODE 5th digit 2 rest
// machining (an error: ncc does not know what an earlier tool left).
bool spigotJob(const CycleArgs &a, const CycleContext &ctx, const SinNames &n, bool edgeFinish, MillJob &m,
               std::string &err) {
  const double cdir = a.get("_CDIR");
  if (cdir != 0 && cdir != 1) return fail(err, "_CDIR must be 0 (climb) or 1 (conventional)");
  if (!sinPocketJob(a, ctx, n, m, err)) return false;
  switch (digit(a.get("_VARI"), 1)) {
  case 1: m.op = 1; break;
  case 2: m.op = 2, m.wallPass = true, m.floorPass = m.floorAllowance > 0; break;
  case 3:
    if (!edgeFinish) return fail(err, "_VARI 1st digit must be 1 (roughing), 2 (finishing) or 5 (chamfering)");
    m.op = 2, m.wallPass = true;
    break;
  case 5: return fail(err, "_VARI 5 (chamfering) needs the tool's point angle: not supported");
  default:
    return fail(err, edgeFinish ? "_VARI 1st digit must be 1 (roughing), 2 (finishing), 3 (edge finishing) or 5 (chamfering)"
                                : "_VARI 1st digit must be 1 (roughing), 2 (finishing) or 5 (chamfering)");
  }
  if (digit(a.get("_GMODE"), 5) == 2)
    return fail(err, "_GMODE 5th digit 2 (rest machining after a larger tool) is not supported");
  if (!(a.get("_AP1") > 0)) return fail(err, "_AP1 (blank size) is required and must be greater than 0");
  return true;
}

// The stud from the approach point _SDIS outside the blank on the stud's +x side [model], from
// and back to _RTP.
void spigot(const MillJob &m, StudShape &s, double blankHalf, Mill &mill) {
  s.approach = {blankHalf + m.r + m.clearance, 0};
  mill.go(s.approach, m.lv.z2);
  millStud(m, s, mill);
}

bool sinCycle76(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!spigotJob(a, ctx, kSpigotNames, false, m, err)) return false;
  const double L = a.get("_LENG"), W = a.get("_WID"), rc = a.get("_CRAD"), BL = a.get("_AP1"), BW = a.get("_AP2");
  const int dim = digit(a.get("_GMODE"), 4);
  if (!(L > 0) || !(W > 0)) return fail(err, "_LENG and _WID (spigot length and width) must be greater than 0");
  if (!(BL > L) || !(BW > W)) return fail(err, "the blank _AP1 x _AP2 must be larger than the spigot _LENG x _WID");
  if (rc < 0 || 2 * rc > std::min(L, W)) return fail(err, "_CRAD (corner radius) must lie between 0 and half the shorter side");
  if (dim > 5) return fail(err, "_GMODE 4th digit must be 0 … 5");
  StudShape s{rectLap, L / 2, W / 2, rc};
  s.reach = rectReach(s, BL / 2, BW / 2);
  PlanePoint about;
  Mill mill = placed(out, ctx, m, {kSinCorner[dim][0] * L / 2, kSinCorner[dim][1] * W / 2}, a.get("_STA"),
                     sinPlane(a, ctx), reference(a, "_PA", "_PO", about));
  spigot(m, s, BL / 2, mill);
  return true;
}

bool sinCycle77(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!spigotJob(a, ctx, kSpigotNames, false, m, err)) return false;
  const double d = a.get("_CDIAM"), blank = a.get("_AP1");
  if (!(d > 0)) return fail(err, "_CDIAM (spigot diameter) must be greater than 0");
  if (!(blank > d)) return fail(err, "_AP1 (blank diameter) must be larger than _CDIAM");
  StudShape s{circleLap, d / 2, d / 2, d / 2};
  s.reach = (blank - d) / 2;
  PlanePoint about;
  Mill mill = placed(out, ctx, m, {0, 0}, 0, sinPlane(a, ctx), reference(a, "_PA", "_PO", about));
  spigot(m, s, blank / 2, mill);
  return true;
}

// CYCLE79: _NUM edges, _SWL the width across flats (_VARI 2nd digit 0, an even _NUM) or the edge
// length (1), the middle of the first edge at _STA from the 1st axis, corners rounded by _RC
// (_AMODE 4th digit 0), from the round blank _AP1, laps at most _MIDA apart.
bool sinCycle79(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  MillJob m;
  if (!spigotJob(a, ctx, kPolygonNames, true, m, err) || !sinMida(a, m, err)) return false;
  const double n = a.get("_NUM"), swl = a.get("_SWL"), rc = a.get("_RC"), blank = a.get("_AP1");
  const bool edgeLength = digit(a.get("_VARI"), 2) == 1;
  if (n == 1 || n == 2) return fail(err, "_NUM 1 or 2 (one or two flats) is not supported: program 3 or more edges");
  if (!(n >= 3 && n <= 99) || n != std::floor(n)) return fail(err, "_NUM (number of edges) must be a whole number 1 … 99");
  if (!(swl > 0)) return fail(err, "_SWL (width across flats or edge length) must be greater than 0");
  if (!edgeLength && std::fmod(n, 2) != 0)
    return fail(err, "_SWL as the width across flats (_VARI 2nd digit 0) needs an even _NUM: program the edge length");
  if (digit(a.get("_AMODE"), 4) == 1 && rc != 0)
    return fail(err, "_RC as a corner chamfer (_AMODE 4th digit 1) is not supported: program a corner radius");
  StudShape s{polygonLap, 0, 0, rc};
  s.corners = (int)n;
  s.a = edgeLength ? swl / (2 * std::tan(M_PI / n)) : swl / 2;  // the apothem
  if (rc < 0 || rc > s.a) return fail(err, "_RC (corner radius) must lie between 0 and the polygon's inscribed radius");
  if (!(blank / 2 > s.a)) return fail(err, "_AP1 (blank diameter) must be larger than the polygon's width across flats");
  s.reach = blank / 2 - s.a;  // the blank's farthest point lies off the middle of an edge
  PlanePoint about;
  Mill mill = placed(out, ctx, m, {0, 0}, a.get("_STA"), sinPlane(a, ctx), reference(a, "_PA", "_PO", about));
  spigot(m, s, blank / 2, mill);
  return true;
}

const CycleDef kSinSpigotEntries[] = {
    {"sin.CYCLE76",
     "_RTP _RFP _SDIS _DP _DPR _LENG _WID _CRAD _PA _PO _STA _MID _FAL _FALD _FFP1 _FFD _CDIR _VARI _AP1 _AP2 _FS _ZFS "
     "_GMODE _DMODE _AMODE",
     "Sinumerik rectangular spigot", sinCycle76, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v"},
    {"sin.CYCLE77",
     "_RTP _RFP _SDIS _DP _DPR _CDIAM _PA _PO _MID _FAL _FALD _FFP1 _FFD _CDIR _VARI _AP1 _FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik circular spigot", sinCycle77, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v"},
    {"sin.CYCLE79",
     "_RTP _RFP _SDIS _DP _NUM _SWL _PA _PO _STA _RC _AP1 _MIDA _MID _FAL _FALD _FFP1 _CDIR _VARI _FS _ZFS _GMODE _DMODE "
     "_AMODE",
     "Sinumerik multi-edge spigot", sinCycle79, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v"},
};

}  // namespace

void addSinSpigotEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kSinSpigotEntries) out.push_back(d);
}

}  // namespace ncc
