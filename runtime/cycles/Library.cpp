#include "runtime/Transmit.h"
#include "runtime/cycles/Library.h"
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/Mill.h"
#include "runtime/Geometry.h"

#include <algorithm>
#include <fmt/format.h>
#include <cmath>

namespace ncc {

int entry::digit(double word, int n) {
  long v = (long)std::fabs(word);
  for (int i = 1; i < n; ++i) v /= 10;
  return (int)(v % 10);
}

int entry::sinPlane(const CycleArgs &a, const CycleContext &ctx) {
  int p = digit(a.get("_DMODE"), 1);
  return p >= 1 && p <= 3 ? p - 1 : ctx.plane;
}

bool entry::heiLevels(const CycleArgs &a, HeiLevels &l, std::string &err) {
  for (const char *k : {"Q200", "Q201", "Q203", "Q206"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  double depth = a.get("Q201"), surface = a.get("Q203");
  l.dir = depth < 0 ? -1 : 1;
  l.zsc = surface - l.dir * std::fabs(a.get("Q200"));
  l.bottom = surface + depth;
  l.z2 = surface - l.dir * std::max(std::fabs(a.get("Q200")), std::fabs(a.get("Q204")));
  if (!(a.get("Q206") > 0)) return fail(err, "Q206 (plunging feed) must be greater than 0");
  return true;
}

using namespace entry;

namespace {

// A move (rapid or feed) at the hole (the cycle runs at ctx.position) to `level` on the drilling axis.
void atLevel(const CycleContext &ctx, int plane, double level, std::vector<CycleStep> &out,
             CycleStepKind kind = CycleStepKind::Rapid, double feed = 0) {
  CycleStep st;
  st.kind = kind;
  st.pos = ctx.position;
  st.pos[planeAxes((Plane)plane).n] = level;
  st.feed = feed;
  out.push_back(st);
}

// A spindle step: 1 (M3) clockwise, 2 (M4) counter-clockwise, anything else stop.
void spindleStep(int dir, std::vector<CycleStep> &out) {
  CycleStep st;
  st.kind = dir == 1 ? CycleStepKind::SpindleCW : dir == 2 ? CycleStepKind::SpindleCCW : CycleStepKind::SpindleStop;
  out.push_back(st);
}

// The steps of one hole: rapid to the start level above the hole, then the HoleSpec.
void hole(const HoleSpec &h, int plane, const CycleContext &ctx, std::vector<CycleStep> &out) {
  const PlaneAxes ax = planeAxes((Plane)plane);
  if (ctx.position[ax.n] != h.start) atLevel(ctx, plane, h.start, out);  // a pattern may already be there
  holeSteps(h, ax.u, ax.v, ax.n, ctx.position[ax.u], ctx.position[ax.v], out);
}

// ---- Sinumerik drilling cycles (seed000c 19.1.21-23, 19.1.25): RTP RFP SDIS DP DPR …
// Depth: _AMODE 1st digit 1 = DPR (relative to RFP), 2 = DP; 0 (compatibility) = DPR when it is
// programmed, else DP. Dwell: _AMODE digit: 1 s, 2 revolutions, 0 = the sign (>0 s, <0 rev).
struct SinHole {
  double rtp, start, bottom, dir;
  int plane;
};
bool sinLevels(const CycleArgs &a, const CycleContext &ctx, SinHole &h, std::string &err) {
  for (const char *k : {"RTP", "RFP"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  double rfp = a.get("RFP");
  int mode = digit(a.get("_AMODE"), 1);
  bool rel = mode == 1 || (mode == 0 && a.has("DPR"));
  if (rel ? !a.has("DPR") : !a.has("DP")) return fail(err, rel ? "DPR (relative depth) is required" : "DP or DPR (depth) is required");
  double bottom = rel ? rfp - a.get("DPR") : a.get("DP");
  h.dir = bottom < rfp ? -1 : 1;
  h.rtp = a.get("RTP");
  h.start = rfp - h.dir * std::fabs(a.get("SDIS"));
  h.bottom = bottom;
  h.plane = sinPlane(a, ctx);
  if ((h.rtp - h.start) * h.dir > 0) return fail(err, "the retraction plane RTP lies below the safety level RFP + SDIS");
  return true;
}
bool sinDwell(const CycleArgs &a, const char *key, int amodeDigit, const CycleContext &ctx, double &out,
              std::string &err) {
  out = -1;
  if (!a.has(key) || a.get(key) == 0) return true;
  double v = a.get(key);
  int mode = digit(a.get("_AMODE"), amodeDigit);
  bool revs = mode == 2 || (mode == 0 && v < 0);
  if (!revs) return out = std::fabs(v), true;
  if (ctx.speed <= 0) return fail(err, std::string(key) + " in spindle revolutions needs a spindle speed");
  out = std::fabs(v) * 60 / ctx.speed;
  return true;
}

bool sinCycle81(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  if (digit(a.get("_GMODE"), 2) == 1) return fail(err, "centring to a diameter (_GMODE 2nd digit 1) needs the tool angle: not supported");
  HoleSpec h;
  h.start = s.start, h.bottom = s.bottom, h.retract = s.rtp;
  if (!sinDwell(a, "DTB", 2, ctx, h.dwellBottom, err)) return false;
  hole(h, s.plane, ctx, out);
  return true;
}

// A CYCLE82 feed S_FA/S_FD: _AMODE digit 0 = % of the drilling feed, 1 = mm/min, 2 = mm/rev.
bool sinFeed82(const CycleArgs &a, const char *key, int amodeDigit, const CycleContext &ctx, double &out,
               std::string &err) {
  double v = a.get(key);
  if (!(v > 0)) return fail(err, std::string(key) + " (feed) must be greater than 0");
  int unit = digit(a.get("_AMODE"), amodeDigit);
  if (unit == 1) return out = v, true;
  if (unit == 2) {
    if (ctx.speed <= 0) return fail(err, std::string(key) + " per revolution needs a spindle speed");
    return out = v * ctx.speed, true;
  }
  if (ctx.feed <= 0) return fail(err, std::string(key) + " in % needs a feed programmed before the cycle");
  return out = ctx.feed * v / 100, true;
}

// CYCLE82 (seed000c §19.1.22, [model] order): rapid to RFP + SDIS; spot drilling (_VARI 5th
// digit) feeds at S_FA to S_ZA (inc below RFP or abs, _AMODE 3rd digit); the drilling feed to
// DP, or with through-drilling (_VARI 4th digit) to S_ZD above DP (inc or abs, _AMODE 5th digit)
// and at S_FD on to DP; dwell DTB; rapid to RTP.
bool sinCycle82(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (digit(a.get("_GMODE"), 2) == 1) return fail(err, "depth to the shank (_GMODE 2nd digit 1) needs the tool angle: not supported");
  const bool through = digit(a.get("_VARI"), 4) == 1, spot = digit(a.get("_VARI"), 5) == 1;
  if (!through && !spot) return sinCycle81(a, ctx, out, err);
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  const double rfp = a.get("RFP");
  double spotLevel = s.start, residual = s.bottom, spotFeed = 0, residualFeed = 0;
  if (spot) {
    spotLevel = digit(a.get("_AMODE"), 3) == 1 ? a.get("S_ZA") : rfp + s.dir * std::fabs(a.get("S_ZA"));
    if ((spotLevel - s.start) * s.dir <= 0 || (spotLevel - s.bottom) * s.dir > 0)
      return fail(err, "the spot-drilling depth S_ZA must lie between RFP + SDIS and the drilling depth");
    if (!sinFeed82(a, "S_FA", 4, ctx, spotFeed, err)) return false;
  }
  if (through) {
    residual = digit(a.get("_AMODE"), 5) == 1 ? a.get("S_ZD") : s.bottom - s.dir * std::fabs(a.get("S_ZD"));
    if ((residual - spotLevel) * s.dir < 0 || (residual - s.bottom) * s.dir > 0)
      return fail(err, "the residual depth S_ZD must lie between the spot-drilling level and the drilling depth");
    if (!sinFeed82(a, "S_FD", 6, ctx, residualFeed, err)) return false;
  }
  double dwell;
  if (!sinDwell(a, "DTB", 2, ctx, dwell, err)) return false;
  if (ctx.position[planeAxes((Plane)s.plane).n] != s.start) atLevel(ctx, s.plane, s.start, out);
  if (spot) atLevel(ctx, s.plane, spotLevel, out, CycleStepKind::Feed, spotFeed);
  if (residual != spotLevel) atLevel(ctx, s.plane, residual, out, CycleStepKind::Feed);
  if (through && residual != s.bottom) atLevel(ctx, s.plane, s.bottom, out, CycleStepKind::Feed, residualFeed);
  if (dwell >= 0) {
    CycleStep d;
    d.kind = CycleStepKind::Dwell;
    d.seconds = dwell;
    out.push_back(d);
  }
  atLevel(ctx, s.plane, s.rtp, out);
  return true;
}

bool sinCycle83(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  if (digit(a.get("_GMODE"), 2) == 1) return fail(err, "depth to the shank (_GMODE 2nd digit 1) needs the tool angle: not supported");
  if (a.has("_AXN") && a.get("_AXN") != 0) return fail(err, "_AXN (tool axis other than the plane's) is not supported");
  HoleSpec h;
  h.start = s.start, h.bottom = s.bottom, h.retract = s.rtp;
  double rfp = a.get("RFP");
  // First depth: FDPR relative to RFP or FDEP absolute (_AMODE 5th digit, 0 = whichever is given).
  int m5 = digit(a.get("_AMODE"), 5);
  bool rel = m5 == 1 || (m5 == 0 && a.has("FDPR"));
  if (rel ? !a.has("FDPR") : !a.has("FDEP")) return fail(err, "FDEP or FDPR (first drilling depth) is required");
  double first = rel ? rfp - a.get("FDPR") : a.get("FDEP");
  double firstPeck = (h.start - first) * -s.dir;  // from the start level
  if (firstPeck <= 0) return fail(err, "the first drilling depth lies above the start level RFP + SDIS");
  if (std::fabs(h.bottom - h.start) / firstPeck > kMaxPecks) return fail(err, "first drilling depth too small");
  h.peck = firstPeck;
  // Degression: _AMODE 6th digit 1 = amount, 2 = percentage, 0 = the sign of _DAM (>0 amount).
  double dam = a.get("_DAM");
  int m6 = digit(a.get("_AMODE"), 6);
  if (m6 == 2 || (m6 == 0 && dam < 0))
    return fail(err, "CYCLE83 percentage degression (_DAM < 0 or _AMODE 6th digit 2) is not supported");
  // The classic 840D rule: each infeed is the previous one less _DAM, and never less than _DAM.
  h.decrement = h.minPeck = std::fabs(dam);
  if (dam == 0) h.minPeck = 0, h.decrement = 0;
  // First-infeed feed factor FRF (0.001..1, 0 = 100 %).
  double frf = a.get("FRF");
  if (digit(a.get("_AMODE"), 8) == 1) frf /= 100;
  if (frf < 0 || frf > 9.99999) return fail(err, "FRF out of range");
  if (frf > 0 && frf != 1) {
    if (ctx.feed <= 0) return fail(err, "FRF needs a feed programmed before the cycle");
    h.firstFeed = ctx.feed * frf;
  }
  if (!sinDwell(a, "DTB", 2, ctx, h.dwellPeck, err) || !sinDwell(a, "_DTD", 4, ctx, h.dwellBottom, err))
    return false;
  if (!a.has("_DTD")) h.dwellBottom = h.dwellPeck;  // compatibility: DTB also at the final depth
  if (digit(a.get("VARI"), 1) == 0) {  // chip breaking: back by V2 (_VRT, default 1 mm) at the feed
    h.breaksPerRetract = -1;
    h.chipBreak = a.get("_VRT") > 0 ? a.get("_VRT") : 1.0;
    h.chipBreakRapid = false;
  } else {  // chip removal: rapid to RFP + SDIS, dwell DTS, rapid back to V3 above the last depth
    h.breaksPerRetract = 0;
    if (!sinDwell(a, "DTS", 3, ctx, h.dwellTop, err)) return false;
    int m7 = digit(a.get("_AMODE"), 7);
    if (m7 == 1 || (m7 == 0 && a.get("_DIS1") <= 0))
      return fail(err, "CYCLE83 automatic anticipation distance (_DIS1 = 0) is computed by the controller: program _DIS1 > 0");
    h.reentry = a.get("_DIS1");
  }
  hole(h, s.plane, ctx, out);
  return true;
}

bool sinCycle85(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  if (!(a.get("FFR") > 0) || !(a.get("RFF") > 0)) return fail(err, "FFR and RFF (feeds in and out) must be greater than 0");
  HoleSpec h;
  h.start = s.start, h.bottom = s.bottom, h.retract = s.rtp;
  h.feed = a.get("FFR");
  h.exit = HoleExit::Feed, h.exitLevel = s.start, h.exitFeed = a.get("RFF");
  if (!sinDwell(a, "DTB", 2, ctx, h.dwellBottom, err)) return false;
  hole(h, s.plane, ctx, out);
  return true;
}

// CYCLE86 (seed000c, [model]): spindle on per SDIR, in at the active feed, dwell DTB, oriented
// stop at POSS, lift-off RPA RPO (plane axes) RPAP (tool axis) unless _GMODE 1, rapid out to
// RFP + SDIS, back to the centre there, rapid to RTP, spindle on again.
bool sinCycle86(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  int sdir = (int)a.get("SDIR");
  if (sdir != 3 && sdir != 4) return fail(err, "SDIR (spindle direction) must be 3 (M3) or 4 (M4)");
  HoleSpec h;
  h.start = s.start, h.bottom = s.bottom, h.retract = s.rtp;
  if (!sinDwell(a, "DTB", 2, ctx, h.dwellBottom, err)) return false;
  h.exit = HoleExit::OrientShift;
  h.orientAngle = a.get("POSS");
  h.exitLevel = s.start, h.centreAtExit = true;
  h.spindle = sdir == 4 ? 2 : 1;
  if (digit(a.get("_GMODE"), 1) == 0) h.shift[0] = a.get("RPA"), h.shift[1] = a.get("RPO"), h.shift[2] = a.get("RPAP");
  spindleStep(h.spindle, out);
  hole(h, s.plane, ctx, out);
  return true;
}

// ISO metric coarse threads: the pitch of M<d> (CYCLE840 MPIT, DIN 13-1).
double metricCoarsePitch(double d) {
  static const double kPitch[][2] = {{3, 0.5},   {4, 0.7},   {5, 0.8},   {6, 1},   {8, 1.25}, {10, 1.5}, {12, 1.75},
                                     {14, 2},    {16, 2},    {18, 2.5},  {20, 2.5}, {22, 2.5}, {24, 3},   {27, 3},
                                     {30, 3.5},  {33, 3.5},  {36, 4},    {39, 4},   {42, 4.5}, {45, 4.5}, {48, 5}};
  for (auto &p : kPitch)
    if (p[0] == d) return p[1];
  return 0;
}

// CYCLE840 (seed000c, [model]), tapping with a compensating chuck: in from RFP + SDIS to the depth at
// the tapping feed, the spindle reversed (SDR 3/4, 0: the other way), out to RFP + SDIS, the
// spindle as SDAC says (3 M3, 4 M4, 5 M5), rapid to RTP. ENC: 1 feed as programmed, dwell at the
// depth; 11 feed S x pitch (MPIT or PIT), dwell at the depth; 0 (with encoder, G33) feed
// S x pitch, no dwell; 20 as 0 with the dwell after the retraction.
bool sinCycle840(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  if (ctx.spindle == 0) return fail(err, "CYCLE840 needs the spindle turning (M3/M4) before the cycle");
  const int enc = (int)a.get("ENC"), sdr = (int)a.get("SDR"), sdac = a.has("SDAC") ? (int)a.get("SDAC") : 5;
  if (enc != 0 && enc != 1 && enc != 11 && enc != 20) return fail(err, "ENC must be 0, 1, 11 or 20");
  if (sdr != 0 && sdr != 3 && sdr != 4) return fail(err, "SDR (retraction direction) must be 0, 3 or 4");
  if (sdac != 3 && sdac != 4 && sdac != 5) return fail(err, "SDAC (direction after the cycle) must be 3, 4 or 5");
  if (a.get("_PITA") != 0 && a.get("_PITA") != 1) return fail(err, "_PITA other than mm (0, 1) is not supported");
  if (a.get("_TECHNO") != 0) return fail(err, "_TECHNO (exact stop, feedforward, acceleration settings) is not supported");
  double feed = ctx.feed;
  if (enc != 1) {
    double pitch = a.get("PIT");
    if (a.has("MPIT") && a.get("_PITA") == 0) {
      pitch = metricCoarsePitch(a.get("MPIT"));
      if (pitch == 0) return fail(err, "MPIT must be an ISO metric size 3..48 (M3..M48)");
    }
    if (!(pitch > 0)) return fail(err, "MPIT or PIT (the thread pitch) is required");
    if (!(ctx.speed > 0)) return fail(err, "CYCLE840 needs a spindle speed: the feed is S x pitch");
    feed = ctx.speed * pitch;
  } else if (!(feed > 0)) {
    return fail(err, "CYCLE840 with ENC 1 taps at the programmed feed: program F first");
  }
  double dwell = -1;
  if (enc == 1 || enc == 11 || enc == 20)
    if (!sinDwell(a, "DTB", 2, ctx, dwell, err)) return false;
  auto dwellStep = [&] {
    CycleStep st;
    st.kind = CycleStepKind::Dwell;
    st.seconds = dwell;
    if (dwell >= 0) out.push_back(st);
  };
  if (ctx.position[planeAxes((Plane)s.plane).n] != s.start) atLevel(ctx, s.plane, s.start, out);
  atLevel(ctx, s.plane, s.bottom, out, CycleStepKind::Feed, feed);
  if (enc != 20) dwellStep();
  spindleStep(sdr ? sdr - 2 : 3 - ctx.spindle, out);  // SDR 3/4 = M3/M4; 0: the other way
  atLevel(ctx, s.plane, s.start, out, CycleStepKind::Feed, feed);
  if (enc == 20) dwellStep();
  spindleStep(sdac - 2, out);  // 3 M3, 4 M4, 5 stop
  atLevel(ctx, s.plane, s.rtp, out);
  return true;
}

// CYCLE84 (seed000c, [model]), rigid tapping: rapid to RFP + SDIS, oriented stop at POSS, G331 to
// the depth at SST with the pitch (MPIT's ISO coarse pitch or PIT), G332 back to RFP + SDIS, the
// spindle as SDAC says (3 M3, 4 M4, 5 stop), rapid to RTP. The tap is one rigid-tap record pair,
// so a dwell at the depth (DTB), another retraction speed (SST1), deep tapping (_VARI) and the
// technology settings (_TECHNO) are refused. The hand (the sign of MPIT/PIT or _AMODE's 4th
// digit) only turns the spindle the other way: the path is the same.
bool sinCycle84(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  SinHole s;
  if (!sinLevels(a, ctx, s, err)) return false;
  const int sdac = a.has("SDAC") ? (int)a.get("SDAC") : 5;
  if (sdac != 3 && sdac != 4 && sdac != 5) return fail(err, "SDAC (direction after the cycle) must be 3, 4 or 5");
  if (a.get("_PITA") != 0 && a.get("_PITA") != 1) return fail(err, "_PITA other than mm (0, 1) is not supported");
  if (a.get("_TECHNO") != 0) return fail(err, "_TECHNO (exact stop, feedforward, acceleration settings) is not supported");
  if (digit(a.get("_VARI"), 1) != 0) return fail(err, "deep-hole tapping (_VARI 1 or 2: pecks with G332) is not supported");
  if (a.get("DTB") != 0)
    return fail(err, "a dwell at the thread depth (DTB) is not supported: the tap is one rigid-tap record down and back");
  double pitch = std::fabs(a.get("PIT"));
  if (a.has("MPIT") && a.get("MPIT") != 0 && a.get("_PITA") == 0) {
    pitch = metricCoarsePitch(std::fabs(a.get("MPIT")));
    if (pitch == 0) return fail(err, "MPIT must be an ISO metric size 3..48 (M3..M48)");
  }
  if (!(pitch > 0)) return fail(err, "MPIT or PIT (the thread pitch) is required");
  const double sst = a.get("SST"), sst1 = a.get("SST1");
  if (sst < 0 || sst1 < 0) return fail(err, "SST and SST1 (spindle speeds) must not be negative");
  if (!(sst > 0) && !(ctx.speed > 0)) return fail(err, "CYCLE84 needs a spindle speed: SST or S before the cycle");
  if (sst1 > 0 && sst1 != (sst > 0 ? sst : ctx.speed))
    return fail(err, "a retraction speed SST1 other than the tapping speed is not supported (the tap is one record)");
  if (ctx.position[planeAxes((Plane)s.plane).n] != s.start) atLevel(ctx, s.plane, s.start, out);
  CycleStep orient;
  orient.kind = CycleStepKind::SpindleOrient;
  orient.angle = a.get("POSS");
  out.push_back(orient);
  atLevel(ctx, s.plane, s.bottom, out);
  out.back().kind = CycleStepKind::RigidTap;
  out.back().lead = pitch;
  out.back().speed = sst;
  spindleStep(sdac - 2, out);  // 3 M3, 4 M4, 5 stop
  atLevel(ctx, s.plane, s.rtp, out);
  return true;
}

// ---- Heidenhain drilling cycles (seed002a 200, 201, 203): levels as heiLevels (Entry.h); depth
// 0: the cycle does nothing.
double heiDwell(const CycleArgs &a, const char *k) { return a.get(k) > 0 ? a.get(k) : -1; }

// The common part of 200 and 203: levels, the plunge feed, infeeds of Q202 counted from the
// surface (one pass when Q202 reaches the depth) and Q210 at the top. False with err set, or
// with err empty when the depth is 0 (the TNC does not run the cycle).
bool heiPeckHole(const CycleArgs &a, HoleSpec &h, std::string &err) {
  HeiLevels l;
  if (!heiLevels(a, l, err)) return false;
  if (a.get("Q201") == 0) return false;
  if (a.get("Q395") != 0) return fail(err, "Q395 = 1 (depth to the cylindrical part) needs the tool's point angle: not supported");
  h.start = l.zsc, h.bottom = l.bottom, h.retract = l.z2;
  h.feed = a.get("Q206");
  double peck = std::fabs(a.get("Q202"));
  if (peck > 0 && peck < std::fabs(a.get("Q201"))) {
    if (std::fabs(a.get("Q201")) / peck > kMaxPecks) return fail(err, "Q202 (plunging depth) too small");
    h.peck = peck;
    h.peckFromSet = true, h.peckFrom = a.get("Q203");
    h.dwellTop = heiDwell(a, "Q210");
  }
  return true;
}

bool hei200(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HoleSpec h;
  if (!heiPeckHole(a, h, err)) return err.empty();
  h.breaksPerRetract = 0;  // every infeed: rapid to the set-up clearance, dwell, rapid back
  h.reentry = std::fabs(a.get("Q200"));
  h.dwellPeck = h.dwellBottom = heiDwell(a, "Q211");  // at every infeed (manual L1904)
  hole(h, ctx.plane, ctx, out);
  return true;
}

// One pass at Q206 from the set-up clearance to the depth, out to the 2nd set-up clearance: the
// common part of 201, 202 and 206. False with err set, or with err empty when the depth is 0.
bool heiHole(const CycleArgs &a, HoleSpec &h, HeiLevels &l, std::string &err) {
  if (!heiLevels(a, l, err) || a.get("Q201") == 0) return false;
  h.start = l.zsc, h.bottom = l.bottom, h.retract = l.z2;
  h.feed = a.get("Q206");
  return true;
}

bool hei201(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HeiLevels l;
  HoleSpec h;
  if (!heiHole(a, h, l, err)) return err.empty();
  h.dwellBottom = heiDwell(a, "Q211");
  h.exit = HoleExit::Feed, h.exitLevel = l.zsc;
  h.exitFeed = a.get("Q208") > 0 ? a.get("Q208") : h.feed;
  h.exitRapid = l.z2 != l.zsc;
  hole(h, ctx.plane, ctx, out);
  return true;
}

bool hei203(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HoleSpec h;
  if (!heiPeckHole(a, h, err)) return err.empty();
  h.decrement = std::fabs(a.get("Q212"));
  h.minPeck = std::fabs(a.get("Q205"));
  h.breaksPerRetract = (int)std::max(0.0, a.get("Q213"));
  h.chipBreak = h.reentry = std::fabs(a.get("Q256"));
  h.fullRetractFeed = a.get("Q208") > 0 ? a.get("Q208") : h.feed;
  h.dwellBottom = heiDwell(a, "Q211");
  hole(h, ctx.plane, ctx, out);
  return true;
}

// 202 BORING: in at Q206, dwell Q211, oriented stop at Q336, 0.2 mm off the wall towards Q214
// (1 -a1, 2 -a2, 3 +a1, 4 +a2; 0 none), out at Q208 to the set-up clearance, rapid to the 2nd,
// back to the centre, spindle on again ([model]: the manual does not say; as before the cycle).
bool hei202(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HeiLevels l;
  HoleSpec h;
  if (!heiHole(a, h, l, err)) return err.empty();
  int q214 = (int)a.get("Q214");
  if (q214 < 0 || q214 > 4 || q214 != a.get("Q214")) return fail(err, "Q214 (disengaging direction) must be 0..4");
  if (ctx.spindle == 0) return fail(err, "202 needs the spindle turning (M3/M4) before the cycle");
  h.dwellBottom = heiDwell(a, "Q211");
  h.exit = HoleExit::OrientShift;
  h.orientAngle = a.get("Q336");
  h.exitLevel = l.zsc;
  h.exitFeed = a.get("Q208") > 0 ? a.get("Q208") : h.feed;
  h.spindle = ctx.spindle;
  static const int kAxis[] = {0, 0, 1, 0, 1};
  static const double kSign[] = {0, -1, -1, 1, 1};
  h.shift[kAxis[q214]] = 0.2 * kSign[q214];
  hole(h, ctx.plane, ctx, out);
  return true;
}

// 206 TAPPING with a floating holder: in at Q206 (= S x pitch), reverse, dwell Q211, out at Q206
// to the set-up clearance, forward again there, rapid to the 2nd set-up clearance. The thread's
// hand is the spindle's direction (M3 right, M4 left).
bool hei206(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HeiLevels l;
  HoleSpec h;
  if (!heiHole(a, h, l, err)) return err.empty();
  if (ctx.spindle == 0) return fail(err, "206 needs the spindle turning (M3/M4) before the cycle");
  h.retract = l.zsc;
  h.exitFeed = h.feed;
  h.dwellBottom = heiDwell(a, "Q211");
  h.exit = HoleExit::Tap;
  h.spindle = ctx.spindle;
  hole(h, ctx.plane, ctx, out);
  if (l.z2 != l.zsc) atLevel(ctx, ctx.plane, l.z2, out);
  return true;
}

// 240 CENTERING (L1771-L1856): in at Q206 to the depth Q201 (Q343 = 0) or to the diameter Q344
// (Q343 = 1), dwell Q211, rapid to the 2nd set-up clearance. A diameter needs the tool's point
// angle T-ANGLE (L1826-L1828): the cone of point angle T reaches the diameter D at the depth
// D / 2 / tan(T / 2) below its tip; Q344's sign is the direction, as Q201's.
bool hei240(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  const double toDiameter = a.get("Q343");
  if (toDiameter != 0 && toDiameter != 1) return fail(err, "Q343 must be 0 (to the depth Q201) or 1 (to the diameter Q344)");
  CycleArgs b = a;
  if (toDiameter == 1) {
    const double t = ctx.pointAngle, d = a.get("Q344");
    if (!(t > 0 && t < 180))
      return fail(err, t == 0 ? "Q343 = 1 (centring to the diameter Q344) needs the tool's point angle T-ANGLE "
                                "(point_angle in the machine's tool table)"
                              : "Q343 = 1: the tool's point angle T-ANGLE must lie between 0 and 180 degrees");
    b.num["Q201"] = d / 2 / std::tan(t / 2 * M_PI / 180);
  }
  HeiLevels l;
  HoleSpec h;
  if (!heiHole(b, h, l, err)) return err.empty();
  h.dwellBottom = heiDwell(a, "Q211");
  hole(h, ctx.plane, ctx, out);
  return true;
}

// 209 TAPPING WITH CHIP BREAKING (L4330-L4489): rapid to the set-up clearance, spindle oriented
// to Q336, then in the tapping direction (the sign of Q239) at S x |Q239| in infeeds of Q257
// counted from the surface; after each the spindle reverses, the tool backs out Q256 x |Q239|
// (Q256 = 0: to the set-up clearance) and, forward again, goes on to the next infeed; at the
// depth it reverses and comes out to the set-up clearance, where the spindle stops; rapid to the
// 2nd set-up clearance; a spindle that turned before the cycle turns again (L4387-L4396).
// Q403 (a faster retraction speed) other than 1 is an error: the steps carry no speed change.
bool hei209(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"Q200", "Q201", "Q239", "Q203"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (a.get("Q201") == 0) return true;
  const double pitch = a.get("Q239");
  if (pitch == 0) return fail(err, "Q239 (thread pitch) must not be 0");
  if (!(ctx.speed > 0)) return fail(err, "209 needs a spindle speed: the feed is S x pitch");
  if (a.has("Q403") && a.get("Q403") != 1)
    return fail(err, "Q403 (retraction speed factor) other than 1 is not supported");
  CycleArgs b = a;
  const double feed = ctx.speed * std::fabs(pitch);
  b.num["Q206"] = feed;
  HeiLevels l;
  if (!heiLevels(b, l, err)) return false;
  const int plane = ctx.plane, tap = pitch > 0 ? 1 : 2, back = 3 - tap;
  const double infeed = std::fabs(a.get("Q257")), backOff = std::fabs(a.get("Q256")) * std::fabs(pitch);
  if (infeed > 0 && std::fabs(l.bottom - a.get("Q203")) / infeed > kMaxPecks)
    return fail(err, "Q257 (infeed depth per chip break) too small");
  atLevel(ctx, plane, l.zsc, out);
  CycleStep orient;
  orient.kind = CycleStepKind::SpindleOrient;
  orient.angle = a.get("Q336");
  out.push_back(orient);
  spindleStep(tap, out);
  for (double level = a.get("Q203");;) {
    level = infeed > 0 ? level + l.dir * infeed : l.bottom;
    if ((level - l.bottom) * l.dir >= 0) level = l.bottom;
    atLevel(ctx, plane, level, out, CycleStepKind::Feed, feed);
    spindleStep(back, out);
    if (level == l.bottom) break;
    atLevel(ctx, plane, backOff > 0 ? level - l.dir * backOff : l.zsc, out, CycleStepKind::Feed, feed);
    spindleStep(tap, out);
  }
  atLevel(ctx, plane, l.zsc, out, CycleStepKind::Feed, feed);
  spindleStep(0, out);
  if (l.z2 != l.zsc) atLevel(ctx, plane, l.z2, out);
  if (ctx.spindle != 0) spindleStep(ctx.spindle, out);
  return true;
}

// 208 BORE MILLING (L3197-L3329): rapid to the set-up clearance over the centre, out to the bore
// radius Q335/2 - r, a helix of Q334 per turn at Q206 to the depth, once round there, back to the
// centre, rapid to the 2nd set-up clearance; a bore as wide as the tool is drilled straight down.
// The direction: Q351 +1 (or 0) climb, -1 up-cut, for M3 (M4 reverses): climb inside a bore runs
// counter-clockwise. [model] the move out to the radius and back to the centre at Q206, the helix
// starting on the +main axis side; the tool table has no ANGLE to limit Q334 (the manual: only
// when ANGLE is set).
bool hei208(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  HeiLevels l;
  for (const char *k : {"Q334", "Q335"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (!heiLevels(a, l, err)) return false;
  if (a.get("Q201") == 0) return true;
  if (!(ctx.toolRadius > 0)) return fail(err, "208 needs the tool's radius (a tool with a radius in the spindle)");
  const double feed = a.get("Q206"), rb = a.get("Q335") / 2 - ctx.toolRadius, pitch = std::fabs(a.get("Q334"));
  if (rb < -1e-9) return fail(err, "Q335 (the bore's diameter) is smaller than the tool");
  if (a.get("Q342") <= 0 && a.get("Q335") > 4 * ctx.toolRadius)
    return fail(err, "Q335 is more than twice the tool's diameter: give the pre-drilled diameter Q342");
  if (rb > 1e-9 && !(pitch > 0)) return fail(err, "Q334 (infeed per helix turn) must be greater than 0");
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  Mill mill(out, ctx.plane, {ctx.position[ax.u], ctx.position[ax.v]}, 0, l.dir, ctx.position);
  mill.up(l.zsc);
  if (rb <= 1e-9) {
    mill.feed({0, 0}, l.bottom, feed);
  } else {
    const bool ccw = (a.get("Q351") >= 0) == (ctx.spindle != 2);
    const double turns = std::fabs(l.zsc - l.bottom) / pitch, whole = std::floor(turns + 1e-9), part = turns - whole;
    mill.feed({rb, 0}, l.zsc, feed);
    const double angle = (ccw ? 1 : -1) * part * 2 * M_PI;
    PlanePoint end = part < 1e-9 ? PlanePoint{rb, 0} : PlanePoint{rb * std::cos(angle), rb * std::sin(angle)};
    mill.arc(end, {0, 0}, ccw, l.bottom, feed, part < 1e-9 ? (int)whole : (int)whole + 1);
    mill.arc(mill.here(), {0, 0}, ccw, l.bottom, feed);
    mill.feed({0, 0}, l.bottom, feed);
  }
  mill.up(l.z2);
  return true;
}

// 207 RIGID TAPPING: the feed is S x |Q239| (spindle-synchronised), the hand the sign of Q239
// (+ right-hand, M3; - left-hand, M4); reverse at the bottom, out to the set-up clearance where
// the spindle stops, rapid to the 2nd; a spindle that turned before the cycle turns again.
bool hei207(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  for (const char *k : {"Q200", "Q201", "Q239", "Q203"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  if (a.get("Q201") == 0) return true;
  double pitch = a.get("Q239");
  if (pitch == 0) return fail(err, "Q239 (thread pitch) must not be 0");
  if (!(ctx.speed > 0)) return fail(err, "207 needs a spindle speed: the feed is S x pitch");
  CycleArgs b = a;
  b.num["Q206"] = ctx.speed * std::fabs(pitch);
  HeiLevels l;
  if (!heiLevels(b, l, err)) return false;
  HoleSpec h;
  h.start = l.zsc, h.bottom = l.bottom, h.retract = l.zsc;
  h.feed = h.exitFeed = b.get("Q206");
  h.exit = HoleExit::Tap;
  h.spindle = pitch > 0 ? 1 : 2;
  if (ctx.spindle != h.spindle) spindleStep(h.spindle, out);  // the tapping direction before the infeed
  hole(h, ctx.plane, ctx, out);
  out.pop_back();  // Tap turns forward again at the top: 207 leaves the spindle stopped there
  if (l.z2 != l.zsc) atLevel(ctx, ctx.plane, l.z2, out);
  if (ctx.spindle != 0) spindleStep(ctx.spindle, out);
  return true;
}

// ---- patterns
bool count(const CycleArgs &a, const char *k, int &n, std::string &err) {
  double v = a.get(k);
  if (!a.has(k) || v < 1 || v != std::floor(v) || v > 99999) return fail(err, std::string(k) + " must be a count 1..99999");
  n = (int)v;
  return true;
}

bool sinHoles1(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  int n;
  if (!count(a, "NUM", n, err)) return false;
  out = linePattern({a.get("SPCA"), a.get("SPCO")}, a.get("STA1"), a.get("FDIS"), a.get("DBH"), n);
  // _HIDE is a STRING; a single position may arrive as a number.
  auto hide = a.text.find("_HIDE");
  if (hide != a.text.end()) return hidePositions(out, hide->second, err);
  return !a.has("_HIDE") || hidePositions(out, std::to_string((long)a.get("_HIDE")), err);
}

bool sinHoles2(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  int n;
  if (!count(a, "NUM", n, err)) return false;
  double vari = a.get("_VARI");
  if (digit(vari, 2) == 1) return fail(err, "HOLES2 positioning along the circle (_VARI 2nd digit 1) is not supported");
  if (digit(vari, 5) != 0) return fail(err, "HOLES2 with a rotary axis (_VARI 5th digit) is not supported");
  int form = digit(vari, 4);  // 1 full circle, 2 pitch circle, 0 compatibility: INDA = 0 is full
  bool full = form == 1 || (form == 0 && a.get("INDA") == 0);
  double step = full ? 360.0 / n : a.get("INDA");
  out = circlePattern({a.get("CPA"), a.get("CPO")}, a.get("RAD"), a.get("STA1"), step, n);
  return true;
}

// CYCLE801 (seed000c 19.1.34): _NUM1 columns _DIS1 apart along the axis turned by _STA, _NUM2
// rows _DIS2 apart across; _VARI 1st digit 1 the frame only. [model] the rows meander (the
// manual leaves the order to the control) and the _HIDE numbers count in that order; the shear
// angles _ANG1 _ANG2 are errors.
bool sinCycle801(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  int n1, n2;
  if (!count(a, "_NUM1", n1, err) || !count(a, "_NUM2", n2, err)) return false;
  if (a.get("_ANG1") != 0 || a.get("_ANG2") != 0)
    return fail(err, "CYCLE801 with shear angles (_ANG1, _ANG2) is not supported");
  int form = digit(a.get("_VARI"), 1);
  if (form > 1) return fail(err, "_VARI 1st digit must be 0 (grid) or 1 (frame)");
  out = gridPattern({a.get("_SPCA"), a.get("_SPCO")}, a.get("_STA"), std::fabs(a.get("_DIS1")), std::fabs(a.get("_DIS2")),
                    n1, n2, true, form == 1);
  auto hide = a.text.find("_HIDE");
  return hide == a.text.end() || hidePositions(out, hide->second, err);
}

// CYCLE802 (seed000c 19.1.35): up to nine positions _X0 _Y0 … _X8 _Y8, each coordinate absolute
// or incremental to the position before by its digit of _XA / _YA (digit n, from the units, for
// position n: 1 absolute, 2 incremental; the first programmed position is absolute). A position
// with one coordinate keeps the other from the position before [model]. Rotary-axis patterns
// (_VARI 5th digit): errors.
bool sinCycle802(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  if (digit(a.get("_VARI"), 5) != 0) return fail(err, "CYCLE802 with a rotary axis (_VARI 5th digit) is not supported");
  PlanePoint at{0, 0};
  for (int n = 0; n < 9; ++n) {
    const std::string k[2] = {"_X" + std::to_string(n), "_Y" + std::to_string(n)};
    if (!a.has(k[0]) && !a.has(k[1])) continue;
    for (int i = 0; i < 2; ++i) {
      if (!a.has(k[i])) continue;
      int mode = out.empty() ? 1 : digit(a.get(i ? "_YA" : "_XA"), n + 1);
      if (mode != 1 && mode != 2)
        return fail(err, fmt::format("{} digit {} (position {}) must be 1 (absolute) or 2 (incremental)", i ? "_YA" : "_XA",
                                     n + 1, n));
      at[i] = mode == 1 ? a.get(k[i]) : at[i] + a.get(k[i]);
    }
    out.push_back(at);
  }
  if (out.empty()) return fail(err, "CYCLE802 has no position (_X0 _Y0 …)");
  return true;
}

bool hei220(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  int n;
  if (!count(a, "Q241", n, err)) return false;
  if (a.get("Q365") != 0) return fail(err, "Q365 = 1 (traverse along the pitch circle) is not supported");
  double start = a.get("Q245"), stop = a.get("Q246"), step = a.get("Q247");
  if (step == 0) {
    if (std::fabs(stop - start) == 360) step = 360.0 / n;
    else if (stop == start) return fail(err, "Q246 (stopping angle) must differ from Q245");
    else step = n > 1 ? (stop - start) / (n - 1) : 0;
  }
  out = circlePattern({a.get("Q216"), a.get("Q217")}, a.get("Q244") / 2, start, step, n);
  return true;
}

bool hei221(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  int n1, n2;
  if (!count(a, "Q242", n1, err) || !count(a, "Q243", n2, err)) return false;
  out = gridPattern({a.get("Q225"), a.get("Q226")}, a.get("Q224"), a.get("Q237"), a.get("Q238"), n1, n2, true, false);
  return true;
}

constexpr const char *kDrillCoords = "RTP:n RFP:n DP:n";  // the Sinumerik drilling cycles' planes

const CycleDef kHoleEntries[] = {
    {"sin.CYCLE81", "RTP RFP SDIS DP DPR DTB _GMODE _DMODE _AMODE", "Sinumerik drilling, centring", sinCycle81, nullptr, kDrillCoords},
    {"sin.CYCLE82", "RTP RFP SDIS DP DPR DTB _GMODE _DMODE _AMODE _VARI S_ZA S_FA S_ZD S_FD",
     "Sinumerik drilling, counterboring", sinCycle82, nullptr, kDrillCoords},
    {"sin.CYCLE83",
     "RTP RFP SDIS DP DPR FDEP FDPR _DAM DTB DTS FRF VARI _AXN _MDEP _VRT _DTD _DIS1 _GMODE _DMODE _AMODE",
     "Sinumerik deep-hole drilling", sinCycle83, nullptr, "RTP:n RFP:n DP:n FDEP:n"},
    {"sin.CYCLE85", "RTP RFP SDIS DP DPR DTB FFR RFF _GMODE _DMODE _AMODE", "Sinumerik reaming", sinCycle85, nullptr, kDrillCoords},
    {"sin.CYCLE86", "RTP RFP SDIS DP DPR DTB SDIR RPA RPO RPAP POSS _GMODE _DMODE _AMODE",
     "Sinumerik boring with oriented stop and lift-off", sinCycle86, nullptr, kDrillCoords},
    {"sin.CYCLE84", "RTP RFP SDIS DP DPR DTB SDAC MPIT PIT POSS SST SST1 _AXN _PITA _TECHNO _VARI _DAM _VRT _PITM _PTAB _PTABA _GMODE _DMODE _AMODE",
     "Sinumerik rigid tapping", sinCycle84, nullptr, kDrillCoords},
    {"sin.CYCLE840", "RTP RFP SDIS DP DPR DTB SDR SDAC ENC MPIT PIT _AXN _PITA _TECHNO _PITM _PTAB _PTABA _GMODE _DMODE _AMODE",
     "Sinumerik tapping with a compensating chuck", sinCycle840, nullptr, kDrillCoords},
    {"sin.HOLES1", "SPCA SPCO STA1 FDIS DBH NUM _VARI _UMODE _HIDE _NSP _DMODE", "Sinumerik row of holes", nullptr,
     sinHoles1, "SPCA:u SPCO:v", "_HIDE"},
    {"sin.HOLES2", "CPA CPO RAD STA1 INDA NUM _VARI _UMODE _HIDE _NSP _DMODE", "Sinumerik circle of holes", nullptr,
     sinHoles2, "CPA:u CPO:v", "_HIDE"},
    {"sin.CYCLE801", "_SPCA _SPCO _STA _DIS1 _DIS2 _NUM1 _NUM2 _VARI _UMODE _ANG1 _ANG2 _HIDE _NSP _DMODE",
     "Sinumerik grid or frame of positions", nullptr, sinCycle801, "_SPCA:u _SPCO:v", "_HIDE"},
    {"sin.CYCLE802",
     "_XA _YA _X0 _Y0 _X1 _Y1 _X2 _Y2 _X3 _Y3 _X4 _Y4 _X5 _Y5 _X6 _Y6 _X7 _Y7 _X8 _Y8 _VARI _UMODE _DMODE S_ABA S_AB0 "
     "S_AB1 S_AB2 S_AB3 S_AB4 S_AB5 S_AB6 S_AB7 S_AB8",
     "Sinumerik arbitrary positions", nullptr, sinCycle802},
    {"hei.200", "Q200 Q201 Q206 Q202 Q210 Q203 Q204 Q211 Q395", "Heidenhain drilling", hei200, nullptr},
    {"hei.201", "Q200 Q201 Q206 Q211 Q208 Q203 Q204", "Heidenhain reaming", hei201, nullptr},
    {"hei.203", "Q200 Q201 Q206 Q202 Q210 Q203 Q204 Q212 Q213 Q205 Q211 Q208 Q256 Q395",
     "Heidenhain universal drilling", hei203, nullptr},
    {"hei.202", "Q200 Q201 Q206 Q211 Q208 Q203 Q204 Q214 Q336", "Heidenhain boring", hei202, nullptr},
    {"hei.206", "Q200 Q201 Q206 Q211 Q203 Q204", "Heidenhain tapping with a floating holder", hei206, nullptr},
    {"hei.207", "Q200 Q201 Q239 Q203 Q204", "Heidenhain rigid tapping", hei207, nullptr},
    {"hei.240", "Q200 Q343 Q201 Q344 Q206 Q211 Q203 Q204", "Heidenhain centering", hei240, nullptr},
    {"hei.208", "Q200 Q201 Q206 Q334 Q203 Q204 Q335 Q342 Q351", "Heidenhain bore milling", hei208, nullptr},
    {"hei.209", "Q200 Q201 Q239 Q203 Q204 Q257 Q256 Q336 Q403", "Heidenhain tapping with chip breaking", hei209, nullptr},
    {"hei.220", "Q216 Q217 Q244 Q245 Q246 Q247 Q241 Q200 Q203 Q204 Q301 Q365", "Heidenhain polar pattern", nullptr,
     hei220},
    {"hei.221", "Q225 Q226 Q237 Q238 Q242 Q243 Q224 Q200 Q203 Q204 Q301", "Heidenhain Cartesian pattern", nullptr,
     hei221},
};

}  // namespace

void addHoleEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kHoleEntries) out.push_back(d);
}

const std::vector<CycleDef> &cycleLibrary() {
  static const std::vector<CycleDef> all = [] {
    std::vector<CycleDef> v;
    addHoleEntries(v);
    addClearingEntries(v);
    addSinClearingEntries(v);
    addSinSpigotEntries(v);
    addSinThreadMillEntries(v);
    addSinDrillThreadEntries(v);
    addHeiPatternEntries(v);
    addHeiThreadMillEntries(v);
    addHeiDeepHoleEntries(v);
    addSinThreadEntries(v);
    addSinTurningEntries(v);
    addTransformEntries(v);  // runtime/Transmit.cpp: TRANSMIT, TRACYL, TRAFOOF
    addSinGrooveEntries(v);
    addSinUndercutEntries(v);
    return v;
  }();
  return all;
}

const CycleDef *findCycle(std::string_view name) {
  for (auto &d : cycleLibrary())
    if (name == d.name) return &d;
  return nullptr;
}

bool cycleSignature(std::string_view name, CycleSignature &out) {
  const CycleDef *d = findCycle(name);
  if (!d) return false;
  out = {d->name, d->params, d->strings ? d->strings : "", d->positions != nullptr, d->contour};
  return true;
}

std::vector<std::string_view> cycleParamNames(const CycleDef &def) {
  std::vector<std::string_view> out;
  std::string_view s = def.params;
  for (size_t i = 0; i < s.size();) {
    size_t j = s.find(' ', i);
    if (j == std::string_view::npos) j = s.size();
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j + 1;
  }
  return out;
}

int cycleParamIndex(const CycleDef &def, std::string_view name) {
  auto ps = cycleParamNames(def);
  auto it = std::find(ps.begin(), ps.end(), name);
  return it == ps.end() ? -1 : (int)(it - ps.begin());
}

bool checkCycleArgs(const CycleDef &def, const CycleArgs &args, std::string &err) {
  auto known = [&](const std::string &k) { return cycleParamIndex(def, k) >= 0; };
  for (auto &[k, v] : args.num)
    if (!known(k)) return fail(err, std::string(def.name) + " has no parameter " + k + " (it has: " + def.params + ")");
  for (auto &[k, v] : args.text) {
    if (!known(k)) return fail(err, std::string(def.name) + " has no parameter " + k + " (it has: " + def.params + ")");
    std::string_view strings = def.strings ? def.strings : "";
    if (strings.find(k) == std::string_view::npos)
      return fail(err, std::string(def.name) + " parameter " + k + " takes a number, not a string");
  }
  return true;
}

bool expandPattern(const CycleDef &pattern, const CycleArgs &pa, const CycleDef *hole, CycleArgs ha,
                   const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (isCallPatPattern(pattern)) {
    if (!hole) return fail(err, "CYCL CALL PAT needs a machining cycle defined (CYCL DEF) before it");
    return walkCallPat(pattern, pa, *hole, ha, ctx, out, err);
  }
  if (!pattern.positions || (hole && !hole->expand))
    return fail(err, std::string(pattern.name) + " with " + hole->name + ": a position pattern runs a machining cycle");
  bool hei = std::string_view(pattern.name).substr(0, 4) == "hei.";
  if (!hole && hei) return fail(err, std::string(pattern.name) + " needs a cycle to run at its positions");
  if (hole && hei != (std::string_view(hole->name).substr(0, 4) == "hei."))
    return fail(err, "a pattern runs the cycles of its own controller");
  std::vector<PlanePoint> pts;
  if (!pattern.positions(pa, pts, err)) return false;
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  const int a1 = ax.u, a2 = ax.v, d = ax.n;
  std::array<double, 3> here = ctx.position;
  double between = here[d];  // Sinumerik: from hole to hole at the level the cycle retracts to
  if (hei) {
    // The pattern's Q200 Q203 Q204 replace the cycle's; Q301 picks the level between holes.
    for (const char *k : {"Q200", "Q203", "Q204"})
      if (pa.has(k)) ha.num[k] = pa.get(k);
    double dir = ha.get("Q201") < 0 ? -1 : 1, surface = ha.get("Q203");
    double zsc = surface - dir * std::fabs(ha.get("Q200"));
    double z2 = surface - dir * std::max(std::fabs(ha.get("Q200")), std::fabs(ha.get("Q204")));
    between = pa.get("Q301") != 0 ? z2 : zsc;
    CycleStep up;  // rapid to the 2nd set-up clearance first
    up.pos = here, up.pos[d] = z2;
    out.push_back(up);
    here[d] = z2;
  }
  for (size_t i = 0; i < pts.size(); ++i) {
    CycleStep to;  // rapid in the plane at the current level
    to.pos = here, to.pos[a1] = pts[i][0], to.pos[a2] = pts[i][1];
    out.push_back(to);
    here = to.pos;
    if (!hole) continue;  // Sinumerik: without a modal cycle the pattern only positions
    CycleContext at = ctx;
    at.position = to.pos;
    size_t first = out.size();
    if (!hole->expand(ha, at, out, err)) return false;
    // The last retract of the hole goes to the level between holes (Heidenhain Q301); the last
    // hole retracts as the cycle says.
    if (hei && i + 1 < pts.size())
      for (size_t k = out.size(); k-- > first;)
        if (out[k].kind == CycleStepKind::Rapid) {
          out[k].pos[d] = between;
          break;
        }
    here = out.back().pos;
    for (size_t k = out.size(); k-- > first;)
      if (out[k].kind == CycleStepKind::Rapid || out[k].kind == CycleStepKind::Feed) {
        here = out[k].pos;
        break;
      }
  }
  return true;
}

}  // namespace ncc
