// Sinumerik CYCLE70 thread milling (seed000c 19.1.15, L29487-29601) on the thread helix of the
// Heidenhain thread-milling cycles (ThreadMill.h). The manual lists the parameters only; what it
// leaves open is ncc's choice [model], docs/CYCLES.md "Sinumerik thread milling".
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/ThreadMill.h"
#include "runtime/Geometry.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

bool entry::sinPitchMm(const CycleArgs &a, double &pitch, std::string &err) {
  const double p = a.get("_PIT");
  if (!(p > 0)) return fail(err, "_PIT (thread pitch) must be greater than 0");
  switch ((int)a.get("_PITA")) {
  case 0: case 1: pitch = p; break;
  case 2: pitch = 25.4 / p; break;
  case 3: pitch = 25.4 * p; break;
  case 4: pitch = M_PI * p; break;
  default: return fail(err, "_PITA must be 0 … 4");
  }
  return true;
}

namespace {

// The radial depths of the passes (from the crest): roughing (_VARI 1) in equal cuts of at most
// _MID to _H1 - _FAL, finishing (2) the one pass at _H1.
bool passDepths(const CycleArgs &a, std::vector<double> &out, std::string &err) {
  const double h = a.get("_H1"), mid = a.get("_MID"), fal = a.get("_FAL");
  if (!(h > 0)) return fail(err, "_H1 (thread depth) must be greater than 0");
  if (fal < 0 || fal >= h) return fail(err, "_FAL (finishing allowance) must lie between 0 and the thread depth _H1");
  switch (digit(a.get("_VARI"), 1)) {
  case 1: {
    if (!(mid > 0)) return fail(err, "_MID (infeed per cut) must be greater than 0");
    const int n = (int)std::ceil((h - fal) / mid - 1e-9);
    if (n > kMaxPecks) return fail(err, "_MID (infeed per cut) too small");
    for (int k = 1; k <= n; ++k) out.push_back((h - fal) * k / n);
    return true;
  }
  case 2: out.push_back(h); return true;
  default: return fail(err, "_VARI 1st digit must be 1 (roughing) or 2 (finishing)");
  }
}

bool sinCycle70(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"_RTP", "_RFP", "_DP", "_DIATH", "_H1", "_PIT", "_FFR"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  Thread t;
  if (!sinPitchMm(a, t.pitch, err)) return false;
  // The thread length: _DP absolute, or (_AMODE 1st digit 1) below _RFP.
  const double rfp = a.get("_RFP"), sdis = std::fabs(a.get("_SDIS"));
  const double end = digit(a.get("_AMODE"), 1) == 1 ? rfp - a.get("_DP") : a.get("_DP");
  if (end == rfp) return fail(err, "the thread length is 0: _DP lies on the reference plane _RFP");
  t.dir = end < rfp ? -1 : 1;
  t.surface = rfp, t.zsc = rfp - t.dir * sdis, t.z2 = a.get("_RTP");
  if ((t.z2 - t.zsc) * t.dir > 0) return fail(err, "the retraction plane _RTP lies below the safety level _RFP + _SDIS");
  const double length = std::fabs(end - rfp);
  const double typth = a.get("_TYPTH"), nt = a.has("_NT") ? a.get("_NT") : 1;
  if (typth != 0 && typth != 1) return fail(err, "_TYPTH must be 0 (internal) or 1 (external thread)");
  if (nt < 0 || nt != std::floor(nt) || nt > 999) return fail(err, "_NT (teeth on the insert) must be a whole number 0 … 999");
  const int down = digit(a.get("_VARI"), 2), hand = digit(a.get("_VARI"), 3);
  if (down != 1 && down != 2) return fail(err, "_VARI 2nd digit must be 1 (top down) or 2 (bottom up)");
  if (hand > 1) return fail(err, "_VARI 3rd digit must be 0 (right-hand) or 1 (left-hand thread)");
  if (!(a.get("_FFR") > 0)) return fail(err, "_FFR (milling feed) must be greater than 0");
  if (!(ctx.toolRadius > 0)) return fail(err, "thread milling needs the tool's radius (a tool with a radius in the spindle)");
  std::vector<double> depths;
  if (!passDepths(a, depths, err)) return false;
  const bool outside = typth == 1;
  const double r = ctx.toolRadius, nominal = a.get("_DIATH") / 2, h = a.get("_H1");
  if (!(nominal > 0)) return fail(err, "_DIATH (nominal diameter) must be greater than 0");
  // The crest of the cutting edge at radial depth d: inside from the core (nominal - _H1) outward,
  // outside from the nominal radius inward.
  auto crest = [&](double d) { return outside ? nominal - d : nominal - h + d; };
  if (!(crest(0) - (outside ? 0 : r) > 1e-9) || !(crest(h) > 1e-9))
    return fail(err, outside ? "_H1 (thread depth) reaches the thread's axis" : "the tool does not fit the thread's core diameter (_DIATH - 2 x _H1)");
  // [model] A right-hand thread rises turning counter-clockwise: top down (2nd digit 1) it turns
  // clockwise; a left-hand thread the other way.
  t.ccw = (down == 2) == (hand == 0);
  t.mill = t.approach = a.get("_FFR");
  t.pre = 0;  // along the axis at rapid
  t.start = outside ? nominal + r + t.pitch : 0;  // [model] as Heidenhain 267 outside
  // _NSP turns the start point (the helix at the starting plane) about the axis.
  const PlaneAxes ax = planeAxes((Plane)sinPlane(a, ctx));
  const bool centreGiven = a.has("_PA") || a.has("_PO");
  const PlanePoint centre = centreGiven ? PlanePoint{a.get("_PA"), a.get("_PO")} : PlanePoint{ctx.position[ax.u], ctx.position[ax.v]};
  Mill m(out, sinPlane(a, ctx), centre, a.get("_NSP"), t.dir, ctx.position);
  m.go({t.start, 0}, t.z2);
  m.rapid({t.start, 0}, t.zsc);
  // _NT teeth cover _NT pitches per turn: turns _NT pitches apart, the deepest ending at the
  // thread's end (as Heidenhain's Q355); 0 or 1 one helix over the whole length.
  const double shift = nt * t.pitch;
  const int turns = nt <= 1 ? 1 : std::max(1, (int)std::ceil(length / shift - 1e-9));
  if (turns * depths.size() > (size_t)kMaxPecks) return fail(err, "too many helices: check _PIT, _NT and _MID");
  for (double d : depths) {
    t.radius = crest(d);
    t.centre = outside ? t.radius + r : t.radius - r;
    for (int k = 0; k < turns; ++k) {
      if (nt <= 1) {
        down == 1 ? helix(m, t, 0, length) : helix(m, t, length, 0);
        continue;
      }
      const double deep = length - (down == 2 ? k : turns - 1 - k) * shift;
      down == 1 ? helix(m, t, deep - t.pitch, deep) : helix(m, t, deep, deep - t.pitch);
    }
  }
  m.up(t.z2);
  return true;
}

const CycleDef kSinThreadMillEntries[] = {
    {"sin.CYCLE70",
     "_RTP _RFP _SDIS _DP _DIATH _H1 _FAL _PIT _NT _MID _FFR _TYPTH _PA _PO _NSP _VARI _PITA _PITM _PTAB _PTABA _GMODE _DMODE "
     "_AMODE",
     "Sinumerik thread milling", sinCycle70, nullptr, "_RTP:n _RFP:n _DP:n _PA:u _PO:v", "_PITM _PTAB _PTABA"},
};

}  // namespace

void addSinThreadMillEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kSinThreadMillEntries) out.push_back(d);
}

}  // namespace ncc
