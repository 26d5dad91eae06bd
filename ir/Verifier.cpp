// Structural checks of NC IR, driven by the OpInfo table (keys, region counts) plus a few
// small rule tables (enumerated symbol values, keys that must name a variable). Every problem is
// one diagnostic at the op's loc; the verifier never stops early and never assumes a
// well-formed module (null expressions, bad kinds are reported, not dereferenced).
#include "ir/Builtins.h"
#include "ir/Decls.h"
#include "ir/ModeTable.h"
#include "ir/OpSymbols.h"
#include "ir/SystemVars.h"
#include "ir/NCIR.h"
#include "ir/WordList.h"
#include "ir/Value.h"

#include <fmt/format.h>

#include <cstring>
#include <set>
#include <string>

namespace ncc::ir {

namespace {

// Keys whose value must be a variable reference (something that can be assigned).
struct VarRule {
  OpKind kind;
  const char *key;
};
const VarRule kVarRules[] = {{OpKind::Declare, "var"}, {OpKind::Assign, "target"}, {OpKind::Call, "result"}};

// Keys whose value must be a non-negative integer constant (source block numbers).
const VarRule kIntConstRules[] = {{OpKind::Block, "n"}, {OpKind::Block, "skip"}};

// Keys of `call` besides the `a.<name>` arguments.
const char *kCallKeys = "callee count frame result";


std::string lower(std::string_view s) {
  std::string o(s);
  for (char &c : o)
    if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
  return o;
}

bool isIntConst(const Expr *e) {
  return e && e->kind == ExprKind::Number && e->num >= 0 && e->num == (double)(long long)e->num;
}

// Block numbers and label names of one function, gathered before gotos are checked
// (a goto may jump forward or into/out of nested regions).
struct Targets {
  std::set<double> blocks;
  std::set<std::string> labels;
};

class Verifier {
public:
  Verifier(const Module &m, Diagnostics &d) : m_(m), d_(d) {}

  bool run() {
    if (m_.functions.empty()) error({}, "module has no functions (functions[0] is the entry)");
    if (!collectDecls(m_, decls_, &d_)) ++errors_;
    std::set<std::string> names;
    for (auto &f : m_.functions) {
      if (!names.insert(f.name).second) error(f.loc, fmt::format("function '@{}' is defined twice", f.name));
      verifyFunction(f);
    }
    return errors_ == 0;
  }

private:
  const Module &m_;
  Diagnostics &d_;
  unsigned errors_ = 0;
  unsigned loopDepth_ = 0;
  Targets targets_;
  std::set<std::string> labelsSeen_;
  DeclTable decls_;
  const Function *fn_ = nullptr;

  void error(SourceLoc l, std::string msg) {
    ++errors_;
    d_.error(l, std::move(msg));
  }

  void verifyFunction(const Function &f) {
    fn_ = &f;
    if (f.name.empty()) error(f.loc, "function has no name");
    std::set<std::string> params;
    for (auto &p : f.params) {
      if (p.name.empty()) error(f.loc, fmt::format("function '@{}' has a parameter without a name", f.name));
      else if (!params.insert(p.name).second)
        error(f.loc, fmt::format("function '@{}' has parameter '{}' twice", f.name, p.name));
      if (p.defaultValue)
        verifyExpr(p.defaultValue.get(), f.loc, fmt::format("default of parameter '{}'", p.name));
    }
    targets_ = {};
    labelsSeen_.clear();
    collectTargets(f.body, f.name);
    loopDepth_ = 0;
    for (auto &op : f.body) verifyOp(op);
  }

  void collectTargets(const Region &r, const std::string &fn) {
    for (auto &op : r) {
      if (op.kind == OpKind::Block) {
        const Expr *n = op.get("n");
        if (n && n->kind == ExprKind::Number) targets_.blocks.insert(n->num);
      } else if (op.kind == OpKind::Label) {
        const Expr *n = op.get("name");
        if (n && n->kind == ExprKind::String && !targets_.labels.insert(n->str).second)
          error(op.loc, fmt::format("label '{}' is defined twice in function '@{}'", n->str, fn));
      }
      for (auto &sub : op.regions) collectTargets(sub, fn);
    }
  }

  void verifyOp(const Op &op) {
    if ((unsigned)op.kind >= (unsigned)OpKind::Count) {
      error(op.loc, fmt::format("invalid op kind {}", (unsigned)op.kind));
      return;
    }
    const OpInfo &info = opInfo(op.kind);
    std::string name = info.name;
    checkKeys(op, info);
    size_t nr = op.regions.size();
    if (nr < info.regionsMin || nr > info.regionsMax) {
      std::string expect = info.regionsMin == info.regionsMax ? fmt::format("{}", info.regionsMin)
                                                              : fmt::format("{} to {}", info.regionsMin, info.regionsMax);
      error(op.loc, fmt::format("'{}' has {} region{}, expected {}", name, nr, nr == 1 ? "" : "s", expect));
    }
    for (auto &a : op.args) verifyExpr(a.value.get(), op.loc, fmt::format("'{}' argument '{}'", name, a.key));
    checkValues(op, name);
    checkControl(op, name);
    bool loop = op.kind == OpKind::While || op.kind == OpKind::Loop;
    if (loop) ++loopDepth_;
    for (auto &r : op.regions)
      for (auto &sub : r) verifyOp(sub);
    if (loop) --loopDepth_;
  }

  void checkKeys(const Op &op, const OpInfo &info) {
    std::set<std::string> seen;
    for (auto &a : op.args) {
      if (!seen.insert(a.key).second) error(op.loc, fmt::format("'{}' has argument '{}' twice", info.name, a.key));
      bool ok;
      if (op.kind == OpKind::Call || op.kind == OpKind::ModalCall)
        ok = inWordList(op.kind == OpKind::Call ? kCallKeys : "callee count", a.key) ||
             (a.key.size() > 2 && a.key.compare(0, 2, "a.") == 0);
      else ok = std::string_view(info.allowed) == "*" || inWordList(info.required, a.key) || inWordList(info.allowed, a.key);
      if (!ok) error(op.loc, fmt::format("'{}' has unknown argument '{}'", info.name, a.key));
    }
    std::string_view req = info.required;
    size_t i = 0;
    while (i < req.size()) {
      size_t j = req.find(' ', i);
      if (j == std::string_view::npos) j = req.size();
      std::string key(req.substr(i, j - i));
      if (!op.get(key)) error(op.loc, fmt::format("'{}' is missing required argument '{}'", info.name, key));
      i = j + 1;
    }
  }

  void checkValues(const Op &op, const std::string &name) {
    // Symbol-valued keys (ir/OpSymbols.h), each key once.
    size_t count;
    const OpSymbol *table = opSymbols(count);
    for (size_t i = 0; i < count; ++i) {
      const OpSymbol &r = table[i];
      if (r.op != op.kind || (i > 0 && table[i - 1].op == r.op && !std::strcmp(table[i - 1].key, r.key))) continue;
      const Expr *v = op.get(r.key);
      if (!v) continue;
      std::string word = v->kind == ExprKind::Symbol ? (op.kind == OpKind::Declare ? lower(v->str) : v->str) : "";
      uint8_t code;
      if (word.empty() || !opSymbolCode(op.kind, r.key, word, code))
        error(op.loc, fmt::format("'{}' argument '{}' must be one of: {}", name, r.key, opSymbolValues(op.kind, r.key)));
    }
    for (auto &r : kVarRules) {
      const Expr *v = op.kind == r.kind ? op.get(r.key) : nullptr;
      if (v && v->kind != ExprKind::Var)
        error(op.loc, fmt::format("'{}' argument '{}' must be a variable", name, r.key));
    }
    for (auto &r : kIntConstRules) {
      const Expr *v = op.kind == r.kind ? op.get(r.key) : nullptr;
      if (v && !isIntConst(v))
        error(op.loc, fmt::format("'{}' argument '{}' must be a non-negative integer constant", name, r.key));
    }
    if (op.kind == OpKind::Mode) checkModes(op);
    // One aux op is one auxiliary function: its letter is the key.
    if (op.kind == OpKind::Aux && !!op.get("m") + !!op.get("b") + !!op.get("h") != 1)
      error(op.loc, "'aux' needs exactly one of m=, b=, h=");
    // The orientation's angle, way and wait belong to dir=orient only.
    if (op.kind == OpKind::Spindle && (op.get("angle") || op.get("way") || op.get("wait"))) {
      const Expr *d = op.get("dir");
      if (!d || d->str != "orient") error(op.loc, "'spindle' angle=, way= and wait= need dir=orient");
    }
    // A speed op sets S, a spindle mode or a limit: at least one of them.
    if (op.kind == OpKind::Speed && !op.get("value") && !op.get("mode") && !op.get("limit"))
      error(op.loc, "'speed' needs value=, mode= or limit=");
    // DEF declares named variables; numbered parameters exist without a declaration.
    if (const Expr *v = op.kind == OpKind::Declare ? op.get("var") : nullptr)
      if (v->kind == ExprKind::Var && v->space != VarSpace::Local && v->space != VarSpace::Global)
        error(op.loc, "'declare' argument 'var' must be a named variable (%name or %%name)");
  }

  void checkModes(const Op &op) {
    for (auto &a : op.args) {
      ModeGroup g;
      if (!modeGroupFromName(a.key, g)) continue;  // already reported as an unknown argument
      const Expr *v = a.value.get();
      ModeValue mv;
      if (!v || v->kind != ExprKind::Symbol) {
        error(op.loc, fmt::format("'mode' argument '{}' must be a mode name", a.key));
      } else if (!modeValueFromName(v->str, mv)) {
        error(op.loc, fmt::format("'mode' has unknown value '{}' for '{}'", v->str, a.key));
      } else if (modeValueInfo(mv).group != g) {
        error(op.loc, fmt::format("'mode' value '{}' belongs to group '{}', not '{}'", v->str,
                                  modeGroupName(modeValueInfo(mv).group), a.key));
      }
    }
  }

  // The shape of a `cycle` op (docs/IR.md §5.7); sema checks the names against the library.
  void checkCycle(const Op &op) {
    const Expr *act = op.get("action");
    std::string a = act ? act->str : "run";
    bool entry = op.get("entry"), pattern = op.get("pattern");
    for (auto &arg : op.args) {
      std::string_view k = arg.key;
      bool ok = k == "entry" || k == "pattern" || k == "action" || (k.size() > 2 && (k.substr(0, 2) == "a." || k.substr(0, 2) == "p."));
      if (!ok) error(op.loc, fmt::format("'cycle' has unknown argument '{}'", k));
      if ((k == "entry" || k == "pattern") && (!arg.value || arg.value->kind != ExprKind::String))
        error(op.loc, fmt::format("'cycle' argument '{}' must be a string naming a library entry", k));
      if (k.substr(0, 2) == "a." && !entry) error(op.loc, fmt::format("'cycle' argument '{}' needs entry=", k));
      if (k.substr(0, 2) == "p." && !pattern) error(op.loc, fmt::format("'cycle' argument '{}' needs pattern=", k));
    }
    bool wantsEntry = a == "run" || a == "define" || a == "modal";
    if (wantsEntry != entry)
      error(op.loc, fmt::format("'cycle' action={} {} entry=", a, wantsEntry ? "needs" : "takes no"));
    if (pattern && a != "run" && a != "call") error(op.loc, fmt::format("'cycle' action={} takes no pattern=", a));
  }

  void checkControl(const Op &op, const std::string &name_) {
    switch (op.kind) {
    case OpKind::Break:
    case OpKind::Continue:
      if (loopDepth_ == 0) error(op.loc, fmt::format("'{}' outside of a 'while' or 'loop'", name_));
      break;
    case OpKind::Goto: {
      const Expr *n = op.get("n"), *l = op.get("label");
      if (!n && !l) error(op.loc, "'goto' needs a target: n= or label=");
      if (n && l) error(op.loc, "'goto' has both n= and label=");
      if (n && n->isConstant() && n->kind != ExprKind::Number) error(op.loc, "'goto' argument 'n' must be a number");
      if (l && l->isConstant() && l->kind != ExprKind::String) error(op.loc, "'goto' argument 'label' must be a string");
      if (n && n->kind == ExprKind::Number && !targets_.blocks.count(n->num))
        error(op.loc, fmt::format("'goto' target block N{} is not in this function", n->num));
      if (l && l->kind == ExprKind::String && !targets_.labels.count(l->str))
        error(op.loc, fmt::format("'goto' target label '{}' is not in this function", l->str));
      break;
    }
    case OpKind::CallSection:  // the section's labels: constants of this function
      for (const char *key : {"from", "to"})
        if (const Expr *l = op.get(key)) {
          if (l->kind != ExprKind::String) error(op.loc, fmt::format("'call_section' argument '{}' must be a label name (a string)", key));
          else if (!targets_.labels.count(l->str))
            error(op.loc, fmt::format("'call_section' label '{}' is not in this function", l->str));
        }
      break;
    case OpKind::Cycle: checkCycle(op); break;
    case OpKind::ModalCall:
    case OpKind::Call: {
      const Expr *c = op.get("callee");
      if (!c) break;
      // A string names the function, a number n the program O<n>; computed ones are looked up
      // at run time.
      std::string name;
      if (constantCallee(*c, name)) {
        const Function *f = m_.find(name);
        if (!f) error(op.loc, fmt::format("'{}' target '{}' is not a function of this module", name_, name));
        for (auto &a : op.args) {  // a VAR parameter aliases a variable of the caller
          const Param *p = f && a.key.size() > 2 ? f->param(std::string_view(a.key).substr(2)) : nullptr;
          if (p && p->byRef && a.value && (a.value->kind != ExprKind::Var || a.value->space == VarSpace::System))
            error(op.loc, fmt::format("'{}' argument '{}' must be a variable: parameter '{}' of '@{}' is VAR", name_,
                                      a.key, p->name, f->name));
        }
      } else if (c->kind != ExprKind::Var && c->kind != ExprKind::Unary && c->kind != ExprKind::Binary &&
                 c->kind != ExprKind::Call) {
        error(op.loc, fmt::format("'{}' argument 'callee' must be a string or a program number", name_));
      }
      break;
    }
    default: break;
    }
  }

  // ---------------------------------------------------------------- what the engines run
  // The IR can express more than the eval engine and the JIT execute; until they do, these are
  // errors before running instead of wrong results (docs/IR.md §7, "What the engines run").
  // Assumes a module that passed run().
public:
  bool runnable() {
    collectDecls(m_, decls_, nullptr);
    for (auto &f : m_.functions) {
      fn_ = &f;
      for (auto &p : f.params) {
        // Defaults are evaluated in the callee when it starts: no variables of either side.
        if (p.defaultValue && usesVariable(*p.defaultValue))
          error(f.loc, fmt::format("function '@{}': default of parameter '{}' must not use variables", f.name, p.name));
        if (p.type != Type::Real && p.type != Type::Bool && p.type != Type::Int && p.type != Type::String &&
            p.type != Type::Axis && p.type != Type::Frame)
          error(f.loc, fmt::format("function '@{}': parameter '{}' of type {} is not supported yet (REAL, INT, BOOL, "
                                   "STRING, AXIS, FRAME)",
                                   f.name, p.name, typeName(p.type)));
      }
      walk(f.body);
    }
    return errors_ == 0;
  }

private:
  static bool usesVariable(const Expr &e) {
    if (e.kind == ExprKind::Var) return true;
    for (auto &a : e.args)
      if (a && usesVariable(*a)) return true;
    return false;
  }

  void walk(const Region &r) {
    for (auto &op : r) {
      if ((unsigned)op.kind < (unsigned)OpKind::Count) checkSupported(op, opInfo(op.kind).name);
      for (auto &sub : op.regions) walk(sub);
    }
  }

  // Where an argument sits ("'move' argument 'X'"), formatted only when an error needs it: this
  // check runs on every chunk of a streamed run.
  struct Where {
    std::string_view op, key;
    std::string text() const { return fmt::format("'{}' argument '{}'", op, key); }
    std::string operator+(const char *s) const { return text() + s; }
  };

  void checkSupported(const Op &op, const char *name) {
    for (auto &a : op.args) {
      const Expr *v = a.value.get();
      if (!v) continue;
      Where where{name, a.key};
      switch (argContext(op, a.key)) {
      case Ctx::Number: numericExpr(*v, op.loc, where); break;
      case Ctx::Any:
      case Ctx::Text: anyExpr(*v, op.loc, where); break;
      case Ctx::Callee:
        if (v->kind != ExprKind::Symbol) anyExpr(*v, op.loc, where);  // symbols: checkControl
        break;
      case Ctx::Constant:
        if (v->kind != ExprKind::String) error(op.loc, where + " must be a string constant");
        break;
      case Ctx::Var:
        if (v->kind != ExprKind::Var) break;  // reported by kVarRules
        if (v->space == VarSpace::System) {  // controller state: only some of it may be written
          if (variable(*v, op.loc, where) && !systemWritable(*v))
            error(op.loc, fmt::format("{}: system variable '${}' is read-only", where.text(), v->str));
          break;
        }
        if (variable(*v, op.loc, where) && op.kind != OpKind::Declare)
          for (auto &i : v->args)
            if (i) numericExpr(*i, op.loc, where);
        if (op.kind == OpKind::Assign && numericSpace(*v))
          if (const Expr *val = op.get("value"); val && (kindOf(*val) == 's' || kindOf(*val) == 'f'))
            error(op.loc, fmt::format("'assign': {}", handleMessage(HandleUse::InParameter, kindName(kindOf(*val)))));
        break;
      case Ctx::Symbol: break;  // checked against ir/OpSymbols.h / checkModes
      }
    }
    switch (op.kind) {
    case OpKind::Declare: {
      const Expr *t = op.get("type");
      if (t && t->kind == ExprKind::Symbol && lower(t->str) == "symbol")
        error(op.loc, fmt::format("'declare' type '{}' is not supported yet", t->str));
      break;
    }
    case OpKind::ModalCall:
    case OpKind::Call: {
      const Expr *f = op.get("frame");
      bool modal = op.kind == OpKind::ModalCall;  // always a new frame
      bool shared = !modal && (!f || f->str != "new");
      std::string calleeName;
      // A computed callee may be any function: an argument named like a VAR parameter of one of
      // them must be a variable it can alias. A modal call runs later, when the caller's
      // variables may be gone: no VAR arguments.
      if (const Expr *c = op.get("callee"); c && (modal || !constantCallee(*c, calleeName)))
        for (auto &a : op.args)
          for (auto &fn : m_.functions)
            if (const Param *p = a.key.size() > 2 ? fn.param(std::string_view(a.key).substr(2)) : nullptr; p && p->byRef) {
              if (modal)
                error(op.loc, fmt::format("'{}' argument '{}': a modal call cannot take VAR parameter '{}' of '@{}'",
                                          name, a.key, p->name, fn.name));
              else if (a.value && (a.value->kind != ExprKind::Var || a.value->space == VarSpace::System))
                error(op.loc, fmt::format("'{}' argument '{}' must be a variable: parameter '{}' of '@{}' is VAR "
                                          "and the callee is computed",
                                          name, a.key, p->name, fn.name));
              break;
            }
      for (auto &a : op.args) {
        if (a.key.rfind("a.", 0) != 0) continue;
        std::string k = a.key.substr(2);
        if (shared) error(op.loc, fmt::format("'call' argument '{}' needs frame=new (a shared frame takes no arguments)", a.key));
        else if (k[0] >= '0' && k[0] <= '9') {  // a Macro B local of the new frame
          char *end;
          long n = std::strtol(k.c_str(), &end, 10);
          if (*end || n < 1 || n > kMacroLocals)
            error(op.loc, fmt::format("'{}' argument '{}' must name a local #1..#{}", name, a.key, kMacroLocals));
        }
      }
      if (modal && !op.get("callee") && op.args.size())
        error(op.loc, "'modal_call' without a callee (a cancel) takes no arguments");
      break;
    }
    case OpKind::Home: {
      const Expr *r = op.get("ref");
      if (r && !(r->kind == ExprKind::Number && (r->num == 1 || r->num == 2)))
        error(op.loc, "'home' argument 'ref' must be the constant 1 or 2");
      break;
    }
    case OpKind::MachineMove:
      if (const Expr *r = op.get("rapid"); r && r->kind != ExprKind::Bool)
        error(op.loc, "'machine_move' argument 'rapid' must be true or false");
      break;
    case OpKind::WorkOffset:
      if (const Expr *i = op.get("index"); i && !(isIntConst(i) && i->num >= 0 && i->num < kUserFrames))
        error(op.loc, "'work_offset' argument 'index' must be a constant 0..99");
      break;
    default: break;
    }
  }

  // Where an argument's value is used: a number (the default), a run-time string, a call
  // target, a string constant, a variable to assign, or a symbol.
  enum class Ctx { Number, Any, Text, Callee, Constant, Var, Symbol };
  static Ctx argContext(const Op &op, const std::string &key) {
    if (op.kind == OpKind::Message && key == "text") return Ctx::Text;
    if ((op.kind == OpKind::Assign && key == "value") || (op.kind == OpKind::Declare && key == "init") ||
        (op.kind == OpKind::Return && key == "value") ||
        ((op.kind == OpKind::Call || op.kind == OpKind::ModalCall) && key.rfind("a.", 0) == 0 &&
         !(key.size() > 2 && key[2] >= '0' && key[2] <= '9')) ||
        (op.kind == OpKind::Cycle && (key.rfind("a.", 0) == 0 || key.rfind("p.", 0) == 0)))  // sema: numbers or a STRING
      return Ctx::Any;
    if (op.kind == OpKind::Declare && key == "len") return Ctx::Symbol;  // a constant (ir/Decls.cpp)
    if ((op.kind == OpKind::Move && (key == "ic" || key == "ac")) || (op.kind == OpKind::Home && key == "ic"))
      return Ctx::Symbol;  // axis letters (CmdTemplate)
    if ((op.kind == OpKind::Call || op.kind == OpKind::ModalCall) && key == "callee") return Ctx::Callee;
    if (op.kind == OpKind::Goto && key == "label") return Ctx::Text;  // a computed one: any value as text
    if ((op.kind == OpKind::Comment && key == "text") || (op.kind == OpKind::Label && key == "name") ||
        (op.kind == OpKind::CallSection && (key == "from" || key == "to")) ||
        (op.kind == OpKind::Cycle && (key == "entry" || key == "pattern")))
      return Ctx::Constant;
    for (auto &r : kVarRules)
      if (r.kind == op.kind && key == r.key) return Ctx::Var;
    if (!opSymbolValues(op.kind, key).empty()) return Ctx::Symbol;
    if (op.kind == OpKind::Mode && key != "tolerance" && key != "naive_tolerance") return Ctx::Symbol;
    return Ctx::Number;
  }

  // What an expression statically is: 's' a string (constants, symbols, concat, string
  // builtins, variables declared string/char/axis), 'f' a frame (frame builtins, FRAME
  // variables), 'n' a number, 'a' any (undeclared named variables and QS parameters hold what
  // was assigned: checked at run time).
  static const char *kindName(char k) { return k == 's' ? "string" : k == 'f' ? "frame" : "number"; }
  char kindOf(const Expr &e) const {
    switch (e.kind) {
    case ExprKind::String:
    case ExprKind::Symbol: return 's';
    case ExprKind::Binary: return e.op == OpCode::Concat ? 's' : 'n';
    case ExprKind::Call: {
      const BuiltinInfo *b = findBuiltin(e.str);
      return b ? b->result : 'n';
    }
    case ExprKind::Var: {
      if (e.space == VarSpace::QParam) return e.str == "QS" ? 'a' : 'n';
      if (e.space == VarSpace::System) return sysVarNameIsFrame(e.str) ? 'f' : 'n';
      if (e.space != VarSpace::Local && e.space != VarSpace::Global) return 'n';
      const VarDecl *d = fn_ ? decls_.find(*fn_, e) : nullptr;
      if (!d || d->type == ValueType::Any) return 'a';
      return d->type == ValueType::Frame ? 'f' : holdsHandle(d->type) ? 's' : 'n';
    }
    default: return 'n';
    }
  }
  static bool numericSpace(const Expr &v) {
    return v.space == VarSpace::Numbered || v.space == VarSpace::RParam || (v.space == VarSpace::QParam && v.str != "QS");
  }

  // A value of any kind; its operands are checked for what they must be. Reports the first
  // problem of the expression only.
  bool anyExpr(const Expr &e, SourceLoc l, const Where &where) {
    if (e.kind == ExprKind::Var && !variable(e, l, where)) return false;
    if (e.kind == ExprKind::Var) {
      for (auto &i : e.args)
        if (i && !systemAxisIndex(e, *i) && !numericExpr(*i, l, where)) return false;
      return true;
    }
    if (e.kind == ExprKind::Binary && e.args.size() == 2 && e.args[0] && e.args[1]) {
      if (e.op == OpCode::Concat) return anyExpr(*e.args[0], l, where) && anyExpr(*e.args[1], l, where);
      if (e.op >= OpCode::Eq && e.op <= OpCode::Ge) {
        char a = kindOf(*e.args[0]), b = kindOf(*e.args[1]);
        if (a == 'f' || b == 'f') {
          error(l, where + (": " + handleMessage(HandleUse::Operator, "frame", opCodeName(e.op))).c_str());
          return false;
        }
        if ((a == 's' && b == 'n') || (a == 'n' && b == 's')) {
          error(l, where + ": cannot compare a string with a number");
          return false;
        }
        return anyExpr(*e.args[0], l, where) && anyExpr(*e.args[1], l, where);
      }
    }
    if (e.kind == ExprKind::Call)
      if (const BuiltinInfo *b = findBuiltin(e.str); b && b->sfn) {
        for (size_t i = 0; i < e.args.size(); ++i) {
          if (!e.args[i]) continue;
          char want = b->argKind(i), have = kindOf(*e.args[i]);
          if ((want == 's' || want == 'f') && have != 'a' && have != want) {
            error(l, fmt::format("{}: '{}' argument {} must be a {}", where.text(), b->name, i + 1, kindName(want)));
            return false;
          }
          if (!(want == 'n' ? numericExpr(*e.args[i], l, where) : anyExpr(*e.args[i], l, where))) return false;
        }
        return true;
      }
    for (auto &a : e.args)
      if (a && !numericExpr(*a, l, where)) return false;
    return true;
  }

  // A number: a statically known string here is an error (at run time too, for 'a').
  bool numericExpr(const Expr &e, SourceLoc l, const Where &where) {
    if (char k = kindOf(e); k == 's' || k == 'f') {
      error(l, where + (": " + handleMessage(HandleUse::AsNumber, kindName(k))).c_str());
      return false;
    }
    return anyExpr(e, l, where);
  }

  // A system variable is a name of ir/SystemVars.h, or a family's base name with its indices.
  bool variable(const Expr &e, SourceLoc l, const Where &where) {
    if (e.space != VarSpace::System) return true;
    SysVar sv;
    SysFamily f;
    int dims = sysFamilyFromName(e.str, f);
    if (!dims && !sysVarFromName(e.str, sv)) {
      error(l, fmt::format("{}: system variable '${}' is not supported yet", where.text(), e.str));
      return false;
    }
    if ((int)e.args.size() != dims) {
      error(l, fmt::format("{}: system variable '${}' takes {} ind{}", where.text(), e.str, dims == 0 ? "no" : std::to_string(dims),
                           dims == 1 ? "ex" : "ices"));
      return false;
    }
    for (auto &i : e.args) {
      if (i->kind == ExprKind::Symbol && (axisIndex(i->str) < 0 || f == SysFamily::ToolData)) {
        error(l, f == SysFamily::ToolData
                     ? fmt::format("{}: '${}' takes numbers as indices, not '{}'", where.text(), e.str, i->str)
                     : fmt::format("{}: '{}' is not an axis (X Y Z A B C) in '${}'", where.text(), i->str, e.str));
        return false;
      }
      if (!systemAxisIndex(e, *i) && !numericExpr(*i, l, where)) return false;
    }
    return true;
  }
  // An axis name as a system variable's index ($_work_offset[1, X]): a number when compiled.
  static bool systemAxisIndex(const Expr &var, const Expr &index) {
    return var.space == VarSpace::System && index.kind == ExprKind::Symbol;
  }
  static bool systemWritable(const Expr &e) {
    SysFamily f;
    SysVar sv = kNoSysVar;
    if (sysFamilyFromName(e.str, f)) return sysFamilyWritable(f);  // writability is per family
    return sysVarFromName(e.str, sv) && sysVarWritable(sv);
  }

  void verifyExpr(const Expr *e, SourceLoc l, const std::string &where) {
    if (!e) {
      error(l, where + ": missing expression");
      return;
    }
    size_t n = e->args.size();
    for (auto &a : e->args)
      if (!a) {
        error(l, where + ": missing operand");
        return;
      }
    switch (e->kind) {
    case ExprKind::Number:
    case ExprKind::String:
    case ExprKind::Bool:
    case ExprKind::Symbol:
    case ExprKind::Vacant:
      if (n) error(l, where + ": a constant has operands");
      return;
    case ExprKind::Var: verifyVar(*e, l, where); break;
    case ExprKind::Unary:
      if (n != 1 || (e->op != OpCode::Neg && e->op != OpCode::Not))
        error(l, fmt::format("{}: unary '{}' with {} operand(s)", where, opCodeName(e->op), n));
      break;
    case ExprKind::Binary:
      if (n != 2 || e->op < OpCode::Add || e->op > OpCode::BXor)
        error(l, fmt::format("{}: binary '{}' with {} operand(s)", where, opCodeName(e->op), n));
      break;
    case ExprKind::Call: {
      const BuiltinInfo *b = findBuiltin(e->str);
      if (!b) error(l, fmt::format("{}: unknown function '{}'", where, e->str));
      else if (!b->accepts(n))
        error(l, fmt::format("{}: function '{}' takes {} argument{}, found {}", where, b->name, builtinArity(*b),
                             b->arity == 1 ? "" : "s", n));
      break;
    }
    default: error(l, where + ": invalid expression kind"); return;
    }
    for (auto &a : e->args) verifyExpr(a.get(), l, where);
  }

  void verifyVar(const Expr &e, SourceLoc l, const std::string &where) {
    bool named = e.space == VarSpace::Local || e.space == VarSpace::Global;
    if (e.space == VarSpace::System) return;  // a family's indices: variable()
    if (e.args.size() > (named ? kMaxArrayRank : 1))
      error(l, fmt::format("{}: a variable has more than {} ind{}", where, named ? kMaxArrayRank : 1,
                           named ? "ices" : "ex"));
    else if (named && fn_ && !where.starts_with("'declare' argument 'var'")) {
      // Declared arrays are indexed with their rank; undeclared named arrays are 1-D.
      const VarDecl *d = decls_.find(*fn_, e);
      unsigned rank = d ? d->rank : (e.args.empty() ? 0 : 1);
      if (e.args.size() != rank) {
        if (d && d->rank == 0)
          error(l, fmt::format("{}: '{}' is declared as a scalar, not an array", where, e.str));
        else if (d)
          error(l, fmt::format("{}: array '{}' is declared with {} dimension{}, indexed with {}", where, e.str,
                               d->rank, d->rank == 1 ? "" : "s", e.args.size()));
        else
          error(l, fmt::format("{}: '{}' has {} indices but is not declared as an array", where, e.str,
                               e.args.size()));
      }
    }
    switch (e.space) {
    case VarSpace::QParam:
      if (e.str != "Q" && e.str != "QL" && e.str != "QR" && e.str != "QS")
        error(l, fmt::format("{}: Q parameter prefix '{}' is not Q, QL, QR or QS", where, e.str));
      [[fallthrough]];
    case VarSpace::Numbered:
    case VarSpace::RParam:
      if (e.args.empty()) error(l, where + ": numbered parameter without a number");
      break;
    case VarSpace::Local:
    case VarSpace::Global:
    case VarSpace::System:
      if (e.str.empty()) error(l, where + ": variable without a name");
      break;
    default: error(l, where + ": invalid variable space");
    }
  }
};

}  // namespace

bool verifyModule(const Module &m, Diagnostics &diags) { return Verifier(m, diags).run(); }
bool verifyRunnable(const Module &m, Diagnostics &diags) { return Verifier(m, diags).runnable(); }

}  // namespace ncc::ir
