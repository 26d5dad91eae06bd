// Numbered parameters that are controller state: LinuxCNC's #5161-#5428 and Fanuc Custom Macro
// B's system variables (#1000 and up). A constant `#n` in such a range becomes a System variable
// (ir/SystemVars.h) the executor answers, or an error when ncc does not provide it: reading it
// as a plain parameter would be silently wrong.
#include "frontend/iso/Syntax.h"
#include "ir/SystemVars.h"

#include <fmt/format.h>

namespace ncc::iso {

namespace {
constexpr const char *kAxisLetters = "XYZABCUVW";

// A run of numbers mapped onto one family or variable: n = first + stride*(system-1) + axis.
struct ParamRange {
  Flavour flavour;
  int first, last;   // inclusive
  SysFamily family;  // None: `named` for every number of the range
  SysVar named;
  int stride = 0, systems = 1, axes = 6;  // families: systems of `stride` numbers, `axes` axes each
  const char *what;
};

constexpr Flavour R = Flavour::RS274, F = Flavour::Fanuc;
const ParamRange kRanges[] = {
    // LinuxCNC (Numbered Parameters of the G-code manual). Axes U V W: ncc has none.
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
// tool n's H/D edge, as H and D words address it (docs/MACHINE.md).
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

}  // namespace

SystemParam classifyParameter(Flavour f, OffsetMemory mem, long n) {
  SystemParam p;
  if (f == Flavour::RS274 ? plainNgcParameter((double)n) : plainMacroVariable((double)n)) return p;
  for (const ParamRange &r : kRanges) {
    if (r.flavour != f || n < r.first || n > r.last) continue;
    int off = n - r.first, sys = r.stride ? off / r.stride + 1 : 1, axis = r.stride ? off % r.stride : off;
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
  const OffsetRange *o = f == Flavour::Fanuc ? offsetRange(n) : nullptr;
  if (o && mem == OffsetMemory::C) {
    int number = (int)(n - o->first + 1);
    p.kind = SystemParam::System;
    p.var = {sysVarOf(SysFamily::ToolData, 0, (int)o->field), number, 0};
    p.what = fmt::format("tool offset {} {}", number, o->what);
    return p;
  }
  p.kind = SystemParam::Unsupported;
  if (o)
    p.what = fmt::format("#{} is a tool offset variable: the machine's [controller] offset_memory is \"none\" (\"C\": "
                         "Fanuc tool compensation memory C)",
                         n);
  else if (f == Flavour::RS274)
    p.what = n > 5602 ? fmt::format("parameter #{} is out of range (rs274 has #1-#5602)", n)
                      : fmt::format("parameter #{} (LinuxCNC controller state) is not provided by ncc", n);
  else if (n == 3000 || n == 3006)
    p.kind = SystemParam::Alarm;
  else
    p.what = n >= 34 && n <= 99 ? fmt::format("#{} does not exist in Custom Macro B (#1-#33 local, #100-#999 common)", n)
                                : fmt::format("Fanuc system variable #{} is not supported", n);
  return p;
}

// A System variable reading `ref`: its name, or tool data's family with constant indices.
static ir::ExprPtr systemVariable(const SysRef &ref, SourceLoc loc) {
  SysVarInfo info = sysVarInfo(ref.var);
  if (info.family != SysFamily::ToolData) return ir::Expr::var(ir::VarSpace::System, sysVarName(ref.var), nullptr, loc);
  auto e = ir::Expr::var(ir::VarSpace::System, sysFamilyName(info.family), ir::Expr::number(ref.tool, ir::Type::Int, loc), loc);
  e->args.push_back(ir::Expr::number(ref.edge, ir::Type::Int, loc));
  e->args.push_back(ir::Expr::number(info.axis, ir::Type::Int, loc));
  return e;
}

ir::ExprPtr numberedParameter(Flavour f, OffsetMemory mem, long n, SourceLoc loc, std::string &err) {
  SystemParam sp = classifyParameter(f, mem, n);
  switch (sp.kind) {
  case SystemParam::Plain: return ir::Expr::var(ir::VarSpace::Numbered, "", ir::Expr::number((double)n, ir::Type::Int, loc), loc);
  case SystemParam::System: return systemVariable(sp.var, loc);
  case SystemParam::Alarm: err = fmt::format("#{} can only be assigned (alarm and message stop)", n); return nullptr;
  case SystemParam::Unsupported: err = sp.what; return nullptr;
  }
  return nullptr;
}

}  // namespace ncc::iso
