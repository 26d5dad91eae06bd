#include "ir/SystemVars.h"
#include "ir/Value.h"

#include <fmt/format.h>

#include <iterator>
#include <string>
#include <vector>

namespace ncc {

// In SysVar order.
static const char *const kNames[] = {
    "_vmajor", "_vminor", "_line", "_motion_mode", "_plane", "_ccomp", "_metric", "_imperial",
    "_absolute", "_incremental", "_inverse_time", "_units_per_minute", "_units_per_rev",
    "_coord_system", "_tool_offset", "_retract_r_plane", "_retract_old_z", "_spindle_rpm_mode",
    "_spindle_css_mode", "_ijk_absolute_mode", "_lathe_diameter_mode", "_lathe_radius_mode",
    "_spindle_on", "_spindle_cw", "_mist", "_flood", "_speed_override", "_feed_override",
    "_adaptive_feed", "_feed_hold", "_feed", "_rpm", "_x", "_y", "_z", "_a", "_b", "_c", "_u", "_v",
    "_w", "_current_tool", "_current_pocket", "_selected_tool", "_selected_pocket",
    "_remap_level", "_task", "_g92_on", "_coord_system_number", "_tool_diameter", "_tool_length_h",
    "_cutter_d", "_sin_deldl_status", "_probe_x", "_probe_y", "_probe_z", "_probe_a", "_probe_b", "_probe_c", "_probe_u",
    "_probe_v", "_probe_w", "_probe_tripped", "_pframe", "_iframe", "_actframe", "_actbframe", "_chbfrmask",
    "_ncbfrmask", "_partframe", "_setframe", "_extframe", "_iso1frame", "_iso2frame", "_iso3frame", "_gframe",
    "_toolframe", "_wpframe", "_traframe", "_iso4frame", "_cycframe", "_plane_a", "_plane_b", "_plane_c"};
static_assert(sizeof(kNames) / sizeof(kNames[0]) == (size_t)SysVar::Count);

namespace {
constexpr int kWorkOffsetIds = 9 * 7;
constexpr const char *kAxisNames[] = {"x", "y", "z", "a", "b", "c", "r"};
// Family prefixes after the work offsets, in SysFamily order from G92 on.
constexpr const char *kFamilyPrefix[] = {"_g92_", "_home1_", "_home2_", "_abs_", "_tool_offset_"};
// In ToolField order (names in messages; programs index the fields by number).
static_assert(kToolFields == 61, "the range in sysVarIndexMessage");
constexpr const char *kToolFieldNames[] = {"length",       "radius",       "length_wear", "radius_wear", "type",
                                           "cut_pos",      "length2",      "length3",     "length2_wear",
                                           "length3_wear", "base1",        "base2",       "base3"};
static_assert(std::size(kToolFieldNames) == (size_t)kToolSumFields);

// Every id's name, built once: the named ones, then the families.
const std::vector<std::string> &allNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n(kNames, kNames + (size_t)SysVar::Count);
    for (int s = 1; s <= 9; ++s)
      for (int a = 0; a < 7; ++a) n.push_back("_work_offset" + std::to_string(s) + "_" + kAxisNames[a]);
    for (const char *p : kFamilyPrefix)
      for (int a = 0; a < 6; ++a) n.push_back(std::string(p) + kAxisNames[a]);
    for (const char *f : kToolFieldNames) n.push_back(std::string("_tool_data_") + f);
    for (const char *kind : {"scp", "ecp"})  // Sinumerik $TC_SCPxy / $TC_ECPxy
      for (int x = 1; x <= kDlSets; ++x)
        for (int y = 3; y < 3 + kDlParams; ++y) n.push_back(fmt::format("_tool_data_{}{}{}", kind, x, y));
    for (int i = 0; i < kUserFrames; ++i) n.push_back("_uifr[" + std::to_string(i) + "]");
    for (const char *base : {"_chbfr", "_chbframe", "_ncbfr", "_ncbframe"})
      for (int i = 0; i < kBaseFrames; ++i) n.push_back(fmt::format("{}[{}]", base, i));
    n.push_back("_sin_table");
    return n;
  }();
  return names;
}
}  // namespace

bool sysVarFromName(std::string_view name, SysVar &out) {
  const auto &names = allNames();
  for (size_t i = 0; i < (size_t)kToolDataIds; ++i)
    if (name == names[i]) {
      out = (SysVar)i;
      return true;
    }
  return false;
}

const char *sysVarName(SysVar v) { return (size_t)v < allNames().size() ? allNames()[(size_t)v].c_str() : "?"; }

std::string sysRefText(const SysRef &r) {
  SysVarInfo info = sysVarInfo(r.var);
  if (info.family == SysFamily::SinTable) return fmt::format("_sin_table[{}, {}]", r.tool, r.edge);
  if (info.family != SysFamily::ToolData) return sysVarName(r.var);
  return "_tool_data[" + std::to_string(r.tool) + ", " + std::to_string(r.edge) + ", " + std::to_string(info.axis) + "]";
}

SysVarInfo sysVarInfo(SysVar v) {
  int id = (int)v - (int)SysVar::Count;
  if (id < 0 || id >= kSysVarIds - (int)SysVar::Count) return {};
  if (id < kWorkOffsetIds) return {SysFamily::WorkOffset, id / 7 + 1, id % 7};
  if ((int)v == kSinTableId) return {SysFamily::SinTable, 0, 0};
  if ((int)v >= kBaseFrameIds) {
    int b = (int)v - kBaseFrameIds;
    return {(SysFamily)((int)SysFamily::ChBfr + b / kBaseFrames), b % kBaseFrames, 0};
  }
  if ((int)v >= kUserFrameIds) return {SysFamily::UserFrame, (int)v - kUserFrameIds, 0};
  if ((int)v >= kToolDataIds) return {SysFamily::ToolData, 0, (int)v - kToolDataIds};
  id -= kWorkOffsetIds;
  return {(SysFamily)((int)SysFamily::G92 + id / 6), 0, id % 6};
}

SysVar sysVarOf(SysFamily f, int system, int axis) {
  int base = (int)SysVar::Count;
  if (f == SysFamily::WorkOffset && system >= 1 && system <= 9 && axis >= 0 && axis < 7)
    return (SysVar)(base + (system - 1) * 7 + axis);
  if (f >= SysFamily::G92 && f <= SysFamily::ToolOffset && axis >= 0 && axis < 6)
    return (SysVar)(base + kWorkOffsetIds + ((int)f - (int)SysFamily::G92) * 6 + axis);
  if (f == SysFamily::ToolData && axis >= 0 && axis < kToolFields) return (SysVar)(kToolDataIds + axis);
  if (f == SysFamily::UserFrame && system >= 0 && system < kUserFrames) return (SysVar)(kUserFrameIds + system);
  if (f >= SysFamily::ChBfr && f <= SysFamily::NcBframe && system >= 0 && system < kBaseFrames)
    return (SysVar)(kBaseFrameIds + ((int)f - (int)SysFamily::ChBfr) * kBaseFrames + system);
  if (f == SysFamily::SinTable) return (SysVar)kSinTableId;
  return kNoSysVar;
}

// var + 2^16 (tool + 2^17 edge): below 2^50, so a double holds it exactly.
double sysRefNumber(SysRef r) { return (double)(uint16_t)r.var + 65536.0 * (r.tool + 131072.0 * r.edge); }
SysRef sysRefFromNumber(double n) {
  auto bits = (uint64_t)n;
  return {(SysVar)(bits & 0xffff), (int32_t)((bits >> 16) & 0x1ffff), (int32_t)(bits >> 33)};
}
static_assert(kMaxToolNumber < 131072);

namespace {
// Base names of the indexed families, in SysFamily order from WorkOffset on.
constexpr const char *kFamilyBase[] = {"_work_offset", "_g92", "_home1", "_home2", "_abs", "_tool_offsets", "_tool_data",
                                       "_uifr",         "_chbfr", "_chbframe", "_ncbfr",      "_ncbframe", "_sin_table"};
constexpr int kFamilyDims[] = {2, 1, 1, 1, 1, 1, 3, 1, 1, 1, 1, 1, 2};
static_assert(std::size(kFamilyBase) == (size_t)SysFamily::SinTable && std::size(kFamilyDims) == std::size(kFamilyBase));
bool wholeIn(double x, int lo, int hi) { return x >= lo && x <= hi && x == (double)(int)x; }
}  // namespace

int sysFamilyFromName(std::string_view name, SysFamily &out) {
  for (size_t i = 0; i < std::size(kFamilyBase); ++i)
    if (name == kFamilyBase[i]) {
      out = (SysFamily)(i + 1);
      return kFamilyDims[i];
    }
  return 0;
}

const char *sysFamilyName(SysFamily f) { return f == SysFamily::None ? "" : kFamilyBase[(int)f - 1]; }

SysRef sysVarAt(SysFamily f, double i, double j, double k) {
  switch (f) {
  case SysFamily::WorkOffset: return {wholeIn(i, 1, 9) && wholeIn(j, 0, 6) ? sysVarOf(f, (int)i, (int)j) : kNoSysVar};
  case SysFamily::ToolData:
    if (!wholeIn(i, 1, kMaxToolNumber) || !wholeIn(j, 0, kMaxToolNumber) || !wholeIn(k, 0, kToolFields - 1)) return {};
    return {sysVarOf(f, 0, (int)k), (int32_t)i, (int32_t)j};
  case SysFamily::UserFrame: return {wholeIn(i, 0, kUserFrames - 1) ? sysVarOf(f, (int)i, 0) : kNoSysVar};
  case SysFamily::ChBfr:
  case SysFamily::ChBframe:
  case SysFamily::NcBfr:
  case SysFamily::NcBframe: return {wholeIn(i, 0, kBaseFrames - 1) ? sysVarOf(f, (int)i, 0) : kNoSysVar};
  case SysFamily::SinTable:
    if (!wholeIn(i, 0, kSinTableRows - 1) || !wholeIn(j, 0, kSinTableColumns - 1)) return {};
    return {sysVarOf(f, 0, 0), (int32_t)i, (int32_t)j};
  default: return {wholeIn(i, 0, 5) ? sysVarOf(f, 0, (int)i) : kNoSysVar};
  }
}

std::string sysVarIndexMessage(std::string_view name, SysFamily f, double i, double j, double k) {
  int dims = f == SysFamily::None ? 0 : kFamilyDims[(int)f - 1];
  std::string idx = numberText(i);
  if (dims > 1) idx += ", " + numberText(j);
  if (dims > 2) idx += ", " + numberText(k);
  const char *range = f == SysFamily::WorkOffset ? "system 1..9, axis 0..6"
                      : f == SysFamily::ToolData  ? "tool 1..99999, edge 0..99999, field 0..60"
                      : f == SysFamily::UserFrame ? "settable frame 0..99"
                      : f == SysFamily::SinTable  ? "row 0..131071, column 0..31"
                      : f >= SysFamily::ChBfr     ? "base frame 0..7"
                                                  : "axis 0..5";
  return "system variable '$" + std::string(name) + "[" + idx + "]': index out of range (" + range + ")";
}

int axisIndex(std::string_view name) {
  static const char kAxes[] = "xyzabc";
  if (name.size() != 1) return -1;
  char c = (char)(name[0] | 0x20);
  for (int i = 0; i < 6; ++i)
    if (kAxes[i] == c) return i;
  return -1;
}

bool sysFamilyWritable(SysFamily f) {
  switch (f) {
  case SysFamily::WorkOffset:
  case SysFamily::G92:
  case SysFamily::Home1:
  case SysFamily::Home2:
  case SysFamily::ToolData:
  case SysFamily::UserFrame:
  case SysFamily::ChBfr:
  case SysFamily::ChBframe:
  case SysFamily::NcBfr:
  case SysFamily::NcBframe: return true;
  default: return false;
  }
}

bool sysVarWritable(SysVar v) {
  return v == SysVar::PFrame || v == SysVar::IFrame || (v >= SysVar::ProbeX && v <= SysVar::ProbeTripped) ||
         (v >= SysVar::ChBfrMask && v <= SysVar::CycFrame) || sysFamilyWritable(sysVarInfo(v).family);
}

bool sysVarIsFrame(SysVar v) {
  return v == SysVar::PFrame || v == SysVar::IFrame || v == SysVar::ActFrame || v == SysVar::ActBFrame ||
         (v >= SysVar::PartFrame && v <= SysVar::CycFrame) || sysFamilyIsFrame(sysVarInfo(v).family);
}

bool sysVarNameIsFrame(std::string_view name) {
  SysFamily f;
  SysVar v;
  if (sysFamilyFromName(name, f)) return sysFamilyIsFrame(f);
  return sysVarFromName(name, v) && sysVarIsFrame(v);
}

}  // namespace ncc
