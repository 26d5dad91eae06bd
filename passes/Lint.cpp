// Static lint rules on NC IR. Rules that need run-time state (motion without feed, arc end
// point off the circle, compensation without D) are reported by the executor while the
// program runs; `ncc lint` runs both.
#include "passes/Pass.h"

#include <fmt/format.h>

#include <set>

namespace ncc {
using namespace ir;

namespace {
struct Targets {
  std::set<int64_t> numbers;
  std::set<std::string> labels;
};

void collectTargets(const Region &r, Targets &t) {
  for (const Op &op : r) {
    if (op.kind == OpKind::Goto) {
      if (const Expr *n = op.get("n"); n && n->kind == ExprKind::Number) t.numbers.insert((int64_t)n->num);
      if (const Expr *l = op.get("label")) t.labels.insert(l->str);
    }
    for (auto &sub : op.regions) collectTargets(sub, t);
  }
}

bool isTarget(const Op &op, const Targets &t) {
  if (op.kind == OpKind::Label) return true;
  if (op.kind == OpKind::Block)
    if (const Expr *n = op.get("n"); n && t.numbers.count((int64_t)n->num)) return true;
  return false;
}

bool endsProgram(const Op &op) {
  if (op.kind != OpKind::Stop) return false;
  const Expr *k = op.get("kind");
  return k && (k->str == "end" || k->str == "end_rewind");
}

void lintRegion(const Region &r, const Targets &t, bool isMain, Diagnostics &diags) {
  // After an unconditional transfer, code up to the next jump target never runs.
  const char *dead = nullptr;
  bool reported = false;  // report the first block of each dead stretch only
  for (const Op &op : r) {
    if (dead && isTarget(op, t)) dead = nullptr;
    if (dead && !reported && op.kind == OpKind::Block) {
      if (std::string_view(dead) == "code-after-end")
        diags.warning(op.loc, "code after the end of the program (M2/M30) is never executed", dead);
      else
        diags.warning(op.loc, "block is unreachable", dead);
      reported = true;
    }
    if (!dead) {
      reported = false;
      if (op.kind == OpKind::Goto || op.kind == OpKind::Return) dead = "unreachable-block";
      else if (isMain && endsProgram(op)) dead = "code-after-end";
    }
    for (auto &sub : op.regions) lintRegion(sub, t, false, diags);
  }
}
}  // namespace

bool runLint(Module &m, Diagnostics &diags, PassContext &) {
  for (size_t i = 0; i < m.functions.size(); ++i) {
    Targets t;
    collectTargets(m.functions[i].body, t);
    lintRegion(m.functions[i].body, t, i == 0, diags);
  }
  return true;
}

}  // namespace ncc
