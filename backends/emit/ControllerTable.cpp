// Default output tables of the controllers and the [emit.*] key parser.
#include "backends/emit/ControllerTable.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>

namespace ncc::emit {

namespace {

struct CodeDef {
  Code code;
  const char *key;        // machine description key (code_<key>)
  const char *iso, *sinumerik;
};

// One row per event. ISO follows seed 001 (808D ISO dialect, which has one exact-stop mode
// G61); Sinumerik follows seed 000 (G60 exact stop).
const CodeDef kCodes[] = {
    {Code::Rapid, "rapid", "G0", "G0"},
    {Code::Linear, "linear", "G1", "G1"},
    {Code::ArcCW, "arc_cw", "G2", "G2"},
    {Code::ArcCCW, "arc_ccw", "G3", "G3"},
    {Code::Dwell, "dwell", "G4", "G4"},
    // ISO G09 exists (seed 001 §2.9) but ncc's ISO front end does not read it yet, so the
    // translated program would not run back: off by default (code_exact_stop_once = G9).
    {Code::ExactStopOnce, "exact_stop_once", "", "G9"},
    {Code::PlaneXY, "plane_xy", "G17", "G17"},
    {Code::PlaneZX, "plane_zx", "G18", "G18"},
    {Code::PlaneYZ, "plane_yz", "G19", "G19"},
    {Code::PerMinute, "per_minute", "G94", "G94"},
    {Code::PerRev, "per_rev", "G95", "G95"},
    {Code::InverseTime, "inverse_time", "G93", "G93"},
    {Code::ExactPath, "exact_path", "G61", "G60"},
    {Code::ExactStop, "exact_stop", "G61", "G60"},
    {Code::Continuous, "continuous", "G64", "G64"},
    {Code::SpindleCW, "spindle_cw", "M3", "M3"},
    {Code::SpindleCCW, "spindle_ccw", "M4", "M4"},
    {Code::SpindleStop, "spindle_stop", "M5", "M5"},
    {Code::FloodOn, "flood_on", "M8", "M8"},
    {Code::MistOn, "mist_on", "M7", "M7"},
    {Code::CoolantOff, "coolant_off", "M9", "M9"},
    {Code::ToolChange, "tool_change", "M6", "M6"},
    {Code::ProgramStop, "program_stop", "M0", "M0"},
    {Code::OptionalStop, "optional_stop", "M1", "M1"},
    {Code::EndM2, "end_m2", "M2", "M2"},
    {Code::EndM30, "end_m30", "M30", "M30"},
};
static_assert(sizeof(kCodes) / sizeof(kCodes[0]) == (size_t)Code::Count);

const char *const kClassNames[] = {"axis", "rotary", "center", "feed", "speed", "dwell"};
static_assert(sizeof(kClassNames) / sizeof(kClassNames[0]) == (size_t)WordClass::Count);

std::string trim(const std::string &s) {
  size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  std::string t = s.substr(b, e - b + 1);
  if (t.size() >= 2 && (t.front() == '"' || t.front() == '\'') && t.back() == t.front())
    t = t.substr(1, t.size() - 2);
  return t;
}

std::string lower(std::string s) {
  for (char &c : s) c = (char)std::tolower((unsigned char)c);
  return s;
}

bool parseBool(const std::string &v, bool &out) {
  std::string l = lower(v);
  if (l == "yes" || l == "true" || l == "on" || l == "1") return out = true, true;
  if (l == "no" || l == "false" || l == "off" || l == "0") return out = false, true;
  return false;
}

bool parseInt(const std::string &v, int64_t lo, int64_t hi, int64_t &out) {
  if (v.empty()) return false;
  char *end = nullptr;
  long long x = std::strtoll(v.c_str(), &end, 10);
  if (*end || x < lo || x > hi) return false;
  out = x;
  return true;
}

bool parseDouble(const std::string &v, double lo, double hi, double &out) {
  if (v.empty()) return false;
  char *end = nullptr;
  double x = std::strtod(v.c_str(), &end);
  if (*end || !(x >= lo && x <= hi)) return false;
  out = x;
  return true;
}

// A discrete size 1, 0.1 ... 1e-9 as the decimals it stands for (-1: not a power of ten).
int discreteDecimals(double d) {
  for (int k = 0; k <= 9; ++k)
    if (std::fabs(d - std::pow(10.0, -k)) <= 1e-12 * std::pow(10.0, -k)) return k;
  return -1;
}

// "none" (or empty) means no text.
std::string optText(const std::string &v) { return lower(v) == "none" ? std::string() : v; }

// Picks one of `names`; returns its index or -1.
int choose(const std::string &v, std::initializer_list<const char *> names) {
  int i = 0;
  for (const char *n : names) {
    if (lower(v) == n) return i;
    ++i;
  }
  return -1;
}

// "a | b" -> {"a", "b"}; "none" or empty -> {}.
std::vector<std::string> splitBlocks(const std::string &v) {
  std::vector<std::string> out;
  if (optText(v).empty()) return out;
  size_t p = 0;
  while (p <= v.size()) {
    size_t q = v.find('|', p);
    if (q == std::string::npos) q = v.size();
    std::string blk = trim(v.substr(p, q - p));
    if (!blk.empty()) out.push_back(blk);
    p = q + 1;
  }
  return out;
}

using Setter = std::function<bool(const std::string &, ControllerStyle &)>;
struct KeyDef {
  const char *key;
  const char *expect;  // for the error message
  Setter set;
};

template <class E>
Setter enumSetter(E ControllerStyle::*field, std::initializer_list<const char *> names) {
  std::vector<const char *> ns(names);
  return [field, ns](const std::string &v, ControllerStyle &s) {
    for (size_t i = 0; i < ns.size(); ++i)
      if (lower(v) == ns[i]) return s.*field = (E)i, true;
    return false;
  };
}

Setter textSetter(std::string ControllerStyle::*field) {
  return [field](const std::string &v, ControllerStyle &s) { return s.*field = optText(v), true; };
}

Setter intSetter(int64_t lo, int64_t hi, std::function<void(ControllerStyle &, int64_t)> put) {
  return [lo, hi, put](const std::string &v, ControllerStyle &s) {
    int64_t x;
    if (!parseInt(v, lo, hi, x)) return false;
    put(s, x);
    return true;
  };
}

Setter numberSetter(double lo, double hi, std::function<void(ControllerStyle &, double)> put) {
  return [lo, hi, put](const std::string &v, ControllerStyle &s) {
    double x;
    if (!parseDouble(v, lo, hi, x)) return false;
    put(s, x);
    return true;
  };
}

Setter boolSetter(bool ControllerStyle::*field) {
  return [field](const std::string &v, ControllerStyle &s) { return parseBool(v, s.*field); };
}

const std::vector<KeyDef> &keyTable() {
  static const std::vector<KeyDef> table = {
      {"arc_style", "ijk or r", enumSetter(&ControllerStyle::arcStyle, {"ijk", "r"})},
      {"helix_turns", "word or split", enumSetter(&ControllerStyle::helixTurns, {"word", "split"})},
      {"radius_word", "an address", textSetter(&ControllerStyle::radiusWord)},
      {"turns_word", "an address", textSetter(&ControllerStyle::turnsWord)},
      {"turns_count", "total or extra",
       [](const std::string &v, ControllerStyle &s) {
         int k = choose(v, {"total", "extra"});
         return k >= 0 ? (s.turnsOffset = k, true) : false;
       }},
      {"dwell_word", "an address", textSetter(&ControllerStyle::dwellWord)},
      {"dwell_unit", "s or ms",
       [](const std::string &v, ControllerStyle &s) {
         int k = choose(v, {"s", "ms"});
         return k >= 0 ? (s.dwellScale = k ? 1000 : 1, true) : false;
       }},
      {"tool_digits", "0..8", intSetter(0, 8, [](ControllerStyle &s, int64_t x) { s.toolDigits = (int)x; })},
      {"tool_offset_word", "a word or none", textSetter(&ControllerStyle::toolOffsetWord)},
      {"comment_style", "paren or semicolon",
       enumSetter(&ControllerStyle::commentStyle, {"paren", "semicolon"})},
      {"message_style", "paren or msg", enumSetter(&ControllerStyle::messageStyle, {"paren", "msg"})},
      {"block_numbers", "off, renumber or source (or yes/no)",
       [](const std::string &v, ControllerStyle &s) {
         bool b;
         int k = choose(v, {"off", "renumber", "source"});
         if (k < 0 && parseBool(v, b)) k = b ? 1 : 0;
         return k >= 0 ? (s.numbering = (Numbering)k, true) : false;
       }},
      {"block_every", "1..1000", intSetter(1, 1000, [](ControllerStyle &s, int64_t x) { s.blockEvery = (int)x; })},
      {"line_ending", "lf or crlf",
       [](const std::string &v, ControllerStyle &s) {
         int k = choose(v, {"lf", "crlf"});
         return k >= 0 ? (s.lineEnding = k ? "\r\n" : "\n", true) : false;
       }},
      {"block_start", "0..999999999",
       intSetter(0, 999999999, [](ControllerStyle &s, int64_t x) { s.blockStart = x; })},
      {"block_step", "1..100000", intSetter(1, 100000, [](ControllerStyle &s, int64_t x) { s.blockStep = x; })},
      {"block_digits", "0..9", intSetter(0, 9, [](ControllerStyle &s, int64_t x) { s.blockDigits = (int)x; })},
      {"separator", "space or none",
       [](const std::string &v, ControllerStyle &s) {
         int k = choose(v, {"space", "none"});
         return k >= 0 ? (s.separator = k ? "" : " ", true) : false;
       }},
      {"end_of_block", "none or semicolon",
       [](const std::string &v, ControllerStyle &s) {
         int k = choose(v, {"none", "semicolon"});
         return k >= 0 ? (s.endOfBlock = k ? ";" : "", true) : false;
       }},
      {"program_header", "lines separated by |",
       [](const std::string &v, ControllerStyle &s) { return s.programHeader = splitBlocks(v), true; }},
      {"program_footer", "lines separated by |",
       [](const std::string &v, ControllerStyle &s) { return s.programFooter = splitBlocks(v), true; }},
      {"program_number", "yes or no",
       [](const std::string &v, ControllerStyle &s) { return parseBool(v, s.programNumber); }},
      {"program_number_digits", "1..8",
       intSetter(1, 8, [](ControllerStyle &s, int64_t x) { s.programNumberDigits = (int)x; })},
      {"setup_blocks", "blocks separated by |",
       [](const std::string &v, ControllerStyle &s) { return s.setup = splitBlocks(v), true; }},
      // The passport's motions and interpolators (seed 004 §3.3 items 5-6).
      {"max_increment", "a length 0..1e6 mm (0 = unlimited)",
       numberSetter(0, 1e6, [](ControllerStyle &s, double x) { s.maxIncrement = {x, x, x}; })},
      {"max_increment.x", "a length 0..1e6 mm (0 = unlimited)",
       numberSetter(0, 1e6, [](ControllerStyle &s, double x) { s.maxIncrement[0] = x; })},
      {"max_increment.y", "a length 0..1e6 mm (0 = unlimited)",
       numberSetter(0, 1e6, [](ControllerStyle &s, double x) { s.maxIncrement[1] = x; })},
      {"max_increment.z", "a length 0..1e6 mm (0 = unlimited)",
       numberSetter(0, 1e6, [](ControllerStyle &s, double x) { s.maxIncrement[2] = x; })},
      {"rapid_split", "xyz, xy_then_z, xz_then_y or zy_then_x",
       enumSetter(&ControllerStyle::rapidSplit, {"xyz", "xy_then_z", "xz_then_y", "zy_then_x"})},
      {"arcs", "yes or no", boolSetter(&ControllerStyle::arcs)},
      {"arc_quadrants", "yes or no", boolSetter(&ControllerStyle::arcQuadrants)},
      {"max_arc_radius", "a length 0..1e9 mm (0 = unlimited)",
       numberSetter(0, 1e9, [](ControllerStyle &s, double x) { s.maxArcRadius = x; })},
      {"motion_modal", "yes or no", boolSetter(&ControllerStyle::motionModal)},
  };
  return table;
}

// <class>_<property> or <property> (all classes).
bool applyFormatKey(const std::string &key, const std::string &v, ControllerStyle &s, bool &known, const char *&expect) {
  static const char *const props[] = {"decimals",  "trailing_zeros", "point_on_integer", "leading_zero",
                                      "plus_sign", "max_digits",     "modal",            "discrete"};
  known = false;
  for (int p = 0; p < 8; ++p) {
    std::string prop = props[p];
    if (key.size() < prop.size() || key.compare(key.size() - prop.size(), prop.size(), prop) != 0) continue;
    std::string prefix = key.substr(0, key.size() - prop.size());
    int first = 0, last = (int)WordClass::Count;
    if (!prefix.empty()) {
      if (prefix.back() != '_') continue;
      prefix.pop_back();
      first = -1;
      for (int c = 0; c < (int)WordClass::Count; ++c)
        if (prefix == kClassNames[c]) first = c, last = c + 1;
      if (first < 0) continue;
    }
    known = true;
    static const char *const expects[] = {"decimals 0..9", "yes or no", "yes or no", "yes or no", "yes or no",
                                          "digits 0..18", "yes or no", "a power of ten 1, 0.1 ... 1e-9 (0 = off)"};
    expect = expects[p];
    int64_t n = 0;
    bool b = false;
    if (p == 7) {  // a discrete size: a power of ten, 0 = off (the decimals then stay)
      double d;
      if (!parseDouble(v, 0, 1, d) || (d != 0 && discreteDecimals(d) < 0)) return false;
      for (int c = first; c < last; ++c) {
        s.formats[c].discrete = d != 0;
        if (d != 0) s.formats[c].decimals = discreteDecimals(d);
      }
      return true;
    }
    bool isInt = p == 0 || p == 5;
    if (isInt ? !parseInt(v, 0, p == 0 ? 9 : 18, n) : !parseBool(v, b)) return false;
    for (int c = first; c < last; ++c) {
      NumberFormat &f = s.formats[c];
      switch (p) {
      case 0: f.decimals = (int)n; break;
      case 1: f.trailingZeros = b; break;
      case 2: f.pointOnInteger = b; break;
      case 3: f.leadingZero = b; break;
      case 4: f.plusSign = b; break;
      case 5: f.maxIntDigits = (int)n; break;
      case 6: f.modal = b; break;
      }
    }
    return true;
  }
  return true;
}

}  // namespace

ControllerStyle defaultStyle(Target t) {
  if (t == Target::Nc200) return nc200Style();
  ControllerStyle s;
  s.target = t;
  bool iso = t == Target::ISO;
  static const char *const kSections[] = {"emit.iso", "emit.sinumerik", "emit.heidenhain"};
  s.section = kSections[(size_t)t];
  // Klartext uses the M codes only, which are Sinumerik's (and ISO's).
  for (const CodeDef &d : kCodes) s.codes[(size_t)d.code] = iso ? d.iso : d.sinumerik;

  NumberFormat length;  // 3 decimals: the 0.001 mm input increment (IS-B)
  length.decimals = 3;
  length.pointOnInteger = iso;  // ISO "X10.": a point keeps the value in mm under IS-B/IS-C too
  for (auto &f : s.formats) f = length;
  // Centre offsets and radii get one digit more so that the re-read arc closes well inside the
  // 0.002 mm arc tolerance (see docs/EMIT.md, "Arcs").
  s.formats[(size_t)WordClass::Center].decimals = 4;
  s.formats[(size_t)WordClass::Speed].pointOnInteger = false;  // S1200: S is never scaled
  // Feeds converted from inch or computed by the program keep their value to 1e-6 relative
  // (what `translate --verify` compares) down to about 50 mm/min.
  s.formats[(size_t)WordClass::Feed].decimals = 4;

  if (iso) {
    s.arcStyle = ArcStyle::IJK;
    s.helixTurns = HelixTurns::Word;  // G2/G3 P<turns>: LinuxCNC and ncc read it; 808D may not
    s.radiusWord = "R";
    s.turnsWord = "P";
    s.turnsOffset = 0;
    s.dwellWord = "X";
    s.commentStyle = CommentStyle::Paren;
    s.messageStyle = MessageStyle::ParenMsg;
    s.numbering = Numbering::Off;
    s.programHeader = {"%"};
    s.programFooter = {"%"};
    s.programNumber = true;
    // 808D: G20/G21 must stand alone in their block (seed 001 §2.2).
    s.setup = {"G21", "G90 G17 G94 G54"};
  } else if (t == Target::Heidenhain) {
    // Klartext: signed coordinates (X+10 X-2.5), blocks numbered from 0 (BEGIN PGM) by 1, `;`
    // comments; F, S and the dwell unsigned. Klartext.cpp writes the frame and the blocks.
    for (WordClass c : {WordClass::Axis, WordClass::Rotary, WordClass::Center}) s.formats[(size_t)c].plusSign = true;
    s.commentStyle = CommentStyle::Semicolon;
    s.numbering = Numbering::Renumber;
    s.blockStart = 0;
    s.blockStep = 1;
  } else {
    s.arcStyle = ArcStyle::IJK;
    s.helixTurns = HelixTurns::Word;
    s.radiusWord = "CR=";
    s.turnsWord = "TURN=";
    s.turnsOffset = 1;
    s.dwellWord = "F";
    s.toolOffsetWord = "D0";
    s.commentStyle = CommentStyle::Semicolon;
    s.messageStyle = MessageStyle::MsgCall;
    s.numbering = Numbering::Renumber;
    s.programNumber = false;
    s.setup = {"G71 G90 G17 G94 G54"};
  }
  return s;
}

// The 808D turning tables (seed 001 Tables 1-2/1-4): system A has no G90/G91 (U W are the
// increments) and G98/G99 feed modes, G50 S the speed limit, G32 threads; system B keeps the
// milling G90 G94 G95 and writes G92 S, G33. Neither has G93 or G61/G64 on a lathe: inverse time
// is refused by the emitter, the path mode (timing, not geometry) is not written. Tools are
// T<tt>00 (offset 00: the positions already hold the offsets), no M6.
bool applyLathe(const Machine &m, ControllerStyle &s, Diagnostics &diags) {
  if (!m.controller.lathe()) return true;
  if (s.target == Target::Nc200) return applyNc200Lathe(m, s, diags);
  s.lathe = true;
  s.setupPlane = Plane::ZX;
  s.xScale = m.controller.diameterProgramming ? 2 : 1;
  if (s.target == Target::Sinumerik) {
    s.setup = {std::string("G71 G90 G18 G94 G54 ") + (m.controller.diameterProgramming ? "DIAMON" : "DIAMOF")};
    return true;
  }
  auto refuse = [&](const std::string &why) {
    diags.error(SourceLoc{}, "machine '" + m.name + "': the [emit.iso] emitter does not write lathe programs " + why);
    return false;
  };
  if (m.controller.family == "linuxcnc") return refuse("for LinuxCNC (G7/G8 diameter modes, T with M6)");
  const bool a = m.controller.gcodeSystem == "A";
  const bool c = m.controller.gcodeSystem == "C";  // B with metric G71 (the other codes it moves are not written)
  s.codes[(size_t)Code::PerMinute] = a ? "G98" : "G94";
  s.codes[(size_t)Code::PerRev] = a ? "G99" : "G95";
  for (Code c : {Code::InverseTime, Code::ExactPath, Code::ExactStop, Code::Continuous, Code::ToolChange})
    s.codes[(size_t)c].clear();
  s.setup = {c ? "G71" : "G21", a ? "G18 G98 G54" : "G90 G18 G94 G54"};
  s.threadCode = a ? "G32" : "G33";
  s.speedLimitCode = a ? "G50" : "G92";
  return true;
}

bool applyMachineSection(const Machine &m, ControllerStyle &style, Diagnostics &diags) {
  auto sec = m.sections.find(style.section);
  if (sec == m.sections.end()) return true;
  bool ok = true;
  // The value's place in the machine file when the driver registered it (docs/MACHINE.md).
  auto at = [&](const std::string &rawKey) {
    auto sp = m.sectionPositions.find(style.section);
    if (!m.sourceFile || sp == m.sectionPositions.end()) return SourceLoc{};
    auto p = sp->second.find(rawKey);
    return p == sp->second.end() ? SourceLoc{} : SourceLoc{m.sourceFile, p->second.first, p->second.second};
  };
  std::string rawKey;
  auto bad = [&](const std::string &key, const std::string &value, const char *expect) {
    diags.error(at(rawKey), "machine '" + m.name + "' [" + style.section + "] " + key + " = '" + value +
                                "': expected " + expect);
    ok = false;
  };
  // Global number-format keys first so that class keys refine them whatever the file order.
  for (int pass = 0; pass < 2; ++pass) {
    for (const auto &[fileKey, rawValue] : sec->second) {
      rawKey = fileKey;
      std::string key = lower(trim(rawKey)), value = trim(rawValue);
      bool isGlobalFormat = false;
      for (const char *p : {"decimals", "trailing_zeros", "point_on_integer", "leading_zero", "plus_sign",
                            "max_digits", "modal", "discrete"})
        if (key == p) isGlobalFormat = true;
      if ((pass == 0) != isGlobalFormat) continue;

      bool known = false;
      for (const KeyDef &k : keyTable())
        if (key == k.key) {
          known = true;
          if (!k.set(value, style)) bad(key, value, k.expect);
        }
      if (!known && key.rfind("code_", 0) == 0) {
        for (const CodeDef &d : kCodes)
          if (key.substr(5) == d.key) {
            known = true;
            style.codes[(size_t)d.code] = optText(value);
          }
      }
      if (!known && key.rfind("format.", 0) == 0) {
        // format.<LETTER> = decimals (the letter's word class; classes share one setting).
        static const std::pair<const char *, WordClass> letters[] = {
            {"x", WordClass::Axis},   {"y", WordClass::Axis},   {"z", WordClass::Axis},   {"a", WordClass::Rotary},
            {"b", WordClass::Rotary}, {"c", WordClass::Rotary}, {"i", WordClass::Center}, {"j", WordClass::Center},
            {"k", WordClass::Center}, {"r", WordClass::Center}, {"cr", WordClass::Center}, {"f", WordClass::Feed},
            {"s", WordClass::Speed},  {"p", WordClass::Dwell}};
        for (auto &[l, cls] : letters)
          if (key.substr(7) == l) {
            known = true;
            int64_t n;
            if (!parseInt(value, 0, 9, n)) bad(key, value, "decimals 0..9");
            else style.formats[(size_t)cls].decimals = (int)n;
          }
      }
      const char *expect = "";
      if (!known && !applyFormatKey(key, value, style, known, expect)) bad(key, value, expect);
      if (!known)
        diags.warning(at(rawKey), "machine '" + m.name + "' [" + style.section + "]: unknown key '" + key + "'");
    }
  }
  return ok;
}

}  // namespace ncc::emit
