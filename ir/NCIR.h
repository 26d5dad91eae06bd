// NC IR: the typed, structured, source-located program form every front end produces and every
// pass reads. See docs/IR.md for the op list, the type system and the dialect mapping.
//
// Shape (MLIR-like, kept small): a Module holds Functions (main program, subprograms, macros);
// a Function holds a Region (a list of Ops); an Op has a kind, named arguments (key = Expr) and
// nested Regions (if/while bodies). Expressions are trees of Expr. The textual form is generic:
//   <op-name> key=<expr> key=<expr> ... [{ region }]* loc(<file>:<line>:<col>)
// so printing and parsing need no per-op code, and the verifier checks each op against the
// OpInfo table (required/allowed keys, region count).
#pragma once
#include "ir/Diagnostics.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::ir {

// ---------------------------------------------------------------- types
enum class Type : uint8_t { Unknown, Void, Bool, Int, Real, String, Symbol, Axis, Frame };
const char *typeName(Type t);

// Where a variable lives. Numbered = Macro B / RS274 `#n` (meaning by number range: #1-#33
// call locals, #100-#199 and #500-#999 commons, others system); RParam = Sinumerik R n;
// QParam = Heidenhain Q/QL/QR/QS (name holds the prefix); Local/Global = named variables
// (Sinumerik DEF / GUD, RS274 #<x> / #<_x>); System = controller variables ($AA_IM, #5221…).
enum class VarSpace : uint8_t { Local, Global, Numbered, RParam, QParam, System };

// ---------------------------------------------------------------- expressions
enum class ExprKind : uint8_t {
  Number,  // num (type Int when integral literal without point, else Real)
  String,  // str
  Bool,    // num != 0
  Symbol,  // str: an enum-like bare word (mode names, dialect keywords)
  Vacant,  // Macro B #0 / "no value"
  Var,     // space + str (name) + optional args[0] (index); named variables up to 3 indices
  Unary,   // op + args[0]
  Binary,  // op + args[0], args[1]
  Call,    // str (builtin function name, upper case) + args
};

enum class OpCode : uint8_t {
  None,
  Neg, Not,                          // unary
  Add, Sub, Mul, Div, Mod, Pow,      // arithmetic
  IDiv,                              // integer division (Sinumerik DIV)
  Eq, Ne, Lt, Le, Gt, Ge,            // comparison (result Bool)
  And, Or, Xor,                      // logical: 1 or 0
  Concat,                            // string concatenation (Sinumerik <<)
  BAnd, BOr, BXor,                   // bitwise on integers (Fanuc Macro B AND/OR/XOR in values)
  // Keep BXor last: the text parser and the verifier take [Add, BXor] as the binary operators.
};
const char *opCodeName(OpCode op);  // "add", "lt", ...

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Expr {
  ExprKind kind = ExprKind::Number;
  Type type = Type::Unknown;
  OpCode op = OpCode::None;
  VarSpace space = VarSpace::Local;
  SourceLoc loc;
  double num = 0;
  std::string str;
  std::vector<ExprPtr> args;

  // Expressions come and go per block on the streaming path (3 or 4 per line of a flat
  // program): freed nodes are kept on a per-thread free list instead of going back to malloc.
  static void *operator new(std::size_t size);
  static void operator delete(void *p, std::size_t size) noexcept;

  static ExprPtr number(double v, Type t, SourceLoc loc = {});
  static ExprPtr string(std::string s, SourceLoc loc = {});
  static ExprPtr boolean(bool b, SourceLoc loc = {});
  static ExprPtr symbol(std::string s, SourceLoc loc = {});
  static ExprPtr vacant(SourceLoc loc = {});
  static ExprPtr var(VarSpace space, std::string name, ExprPtr index = nullptr, SourceLoc loc = {});
  static ExprPtr unary(OpCode op, ExprPtr a, SourceLoc loc = {});
  static ExprPtr binary(OpCode op, ExprPtr a, ExprPtr b, SourceLoc loc = {});
  static ExprPtr call(std::string fn, std::vector<ExprPtr> args, SourceLoc loc = {});

  ExprPtr clone() const;
  bool isConstant() const { return kind == ExprKind::Number || kind == ExprKind::Bool || kind == ExprKind::String; }
  // A string expression by its shape: a string constant or a concat (whose operands may be
  // numbers). Variables and string builtins may hold strings too (docs/IR.md §2.1).
  bool isStringExpr() const { return kind == ExprKind::String || (kind == ExprKind::Binary && op == OpCode::Concat); }
};

// ---------------------------------------------------------------- ops
enum class OpKind : uint8_t {
  // structure and text
  Block,       // n=<int>? skip=<int>?  start of a source block (N word, block-delete level)
  Comment,     // text=<string>
  Message,     // text=<string>  operator message (MSG)
  // machine state and motion (each becomes a MachineCmd at run time, see MachineCmd.h)
  Mode,        // <group>=<symbol> ... modal codes, group names from the ModeTable
  Feed,        // value=<real>
  Speed,       // value=<real>
  ToolSelect,  // value=<int>
  ToolChange,  //
  Spindle,     // dir=cw|ccw|stop
  Coolant,     // flood=on|off mist=on|off
  Dwell,       // seconds=<real>
  Move,        // X Y Z A B C U V W I J K R P Q L=<real>…  move in the current motion mode
  Home,        // ref=<int> X Y Z…  G28/G30: via the given intermediate point to reference ref
  MachineMove, // rapid=<bool> X Y Z…  G53: one move in machine coordinates
  ToolLength,  // h=<int> (0 = cancel)
  CutterComp,  // side=off|left|right d=<int>?
  WorkOffset,  // index=<int> 0..99 (Sinumerik G500, G54.., G505..G599; ISO 1..9)
  SetOffset,   // kind=g92|g92_1|g92_2|g92_3|g10l2|g10l20|g28_1|g30_1|g52 index=<int>? X Y Z… offsets and origin setting
  Stop,        // kind=program|optional|end|end_rewind
  Aux,         // m=<int>  other M codes; h=/b= auxiliary values
  Frame,       // slot=local|rotation|scale|mirror action=set|cancel form=plane|axis? X Y Z I J K R
               //   a programmable frame slot (ISO G52 G68 G51 G51.1, see docs/IR.md)
  Contour,     // action=data|begin|end|run use=finish|rough_z|rough_x|pattern|outline|island|pocket  contour capture
               //   (docs/IR.md): begin..end runs blocks whose path goes to the `use` consumer
  Cycle,       // entry=<string>? pattern=<string>? action=run|define|modal|call|cancel a.<param>=… p.<param>=…
               //   a cycle-library entry (runtime/cycles/Library.h) with run-time arguments (docs/IR.md §5.8)
  // data
  Declare,     // var=<var>[dims]? type=<symbol> init=<expr>? len=<int>?  (ir/Decls.h)
  Assign,      // target=<var> value=<expr>
  // control
  If,          // cond=<bool> {then} {else}?
  While,       // cond=<bool> {body}   (Macro B WHILE/DO id=<int>)
  Loop,        // count=<int>? {body}   (REPEAT / M98 L / K repeats)
  Break,
  Continue,
  Label,       // name=<string>   named jump target (N numbers are Block n=)
  Goto,        // n=<int> | label=<string>  dir=forward|backward|any
  Call,        // callee=<string> count=<int>? frame=new|shared  a.<key>=<expr>… arguments
  Return,      // value=<expr>?
  CallSection, // from=<label> to=<label>? count=<int>?  run a section of this function, then go on
  ModalCall,   // callee=<string>? a.<key>=<expr>…  call after each following move; no callee: cancel
  ModalTrigger,  // run the active modal call now, as after a move (Sinumerik MCALL's blocks without path motion)
  Count
};

struct OpInfo {
  OpKind kind;
  const char *name;        // textual name
  unsigned regionsMin, regionsMax;
  const char *required;    // space-separated keys that must be present
  const char *allowed;     // space-separated keys also allowed; "*" = any key
};
const OpInfo &opInfo(OpKind k);
bool opKindFromName(std::string_view name, OpKind &out);

struct Op;
using Region = std::vector<Op>;

struct Arg {
  std::string key;
  ExprPtr value;
};

struct Op {
  OpKind kind = OpKind::Block;
  SourceLoc loc;
  std::vector<Arg> args;
  std::vector<Region> regions;

  Op() = default;
  explicit Op(OpKind k, SourceLoc l = {}) : kind(k), loc(l) {}
  Op(Op &&) = default;
  Op &operator=(Op &&) = default;
  Op clone() const;

  const Expr *get(std::string_view key) const;
  Expr *get(std::string_view key);
  Op &set(std::string key, ExprPtr value);  // replaces an existing key
  bool erase(std::string_view key);
};

struct Param {
  std::string name;
  Type type = Type::Real;
  bool byRef = false;
  ExprPtr defaultValue;  // may be null
};

enum class Dialect : uint8_t { ISO, Sinumerik, Heidenhain, CLData, Unknown };
const char *dialectName(Dialect d);
bool dialectFromName(std::string_view s, Dialect &out);


struct Function {
  std::string name;        // "main" for the main program; "O1234", "L10", "SUB" for others
  SourceLoc loc;
  std::vector<Param> params;
  bool save = false;       // Sinumerik SAVE: the caller's modal state comes back on return (docs/IR.md §5.4)
  // The dialect its source was written in when it differs from the module's (an ISO program
  // calling a Sinumerik cycle, docs/IR.md §5.8); Unknown: the module's. Only diagnostics and
  // tools read it: the ops themselves carry every dialect rule.
  Dialect dialect = Dialect::Unknown;
  Region body;
  const Param *param(std::string_view name) const {  // null when there is no such parameter
    for (auto &p : params)
      if (p.name == name) return &p;
    return nullptr;
  }
};


struct Module {
  Dialect dialect = Dialect::ISO;
  std::string name;                 // main file name
  std::vector<Function> functions;  // functions[0] is the entry
  Function *find(std::string_view name);
  const Function *find(std::string_view name) const;
};

// The dialect a function was written in (its own, else the module's).
Dialect functionDialect(const Module &m, const Function &f);
// Appends the functions of `from` (another program or library, read by any front end with the
// same SourceManager) to `into`, each keeping its dialect. A name both define is an error at the
// second definition; false then.
bool linkModule(Module &into, Module &&from, Diagnostics &diags);

// The function a constant `call callee=` names: a string names it, a number n the program
// "O<n>". False for computed callees and for constants that name no function (2.5, a symbol).
bool constantCallee(const Expr &callee, std::string &name);

// ---------------------------------------------------------------- text form
std::string printExpr(const Expr &e);
// Without a SourceManager the `source K "..."` lines cannot name the files (they print as
// "file<id>"); drivers pass theirs so the text can be parsed back with the right paths.
std::string printModule(const Module &m);
std::string printModule(const Module &m, const SourceManager &sm);
// Parses the text form. File ids in loc() refer to names registered in `sm` on demand.
bool parseModule(std::string_view text, uint32_t fileId, SourceManager &sm, Diagnostics &diags,
                 Module &out);
// Checks structure: op keys, region counts, expression shapes, goto targets, call targets.
bool verifyModule(const Module &m, Diagnostics &diags);
// Checks that the engines can run a verified module: what the IR expresses but neither the eval
// engine nor the JIT implements yet (strings outside messages and call targets, system and QS
// variables, computed gotos, by-reference parameters, …) is an error here, not a wrong result.
// Both engines call it before running (docs/IR.md §7).
bool verifyRunnable(const Module &m, Diagnostics &diags);

}  // namespace ncc::ir
