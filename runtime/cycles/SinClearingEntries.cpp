// The Sinumerik pocket and slot entries of the cycle library (seed000c 19.1.5-19.1.9: POCKET3,
// POCKET4, SLOT1, SLOT2, LONGHOLE): the manual lists their parameters only, so each maps them
// onto a MillJob and a shape for the shared milling engine (Pocket.h) [model], docs/CYCLES.md.
#include "runtime/Geometry.h"
#include "runtime/cycles/Hole.h"
#include "runtime/cycles/SinMill.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

// ---- Sinumerik POCKET3 and POCKET4 (seed000c 19.1.5, 19.1.6). The manual lists the parameters
// only: the motion is the shared pocket's (heiPocket) [model], from over the pocket's centre at
// the retraction plane _RTP, back up to it at the end.
constexpr SinNames kPocketNames{"_RTP", "_RFP", "_SDIS", "_MID", "_FAL", "_FALD", "_FFP1", "_FFD",
                                "_CDIR", "_VARI", "_RAD1", "_DP1", kDepthDP};
constexpr SinNames kSlotNames{"RTP", "RFP", "SDIS", "_MID", "_FAL", "_FALD", "FFP1", "FFD",
                              "CDIR", "VARI", "_STA2", "_DP1", kDepthSlot};
constexpr SinNames kLongholeNames{"RTP", "_RFP", "SDIS", "MID", nullptr, nullptr, "FFP1", "FFD",
                                  nullptr, nullptr, nullptr, nullptr, kDepthSlot};

}  // namespace

static double get(const CycleArgs &a, const char *k) { return k ? a.get(k) : 0; }

bool entry::sinPocketJob(const CycleArgs &a, const CycleContext &ctx, const SinNames &n, MillJob &m, std::string &err) {
  for (const char *k : {n.rtp, n.rfp, n.mid, n.ffp1, n.ffd})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (!toolRadius(ctx, m, err)) return false;
  // The depth by n.depthMode (SinMill.h).
  const double rfp = a.get(n.rfp);
  const int mode = digit(a.get("_AMODE"), 1);
  const bool below = mode == 1 || (n.depthMode == kDepthSlot && mode == 0 && a.has("_DPR"));
  const char *depthKey = n.depthMode != kDepthDP && below ? "_DPR" : "_DP";
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

const PlanePoint *entry::reference(const CycleArgs &a, const char *ka, const char *kb, PlanePoint &out) {
  if (!a.has(ka) && !a.has(kb)) return nullptr;
  out = {a.get(ka), a.get(kb)};
  return &out;
}

bool entry::sinMida(const CycleArgs &a, MillJob &m, std::string &err) {
  double mida = a.get("_MIDA");
  if (digit(a.get("_AMODE"), 2) == 1) mida *= 2 * m.r / 100;
  m.stepover = mida > 0 ? mida : 1.6 * m.r;
  if (mida < 0 || m.stepover > 2 * m.r) return fail(err, "_MIDA (plane infeed) must lie between 0 and the tool diameter");
  return true;
}

namespace {

// POCKET3/4: _MIDA (sinMida); no pre-machined pockets.
bool sinPlaneInfeed(const CycleArgs &a, MillJob &m, std::string &err) {
  if (!sinMida(a, m, err)) return false;
  if (digit(a.get("_GMODE"), 5) == 2 || a.get("_AP1") != 0 || a.get("_AP2") != 0 || a.get("_AD") != 0)
    return fail(err, "machining a pre-machined pocket (_AP1 _AP2 _AD, _GMODE 5th digit 2) is not supported");
  return true;
}

// Pocket, then up to _RTP where the tool is.
bool sinPocket(const MillJob &m, const PocketShape &p, Mill &mill, std::string &err) {
  mill.go({0, 0}, m.lv.z2);
  if (!millPocket(m, p, mill, err)) return false;
  mill.up(m.lv.z2);
  return true;
}

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
                               "CDIR", nullptr, nullptr, nullptr, kDepthSlot};

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

const CycleDef kSinClearingEntries[] = {
    {"sin.POCKET3",
     "_RTP _RFP _SDIS _DP _LENG _WID _CRAD _PA _PO _STA _MID _FAL _FALD _FFP1 _FFD _CDIR _VARI _MIDA _AP1 _AP2 _AD _RAD1 _DP1 "
     "_UMODE _FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik rectangular pocket", sinPocket3, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v"},
    {"sin.POCKET4",
     "_RTP _RFP _SDIS _DP _CDIAM _PA _PO _MID _FAL _FALD _FFP1 _FFD _CDIR _VARI _MIDA _AP1 _AD _RAD1 _DP1 _UMODE _FS _ZFS "
     "_GMODE _DMODE _AMODE",
     "Sinumerik circular pocket", sinPocket4, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v"},
    {"sin.SLOT1",
     "RTP RFP SDIS _DP _DPR NUM LENG WID _CPA _CPO RAD STA1 INDA FFD FFP1 _MID CDIR _FAL VARI _MIDF FFP2 SSF _FALD _STA2 "
     "_DP1 _UMODE _FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik longitudinal slot", sinSlot1, nullptr, "RTP:n RFP:n _DP:n _CPA:u _CPO:v"},
    {"sin.SLOT2",
     "RTP RFP SDIS _DP _DPR NUM AFSL WID _CPA _CPO RAD STA1 INDA FFD FFP1 _MID CDIR _FAL VARI _MIDF FFP2 SSF _FFCP _UMODE "
     "_FS _ZFS _GMODE _DMODE _AMODE",
     "Sinumerik circumferential slots", sinSlot2, nullptr, "RTP:n RFP:n _DP:n _CPA:u _CPO:v"},
    {"sin.LONGHOLE",
     "RTP _RFP SDIS _DP _DPR NUM LENG _CPA _CPO RAD STA1 INDA FFD FFP1 MID _VARI _UMODE _GMODE _DMODE _AMODE",
     "Sinumerik elongated hole", sinLonghole, nullptr, "RTP:n _RFP:n _DP:n _CPA:u _CPO:v"},
};

}  // namespace

void addSinClearingEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kSinClearingEntries) out.push_back(d);
}

}  // namespace ncc
