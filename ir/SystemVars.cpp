#include "ir/SystemVars.h"

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
    "_remap_level", "_task"};
static_assert(sizeof(kNames) / sizeof(kNames[0]) == (size_t)SysVar::Count);

bool sysVarFromName(std::string_view name, SysVar &out) {
  for (size_t i = 0; i < (size_t)SysVar::Count; ++i)
    if (name == kNames[i]) {
      out = (SysVar)i;
      return true;
    }
  return false;
}

const char *sysVarName(SysVar v) { return kNames[(size_t)v]; }

}  // namespace ncc
