// Sinumerik thread turning (SIN-CYC-27): CYCLE99 (one thread: longitudinal or taper) and CYCLE98
// (a chain of up to three sections), seed000c 19.1.29-19.1.30. The manual gives the parameters
// only; the passes are ncc's model, docs/CYCLES.md "Sinumerik thread turning". Lathe geometry in
// the ZX plane, program coordinates, x a radius (ncc runs Sinumerik in DIAMOF): the cycles' X
// positions are diameters when absolute and radii when incremental, as the manual says.
#include "runtime/cycles/Entry.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

constexpr size_t kMaxPasses = 10000;  // a runaway schedule (a tiny first infeed) is an error

struct ZX {
  double z = 0, x = 0;
};

// What both cycles hand the pass generator.
struct ThreadJob {
  std::vector<ZX> crest;      // the crest line: start, intermediate points, end (x radius)
  std::vector<double> lead;   // per section, mm/rev along the section's main axis
  double side = 1;            // +1 outside (deeper = smaller x), -1 inside
  double runIn = 0, runOut = 0;      // straight extensions before the start and after the end
  double entry = 0, exit = 0;        // slanted entry / run-out lengths (from / to the crest)
  double clearance = 0;              // the retract over the crest
  std::vector<double> depths;        // the passes' depths below the crest
  std::vector<double> shifts;        // their shifts along Z (flank infeed)
  std::vector<double> starts;        // the start angles of the thread starts, in machining order
  double changeDepth = 0;            // _GDEP: the starts alternate every this much depth (0: one after another)
};

// The main axis of a section (the lead is measured along it): Z unless X travels further.
int mainAxis(ZX a, ZX b) { return std::fabs(b.x - a.x) > std::fabs(b.z - a.z) ? 0 : 2; }

// The point `len` beyond `from` (along its main axis) on the line from `to` through `from`.
ZX extend(ZX to, ZX from, double len) {
  const double main = mainAxis(to, from) == 2 ? std::fabs(from.z - to.z) : std::fabs(from.x - to.x);
  const double t = len / main;
  return {from.z + (from.z - to.z) * t, from.x + (from.x - to.x) * t};
}

CycleStep threadStep(const CycleContext &ctx, ZX p, double lead, int along, bool chain, double angle) {
  CycleStep s;
  s.kind = CycleStepKind::Thread;
  s.pos = {p.x, ctx.position[1], p.z};
  s.lead = lead, s.along = (uint8_t)along, s.chain = chain, s.angle = chain ? 0 : angle;
  return s;
}

CycleStep rapidStep(const CycleContext &ctx, ZX p) {
  CycleStep s;
  s.pos = {p.x, ctx.position[1], p.z};
  return s;
}

// One pass at `depth`, shifted `shift` along Z, starting at `angle`: rapid to the retract line
// over the pass's start, in, the synchronised chain of sections (with the run-in before and the
// run-out after), out to the retract line.
void threadPass(const ThreadJob &j, const CycleContext &ctx, double retractX, double depth, double shift,
                double angle, std::vector<CycleStep> &out) {
  auto at = [&](ZX p, double d) { return ZX{p.z + shift, p.x - j.side * d}; };
  const std::vector<ZX> &c = j.crest;
  const size_t n = c.size() - 1;
  const int firstAxis = mainAxis(c[0], c[1]), lastAxis = mainAxis(c[n - 1], c[n]);
  ZX begin = at(c[0], depth);
  bool started = false;
  if (j.entry > 0) {  // in on the crest, then down the slope to the thread's start
    ZX e = at(extend(c[1], c[0], j.entry), 0);
    out.push_back(rapidStep(ctx, {e.z, retractX}));
    out.push_back(rapidStep(ctx, e));
    out.push_back(threadStep(ctx, begin, j.lead[0], firstAxis, false, angle));
    started = true;
  } else if (j.runIn > 0) {
    ZX r = at(extend(c[1], c[0], j.runIn), depth);
    out.push_back(rapidStep(ctx, {r.z, retractX}));
    out.push_back(rapidStep(ctx, r));  // the run-in lies on the first section's line
  } else {
    out.push_back(rapidStep(ctx, {begin.z, retractX}));
    out.push_back(rapidStep(ctx, begin));
  }
  for (size_t i = 1; i <= n; ++i) {
    out.push_back(threadStep(ctx, at(c[i], depth), j.lead[i - 1], mainAxis(c[i - 1], c[i]), started, angle));
    started = true;
  }
  ZX last = at(c[n], depth);
  if (j.exit > 0) last = at(extend(c[n - 1], c[n], j.exit), 0);
  else if (j.runOut > 0) last = at(extend(c[n - 1], c[n], j.runOut), depth);
  if (j.exit > 0 || j.runOut > 0) out.push_back(threadStep(ctx, last, j.lead[n - 1], lastAxis, true, angle));
  out.push_back(rapidStep(ctx, {last.z, retractX}));
}

// Every pass of every start; the starts one after another, or (changeDepth > 0) in turn, each
// cutting the passes of the next changeDepth of depth before the next start takes over.
void threadPasses(const ThreadJob &j, const CycleContext &ctx, std::vector<CycleStep> &out) {
  double retractX = j.side > 0 ? -1e300 : 1e300;
  for (const ZX &p : j.crest) retractX = j.side > 0 ? std::max(retractX, p.x) : std::min(retractX, p.x);
  for (double len : {j.runIn, j.entry})
    if (len > 0) {
      double x = extend(j.crest[1], j.crest[0], len).x;
      retractX = j.side > 0 ? std::max(retractX, x) : std::min(retractX, x);
    }
  for (double len : {j.runOut, j.exit})
    if (len > 0) {
      const size_t n = j.crest.size() - 1;
      double x = extend(j.crest[n - 1], j.crest[n], len).x;
      retractX = j.side > 0 ? std::max(retractX, x) : std::min(retractX, x);
    }
  retractX += j.side * j.clearance;
  size_t from = 0;
  while (from < j.depths.size()) {
    size_t to = j.depths.size();
    if (j.changeDepth > 0) {
      const double band = (std::floor(j.depths[from] / j.changeDepth - 1e-9) + 1) * j.changeDepth;
      to = from;
      while (to < j.depths.size() && j.depths[to] <= band + 1e-9) ++to;
    }
    for (double angle : j.starts)
      for (size_t p = from; p < to; ++p) threadPass(j, ctx, retractX, j.depths[p], j.shifts[p], angle, out);
    from = to;
  }
  // [model] the cycle ends on the retract line over the first pass's start, as it began.
  CycleStep first = out.front();
  out.push_back(first);
}

// The pass depths (from the crest): roughing to height - allowance in `count` infeeds or infeeds
// of at most `first` (linear: equal depths; degressive: constant chip section, depth ~ sqrt(n)),
// then the finishing pass at the full height, then `idle` passes where the last one cut.
struct Schedule {
  double height = 0, allowance = 0, first = 0;
  int count = 0;
  bool byFirst = false, degressive = false, rough = true, finish = true;
  int idle = 0;
};
bool threadDepths(const Schedule &s, std::vector<double> &out, std::string &err) {
  const double rough = s.height - s.allowance;
  if (!(s.height > 0)) return fail(err, "the thread depth must be greater than 0");
  if (s.allowance < 0 || !(rough > 0)) return fail(err, "the finishing allowance must be at least 0 and below the thread depth");
  if (s.rough) {
    if (s.byFirst) {
      if (!(s.first > 0)) return fail(err, "the first infeed _MID must be greater than 0");
      if (rough / s.first > (s.degressive ? 1e8 : kMaxPasses)) return fail(err, "the first infeed is too small for the thread depth");
      for (int n = 1; out.empty() || out.back() < rough; ++n) {
        double d = s.degressive ? s.first * std::sqrt((double)n) : s.first * n;
        out.push_back(std::min(d, rough));
        if (out.size() > kMaxPasses) return fail(err, "the first infeed is too small for the thread depth");
      }
    } else {
      if (s.count < 1 || s.count > (int)kMaxPasses) return fail(err, "the number of roughing cuts must be 1 to 10000");
      for (int n = 1; n <= s.count; ++n)
        out.push_back(n == s.count ? rough
                                   : s.degressive ? rough * std::sqrt((double)n / s.count) : rough * n / s.count);
    }
  }
  if (s.finish && (s.allowance > 0 || !s.rough)) out.push_back(s.height);
  if (s.idle < 0 || s.idle > 1000) return fail(err, "the number of idle passes must be 0 to 1000");
  if (out.empty()) return fail(err, "no pass to cut");
  for (int i = 0; i < s.idle; ++i) out.push_back(out.back());
  return true;
}

// The flank infeed: each pass shifted along Z so that the passes approach the full-depth pass
// (which lies on the programmed positions) along a line at `angle` degrees to X; `flank` 1 one
// flank (the sign of the angle picks which), 2 alternating flanks, 0 straight in.
bool flankShifts(double angle, int flank, const std::vector<double> &depths, double height, std::vector<double> &out,
                 std::string &err) {
  if (!(std::fabs(angle) < 90)) return fail(err, "the infeed angle must lie between -90 and 90 degrees");
  const double t = std::tan(std::fabs(angle) * M_PI / 180.0), sign = angle < 0 ? -1.0 : 1.0;
  for (size_t i = 0; i < depths.size(); ++i) {
    double s = flank == 0 || angle == 0 ? 0 : -sign * (height - depths[i]) * t;
    if (flank == 2 && i % 2 == 1) s = -s;
    out.push_back(s);
  }
  return true;
}

// Pitch units (_PITA): 0/1 mm, 2 threads per inch, 3 inch, 4 module (the pitch pi x m).
bool pitchMM(double value, int unit, double &out, std::string &err) {
  switch (unit) {
  case 0: case 1: out = value; break;
  case 2: if (!(value > 0)) return fail(err, "the pitch in threads per inch must be greater than 0"); out = 25.4 / value; break;
  case 3: out = value * 25.4; break;
  case 4: out = value * M_PI; break;
  default: return fail(err, fmt::format("_PITA {:g} is not a pitch unit (0-4)", (double)unit));
  }
  if (!(out > 0)) return fail(err, "the pitch must be greater than 0");
  return true;
}

// The thread starts' angles: `n` starts 360/n apart from `offset`, all of them or (mode 1) from
// start `first` on, or (mode 2) only that one, ascending or (descending) the other way round.
bool startAngles(int n, double offset, int mode, int first, bool descending, std::vector<double> &out, std::string &err) {
  if (n < 1 || n > 360) return fail(err, "the number of thread starts must be 1 to 360");
  if (mode != 0 && (first < 1 || first > n)) return fail(err, fmt::format("the start thread _GST must be 1 to {}", n));
  std::vector<int> order;
  for (int k = 1; k <= n; ++k) order.push_back(descending ? n + 1 - k : k);
  if (mode == 1) order.erase(order.begin(), std::find(order.begin(), order.end(), first));
  if (mode == 2) order = {first};
  for (int k : order) {
    double a = std::fmod(offset + (k - 1) * 360.0 / n, 360.0);
    out.push_back(a < 0 ? a + 360 : a);
  }
  return true;
}

bool lathePlane(const CycleArgs &a, const CycleContext &ctx, std::string &err) {
  if (sinPlane(a, ctx) != 1) return unsupported(err, "thread turning outside the turning plane G18 is not supported");
  return true;
}

// The technology word shared by both cycles (_VARI): 1st digit outside/inside and linear or
// degressive, 3rd the flank infeed, 5th count or first infeed, 6th rough/finish, 7th the order
// of the starts.
bool technology(const CycleArgs &a, const char *tdep, const char *fal, const char *nrc, const char *nid,
                ThreadJob &j, Schedule &s, int &flank, bool compatFlank, std::string &err) {
  const double vari = a.get("_VARI");
  const int tech = digit(vari, 1);
  if (tech < 1 || tech > 4) return fail(err, "_VARI 1st digit must be 1-4 (outside/inside, linear/degressive)");
  j.side = tech == 1 || tech == 3 ? 1 : -1;  // 4: inside (the manual prints "outside" twice)
  s.degressive = tech >= 3;
  flank = digit(vari, 3);
  if (flank > 2) return fail(err, "_VARI 3rd digit (infeed) must be 0, 1 or 2");
  if (flank == 0 && compatFlank) flank = a.get("_IANG") < 0 ? 2 : 1;
  s.byFirst = digit(vari, 5) == 1;
  if (digit(vari, 5) > 1) return fail(err, "_VARI 5th digit must be 0 (number of cuts) or 1 (first infeed)");
  const int mach = digit(vari, 6);
  if (mach > 3) return fail(err, "_VARI 6th digit must be 0-3 (1 roughing, 2 finishing, 3 both)");
  s.rough = mach != 2, s.finish = mach != 1;
  if (!a.has(tdep)) return fail(err, std::string(tdep) + " (thread depth) is required");
  s.height = std::fabs(a.get(tdep));
  s.allowance = std::fabs(a.get(fal));
  s.count = (int)a.get(nrc, 0);
  if (s.count != a.get(nrc, 0)) return fail(err, std::string(nrc) + " (number of roughing cuts) must be whole");
  s.first = a.get("_MID");
  s.idle = (int)a.get(nid);
  if (s.idle != a.get(nid)) return fail(err, std::string(nid) + " (idle passes) must be whole");
  return threadDepths(s, j.depths, err);
}

// CYCLE99(_SPL, _SPD, _FPL, _FPD, _APP, _ROP, _TDEP, _FAL, _IANG, _NSP, _NRC, _NID, _PIT, _VARI,
// _NUMTH, _SDIS, _MID, _GDEP, _PIT1, _FDEP, _GST, _GUD, _IFLANK, _PITA, _PITM, _PTAB, _PTABA,
// _DMODE, _AMODE, _S_XRS)
bool sinCycle99(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (!lathePlane(a, ctx, err)) return false;
  for (const char *k : {"_SPL", "_SPD", "_FPL", "_PIT"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  const double amode = a.get("_AMODE"), dmode = a.get("_DMODE");
  const int kind = digit(dmode, 2);
  if (kind == 1) return unsupported(err, "a face (spiral) thread (_DMODE 2nd digit 1) is not supported");
  if (kind > 2) return fail(err, "_DMODE 2nd digit must be 0 (longitudinal), 1 (face) or 2 (taper)");
  if (a.get("_PIT1") != 0) return unsupported(err, "a variable pitch (_PIT1, G34/G35) is not supported");
  if (a.get("_FDEP") != 0) return unsupported(err, "a plunge depth _FDEP is not supported (the manual does not say how it acts)");
  if (a.get("_S_XRS") != 0) return unsupported(err, "sag compensation _S_XRS (a spherical thread) is not supported");
  if (digit(amode, 4) == 1) return unsupported(err, "the infeed slope as a width (_AMODE 4th digit 1, _IFLANK) is not supported");
  ZX start{a.get("_SPL"), a.get("_SPD") / 2}, end;
  end.z = digit(amode, 1) == 1 ? start.z + a.get("_FPL") : a.get("_FPL");
  const int xform = digit(amode, 2);
  if (xform == 2) return unsupported(err, "the taper as an angle (_AMODE 2nd digit 2) is not supported: give the end X");
  if (xform > 2) return fail(err, "_AMODE 2nd digit must be 0 (absolute diameter), 1 (incremental radius) or 2 (angle)");
  end.x = !a.has("_FPD") ? start.x : xform == 1 ? start.x + a.get("_FPD") : a.get("_FPD") / 2;
  if (kind == 0 && std::fabs(end.x - start.x) > 1e-9)
    return fail(err, "a longitudinal thread (_DMODE 2nd digit 0) ends at its start X: program _DMODE 2nd digit 2 for a taper");
  if (std::fabs(end.z - start.z) < 1e-9) return fail(err, "the thread has no length along Z (_SPL = _FPL)");
  double pitch;
  if (!pitchMM(a.get("_PIT"), (int)a.get("_PITA"), pitch, err)) return false;
  ThreadJob j;
  j.crest = {start, end};
  j.lead = {pitch};
  const int runInMode = digit(amode, 3);
  if (runInMode > 2) return fail(err, "_AMODE 3rd digit must be 0 (run-in), 1 (entry = run-out) or 2 (entry)");
  const double app = std::fabs(a.get("_APP")), rop = std::fabs(a.get("_ROP"));
  if (runInMode == 0) j.runIn = app;
  else j.entry = runInMode == 1 ? rop : app;
  j.exit = rop;
  j.clearance = a.get("_SDIS") == 0 ? 1.0 : std::fabs(a.get("_SDIS"));  // [model] 0: 1 mm, as CYCLE98's _VRT
  Schedule s;
  int flank;
  if (!technology(a, "_TDEP", "_FAL", "_NRC", "_NID", j, s, flank, false, err)) return false;
  if (!flankShifts(a.get("_IANG"), flank, j.depths, s.height, j.shifts, err)) return false;
  const bool multi = digit(amode, 5) == 1;
  if (!multi && a.get("_NUMTH", 1) > 1)
    return fail(err, "_NUMTH > 1 needs a multi-start thread (_AMODE 5th digit 1)");
  const int n = multi ? (int)a.get("_NUMTH", 1) : 1;
  if (multi && n != a.get("_NUMTH", 1)) return fail(err, "_NUMTH (number of starts) must be whole");
  j.changeDepth = multi ? std::fabs(a.get("_GDEP")) : 0;
  const int startMode = multi ? digit(amode, 6) : 0;
  if (startMode > 2) return fail(err, "_AMODE 6th digit must be 0 (all starts), 1 (from _GST) or 2 (only _GST)");
  if (!startAngles(n, a.get("_NSP"), startMode, (int)a.get("_GST"), digit(a.get("_VARI"), 7) == 1, j.starts, err))
    return false;
  threadPasses(j, ctx, out);
  return true;
}

// CYCLE98(_PO1, _DM1, _PO2, _DM2, _PO3, _DM3, _PO4, _DM4, APP, ROP, TDEP, FAL, _IANG, NSP, NRC, NID,
// _PP1, _PP2, _PP3, _VARI, _NUMTH, _VRT, _MID, _GDEP, _IFLANK, _PITA, _PITM1, _PITM2, _PITM3, _DMODE,
// _AMODE)
bool sinCycle98(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (!lathePlane(a, ctx, err)) return false;
  for (const char *k : {"_PO1", "_DM1", "_PO4", "_DM4", "_PP1"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  const double amode = a.get("_AMODE");
  if (digit(amode, 7) == 1) return unsupported(err, "the infeed slope as a width (_AMODE 7th digit 1, _IFLANK) is not supported");
  ThreadJob j;
  j.crest.push_back({a.get("_PO1"), a.get("_DM1") / 2});
  // The points after the start: Z1 X1 … Z3 X3, each absolute or incremental (_AMODE digits 1-6);
  // an intermediate point left out (both words) is no section.
  static const char *const kZ[] = {"_PO2", "_PO3", "_PO4"}, *const kX[] = {"_DM2", "_DM3", "_DM4"},
                           *const kPitch[] = {"_PP1", "_PP2", "_PP3"};
  int section = 0;
  for (int i = 0; i < 3; ++i) {
    if (i < 2 && !a.has(kZ[i]) && !a.has(kX[i])) continue;
    const int zm = digit(amode, 2 * i + 1), xm = digit(amode, 2 * i + 2);
    if (xm == 2) return unsupported(err, fmt::format("the taper as an angle (_AMODE digit {}) is not supported: give the X", 2 * i + 2));
    if (zm > 1 || xm > 2) return fail(err, fmt::format("_AMODE digits {} and {} must be 0 (absolute) or 1 (incremental)", 2 * i + 1, 2 * i + 2));
    const ZX prev = j.crest.back();
    ZX p{zm == 1 ? prev.z + a.get(kZ[i]) : a.get(kZ[i], prev.z), xm == 1 ? prev.x + a.get(kX[i]) : a.has(kX[i]) ? a.get(kX[i]) / 2 : prev.x};
    if (std::hypot(p.z - prev.z, p.x - prev.x) < 1e-9) return fail(err, fmt::format("section {} has no length", section + 1));
    // The pitch of section k is _PP<k>; a section without its own takes the one before.
    const char *pk = kPitch[section];
    double pitch;
    if (!pitchMM(a.has(pk) ? a.get(pk) : a.get(kPitch[std::max(0, section - 1)]), (int)a.get("_PITA"), pitch, err)) return false;
    j.crest.push_back(p);
    j.lead.push_back(pitch);
    ++section;
  }
  j.runIn = std::fabs(a.get("APP"));
  j.runOut = std::fabs(a.get("ROP"));
  j.clearance = a.get("_VRT") == 0 ? 1.0 : std::fabs(a.get("_VRT"));  // 0: 1 mm (the manual)
  Schedule s;
  int flank;
  if (!technology(a, "TDEP", "FAL", "NRC", "NID", j, s, flank, true, err)) return false;
  if (!flankShifts(a.get("_IANG"), flank, j.depths, s.height, j.shifts, err)) return false;
  const int starts = digit(amode, 8);
  if (starts > 2) return fail(err, "_AMODE 8th digit must be 0-2");
  const int n = starts == 1 ? 1 : (int)a.get("_NUMTH", 1);
  if (n != a.get("_NUMTH", 1) && starts != 1) return fail(err, "_NUMTH (number of starts) must be whole");
  j.changeDepth = n > 1 ? std::fabs(a.get("_GDEP")) : 0;
  return startAngles(n, a.get("NSP"), 0, 1, digit(a.get("_VARI"), 7) == 1, j.starts, err) &&
         (threadPasses(j, ctx, out), true);
}

const CycleDef kEntries[] = {
    {"sin.CYCLE99",
     "_SPL _SPD _FPL _FPD _APP _ROP _TDEP _FAL _IANG _NSP _NRC _NID _PIT _VARI _NUMTH _SDIS _MID _GDEP _PIT1 _FDEP _GST "
     "_GUD _IFLANK _PITA _PITM _PTAB _PTABA _DMODE _AMODE _S_XRS",
     "Sinumerik thread turning", sinCycle99, nullptr, "_SPL:u _SPD:d _FPL:u _FPD:d", "~_PITM ~_PTAB ~_PTABA"},
    {"sin.CYCLE98",
     "_PO1 _DM1 _PO2 _DM2 _PO3 _DM3 _PO4 _DM4 APP ROP TDEP FAL _IANG NSP NRC NID _PP1 _PP2 _PP3 _VARI _NUMTH _VRT _MID "
     "_GDEP _IFLANK _PITA _PITM1 _PITM2 _PITM3 _DMODE _AMODE",
     "Sinumerik chained threads", sinCycle98, nullptr, "_PO1:u _DM1:d _PO2:u _DM2:d _PO3:u _DM3:d _PO4:u _DM4:d",
     "~_PITM1 ~_PITM2 ~_PITM3"},
};

}  // namespace

void addSinThreadEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kEntries) out.push_back(d);
}

}  // namespace ncc
