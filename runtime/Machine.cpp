// Machine description parser (format: docs/MACHINE.md). Keys are data tables per section kind,
// so adding a setting is one table row; every error names the file and line.
#include "runtime/Machine.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace ncc {

namespace {

std::string trim(const std::string &s) {
  size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

bool parseNumber(const std::string &v, double &out) {
  if (v.empty()) return false;
  char *end = nullptr;
  errno = 0;
  double d = std::strtod(v.c_str(), &end);
  if (*end != 0 || errno == ERANGE || !std::isfinite(d)) return false;
  out = d;
  return true;
}

bool parseInt(const std::string &v, long long &out) {
  if (v.empty()) return false;
  char *end = nullptr;
  errno = 0;
  long long n = std::strtoll(v.c_str(), &end, 10);
  if (*end != 0 || errno == ERANGE) return false;
  out = n;
  return true;
}

bool parseBool(const std::string &v, bool &out) {
  static const struct { const char *text; bool value; } words[] = {
      {"true", true}, {"yes", true}, {"on", true}, {"1", true},
      {"false", false}, {"no", false}, {"off", false}, {"0", false}};
  for (auto &w : words)
    if (v == w.text) { out = w.value; return true; }
  return false;
}

// "x y z [a b c]": 3 to 6 numbers separated by blanks or commas.
bool parseAxisVec(const std::string &v, AxisVec &out) {
  std::string s = v;
  for (char &c : s) if (c == ',') c = ' ';
  std::istringstream in(s);
  AxisVec r{};
  int n = 0;
  std::string tok;
  while (in >> tok) {
    if (n == kAxes || !parseNumber(tok, r[n])) return false;
    ++n;
  }
  if (n < 3) return false;
  out = r;
  return true;
}

// A setter returns an error text (empty on success).
template <class T> struct KeyDef {
  const char *key;
  std::string (*apply)(T &, const std::string &);
};

#define NCC_NUM(field, cond, what)                                                    \
  [](auto &o, const std::string &v) -> std::string {                                  \
    double d;                                                                         \
    if (!parseNumber(v, d)) return "expected a number, got '" + v + "'";              \
    if (!(cond)) return std::string("value must be ") + what;                         \
    o.field = d;                                                                      \
    return {};                                                                        \
  }

const KeyDef<Machine> kMachineKeys[] = {
    {"name", [](Machine &m, const std::string &v) -> std::string {
       if (v.empty()) return "name must not be empty";
       m.name = v;
       return {};
     }},
    {"dialect", [](Machine &m, const std::string &v) -> std::string {
       static const char *known[] = {"iso", "fanuc", "linuxcnc", "sinumerik", "heidenhain", "cldata"};
       for (auto *k : known)
         if (v == k) { m.dialect = v; return {}; }
       return "unknown dialect '" + v + "' (iso, fanuc, linuxcnc, sinumerik, heidenhain, cldata)";
     }},
    {"decimal_mode", [](Machine &m, const std::string &v) -> std::string {
       if (v != "calculator" && v != "is-b" && v != "is-c")
         return "decimal_mode must be calculator, is-b or is-c, got '" + v + "'";
       m.decimalMode = v;
       return {};
     }},
    {"rapid_feed", NCC_NUM(rapidFeed, d > 0, "> 0")},
    {"max_feed", NCC_NUM(maxFeed, d > 0, "> 0")},
    {"arc_tolerance", NCC_NUM(arcTolerance, d > 0, "> 0")},
    {"path_tolerance", NCC_NUM(pathTolerance, d >= 0, ">= 0")},
    {"free_tools", [](Machine &m, const std::string &v) -> std::string {
       long long n;
       if (!parseInt(v, n) || n < 0 || n > 99999) return "expected an integer 0..99999, got '" + v + "'";
       m.freeTools = (int)n;
       return {};
     }},
    {"lookahead", [](Machine &m, const std::string &v) -> std::string {
       long long n;
       if (!parseInt(v, n)) return "expected an integer, got '" + v + "'";
       if (n < 1 || n > 100000) return "lookahead must be 1..100000";
       m.lookahead = (int)n;
       return {};
     }},
};

const KeyDef<AxisLimits> kAxisKeys[] = {
    {"present", [](AxisLimits &a, const std::string &v) -> std::string {
       return parseBool(v, a.present) ? std::string() : "expected true or false, got '" + v + "'";
     }},
    {"rotary", [](AxisLimits &a, const std::string &v) -> std::string {
       return parseBool(v, a.rotary) ? std::string() : "expected true or false, got '" + v + "'";
     }},
    {"max_velocity", NCC_NUM(maxVelocity, d > 0, "> 0")},
    {"max_accel", NCC_NUM(maxAccel, d > 0, "> 0")},
    {"max_jerk", NCC_NUM(maxJerk, d >= 0, ">= 0 (0 = no jerk limit)")},
    {"min", NCC_NUM(minPos, true, "")},
    {"max", NCC_NUM(maxPos, true, "")},
};

const KeyDef<ToolData> kToolKeys[] = {
    {"length", NCC_NUM(length, true, "")},
    {"radius", NCC_NUM(radius, d >= 0, ">= 0")},
};
#undef NCC_NUM

template <class T, size_t N>
const KeyDef<T> *findKey(const KeyDef<T> (&table)[N], const std::string &key) {
  for (auto &k : table)
    if (key == k.key) return &k;
  return nullptr;
}

// Offsets: g54..g59, g59.1..g59.3 map to workOffsets[0..8].
AxisVec *offsetSlot(Machine &m, const std::string &key) {
  static const char *names[] = {"g54", "g55", "g56", "g57", "g58", "g59", "g59.1", "g59.2", "g59.3"};
  for (int i = 0; i < 9; ++i)
    if (key == names[i]) return &m.workOffsets[i];
  if (key == "home1") return &m.home1;
  if (key == "home2") return &m.home2;
  return nullptr;
}

int axisIndex(char c) {
  static const char letters[] = "XYZABC";
  const char *p = std::strchr(letters, std::toupper((unsigned char)c));
  return (p && *p) ? int(p - letters) : -1;
}

// Strips a comment: '#' after a blank or at line start, ';' only at line start (so a
// Sinumerik header "; text" can be a value). A value in double quotes is taken literally.
std::string stripComment(const std::string &line) {
  std::string t = trim(line);
  if (t.empty() || t[0] == '#' || t[0] == ';') return {};
  bool quoted = false;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '"') quoted = !quoted;
    if (!quoted && t[i] == '#' && i > 0 && (t[i - 1] == ' ' || t[i - 1] == '\t'))
      return trim(t.substr(0, i));
  }
  return t;
}

std::string unquote(const std::string &v) {
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') return v.substr(1, v.size() - 2);
  return v;
}

}  // namespace

std::string Machine::get(const std::string &section, const std::string &key, const std::string &def) const {
  auto s = sections.find(section);
  if (s == sections.end()) return def;
  auto k = s->second.find(key);
  return k == s->second.end() ? def : k->second;
}

bool Machine::parse(const std::string &text, const std::string &name, Machine &out, std::string &err) {
  Machine m;
  m.axes = {};
  std::istringstream in(text);
  std::string raw, section;
  unsigned lineNo = 0;
  std::array<unsigned, kAxes> axisLine{};
  auto fail = [&](unsigned line, const std::string &msg) {
    err = name + ":" + std::to_string(line) + ": " + msg;
    return false;
  };
  while (std::getline(in, raw)) {
    ++lineNo;
    if (lineNo == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0) raw.erase(0, 3);  // UTF-8 byte order mark
    std::string line = stripComment(raw);
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') return fail(lineNo, "missing ']' in section header");
      section = trim(line.substr(1, line.size() - 2));
      if (section.empty()) return fail(lineNo, "empty section name");
      if (section.rfind("axis.", 0) == 0) {
        int ax = section.size() == 6 ? axisIndex(section[5]) : -1;
        if (ax < 0) return fail(lineNo, "unknown axis section [" + section + "] (axes are X Y Z A B C)");
        section = std::string("axis.") + "XYZABC"[ax];
        // A listed axis is present unless it says otherwise; A/B/C default to rotary.
        m.axes[ax].present = true;
        m.axes[ax].rotary = ax >= 3;
        axisLine[ax] = lineNo;
      } else if (section.rfind("tool.", 0) == 0) {
        long long n;
        if (!parseInt(section.substr(5), n) || n < 0 || n > 99999)
          return fail(lineNo, "bad tool section [" + section + "] (expected [tool.N], N = 0..99999)");
        m.tools[(int)n];
      }
      m.sections[section];
      continue;
    }
    size_t eq = line.find('=');
    if (eq == std::string::npos) return fail(lineNo, "expected 'key = value' or '[section]'");
    std::string key = trim(line.substr(0, eq));
    std::string value = unquote(trim(line.substr(eq + 1)));
    if (key.empty()) return fail(lineNo, "missing key before '='");
    if (section.empty()) return fail(lineNo, "key '" + key + "' outside a section");
    auto &sec = m.sections[section];
    if (sec.count(key)) return fail(lineNo, "duplicate key '" + key + "' in [" + section + "]");
    sec[key] = value;

    std::string problem;
    bool known = true;
    if (section == "machine") {
      auto *k = findKey(kMachineKeys, key);
      if (k) problem = k->apply(m, value); else known = false;
    } else if (section.rfind("axis.", 0) == 0) {
      auto *k = findKey(kAxisKeys, key);
      if (k) problem = k->apply(m.axes[axisIndex(section[5])], value); else known = false;
    } else if (section.rfind("tool.", 0) == 0) {
      auto *k = findKey(kToolKeys, key);
      if (k) problem = k->apply(m.tools[std::atoi(section.c_str() + 5)], value); else known = false;
    } else if (section == "offsets") {
      AxisVec *slot = offsetSlot(m, key);
      if (!slot) known = false;
      else if (!parseAxisVec(value, *slot)) problem = "expected 3 to 6 numbers (x y z [a b c]), got '" + value + "'";
    }
    if (!known) return fail(lineNo, "unknown key '" + key + "' in [" + section + "]");
    if (!problem.empty()) return fail(lineNo, key + ": " + problem);
  }
  // Whole-section checks, reported at the section header.
  for (int i = 0; i < kAxes; ++i) {
    const AxisLimits &a = m.axes[i];
    if (!a.present) continue;
    std::string sec = std::string("[axis.") + "XYZABC"[i] + "]";
    if (a.maxVelocity <= 0) return fail(axisLine[i], "present axis " + sec + " needs max_velocity");
    if (a.maxAccel <= 0) return fail(axisLine[i], "present axis " + sec + " needs max_accel");
    if (a.minPos >= a.maxPos) return fail(axisLine[i], sec + ": min must be below max");
  }
  if (!m.axes[0].present && !m.axes[1].present && !m.axes[2].present)
    return fail(lineNo ? lineNo : 1, "no linear axis present (need at least one of [axis.X] [axis.Y] [axis.Z])");
  out = std::move(m);
  return true;
}

bool Machine::load(const std::string &nameOrPath, Machine &out, std::string &err) {
  if (nameOrPath == "default" || nameOrPath == "default-mill") {
    out = builtinDefault();
    return true;
  }
  std::ifstream f(nameOrPath, std::ios::binary);
  if (!f) {
    err = nameOrPath + ": cannot read machine description: " + std::strerror(errno);
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  return parse(ss.str(), nameOrPath, out, err);
}

const char *Machine::builtinDefaultText() {
  static const char text[] =
#include "DefaultMachineText.inc"
      ;
  return text;
}

const Machine &Machine::builtinDefault() {
  static const Machine m = [] {
    Machine r;
    std::string err;
    if (!parse(builtinDefaultText(), "<default-mill>", r, err)) {
      // The embedded text is checked by the unit tests; reaching this is a build defect.
      std::fprintf(stderr, "ncc: internal error: embedded default machine: %s\n", err.c_str());
      std::abort();
    }
    return r;
  }();
  return m;
}

const ToolData *Machine::findTool(int n) const {
  static const ToolData kNone{};
  if (auto it = tools.find(n); it != tools.end()) return &it->second;
  // A machine without a tool table restricts nothing.
  return n == 0 || tools.empty() || (n > 0 && n <= freeTools) ? &kNone : nullptr;
}

}  // namespace ncc
