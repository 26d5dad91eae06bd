// Sinumerik contour tables (SIN-CON-01, -02, -04, -06; manual L27015-L27625; docs/SINUMERIK.md
// "Contour tables"). CONTPRON / CONTDCON open a contour capture (`contour action=begin
// use=sin_table`): the blocks up to EXECUTE are read, not run, and each move notes the modes it
// ran in. At `end` the captured path (exact lines and arcs: RND, CHF, CIP, CT included) becomes
// the table, in the program's coordinates of the active plane, which the program reads back as
// `$_sin_table[row, column]`; the modal state is put back as at CONTPRON. EXECTAB (`contour
// action=run use=sin_table`) moves along one element of a CONTPRON table.
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"
#include "ir/Value.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kSummaryColumn = 16;  // `$_sin_table[0, 16]` the undercuts, `[1, 16]` EXECUTE's error value
const char *const kModeNames = "GLNP";

// Column 8 (L27180-L27182): the largest angle an element's direction makes with the abscissa
// (longitudinal modes) or the ordinate (facing), directions taken modulo 180 degrees into
// [0, 180). Over an arc the direction turns from `from` by `turn` degrees; where it reaches a
// multiple of 180 from below, the largest value is 180 (the manual's rounding arc: 180).
double elementAngle(double from, double turn) {
  auto mod180 = [](double a) {
    double m = std::fmod(a, 180.0);
    if (m < 0) m += 180.0;
    return std::fabs(m - 180.0) < 1e-9 ? 0.0 : m;
  };
  if (turn == 0) return mod180(from);
  double lo = std::min(from, from + turn), hi = std::max(from, from + turn);
  double k = std::floor(hi / 180.0) * 180.0;  // the largest multiple of 180 not above hi
  if (k > lo + 1e-9) return 180.0;
  return std::max(mod180(from), mod180(from + turn));
}
double degrees(double y, double x) { return std::atan2(y, x) * 180.0 / kPi; }
}  // namespace

bool Executor::Impl::sinTableBegin(const MachineCmd &c) {
  const bool coded = c.has(Word::P) && c.get(Word::P) == 6;
  const char *kw = coded ? "CONTDCON" : "CONTPRON";
  if (comp.active()) return error(fmt::format("{} needs cutter compensation off (G40, L27041-L27046)", kw), "contour-invalid");
  if (machine.controller.diameterProgramming)
    return error(fmt::format("{} under diameter programming is not simulated", kw), "unsupported-code");
  const double dir = c.has(Word::W) ? c.get(Word::W) : 0;
  if (dir == 1)
    return coded ? error("CONTDCON: machining direction 1 is not allowed (L27355)", "contour-invalid")
                 : error("CONTPRON: machining direction 1 (the contour in both directions) is not simulated: the "
                         "manual does not define the backward table's links and split elements",
                         "unsupported-code");
  if (dir != 0) return error(fmt::format("{}: the machining direction must be 0 or 1", kw), "contour-invalid");
  sinTable.coded = coded;
  sinTable.mode = coded ? 0 : (int)c.get(Word::U);
  if (!coded && (sinTable.mode < 0 || sinTable.mode > 3))
    return error("CONTPRON: the machining mode must be \"G\", \"L\", \"N\" or \"P\"", "contour-invalid");
  sinTable.rows = (int)c.get(Word::R);
  sinTable.unitHint = c.has(Word::D) ? (int)c.get(Word::D) : -1;
  sinTable.modes.clear();
  sinTable.built = false;
  return true;
}

void Executor::Impl::sinTableNote() {
  sinTable.modes.push_back({loc, st.distance, st.units, st.feedMode, st.pathMode, st.css, stopOnce, pathTolerance, st.feed});
}

bool Executor::Impl::sinTableBuild(const Contour &ct) {
  auto &T = sinTable;
  const char *kw = T.coded ? "CONTDCON" : "CONTPRON";
  const PlaneAxes ax = planeAxes(plane());
  // Machine to program coordinates: the chain only shifts (begin refuses rotations, scaling,
  // mirror), and the state is back as at begin.
  auto prog = [&](int axis, double m) { return (m - offset(axis)) / axisScale(axis); };
  struct Elem {
    int motion;  // 0 … 3: G0 … G3
    double xs, ys, xe, ye, cx = 0, cy = 0;
    const SinTable::Modes *modes;
    // An arc's start angle about its centre and its sweep, degrees (> 0, in its own sense).
    void arcAngles(double &from, double &sweep) const {
      from = degrees(ys - cy, xs - cx);
      const double to = degrees(ye - cy, xe - cx);
      sweep = motion == 3 ? to - from : from - to;
      while (sweep <= 1e-9) sweep += 360;
    }
  };
  std::vector<Elem> el;
  double xs = prog(ax.u, ct.start.a), ys = prog(ax.v, ct.start.b);
  const double x0 = xs, y0 = ys;
  for (auto &e : ct.elems) {
    Elem m{e.kind == ContourKind::Rapid ? 0 : e.kind == ContourKind::Line ? 1 : e.ccw ? 3 : 2, xs, ys,
           prog(ax.u, e.end.a), prog(ax.v, e.end.b), 0, 0, nullptr};
    if (m.motion >= 2) m.cx = prog(ax.u, e.centre.a), m.cy = prog(ax.v, e.centre.b);
    else if (std::hypot(m.xe - xs, m.ye - ys) < 1e-9) continue;  // no element
    for (size_t i = T.modes.size(); i-- > 0;)
      if (T.modes[i].loc.file == e.loc.file && T.modes[i].loc.line == e.loc.line && T.modes[i].loc.col == e.loc.col) {
        m.modes = &T.modes[i];
        break;
      }
    if (!m.modes && !T.modes.empty()) m.modes = &T.modes.back();
    if (m.modes && m.modes->units != st.units)
      return error(fmt::format("{}: G70/G71 (G700/G710) must not change inside the contour preparation (L27309)", kw),
                   "contour-invalid");
    el.push_back(m);
    xs = m.xe, ys = m.ye;
  }
  const int n = (int)el.size();
  if (n == 0) return error(fmt::format("{}: no contour element between {} and EXECUTE", kw, kw), "contour-invalid");
  if (n + 1 > T.rows)
    return error(fmt::format("{}: the contour has {} elements, the table needs {} rows and has {}", kw, n, n + 1, T.rows),
                 "contour-invalid");
  const bool metric = st.units == ModeValue::MM;
  T.table.assign(n + 1, std::vector<double>(T.coded ? 6 : 11, 0.0));
  T.undercuts = 0;
  if (T.coded) {
    // L27452-L27474: row 0 the start (G0 and the unit code), rows 1 … n the elements.
    const int units = metric ? (T.unitHint == 3 ? 3 : 1) : (T.unitHint == 0 ? 0 : 2);
    T.table[0] = {10.0 * units, x0, y0, 0, 0, (double)n};
    for (int i = 0; i < n; ++i) {
      const Elem &e = el[i];
      const SinTable::Modes m = e.modes ? *e.modes : SinTable::Modes{{}, st.distance, st.units, st.feedMode, st.pathMode,
                                                                       st.css, false, pathTolerance, st.feed};
      int feedType = m.feedMode == ModeValue::InverseTime ? 0 : m.feedMode == ModeValue::PerMinute ? (m.css ? -1 : 1)
                                                                                                  : (m.css ? 3 : 2);
      if (feedType < 0) return error("CONTDCON: G961 has no code in the table (L27438)", "unsupported-code");
      int path = m.pathMode == ModeValue::ExactStop ? 0 : m.pathMode == ModeValue::Continuous && m.tolerance == 0 ? 1 : -1;
      if (path < 0)
        return error("CONTDCON: G641/G642 (smoothing) in the table: which of them ran is not kept (L27439)",
                     "unsupported-code");
      double code = e.motion + 10 * units + 100 * (m.distance == ModeValue::Incremental) + 1000 * feedType +
                    10000 * path + 100000 * m.g9;
      T.table[i + 1] = {code, e.xe, e.ye, e.motion >= 2 ? e.cx : 0, e.motion >= 2 ? e.cy : 0, m.feed};
    }
    T.built = true;
    return true;
  }
  // CONTPRON (L27166-L27190): rows 0 … n-1 the elements (row 0 the move from the start point),
  // row n the undercut counts. Undercuts (a contour whose ordinate, or abscissa when facing,
  // turns back) are refused: the control splits such elements and marks them in a form the
  // manual does not define.
  const bool facing = T.mode >= 2;
  auto coord = [&](double x, double y) { return facing ? x : y; };
  int trend = 0;
  for (int i = 1; i < n; ++i) {
    const Elem &e = el[i];
    double d = coord(e.xe, e.ye) - coord(e.xs, e.ys);
    bool turns = false;
    if (e.motion >= 2) {  // an arc whose coordinate has its extreme inside the sweep turns back
      double a0, sw;
      e.arcAngles(a0, sw);
      for (double ext = facing ? 0 : 90; ext < 360; ext += 180) {
        double from = e.motion == 3 ? ext - a0 : a0 - ext;
        from = std::fmod(std::fmod(from, 360.0) + 360.0, 360.0);
        if (from > 1e-9 && from < sw - 1e-9) turns = true;
      }
    }
    int s = std::fabs(d) < 1e-9 ? 0 : d > 0 ? 1 : -1;
    if (turns || (s && trend && s != trend))
      return error(fmt::format("CONTPRON: the contour has undercut elements for machining mode \"{}\" (its {} turns "
                               "back at element {}): their splitting and markers are not simulated",
                               kModeNames[T.mode], facing ? "abscissa" : "ordinate", i),
                   "unsupported-code");
    if (s) trend = s;
  }
  for (int i = 0; i < n; ++i) {
    const Elem &e = el[i];
    auto &row = T.table[i];
    if (i == 0) row[0] = row[1] = n - 1;  // the last element, the end of the table forward
    else row[0] = i - 1, row[1] = i + 1 < n ? i + 1 : 0;
    const int a = e.modes && e.modes->distance == ModeValue::Incremental;
    row[2] = 100 * a + 10 * metric + e.motion;
    row[3] = e.xs, row[4] = e.ys, row[5] = e.xe, row[6] = e.ye;
    // Column 7, the max/min marker: the manual's example 1 (no undercuts) marks the first element
    // after the start with -1111 and no other (docs/SINUMERIK.md).
    row[7] = i == 1 ? -1111 : 0;
    double from, turn = 0;
    if (e.motion >= 2) {
      double r0, sw;
      e.arcAngles(r0, sw);
      from = e.motion == 3 ? r0 + 90 : r0 - 90;  // the direction at the start
      turn = e.motion == 3 ? sw : -sw;
      row[9] = e.cx, row[10] = e.cy;
    } else {
      from = degrees(e.ye - e.ys, e.xe - e.xs);
    }
    row[8] = elementAngle(facing ? from - 90 : from, turn);
  }
  // Row n: undercuts forward and backward (none: refused above); its other columns 0.
  T.built = true;
  return true;
}

// EXECTAB(TAB[n]): the element's code (P), end point (U W) and centre (D E), as a block
// `G<c> <abscissa>=AC(..) <ordinate>=AC(..) [centre words =AC(..)]` in the active plane.
bool Executor::Impl::sinTableExec(const MachineCmd &c) {
  const double code = c.get(Word::P);
  const int a = (int)code / 100, b = (int)code / 10 % 10, motion = (int)code % 10;
  if (!(code >= 0 && code < 200 && code == std::floor(code)) || b > 1 || motion > 3)
    return error(fmt::format("EXECTAB: {} is no element code of a CONTPRON table (abc: G90/G91, G70/G71, G0-G3)",
                             numberText(code)),
                 "contour-invalid");
  if (a == 1) return error("EXECTAB: an element recorded under G91 is not simulated", "unsupported-code");
  if ((b == 1) != (st.units == ModeValue::MM))
    return error(fmt::format("EXECTAB: the element is coded {} but the program runs in {}", b ? "G71" : "G70",
                             st.units == ModeValue::MM ? "mm" : "inch"),
                 "contour-invalid");
  if (machine.controller.diameterProgramming) return error("EXECTAB under diameter programming is not simulated", "unsupported-code");
  static const ModeValue kMotion[] = {ModeValue::Rapid, ModeValue::Linear, ModeValue::ArcCW, ModeValue::ArcCCW};
  MachineCmd mode;
  mode.kind = CmdKind::Mode;
  mode.loc = loc;
  mode.modes[0] = kMotion[motion];
  mode.nmodes = 1;
  if (!execMode(mode)) return false;
  const PlaneAxes ax = planeAxes(plane());
  MachineCmd mv;
  mv.kind = CmdKind::Move;
  mv.loc = loc;
  mv.set((Word)ax.u, c.get(Word::U));
  mv.set((Word)ax.v, c.get(Word::W));
  unsigned abs = 1u << ax.u | 1u << ax.v;
  if (motion >= 2) {
    mv.set((Word)((int)Word::I + ax.u), c.get(Word::D));
    mv.set((Word)((int)Word::I + ax.v), c.get(Word::E));
    abs |= 1u << ((int)Word::I + ax.u) | 1u << ((int)Word::I + ax.v);
  }
  mv.sub2 = (uint16_t)abs;
  if (capture.table) sinTableNote();
  return execMove(mv);
}

bool Executor::Impl::sinTableRead(const SysRef &ref, double &out, std::string &err) const {
  out = 0;
  if (ref.edge == kSummaryColumn) {
    if (ref.tool == 0) out = sinTable.undercuts;  // [1, 16]: EXECUTE's error value, 0: none (a run stops at one)
    return true;
  }
  if (!sinTable.built) {
    err = "no contour table was built (CONTPRON or CONTDCON … EXECUTE)";
    return false;
  }
  if ((size_t)ref.tool < sinTable.table.size() && (size_t)ref.edge < sinTable.table[ref.tool].size())
    out = sinTable.table[ref.tool][ref.edge];
  return true;
}

}  // namespace ncc
