// Declared types of named variables, one analysis for the verifier, sema and both engines:
// `declare var=%x type=int` (arrays: `declare var=%A[2, 3] type=real`, strings `len=`) and
// typed function parameters. A local declaration holds in its function, a global one (%%x) in
// the whole module. Undeclared named variables have no type (ValueType::Any: they hold what is
// assigned) and undeclared indexed ones are the 1-D arrays of kArrayElements (ir/Value.h).
#pragma once
#include "ir/NCIR.h"
#include "ir/Strings.h"

#include <map>
#include <string>
#include <unordered_map>

namespace ncc::ir {

constexpr unsigned kMaxArrayRank = 3;
constexpr uint32_t kMaxArrayExtent = 65535;       // elements per dimension (Sinumerik)
constexpr uint64_t kMaxArrayElements = 1000000;   // elements of one declared array

struct VarDecl {
  ValueType type = ValueType::Any;
  uint32_t len = 0;   // STRING: the most characters
  unsigned rank = 0;  // 0: scalar; else the number of declared dimensions
  uint32_t dims[kMaxArrayRank] = {0, 0, 0};
  bool param = false;  // a typed function parameter (holds the argument; no initial value)
  uint64_t size() const {
    uint64_t n = 1;
    for (unsigned i = 0; i < rank; ++i) n *= dims[i];
    return n;
  }
  bool sameAs(const VarDecl &o) const;
};

struct DeclTable {
  std::map<std::string, VarDecl> globals;
  std::unordered_map<const Function *, std::map<std::string, VarDecl>> locals;
  // The declaration of a named variable (Local or Global) used in `f`; null when undeclared.
  const VarDecl *find(const Function &f, const Expr &var) const;
  const VarDecl *find(const Function &f, VarSpace space, const std::string &name) const;
};

// The declaration a `declare` op makes; false (with `error`) when its type, dimensions or length
// are malformed.
bool declOf(const Op &declare, VarDecl &out, std::string &error);
// Collects every declaration of the module. With `diags`, reports malformed declarations and
// variables declared twice differently; returns false if there were any.
bool collectDecls(const Module &m, DeclTable &out, Diagnostics *diags);

}  // namespace ncc::ir
