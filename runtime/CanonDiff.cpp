#include "runtime/CanonDiff.h"
#include "ir/MotionIR.h"

#include <algorithm>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace ncc {

namespace {

// One line of a trace split into its parts (views into the trace text).
struct CanonLine {
  size_t lineNo = 0;
  std::string_view text;  // the whole line
  std::string_view name;  // empty when the line is not `... NAME(args)`
  std::string_view args;  // between the parentheses
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Splits `%5d N..... NAME(args)`; tolerates a missing sequence or N column.
void splitLine(CanonLine &l) {
  std::string_view s = l.text;
  size_t i = 0, n = s.size();
  while (i < n && isSpace(s[i])) ++i;
  size_t seq = i;
  while (i < n && isDigit(s[i])) ++i;
  if (i > seq) {
    if (i >= n || s[i] != ' ') {  // not a sequence number after all
      i = seq;
    } else {
      while (i < n && isSpace(s[i])) ++i;
    }
  }
  if (i + 1 < n && s[i] == 'N' && (isDigit(s[i + 1]) || s[i + 1] == '.')) {
    ++i;
    while (i < n && (isDigit(s[i]) || s[i] == '.')) ++i;
    while (i < n && isSpace(s[i])) ++i;
  }
  size_t nameStart = i;
  while (i < n && s[i] != '(') {
    char c = s[i];
    if (!((c >= 'A' && c <= 'Z') || isDigit(c) || c == '_' || c == '.')) return;
    ++i;
  }
  if (i >= n || i == nameStart) return;
  size_t close = s.rfind(')');
  if (close == std::string_view::npos || close < i) return;
  l.name = s.substr(nameStart, i - nameStart);
  l.args = s.substr(i + 1, close - i - 1);
}

// Iterates the lines of a trace.
class LineReader {
public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(CanonLine &l) {
    if (pos_ >= text_.size()) return false;
    size_t e = text_.find('\n', pos_);
    if (e == std::string_view::npos) e = text_.size();
    l = CanonLine();
    l.lineNo = ++line_;
    l.text = text_.substr(pos_, e - pos_);
    if (!l.text.empty() && l.text.back() == '\r') l.text.remove_suffix(1);
    pos_ = e + 1;
    splitLine(l);
    return true;
  }

private:
  std::string_view text_;
  size_t pos_ = 0, line_ = 0;
};

// Splits arguments at commas and blanks (USE_TOOL_LENGTH_OFFSET and SET_SPINDLE_MODE use both).
template <size_t N> int numbers(std::string_view args, std::array<double, N> &out, bool &ok) {
  int count = 0;
  ok = true;
  size_t i = 0, n = args.size();
  while (i < n) {
    while (i < n && (isSpace(args[i]) || args[i] == ',')) ++i;
    if (i >= n) break;
    size_t s = i;
    while (i < n && !isSpace(args[i]) && args[i] != ',') ++i;
    double v = 0;
    const char *b = args.data() + s, *e = args.data() + i;
    if (*b == '+') ++b;
    auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e) ok = false;
    if (count < (int)N) out[count] = v;
    ++count;
  }
  return count;
}

enum class MotionKind { Traverse, Feed, Arc, Probe, RigidTap, Dwell, Nurbs };

struct Motion {
  MotionKind kind;
  CanonLine line;
  AxisVec pos{};  // machine mm / degrees (Dwell: pos[0] = seconds, Nurbs: the count)
  std::array<double, 2> center{};
  int plane = 0, rot = 0;
  double unitScale = 1;
};

// Replays a trace's state commands and yields its motion in the machine frame.
class MachineReader {
public:
  explicit MachineReader(std::string_view text) : lines_(text) {}
  // Returns false at the end; sets err (and returns false) on a malformed motion line.
  bool next(Motion &m, std::string &err);
  size_t lastLine() const { return last_; }

private:
  // Offsets are kept in mm as of the units in force when they were set: rs274 does not reprint
  // them after USE_LENGTH_UNITS.
  // n values: X Y Z A B C, with U V W when the trace has them (rs274 built with them).
  void setOffset(AxisVec &dst, const double *v, int n) {
    dst = {};
    for (int i = 0; i < std::min(n, kAxes); ++i) dst[i] = isLengthAxis(i) ? v[i] * scale_ : v[i];
  }
  void toMachine(const AxisVec &p, AxisVec &out) const {
    AxisVec q;
    for (int i = 0; i < kAxes; ++i) q[i] = (isLengthAxis(i) ? p[i] * scale_ : p[i]) + g92_[i];
    if (rot_ != 0) {
      double r = rot_ * M_PI / 180, c = std::cos(r), s = std::sin(r);
      double x = q[0] * c - q[1] * s, y = q[0] * s + q[1] * c;
      q[0] = x, q[1] = y;
    }
    for (int i = 0; i < kAxes; ++i) out[i] = q[i] + g5x_[i] + tool_[i];
  }
  LineReader lines_;
  size_t last_ = 0;
  AxisVec pos_{};  // machine position after the last straight move
  double scale_ = 1, rot_ = 0;
  AxisVec g5x_{}, g92_{}, tool_{};
  int plane_ = 0;
};

constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};

bool MachineReader::next(Motion &m, std::string &err) {
  CanonLine l;
  while (lines_.next(l)) {
    last_ = l.lineNo;
    if (l.name.empty()) continue;
    std::string_view nm = l.name;
    std::array<double, 16> v{};
    int count = 0;
    bool ok = true;
    auto bad = [&] {
      err = "line " + std::to_string(l.lineNo) + ": cannot read the arguments of " + std::string(nm);
      return false;
    };
    bool state = true;
    if (nm == "USE_LENGTH_UNITS") {
      scale_ = l.args.find("INCH") != std::string_view::npos ? 25.4
               : l.args.find("CM") != std::string_view::npos ? 10.0 : 1.0;
    } else if (nm == "SET_G5X_OFFSET") {
      if ((count = numbers(l.args, v, ok)) < 7 || !ok) return bad();
      setOffset(g5x_, &v[1], count - 1);
    } else if (nm == "SET_G92_OFFSET") {
      if ((count = numbers(l.args, v, ok)) < 6 || !ok) return bad();
      setOffset(g92_, &v[0], count);
    } else if (nm == "SET_XY_ROTATION") {
      if (numbers(l.args, v, ok) < 1 || !ok) return bad();
      rot_ = v[0];
    } else if (nm == "USE_TOOL_LENGTH_OFFSET") {
      if ((count = numbers(l.args, v, ok)) < 6 || !ok) return bad();
      setOffset(tool_, &v[0], count);
    } else if (nm == "SELECT_PLANE") {
      plane_ = l.args.find("XZ") != std::string_view::npos ? 1 : l.args.find("YZ") != std::string_view::npos ? 2 : 0;
    } else {
      state = false;
    }
    if (state) continue;
    if (nm == "STRAIGHT_TRAVERSE" || nm == "STRAIGHT_FEED" || nm == "STRAIGHT_PROBE") {
      if ((count = numbers(l.args, v, ok)) < 6 || !ok) return bad();
      m = Motion();
      m.kind = nm == "STRAIGHT_TRAVERSE" ? MotionKind::Traverse
               : nm == "STRAIGHT_FEED"   ? MotionKind::Feed : MotionKind::Probe;
      AxisVec p{};
      for (int i = 0; i < std::min(count, kAxes); ++i) p[i] = v[i];
      toMachine(p, m.pos);
    } else if (nm == "RIGID_TAP") {
      if (numbers(l.args, v, ok) < 3 || !ok) return bad();
      m = Motion();
      m.kind = MotionKind::RigidTap;
      AxisVec p{v[0], v[1], v[2]};
      toMachine(p, m.pos);
    } else if (nm == "ARC_FEED") {
      if ((count = numbers(l.args, v, ok)) < 9 || !ok) return bad();
      m = Motion();
      m.kind = MotionKind::Arc;
      const int *ax = kPlaneAxes[plane_];
      AxisVec p{};
      p[ax[0]] = v[0], p[ax[1]] = v[1], p[ax[2]] = v[5];
      for (int i = 3; i < std::min(count - 3, kAxes); ++i) p[i] = v[i + 3];  // A B C (U V W)
      toMachine(p, m.pos);
      AxisVec c = p, cm;
      c[ax[0]] = v[2], c[ax[1]] = v[3];
      toMachine(c, cm);
      m.center = {cm[ax[0]], cm[ax[1]]};
      m.rot = (int)std::lround(v[4]);
      m.plane = plane_;
    } else if (nm == "NURBS_FEED") {
      // rs274 prints only the number of control points; the curve's end shows in the next
      // motion's position.
      size_t comma = l.args.find(',');
      std::array<double, 1> c{};
      if (comma == std::string_view::npos || numbers(l.args.substr(0, comma), c, ok) != 1 || !ok) return bad();
      m = Motion();
      m.kind = MotionKind::Nurbs;
      m.pos[0] = c[0];
    } else if (nm == "DWELL") {
      if (numbers(l.args, v, ok) < 1 || !ok) return bad();
      m = Motion();
      m.kind = MotionKind::Dwell;
      m.pos[0] = v[0];
    } else {
      continue;
    }
    if (m.kind == MotionKind::Nurbs) {
      pos_.fill(NAN);  // unknown end: the next straight move is motion whatever its target
    } else if (m.kind != MotionKind::Dwell) {
      // A straight move to where the machine already is moves nothing (rs274 prints one for a
      // bare `G0` after a tool change): not motion at machine level.
      // Positions computed through a rotation differ in the last bits: "where it is" within 1e-9.
      bool still = m.kind == MotionKind::Traverse || m.kind == MotionKind::Feed;
      for (int i = 0; i < kAxes && still; ++i) still = std::fabs(m.pos[i] - pos_[i]) <= 1e-9;
      pos_ = m.pos;
      if (still) continue;
    }
    m.line = l;
    m.unitScale = scale_;
    return true;
  }
  return false;
}

const char *kMotionNames[] = {"STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED", "STRAIGHT_PROBE", "RIGID_TAP", "DWELL",
                              "NURBS_FEED"};
const char *kPlaneNames[] = {"XY", "XZ", "YZ"};

std::string fmt(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.6f", v);
  return b;
}

std::string where(const char *side, const CanonLine &l) {
  return std::string("  ") + side + ":" + std::to_string(l.lineNo) + ": " + std::string(l.text) + "\n";
}

// Compares two motions; returns an empty string when they match.
std::string compareMotion(const Motion &a, const Motion &b, double tol) {
  if (a.kind != b.kind)
    return std::string("command differs: ") + kMotionNames[(int)a.kind] + " vs " + kMotionNames[(int)b.kind];
  double t = tol * std::max(a.unitScale, b.unitScale) + 1e-9;
  if (a.kind == MotionKind::Nurbs) {
    if (a.pos[0] != b.pos[0])
      return "NURBS control point count differs: " + std::to_string((long)a.pos[0]) + " vs " + std::to_string((long)b.pos[0]);
    return {};
  }
  if (a.kind == MotionKind::Dwell) {
    if (std::fabs(a.pos[0] - b.pos[0]) > tol + 1e-9)
      return "dwell differs: " + fmt(a.pos[0]) + " vs " + fmt(b.pos[0]) + " s";
    return {};
  }
  for (int i = 0; i < kAxes; ++i) {
    double ti = isLengthAxis(i) ? t : tol + 1e-9;
    if (std::fabs(a.pos[i] - b.pos[i]) > ti)
      return std::string(1, kAxisLetters[i]) + " differs: " + fmt(a.pos[i]) + " vs " + fmt(b.pos[i]) +
             (isLengthAxis(i) ? " mm" : " deg");
  }
  if (a.kind == MotionKind::Arc) {
    if (a.plane != b.plane)
      return std::string("arc plane differs: ") + kPlaneNames[a.plane] + " vs " + kPlaneNames[b.plane];
    if (a.rot != b.rot) return "arc turns differ: " + std::to_string(a.rot) + " vs " + std::to_string(b.rot);
    for (int i = 0; i < 2; ++i)
      if (std::fabs(a.center[i] - b.center[i]) > t)
        return "arc centre " + std::string(1, kAxisLetters[kPlaneAxes[a.plane][i]]) + " differs: " +
               fmt(a.center[i]) + " vs " + fmt(b.center[i]) + " mm";
  }
  return {};
}

bool machineDiff(std::string_view a, std::string_view b, const CanonDiffOptions &o, std::string &report) {
  MachineReader ra(a), rb(b);
  Motion ma, mb;
  std::string err;
  size_t count = 0;
  for (;;) {
    bool ha = ra.next(ma, err);
    if (!err.empty()) {
      report = "A: " + err + "\n";
      return false;
    }
    bool hb = rb.next(mb, err);
    if (!err.empty()) {
      report = "B: " + err + "\n";
      return false;
    }
    if (!ha && !hb) break;
    ++count;
    if (ha != hb) {
      const char *longer = ha ? "A" : "B";
      const char *shorter = ha ? "B" : "A";
      report = "machine level: " + std::string(shorter) + " ends after " + std::to_string(count - 1) +
               " motion commands (line " + std::to_string(ha ? rb.lastLine() : ra.lastLine()) + "), " + longer +
               " continues:\n" + where(longer, ha ? ma.line : mb.line);
      return false;
    }
    std::string why = compareMotion(ma, mb, o.tolerance);
    if (!why.empty()) {
      report = "machine level: motion #" + std::to_string(count) + " differs: " + why + "\n" +
               where("A", ma.line) + where("B", mb.line);
      return false;
    }
  }
  report = "machine level: traces match (" + std::to_string(count) + " motion commands)\n";
  return true;
}

// Program level: the lines that count (interpreter comments and blank lines dropped).
bool nextProgramLine(LineReader &r, const CanonDiffOptions &o, CanonLine &l) {
  while (r.next(l)) {
    if (l.name.empty()) {
      bool blank = true;
      for (char c : l.text) blank &= isSpace(c);
      if (!blank) return true;
      continue;
    }
    if ((l.name == "COMMENT") && l.args.substr(0, 13) == "\"interpreter:") continue;
    if (o.ignoreComments && (l.name == "COMMENT" || l.name == "MESSAGE")) continue;
    return true;
  }
  return false;
}

// Compares argument lists token by token; numbers with the tolerance.
bool sameArgs(std::string_view a, std::string_view b, double tol) {
  size_t i = 0, j = 0;
  auto token = [](std::string_view s, size_t &k) {
    while (k < s.size() && (isSpace(s[k]) || s[k] == ',')) ++k;
    size_t st = k;
    while (k < s.size() && !isSpace(s[k]) && s[k] != ',') ++k;
    return s.substr(st, k - st);
  };
  for (;;) {
    std::string_view ta = token(a, i), tb = token(b, j);
    if (ta.empty() || tb.empty()) return ta.empty() && tb.empty();
    if (ta == tb) continue;
    double va, vb;
    auto pa = std::from_chars(ta.data() + (ta[0] == '+'), ta.data() + ta.size(), va);
    auto pb = std::from_chars(tb.data() + (tb[0] == '+'), tb.data() + tb.size(), vb);
    if (pa.ec != std::errc() || pb.ec != std::errc() || pa.ptr != ta.data() + ta.size() ||
        pb.ptr != tb.data() + tb.size())
      return false;
    if (std::fabs(va - vb) > tol + 1e-9) return false;
  }
}

bool programDiff(std::string_view a, std::string_view b, const CanonDiffOptions &o, std::string &report) {
  LineReader ra(a), rb(b);
  CanonLine la, lb;
  size_t count = 0;
  for (;;) {
    bool ha = nextProgramLine(ra, o, la), hb = nextProgramLine(rb, o, lb);
    if (!ha && !hb) break;
    ++count;
    if (ha != hb) {
      report = "program level: " + std::string(ha ? "B" : "A") + " ends, " + (ha ? "A" : "B") +
               " continues:\n" + where(ha ? "A" : "B", ha ? la : lb);
      return false;
    }
    bool same = la.name.empty() || lb.name.empty() ? la.text == lb.text
                                                   : la.name == lb.name && sameArgs(la.args, lb.args, o.tolerance);
    if (!same) {
      report = "program level: line #" + std::to_string(count) + " differs:\n" + where("A", la) + where("B", lb);
      return false;
    }
  }
  report = "program level: traces match (" + std::to_string(count) + " lines)\n";
  return true;
}

}  // namespace

bool canonDiff(std::string_view a, std::string_view b, const CanonDiffOptions &opts, std::string &report) {
  return opts.level == CanonDiffOptions::Level::Machine ? machineDiff(a, b, opts, report)
                                                        : programDiff(a, b, opts, report);
}

}  // namespace ncc
