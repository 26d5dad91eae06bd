#include "ir/Decls.h"

#include <fmt/format.h>

namespace ncc::ir {

bool VarDecl::sameAs(const VarDecl &o) const {
  if (type != o.type || len != o.len || rank != o.rank) return false;
  for (unsigned i = 0; i < rank; ++i)
    if (dims[i] != o.dims[i]) return false;
  return true;
}

const VarDecl *DeclTable::find(const Function &f, VarSpace space, const std::string &name) const {
  if (space == VarSpace::Global) {
    auto it = globals.find(name);
    return it == globals.end() ? nullptr : &it->second;
  }
  if (space != VarSpace::Local) return nullptr;
  auto fit = locals.find(&f);
  if (fit == locals.end()) return nullptr;
  auto it = fit->second.find(name);
  return it == fit->second.end() ? nullptr : &it->second;
}

const VarDecl *DeclTable::find(const Function &f, const Expr &var) const {
  return var.kind == ExprKind::Var ? find(f, var.space, var.str) : nullptr;
}

static bool positiveInt(const Expr *e, uint64_t max, uint32_t &out) {
  if (!e || e->kind != ExprKind::Number || !(e->num >= 1 && e->num <= (double)max) || e->num != (double)(uint64_t)e->num)
    return false;
  out = (uint32_t)e->num;
  return true;
}

bool declOf(const Op &op, VarDecl &d, std::string &error) {
  const Expr *v = op.get("var"), *t = op.get("type"), *len = op.get("len");
  if (!v || v->kind != ExprKind::Var || !t || t->kind != ExprKind::Symbol) return false;  // verifier rules
  std::string tn = t->str;
  for (char &c : tn) c = (char)std::tolower((unsigned char)c);
  if (!valueTypeFromName(tn, d.type)) d.type = ValueType::Any;  // symbol, frame: verifyRunnable
  if (len) {
    if (d.type != ValueType::String) {
      error = "'declare' argument 'len' is only for type string";
      return false;
    }
    if (!positiveInt(len, kMaxStringBytes, d.len)) {
      error = fmt::format("'declare' argument 'len' must be an integer constant 1..{}", kMaxStringBytes);
      return false;
    }
  } else if (d.type == ValueType::String) {
    d.len = kDefaultStringLength;
  }
  if (v->args.size() > kMaxArrayRank) {
    error = fmt::format("array '{}' has {} dimensions, at most {} are allowed", v->str, v->args.size(), kMaxArrayRank);
    return false;
  }
  d.rank = (unsigned)v->args.size();
  for (unsigned i = 0; i < d.rank; ++i)
    if (!positiveInt(v->args[i].get(), kMaxArrayExtent, d.dims[i])) {
      error = fmt::format("dimension {} of array '{}' must be an integer constant 1..{}", i + 1, v->str,
                          kMaxArrayExtent);
      return false;
    }
  if (d.type == ValueType::String && d.rank > 2) {  // Sinumerik: STRING arrays have at most 2
    error = fmt::format("string array '{}' has {} dimensions, at most 2 are allowed", v->str, d.rank);
    return false;
  }
  if (d.size() > kMaxArrayElements) {
    error = fmt::format("array '{}' has {} elements, at most {} are allowed", v->str, d.size(), kMaxArrayElements);
    return false;
  }
  return true;
}

static ValueType paramType(Type t) {
  switch (t) {
  case Type::Int: return ValueType::Int;
  case Type::Bool: return ValueType::Bool;
  case Type::String: return ValueType::String;
  case Type::Axis: return ValueType::Axis;
  case Type::Frame: return ValueType::Frame;
  case Type::Real: return ValueType::Real;
  default: return ValueType::Any;
  }
}

bool collectDecls(const Module &m, DeclTable &out, Diagnostics *diags) {
  bool ok = true;
  auto report = [&](SourceLoc l, std::string msg) {
    ok = false;
    if (diags) diags->error(l, std::move(msg));
  };
  for (auto &f : m.functions) {
    auto &locals = out.locals[&f];
    for (auto &p : f.params) {
      VarDecl d;
      d.type = paramType(p.type);
      d.param = true;
      if (d.type == ValueType::String) d.len = kDefaultStringLength;
      locals.emplace(p.name, d);
    }
    auto walk = [&](auto &self, const Region &r) -> void {
      for (auto &op : r) {
        if (op.kind == OpKind::Declare) {
          VarDecl d;
          std::string err;
          const Expr *v = op.get("var");
          if (!declOf(op, d, err)) {
            if (!err.empty()) report(op.loc, err);
          } else if (v->space == VarSpace::Local || v->space == VarSpace::Global) {
            auto &scope = v->space == VarSpace::Global ? out.globals : locals;
            auto [it, fresh] = scope.emplace(v->str, d);
            if (!fresh && !it->second.sameAs(d))
              report(op.loc, fmt::format("variable '{}' is declared again with a different type or size", v->str));
          }
        }
        for (auto &sub : op.regions) self(self, sub);
      }
    };
    walk(walk, f.body);
  }
  return ok;
}

}  // namespace ncc::ir
