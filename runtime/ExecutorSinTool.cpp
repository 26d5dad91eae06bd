// Executor: Sinumerik tool offsets (SIN-TOL-02 … -09, manual L16743-L17412; docs/SINUMERIK.md
// "Tool offsets"). A D word selects edge D of the tool in the spindle; its three length
// components (geometry + base dimension + wear + the active DL set's wear and setup values) go to
// the geometry axes by tool type and plane (or SD42940), with the mirror and wear sign rules of
// SD42900-SD42930. The result is the executor's tool offset on X, Y and Z.
#include "runtime/ExecutorImpl.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

namespace ncc {

namespace {
// Turning and grinding tools: the types whose cutting edge position counts (L17184, L17380).
bool turningType(int type) { return type >= 400 && type <= 599; }

// The geometry axis (0 X, 1 Y, 2 Z) of lengths 1, 2, 3 for each SD42940 value (L17381-L17406);
// with SD42940 = 0 the plane's code (G17 = 17 …) picks the row, which is the "*)" default.
struct LengthRow {
  int code;
  int milling[3], turning[3];
};
constexpr LengthRow kLengthRows[] = {
    {17, {2, 1, 0}, {1, 0, 2}},  {18, {1, 0, 2}, {0, 2, 1}},  {19, {0, 2, 1}, {2, 1, 0}},
    {-17, {2, 0, 1}, {0, 1, 2}}, {-18, {1, 2, 0}, {2, 0, 1}}, {-19, {0, 1, 2}, {1, 2, 0}},
};

const int *lengthAxes(int code, bool turning) {
  // Any other non-zero value counts as 18 for turning tools and 17 for the others.
  const LengthRow *row = &kLengthRows[turning ? 1 : 0];
  for (auto &r : kLengthRows)
    if (r.code == code) row = &r;
  return turning ? row->turning : row->milling;
}

// SD42920: the wear components whose sign the cutting edge position inverts (L17187-L17196), bit
// 0 length 1, bit 1 length 2, by position 1..9.
constexpr int kCutPosWearSign[10] = {0, 0, 2, 3, 1, 0, 0, 2, 1, 0};
}  // namespace

// Which geometry axes the frames mirror: the settable frame's rotation and the programmable frame
// together. A linear part that is not diagonal (a rotation) leaves the mirrored axes undefined.
bool Executor::Impl::mirroredAxes(bool out[3]) const {
  double R[3][3];
  frameRotation(0, 0, chainRot, R);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double m = 0;
      for (int k = 0; k < 3; ++k) m += R[i][k] * pf.composite.m[k][j];
      if (i != j && std::fabs(m) > 1e-12) return false;
      if (i == j) out[i] = m < 0;
    }
  }
  return true;
}

bool Executor::Impl::sinToolOffsets(int t, int d, int dl, Vec3 &length, double &radius, std::string &err) const {
  const Controller &ctl = machine.controller;
  const ToolEdge e = edgeOf(t, d);
  if (e.xOffset != 0 || e.xWear != 0) {
    err = fmt::format("tool {} edge D{}: x_offset/x_wear are the ISO lathe offsets; a Sinumerik edge gives its "
                      "lengths as length/length2/length3 by its type",
                      t, d);
    return false;
  }
  const double *sumWear = dl > 0 ? e.sumWear[dl - 1] : nullptr, *sumSetup = dl > 0 ? e.sumSetup[dl - 1] : nullptr;
  auto additive = [&](int p) { return dl > 0 ? sumWear[p] + sumSetup[p] : 0.0; };
  const double wearSign = ctl.wearSign ? -1 : 1;
  const double geometry[3] = {e.length + e.base1, e.length2 + e.base2, e.length3 + e.base3};
  const double wear[3] = {e.lengthWear + additive(0), e.length2Wear + additive(1), e.length3Wear + additive(2)};
  const bool turning = turningType(e.type);
  static constexpr int kPlaneCode[] = {17, 18, 19};  // Plane XY ZX YZ
  const int *axes = lengthAxes(ctl.toolLengthConst ? ctl.toolLengthConst : kPlaneCode[(int)plane()], turning);
  bool mirrored[3] = {};
  if ((ctl.mirrorToolLength || ctl.mirrorToolWear) && !mirroredAxes(mirrored)) {
    err = "the tool length mirroring of SD42900/SD42910 under a rotated frame is not simulated (which axes are "
          "mirrored is not known)";
    return false;
  }
  const int cutPosBits = ctl.wearSignCutpos && turning && e.tip >= 1 && e.tip <= 9 ? kCutPosWearSign[e.tip] : 0;
  // TOWWCS: the wear is given in the WCS. With frames that only shift it is the MCS's (the
  // shifts do not count for a length, L17316-L17320); a turned, mirrored or scaled WCS would need
  // the conversion, which ncc does not make.
  if (st.wearSystem == ModeValue::WearWork && (wear[0] != 0 || wear[1] != 0 || wear[2] != 0)) {
    double R[3][3];
    frameRotation(0, 0, chainRot, R);
    bool plain = pf.composite.linearIdentity();
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) plain = plain && std::fabs(R[i][k] - (i == k)) < 1e-12;
    if (!plain) {
      err = "TOWWCS (wear in the workpiece system) under a frame that rotates, mirrors or scales is not simulated";
      return false;
    }
  }
  length = {};
  for (int j = 0; j < 3; ++j) {
    const int a = axes[j];
    double g = geometry[j], w = wear[j] * wearSign;
    if (cutPosBits & (1 << j)) w = -w;
    if (mirrored[a] && ctl.mirrorToolLength) g = -g;
    if (mirrored[a] && ctl.mirrorToolWear) w = -w;
    length[a] += g + w;
  }
  radius = e.radius + (e.radiusWear + additive(3)) * wearSign;
  if (radius < 0) {
    err = fmt::format("tool {} edge D{}: the resulting radius {} is negative", t, d, radius);
    return false;
  }
  return true;
}

bool Executor::Impl::applySinTool() {
  Vec3 length;
  double radius;
  std::string err;
  if (!sinToolOffsets(st.toolInSpindle, activeEdge, activeDl, length, radius, err)) return error(err, "unsupported-code");
  toolOffsetX = length[0], toolOffsetY = length[1], toolLength = length[2];
  st.toolLengthH = st.toolInSpindle;
  MotionRecord r = record(RecordKind::ToolLength);
  r.value = toolLength;
  r.value2 = toolOffsetX;
  if (toolOffsetY != 0) r.setParam("Y", toolOffsetY);
  r.ivalue = st.toolLengthH;
  emit(r);
  return true;
}

namespace {
bool dlSet(double dl) { return dl >= 0 && dl <= kDlSets && dl == std::floor(dl); }
}  // namespace

bool Executor::Impl::selectSinEdge(int d, double dl) {
  const int t = st.toolInSpindle;
  if (t == 0) return error(fmt::format("D{} needs a tool in the spindle (T… M6)", d), "unknown-tool");
  if (!hasEdge(t, d)) return error(fmt::format("tool {} has no cutting edge D{}", t, d), "unknown-tool");
  if (!dlSet(dl)) return error(fmt::format("DL={} is not a DL set (1..{}, 0 none)", dl, kDlSets), "bad-number");
  activeEdge = d;
  activeDl = (int)dl;
  if (!applySinTool()) return false;
  // A lathe's G41/G42 given before an edge with a nose radius starts at this selection.
  double radius;
  if (isoLathe() && st.cutterComp != 0 && !comp.active() && sinRadius(t, d, radius) && radius > 0) return noseCompAfterT();
  return true;
}

bool Executor::Impl::selectSinDl(double dl) {
  if (!dlSet(dl)) return error(fmt::format("DL={} is not a DL set (1..{}, 0 none)", dl, kDlSets), "bad-number");
  if (activeEdge == 0) return error("DL (an additive offset) needs an active cutting edge (D1 …)", "unknown-tool");
  activeDl = (int)dl;
  return applySinTool();
}

// SD42940 = 0: the length components follow the plane (L17369-L17375), so a plane change
// assigns them anew for the next move.
bool Executor::Impl::sinPlaneChanged() {
  if (activeEdge == 0 || machine.controller.toolLengthConst != 0) return true;
  return applySinTool();
}

bool Executor::Impl::sinRadius(int t, int d, double &radius) {
  Vec3 length;
  std::string err;
  return sinToolOffsets(t, d, activeDl, length, radius, err) || error(err, "unsupported-code");
}

// DELDL (SIN-TOL-06, L17030-L17066): the wear and setup values of every DL set of the edges named
// (`DELDL[t, d]` one edge, `DELDL[t]` the tool's, `DELDL` every tool's) go. The active tool's stay
// (L17064: "values of active tools cannot be deleted"; [model] active: the tool in the spindle with
// an edge selected, whose offsets are in effect). The status is 0 when everything named was
// deleted, -1 when an edge named does not exist or an active one kept its values (the manual's
// "–"). The active tool's values stay silently in the statement form too, as the manual says.
bool Executor::Impl::deleteAdditive(const MachineCmd &c) {
  const bool oneTool = c.has(Word::P), oneEdge = c.has(Word::D);
  const int t = oneTool ? (int)c.get(Word::P) : 0, d = oneEdge ? (int)c.get(Word::D) : 0;
  std::set<std::pair<int, int>> edges;
  bool missing = false;
  auto toolEdges = [&](int tool) {
    auto it = machine.toolTable.find(tool);
    if (it != machine.toolTable.end())
      for (auto &e : it->second.edges) edges.insert({tool, e.first});
    else if (toolExists(tool))
      edges.insert({tool, 1});  // a valid number the table lacks: edge 1 alone
    for (auto &e : edgeEdits)
      if (e.first.first == tool) edges.insert(e.first);
  };
  if (!oneTool) {
    for (auto &tool : machine.toolTable) toolEdges(tool.first);
    for (auto &e : edgeEdits) edges.insert(e.first);
  } else if (oneEdge) {
    const bool whole = c.get(Word::P) == t && c.get(Word::D) == d;
    if (whole && hasEdge(t, d)) edges.insert({t, d});
    else missing = true;
  } else {
    if (c.get(Word::P) == t) toolEdges(t);
    missing = edges.empty();
  }
  bool kept = false;
  for (auto [tool, edge] : edges) {
    if (tool == st.toolInSpindle && activeEdge != 0) {
      kept = true;
      continue;
    }
    ToolEdge e = edgeOf(tool, edge);
    for (auto *sets : {&e.sumWear, &e.sumSetup})
      for (auto &set : *sets)
        for (double &v : set) v = 0;
    edgeEdits[{tool, edge}] = e;
  }
  deldlStatus = missing || kept ? -1 : 0;
  // The statement form names a tool or edge that does not exist: an error, as for D (the status
  // form leaves it to the program).
  if (missing && c.get(Word::Q) != 1)
    return error(oneEdge ? fmt::format("DELDL[{}, {}]: tool {} has no cutting edge D{}", t, d, t, d)
                         : fmt::format("DELDL[{}]: the machine has no tool {}", t, t),
                 "unknown-tool");
  return true;
}

}  // namespace ncc
