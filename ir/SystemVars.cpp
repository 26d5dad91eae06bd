#include "ir/SystemVars.h"

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
    "_cutter_d"};
static_assert(sizeof(kNames) / sizeof(kNames[0]) == (size_t)SysVar::Count);

namespace {
constexpr int kWorkOffsetIds = 9 * 7;
constexpr const char *kAxisNames[] = {"x", "y", "z", "a", "b", "c", "r"};
// Family prefixes after the work offsets, in SysFamily order from G92 on.
constexpr const char *kFamilyPrefix[] = {"_g92_", "_home1_", "_home2_", "_abs_", "_tool_offset_"};

// Every id's name, built once: the named ones, then the families.
const std::vector<std::string> &allNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n(kNames, kNames + (size_t)SysVar::Count);
    for (int s = 1; s <= 9; ++s)
      for (int a = 0; a < 7; ++a) n.push_back("_work_offset" + std::to_string(s) + "_" + kAxisNames[a]);
    for (const char *p : kFamilyPrefix)
      for (int a = 0; a < 6; ++a) n.push_back(std::string(p) + kAxisNames[a]);
    return n;
  }();
  return names;
}
}  // namespace

bool sysVarFromName(std::string_view name, SysVar &out) {
  const auto &names = allNames();
  for (size_t i = 0; i < names.size(); ++i)
    if (name == names[i]) {
      out = (SysVar)i;
      return true;
    }
  return false;
}

const char *sysVarName(SysVar v) { return allNames()[(size_t)v].c_str(); }

SysVarInfo sysVarInfo(SysVar v) {
  int id = (int)v - (int)SysVar::Count;
  if (id < 0 || id >= kSysVarIds - (int)SysVar::Count) return {};
  if (id < kWorkOffsetIds) return {SysFamily::WorkOffset, id / 7 + 1, id % 7};
  id -= kWorkOffsetIds;
  return {(SysFamily)((int)SysFamily::G92 + id / 6), 0, id % 6};
}

SysVar sysVarOf(SysFamily f, int system, int axis) {
  int base = (int)SysVar::Count;
  if (f == SysFamily::WorkOffset && system >= 1 && system <= 9 && axis >= 0 && axis < 7)
    return (SysVar)(base + (system - 1) * 7 + axis);
  if (f >= SysFamily::G92 && f <= SysFamily::ToolOffset && axis >= 0 && axis < 6)
    return (SysVar)(base + kWorkOffsetIds + ((int)f - (int)SysFamily::G92) * 6 + axis);
  return SysVar::Count;
}

}  // namespace ncc
