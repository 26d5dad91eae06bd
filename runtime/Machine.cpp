// Machine description reader (schema: docs/MACHINE.md). toml++ parses the file and keeps source
// positions; each table's keys are a data table (name, field, range or choices), so adding a
// setting is one row, and every problem is reported as "file:line:col: error: message".
#include "runtime/Machine.h"
#include "runtime/MachineReader.h"
#include "runtime/WorkOffsetCode.h"

#include "runtime/Geometry.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>
#include <variant>

namespace ncc {

using namespace machine_reader;

namespace {

constexpr const char *kAxisNames = kAxisLetters;
constexpr const char *kDialects = "iso fanuc linuxcnc sinumerik heidenhain cldata";
// Modal groups a controller may reset at M2/M30 (the executor's table in runtime/Executor.cpp).
constexpr const char *kResetGroups =
    "motion plane distance feed_mode units cutter_comp tool_length work_offset g92 feed spindle coolant path_mode "
    "rotation scaling mirror local_offset";

// ---- the schema ------------------------------------------------------------------------------

const KeyDef<Machine> kMachineKeys[] = {
    {"name", &Machine::name},
    {"dialect", &Machine::dialect, 0, 0, false, kDialects},
    {"decimal_mode", &Machine::decimalMode, 0, 0, false, "calculator is-b is-c"},
    {"rapid_feed", &Machine::rapidFeed, 0, kInf, true},
    {"max_feed", &Machine::maxFeed, 0, kInf, true},
    {"arc_tolerance", &Machine::arcTolerance, 0, kInf, true},
    {"path_tolerance", &Machine::pathTolerance, 0},
    {"lookahead", &Machine::lookahead, 1, 100000},
    {"free_tools", &Machine::freeTools, 0, 99999},
    {"max_spindle_speed", &Machine::maxSpindleSpeed, 0, kInf},
};

const KeyDef<Controller::MacroCall> kMacroCallKeys[] = {
    {"program", &Controller::MacroCall::program, 0, 0, true},
    {"kind", &Controller::MacroCall::kind, 0, 0, false, "macro subprogram"},
};

// Codes a controller keeps for itself (808D: "conflicts with predefined M numbers (M0, M5, M30,
// M98, M99 ...) are rejected with an alarm"; Fanuc likewise refuses M2, M30, M98, M99): program
// flow, the spindle, and the macro calls themselves.
constexpr const char *kReservedCallCodes[] = {"M0", "M1", "M2", "M3", "M4", "M5", "M17", "M19", "M30", "M98",
                                              "M99", "G65", "G66", "G67"};

void readMacroCalls(Ctx &c, const toml::node &n, void *obj) {
  auto &calls = static_cast<Controller *>(obj)->macroCalls;
  auto entry = [&](const std::string &code, const toml::key &k, const toml::node &v) {
    // M<n> or G<n>[.<n>]: the codes a controller lets a macro replace.
    bool ok = code.size() >= 2 && (code[0] == 'M' || code[0] == 'G');
    size_t dot = code.find('.');
    for (size_t i = 1; ok && i < code.size(); ++i)
      ok = std::isdigit((unsigned char)code[i]) || (i == dot && code[0] == 'G' && i > 1 && i + 1 < code.size());
    if (!ok) return c.error(k.source(), "macro_calls: '" + code + "' is not an M or G code (M6, G81, \"G65.1\")");
    size_t lead = code.find_first_not_of('0', 1);  // M06 -> M6, G00 -> G0
    std::string plain = code.substr(0, 1) + (lead == std::string::npos || lead == dot ? "0" : "") +
                        (lead == std::string::npos ? "" : code.substr(lead));
    if (std::count(std::begin(kReservedCallCodes), std::end(kReservedCallCodes), plain))
      return c.error(k.source(), "macro_calls: " + plain + " is a code of the controller itself and cannot call a program");
    Controller::MacroCall call;
    if (v.is_table()) {
      if (!readTable(c, v, "macro_calls." + code, kMacroCallKeys, call)) return;
    } else if (auto s = readString(c, v, "macro_calls." + code, nullptr)) {
      call.program = *s;
    } else {
      return;
    }
    if (call.program.empty()) return c.error(v.source(), "macro_calls." + code + ": the program name is empty");
    if (calls.count(plain)) return c.error(k.source(), "macro_calls: " + plain + " is given twice");
    calls[plain] = call;
  };
  forEachEntry(c, n, "macro_calls: expected a table of code = \"program\" or { program = \"...\", kind = \"subprogram\" }", entry);
}

// Fanuc tool compensation memory A and B keep one value (A) or one geometry and one wear (B) per
// offset number for H and D alike; the tool table keeps length and radius apart, which only
// memory C matches.
void readOffsetMemory(Ctx &c, const toml::node &n, void *obj) {
  auto s = readString(c, n, "offset_memory", "none A B C");
  if (!s) return;
  if (*s == "A" || *s == "B")
    return c.error(n.source(), "offset_memory: memory " + *s +
                                   " (one register per offset number for H and D) cannot hold the tool table's separate "
                                   "length and radius; ncc models \"none\" and \"C\"");
  static_cast<Controller *>(obj)->offsetMemory = *s;
}

// offset_numbers = { 10 = [1, 1], 11 = [1, 2] }: H/D number -> [tool, edge]; whether the tool
// has that edge is checked when the whole machine is read.
void readOffsetNumbers(Ctx &c, const toml::node &n, void *obj) {
  auto &numbers = static_cast<Controller *>(obj)->offsetNumbers;
  auto entry = [&](const std::string &key, const toml::key &k, const toml::node &v) {
    bool digits = !key.empty() && key.size() <= 5 && key[0] != '0' && key.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) return c.error(k.source(), "offset_numbers: '" + key + "' is not an offset number 1..99999");
    const toml::array *a = v.as_array();
    auto whole = [&](size_t i) { return a && a->size() == 2 && a->get(i)->is_integer() ? **a->get(i)->as_integer() : -1; };
    long long tool = whole(0), edge = whole(1);
    if (tool < 1 || tool > 99999 || edge < 1 || edge > 99999)
      return c.error(v.source(), "offset_numbers." + key + ": expected [tool, edge], two integers 1..99999");
    numbers[std::stoi(key)] = {(int)tool, (int)edge};
  };
  forEachEntry(c, n, "offset_numbers: expected a table of number = [tool, edge]", entry);
}

// The codes `startup` accepts and their modes.
const struct {
  const char *code;
  ModeValue mode;
} kStartupCodes[] = {
    {"G0", ModeValue::Rapid},        {"G1", ModeValue::Linear},          {"G80", ModeValue::CycleOff},
    {"G20", ModeValue::Inch},        {"G21", ModeValue::MM},             {"G90", ModeValue::Absolute},
    {"G91", ModeValue::Incremental}, {"G90.1", ModeValue::ArcAbsolute},  {"G91.1", ModeValue::ArcIncremental},
    {"G93", ModeValue::InverseTime}, {"G94", ModeValue::PerMinute},      {"G95", ModeValue::PerRev},
    {"G98", ModeValue::RetractInitial}, {"G99", ModeValue::RetractR},    {"G61", ModeValue::ExactPath},
    {"G61.1", ModeValue::ExactStop}, {"G64", ModeValue::Continuous},
};

void readStartup(Ctx &c, const toml::node &n, void *obj) {
  auto &modes = static_cast<Controller *>(obj)->startup;
  const toml::array *a = n.as_array();
  if (!a) return c.error(n.source(), "startup: expected an array of G codes, got " + typeName(n));
  modes.clear();
  for (const toml::node &e : *a) {
    auto s = readString(c, e, "startup", nullptr);
    if (!s) continue;
    const ModeValue *found = nullptr;
    for (auto &k : kStartupCodes)
      if (*s == k.code) found = &k.mode;
    if (!found) {
      std::string all;
      for (auto &k : kStartupCodes) all += std::string(all.empty() ? "" : " ") + k.code;
      c.error(e.source(), "startup: '" + *s + "' is not a start-up code (" + all + "; the plane is the key plane)");
      continue;
    }
    for (ModeValue m : modes)
      if (modeValueInfo(m).group == modeValueInfo(*found).group)
        c.error(e.source(), "startup: two codes of one modal group");
    modes.push_back(*found);
  }
}

const KeyDef<Controller> kControllerKeys[] = {
    {"startup", NodeReader(readStartup)},
    {"family", &Controller::family, 0, 0, false, kDialects},
    {"model", &Controller::model},
    {"kind", &Controller::kind, 0, 0, false, "mill lathe"},
    {"gcode_system", &Controller::gcodeSystem, 0, 0, false, "A B C"},
    {"start_mode", &Controller::startMode, 0, 0, false, "siemens iso"},
    {"plane", &Controller::plane, 0, 0, false, "G17 G18 G19"},
    {"diameter_programming", &Controller::diameterProgramming},
    {"reset", &Controller::reset, 0, 0, false, kResetGroups},
    {"r_params", &Controller::rParams, 0, 100000},
    {"q_params", &Controller::qParams, 0, 100000},
    {"display_depth_err", &Controller::displayDepthErr},
    {"real_tolerance", &Controller::realTolerance, 0, 1},
    {"axes_scale_enable", &Controller::axesScaleEnable},
    {"scale_weighting", &Controller::scaleWeighting, 1e-5, 1e-3},
    {"macro_calls", NodeReader(readMacroCalls)},
    {"offset_write", &Controller::offsetWrite, 0, 0, false, "immediate on-select on-change"},
    {"parameter_units", &Controller::parameterUnits, 0, 0, false, "mm inch"},
    {"m19_angle", &Controller::m19Angle, 0, 360},
    {"boring_orient_angle", &Controller::boringOrientAngle, 0, 360},
    {"boring_lift", &Controller::boringLift, 0, 4},
    {"peck_retract", &Controller::peckRetract, 0, 1000},
    {"peck_tapping", &Controller::peckTapping, 0, 0, false, "off chip-breaking chip-removal"},
    {"chip_break_retract", &Controller::chipBreakRetract, 0, 1000},
    {"probe_feed", &Controller::probeFeed, 0.001, 100000},
    {"probe_fmax", &Controller::probeFmax, 0.001, 100000},
    {"probe_prepos", &Controller::probePrepos, 0, 0, false, "machine probe"},
    {"probe_dist", &Controller::probeDist, 0.001, 100000},
    {"probe_set_up", &Controller::probeSetUp, 0, 100000},
    {"tool_write", &Controller::toolWrite, 0, 0, false, "on-select immediate"},
    {"offset_memory", NodeReader(readOffsetMemory)},
    {"offset_numbers", NodeReader(readOffsetNumbers)},
    {"mirror_tool_length", &Controller::mirrorToolLength},
    {"mirror_tool_wear", &Controller::mirrorToolWear},
    {"wear_sign_cutpos", &Controller::wearSignCutpos},
    {"wear_sign", &Controller::wearSign},
    {"tool_length_const", &Controller::toolLengthConst},
    {"dl_default", &Controller::dlDefault, 0, 6},
    {"base_frames", &Controller::baseFrames, 0, 8},
    {"nc_base_frames", &Controller::ncBaseFrames, 0, 8},
    {"settable_frames", &Controller::settableFrames, 5, 100},
    {"base_frame_mask", &Controller::baseFrameMask, 0, 255},
    {"reset_mode_mask", &Controller::resetModeMask, 0, 0x3ffff},
};

void readAxisKind(Ctx &c, const toml::node &n, void *obj) {
  if (auto s = readString(c, n, "kind", "linear rotary")) static_cast<AxisLimits *>(obj)->rotary = *s == "rotary";
}

// The controller's name of the axis (Sinumerik channel axis names such as X1 or Q1): a letter,
// then letters, digits or '_', at most 8 characters.
void readAxisName(Ctx &c, const toml::node &n, void *obj) {
  const std::string *s = n.as_string() ? &n.as_string()->get() : nullptr;
  if (!s) return c.error(n.source(), "name: expected a string, got " + typeName(n));
  bool ok = !s->empty() && s->size() <= 8 && std::isupper((unsigned char)(*s)[0]) &&
            std::all_of(s->begin(), s->end(), [](char ch) { return std::isupper((unsigned char)ch) || std::isdigit((unsigned char)ch) || ch == '_'; });
  if (!ok) return c.error(n.source(), "name: '" + *s + "' is not an axis name (an upper-case letter, then upper-case letters, digits or '_', at most 8)");
  static_cast<AxisLimits *>(obj)->name = *s;
}

const KeyDef<AxisLimits> kAxisKeys[] = {
    {"kind", NodeReader(readAxisKind)},
    {"name", NodeReader(readAxisName)},
    {"max_velocity", &AxisLimits::maxVelocity, 0, kInf, true, nullptr, true},
    {"max_accel", &AxisLimits::maxAccel, 0, kInf, true, nullptr, true},
    {"max_jerk", &AxisLimits::maxJerk, 0},
    {"min", &AxisLimits::minPos},
    {"max", &AxisLimits::maxPos},
};

void readAxes(Ctx &c, const toml::node &n, void *obj) {
  Machine &m = *static_cast<Machine *>(obj);
  forEachNamed(c, n, "axes", [&](const std::string &name, const toml::key &k, const toml::node &v) {
    const char *p = name.size() == 1 ? std::strchr(kAxisNames, name[0]) : nullptr;
    if (!p || !*p) return c.error(k.source(), "axis '" + name + "': the machine axes are X Y Z A B C U V W (name them with 'name')");
    int i = int(p - kAxisNames);
    AxisLimits a;
    a.present = true;
    a.rotary = i >= 3 && i < 6;  // A B C turn unless kind says otherwise
    if (readTable(c, v, "[axes." + name + "]", kAxisKeys, a) && a.minPos >= a.maxPos)
      c.error(v.source(), "[axes." + name + "]: min must be below max");
    if (i >= kBaseAxes && a.rotary)
      c.error(v.source(), "[axes." + name + "]: U V W are linear axes (parallel to X Y Z)");
    m.axes[i] = a;
  });
}

// The [offsets] table: named reference positions, copied into Machine afterwards.
struct OffsetsIn {
  AxisVec g54{}, g55{}, g56{}, g57{}, g58{}, g59{}, g59_1{}, g59_2{}, g59_3{}, home1{}, home2{};
  std::vector<AxisVec> g54p;  // the 808D's extended offsets G54 P1, P2, …
  std::array<AxisVec, 8> base{}, ncBase{};  // Sinumerik $P_CHBFR[n], $P_NCBFR[n]
  std::map<int, AxisVec> settable;           // Sinumerik G510…G599: $P_UIFR[10…99]
};

// [offsets] settable = { g510 = [x, y, z…], … }: the Sinumerik settable frames past G509 (G505…
// G509 are g58…"g59.3", the nine ISO offsets).
void readSettableFrames(Ctx &c, const toml::node &n, void *obj) {
  auto &out = static_cast<OffsetsIn *>(obj)->settable;
  forEachEntry(c, n, "settable: expected a table { g510 = [x, y, z…], … }", [&](const std::string &code, const toml::key &k,
                                                                             const toml::node &v) {
    bool ok = code.size() == 4 && code[0] == 'g' && code[1] == '5' && std::isdigit((unsigned char)code[2]) &&
              std::isdigit((unsigned char)code[3]) && code[2] != '0';
    if (!ok)
      return c.error(k.source(), "settable: '" + code + "' is not one of g510 … g599 (G54…G57 and G505…G509 are g54 … \"g59.3\")");
    readAxisVec(c, v, "settable." + code, out[std::stoi(code.substr(2))]);
  });
}

// [offsets] base = [[x, y, z…], …] and nc_base: the stored base frames 0, 1, … (offsets).
template <std::array<AxisVec, 8> OffsetsIn::*Member> void readBaseFrames(Ctx &c, const toml::node &n, void *obj) {
  const char *key = Member == &OffsetsIn::base ? "base" : "nc_base";
  const toml::array *a = n.as_array();
  if (!a || a->size() > 8)
    return c.error(n.source(), std::string(key) + ": expected an array of at most 8 offsets [[x, y, z…], …], got " +
                                   (a ? std::to_string(a->size()) + " elements" : typeName(n)));
  for (size_t i = 0; i < a->size(); ++i)
    readAxisVec(c, *a->get(i), std::string(key) + "[" + std::to_string(i) + "]", (static_cast<OffsetsIn *>(obj)->*Member)[i]);
}

// [offsets] g54p = [[x, y, z…], …]: the 808D's extended work offsets G54 P1…P93.
void readExtendedOffsets(Ctx &c, const toml::node &n, void *obj) {
  const toml::array *a = n.as_array();
  if (!a || a->size() > 93)
    return c.error(n.source(), "g54p: expected an array of at most 93 offsets [[x, y, z…], …] (G54 P1…P93), got " +
                                   (a ? std::to_string(a->size()) + " elements" : typeName(n)));
  auto &out = static_cast<OffsetsIn *>(obj)->g54p;
  out.assign(a->size(), AxisVec{});
  for (size_t i = 0; i < a->size(); ++i) readAxisVec(c, *a->get(i), "g54p[" + std::to_string(i) + "]", out[i]);
}

const KeyDef<OffsetsIn> kOffsetKeys[] = {
    {"g54", &OffsetsIn::g54},     {"g55", &OffsetsIn::g55},     {"g56", &OffsetsIn::g56},
    {"g57", &OffsetsIn::g57},     {"g58", &OffsetsIn::g58},     {"g59", &OffsetsIn::g59},
    {"g59.1", &OffsetsIn::g59_1}, {"g59.2", &OffsetsIn::g59_2}, {"g59.3", &OffsetsIn::g59_3},
    {"home1", &OffsetsIn::home1}, {"home2", &OffsetsIn::home2},
    {"base", NodeReader(readBaseFrames<&OffsetsIn::base>)}, {"nc_base", NodeReader(readBaseFrames<&OffsetsIn::ncBase>)},
    {"g54p", NodeReader(readExtendedOffsets)},
    {"settable", NodeReader(readSettableFrames)},
};

void readOffsets(Ctx &c, const toml::node &n, void *obj) {
  Machine &m = *static_cast<Machine *>(obj);
  OffsetsIn o;
  readTable(c, n, "[offsets]", kOffsetKeys, o);
  m.workOffsets = {o.g54, o.g55, o.g56, o.g57, o.g58, o.g59, o.g59_1, o.g59_2, o.g59_3};
  // G54 P1-P3 are the slots of G59.1-G59.3: one machine file gives each slot once.
  for (size_t i = 0; i < o.g54p.size(); ++i) {
    AxisVec &slot = m.workOffsets[6 + i];
    if (i < 3 && slot != AxisVec{} && o.g54p[i] != slot)
      c.error(n.source(), "[offsets]: g54p[" + std::to_string(i) + "] (G54 P" + std::to_string(i + 1) +
                              ") and \"g59." + std::to_string(i + 1) + "\" are one offset: give it once");
    slot = o.g54p[i];
  }
  m.home1 = o.home1;
  m.home2 = o.home2;
  m.chanBaseFrames = o.base, m.ncBaseFrames = o.ncBase;
  m.settableFrames = o.settable;
}

struct EdgeIn : ToolEdge {
  int d = -1;
};

const KeyDef<EdgeIn> kEdgeKeys[] = {
    {"d", &EdgeIn::d, 1, 99999, false, nullptr, true},
    {"length", &EdgeIn::length},
    {"radius", &EdgeIn::radius, 0},
    {"length_wear", &EdgeIn::lengthWear},
    {"radius_wear", &EdgeIn::radiusWear},
    {"x_offset", &EdgeIn::xOffset},
    {"x_wear", &EdgeIn::xWear},
    {"tip", &EdgeIn::tip, 0, 9},
    {"type", &EdgeIn::type, 0, 9999},
    {"length2", &EdgeIn::length2},
    {"length3", &EdgeIn::length3},
    {"length2_wear", &EdgeIn::length2Wear},
    {"length3_wear", &EdgeIn::length3Wear},
    {"base1", &EdgeIn::base1},
    {"base2", &EdgeIn::base2},
    {"base3", &EdgeIn::base3},
};

struct ToolIn : Tool {
  int number = -1;
};

void readEdges(Ctx &c, const toml::node &n, void *obj) {
  Tool &tool = *static_cast<ToolIn *>(obj);
  const toml::array *a = n.as_array();
  if (!a || a->empty())
    return c.error(n.source(), "edges: expected a non-empty array of tables {d = 1, length = ..., radius = ...}");
  for (const toml::node &e : *a) {
    EdgeIn in;
    if (!readTable(c, e, "edge", kEdgeKeys, in)) continue;
    if (tool.edges.count(in.d)) c.error(e.source(), "edge d = " + std::to_string(in.d) + " appears twice");
    tool.edges[in.d] = in;
  }
}

const KeyDef<ToolIn> kToolKeys[] = {
    {"number", &ToolIn::number, 0, 99999, false, nullptr, true},
    {"name", &ToolIn::name},
    {"teeth", &ToolIn::teeth, 0, 999},
    {"edges", NodeReader(readEdges), 0, 0, false, nullptr, true},
    {"plunge_angle", &ToolIn::plungeAngle, 0, 90},  // TOOL.T ANGLE
    {"point_angle", &ToolIn::pointAngle, 0, 180},   // TOOL.T T-ANGLE
    {"cutting_length", &ToolIn::cuttingLength, 0},  // TOOL.T LCUTS
    {"width", &ToolIn::width, 0},                   // a grooving insert's width (CYCLE930)
};

void readTools(Ctx &c, const toml::node &n, void *obj) {
  Machine &m = *static_cast<Machine *>(obj);
  const toml::array *a = n.as_array();
  if (!a) return c.error(n.source(), "tools: expected an array of tables [[tools]], got " + typeName(n));
  for (const toml::node &e : *a) {
    ToolIn in;
    if (!readTable(c, e, "[[tools]]", kToolKeys, in)) continue;
    std::string tn = "tool " + std::to_string(in.number);
    if (m.toolTable.count(in.number)) {
      c.error(e.source(), tn + " appears twice");
      continue;
    }
    // T, H and D numbers name a tool and use its edge 1, or its only edge.
    auto edge = in.edges.count(1) ? in.edges.find(1) : in.edges.size() == 1 ? in.edges.begin() : in.edges.end();
    if (edge == in.edges.end()) {
      c.error(e.source(), tn + " has several edges but no d = 1 (the edge T, H and D numbers use)");
      continue;
    }
    const ToolEdge &g = edge->second;
    m.tools[in.number] = ToolData{g.length + g.lengthWear, g.radius + g.radiusWear, g.xOffset + g.xWear, g.tip};
    if (m.tools[in.number].radius < 0) c.error(e.source(), tn + ": radius + radius_wear is negative");
    m.toolTable[in.number] = in;
  }
}

// [emit.iso], [emit.sinumerik]: kept as text for the emitters (nested tables become dotted keys).
void flattenEmit(Ctx &c, const toml::table &t, const std::string &prefix, std::map<std::string, std::string> &out,
                 std::map<std::string, std::pair<uint32_t, uint32_t>> &positions) {
  for (auto &&[k, v] : t) {
    std::string key = prefix + std::string(k.str());
    positions[key] = {v.source().begin.line, v.source().begin.column};
    if (auto *sub = v.as_table()) flattenEmit(c, *sub, key + ".", out, positions);
    else if (auto *s = v.as_string()) out[key] = **s;
    else if (auto *b = v.as_boolean()) out[key] = **b ? "true" : "false";
    else if (auto *i = v.as_integer()) out[key] = std::to_string(**i);
    else if (auto *f = v.as_floating_point()) out[key] = num(**f);
    else c.error(v.source(), key + ": expected a string, number or boolean, got " + typeName(v));
  }
}

void readEmit(Ctx &c, const toml::node &n, void *obj) {
  Machine &m = *static_cast<Machine *>(obj);
  forEachNamed(c, n, "emit", [&](const std::string &name, const toml::key &k, const toml::node &v) {
    if (name != "iso" && name != "sinumerik" && name != "heidenhain" && name != "nc200")
      return c.error(k.source(), "unknown emitter '" + name + "' in [emit] (iso, sinumerik, heidenhain, nc200)");
    if (!v.is_table()) return c.error(v.source(), "emit." + name + ": expected a table, got " + typeName(v));
    flattenEmit(c, *v.as_table(), "", m.sections["emit." + name], m.sectionPositions["emit." + name]);
  });
}

// [transform] (docs/MACHINE.md "[transform]"): the kinematic transformations' data (TRANSMIT,
// TRACYL, ISO G12.1/G07.1), kept as text like [emit.*] and read by runtime/ExecutorTransform.cpp:
// rotary_axis (the spindle's rotary axis, default "C") and tolerance (the chordal tolerance, mm).
void readTransform(Ctx &c, const toml::node &n, void *obj) {
  Machine &m = *static_cast<Machine *>(obj);
  const toml::table *t = n.as_table();
  if (!t) return c.error(n.source(), "transform: expected a table, got " + typeName(n));
  for (auto &&[k, v] : *t) {
    std::string key(k.str());
    if (key == "rotary_axis") {
      auto *sv = v.as_string();
      if (!sv || (**sv != "A" && **sv != "B" && **sv != "C"))
        c.error(v.source(), "transform.rotary_axis: expected \"A\", \"B\" or \"C\"");
    } else if (key == "tolerance") {
      double d = v.is_integer() ? (double)**v.as_integer() : v.is_floating_point() ? **v.as_floating_point() : -1;
      if (!(d > 0 && d <= 1)) c.error(v.source(), "transform.tolerance: expected a number of mm in (0, 1]");
    } else {
      c.error(k.source(), "unknown key '" + key + "' in [transform] (rotary_axis, tolerance)");
    }
  }
  flattenEmit(c, *t, "", m.sections["transform"], m.sectionPositions["transform"]);
}

// ---- kinematics (docs/MACHINE.md "Kinematics") ---------------------------------------------

constexpr const char *kChainTypes = "xyz table-table head-table head-head";

struct JointIn : RotaryJoint {
  std::string axisName;
};

const KeyDef<JointIn> kJointKeys[] = {
    {"axis", &JointIn::axisName, 0, 0, false, nullptr, true},
    {"on", NodeReader([](Ctx &c, const toml::node &n, void *j) {
       if (auto s = readString(c, n, "on", "table head")) static_cast<JointIn *>(j)->onHead = *s == "head";
     }),
     0, 0, false, nullptr, true},
    {"direction", NodeReader([](Ctx &c, const toml::node &n, void *j) {
       readUnitVec(c, n, "direction", static_cast<JointIn *>(j)->direction);
     }),
     0, 0, false, nullptr, true},
    {"center", &JointIn::center},
};

struct ChainIn : KinematicChain {
  std::string type;
};

void readJoints(Ctx &c, const toml::node &n, void *obj) {
  auto &joints = static_cast<ChainIn *>(obj)->joints;
  const toml::array *a = n.as_array();
  if (!a) return c.error(n.source(), "joints: expected an array of tables [[kinematics.joints]], got " + typeName(n));
  for (const toml::node &e : *a) {
    JointIn in;
    bool ok = readTable(c, e, "[[kinematics.joints]]", kJointKeys, in);
    if (in.axisName.empty()) continue;  // reported (missing, or not a string)
    const char *p = in.axisName.size() == 1 ? std::strchr(kAxisNames, in.axisName[0]) : nullptr;
    if (!p || !*p)
      c.error(e.as_table()->get("axis")->source(), "axis: '" + in.axisName + "' is not one of X, Y, Z, A, B, C, U, V, W");
    else if (ok)
      in.axis = int(p - kAxisNames), joints.push_back(in);
  }
}

const KeyDef<ChainIn> kChainKeys[] = {
    {"type", &ChainIn::type, 0, 0, false, kChainTypes, true},
    {"tool_axis", NodeReader([](Ctx &c, const toml::node &n, void *k) {
       readUnitVec(c, n, "tool_axis", static_cast<ChainIn *>(k)->toolAxis);
     })},
    {"prefer", &ChainIn::prefer, 0, 0, false, "nearest positive negative"},
    {"joints", NodeReader(readJoints)},
};

// `kinematics = "xyz"`, or a [kinematics] table with the chain's type and joints.
void readKinematics(Ctx &c, const toml::node &n, void *obj) {
  Machine &m = *static_cast<Machine *>(obj);
  if (n.is_string()) {
    auto s = readString(c, n, "kinematics", kChainTypes);
    if (s && *s != "xyz")
      return c.error(n.source(), "kinematics: \"" + *s + "\" needs its data: write a [kinematics] table with type = \"" +
                                     *s + "\" and its [[kinematics.joints]]");
    return;
  }
  ChainIn in;
  if (!n.is_table()) return c.error(n.source(), "kinematics: expected a string or a table, got " + typeName(n));
  if (!readTable(c, n, "[kinematics]", kChainKeys, in)) return;
  m.kinematics = in.type;
  m.chain = in;
}

bool parallel(const Vec3 &u, const Vec3 &v) {
  Vec3 w = cross(u, v);
  return std::sqrt(dot(w, w)) < 1e-6;
}

// The chain against the axes: two joints of the type's sides, rotary axes the file describes, a
// geometry that can orient the tool (docs/MACHINE.md "Kinematics").
void chainChecks(Ctx &c, const toml::table &doc, const Machine &m) {
  auto kin = doc["kinematics"];
  const auto &joints = m.chain.joints;
  if (!kin.is_table()) return;
  const toml::source_region &header = kin.node()->source();
  const std::string what = "[kinematics]: type \"" + m.kinematics + "\" ";
  if (m.kinematics == "xyz") {
    if (!joints.empty()) c.error(header, what + "has no joints");
    return;
  }
  if (joints.size() != 2)
    return c.error(header, what + "needs 2 joints ([[kinematics.joints]]), got " + std::to_string(joints.size()));
  int heads = (int)std::count_if(joints.begin(), joints.end(), [](auto &j) { return j.onHead; });
  int want = m.kinematics == "head-head" ? 2 : m.kinematics == "head-table" ? 1 : 0;
  static const char *const kSides[] = {"two table joints", "one head and one table joint", "two head joints"};
  if (heads != want) return c.error(header, what + "needs " + kSides[want] + ", got " + kSides[heads]);
  size_t before = c.problems.size();
  for (size_t i = 0; i < joints.size(); ++i) {
    const std::string name(1, kAxisNames[joints[i].axis]);
    const toml::source_region &at = kin["joints"][i]["axis"].node()->source();
    const AxisLimits &a = m.axes[joints[i].axis];
    if (i == 1 && joints[0].axis == joints[1].axis) c.error(at, "joint " + name + " appears twice");
    else if (!a.present) c.error(at, "joint " + name + ": no [axes." + name + "] describes it");
    else if (!a.rotary) c.error(at, "joint " + name + ": axis " + name + " is linear (joints are rotary axes)");
  }
  if (c.problems.size() != before) return;
  auto jointName = [&](int i) { return std::string(1, kAxisNames[joints[i].axis]); };
  if (parallel(joints[0].direction, joints[1].direction))
    return c.error(kin["joints"][1]["direction"].node()->source(),
                   "joints " + jointName(0) + " and " + jointName(1) +
                       " turn about parallel directions: the chain cannot orient the tool axis");
  int tilt = m.chain.tiltJoint();
  if (parallel(joints[tilt].direction, m.chain.toolAxis))
    c.error(kin["joints"][tilt]["direction"].node()->source(),
            "joint " + jointName(tilt) +
                " turns about the tool axis, so it cannot tilt the tool (the joint next to the tool, the outer head "
                "joint or else the first table joint, must not be parallel to tool_axis)");
}

void readSchema(Ctx &c, const toml::node &n, void *) {
  if (n.value_exact<int64_t>() != 1)
    c.error(n.source(), "schema: this ncc reads machine descriptions of schema 1 (write schema = 1)");
}

// A lathe (`kind = "lathe"`): turning G codes of systems A, B and C, X and Z axes; feed per
// revolution unless the start-up list names a feed mode, as Fanuc-style lathes start.
void latheChecks(Ctx &c, const toml::table &doc, Machine &m) {
  if (!m.axes[0].present || !m.axes[2].present) c.error({}, "a lathe (kind = \"lathe\") needs [axes.X] and [axes.Z]");
  auto &st = m.controller.startup;
  if (std::none_of(st.begin(), st.end(), [](ModeValue v) { return modeValueInfo(v).group == ModeGroup::FeedMode; }))
    st.push_back(ModeValue::PerRev);
}

const KeyDef<Machine> kTopKeys[] = {
    {"schema", NodeReader(readSchema)},
    {"kinematics", NodeReader(readKinematics)},
    {"machine", NodeReader([](Ctx &c, const toml::node &n, void *m) {
       readTable(c, n, "[machine]", kMachineKeys, *static_cast<Machine *>(m));
     })},
    {"controller", NodeReader([](Ctx &c, const toml::node &n, void *m) {
       readTable(c, n, "[controller]", kControllerKeys, static_cast<Machine *>(m)->controller);
     })},
    {"axes", NodeReader(readAxes)},
    {"offsets", NodeReader(readOffsets)},
    {"tools", NodeReader(readTools)},
    {"emit", NodeReader(readEmit)},
    {"transform", NodeReader(readTransform)},
};

}  // namespace

std::string Machine::get(const std::string &section, const std::string &key, const std::string &def) const {
  auto s = sections.find(section);
  if (s == sections.end()) return def;
  auto k = s->second.find(key);
  return k == s->second.end() ? def : k->second;
}

bool Machine::parse(const std::string &text, const std::string &name, Machine &out,
                    std::vector<MachineError> &errors) {
  Machine m;
  Ctx c;
  toml::table doc;
  try {
    doc = toml::parse(text, name);
  } catch (const toml::parse_error &e) {
    c.error(e.source(), std::string(e.description()));
  }
  if (c.problems.empty() && !doc.contains("schema"))
    c.error({}, "missing 'schema = 1' (the version of the machine description format)");
  if (c.problems.empty() && readTable(c, doc, "the top level", kTopKeys, m)) {
    // Whole-machine checks, reported at the start of the file.
    if (!m.axes[0].present && !m.axes[1].present && !m.axes[2].present)
      c.error({}, "no linear axis (need at least one of [axes.X] [axes.Y] [axes.Z])");
    // X Y Z are the Cartesian position of the tool (xyz) or of the spindle (rotary chains).
    for (int i = 0; i < 3; ++i)
      if (m.axes[i].present && m.axes[i].rotary)
        c.error(doc["axes"][std::string(1, kAxisNames[i])].node()->source(),
                std::string("axis ") + kAxisNames[i] + ": kinematics \"" + m.kinematics + "\" needs it linear");
    chainChecks(c, doc, m);
    // ISO lathes read U V W as the incremental X Y Z.
    for (int i = kBaseAxes; i < kAxes; ++i)
      if (m.axes[i].present && m.controller.lathe())
        c.error(doc["axes"][std::string(1, kAxisNames[i])].node()->source(),
                std::string("axis ") + kAxisNames[i] + ": a lathe reads U V W as the incremental X Y Z, it cannot have the axis");
    // One name per axis: a name may not repeat, nor be the letter of another described axis.
    for (int i = 0; i < kAxes; ++i)
      for (int j = 0; j < i && m.axes[i].present; ++j)
        if (m.axes[j].present && m.axisName(i) == m.axisName(j))
          c.error(doc["axes"][std::string(1, kAxisNames[i])]["name"].node()
                      ? doc["axes"][std::string(1, kAxisNames[i])]["name"].node()->source()
                      : doc["axes"][std::string(1, kAxisNames[i])].node()->source(),
                  "axis " + std::string(1, kAxisNames[i]) + ": the name '" + m.axisName(i) + "' is already axis " +
                      std::string(1, kAxisNames[j]) + "'s");
    // Every offset number names an edge of the tool table.
    for (auto &[number, edge] : m.controller.offsetNumbers) {
      auto tool = m.toolTable.find(edge.first);
      if (tool == m.toolTable.end() || !tool->second.edges.count(edge.second))
        c.error(doc["controller"]["offset_numbers"][std::to_string(number)].node()->source(),
                "offset_numbers." + std::to_string(number) + ": tool " + std::to_string(edge.first) +
                    (tool == m.toolTable.end() ? " is not in [[tools]]" : " has no edge d = " + std::to_string(edge.second)));
    }
    if (m.controller.lathe()) latheChecks(c, doc, m);
    // Stored base frames beyond the configured number (base_frames, nc_base_frames).
    for (auto [key, list, count] : {std::tuple{"base", &m.chanBaseFrames, m.controller.baseFrames},
                                    std::tuple{"nc_base", &m.ncBaseFrames, m.controller.ncBaseFrames}})
      for (int i = count; i < 8; ++i)
        if ((*list)[i] != AxisVec{})
          c.error(doc["offsets"][key].node()->source(), std::string("offsets.") + key + "[" + std::to_string(i) +
                                                            "]: the machine has " + std::to_string(count) + " such base frames (" +
                                                            (key[0] == 'b' ? "base_frames" : "nc_base_frames") + ")");
    // Settable frames beyond the configured number (settable_frames, MD28080).
    for (auto &[n, offsets] : m.settableFrames)
      if (n >= m.controller.settableFrames)
        c.error(doc["offsets"]["settable"]["g" + std::to_string(500 + n)].node()->source(),
                "offsets.settable.g" + std::to_string(500 + n) + ": the machine has " +
                    std::to_string(m.controller.settableFrames) + " settable frames $P_UIFR[0…" +
                    std::to_string(m.controller.settableFrames - 1) + "] (settable_frames)");
  }
  errors = std::move(c.problems);
  std::stable_sort(errors.begin(), errors.end(),
                   [](auto &a, auto &b) { return std::tie(a.line, a.col) < std::tie(b.line, b.col); });
  if (!errors.empty()) return false;
  out = std::move(m);
  return true;
}

bool Machine::load(const std::string &nameOrPath, Machine &out, std::vector<MachineError> &errors) {
  if (nameOrPath == "default" || nameOrPath == "default-mill") {
    out = builtinDefault();
    return true;
  }
  std::ifstream f(nameOrPath, std::ios::binary);
  if (!f) {
    errors = {{0, 0, std::string("cannot read machine description: ") + std::strerror(errno)}};
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  return parse(ss.str(), nameOrPath, out, errors);
}

namespace {
std::string errorText(const std::string &name, const std::vector<MachineError> &errors) {
  std::string err;
  for (auto &e : errors) {
    err += (err.empty() ? "" : "\n") + name;
    if (e.line) err += ":" + std::to_string(e.line) + ":" + std::to_string(e.col);
    err += ": error: " + e.message;
  }
  return err;
}
}  // namespace

bool Machine::parse(const std::string &text, const std::string &name, Machine &out, std::string &err) {
  std::vector<MachineError> errors;
  if (parse(text, name, out, errors)) return true;
  err = errorText(name, errors);
  return false;
}

bool Machine::load(const std::string &nameOrPath, Machine &out, std::string &err) {
  std::vector<MachineError> errors;
  if (load(nameOrPath, out, errors)) return true;
  err = errorText(nameOrPath, errors);
  return false;
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

OffsetWrite Controller::offsetWritePolicy() const {
  const std::string &k = offsetWrite.empty() ? family : offsetWrite;
  if (k == "on-change" || k == "linuxcnc") return OffsetWrite::OnChange;
  if (k == "on-select" || k == "sinumerik" || k == "heidenhain") return OffsetWrite::OnSelect;
  return OffsetWrite::Immediate;
}

int KinematicChain::tiltJoint() const {
  for (int i = (int)joints.size() - 1; i >= 0; --i)
    if (joints[i].onHead) return i;
  return 0;
}

void Machine::addTool(int n, const ToolEdge &edge) {
  toolTable[n].edges[1] = edge;
  tools[n] = ToolData{edge.length + edge.lengthWear, edge.radius + edge.radiusWear};
}

std::string Machine::axisName(int i) const {
  return axes[i].name.empty() ? std::string(1, kAxisLetters[i]) : axes[i].name;
}

int Machine::axisByName(std::string_view name) const {
  for (int i = 0; i < kAxes; ++i)
    if (axes[i].present && axisName(i) == name) return i;
  return -1;
}

const ToolData *Machine::findTool(int n) const {
  static const ToolData kNone{};
  if (auto it = tools.find(n); it != tools.end()) return &it->second;
  // A machine without a tool table restricts nothing.
  return n == 0 || tools.empty() || (n > 0 && n <= freeTools) ? &kNone : nullptr;
}

std::string workOffsetCode(int n, OffsetCodes codes) {
  if (codes == OffsetCodes::Sinumerik)
    return n < 0 || n > Machine::kWorkOffsets ? "" : n == 0 ? "G500" : n < 5 ? fmt::format("G5{}", 3 + n) : fmt::format("G5{:02d}", n);
  if (n >= 1 && n <= 6) return fmt::format("G5{}", 3 + n);
  if (codes == OffsetCodes::LinuxCnc) return n >= 7 && n <= 9 ? fmt::format("G59.{}", n - 6) : "";
  return n >= 7 && n <= Machine::kWorkOffsets ? fmt::format("G54 P{}", n - 6) : "";
}

}  // namespace ncc
