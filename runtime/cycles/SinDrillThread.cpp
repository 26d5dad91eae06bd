// Sinumerik CYCLE78 drill-thread milling (seed000c 19.1.19, L30120-30317): one tool drills the
// hole and then mills the thread, on the thread helix CYCLE70 and Heidenhain 262-267 share
// (ThreadMill.h). The manual lists the parameters only; the order of the steps and what the
// parameter table leaves open are ncc's choice [model], docs/CYCLES.md "Sinumerik drill-thread
// milling".
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/ThreadMill.h"
#include "runtime/Geometry.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace ncc {

using namespace entry;

namespace {

constexpr double kEps = 1e-9;

// The drilling feed by depth d below _RFP: the spot-drilling feed down to `spotEnd` (_ADPR,
// _VARI 5th digit), FR from `residualFrom` (_LDPR above the final depth, _VARI 4th digit), F1
// between.
struct DrillFeeds {
  double drill = 0, spot = 0, residual = 0;
  double spotEnd = -std::numeric_limits<double>::infinity(), residualFrom = std::numeric_limits<double>::infinity();
  double of(double a, double b) const {
    const double mid = (a + b) / 2;
    return mid < spotEnd ? spot : mid > residualFrom ? residual : drill;
  }
};

// The drilling feed from depth a down to b, split where the feed changes.
void drillTo(Mill &m, const Thread &t, const DrillFeeds &f, double a, double b) {
  for (double cut : {f.spotEnd, f.residualFrom}) {
    if (!(cut > a + kEps && cut < b - kEps)) continue;
    m.feed({0, 0}, t.level(cut), f.of(a, cut));
    a = cut;
  }
  m.feed({0, 0}, t.level(b), f.of(a, b));
}

// The depths below _RFP where the infeeds end: the first _FDPR (not less than the depth: one
// infeed), each following one less by _DAM (_AMODE 2nd digit 0) or _DAM % of the one before (1),
// not below _MDEP; a degression by amount without a minimum stops at the last infeed above 0.
bool infeeds(const CycleArgs &a, double depth, std::vector<double> &ends, std::string &err) {
  double step = a.get("_FDPR");
  if (!(step > 0)) return fail(err, "_FDPR (maximum depth infeed) must be greater than 0");
  const double dam = a.get("_DAM"), mdep = a.get("_MDEP");
  const bool percent = digit(a.get("_AMODE"), 2) == 1;
  if (mdep < 0) return fail(err, "_MDEP (minimum infeed) must not be negative");
  if (percent ? !(dam >= 0.001 && dam <= 100) : dam < 0)
    return fail(err, percent ? "_DAM (degression in percent) must lie between 0.001 and 100" : "_DAM (degression) must not be negative");
  for (double at = 0; at < depth - kEps;) {
    at = std::min(at + step, depth);
    ends.push_back(at);
    const double next = std::max(percent ? step * dam / 100 : step - dam, mdep);
    if (next > kEps) step = next;
    else if (percent) return fail(err, "the infeeds shrink to nothing before the final depth: give a minimum infeed _MDEP");
    if (ends.size() > kMaxPecks) return fail(err, "_FDPR or _MDEP too small: more than a million infeeds");
  }
  return true;
}

// The drilling feeds: F1, the spot-drilling feed (_VARI 5th digit: 0.3 x F1 when F1 is below 0.15
// mm/rev, else 0.1 mm/rev, L30218-L30222) and FR on the residual depth (4th digit).
bool drillFeeds(const CycleArgs &a, const CycleContext &ctx, double depth, DrillFeeds &f, std::string &err) {
  f.drill = a.get("_FFD");
  if (!(f.drill > 0)) return fail(err, "_FFD (drilling feed F1) must be greater than 0");
  if (digit(a.get("_VARI"), 5) == 1) {
    if (!(ctx.speed > 0)) return fail(err, "spot drilling (_VARI 5th digit 1) needs the spindle speed: its feed depends on F1 in mm/rev");
    f.spotEnd = a.get("_ADPR");
    if (!(f.spotEnd > 0) || f.spotEnd > depth) return fail(err, "_ADPR (spot-drilling depth) must lie between 0 and the drilling depth");
    f.spot = f.drill / ctx.speed < 0.15 ? 0.3 * f.drill : 0.1 * ctx.speed;
  }
  if (digit(a.get("_VARI"), 4) == 1) {
    f.residual = a.get("_FRDP");
    if (!(f.residual > 0)) return fail(err, "_FRDP (residual drilling feed FR) must be greater than 0");
    f.residualFrom = depth - a.get("_LDPR");
    if (!(a.get("_LDPR") > 0) || f.residualFrom < 0) return fail(err, "_LDPR (residual depth) must lie between 0 and the drilling depth");
    if (f.residualFrom < f.spotEnd - kEps) return fail(err, "_ADPR (spot drilling) and _LDPR (residual depth) overlap");
  }
  return true;
}

// The mode words: each digit the manual defines, within its values; the others not set.
bool modes(const CycleArgs &a, const CycleContext &ctx, std::string &err) {
  for (int k = 2; k <= 5; ++k)
    if (digit(a.get("_VARI"), k) > 1) return fail(err, fmt::format("_VARI digit {} must be 0 or 1", k));
  if (a.get("_VARI") >= 1e5) return fail(err, "_VARI has five digits");
  if (digit(a.get("_AMODE"), 1) > 1 || digit(a.get("_AMODE"), 2) > 1 || a.get("_AMODE") >= 100)
    return fail(err, "_AMODE must be 0 or 1 in its 1st (depth abs/inc) and 2nd digit (degression amount/percent)");
  if (a.get("_GMODE") != 0) return unsupported(err, "_GMODE is reserved: a value other than 0 is not defined");
  if (a.get("_FFA") != 0)
    return unsupported(err, "_FFA (feed units) other than 0 is not supported: the manual gives no codes; program the feeds in mm/min");
  const int cdir = (int)a.get("_CDIR");
  if (a.get("_CDIR") != cdir || (cdir != 0 && cdir != 1 && cdir != 4))
    return fail(err, "_CDIR must be 0 (climb), 1 (conventional) or 4 (conventional, then climb)");
  if (ctx.spindle == 2) return fail(err, "CYCLE78 drills and mills with a right-hand tool: M3, not M4");
  return true;
}

// One thread helix on the tool-centre circle between the thread's end (depth `length`) and
// _RFP: climb milling inside the hole with M3 turns counter-clockwise, and a right-hand thread
// rises turning counter-clockwise, so it runs bottom up or top down as hand and direction say.
void threadPass(Mill &m, Thread t, bool climb, bool rightHand, double feed, double length) {
  t.ccw = climb;
  t.mill = t.approach = feed;
  const bool rises = rightHand == t.ccw;  // along +n, the tool axis
  const bool bottomUp = (rises ? 1 : -1) == -t.dir;
  bottomUp ? helix(m, t, length, 0) : helix(m, t, 0, length);
}

bool sinCycle78(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"_RTP", "_RFP", "_DP", "_DIAM", "_PIT", "_FFD", "_FFR"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (!modes(a, ctx, err)) return false;
  Thread t;
  if (!sinPitchMm(a, t.pitch, err)) return false;
  // The drilling depth: _DP absolute, or (_AMODE 1st digit 1) below _RFP.
  const double rfp = a.get("_RFP"), sdis = std::fabs(a.get("_SDIS"));
  const double end = digit(a.get("_AMODE"), 1) == 1 ? rfp - a.get("_DP") : a.get("_DP");
  if (end == rfp) return fail(err, "the drilling depth is 0: _DP lies on the reference plane _RFP");
  t.dir = end < rfp ? -1 : 1;
  t.surface = rfp, t.zsc = rfp - t.dir * sdis, t.z2 = a.get("_RTP");
  if ((t.z2 - t.zsc) * t.dir > 0) return fail(err, "the retraction plane _RTP lies below the safety level _RFP + _SDIS");
  const double depth = std::fabs(end - rfp);
  std::vector<double> ends;
  DrillFeeds feeds;
  if (!infeeds(a, depth, ends, err) || !drillFeeds(a, ctx, depth, feeds, err)) return false;
  // The thread: from the thread's end _GE above the final depth up to _RFP on the tool-centre
  // circle _DIAM / 2 - r. The helix's approach and departure reach a quarter pitch beyond its
  // end (ThreadMill.h): that must stay in the drilled hole.
  if (!(ctx.toolRadius > 0)) return fail(err, "drill-thread milling needs the tool's radius (a tool with a radius in the spindle)");
  t.radius = a.get("_DIAM") / 2;
  t.centre = t.radius - ctx.toolRadius;
  if (!(t.centre > kEps)) return fail(err, "_DIAM (thread diameter) is not larger than the tool's diameter");
  const double ge = a.get("_GE"), length = depth - ge;
  if (ge < t.pitch / 4 - kEps)
    return fail(err, "_GE (retraction before thread milling) must be at least a quarter pitch: the helix's approach reaches that far below the thread");
  if (!(length > kEps)) return fail(err, "_GE (retraction before thread milling) leaves no thread: it must be less than the drilling depth");
  const double f2 = a.get("_FFR"), fs = a.get("_FFP2");
  const int cdir = (int)a.get("_CDIR");
  if (!(f2 > 0)) return fail(err, "_FFR (thread-milling feed F2) must be greater than 0");
  if (cdir == 4 && !(fs > 0)) return fail(err, "_FFP2 (finishing feed FS) must be greater than 0 with _CDIR 4");
  const PlaneAxes ax = planeAxes((Plane)sinPlane(a, ctx));
  Mill m(out, sinPlane(a, ctx), {ctx.position[ax.u], ctx.position[ax.v]}, 0, t.dir, ctx.position);
  m.up(t.zsc);
  // Drilling: each infeed from where the tool is, then (not after the last) chip removal: rapid
  // out to _RFP + _SDIS and back to _SDIS above the depth reached.
  double at = -sdis;
  for (size_t i = 0; i < ends.size(); ++i) {
    drillTo(m, t, feeds, at, ends[i]);
    if (i + 1 == ends.size()) break;
    m.rapid({0, 0}, t.zsc);
    at = std::max(ends[i] - sdis, -sdis);
    m.rapid({0, 0}, t.level(at));
  }
  if (digit(a.get("_VARI"), 2) == 1) m.rapid({0, 0}, t.zsc);  // chip removal before the thread
  const bool right = digit(a.get("_VARI"), 3) == 0;
  t.start = 0, t.pre = 0;  // from the hole's centre, along the axis at rapid
  if (cdir == 4) {
    threadPass(m, t, false, right, f2, length);
    threadPass(m, t, true, right, fs, length);
  } else {
    threadPass(m, t, cdir == 0, right, f2, length);
  }
  m.up(t.z2);
  return true;
}

const CycleDef kSinDrillThreadEntries[] = {
    {"sin.CYCLE78",
     "_RTP _RFP _SDIS _DP _ADPR _FDPR _LDPR _DIAM _PIT _PITA _DAM _MDEP _VARI _CDIR _GE _FFD _FRDP _FFR _FFP2 _FFA _PITM "
     "_PTAB _PTABA _GMODE _DMODE _AMODE",
     "Sinumerik drill-thread milling", sinCycle78, nullptr, "_RTP:n _RFP:n _DP:n", "~_PITM ~_PTAB ~_PTABA"},
};

}  // namespace

void addSinDrillThreadEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kSinDrillThreadEntries) out.push_back(d);
}

}  // namespace ncc
