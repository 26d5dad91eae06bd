#include "ir/Jumps.h"

#include "ir/Value.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace ncc::ir {

bool constantJump(const Op &go) {
  const Expr *n = go.get("n"), *l = go.get("label");
  return (n && n->kind == ExprKind::Number) || (l && l->kind == ExprKind::String);
}

JumpDir jumpDir(const Op &go) {
  const Expr *d = go.get("dir");
  if (!d) return JumpDir::Any;
  return d->str == "forward" ? JumpDir::Forward : d->str == "backward" ? JumpDir::Backward : JumpDir::Any;
}

// "N<digits>" as a block number.
static bool blockName(std::string_view name, double &n) {
  if (name.size() < 2 || (name[0] != 'N' && name[0] != 'n')) return false;
  for (char c : name.substr(1))
    if (c < '0' || c > '9') return false;
  n = std::strtod(std::string(name.substr(1)).c_str(), nullptr);
  return true;
}

int64_t findJump(const JumpEntry *entries, size_t count, bool label, double n, std::string_view name,
                 uint32_t from, JumpDir dir) {
  auto matches = [&](const JumpEntry &e) { return label ? e.label && name == e.label : !e.label && e.n == n; };
  for (int pass = 0; pass < 2; ++pass) {
    if (dir != JumpDir::Backward)
      for (size_t i = 0; i < count; ++i)
        if (entries[i].pos > from && matches(entries[i])) return (int64_t)i;
    if (dir != JumpDir::Forward)
      for (size_t i = 0; i < count; ++i)
        if (entries[i].pos <= from && matches(entries[i])) return (int64_t)i;
    if (!label || !blockName(name, n)) break;
    label = false;  // no label of that name: a block number spelled as a string
  }
  return -1;
}

std::string missingJumpMessage(bool label, double n, std::string_view name) {
  return label ? fmt::format("jump to missing label '{}'", name)
               : fmt::format("jump to missing sequence number N{}", numberText(n));
}

SectionEnds sectionEnds(const Function &f) {
  SectionEnds out;
  std::unordered_map<std::string, std::vector<const Op *>> byTo;  // `to` label -> its calls
  auto calls = [&](auto &self, const Region &r) -> void {
    for (auto &op : r) {
      if (op.kind == OpKind::CallSection) {
        if (const Expr *to = op.get("to")) byTo[to->str].push_back(&op);
        else out.before[&op].push_back(&op);
      }
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  calls(calls, f.body);
  auto place = [&](auto &self, const Region &r) -> void {
    const std::vector<const Op *> *pending = nullptr;  // calls whose `to` block is open
    for (auto &op : r) {
      if (pending && (op.kind == OpKind::Block || op.kind == OpKind::Label)) {
        auto &v = out.before[&op];
        v.insert(v.end(), pending->begin(), pending->end());
        pending = nullptr;
      }
      if (op.kind == OpKind::Label)
        if (const Expr *n = op.get("name"); n && byTo.count(n->str)) pending = &byTo[n->str];
      for (auto &sub : op.regions) self(self, sub);
    }
    if (pending) {
      auto &v = out.atEnd[&r];
      v.insert(v.end(), pending->begin(), pending->end());
    }
  };
  place(place, f.body);
  return out;
}

std::string sectionDepthMessage() {
  return fmt::format("section calls nested deeper than {} in one function", kMaxSectionDepth);
}

}  // namespace ncc::ir
