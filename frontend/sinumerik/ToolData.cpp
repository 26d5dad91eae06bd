// DELDL, deleting the additive offsets (SIN-TOL-06, L17030-L17066; docs/SINUMERIK.md "Tool
// offsets"): `DELDL[t, d]`, `DELDL[t]` and `DELDL` as a statement, and `S = DELDL[t, d]` (any of the
// three forms as the value of an assignment) with the status. Each is the NC IR op `set_offset kind=deldl`
// (index the tool, D the edge; absent: all) before the block's other work; in an assignment the op
// carries Q=1 and the value is the status the executor left, `$_sin_deldl_status`. Elsewhere in an
// expression (a condition evaluated again in a loop) DELDL is an error.
#include "frontend/sinumerik/Parser.h"

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

bool BlockParser::deleteAdditive(const Token &at, bool status) {
  SourceLoc l = loc(at);
  ++i_;  // DELDL
  std::vector<ExprPtr> idx;
  if (tok().is("[") && !indexList(idx, false)) return false;
  if (idx.size() > 2) return fail(at, "DELDL takes at most two indices [tool, edge]");
  Op o(OpKind::SetOffset, l);
  o.set("kind", Expr::symbol("deldl", l));
  if (idx.size() > 0) o.set("index", std::move(idx[0]));
  if (idx.size() > 1) o.set("D", std::move(idx[1]));
  if (status) o.set("Q", Expr::number(1, ir::Type::Int, l));
  pre_.push_back(std::move(o));
  return true;
}

ExprPtr BlockParser::deldlStatus(const Token &at) {
  if (!deleteAdditive(at, true)) return nullptr;
  return Expr::var(ir::VarSpace::System, "_sin_deldl_status", nullptr, loc(at));
}

}  // namespace ncc::sin
