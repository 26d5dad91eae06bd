#include "passes/Eval.h"

#include "ir/Arith.h"
#include "ir/Builtins.h"
#include "ir/Decls.h"
#include "ir/Jumps.h"
#include "ir/RunErrors.h"
#include "ir/Strings.h"
#include "ir/SystemParams.h"
#include "ir/SystemAccess.h"
#include "ir/Value.h"
#include "passes/CmdTemplate.h"
#include "passes/EvalCode.h"
#include "passes/Operators.h"
#include "runtime/Executor.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <unordered_map>

namespace ncc {
using namespace ir;
using namespace eval;


namespace {


struct Frame {
  double locals[kMacroLocals + 1];  // [0] unused: #0 is always vacant
  std::vector<double> named;
  // By slot of `named`: the caller's variable a VAR parameter aliases (null: the own slot).
  std::vector<double *> refs;
  std::unordered_map<std::string, std::vector<double>> arrays;  // named local arrays
  std::vector<double> slots;
  uint64_t backJumps = 0;
  struct Section {  // an active call_section
    const Op *call;
    uint32_t start, ret;
    double remaining;
  };
  std::vector<Section> sections;
  double ret = unsetValue();  // `return value=`: what the caller's `call result=` receives
};

}  // namespace

struct Evaluator::Impl {
  CmdSink &sink;
  Diagnostics &diags;
  ExecLimits limits;
  const Module *module = nullptr;
  std::unordered_map<const Function *, std::unique_ptr<CompiledFn>> compiled;
  std::unordered_map<std::string, uint32_t> globalNames;
  std::unordered_map<std::string, uint32_t> mainLocalNames;
  std::deque<double> globalNamed;  // a deque: VAR parameters keep pointers into it
  std::unordered_map<std::string, std::vector<double>> globalArrays;
  double lastIndex = 0;  // index of the last array element referenced (for the unset error)
  std::vector<double> numbered = std::vector<double>(100000, numberedStart());
  ValuePool pool;  // the run's strings (ir/Strings.h)
  DeclTable decls;  // declared types of the current module
  std::vector<double> rparams = std::vector<double>(1000, rParamStart());
  std::vector<double> qparams[kQSpaces];  // by qPrefixIndex, allocated on first use
  unsigned depth = 0;
  uint64_t steps = 0;
  bool ended = false;
  std::chrono::steady_clock::time_point start;

  Impl(CmdSink &s, Diagnostics &d, const ExecLimits &l) : sink(s), diags(d), limits(l) {}

  [[noreturn]] void fail(SourceLoc loc, std::string msg) { throw EvalError{loc, std::move(msg)}; }

  CompiledFn &compile(const Function &f) {
    auto it = compiled.find(&f);
    if (it != compiled.end()) return *it->second;
    auto cf = std::make_unique<CompiledFn>();
    if (!module->functions.empty() && &f == &module->functions[0]) cf->names = &mainLocalNames;
    linearize(f, *cf, diags);
    auto &ref = *cf;
    compiled.emplace(&f, std::move(cf));
    return ref;
  }

  // ------------------------------------------------------------ values
  double &numberedRef(Frame &fr, const Expr &v, bool write) {
    const Expr &ix = *v.args[0];
    if (ix.kind == ExprKind::Call) [[unlikely]]
      return computedRef(fr, v, write);
    return numberedSlot(fr, v, num(number(fr, ix)), write);
  }
  // #[(NGC_PARAMETER e)] and the other maps (ir/SystemParams.h): the number through the map.
  [[gnu::noinline]] double &computedRef(Frame &fr, const Expr &v, bool write) {
    ParamMap map;
    const Expr *e = computedParameterNumber(v, map);
    if (!e) return numberedSlot(fr, v, num(number(fr, *v.args[0])), write);
    double n = parameterNumber(num(number(fr, *e)));
    if (plainParameter(map, n)) return numberedSlot(fr, v, n, write);
    // Controller state: read here (store writes it); a write here is a by-reference argument.
    static double value;
    std::string err;
    if (!accessSystemParameter(sink, pool, map, n, write ? ParamAccess::Reference : ParamAccess::Read, value, v.loc, err))
      fail(v.loc, err);
    return value;
  }
  double &numberedSlot(Frame &fr, const Expr &v, double idx, bool write) {
    // lround, without the library call for the usual whole number.
    long n = idx >= -1e15 && idx <= 1e15 ? (long)idx : -1;
    if ((double)n != idx) n = std::lround(idx);
    if (n >= 1 && n <= kMacroLocals) return fr.locals[n];
    if (n == 0) {
      if (write) fail(v.loc, "#0 is always vacant and cannot be assigned");
      static double vac;
      vac = vacantValue();
      return vac;
    }
    if (n < 0 || n >= (long)numbered.size()) fail(v.loc, runErrorMessage(RunError::Numbered, limits, {}, (double)n));
    return numbered[n];
  }
  // A store into a computed `#[e]`: plain storage or, through the map, controller state.
  [[gnu::noinline]] void storeComputed(const Expr &target, const Expr &e, ParamMap map, double v, Frame &fr,
                                       CompiledFn &cf) {
    v = convert(decls.find(*cf.fn, target), target, v, target.loc);  // no strings
    double n = parameterNumber(num(number(fr, e)));
    std::string err;
    if (plainParameter(map, n)) numberedSlot(fr, target, n, true) = v;
    else if (!accessSystemParameter(sink, pool, map, n, ParamAccess::Write, v, target.loc, err)) fail(target.loc, err);
  }

  double &arrayRef(std::vector<double> &arr, Frame &fr, const Expr &v, RunError outOfRange) {
    long n = v.args.empty() ? 0 : std::lround(num(number(fr, *v.args[0])));
    if (n < 0 || n >= (long)arr.size()) fail(v.loc, runErrorMessage(outOfRange, limits, {}, (double)n));
    return arr[n];
  }

  double &elemRef(std::unordered_map<std::string, std::vector<double>> &arrays, Frame &fr, const Expr &v) {
    if (const VarDecl *d = decls.find(*curFn->fn, v)) {  // declared: rank indices within the bounds
      uint64_t flat = 0;
      for (unsigned k = 0; k < d->rank; ++k) {
        double x = num(number(fr, *v.args[k]));
        if (!(x >= 0 && x < d->dims[k]) || x != std::trunc(x))
          fail(v.loc, declaredIndexMessage(v.str, x, k + 1, d->rank, d->dims[k]));
        flat = flat * d->dims[k] + (uint64_t)x;
      }
      auto &a = arrays[v.str];
      if (a.size() != d->size()) a.assign(d->size(), initialValue(d->type));
      return a[flat];
    }
    lastIndex = number(fr, *v.args[0]);
    uint32_t i;
    if (!arrayIndex(lastIndex, i)) fail(v.loc, arrayIndexMessage(v.str, lastIndex));
    auto &a = arrays[v.str];
    if (a.empty()) a.assign(kArrayElements, unsetValue());
    return a[i];
  }

  // EXISTS: a named variable exists once assigned (in this frame, for locals).
  bool exists(Frame &fr, const Expr &v) {
    if (v.kind != ExprKind::Var || !v.args.empty()) return true;
    if (v.space == VarSpace::Local) {
      auto &names = *curFn->names;
      auto it = names.find(v.str);
      return it != names.end() && it->second < fr.named.size() && !isUnset(namedSlot(fr, it->second));
    }
    if (v.space == VarSpace::Global) {
      auto it = globalNames.find(v.str);
      return it != globalNames.end() && !isUnset(globalNamed[it->second]);
    }
    return true;
  }

  // What a system variable names: `$_metric`, or a family with run-time indices
  // (`$_work_offset[s, a]`, an axis symbol as index; `$_tool_data[t, d, k]`).
  SysRef systemVar(Frame &fr, const Expr &v) {
    SysRef ref;
    SysFamily f;
    int dims = sysFamilyFromName(v.str, f);
    if (!dims) {
      sysVarFromName(v.str, ref.var);
      return ref;
    }
    double ix[3] = {0, 0, 0};
    for (int k = 0; k < dims && k < (int)v.args.size(); ++k)
      ix[k] = v.args[k]->kind == ExprKind::Symbol ? axisIndex(v.args[k]->str) : num(number(fr, *v.args[k]));
    ref = sysVarAt(f, ix[0], ix[1], ix[2]);
    if (ref.var == kNoSysVar) fail(v.loc, sysVarIndexMessage(v.str, f, ix[0], ix[1], ix[2]));
    return ref;
  }

  double &varRef(Frame &fr, CompiledFn &cf, const Expr &v, bool write) {
    if (!v.args.empty() && v.space == VarSpace::Local) return elemRef(fr.arrays, fr, v);
    if (!v.args.empty() && v.space == VarSpace::Global) return elemRef(globalArrays, fr, v);
    switch (v.space) {
    case VarSpace::Numbered: return numberedRef(fr, v, write);
    case VarSpace::RParam: return arrayRef(rparams, fr, v, RunError::RParam);
    case VarSpace::QParam: {
      int q = qPrefixIndex(v.str);
      if (q < 0) fail(v.loc, fmt::format("unknown Q parameter prefix '{}'", v.str));
      auto &arr = qparams[q];
      if (arr.empty()) arr.assign(2000, qParamStart(q));
      return arrayRef(arr, fr, v, RunError::QParam);
    }
    case VarSpace::Local: {
      auto it = (*cf.names).find(v.str);
      if (it == (*cf.names).end()) {
        if (!write) fail(v.loc, runErrorMessage(RunError::UnsetVar, limits, v.str));
        it = (*cf.names).emplace(v.str, (uint32_t)(*cf.names).size()).first;
      }
      if (fr.named.size() <= it->second) fr.named.resize((*cf.names).size(), unsetValue());
      return namedSlot(fr, it->second);
    }
    case VarSpace::Global: {
      auto it = globalNames.find(v.str);
      if (it == globalNames.end()) {
        if (!write) fail(v.loc, runErrorMessage(RunError::UnsetVar, limits, v.str));
        it = globalNames.emplace(v.str, (uint32_t)globalNames.size()).first;
        globalNamed.push_back(unsetValue());
      }
      return globalNamed[it->second];
    }
    case VarSpace::System: {  // read here; execAssign writes
      static double value;
      std::string err;
      if (!readSystemValue(sink, pool, systemVar(fr, v), value, err))
        fail(v.loc, err.empty() ? runErrorMessage(RunError::SysVar, limits, v.str) : err);
      return value;
    }
    }
    fail(v.loc, "bad variable");
  }

  CompiledFn *curFn = nullptr;

  static double &namedSlot(Frame &fr, uint32_t slot) {
    return slot < fr.refs.size() && fr.refs[slot] ? *fr.refs[slot] : fr.named[slot];
  }

  double ev(Frame &fr, const Expr &e) {
    switch (e.kind) {
    case ExprKind::Number:
    case ExprKind::Bool: return e.num;
    case ExprKind::Vacant: return vacantValue();
    case ExprKind::String:
    case ExprKind::Symbol: return intern(e.str, e.loc);
    case ExprKind::Var: {
      double v = varRef(fr, *curFn, e, false);
      if (isUnset(v))
        fail(e.loc, e.args.empty() ? runErrorMessage(RunError::UnsetVar, limits, e.str)
                                   : unsetElementMessage(e.str, lastIndex));
      return v;
    }
    case ExprKind::Unary: {
      double r, a = ev(fr, *e.args[0]);
      if (isHandle(a)) fail(e.loc, operatorOnHandle(e.op, a));
      if (applyUnary(e.op, a, r) != OpStatus::Ok) fail(e.loc, "bad unary operator");
      return r;
    }
    case ExprKind::Binary: {
      if (e.op == OpCode::Concat) {  // the text of the whole concat chain, one new string
        std::string t;
        appendStr(fr, e, t);
        return intern(t, e.loc);
      }
      // Both sides are always evaluated (no short-circuit in Macro B).
      double a = ev(fr, *e.args[0]);
      double b = ev(fr, *e.args[1]);
      double r;
      if (isHandle(a) || isHandle(b)) {
        std::string err;
        if (e.op < OpCode::Eq || e.op > OpCode::Ge) fail(e.loc, operatorOnHandle(e.op, isHandle(a) ? a : b));
        if (!compareStrings(pool, (int)e.op - (int)OpCode::Eq, a, b, r, err)) fail(e.loc, err);
        return r;
      }
      switch (applyBinary(e.op, a, b, r)) {
      case OpStatus::Ok: return r;
      case OpStatus::DivByZero: fail(e.loc, "division by zero");
      case OpStatus::NotInteger: fail(e.loc, bitwiseOperandMessage(opCodeName(e.op)));
      case OpStatus::NotNumeric:
        fail(e.loc, fmt::format("operator '{}' is not supported on numbers", opCodeName(e.op)));
      }
      return r;
    }
    case ExprKind::Call: {
      if (isExistsCall(e.str, e.args.size()) && e.args[0]) return exists(fr, *e.args[0]) ? 1.0 : 0.0;
      const BuiltinInfo *b = findBuiltin(e.str);
      if (!b) fail(e.loc, fmt::format("unknown function '{}'", e.str));
      if (!b->accepts(e.args.size()))
        fail(e.loc, fmt::format("'{}' takes {} argument(s), {} given", b->name, builtinArity(*b), e.args.size()));
      double args[kMaxBuiltinArgs] = {};
      for (size_t i = 0; i < e.args.size() && i < kMaxBuiltinArgs; ++i) args[i] = ev(fr, *e.args[i]);
      double r;
      if (b->sfn) {  // typed builtins (strings, frames) take the values as they are
        std::string err;
        if (!b->sfn(pool, args, (unsigned)e.args.size(), r, err)) fail(e.loc, err);
        return r;
      }
      for (double &a : args) {
        if (isHandle(a)) fail(e.loc, handleMessage(HandleUse::Builtin, handleKind(a), b->name));
        a = num(a);
      }
      r = b->fn(args);
      if (std::isnan(r)) fail(e.loc, builtinDomainError(*b));
      return r;
    }
    }
    fail(e.loc, "bad expression");
  }

  static std::string operatorOnHandle(OpCode op, double v) {
    return handleMessage(HandleUse::Operator, handleKind(v), opCodeName(op));
  }

  double intern(std::string_view s, SourceLoc loc) {
    double h;
    std::string err;
    if (!pool.intern(s, h, err)) fail(loc, err);
    return h;
  }

  // A value used as a number (conditions, counts, indices, words): a string is an error.
  double number(Frame &fr, const Expr &e) {
    double v = ev(fr, e);
    if (isHandle(v)) fail(e.loc, handleMessage(HandleUse::AsNumber, handleKind(v)));
    return v;
  }

  // A string expression's text; numeric operands as numberText, or fixedNumberText (ir/Value.h).
  void appendStr(Frame &fr, const Expr &e, std::string &out, bool fixed = false) {
    if (e.kind == ExprKind::String) out += e.str;
    else if (e.kind == ExprKind::Binary && e.op == OpCode::Concat) {
      appendStr(fr, *e.args[0], out, fixed);
      appendStr(fr, *e.args[1], out, fixed);
    } else if (fixed && !exists(fr, e)) {
      out += fixedNumberText(unsetValue());  // LinuxCNC prints an unknown parameter as ######
    } else out += valueText(pool, ev(fr, e), fixed);
  }

  // The function a callee expression names: a string, or a number meaning the program O<n>.
  const Function &callee(Frame &fr, const Expr &e, SourceLoc loc) {
    std::string name;
    if (e.isStringExpr()) appendStr(fr, e, name);
    else if (double v = ev(fr, e); isString(v)) name = pool.text(v);
    else if (!programName(v, name)) fail(loc, badProgramNumberMessage(v));
    const Function *f = module->find(name);
    if (!f) fail(loc, unknownProgramMessage(name));
    return *f;
  }

  // ------------------------------------------------------------ execution
  void checkTime(SourceLoc loc) {
    if ((++steps & 0xffff) == 0 && limits.maxSeconds > 0) {
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (s > limits.maxSeconds)
        fail(loc, runErrorMessage(RunError::TimeLimit, limits));
    }
  }

  std::string text;  // the last message text built at run time (the sink copies it)

  void execMachine(const CmdTemplate &t, Frame &fr) {
    if (t.slots.empty() && !t.text) return issue(t.base, fr);  // all constant: no copy
    MachineCmd cmd = t.base;
    if (t.text) {
      text.clear();
      appendStr(fr, *t.text, text, cmd.kind == CmdKind::Message && cmd.sub != (uint8_t)MessageKind::Msg);
      cmd.text = text.c_str();
    }
    for (const CmdSlot &s : t.slots) {
      double v = number(fr, *s.expr);
      if (isVacant(v)) continue;
      if (!std::isfinite(v)) fail(s.expr->loc, "value is not a finite number");
      cmd.set(s.word, v);
    }
    issue(cmd, fr);
  }

  // `cmd` may be a template's own command: read before a modal call runs other code.
  void issue(const MachineCmd &cmd, Frame &fr) {
    const bool end = cmd.kind == CmdKind::Stop &&
                     (cmd.sub == (uint8_t)StopKind::End || cmd.sub == (uint8_t)StopKind::EndRewind);
    const SourceLoc loc = cmd.loc;
    if (!sink.exec(cmd)) throw ProgramEnd{};  // the sink reported the error
    if (cmd.kind == CmdKind::Move && !modal.callee.empty() && !inModal) runModal(loc, fr);
    if (end) {
      ended = true;
      throw ProgramEnd{};
    }
  }

  void execAssign(const Expr *target, const Expr *value, bool declare, Frame &fr, CompiledFn &cf) {
    const VarDecl *d = decls.find(*cf.fn, *target);
    double v = value ? ev(fr, *value) : declare ? initialValue(d ? d->type : ValueType::Real) : vacantValue();
    if (isUnset(v)) v = vacantValue();
    if (declare && d && d->rank) {  // an array declaration sets every element
      v = convert(d, *target, v, target->loc);
      auto &arrays = target->space == VarSpace::Global ? globalArrays : fr.arrays;
      arrays[target->str].assign(d->size(), v);
      return;
    }
    store(*target, v, fr, cf);
  }

  // A store into a variable: the value converted for it (its declared type, numeric spaces);
  // a system variable goes to the executor.
  void store(const Expr &target, double v, Frame &fr, CompiledFn &cf) {
    if (target.space == VarSpace::System) {
      std::string err;
      if (!writeSystemValue(sink, pool, systemVar(fr, target), v, target.loc, err)) fail(target.loc, err);
      return;
    }
    ParamMap map;
    if (target.space == VarSpace::Numbered && target.args[0]->kind == ExprKind::Call) [[unlikely]]
      if (const Expr *e = computedParameterNumber(target, map)) return storeComputed(target, *e, map, v, fr, cf);
    v = convert(decls.find(*cf.fn, target), target, v, target.loc);
    varRef(fr, cf, target, true) = v;
  }

  // What a store into `target` keeps: converted to its declared type; numeric parameters take
  // no strings.
  double convert(const VarDecl *d, const Expr &target, double v, SourceLoc loc) {
    if (d) {
      std::string err;
      if (!convertForStore(pool, d->type, d->len, target.str, v, v, err)) fail(loc, err);
    } else if (isHandle(v) && (target.space == VarSpace::Numbered || target.space == VarSpace::RParam ||
                               target.space == VarSpace::QParam)) {
      if (isFrame(v) || target.space != VarSpace::QParam || target.str != "QS")
        fail(loc, handleMessage(HandleUse::InParameter, handleKind(v)));
    }
    return v;
  }

  // Declared variables hold their type's initial value from the start of their scope: locals
  // at each activation, globals from the start of the run.
  std::unordered_map<std::string, bool> globalsStarted;
  void startDeclared(const Function &f, CompiledFn &cf, Frame &fr) {
    // Parameters the call omitted (still unset, never aliased): the default, else the type's
    // initial value (docs/IR.md §5.1).
    for (auto &p : f.params) {
      uint32_t slot = localSlot(cf, p.name);
      if (fr.named.size() <= slot) fr.named.resize((*cf.names).size(), unsetValue());
      if ((slot < fr.refs.size() && fr.refs[slot]) || !isUnset(fr.named[slot])) continue;
      const VarDecl *d = decls.find(f, VarSpace::Local, p.name);
      double v = p.defaultValue ? ev(fr, *p.defaultValue) : initialValue(d ? d->type : ValueType::Real);
      fr.named[slot] = convert(d, *Expr::var(VarSpace::Local, p.name), v, f.loc);
    }
    auto it = decls.locals.find(&f);
    if (it != decls.locals.end())
      for (auto &[name, d] : it->second) {
        if (d.param) continue;
        if (d.rank) fr.arrays[name].assign(d.size(), initialValue(d.type));
        else {
          uint32_t slot = localSlot(cf, name);
          if (fr.named.size() <= slot) fr.named.resize((*cf.names).size(), unsetValue());
          fr.named[slot] = initialValue(d.type);
        }
      }
    for (auto &[name, d] : decls.globals) {
      if (globalsStarted[name]) continue;
      globalsStarted[name] = true;
      if (d.rank) globalArrays[name].assign(d.size(), initialValue(d.type));
      else {
        auto g = globalNames.emplace(name, (uint32_t)globalNames.size());
        if (g.second) globalNamed.push_back(unsetValue());
        globalNamed[g.first->second] = initialValue(d.type);
      }
    }
  }

  // Straight-line code (a streamed chunk, a flat program) runs op by op without linearising:
  // one reused template instead of one per op.
  static bool isStraightLine(const Region &r) {
    for (const Op &op : r)
      if (!isMachineOp(op.kind) && op.kind != OpKind::Assign && op.kind != OpKind::Declare) return false;
    return true;
  }

  void runStraightLine(const Function &f, Frame &fr) {
    CompiledFn cf;
    cf.fn = &f;
    cf.names = &mainLocalNames;
    curFn = &cf;
    startDeclared(f, cf, fr);
    CmdTemplate t;
    for (const Op &op : f.body) {
      if (isMachineOp(op.kind)) {
        if (!buildCmdTemplate(op, t, diags)) fail(op.loc, "invalid machine operation");
        execMachine(t, fr);
      } else {
        bool assign = op.kind == OpKind::Assign;
        const Expr *target = op.get(assign ? "target" : "var");
        if (!target || target->kind != ExprKind::Var) fail(op.loc, "assignment target is not a variable");
        execAssign(target, op.get(assign ? "value" : "init"), !assign, fr, cf);
      }
    }
    curFn = nullptr;
  }

  void runFunction(const Function &f, Frame &fr) {
    CompiledFn &cf = compile(f);
    CompiledFn *saved = curFn;
    curFn = &cf;
    fr.slots.assign(cf.slots, 0.0);
    startDeclared(f, cf, fr);
    const auto &code = cf.code;
    uint32_t pc = 0;
    while (true) {
      const Instr &in = code[pc];
      switch (in.kind) {
      case IK::Machine:
        execMachine(cf.templates[in.slot], fr);
        ++pc;
        break;
      case IK::Assign:
      case IK::Declare:
        execAssign(in.target, in.expr, in.kind == IK::Declare, fr, cf);
        ++pc;
        break;
      case IK::JumpIfFalse: pc = truthy(number(fr, *in.expr)) ? pc + 1 : in.jump; break;
      case IK::Jump:
        if (in.backward) countBackJump(fr, in.op->loc);
        pc = in.jump;
        break;
      case IK::JumpComputed: {
        uint32_t to = computedJump(cf, *in.op, *in.expr, pc, fr);
        if (to <= pc) countBackJump(fr, in.op->loc);
        pc = to;
        break;
      }
      case IK::LoopEnter: fr.slots[in.slot] = 0; ++pc; break;
      case IK::LoopBack:
        if (++fr.slots[in.slot] >= (double)limits.maxLoopIterations)
          fail(in.op->loc, runErrorMessage(RunError::LoopLimit, limits));
        checkTime(in.op->loc);
        pc = in.jump;
        break;
      case IK::CountInit:
        fr.slots[in.slot] = in.expr ? std::round(num(number(fr, *in.expr))) : -1.0;
        ++pc;
        break;
      case IK::CountTest: {
        double &rem = fr.slots[in.slot];
        if (rem == 0) {
          pc = in.jump;
        } else {
          if (rem > 0) rem -= 1;
          ++pc;
        }
        break;
      }
      case IK::Call: call(*in.op, fr); curFn = &cf; ++pc; break;
      case IK::ModalCall: setModal(*in.op, fr); ++pc; break;
      case IK::ModalTrigger:  // as after a move: not inside the modal callee itself; the executor's modal cycle too
        if (!sink.exec(cycleTriggerCmd(in.op->loc))) throw ProgramEnd{};
        if (!modal.callee.empty() && !inModal) runModal(in.op->loc, fr);
        ++pc;
        break;
      case IK::SectionCall: {
        double n = in.expr ? std::round(num(number(fr, *in.expr))) : 1;
        if (!(n >= 1)) {
          ++pc;
          break;
        }
        if (fr.sections.size() >= kMaxSectionDepth) fail(in.op->loc, sectionDepthMessage());
        fr.sections.push_back({in.op, in.jump, pc + 1, n});
        pc = in.jump;
        break;
      }
      case IK::SectionEnd: {
        if (fr.sections.empty() ||
            std::find(in.calls->begin(), in.calls->end(), fr.sections.back().call) == in.calls->end()) {
          ++pc;
          break;
        }
        auto &sec = fr.sections.back();
        checkTime(sec.call->loc);
        if (--sec.remaining > 0) {
          pc = sec.start;
        } else {
          pc = sec.ret;
          fr.sections.pop_back();
        }
        break;
      }
      case IK::Return:
        if (const Expr *v = in.op ? in.op->get("value") : nullptr) fr.ret = ev(fr, *v);
        curFn = saved;
        return;
      }
    }
  }

  void countBackJump(Frame &fr, SourceLoc loc) {
    if (++fr.backJumps > limits.maxLoopIterations)
      fail(loc, runErrorMessage(RunError::BackJump, limits));
    checkTime(loc);
  }

  // A goto's target computed now: n= a number, label= any value as text (ir/Jumps.h).
  uint32_t computedJump(CompiledFn &cf, const Op &go, const Expr &target, uint32_t pc, Frame &fr) {
    bool label = go.get("label");
    double n = NAN;
    std::string name;
    if (label) appendStr(fr, target, name);
    else n = num(number(fr, target));
    int64_t t = findJump(cf.jumps.data(), cf.jumps.size(), label, n, name, pc, jumpDir(go));
    if (t < 0) fail(go.loc, missingJumpMessage(label, n, name));
    return cf.jumps[t].pos;
  }

  // The a.<key> arguments of a call, evaluated once in the caller's frame: numbered ones for
  // #1..#33, named ones converted for the callee's typed parameters, VAR ones as the address of
  // the caller's variable.
  struct CallArgs {
    std::vector<std::pair<long, double>> numbered;
    std::vector<std::pair<std::string, double>> named;
    std::vector<std::pair<std::string, double *>> refs;
  };
  CallArgs evalArgs(const Op &op, const Function &f, Frame &fr) {
    CallArgs out;
    for (auto &a : op.args) {
      if (a.key.rfind("a.", 0) != 0) continue;
      std::string k = a.key.substr(2);
      if (const Param *p = f.param(k); p && p->byRef) {
        out.refs.push_back({k, &varRef(fr, *curFn, *a.value, true)});
        continue;
      }
      double v = ev(fr, *a.value);
      if (!k.empty() && k[0] >= '0' && k[0] <= '9') {
        if (isHandle(v)) fail(op.loc, handleMessage(HandleUse::InParameter, handleKind(v)));
        out.numbered.push_back({std::atol(k.c_str()), v});
      } else {
        // A typed parameter converts its argument (ir/Strings.h convertForStore).
        if (const VarDecl *d = decls.find(f, VarSpace::Local, k)) {
          std::string err;
          if (!convertForStore(pool, d->type, d->len, k, v, v, err)) fail(op.loc, err);
        }
        out.named.push_back({k, v});
      }
    }
    return out;
  }

  void checkDepth(SourceLoc loc) {
    if (depth + 1 > limits.maxCallDepth)
      fail(loc, runErrorMessage(RunError::CallDepth, limits));
  }

  void call(const Op &op, Frame &fr) {
    const Expr *calleeE = op.get("callee");
    if (!calleeE) fail(op.loc, unknownProgramMessage("?"));
    const Function *f = &callee(fr, *calleeE, op.loc);
    const Expr *countE = op.get("count");
    double count = countE ? num(number(fr, *countE)) : 1;
    const Expr *frameE = op.get("frame");
    bool newFrame = frameE && frameE->str == "new";
    checkDepth(op.loc);
    CallArgs args = evalArgs(op, *f, fr);
    double ret = invoke(*f, args, newFrame, count, op.loc, fr);
    if (const Expr *result = op.get("result")) {
      if (isUnset(ret)) fail(op.loc, noReturnValueMessage());
      store(*result, ret, fr, *curFn);
    }
  }

  // Runs `f` llround(count) times with the evaluated arguments; the last repetition's return
  // value (unset: none).
  double invoke(const Function &f, const CallArgs &args, bool newFrame, double count, SourceLoc loc, Frame &fr) {
    ++depth;
    double ret = unsetValue();
    for (long i = 0; i < (long)std::llround(count); ++i) {
      checkTime(loc);  // a huge repeat count must still stop at the run-time limit
      if (f.save && !sink.saveModal()) throw ProgramEnd{};
      if (newFrame) {
        Frame nf;
        for (double &l : nf.locals) l = vacantValue();
        for (auto &[n, v] : args.numbered)
          if (n >= 1 && n <= kMacroLocals) nf.locals[n] = v;
        CompiledFn &cf = compile(f);
        for (auto &[n, v] : args.named) localSlot(cf, n);  // the callee may only read it
        for (auto &[n, r] : args.refs) localSlot(cf, n);
        nf.named.assign((*cf.names).size(), unsetValue());
        nf.refs.assign((*cf.names).size(), nullptr);
        for (auto &[n, v] : args.named) nf.named[(*cf.names).at(n)] = v;
        for (auto &[n, r] : args.refs) nf.refs[(*cf.names).at(n)] = r;
        runFunction(f, nf);
        ret = nf.ret;
      } else {
        Frame shared;
        std::memcpy(shared.locals, fr.locals, sizeof fr.locals);
        runFunction(f, shared);
        std::memcpy(fr.locals, shared.locals, sizeof fr.locals);
        ret = shared.ret;
      }
      if (f.save && !sink.restoreModal(loc)) throw ProgramEnd{};  // SAVE: the caller's modes again
    }
    --depth;
    return ret;
  }

  // modal_call (docs/IR.md §5.5): the callee and arguments set by the last one; after each move
  // executed outside the modal callee, the callee runs with them in a new frame.
  struct ModalCall {
    std::string callee;  // empty: none (resolved again at each call: a streamed chunk is a new module)
    double count = 1;    // calls per move (Fanuc G66 L)
    CallArgs args;
  };
  ModalCall modal;
  bool inModal = false;

  void setModal(const Op &op, Frame &fr) {
    modal = ModalCall();
    const Expr *calleeE = op.get("callee");
    if (!calleeE) return;
    const Function &f = callee(fr, *calleeE, op.loc);
    const Expr *countE = op.get("count");
    modal.count = countE ? num(number(fr, *countE)) : 1;
    modal.args = evalArgs(op, f, fr);
    modal.callee = f.name;
  }

  void runModal(SourceLoc loc, Frame &fr) {
    const Function *f = module->find(modal.callee);
    if (!f) fail(loc, unknownProgramMessage(modal.callee));
    checkDepth(loc);
    inModal = true;
    invoke(*f, modal.args, true, modal.count, loc, fr);
    inModal = false;
  }

  // The main program's frame outlives run() so a streamed program (run chunk by chunk) keeps
  // its locals between chunks.
  Frame mainFrame;
  bool started = false;
  bool trusted = false;  // skip verifyRunnable (trustInput)

  bool run(const Module &m) {
    module = &m;
    compiled.clear();  // a new module (or chunk) may reuse addresses of the last one
    if (m.functions.empty()) return true;
    if (!trusted && !verifyRunnable(m, diags)) return false;
    decls = DeclTable();
    collectDecls(m, decls, nullptr);
    if (!started) {
      start = std::chrono::steady_clock::now();
      for (double &l : mainFrame.locals) l = vacantValue();
      started = true;
    }
    if (ended) return true;
    try {
      if (m.functions.size() == 1 && isStraightLine(m.functions[0].body))
        runStraightLine(m.functions[0], mainFrame);
      else
        runFunction(m.functions[0], mainFrame);
    } catch (const EvalError &e) {
      diags.error(e.loc, e.message);
      return false;
    } catch (const ProgramEnd &) {
      return !diags.hasErrors();
    }
    return true;
  }
};

Evaluator::Evaluator(CmdSink &sink, Diagnostics &diags, const ExecLimits &limits)
    : impl_(std::make_unique<Impl>(sink, diags, limits)) {}
Evaluator::~Evaluator() = default;
bool Evaluator::run(const Module &m) { return impl_->run(m); }
bool Evaluator::ended() const { return impl_->ended; }

void Evaluator::trustInput(bool trusted) { impl_->trusted = trusted; }

}  // namespace ncc
