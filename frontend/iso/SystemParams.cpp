// Numbered parameters that are controller state, as the ISO front end writes them in NC IR: a
// constant `#n` the map of ir/SystemParams.h makes controller state becomes a System variable
// (ir/SystemVars.h) the executor answers, or an error when ncc does not provide it: reading it
// as a plain parameter would be silently wrong. A computed `#[e]` keeps the map's builtin around
// its number, and the engines resolve it with the same map when the program runs.
#include "frontend/iso/Syntax.h"

namespace ncc::iso {

ParamMap paramMapFor(Flavour f, OffsetMemory mem, bool lathe) {
  if (f == Flavour::RS274) return ParamMap::Rs274;
  if (lathe) return ParamMap::MacroBLathe;
  return mem == OffsetMemory::C ? ParamMap::MacroBMemoryC : ParamMap::MacroB;
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

ir::ExprPtr numberedParameter(ParamMap m, long n, SourceLoc loc, std::string &err) {
  SystemParam sp = classifyParameter(m, n);
  switch (sp.kind) {
  case SystemParam::Plain: return ir::Expr::var(ir::VarSpace::Numbered, "", ir::Expr::number((double)n, ir::Type::Int, loc), loc);
  case SystemParam::System: return systemVariable(sp.var, loc);
  case SystemParam::Alarm: err = alarmParameterMessage(n, false); return nullptr;
  case SystemParam::Unsupported: err = sp.what; return nullptr;
  }
  return nullptr;
}

ir::ExprPtr computedParameter(ParamMap m, ir::ExprPtr number, SourceLoc loc) {
  std::vector<ir::ExprPtr> arg;
  arg.push_back(std::move(number));
  return ir::Expr::var(ir::VarSpace::Numbered, "", ir::Expr::call(paramMapBuiltin(m), std::move(arg), loc), loc);
}

}  // namespace ncc::iso
