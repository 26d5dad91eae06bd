#include "frontend/sinumerik/Codes.h"

#include "ir/SystemVars.h"

#include <cctype>
#include <cstring>

namespace ncc::sin {

static const GCode kGCodes[] = {
#include "frontend/sinumerik/GCodeTable.inc"
};

const GCode *gcodeTable(size_t &count) {
  count = sizeof(kGCodes) / sizeof(kGCodes[0]);
  return kGCodes;
}

// What ncc executes; every other code of the table is Default (when it is its group's initial
// setting) or Unsupported.
struct GRow {
  const char *name;
  GAct act;
  ModeValue mode;
  int arg;
};
static const GRow kExecuted[] = {
    {"G0", GAct::Mode, ModeValue::Rapid, 0},
    {"G1", GAct::Mode, ModeValue::Linear, 0},
    {"G2", GAct::Mode, ModeValue::ArcCW, 0},
    {"G3", GAct::Mode, ModeValue::ArcCCW, 0},
    {"CIP", GAct::Mode, ModeValue::ArcThrough, 0},
    {"CT", GAct::Mode, ModeValue::ArcTangent, 0},
    {"ASPLINE", GAct::Mode, ModeValue::SplineAkima, 0},
    {"BSPLINE", GAct::Mode, ModeValue::SplineB, 0},
    {"CSPLINE", GAct::Mode, ModeValue::SplineC, 0},
    {"POLY", GAct::Mode, ModeValue::Poly, 0},
    {"BNAT", GAct::Mode, ModeValue::StartNatural, 0},
    {"BAUTO", GAct::Mode, ModeValue::StartAuto, 0},
    {"BTAN", GAct::Mode, ModeValue::StartTangent, 0},
    {"ENAT", GAct::Mode, ModeValue::EndNatural, 0},
    {"EAUTO", GAct::Mode, ModeValue::EndAuto, 0},
    {"ETAN", GAct::Mode, ModeValue::EndTangent, 0},
    {"G4", GAct::Dwell, ModeValue::Count, 0},
    {"G110", GAct::Pole, ModeValue::Count, 0},
    {"G111", GAct::Pole, ModeValue::Count, 1},
    {"G112", GAct::Pole, ModeValue::Count, 2},
    {"G17", GAct::Mode, ModeValue::XY, 0},
    {"G18", GAct::Mode, ModeValue::ZX, 0},
    {"G19", GAct::Mode, ModeValue::YZ, 0},
    {"G40", GAct::CutterComp, ModeValue::Count, 0},
    {"G41", GAct::CutterComp, ModeValue::Count, 1},
    {"G42", GAct::CutterComp, ModeValue::Count, 2},
    {"G500", GAct::WorkOffset, ModeValue::Count, 0},
    {"G54", GAct::WorkOffset, ModeValue::Count, 1},
    {"G55", GAct::WorkOffset, ModeValue::Count, 2},
    {"G56", GAct::WorkOffset, ModeValue::Count, 3},
    {"G57", GAct::WorkOffset, ModeValue::Count, 4},
    // G505 … G599: settable frames 5 … 99 (findGCode).
    {"G53", GAct::MachineCoord, ModeValue::Count, 0},
    {"G153", GAct::MachineCoord, ModeValue::Count, 0},
    {"SUPA", GAct::MachineCoord, ModeValue::Count, 0},
    {"G9", GAct::Mode, ModeValue::ExactStopOnce, 0},
    // G group 56: without an orientable toolholder or a kinematic transformation every system but
    // the WCS coincides with the MCS (L17314-L17320), so these are one value.
    {"TOWSTD", GAct::Mode, ModeValue::WearMachine, 0},
    {"TOWMCS", GAct::Mode, ModeValue::WearMachine, 0},
    {"TOWBCS", GAct::Mode, ModeValue::WearMachine, 0},
    {"TOWTCS", GAct::Mode, ModeValue::WearMachine, 0},
    {"TOWKCS", GAct::Mode, ModeValue::WearMachine, 0},
    {"TOWWCS", GAct::Mode, ModeValue::WearWork, 0},
    {"G60", GAct::Mode, ModeValue::ExactStop, 0},
    {"G64", GAct::Mode, ModeValue::Continuous, 0},
    {"G70", GAct::Units, ModeValue::Inch, 2},
    {"G71", GAct::Units, ModeValue::MM, 0},
    {"G700", GAct::Units, ModeValue::Inch, 1},
    {"G710", GAct::Units, ModeValue::MM, 0},
    {"G90", GAct::Mode, ModeValue::Absolute, 0},
    {"G91", GAct::Mode, ModeValue::Incremental, 0},
    {"G93", GAct::Mode, ModeValue::InverseTime, 0},
    {"G94", GAct::Mode, ModeValue::PerMinute, 0},
    {"G95", GAct::Mode, ModeValue::PerRev, 0},
    {"G96", GAct::SpindleMode, ModeValue::Count, 0},
    {"G961", GAct::SpindleMode, ModeValue::Count, 1},
    {"G962", GAct::SpindleMode, ModeValue::Count, 2},
    {"G97", GAct::SpindleMode, ModeValue::Count, 3},
    {"G971", GAct::SpindleMode, ModeValue::Count, 4},
    {"G972", GAct::SpindleMode, ModeValue::Count, 5},
    {"G33", GAct::Mode, ModeValue::ThreadLead, 0},
    {"G34", GAct::Mode, ModeValue::ThreadLead, 1},   // the lead grows by F every revolution
    {"G35", GAct::Mode, ModeValue::ThreadLead, -1},  // the lead shrinks by F
    {"G331", GAct::Mode, ModeValue::TapIn, 0},
    {"G332", GAct::Mode, ModeValue::TapOut, 0},
    {"G63", GAct::FloatTap, ModeValue::Count, 0},
    {"G641", GAct::Smoothing, ModeValue::Continuous, 1},
    {"G642", GAct::Smoothing, ModeValue::Continuous, 0},
    {"G643", GAct::Smoothing, ModeValue::Continuous, 0},
    {"G645", GAct::Smoothing, ModeValue::Continuous, 0},
    {"TRANS", GAct::Frame, ModeValue::Count, (int)FrameKind::Trans},
    {"ATRANS", GAct::Frame, ModeValue::Count, (int)FrameKind::Trans},
    {"ROT", GAct::Frame, ModeValue::Count, (int)FrameKind::Rot},
    {"AROT", GAct::Frame, ModeValue::Count, (int)FrameKind::Rot},
    {"SCALE", GAct::Frame, ModeValue::Count, (int)FrameKind::Scale},
    {"ASCALE", GAct::Frame, ModeValue::Count, (int)FrameKind::Scale},
    {"MIRROR", GAct::Frame, ModeValue::Count, (int)FrameKind::Mirror},
    {"AMIRROR", GAct::Frame, ModeValue::Count, (int)FrameKind::Mirror},
    {"ROTS", GAct::Frame, ModeValue::Count, (int)FrameKind::SolidRot},
    {"AROTS", GAct::Frame, ModeValue::Count, (int)FrameKind::SolidRot},
};

const SpindleModeArg &spindleModeArg(int arg) {
  static const SpindleModeArg kArgs[] = {
      {true, ModeValue::PerRev},  {true, ModeValue::PerMinute},  {true, ModeValue::Count},   // G96 G961 G962
      {false, ModeValue::PerRev}, {false, ModeValue::PerMinute}, {false, ModeValue::Count},  // G97 G971 G972
  };
  return kArgs[arg];
}

GInfo findGCode(std::string_view name) {
  GInfo g;
  for (auto &c : kGCodes)
    if (name == c.name) {
      g.code = &c;
      break;
    }
  if (!g.code) return g;
  // G505 … G599 select settable frame 5 … 99 (manual L12358-L12372); whether the machine has it
  // is the executor's question (settable_frames).
  if (name.size() == 4 && name.substr(0, 2) == "G5" && name >= "G505" && name <= "G599") {
    g.act = GAct::WorkOffset, g.mode = ModeValue::Count, g.arg = (name[2] - '0') * 10 + (name[3] - '0');
    return g;
  }
  for (auto &r : kExecuted)
    if (name == r.name) {
      g.act = r.act;
      g.mode = r.mode;
      g.arg = r.arg;
      g.additive = r.act == GAct::Frame && name[0] == 'A';
      return g;
    }
  g.act = g.code->isDefault ? GAct::Default : GAct::Unsupported;
  return g;
}

static const AddrInfo kAddrs[] = {
    {"X", Addr::Axis}, {"Y", Addr::Axis}, {"Z", Addr::Axis}, {"A", Addr::Axis}, {"B", Addr::Axis},
    {"C", Addr::Axis}, {"U", Addr::Axis}, {"V", Addr::Axis}, {"W", Addr::Axis},
    {"I", Addr::Center}, {"J", Addr::Center}, {"K", Addr::Center},
    {"I1", Addr::Via}, {"J1", Addr::Via}, {"K1", Addr::Via},
    {"CR", Addr::Radius}, {"CHF", Addr::Corner}, {"CHR", Addr::Corner}, {"RND", Addr::Corner},
    {"F", Addr::Feed}, {"S", Addr::Speed}, {"T", Addr::Tool}, {"D", Addr::Edge}, {"DL", Addr::Edge}, {"M", Addr::Misc}, {"G", Addr::G},
    {"ADIS", Addr::Smoothing}, {"ADISPOS", Addr::Smoothing}, {"CTOL", Addr::Smoothing},
    {"SF", Addr::StartAngle},          {"LIMS", Addr::SpeedLimit},
    {"AR", Addr::Opening},             {"TURN", Addr::Turns},
    {"AP", Addr::Polar},               {"RP", Addr::Polar},
    {"PW", Addr::SplinePoint},         {"SD", Addr::SplinePoint},
    {"PL", Addr::SplinePoint},
    {"RNDM", Addr::Refused, "modal rounding"},
    {"OFFN", Addr::Refused, "a contour offset"},
    {"OTOL", Addr::Refused, "an orientation tolerance"},
    {"H", Addr::Refused, "an auxiliary function H"},
    {"E", Addr::Refused, "an address without meaning on this machine"},
};

const AddrInfo *findAddress(std::string_view name) {
  for (auto &a : kAddrs)
    if (name == a.name) return &a;
  return nullptr;
}

// The $TC_DP parameters ncc keeps (ir/SystemVars.h ToolField; docs/SINUMERIK.md "Tool offsets"):
// type, cutting edge position, lengths 1-3 with their wear and base dimensions, the radius and its
// wear. The others (DP7-DP11, DP16-DP20, DP24, DP25) shape a tool ncc does not model: errors,
// not zeros. $TC_SCPxy / $TC_ECPxy: findToolSumVar.
static const SysMap kSys[] = {
    {"P_PFRAME", "_pframe", 0},       {"P_IFRAME", "_iframe", 0},       {"P_ACTFRAME", "_actframe", 0},
    {"P_UIFR", "_uifr", 1},           {"AA_IW", "_abs", 1},             {"P_EP", "_abs", 1},
    {"P_TOOLNO", "_current_tool", 0}, {"P_TOOL", "_cutter_d", 0},       {"P_UIFRNUM", "_coord_system_number", 0},
    {"P_F", "_feed", 0},              {"P_S", "_rpm", 0},
    // Base and system frames (docs/SINUMERIK.md "Frame chain").
    {"P_CHBFR", "_chbfr", 1},         {"P_CHBFRAME", "_chbframe", 1},   {"P_NCBFR", "_ncbfr", 1},
    {"P_NCBFRAME", "_ncbframe", 1},   {"P_UBFR", "_chbfr", 0, -1, 0},   {"P_BFRAME", "_chbframe", 0, -1, 0},
    {"P_ACTBFRAME", "_actbframe", 0}, {"P_CHBFRMASK", "_chbfrmask", 0}, {"P_NCBFRMASK", "_ncbfrmask", 0},
    {"P_PARTFRAME", "_partframe", 0}, {"P_SETFRAME", "_setframe", 0},   {"P_EXTFRAME", "_extframe", 0},
    {"P_ISO1FRAME", "_iso1frame", 0}, {"P_ISO2FRAME", "_iso2frame", 0}, {"P_ISO3FRAME", "_iso3frame", 0},
    {"P_GFRAME", "_gframe", 0},       {"P_TOOLFRAME", "_toolframe", 0}, {"P_WPFRAME", "_wpframe", 0},
    {"P_TRAFRAME", "_traframe", 0},   {"P_ISO4FRAME", "_iso4frame", 0}, {"P_CYCFRAME", "_cycframe", 0},
    {"TC_DP1", "_tool_data", 2, (int)ToolField::Type},         {"TC_DP2", "_tool_data", 2, (int)ToolField::CutPos},
    {"TC_DP3", "_tool_data", 2, (int)ToolField::Length},       {"TC_DP4", "_tool_data", 2, (int)ToolField::Length2},
    {"TC_DP5", "_tool_data", 2, (int)ToolField::Length3},      {"TC_DP6", "_tool_data", 2, (int)ToolField::Radius},
    {"TC_DP12", "_tool_data", 2, (int)ToolField::LengthWear},  {"TC_DP13", "_tool_data", 2, (int)ToolField::Length2Wear},
    {"TC_DP14", "_tool_data", 2, (int)ToolField::Length3Wear}, {"TC_DP15", "_tool_data", 2, (int)ToolField::RadiusWear},
    {"TC_DP21", "_tool_data", 2, (int)ToolField::Base1},       {"TC_DP22", "_tool_data", 2, (int)ToolField::Base2},
    {"TC_DP23", "_tool_data", 2, (int)ToolField::Base3},
};

// $TC_SCPxy (wear) and $TC_ECPxy (setup value) of DL set x = 1..6 for parameter y = 3..6
// (lengths 1-3, radius; L16993-L17028): the tool data field, -1 for another name, -2 for a
// parameter ncc does not keep (y = 7..11).
int findToolSumVar(std::string_view name) {
  bool wear = name.substr(0, 6) == "TC_SCP", setup = name.substr(0, 6) == "TC_ECP";
  if ((!wear && !setup) || name.size() != 8 || name[6] < '1' || name[6] > '6' || !std::isdigit((unsigned char)name[7]))
    return name.size() == 9 && (wear || setup) ? -2 : -1;  // $TC_SCP410: y = 10, 11
  int x = name[6] - '1', y = name[7] - '0';
  if (y < 3 || y > 6) return -2;
  return (wear ? kToolSumFields : kToolSetupFields) + x * kDlParams + (y - 3);
}

const SysMap *findSystemVar(std::string_view name) {
  for (auto &s : kSys)
    if (name == s.name) return &s;
  return nullptr;
}

static const FnMap kFns[] = {
    {"SIN", "SIN", false},         {"COS", "COS", false},         {"TAN", "TAN", false},
    {"ASIN", "ASIN", false},       {"ACOS", "ACOS", false},       {"ATAN2", "ATAN2_SIGNED", false},
    {"SQRT", "SQRT", false},       {"ABS", "ABS", false},         {"POT", "POT", false},
    {"TRUNC", "TRUNC", false},     {"ROUND", "ROUND", false},     {"ROUNDUP", "ROUNDUP", false},
    {"LN", "LN", false},           {"EXP", "EXP", false},         {"MINVAL", "MINVAL", false},
    {"MAXVAL", "MAXVAL", false},   {"BOUND", "BOUND", false},     {"STRLEN", "STRLEN", false},
    {"INDEX", "INDEX", false},     {"RINDEX", "RINDEX", false},   {"MINDEX", "MINDEX", false},
    {"MATCH", "MATCH", false},     {"SUBSTR", "SUBSTR", false},   {"TOUPPER", "TOUPPER", false},
    {"TOLOWER", "TOLOWER", false}, {"NUMBER", "NUMBER", false},   {"ISNUMBER", "ISNUMBER", false},
    {"CTRANS", "CTRANS", true},    {"CFINE", "CFINE", true},      {"CROT", "CROT", true},
    {"CROTS", "CROTS", true},
    {"CSCALE", "CSCALE", true},    {"CMIRROR", "CMIRROR", true},  {"INVFRAME", "INVFRAME", false},
    {"SPRINT", "SPRINT", false},
    {"AXNAME", "AXNAME", false},   {"AXSTRING", "TOSTR", false},  // an AXIS holds its name
    {"ISFILE", "FILE_EXISTS", false},  // the command's name goes first (ir/FileCommands.h)
};

const FnMap *findFunction(std::string_view name) {
  for (auto &f : kFns)
    if (name == f.name) return &f;
  return nullptr;
}

}  // namespace ncc::sin
