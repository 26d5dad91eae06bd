#include "ir/ModeTable.h"
#include "ir/MachineCmd.h"

namespace ncc {

static const char *kGroupNames[] = {"motion", "plane", "units", "distance", "arc_distance",
                                    "feed_mode", "retract", "path_mode", "spline_start", "spline_end", "stop_once",
                                    "wear_system"};
static_assert(sizeof(kGroupNames) / sizeof(kGroupNames[0]) == (size_t)ModeGroup::Count);

static const ModeValueInfo kValues[] = {
    {ModeValue::Rapid, ModeGroup::Motion, "rapid"},
    {ModeValue::Linear, ModeGroup::Motion, "linear"},
    {ModeValue::ArcCW, ModeGroup::Motion, "arc_cw"},
    {ModeValue::ArcCCW, ModeGroup::Motion, "arc_ccw"},
    {ModeValue::ArcThrough, ModeGroup::Motion, "arc_through"},
    {ModeValue::ArcTangent, ModeGroup::Motion, "arc_tangent"},
    {ModeValue::CycleOff, ModeGroup::Motion, "cycle_off"},
    {ModeValue::Drill, ModeGroup::Motion, "drill"},
    {ModeValue::DrillDwell, ModeGroup::Motion, "drill_dwell"},
    {ModeValue::Peck, ModeGroup::Motion, "peck"},
    {ModeValue::PeckChipBreak, ModeGroup::Motion, "peck_chipbreak"},
    {ModeValue::Tap, ModeGroup::Motion, "tap"},
    {ModeValue::TapLeft, ModeGroup::Motion, "tap_left"},
    {ModeValue::BoreFeed, ModeGroup::Motion, "bore_feed"},
    {ModeValue::BoreStop, ModeGroup::Motion, "bore_stop"},
    {ModeValue::BoreDwell, ModeGroup::Motion, "bore_dwell"},
    {ModeValue::BoreBack, ModeGroup::Motion, "bore_back"},
    {ModeValue::BoreFine, ModeGroup::Motion, "bore_fine"},
    {ModeValue::CycleCancel, ModeGroup::Motion, "cycle_cancel"},
    {ModeValue::SplineCubic, ModeGroup::Motion, "spline_cubic"},
    {ModeValue::SplineQuadratic, ModeGroup::Motion, "spline_quadratic"},
    {ModeValue::Nurbs, ModeGroup::Motion, "nurbs"},
    {ModeValue::NurbsEnd, ModeGroup::Motion, "nurbs_end"},
    {ModeValue::TurnAlongZ, ModeGroup::Motion, "turn_z"},
    {ModeValue::TurnAlongX, ModeGroup::Motion, "turn_x"},
    {ModeValue::Thread, ModeGroup::Motion, "thread"},
    {ModeValue::RigidTap, ModeGroup::Motion, "rigid_tap"},
    {ModeValue::ThreadCycle, ModeGroup::Motion, "thread_cycle"},
    {ModeValue::ThreadSingle, ModeGroup::Motion, "thread_single"},
    {ModeValue::ThreadMulti, ModeGroup::Motion, "thread_multi"},
    {ModeValue::ThreadVariable, ModeGroup::Motion, "thread_variable"},
    {ModeValue::ThreadLead, ModeGroup::Motion, "thread_lead"},
    {ModeValue::TapIn, ModeGroup::Motion, "tap_in"},
    {ModeValue::TapOut, ModeGroup::Motion, "tap_out"},
    {ModeValue::PeckAlongZ, ModeGroup::Motion, "peck_z"},
    {ModeValue::PeckAlongX, ModeGroup::Motion, "peck_x"},
    {ModeValue::ProbeToward, ModeGroup::Motion, "probe_toward"},
    {ModeValue::ProbeTowardNoError, ModeGroup::Motion, "probe_toward_no_error"},
    {ModeValue::ProbeAway, ModeGroup::Motion, "probe_away"},
    {ModeValue::ProbeAwayNoError, ModeGroup::Motion, "probe_away_no_error"},
    {ModeValue::Skip, ModeGroup::Motion, "skip"},
    {ModeValue::SplineAkima, ModeGroup::Motion, "spline_akima"},
    {ModeValue::SplineB, ModeGroup::Motion, "spline_b"},
    {ModeValue::SplineC, ModeGroup::Motion, "spline_c"},
    {ModeValue::Poly, ModeGroup::Motion, "poly"},
    {ModeValue::XY, ModeGroup::Plane, "xy"},
    {ModeValue::ZX, ModeGroup::Plane, "zx"},
    {ModeValue::YZ, ModeGroup::Plane, "yz"},
    {ModeValue::MM, ModeGroup::Units, "mm"},
    {ModeValue::Inch, ModeGroup::Units, "inch"},
    {ModeValue::Absolute, ModeGroup::Distance, "absolute"},
    {ModeValue::Incremental, ModeGroup::Distance, "incremental"},
    {ModeValue::ArcAbsolute, ModeGroup::ArcDistance, "arc_absolute"},
    {ModeValue::ArcIncremental, ModeGroup::ArcDistance, "arc_incremental"},
    {ModeValue::PerMinute, ModeGroup::FeedMode, "per_minute"},
    {ModeValue::PerRev, ModeGroup::FeedMode, "per_rev"},
    {ModeValue::InverseTime, ModeGroup::FeedMode, "inverse_time"},
    {ModeValue::RetractInitial, ModeGroup::Retract, "retract_initial"},
    {ModeValue::RetractR, ModeGroup::Retract, "retract_r"},
    {ModeValue::ExactPath, ModeGroup::PathMode, "exact_path"},
    {ModeValue::ExactStop, ModeGroup::PathMode, "exact_stop"},
    {ModeValue::Continuous, ModeGroup::PathMode, "continuous"},
    {ModeValue::StartNatural, ModeGroup::SplineStart, "start_natural"},
    {ModeValue::StartAuto, ModeGroup::SplineStart, "start_auto"},
    {ModeValue::StartTangent, ModeGroup::SplineStart, "start_tangent"},
    {ModeValue::EndNatural, ModeGroup::SplineEnd, "end_natural"},
    {ModeValue::EndAuto, ModeGroup::SplineEnd, "end_auto"},
    {ModeValue::EndTangent, ModeGroup::SplineEnd, "end_tangent"},
    {ModeValue::ExactStopOnce, ModeGroup::StopOnce, "exact_stop_once"},
    {ModeValue::WearMachine, ModeGroup::WearSystem, "wear_machine"},
    {ModeValue::WearWork, ModeGroup::WearSystem, "wear_work"},
};
static_assert(sizeof(kValues) / sizeof(kValues[0]) == (size_t)ModeValue::Count);

const char *modeGroupName(ModeGroup g) { return kGroupNames[(unsigned)g]; }

bool modeGroupFromName(std::string_view s, ModeGroup &out) {
  for (unsigned i = 0; i < (unsigned)ModeGroup::Count; ++i)
    if (s == kGroupNames[i]) {
      out = (ModeGroup)i;
      return true;
    }
  return false;
}

const ModeValueInfo &modeValueInfo(ModeValue v) { return kValues[(unsigned)v]; }

bool modeValueFromName(std::string_view s, ModeValue &out) {
  for (auto &i : kValues)
    if (s == i.name) {
      out = i.value;
      return true;
    }
  return false;
}

// Letter -> word slot, built once from the words' letters (on the hot path of every move).
static const struct LetterTable {
  int8_t slot[26];
  LetterTable() {
    for (auto &s : slot) s = -1;
    for (int i = 0; i < kWords; ++i)
      if (char l = wordLetter((Word)i); l >= 'A' && l <= 'Z') slot[l - 'A'] = (int8_t)i;
  }
} kLetters;

bool wordFromLetter(char c, Word &out) {
  if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
  if (c < 'A' || c > 'Z' || kLetters.slot[c - 'A'] < 0) return false;
  out = (Word)kLetters.slot[c - 'A'];
  return true;
}

bool wordFromKey(std::string_view key, Word &out) {
  if (key.size() == 1) return wordFromLetter(key[0], out);
  for (int i = 0; i < kWords; ++i)
    if (key == kWordKeys[i]) return out = (Word)i, true;
  return false;
}

}  // namespace ncc
