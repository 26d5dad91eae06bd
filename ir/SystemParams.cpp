#include "ir/SystemParams.h"
#include "ir/RunErrors.h"
#include "ir/SystemAccess.h"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace ncc {

namespace {
constexpr const char *kAxisLetters = "XYZABCUVW";

// The maps a table row holds in (bits by ParamMap).
constexpr unsigned bit(ParamMap m) { return 1u << (unsigned)m; }
constexpr unsigned R = bit(ParamMap::Rs274);
constexpr unsigned F = bit(ParamMap::MacroB) | bit(ParamMap::MacroBMemoryC) | bit(ParamMap::MacroBLathe);

constexpr const char *kBuiltins[] = {"NGC_PARAMETER", "MACRO_VARIABLE", "MACRO_VARIABLE_C", "MACRO_VARIABLE_LATHE"};
static_assert(std::size(kBuiltins) == (size_t)ParamMap::Count);

// In ParamMap order; an unused second range is empty (first > last).
constexpr PlainRange kPlain[][kPlainRanges] = {
    {{0, 5000}, {5599, 5601}},  // LinuxCNC
    {{0, 33}, {100, 999}},      // Macro B: locals, commons
    {{0, 33}, {100, 999}},
    {{0, 33}, {100, 999}},
};
static_assert(std::size(kPlain) == (size_t)ParamMap::Count);

// A run of numbers mapped onto one family or variable: n = first + stride*(system-1) + axis.
struct ParamRange {
  unsigned maps;
  int first, last;   // inclusive
  SysFamily family;  // None: `named` for every number of the range (Count: the position of the axis)
  SysVar named;
  int stride = 0, systems = 1, axes = 6;  // families: systems of `stride` numbers, `axes` axes each
  const char *what;
};

const ParamRange kRanges[] = {
    // LinuxCNC (Numbered Parameters of the G-code manual). Axes U V W: ncc has none.
    {R, 5061, 5061, SysFamily::None, SysVar::ProbeX, 0, 1, 1, "probe result X"},
    {R, 5062, 5062, SysFamily::None, SysVar::ProbeY, 0, 1, 1, "probe result Y"},
    {R, 5063, 5063, SysFamily::None, SysVar::ProbeZ, 0, 1, 1, "probe result Z"},
    {R, 5064, 5064, SysFamily::None, SysVar::ProbeA, 0, 1, 1, "probe result A"},
    {R, 5065, 5065, SysFamily::None, SysVar::ProbeB, 0, 1, 1, "probe result B"},
    {R, 5066, 5066, SysFamily::None, SysVar::ProbeC, 0, 1, 1, "probe result C"},
    {R, 5067, 5067, SysFamily::None, SysVar::ProbeU, 0, 1, 1, "probe result U"},
    {R, 5068, 5068, SysFamily::None, SysVar::ProbeV, 0, 1, 1, "probe result V"},
    {R, 5069, 5069, SysFamily::None, SysVar::ProbeW, 0, 1, 1, "probe result W"},
    {R, 5070, 5070, SysFamily::None, SysVar::ProbeTripped, 0, 1, 1, "probe tripped"},
    {R, 5161, 5166, SysFamily::Home1, SysVar::Count, 0, 1, 6, "G28 reference point"},
    {R, 5181, 5186, SysFamily::Home2, SysVar::Count, 0, 1, 6, "G30 reference point"},
    {R, 5210, 5210, SysFamily::None, SysVar::G92On, 0, 1, 1, "G92 offsets applied"},
    {R, 5211, 5216, SysFamily::G92, SysVar::Count, 0, 1, 6, "G92 offset"},
    {R, 5220, 5220, SysFamily::None, SysVar::CoordSystemNumber, 0, 1, 1, "coordinate system number"},
    {R, 5221, 5390, SysFamily::WorkOffset, SysVar::Count, 20, 9, 7, "work offset"},  // +9 = R
    {R, 5400, 5400, SysFamily::None, SysVar::CurrentTool, 0, 1, 1, "tool number"},
    {R, 5401, 5406, SysFamily::ToolOffset, SysVar::Count, 0, 1, 6, "tool offset"},
    {R, 5410, 5410, SysFamily::None, SysVar::ToolDiameter, 0, 1, 1, "tool diameter"},
    {R, 5420, 5420, SysFamily::None, SysVar::PosX, 0, 1, 1, "current X"},
    {R, 5421, 5421, SysFamily::None, SysVar::PosY, 0, 1, 1, "current Y"},
    {R, 5422, 5422, SysFamily::None, SysVar::PosZ, 0, 1, 1, "current Z"},
    {R, 5423, 5423, SysFamily::None, SysVar::PosA, 0, 1, 1, "current A"},
    {R, 5424, 5424, SysFamily::None, SysVar::PosB, 0, 1, 1, "current B"},
    {R, 5425, 5425, SysFamily::None, SysVar::PosC, 0, 1, 1, "current C"},
    // Fanuc Custom Macro B (0i): positions (#5001 block end, #5041 current: without read-ahead both
    // are the position now), machine position, G54-G59 offsets, modal F D H S T.
    {F, 5001, 5006, SysFamily::None, SysVar::Count, 0, 1, 6, "block end position"},
    {F, 5021, 5026, SysFamily::MachinePos, SysVar::Count, 0, 1, 6, "machine position"},
    {F, 5041, 5046, SysFamily::None, SysVar::Count, 0, 1, 6, "current position"},
    // Fanuc: the G31 skip position in work coordinates, axes 1-6 (the probe result, ISO-MEAS-01).
    {F, 5061, 5061, SysFamily::None, SysVar::ProbeX, 0, 1, 1, "skip position X"},
    {F, 5062, 5062, SysFamily::None, SysVar::ProbeY, 0, 1, 1, "skip position Y"},
    {F, 5063, 5063, SysFamily::None, SysVar::ProbeZ, 0, 1, 1, "skip position Z"},
    {F, 5064, 5064, SysFamily::None, SysVar::ProbeA, 0, 1, 1, "skip position A"},
    {F, 5065, 5065, SysFamily::None, SysVar::ProbeB, 0, 1, 1, "skip position B"},
    {F, 5066, 5066, SysFamily::None, SysVar::ProbeC, 0, 1, 1, "skip position C"},
    {F, 5221, 5326, SysFamily::WorkOffset, SysVar::Count, 20, 6, 6, "work offset"},
    {F, 4107, 4107, SysFamily::None, SysVar::CutterD, 0, 1, 1, "modal D"},
    {F, 4109, 4109, SysFamily::None, SysVar::Feed, 0, 1, 1, "modal F"},
    {F, 4111, 4111, SysFamily::None, SysVar::ToolLengthH, 0, 1, 1, "modal H"},
    {F, 4119, 4119, SysFamily::None, SysVar::Rpm, 0, 1, 1, "modal S"},
    {F, 4120, 4120, SysFamily::None, SysVar::SelectedTool, 0, 1, 1, "modal T"},
};
constexpr SysVar kPositions[] = {SysVar::PosX, SysVar::PosY, SysVar::PosZ, SysVar::PosA, SysVar::PosB, SysVar::PosC};

// Fanuc tool compensation memory C (0i-MF Custom Macro B, milling): H and D offsets, geometry and
// wear apart, #2001-#2400 for offsets 1-200 and #10001-#13999 for 1-999. Offset number n is
// tool n's H/D edge, as H and D words address it (docs/MACHINE.md). A lathe numbers its
// offsets otherwise (X, Z, nose radius, tip): not provided.
struct OffsetRange {
  int first, last;
  ToolField field;
  const char *what;
};
const OffsetRange kMemoryC[] = {
    {2001, 2200, ToolField::LengthWear, "H wear"},   {2201, 2400, ToolField::Length, "H geometry"},
    {10001, 10999, ToolField::LengthWear, "H wear"}, {11001, 11999, ToolField::Length, "H geometry"},
    {12001, 12999, ToolField::RadiusWear, "D wear"}, {13001, 13999, ToolField::Radius, "D geometry"},
};
const OffsetRange *offsetRange(long n) {
  for (const OffsetRange &r : kMemoryC)
    if (n >= r.first && n <= r.last) return &r;
  return nullptr;
}

bool isMacroB(ParamMap m) { return (bit(m) & F) != 0; }

// Why n is no variable ncc provides (kind Unsupported or Alarm).
SystemParam notProvided(ParamMap m, long n) {
  SystemParam p;
  p.kind = SystemParam::Unsupported;
  if (offsetRange(n) && m == ParamMap::MacroBLathe)
    p.what = fmt::format("#{} is a lathe tool offset variable: ncc provides Fanuc's offset variables on mills "
                         "(tool compensation memory C) only",
                         n);
  else if (offsetRange(n) && isMacroB(m))
    p.what = fmt::format("#{} is a tool offset variable: the machine's [controller] offset_memory is \"none\" (\"C\": "
                         "Fanuc tool compensation memory C)",
                         n);
  else if (m == ParamMap::Rs274)
    p.what = n < 0 || n > 5602 ? fmt::format("parameter #{} is out of range (rs274 has #1-#5602)", n)
                               : fmt::format("parameter #{} (LinuxCNC controller state) is not provided by ncc", n);
  else if (n == 3000 || n == 3006)
    p.kind = SystemParam::Alarm;
  else
    p.what = (n >= 34 && n <= 99) || n < 0
                 ? fmt::format("#{} does not exist in Custom Macro B (#1-#33 local, #100-#999 common)", n)
                 : fmt::format("Fanuc system variable #{} is not supported", n);
  return p;
}
}  // namespace

const char *paramMapBuiltin(ParamMap m) { return kBuiltins[(int)m]; }

bool paramMapFromBuiltin(std::string_view name, ParamMap &out) {
  for (size_t i = 0; i < std::size(kBuiltins); ++i)
    if (name == kBuiltins[i]) {
      out = (ParamMap)i;
      return true;
    }
  return false;
}

double parameterNumber(double x) { return std::isnan(x) ? 1e9 : std::round(std::fmax(-1e9, std::fmin(1e9, x))); }

const PlainRange *plainRanges(ParamMap m) { return kPlain[(int)m]; }

bool plainParameter(ParamMap m, double n) {
  for (const PlainRange &r : kPlain[(int)m])
    if (n >= r.first && n <= r.last) return true;
  return false;
}

std::string plainRangesText(ParamMap m) {
  std::string s;
  for (const PlainRange &r : kPlain[(int)m])
    if (r.first <= r.last) s += fmt::format("{}#{}-#{}", s.empty() ? "" : " or ", r.first, r.last);
  return s;
}

SystemParam classifyParameter(ParamMap m, long n) {
  SystemParam p;
  if (plainParameter(m, (double)n)) return p;
  for (const ParamRange &r : kRanges) {
    if (!(r.maps & bit(m)) || n < r.first || n > r.last) continue;
    int off = (int)(n - r.first), sys = r.stride ? off / r.stride + 1 : 1, axis = r.stride ? off % r.stride : off;
    if (r.family == SysFamily::WorkOffset && axis == 9 && r.axes == 7) axis = 6;  // LinuxCNC R
    else if (axis >= r.axes || (r.family == SysFamily::WorkOffset && axis >= 6)) break;
    p.kind = SystemParam::System;
    if (r.family != SysFamily::None) p.var.var = sysVarOf(r.family, sys, axis);
    else if (r.named != SysVar::Count) p.var.var = r.named;
    else p.var.var = kPositions[axis];
    p.what = r.family == SysFamily::WorkOffset
                 ? fmt::format("{} {} {}", r.what, sys, axis == 6 ? 'R' : kAxisLetters[axis])
                 : r.axes > 1 ? fmt::format("{} {}", r.what, kAxisLetters[axis]) : std::string(r.what);
    return p;
  }
  const OffsetRange *o = m == ParamMap::MacroBMemoryC ? offsetRange(n) : nullptr;
  if (!o) return notProvided(m, n);
  int number = (int)(n - o->first + 1);
  p.kind = SystemParam::System;
  p.var = {sysVarOf(SysFamily::ToolData, 0, (int)o->field), number, 0};
  p.what = fmt::format("tool offset {} {}", number, o->what);
  return p;
}

std::string readOnlyParameterMessage(long n, const std::string &what) { return fmt::format("#{} ({}) is read-only", n, what); }

std::string alarmParameterMessage(long n, bool computed) {
  return computed ? fmt::format("#{} (alarm and message stop) can only be assigned with a constant number", n)
                  : fmt::format("#{} can only be assigned (alarm and message stop)", n);
}

const ir::Expr *computedParameterNumber(const ir::Expr &var, ParamMap &map) {
  if (var.space != ir::VarSpace::Numbered || var.args.size() != 1) return nullptr;
  const ir::Expr &ix = *var.args[0];
  return ix.kind == ir::ExprKind::Call && ix.args.size() == 1 && paramMapFromBuiltin(ix.str, map) ? ix.args[0].get()
                                                                                                 : nullptr;
}

bool accessSystemParameter(CmdSink &sink, ValuePool &pool, ParamMap m, double n, ParamAccess a, double &v,
                           SourceLoc loc, std::string &err) {
  long k = (long)parameterNumber(n);
  SystemParam p = classifyParameter(m, k);
  switch (p.kind) {
  case SystemParam::Plain: err = fmt::format("#{} is a plain parameter", k); return false;  // callers ask plainParameter
  case SystemParam::Alarm: err = alarmParameterMessage(k, true); return false;
  case SystemParam::Unsupported: err = p.what; return false;
  case SystemParam::System: break;
  }
  switch (a) {
  case ParamAccess::Reference:
    err = fmt::format("#{} ({}) is controller state: it cannot be passed by reference", k, p.what);
    return false;
  case ParamAccess::Write:
    if (!sysVarWritable(p.var.var)) {
      err = readOnlyParameterMessage(k, p.what);
      return false;
    }
    return writeSystemValue(sink, pool, p.var, v, loc, err);
  case ParamAccess::Read:
    if (readSystemValue(sink, pool, p.var, v, err)) return true;
    if (err.empty()) err = runErrorMessage(RunError::SysVar, ExecLimits{}, sysRefText(p.var));
    return false;
  }
  return false;
}

}  // namespace ncc
