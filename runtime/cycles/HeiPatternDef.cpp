// Heidenhain PATTERN DEF and point tables with CYCL CALL PAT (seed002a §3.3, §3.4; manual
// L1241-L1278, L1607-L1676): the six forms' positions (the shared walkers of Pattern.h) and the
// walk between them, which differs from cycles 220/221 (expandPattern): the pattern does not
// replace the cycle's Q200/Q203/Q204, each position has a surface of its own that adds to Q203,
// the tool goes to the "safe height" (the higher of the tool-axis position at the call and the
// cycle's 2nd set-up clearance) between positions at the call's feed, and GLOBAL DEF 125
// (Q345 = 1) makes that the 2nd set-up clearance alone.
#include "runtime/cycles/Entry.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/Library.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

using namespace entry;

namespace {

// The walk's own parameters, after each form's: F the feed between positions (absent: the
// programmed feed), FMAX 1 rapid, Q345 GLOBAL DEF 125's switch, H the tool-axis position at the
// CYCL CALL PAT when this op continues a pattern split over several ops (a point table, several
// forms in one PATTERN DEF): its first position is then reached as any other between positions.
#define HEI_WALK " F FMAX Q345 H"

bool countOf(const CycleArgs &a, const char *k, int &n, std::string &err) {
  double v = a.get(k);
  if (!a.has(k) || v < 1 || v != std::floor(v) || v > 99999) return fail(err, std::string(k) + " must be a count 1..99999");
  n = (int)v;
  return true;
}

bool required(const CycleArgs &a, std::initializer_list<const char *> ks, std::string &err) {
  for (const char *k : ks)
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  return true;
}

// POS1 … POS9 (the front end makes incremental ones absolute; a point table arrives the same way,
// nine rows per op).
bool posPattern(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  for (int k = 1; k <= 9; ++k) {
    std::string x = fmt::format("X{}", k), y = fmt::format("Y{}", k);
    if (!a.has(x) && !a.has(y)) break;
    if (!a.has(x) || !a.has(y)) return fail(err, fmt::format("position {} needs X and Y", k));
    out.push_back({a.get(x), a.get(y)});
  }
  if (out.empty()) return fail(err, "no position (X1 Y1 …)");
  return true;
}

bool rowPattern(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) {
  int n;
  if (!required(a, {"X", "Y", "D"}, err) || !countOf(a, "NUM", n, err)) return false;
  out = linePattern({a.get("X"), a.get("Y")}, a.get("ROT"), 0, a.get("D"), n);
  return true;
}

// PAT1 / FRAME1: ROTX turns the main-axis direction, ROTY the secondary one, each added to ROT
// (the digest's vector reading of L1345-L1396). [model] the rows are visited in a meander, as
// cycle 221 does (the manual gives no order).
bool gridOf(const CycleArgs &a, bool frame, std::vector<PlanePoint> &out, std::string &err) {
  int n1, n2;
  if (!required(a, {"X", "Y", "DX", "DY"}, err) || !countOf(a, "NUMX", n1, err) || !countOf(a, "NUMY", n2, err))
    return false;
  double rot = a.get("ROT");
  out = shearedGridPattern({a.get("X"), a.get("Y")}, rot + a.get("ROTX"), rot + a.get("ROTY"), a.get("DX"), a.get("DY"),
                           n1, n2, true, frame);
  return true;
}
bool patPattern(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) { return gridOf(a, false, out, err); }
bool framePattern(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) { return gridOf(a, true, out, err); }

bool circOf(const CycleArgs &a, bool full, std::vector<PlanePoint> &out, std::string &err) {
  int n;
  if (!required(a, {"X", "Y", "D"}, err) || !countOf(a, "NUM", n, err)) return false;
  if (!full && !a.has("STEP")) return fail(err, "STEP (the angle step) is required");
  if (!(a.get("D") > 0)) return fail(err, "D (the circle's diameter) must be greater than 0");
  out = circlePattern({a.get("X"), a.get("Y")}, a.get("D") / 2, a.get("START"), full ? 360.0 / n : a.get("STEP"), n);
  return true;
}
bool circPattern(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) { return circOf(a, true, out, err); }
bool pitchPattern(const CycleArgs &a, std::vector<PlanePoint> &out, std::string &err) { return circOf(a, false, out, err); }

// The surface of each position: POSn's Zn, one Z for the other forms (absent: 0).
std::vector<double> surfacesOf(const CycleDef &pattern, const CycleArgs &a, size_t n) {
  std::vector<double> z(n, a.get("Z"));
  if (pattern.positions == posPattern)
    for (size_t k = 0; k < n; ++k) z[k] = a.get(fmt::format("Z{}", k + 1));
  return z;
}

const CycleDef kEntries[] = {
    {"hei.PATTERN.POS",
     "X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3 X4 Y4 Z4 X5 Y5 Z5 X6 Y6 Z6 X7 Y7 Z7 X8 Y8 Z8 X9 Y9 Z9" HEI_WALK,
     "Heidenhain PATTERN DEF POS1-9 or point-table rows, with CYCL CALL PAT", nullptr, posPattern},
    {"hei.PATTERN.ROW", "X Y D NUM ROT Z" HEI_WALK, "Heidenhain PATTERN DEF ROW1", nullptr, rowPattern},
    {"hei.PATTERN.PAT", "X Y DX DY NUMX NUMY ROT ROTX ROTY Z" HEI_WALK, "Heidenhain PATTERN DEF PAT1", nullptr, patPattern},
    {"hei.PATTERN.FRAME", "X Y DX DY NUMX NUMY ROT ROTX ROTY Z" HEI_WALK, "Heidenhain PATTERN DEF FRAME1", nullptr,
     framePattern},
    {"hei.PATTERN.CIRC", "X Y D START NUM Z" HEI_WALK, "Heidenhain PATTERN DEF CIRC1", nullptr, circPattern},
    {"hei.PATTERN.PITCHCIRC", "X Y D START STEP NUM Z" HEI_WALK, "Heidenhain PATTERN DEF PITCHCIRC1", nullptr,
     pitchPattern},
};

}  // namespace

void addHeiPatternEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kEntries) out.push_back(d);
}

bool isCallPatPattern(const CycleDef &pattern) {
  return std::string_view(pattern.name).substr(0, 12) == "hei.PATTERN.";
}

bool walkCallPat(const CycleDef &pattern, const CycleArgs &pa, const CycleDef &hole, const CycleArgs &ha,
                 const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (std::string_view(hole.name).substr(0, 4) != "hei." || !hole.expand)
    return fail(err, "CYCL CALL PAT runs a Heidenhain machining cycle");
  // The points are hole centres or start points on the surface Q203 (L1645-L1660): the cycles
  // without a surface (face milling 232, 233) take them otherwise.
  if (cycleParamIndex(hole, "Q203") < 0)
    return fail(err, std::string(hole.name) + " at the points of CYCL CALL PAT is not simulated (it has no surface Q203)");
  std::vector<PlanePoint> pts;
  if (!pattern.positions(pa, pts, err)) return false;
  std::vector<double> surfaces = surfacesOf(pattern, pa, pts.size());
  const PlaneAxes ax = planeAxes((Plane)ctx.plane);
  const int d = ax.n;
  const bool fmax = pa.get("FMAX") != 0, always2nd = pa.get("Q345") != 0;
  const double callLevel = pa.has("H") ? pa.get("H") : ctx.position[d];
  CycleStep between;  // the moves between positions: the call's feed (0: the programmed one) or rapid
  between.kind = fmax ? CycleStepKind::Rapid : CycleStepKind::Feed;
  between.feed = fmax ? 0 : pa.get("F");
  std::array<double, 3> here = ctx.position;
  for (size_t i = 0; i < pts.size(); ++i) {
    CycleArgs h = ha;
    double q203 = ha.get("Q203"), zp = surfaces[i];
    // L1263-L1270: a pattern surface above the cycle's counts alone, else both add; the two
    // readings differ only when both are set and the pattern's is the higher.
    if (zp != 0 && q203 != 0 && zp > q203)
      return fail(err, fmt::format("position {}: a pattern surface Z{:g} above the cycle's Q203={:g} (the manual's two "
                                   "rules for the 2nd set-up clearance disagree): program one of them 0",
                                   i + 1, zp, q203));
    h.num["Q203"] = q203 + zp;
    double up = h.get("Q201") > 0 ? -1 : 1;  // the side the tool retracts to
    double z2 = h.get("Q203") + up * std::max(std::fabs(h.get("Q200")), std::fabs(h.get("Q204")));
    bool first = i == 0 && !pa.has("H");
    double safe = (first || !always2nd) && (callLevel - z2) * up > 0 ? callLevel : z2;
    if (here[d] != safe) {
      CycleStep s = between;
      s.pos = here, s.pos[d] = safe;
      out.push_back(s);
      here = s.pos;
    }
    CycleStep to = between;
    to.pos = here, to.pos[ax.u] = pts[i][0], to.pos[ax.v] = pts[i][1];
    out.push_back(to);
    CycleContext at = ctx;
    at.position = to.pos;
    size_t mark = out.size();
    if (!hole.expand(h, at, out, err)) return false;
    here = to.pos;
    for (size_t k = out.size(); k-- > mark;)
      if (out[k].kind == CycleStepKind::Rapid || out[k].kind == CycleStepKind::Feed || out[k].kind == CycleStepKind::Arc) {
        here = out[k].pos;
        break;
      }
  }
  return true;
}

}  // namespace ncc
