#include "runtime/ProbeResults.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstring>

namespace ncc {

namespace {
// How far (program units, degrees) a given axis may lie from the straight move: the file holds
// positions as measured and printed, with a few decimals.
constexpr double kOnLine = 1e-4;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
}  // namespace

bool parseProbeResults(const SourceManager &sm, uint32_t file, Diagnostics &diags, ProbeResults &out) {
  out.file = sm.name(file);
  std::string_view text = sm.text(file);
  bool ok = true;
  uint32_t lineNo = 0;
  for (size_t b = 0; b < text.size();) {
    size_t e = text.find('\n', b);
    if (e == std::string_view::npos) e = text.size();
    std::string_view line = text.substr(b, e - b);
    b = e + 1;
    ++lineNo;
    line = line.substr(0, line.find('#'));
    size_t p = 0;
    auto skip = [&] {
      while (p < line.size() && isBlank(line[p])) ++p;
    };
    auto fail = [&](size_t at, std::string msg) {
      diags.error(SourceLoc{file, lineNo, (uint32_t)at + 1}, std::move(msg), "probe-results");
      ok = false;
    };
    skip();
    if (p >= line.size()) continue;
    size_t w0 = p;
    while (p < line.size() && !isBlank(line[p])) ++p;
    std::string_view word = line.substr(w0, p - w0);
    ProbeOutcome o;
    o.loc = SourceLoc{file, lineNo, (uint32_t)w0 + 1};
    if (word == "miss" || word == "end") {
      o.tripped = word == "end";
      skip();
      if (p < line.size()) {
        fail(p, fmt::format("'{}' takes no positions", word));
        continue;
      }
    } else if (word != "trip") {
      fail(w0, fmt::format("expected trip, end or miss, found '{}'", word));
      continue;
    }
    bool lineOk = true;
    for (skip(); p < line.size() && lineOk; skip()) {
      size_t at = p;
      const char *letter = std::strchr(kAxisLetters, line[p] & ~0x20);
      if (!letter || !*letter) {
        fail(at, fmt::format("expected an axis letter (X Y Z A B C U V W) and a number, found '{}'", line[p]));
        lineOk = false;
        break;
      }
      int axis = (int)(letter - kAxisLetters);
      if (o.has[axis]) {
        fail(at, fmt::format("{} is given twice", kAxisLetters[axis]));
        lineOk = false;
        break;
      }
      size_t n0 = ++p;
      while (p < line.size() && !isBlank(line[p])) ++p;
      std::string_view num = line.substr(n0, p - n0);
      if (!num.empty() && num[0] == '+') num.remove_prefix(1);
      double v;
      auto res = std::from_chars(num.data(), num.data() + num.size(), v);
      if (num.empty() || res.ec != std::errc() || res.ptr != num.data() + num.size() || !std::isfinite(v)) {
        fail(n0, fmt::format("expected a number after {}", kAxisLetters[axis]));
        lineOk = false;
        break;
      }
      o.has[axis] = true;
      o.at[axis] = v;
    }
    if (lineOk) out.outcomes.push_back(o);
  }
  return ok;
}

bool probeStopFraction(const ProbeOutcome &o, const AxisVec &start, const AxisVec &target, double &t, std::string &err) {
  t = 1;
  // The given axis that moves most fixes the point; the others must lie on the line there.
  int k = -1;
  for (int i = 0; i < kAxes; ++i)
    if (o.has[i] && (k < 0 || std::fabs(target[i] - start[i]) > std::fabs(target[k] - start[k]))) k = i;
  if (!o.tripped || k < 0) return true;
  if (target == start) {  // G38.3/G38.5 where the machine stands: a trip can only be there
    for (int i = 0; i < kAxes; ++i)
      if (o.has[i] && !(std::fabs(o.at[i] - start[i]) <= kOnLine)) {
        err = fmt::format("{}{} is not where this probe move starts and ends ({})", kAxisLetters[i], o.at[i], start[i]);
        return false;
      }
    return true;
  }
  if (target[k] == start[k]) {
    err = fmt::format("{} does not move in this probe move: give an axis that does", kAxisLetters[k]);
    return false;
  }
  t = (o.at[k] - start[k]) / (target[k] - start[k]);
  if (t > 1 && (t - 1) * std::fabs(target[k] - start[k]) <= kOnLine) t = 1;  // the target as printed
  for (int i = 0; i < kAxes; ++i)
    if (o.has[i] && !(std::fabs(start[i] + t * (target[i] - start[i]) - o.at[i]) <= kOnLine)) {
      err = fmt::format("{}{} is not on the probe move's straight line (there {} is {})", kAxisLetters[i], o.at[i],
                        kAxisLetters[i], start[i] + t * (target[i] - start[i]));
      return false;
    }
  if (!(t > 0 && t <= 1)) {
    err = fmt::format("{}{} is not between the probe move's start ({}) and its target ({})", kAxisLetters[k], o.at[k],
                      start[k], target[k]);
    return false;
  }
  return true;
}

}  // namespace ncc
