// Program-wide data that no part program defines: the global user data of the GUD definition
// files (SIN-VAR-10, L711-L741, L865-L908) and the global R parameters RG[n] (SIN-VAR-05).
#include "frontend/SubprogramFiles.h"
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::Op;

// The definition files in the order the control activates them (L713, L720-L721): the
// manufacturer's SGUD and MGUD, the user's UGUD, then GUD4 … GUD9.
static const char *const kGudFiles[] = {"SGUD", "MGUD", "UGUD", "GUD4", "GUD5", "GUD6", "GUD7", "GUD8", "GUD9"};

// What a definition file may hold: its DEF NCK/CHAN lines (with their SET/REP values), blocks,
// comments and the closing M30/M17.
static bool definitionOp(const Op &op) {
  switch (op.kind) {
  case ir::OpKind::Block: case ir::OpKind::Comment: case ir::OpKind::Declare: case ir::OpKind::Assign:
  case ir::OpKind::Return: case ir::OpKind::Stop:
    return true;
  default:
    return false;
  }
}

bool ProgramParser::loadDefinitionFiles() {
  // The folders of the search path and their definition folder `/_N_DEF_DIR` (docs/SINUMERIK.md
  // "Program memory").
  std::vector<std::string> dirs;
  for (auto &d : opts.searchDirs)
    for (const char *sub : {"", "/_N_DEF_DIR", "/DEF.DIR", "/def.dir"}) dirs.push_back(d + sub);
  bool good = true;
  for (const char *base : kGudFiles) {
    std::string b(base), low(base);
    for (auto &c : low) c = (char)std::tolower((unsigned char)c);
    uint32_t fid = findSubprogramFile(sm, dirs, {"_N_" + b + "_DEF", b + ".DEF", low + ".def"}, true);
    if (!fid) continue;
    FunctionParser fp(*this, fid, "_N_" + b + "_DEF", false);
    fp.definitions = true;
    if (!fp.run()) good = false;
    for (auto &op : fp.fn.body) {
      if (!definitionOp(op)) {
        good = error(op.loc, "a GUD definition file holds DEF NCK|CHAN lines only");
        break;
      }
      if (op.kind == ir::OpKind::Declare || op.kind == ir::OpKind::Assign) gudOps.push_back(op.clone());
    }
    for (auto &[name, d] : fp.vars)
      if (d.global) guds[name] = d;
  }
  return good;
}

void declareGlobalR(ir::Region &mainBody) {
  Op d(ir::OpKind::Declare, {});
  auto v = Expr::var(ir::VarSpace::Global, kGlobalR, nullptr, {});
  v->args.push_back(Expr::number(kGlobalRCount, ir::Type::Int));
  d.set("var", std::move(v));
  d.set("type", Expr::symbol("real"));
  mainBody.insert(mainBody.begin(), std::move(d));
}

}  // namespace ncc::sin
