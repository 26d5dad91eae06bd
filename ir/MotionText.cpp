// Parser of the Motion IR text form (docs/IR.md "Motion IR text"): reads exactly what
// appendMotionRecord (ir/MotionIR.cpp) writes, plus blank lines and `#` comment lines.
#include "ir/MotionIR.h"
#include "ir/TextQuote.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace ncc {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }
bool isWordChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// One line of text. Every method reports its own error and returns false.
class LineParser {
public:
  LineParser(std::string_view line, uint32_t file, uint32_t lineNo, Diagnostics &diags)
      : s_(line), file_(file), line_(lineNo), diags_(diags) {}

  bool error(size_t at, std::string msg) {
    diags_.error(SourceLoc{file_, line_, (uint32_t)at + 1}, std::move(msg));
    return false;
  }
  void skipBlanks() {
    while (p_ < s_.size() && isBlank(s_[p_])) ++p_;
  }
  bool atEnd() {
    skipBlanks();
    return p_ >= s_.size();
  }
  size_t pos() const { return p_; }
  // The text of the current token (up to a blank, ',' or ')'), for messages.
  std::string_view token(size_t from) const {
    size_t e = from;
    while (e < s_.size() && !isBlank(s_[e]) && s_[e] != ',' && s_[e] != ')') ++e;
    return s_.substr(from, e - from);
  }
  std::string_view word() {
    size_t b = p_;
    while (p_ < s_.size() && isWordChar(s_[p_])) ++p_;
    return s_.substr(b, p_ - b);
  }
  std::string_view letters() {
    size_t b = p_;
    while (p_ < s_.size() && ((s_[p_] >= 'a' && s_[p_] <= 'z') || (s_[p_] >= 'A' && s_[p_] <= 'Z'))) ++p_;
    return s_.substr(b, p_ - b);
  }
  bool peek(std::string_view lit) const { return s_.substr(p_, lit.size()) == lit; }
  // Expects ` lit` (blanks before it).
  bool expect(std::string_view lit, const char *what) {
    skipBlanks();
    if (!peek(lit)) {
      std::string_view t = token(p_);
      return error(p_, t.empty() ? fmt::format("expected {}, found the end of the line", what)
                                 : fmt::format("expected {}, found '{}'", what, t));
    }
    p_ += lit.size();
    return true;
  }
  // A number in shortest round-trip form (also inf, -inf, nan), ending at a blank, ',' or ')'.
  bool number(double &v) {
    size_t b = p_;
    std::string_view t = token(p_);
    if (t.empty()) return error(b, p_ >= s_.size() ? "expected a number, found the end of the line"
                                                   : fmt::format("expected a number, found '{}'", s_[p_]));
    auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (res.ec == std::errc::result_out_of_range) return error(b, fmt::format("number '{}' is out of range", t));
    if (res.ec != std::errc() || res.ptr != t.data() + t.size()) return error(b, fmt::format("invalid number '{}'", t));
    p_ += t.size();
    return true;
  }
  bool integer(int64_t &v) {
    size_t b = p_;
    std::string_view t = token(p_);
    auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || res.ec != std::errc() || res.ptr != t.data() + t.size())
      return error(b, t.empty() ? std::string("expected an integer") : fmt::format("invalid integer '{}'", t));
    p_ += t.size();
    return true;
  }
  // `(a, b, c)`
  bool triple(std::array<double, 3> &v) {
    if (!expect("(", "'('")) return false;
    for (int i = 0; i < 3; ++i) {
      skipBlanks();
      if (!number(v[i])) return false;
      if (i < 2 && !expect(",", "','")) return false;
    }
    return expect(")", "')'");
  }
  // `(a, b, ...)` numbers, or `(t, t, ...)` triples when `triples`; may be empty: `()`.
  template <class T> bool list(std::vector<T> &out, bool (LineParser::*item)(T &)) {
    if (!expect("(", "'('")) return false;
    skipBlanks();
    if (peek(")")) return ++p_, true;
    while (true) {
      skipBlanks();
      out.emplace_back();
      if (!(this->*item)(out.back())) return false;
      skipBlanks();
      if (peek(")")) return ++p_, true;
      if (!expect(",", "',' or ')'")) return false;
    }
  }
  // X Y Z A B C, then U V W when written (all three; absent: 0, see writtenAxes).
  bool axes(AxisVec &v) {
    for (int i = 0; i < kAxes; ++i) {
      if (i == kBaseAxes) {
        skipBlanks();
        if (!peek("U")) {
          for (; i < kAxes; ++i) v[i] = 0;
          return true;
        }
      }
      char name[2] = {kAxisLetters[i], 0};
      if (!expect(name, fmt::format("'{}' and a number", kAxisLetters[i]).c_str()) || !number(v[i])) return false;
    }
    return true;
  }
  bool string(std::string &out) {
    skipBlanks();
    size_t b = p_;
    if (!peek("\"")) return error(p_, "expected a string in double quotes");
    ++p_;
    out.clear();
    while (true) {
      if (p_ >= s_.size()) return error(b, "unterminated string");
      char c = s_[p_++];
      if (c == '"') return true;
      if (c != '\\') {
        out += c;
        continue;
      }
      size_t esc = p_ - 1;
      const char *msg = nullptr;
      if (!text::decodeEscape(s_, p_, out, msg))
        return p_ >= s_.size() ? error(b, "unterminated string") : error(esc, msg);
    }
  }
  // ` key=value` pairs until the tail (exact_stop, N, @) or the end of the line.
  bool namedNumbers(MotionRecord &r) {
    while (true) {
      skipBlanks();
      size_t b = p_;
      if (p_ >= s_.size() || s_[p_] == '@') return true;
      std::string_view k = word();
      if (!peek("=")) {
        p_ = b;
        return true;  // not a pair: the tail
      }
      if (!isNamedNumberKey(k))
        return error(b, fmt::format("invalid key '{}' (1 to {} letters, digits or '_', not starting with a digit)", k,
                                    NamedNumber::kMaxKey));
      if (r.param(k)) return error(b, fmt::format("duplicate key '{}'", k));
      ++p_;
      double v;
      if (!number(v)) return false;
      r.setParam(k, v);
    }
  }
  // `[exact_stop] [N<int>] [@line:col]` then the end of the line.
  bool tail(MotionRecord &r) {
    skipBlanks();
    if (peek("exact_stop") && (p_ + 10 == s_.size() || isBlank(s_[p_ + 10]))) {
      r.exactStop = true;
      p_ += 10;
      skipBlanks();
    }
    if (peek("N")) {
      ++p_;
      if (!integer(r.blockNumber)) return false;
      if (r.blockNumber < 0) return error(p_, "a block number is not negative");
      skipBlanks();
    }
    if (peek("@")) {
      size_t b = p_++;
      int64_t l, c;
      std::string_view t = token(p_);  // after the '@'
      size_t colon = t.find(':');
      if (colon == std::string_view::npos) return error(b, fmt::format("expected '@line:column', found '@{}'", t));
      auto r1 = std::from_chars(t.data(), t.data() + colon, l);
      auto r2 = std::from_chars(t.data() + colon + 1, t.data() + t.size(), c);
      if (r1.ec != std::errc() || r1.ptr != t.data() + colon || r2.ec != std::errc() ||
          r2.ptr != t.data() + t.size() || l <= 0 || c < 0 || l > UINT32_MAX || c > UINT32_MAX)
        return error(b, fmt::format("expected '@line:column', found '@{}'", t));
      r.loc = SourceLoc{0, (uint32_t)l, (uint32_t)c};
      p_ += t.size();
    }
    if (!atEnd()) return error(p_, fmt::format("unexpected '{}' after the record", token(p_)));
    return true;
  }

private:
  std::string_view s_;
  size_t p_ = 0;
  uint32_t file_, line_;
  Diagnostics &diags_;
};

bool kindFromName(std::string_view name, RecordKind &out) {
  for (unsigned k = 0; k < (unsigned)RecordKind::Count; ++k)
    if (name == recordKindName((RecordKind)k)) {
      out = (RecordKind)k;
      return true;
    }
  return false;
}

// The machine state the text implies: where the last move ended, the selected plane.
struct TextState {
  AxisVec pos{};
  Plane plane = Plane::XY;
};

bool parseRecord(LineParser &p, TextState &st, MotionRecord &r) {
  p.skipBlanks();
  size_t at = p.pos();
  std::string_view name = p.word();
  if (name.empty()) return p.error(at, fmt::format("expected a record kind, found '{}'", p.token(at)));
  if (!kindFromName(name, r.kind)) return p.error(at, fmt::format("unknown Motion IR record kind '{}'", name));
  r.plane = st.plane;
  r.start = r.end = st.pos;
  switch (r.kind) {
  case RecordKind::Rapid:
  case RecordKind::Linear:
    if (!p.axes(r.end)) return false;
    if (r.kind == RecordKind::Linear && !(p.expect("F", "'F' and the feed") && p.number(r.feed))) return false;
    break;
  case RecordKind::Arc: {
    if (!p.axes(r.end) || !p.expect("center", "'center'") || !p.triple(r.center) ||
        !p.expect("plane=", "'plane='"))
      return false;
    size_t b = p.pos();
    std::string_view pl = p.word();
    if (pl == "xy") r.plane = Plane::XY;
    else if (pl == "zx") r.plane = Plane::ZX;
    else if (pl == "yz") r.plane = Plane::YZ;
    else return p.error(b, fmt::format("expected the plane xy, zx or yz, found '{}'", p.token(b)));
    p.skipBlanks();
    if (p.peek("normal=")) {
      size_t nb = p.pos();
      std::array<double, 3> n;
      if (!p.expect("normal=", "'normal='") || !p.triple(n)) return false;
      double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(std::fabs(len - 1) <= 1e-9))
        return p.error(nb, fmt::format("the arc normal ({}, {}, {}) is not a unit vector", n[0], n[1], n[2]));
      r.setNormal(n);
    }
    int64_t turns;
    if (!p.expect("turns=", "'turns='")) return false;
    size_t tb = p.pos();
    if (!p.integer(turns)) return false;
    if (turns < INT32_MIN || turns > INT32_MAX) return p.error(tb, "turns out of range");
    r.turns = (int32_t)turns;
    if (!p.expect("F", "'F' and the feed") || !p.number(r.feed)) return false;
    break;
  }
  case RecordKind::Spline: {
    SplineData sp;
    int64_t degree;
    if (!p.axes(r.end) || !p.expect("degree=", "'degree='")) return false;
    size_t db = p.pos();
    if (!p.integer(degree)) return false;
    if (degree < 1 || degree > 15) return p.error(db, fmt::format("the spline degree {} is not between 1 and 15", degree));
    sp.degree = (int)degree;
    if (!p.expect("points=", "'points='") || !p.list(sp.points, &LineParser::triple)) return false;
    p.skipBlanks();
    if (p.peek("weights=") && !(p.expect("weights=", "'weights='") && p.list(sp.weights, &LineParser::number)))
      return false;
    p.skipBlanks();
    if (p.peek("knots=") && !(p.expect("knots=", "'knots='") && p.list(sp.knots, &LineParser::number)))
      return false;
    if (!p.expect("F", "'F' and the feed") || !p.number(r.feed)) return false;
    r.setSpline(std::move(sp));
    if (std::string why = splineError(r); !why.empty()) return p.error(at, why);
    break;
  }
  case RecordKind::Thread: {
    if (!p.axes(r.end) || !p.expect("lead=", "'lead='") || !p.number(r.value)) return false;
    p.skipBlanks();
    if (p.peek("dlead=")) {
      double d;
      if (!p.expect("dlead=", "'dlead='") || !p.number(d)) return false;
      if (d != 0) r.setParam("dlead", d);
    }
    if (!p.expect("along=", "'along='")) return false;
    size_t b = p.pos();
    std::string_view along = p.word();
    int a = 0;
    while (a < 4 && along != threadAxisName((ThreadAxis)a)) ++a;
    if (a == 4) return p.error(b, fmt::format("expected the lead's axis x, y, z or path, found '{}'", p.token(b)));
    r.ivalue = a;
    if (!p.expect("sync=", "'sync='")) return false;
    b = p.pos();
    std::string_view sync = p.word();
    int k = 0;
    while (k < 4 && sync != threadSyncName((ThreadSync)k)) ++k;
    if (k == 4) return p.error(b, fmt::format("expected index, chain, tap_in or tap_out, found '{}'", p.token(b)));
    r.sync = (ThreadSync)k;
    p.skipBlanks();
    if (p.peek("start=") && !(p.expect("start=", "'start='") && p.number(r.value2))) return false;
    if (!p.expect("F", "'F' and the feed") || !p.number(r.feed)) return false;
    if (std::string why = threadError(r); !why.empty()) return p.error(at, why);
    break;
  }
  case RecordKind::Probe: {
    ProbeData pd;
    std::vector<double> target;
    if (!p.axes(r.end) || !p.expect("target=", "'target='")) return false;
    size_t b = p.pos();
    if (!p.list(target, &LineParser::number)) return false;
    if (target.size() != kBaseAxes && target.size() != kAxes)
      return p.error(b, fmt::format("a probe target has {} or {} positions, not {}", kBaseAxes, kAxes, target.size()));
    std::copy(target.begin(), target.end(), pd.target.begin());
    // Named choices: `key=` then one of two words.
    auto choice = [&](const char *key, const char *no, const char *yes, bool &out) {
      if (!p.expect(key, fmt::format("'{}'", key).c_str())) return false;
      size_t at = p.pos();
      std::string_view w = p.word();
      if (w != no && w != yes) return p.error(at, fmt::format("expected {} or {}, found '{}'", no, yes, p.token(at)));
      out = w == yes;
      return true;
    };
    bool release, error, tripped;
    if (!choice("signal=", "contact", "release", release) || !choice("miss=", "ok", "error", error) ||
        !choice("tripped=", "0", "1", tripped) || !p.expect("F", "'F' and the feed") || !p.number(r.feed))
      return false;
    pd.signal = release ? ProbeSignal::Release : ProbeSignal::Contact;
    pd.missIsError = error, pd.tripped = tripped;
    r.setProbe(pd);
    break;
  }
  case RecordKind::Comment:
  case RecordKind::Message:
    if (!p.string(r.text)) return false;
    break;
  case RecordKind::Dwell:
  case RecordKind::SpindleSpeed:
  case RecordKind::FeedRate:
  case RecordKind::ToolLength:
    p.skipBlanks();
    if (!p.number(r.value)) return false;
    if (r.kind == RecordKind::ToolLength && !(p.expect("H", "'H' and the offset number") && p.integer(r.ivalue)))
      return false;
    if (r.kind == RecordKind::ToolLength && (p.skipBlanks(), p.peek("X")) && !(p.expect("X", "'X'") && p.number(r.value2)))
      return false;
    if (r.kind == RecordKind::ToolLength && (p.skipBlanks(), p.peek("Y"))) {
      double y;
      if (!(p.expect("Y", "'Y'") && p.number(y))) return false;
      r.setParam("Y", y);
    }
    break;
  case RecordKind::Aux: {
    p.skipBlanks();
    size_t b = p.pos();
    r.text = std::string(p.letters());
    if (r.text.empty()) return p.error(b, "expected an auxiliary function: its letter and number (M7, B5)");
    if (!p.integer(r.ivalue)) return false;
    break;
  }
  case RecordKind::PathMode:
    p.skipBlanks();
    if (!p.integer(r.ivalue)) return false;
    p.skipBlanks();
    if (!p.number(r.value)) return false;
    if (r.ivalue == 2) {
      p.skipBlanks();
      if (!p.number(r.value2)) return false;
    }
    break;
  case RecordKind::SpindleOrient: {
    p.skipBlanks();
    if (!p.number(r.value)) return false;
    p.skipBlanks();
    size_t b = p.pos();
    if (!p.integer(r.ivalue)) return false;
    if (r.ivalue < 0 || r.ivalue > 2) return p.error(b, "an orientation way is 0 (cw), 1 (ccw) or 2 (shortest)");
    p.skipBlanks();
    b = p.pos();
    if (!p.number(r.value2)) return false;
    if (!(r.value2 >= 0)) return p.error(b, "the wait for the orientation must not be negative");
    break;
  }
  case RecordKind::SpindleMode: {
    p.skipBlanks();
    size_t b = p.pos();
    if (!p.integer(r.ivalue)) return false;
    if (r.ivalue < 0 || r.ivalue > 2)
      return p.error(b, "a spindle mode is 0 (rpm), 1 (constant surface speed) or 2 (its origin moved)");
    p.skipBlanks();
    b = p.pos();
    if (!p.number(r.value)) return false;
    if (!(r.value >= 0)) return p.error(b, "the spindle-speed limit must not be negative");
    p.skipBlanks();
    if (!p.number(r.value2)) return false;
    break;
  }
  case RecordKind::DigitalOutput:
  case RecordKind::AnalogOutput: {
    p.skipBlanks();
    size_t b = p.pos();
    if (!p.integer(r.ivalue)) return false;
    if (r.ivalue < 0) return p.error(b, "an output number must not be negative");
    p.skipBlanks();
    if (!p.number(r.value)) return false;
    p.skipBlanks();
    b = p.pos();
    if (!p.number(r.value2)) return false;
    if (r.value2 != 0 && r.value2 != 1) return p.error(b, "1 (synchronized with motion) or 0 (at once)");
    break;
  }
  case RecordKind::CycleBegin:
  case RecordKind::FrameChange:
    p.skipBlanks();
    if (p.peek("\"") && !p.string(r.text)) return false;
    if (!p.namedNumbers(r)) return false;
    break;
  case RecordKind::CycleEnd:
    break;
  default: {
    p.skipBlanks();
    size_t b = p.pos();
    if (!p.integer(r.ivalue)) return false;
    if (r.kind == RecordKind::Plane) {
      if (r.ivalue < 0 || r.ivalue > 2) return p.error(b, "a plane record takes 0 (xy), 1 (zx) or 2 (yz)");
      r.plane = st.plane = (Plane)r.ivalue;
    }
    break;
  }
  }
  if (!p.tail(r)) return false;
  // The probe's rules need its exact_stop, which the tail gives.
  if (r.kind == RecordKind::Probe)
    if (std::string why = probeError(r); !why.empty()) return p.error(at, why);
  if (isMoveRecord(r.kind)) st.pos = r.end;
  return true;
}

}  // namespace

bool parseMotionText(const SourceManager &sm, uint32_t file, MotionSink &sink, Diagnostics &diags) {
  std::string_view text = sm.text(file);
  TextState st;
  bool ok = true;
  uint32_t lineNo = 0;
  size_t b = 0;
  MotionRecord r;
  while (b < text.size()) {
    size_t e = text.find('\n', b);
    if (e == std::string_view::npos) e = text.size();
    std::string_view line = text.substr(b, e - b);
    b = e + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line[first] == '#') continue;
    LineParser p(line, file, lineNo, diags);
    r = MotionRecord{};
    // After an error the remaining lines are still checked, but no record reaches the sink.
    if (!parseRecord(p, st, r)) ok = false;
    else if (ok) sink.record(r);
  }
  return ok;
}

}  // namespace ncc
