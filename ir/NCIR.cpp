#include "ir/NCIR.h"
#include "ir/MachineCmd.h"
#include "ir/Value.h"

#include <fmt/format.h>

#include <cstring>

namespace ncc::ir {

const char *typeName(Type t) {
  static const char *names[] = {"unknown", "void", "bool", "int", "real", "string", "symbol", "axis", "frame"};
  return names[(unsigned)t];
}

const char *opCodeName(OpCode op) {
  static const char *names[] = {"none", "neg", "not", "add", "sub", "mul", "div", "mod", "pow", "idiv",
                                "eq",   "ne",  "lt",  "le",  "gt",  "ge",  "and", "or",  "xor", "concat",
                                "band", "bor", "bxor"};
  return names[(unsigned)op];
}

namespace {
// A bounded free list per thread: enough for a streamed chunk's expressions; beyond it nodes
// go back to the heap, so a large module freed at once does not stay pooled. No destructor:
// the nodes left at thread exit are reclaimed with the process (or leaked by a finished thread).
struct ExprFreeList {
  void *head = nullptr;
  size_t count = 0;
};
// Under AddressSanitizer the pool is off, so a use after free of an expression stays visible.
#if defined(__SANITIZE_ADDRESS__)
constexpr size_t kExprPoolMax = 0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr size_t kExprPoolMax = 0;
#else
constexpr size_t kExprPoolMax = 16384;
#endif
#else
constexpr size_t kExprPoolMax = 16384;
#endif
thread_local ExprFreeList tExprFree;
}  // namespace

void *Expr::operator new(std::size_t size) {
  ExprFreeList &fl = tExprFree;
  if (size == sizeof(Expr) && fl.head) {
    void *p = fl.head;
    fl.head = *static_cast<void **>(p);
    --fl.count;
    return p;
  }
  return ::operator new(size);
}

void Expr::operator delete(void *p, std::size_t size) noexcept {
  ExprFreeList &fl = tExprFree;
  if (p && size == sizeof(Expr) && fl.count < kExprPoolMax) {
    *static_cast<void **>(p) = fl.head;
    fl.head = p;
    ++fl.count;
    return;
  }
  ::operator delete(p);
}

ExprPtr Expr::number(double v, Type t, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Number;
  e->type = t;
  e->num = v;
  e->loc = loc;
  return e;
}
ExprPtr Expr::string(std::string s, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::String;
  e->type = Type::String;
  e->str = std::move(s);
  e->loc = loc;
  return e;
}
ExprPtr Expr::boolean(bool b, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Bool;
  e->type = Type::Bool;
  e->num = b ? 1 : 0;
  e->loc = loc;
  return e;
}
ExprPtr Expr::symbol(std::string s, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Symbol;
  e->type = Type::Symbol;
  e->str = std::move(s);
  e->loc = loc;
  return e;
}
ExprPtr Expr::vacant(SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Vacant;
  e->type = Type::Real;
  e->loc = loc;
  return e;
}
ExprPtr Expr::var(VarSpace space, std::string name, ExprPtr index, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Var;
  e->space = space;
  e->str = std::move(name);
  if (index) e->args.push_back(std::move(index));
  e->loc = loc;
  return e;
}
ExprPtr Expr::unary(OpCode op, ExprPtr a, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Unary;
  e->op = op;
  e->args.push_back(std::move(a));
  e->loc = loc;
  return e;
}
ExprPtr Expr::binary(OpCode op, ExprPtr a, ExprPtr b, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Binary;
  e->op = op;
  e->args.push_back(std::move(a));
  e->args.push_back(std::move(b));
  e->loc = loc;
  return e;
}
ExprPtr Expr::call(std::string fn, std::vector<ExprPtr> args, SourceLoc loc) {
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Call;
  e->str = std::move(fn);
  e->args = std::move(args);
  e->loc = loc;
  return e;
}

ExprPtr Expr::clone() const {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->type = type;
  e->op = op;
  e->space = space;
  e->loc = loc;
  e->num = num;
  e->str = str;
  for (auto &a : args) e->args.push_back(a->clone());
  return e;
}

bool constantCallee(const Expr &callee, std::string &name) {
  if (callee.kind == ExprKind::String) {
    name = callee.str;
    return true;
  }
  return callee.kind == ExprKind::Number && programName(callee.num, name);
}

// The keys of `mode` are the mode groups (MachineCmd::modes has one slot per group) and the
// G64 tolerances, which are words (P, Q).
static constexpr char kModeKeys[] =
    "motion plane units distance arc_distance feed_mode retract path_mode spline_start spline_end stop_once wear_system";
static constexpr char kModeOpKeys[] =
    "motion plane units distance arc_distance feed_mode retract path_mode spline_start spline_end stop_once wear_system "
    "tolerance "
    "naive_tolerance";
static constexpr size_t countWords(std::string_view s) {
  size_t n = 0;
  for (size_t i = 0; i < s.size(); ++i) n += s[i] != ' ' && (i == 0 || s[i - 1] == ' ');
  return n;
}
static_assert(countWords(kModeKeys) == kMaxModes, "MachineCmd::modes must hold every key of 'mode'");

// The op table: textual name, region counts, required and allowed argument keys.
static const OpInfo kOps[] = {
    {OpKind::Block, "block", 0, 0, "", "n skip"},
    {OpKind::Comment, "comment", 0, 0, "text", ""},
    {OpKind::Message, "message", 0, 0, "text", "kind"},
    {OpKind::Mode, "mode", 0, 0, "", kModeOpKeys},
    {OpKind::Feed, "feed", 0, 0, "value", ""},
    {OpKind::Speed, "speed", 0, 0, "", "value mode limit after_css"},
    {OpKind::ToolSelect, "tool_select", 0, 0, "value", ""},
    {OpKind::ToolChange, "tool_change", 0, 0, "", "number"},
    {OpKind::Spindle, "spindle", 0, 0, "dir", "angle way wait"},
    {OpKind::Coolant, "coolant", 0, 0, "", "flood mist"},
    {OpKind::Dwell, "dwell", 0, 0, "seconds", ""},
    {OpKind::Move, "move", 0, 0, "", "X Y Z A B C U V W I J K R P Q L H E polar_r polar_a chamfer chamfer_leg round via_x via_y via_z opening weight degree poly_index interval denominator dlead fanuc_cycle ic ac"},
    {OpKind::Home, "home", 0, 0, "ref", "X Y Z A B C U V W ic"},
    {OpKind::MachineMove, "machine_move", 0, 0, "rapid", "X Y Z A B C U V W"},
    {OpKind::ToolLength, "tool_length", 0, 0, "", "h D dl form X Y Z A B C U V W"},
    {OpKind::CutterComp, "cutter_comp", 0, 0, "side", "d d_default entry radius orientation"},
    {OpKind::WorkOffset, "work_offset", 0, 0, "index", ""},
    {OpKind::SetOffset, "set_offset", 0, 0, "kind", "index X Y Z A B C U V W R H D Q"},
    {OpKind::Stop, "stop", 0, 0, "kind", ""},
    {OpKind::Aux, "aux", 0, 0, "", "m b h index value input"},
    {OpKind::Frame, "frame", 0, 0, "slot action", "form combine tilt position X Y Z A B C U V W I J K R F H P Q E"},
    {OpKind::Contour, "contour", 0, 0, "action",
     "use U W R D E I P Q type depth infeed surface clearance height stepover overlap side_allowance floor_allowance direction "
     "plunge_feed feed retract_feed corner_radius finish_allowance extension T"},
    {OpKind::Cycle, "cycle", 0, 0, "", "*"},
    {OpKind::Declare, "declare", 0, 0, "var type", "init len"},
    {OpKind::Assign, "assign", 0, 0, "target value", ""},
    {OpKind::If, "if", 1, 2, "cond", ""},
    {OpKind::While, "while", 1, 1, "cond", "id"},
    {OpKind::Loop, "loop", 1, 1, "", "count"},
    {OpKind::Break, "break", 0, 0, "", ""},
    {OpKind::Continue, "continue", 0, 0, "", ""},
    {OpKind::Label, "label", 0, 0, "name", ""},
    {OpKind::Goto, "goto", 0, 0, "", "n label dir"},
    {OpKind::Call, "call", 0, 0, "callee", "*"},
    {OpKind::Return, "return", 0, 0, "", "value"},
    {OpKind::CallSection, "call_section", 0, 0, "from", "to count"},
    {OpKind::ModalCall, "modal_call", 0, 0, "", "*"},
    {OpKind::ModalTrigger, "modal_trigger", 0, 0, "", ""},
};
static_assert(sizeof(kOps) / sizeof(kOps[0]) == (size_t)OpKind::Count, "op table out of sync");

const OpInfo &opInfo(OpKind k) { return kOps[(unsigned)k]; }

bool opKindFromName(std::string_view name, OpKind &out) {
  for (auto &i : kOps)
    if (name == i.name) {
      out = i.kind;
      return true;
    }
  return false;
}

Op Op::clone() const {
  Op o(kind, loc);
  for (auto &a : args) o.args.push_back({a.key, a.value ? a.value->clone() : nullptr});
  for (auto &r : regions) {
    Region nr;
    nr.reserve(r.size());
    for (auto &op : r) nr.push_back(op.clone());
    o.regions.push_back(std::move(nr));
  }
  return o;
}

const Expr *Op::get(std::string_view key) const {
  for (auto &a : args)
    if (a.key == key) return a.value.get();
  return nullptr;
}
Expr *Op::get(std::string_view key) {
  for (auto &a : args)
    if (a.key == key) return a.value.get();
  return nullptr;
}
Op &Op::set(std::string key, ExprPtr value) {
  for (auto &a : args)
    if (a.key == key) {
      a.value = std::move(value);
      return *this;
    }
  args.push_back({std::move(key), std::move(value)});
  return *this;
}
bool Op::erase(std::string_view key) {
  for (size_t i = 0; i < args.size(); ++i)
    if (args[i].key == key) {
      args.erase(args.begin() + i);
      return true;
    }
  return false;
}

const char *dialectName(Dialect d) {
  static const char *names[] = {"iso", "sinumerik", "heidenhain", "cldata", "unknown"};
  return names[(unsigned)d];
}
bool dialectFromName(std::string_view s, Dialect &out) {
  for (unsigned i = 0; i < 4; ++i)
    if (s == dialectName((Dialect)i)) {
      out = (Dialect)i;
      return true;
    }
  return false;
}

Function *Module::find(std::string_view name) {
  for (auto &f : functions)
    if (f.name == name) return &f;
  return nullptr;
}
const Function *Module::find(std::string_view name) const {
  for (auto &f : functions)
    if (f.name == name) return &f;
  return nullptr;
}

Dialect functionDialect(const Module &m, const Function &f) {
  return f.dialect == Dialect::Unknown ? m.dialect : f.dialect;
}

bool linkModule(Module &into, Module &&from, Diagnostics &diags) {
  bool ok = true;
  for (Function &f : from.functions) {
    if (into.find(f.name)) {
      diags.error(f.loc, fmt::format("function '@{}' of '{}' is already defined by '{}'", f.name, from.name, into.name));
      ok = false;
      continue;
    }
    Dialect d = functionDialect(from, f);
    f.dialect = d == into.dialect ? Dialect::Unknown : d;
    into.functions.push_back(std::move(f));
  }
  return ok;
}

}  // namespace ncc::ir
