// Name resolution and type checking. Gives every expression a type (INT, REAL, BOOL, STRING, FRAME)
// and reports what no engine could run: unknown functions, wrong arity, strings in arithmetic,
// calls to programs the module does not have.
#include "ir/Builtins.h"
#include "ir/Decls.h"
#include "ir/SystemVars.h"
#include "passes/CycleOp.h"
#include "passes/Pass.h"

#include <fmt/format.h>

namespace ncc {
using namespace ir;

namespace {
struct Sema {
  const Module &m;
  Diagnostics &diags;
  DeclTable decls;
  const Function *fn = nullptr;

  // A variable's type: from its declaration (or typed parameter); undeclared named variables
  // and QS parameters hold what was assigned (Unknown); numbered, R and Q parameters are REAL.
  Type varType(const Expr &e) const {
    if (e.space == VarSpace::QParam) return e.str == "QS" ? Type::Unknown : Type::Real;
    if (e.space != VarSpace::Local && e.space != VarSpace::Global) return Type::Real;
    const VarDecl *d = fn ? decls.find(*fn, e) : nullptr;
    switch (d ? d->type : ValueType::Any) {
    case ValueType::Int: return Type::Int;
    case ValueType::Real: return Type::Real;
    case ValueType::Bool: return Type::Bool;
    case ValueType::Char:
    case ValueType::String: return Type::String;
    case ValueType::Axis: return Type::Axis;
    case ValueType::Frame: return Type::Frame;
    case ValueType::Any: break;
    }
    return Type::Unknown;
  }

  static bool numeric(Type t) { return t == Type::Int || t == Type::Real || t == Type::Bool || t == Type::Unknown; }

  Type expr(Expr &e) {
    for (auto &a : e.args) expr(*a);
    switch (e.kind) {
    case ExprKind::Number: if (e.type == Type::Unknown) e.type = Type::Real; break;
    case ExprKind::Bool: e.type = Type::Bool; break;
    case ExprKind::String: e.type = Type::String; break;
    case ExprKind::Symbol: e.type = Type::Symbol; break;
    case ExprKind::Vacant: e.type = Type::Real; break;
    case ExprKind::Var:
      // System variables may be indexed by axis name ($AA_IM[X]); others by number.
      for (auto &i : e.args)
        if (i && !numeric(i->type) && !(e.space == VarSpace::System && i->kind == ExprKind::Symbol))
          diags.error(e.loc, fmt::format("variable index must be a number, found {}", typeName(i->type)), "type-mismatch");
      e.type = e.space != VarSpace::System ? varType(e) : sysVarNameIsFrame(e.str) ? Type::Frame : Type::Real;
      break;
    case ExprKind::Unary:
      if (!numeric(e.args[0]->type))
        diags.error(e.loc, fmt::format("operand of '{}' must be a number, found {}", opCodeName(e.op), typeName(e.args[0]->type)),
                    "type-mismatch");
      e.type = e.op == OpCode::Not ? Type::Bool : e.args[0]->type == Type::Int ? Type::Int : Type::Real;
      break;
    case ExprKind::Binary: {
      Type a = e.args[0]->type, b = e.args[1]->type;
      if (e.op == OpCode::Concat) {
        e.type = Type::String;
        break;
      }
      bool cmp = e.op >= OpCode::Eq && e.op <= OpCode::Ge;
      auto str = [](Type t) { return t == Type::String || t == Type::Unknown || t == Type::Symbol || t == Type::Axis; };
      auto known = [](Type t) { return t != Type::Unknown; };
      if (cmp && ((str(a) && known(a) && numeric(b) && known(b)) || (numeric(a) && known(a) && str(b) && known(b))))
        diags.error(e.loc, "cannot compare a string with a number", "type-mismatch");
      else if (!(numeric(a) && numeric(b)) && !(cmp && str(a) && str(b)))
        diags.error(e.loc, fmt::format("operands of '{}' must be numbers, found {} and {}", opCodeName(e.op), typeName(a), typeName(b)),
                    "type-mismatch");
      if (cmp || e.op == OpCode::And || e.op == OpCode::Or || e.op == OpCode::Xor) e.type = Type::Bool;
      else if (a == Type::Int && b == Type::Int && e.op != OpCode::Div && e.op != OpCode::Pow) e.type = Type::Int;
      else e.type = Type::Real;
      break;
    }
    case ExprKind::Call: {
      const BuiltinInfo *b = findBuiltin(e.str);
      if (!b) diags.error(e.loc, fmt::format("unknown function '{}'", e.str));
      else if (!b->accepts(e.args.size()))
        diags.error(e.loc, fmt::format("'{}' takes {} argument(s), {} given", b->name, builtinArity(*b), e.args.size()));
      for (size_t i = 0; i < e.args.size(); ++i) {
        char want = b ? b->argKind(i) : 'n';
        Type t = e.args[i]->type;
        const char *need = want == 'n' && !numeric(t)                                             ? "number"
                           : want == 's' && ((numeric(t) && t != Type::Unknown) || t == Type::Frame) ? "string"
                           : want == 'f' && t != Type::Frame && t != Type::Unknown                ? "frame"
                                                                                                  : nullptr;
        if (need)
          diags.error(e.args[i]->loc, fmt::format("argument {} of {} must be a {}, found {}", i + 1, e.str, need, typeName(t)),
                      "type-mismatch");
      }
      e.type = !b ? Type::Real : b->result == 's' ? Type::String : b->result == 'f' ? Type::Frame : Type::Real;
      break;
    }
    }
    return e.type;
  }

  void region(Region &r) {
    for (Op &op : r) {
      for (auto &a : op.args)
        if (a.value) expr(*a.value);
      if (op.kind == OpKind::Call) {
        const Expr *c = op.get("callee");
        std::string name = "?";
        bool computed = c && !c->isConstant();  // looked up at run time
        if (!computed && (!c || !constantCallee(*c, name) || !m.find(name)))
          diags.error(op.loc, fmt::format("call to unknown program '{}'", name), "missing-subprogram");
      }
      if (op.kind == OpKind::Cycle) {  // the library's entries and parameters (passes/CycleOp.h)
        CycleOpShape shape;
        std::string err;
        if (!resolveCycleOp(op, shape, err)) diags.error(op.loc, err, "cycle-invalid");
        for (auto &a : op.args)
          if (a.value && (a.key.rfind("a.", 0) == 0 || a.key.rfind("p.", 0) == 0) && !numeric(a.value->type) &&
              a.value->kind != ExprKind::String)
            diags.error(a.value->loc.line ? a.value->loc : op.loc,
                        fmt::format("cycle argument '{}' must be a number or a constant string", a.key.substr(2)), "type-mismatch");
      }
      if (op.kind == OpKind::Assign || op.kind == OpKind::Declare) {  // stores the declared type refuses
        bool assign = op.kind == OpKind::Assign;
        const Expr *t = op.get(assign ? "target" : "var"), *v = op.get(assign ? "value" : "init");
        const VarDecl *d = t && v && fn ? decls.find(*fn, *t) : nullptr;
        bool strValue = v && (v->type == Type::String || v->type == Type::Symbol);
        bool numValue = v && v->type != Type::Unknown && numeric(v->type);
        bool frameValue = v && v->type == Type::Frame;
        if (d && frameValue && d->type != ValueType::Frame && d->type != ValueType::Any)
          diags.error(op.loc, fmt::format("cannot assign a frame to {} variable '{}'", valueTypeName(d->type), t->str), "type-mismatch");
        if (assign && t && v && t->space == VarSpace::System) {  // controller state: frames or numbers
          bool frameVar = sysVarNameIsFrame(t->str);
          if (frameVar ? (strValue || numValue) : frameValue)
            diags.error(op.loc, fmt::format("cannot assign a {} to system variable '${}'",
                                            frameValue ? "frame" : strValue ? "string" : "number", t->str), "type-mismatch");
        }
        if (d && d->type == ValueType::Frame && (strValue || numValue))
          diags.error(op.loc, fmt::format("cannot assign a {} to frame variable '{}'", strValue ? "string" : "number", t->str), "type-mismatch");
        if (d && strValue && (d->type == ValueType::Int || d->type == ValueType::Real))
          diags.error(op.loc, fmt::format("cannot assign a string to {} variable '{}'", valueTypeName(d->type), t->str), "type-mismatch");
        if (d && numValue && (d->type == ValueType::String || d->type == ValueType::Axis))
          diags.error(op.loc, fmt::format("cannot assign a number to {} variable '{}'", valueTypeName(d->type), t->str), "type-mismatch");
      }
      if ((op.kind == OpKind::If || op.kind == OpKind::While)) {
        const Expr *c = op.get("cond");
        if (c && !numeric(c->type))
          diags.error(c->loc, fmt::format("condition must be a number or boolean, found {}", typeName(c->type)), "type-mismatch");
      }
      for (auto &sub : op.regions) region(sub);
    }
  }
};
}  // namespace

bool runSema(Module &m, Diagnostics &diags, PassContext &) {
  unsigned before = diags.errorCount();
  Sema s{m, diags, {}, nullptr};
  collectDecls(m, s.decls, nullptr);
  for (auto &f : m.functions) {
    s.fn = &f;
    s.region(f.body);
  }
  return diags.errorCount() == before;
}

}  // namespace ncc
