#include "backends/jit/MachineOps.h"

#include "ir/Value.h"

#include <cmath>

namespace ncc::jit {

using ir::Expr;
using ir::ExprKind;
using ir::Op;
using ir::OpKind;

namespace {

// How one op kind maps onto a command: the command kind and the key holding `sub`.
enum class SubSource : uint8_t { None, Symbol, Round, NotTruthy };
struct SymbolValue {
  const char *name;
  uint8_t value;
};
struct MachineOpRule {
  OpKind op;
  CmdKind cmd;
  const char *valueKey;  // key whose value goes to `valueWord` (null: none)
  Word valueWord;
  const char *subKey;    // key giving `sub`
  SubSource subSource;
  const SymbolValue *symbols;  // for SubSource::Symbol, null-terminated
  bool axisWords;              // single-letter keys X..L are words
};

const SymbolValue kSpindleDirs[] = {{"stop", 0}, {"cw", 1}, {"ccw", 2}, {nullptr, 0}};
const SymbolValue kCompSides[] = {{"off", 0}, {"left", 1}, {"right", 2}, {nullptr, 0}};
const SymbolValue kOffsetKinds[] = {{"g92", (uint8_t)SetOffsetKind::G92},
                                    {"g92_1", (uint8_t)SetOffsetKind::G92Cancel},
                                    {"g10l2", (uint8_t)SetOffsetKind::G10L2},
                                    {"g10l20", (uint8_t)SetOffsetKind::G10L20},
                                    {nullptr, 0}};
const SymbolValue kStopKinds[] = {{"program", (uint8_t)StopKind::Program},
                                  {"optional", (uint8_t)StopKind::Optional},
                                  {"end", (uint8_t)StopKind::End},
                                  {"end_rewind", (uint8_t)StopKind::EndRewind},
                                  {nullptr, 0}};

const MachineOpRule kRules[] = {
    {OpKind::Feed, CmdKind::Feed, "value", Word::F, nullptr, SubSource::None, nullptr, false},
    {OpKind::Speed, CmdKind::Speed, "value", Word::S, nullptr, SubSource::None, nullptr, false},
    {OpKind::ToolSelect, CmdKind::ToolSelect, "value", Word::T, nullptr, SubSource::None, nullptr, false},
    {OpKind::ToolChange, CmdKind::ToolChange, nullptr, Word::X, nullptr, SubSource::None, nullptr, false},
    {OpKind::Spindle, CmdKind::Spindle, nullptr, Word::X, "dir", SubSource::Symbol, kSpindleDirs, false},
    {OpKind::Dwell, CmdKind::Dwell, "seconds", Word::P, nullptr, SubSource::None, nullptr, false},
    {OpKind::Move, CmdKind::Move, nullptr, Word::X, nullptr, SubSource::None, nullptr, true},
    {OpKind::Home, CmdKind::Home, nullptr, Word::X, "ref", SubSource::Round, nullptr, true},
    {OpKind::MachineMove, CmdKind::MachineMove, nullptr, Word::X, "rapid", SubSource::NotTruthy, nullptr, true},
    {OpKind::ToolLength, CmdKind::ToolLength, "h", Word::H, nullptr, SubSource::None, nullptr, false},
    {OpKind::CutterComp, CmdKind::CutterComp, "d", Word::D, "side", SubSource::Symbol, kCompSides, false},
    {OpKind::WorkOffset, CmdKind::WorkOffset, nullptr, Word::X, "index", SubSource::Round, nullptr, false},
    {OpKind::SetOffset, CmdKind::SetOffset, "index", Word::P, "kind", SubSource::Symbol, kOffsetKinds, true},
    {OpKind::Stop, CmdKind::Stop, nullptr, Word::X, "kind", SubSource::Symbol, kStopKinds, false},
};

const MachineOpRule *findRule(OpKind k) {
  for (auto &r : kRules)
    if (r.op == k) return &r;
  return nullptr;
}

// A symbol-or-bool operand (on/off, true/false); -1 when it is neither.
int onOff(const Expr &e) {
  if (e.kind == ExprKind::Symbol) {
    if (e.str == "on" || e.str == "true") return 1;
    if (e.str == "off" || e.str == "false") return 0;
    return -1;
  }
  if (e.kind == ExprKind::Bool || e.kind == ExprKind::Number) return truthy(e.num) ? 1 : 0;
  return -1;
}

// Puts a word operand into the spec: literal now, otherwise at run time.
bool addWord(CmdSpec &s, Word w, const Expr &e, Diagnostics &diags) {
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Bool: s.cmd.set(w, e.num); return true;
  case ExprKind::Vacant: return true;  // a vacant word is as if not programmed
  case ExprKind::String:
  case ExprKind::Symbol:
    diags.error(e.loc, std::string("word ") + kWordLetters[(unsigned)w] + " needs a number");
    return false;
  default: s.words.push_back({w, &e}); return true;
  }
}

bool lowerText(const Op &op, CmdKind kind, std::vector<CmdSpec> &out, Diagnostics &diags) {
  const Expr *t = op.get("text");
  if (!t || t->kind != ExprKind::String) {
    diags.error(op.loc, "comment and message text must be a string literal");
    return false;
  }
  CmdSpec s;
  s.cmd.kind = kind;
  s.cmd.loc = op.loc;
  s.text = t->str;
  out.push_back(std::move(s));
  return true;
}

bool lowerMode(const Op &op, std::vector<CmdSpec> &out, Diagnostics &diags) {
  CmdSpec s;
  s.cmd.kind = CmdKind::Mode;
  s.cmd.loc = op.loc;
  for (auto &a : op.args) {
    ModeValue v;
    if (!a.value || a.value->kind != ExprKind::Symbol || !modeValueFromName(a.value->str, v)) {
      diags.error(op.loc, "unknown mode value for '" + a.key + "'");
      return false;
    }
    if (s.cmd.nmodes == 6) {  // more groups than one command carries: continue in another
      out.push_back(s);
      s.cmd.nmodes = 0;
    }
    s.cmd.modes[s.cmd.nmodes++] = v;
  }
  out.push_back(std::move(s));
  return true;
}

bool lowerAux(const Op &op, std::vector<CmdSpec> &out, Diagnostics &diags) {
  static const struct {
    const char *key;
    uint8_t letter;
  } kAuxKeys[] = {{"m", 'M'}, {"b", 'B'}, {"h", 'H'}};
  for (auto &k : kAuxKeys)
    if (const Expr *e = op.get(k.key)) {
      CmdSpec s;
      s.cmd.kind = CmdKind::Aux;
      s.cmd.sub = k.letter;
      s.cmd.loc = op.loc;
      if (!addWord(s, Word::P, *e, diags)) return false;
      out.push_back(std::move(s));
    }
  return true;
}

bool lowerBlock(const Op &op, std::vector<CmdSpec> &out, Diagnostics &diags) {
  CmdSpec s;
  s.cmd.kind = CmdKind::Block;
  s.cmd.loc = op.loc;
  if (const Expr *n = op.get("n")) {
    if (n->kind != ExprKind::Number) {
      diags.error(op.loc, "block number must be a literal");
      return false;
    }
    s.cmd.blockNumber = (int64_t)std::llround(n->num);
  }
  out.push_back(std::move(s));
  return true;
}

bool lowerSub(const Op &op, const MachineOpRule &r, CmdSpec &s, Diagnostics &diags) {
  const Expr *e = op.get(r.subKey);
  if (!e) return true;  // optional sub keys keep 0
  if (r.subSource == SubSource::Symbol) {
    if (e->kind == ExprKind::Symbol)
      for (const SymbolValue *v = r.symbols; v->name; ++v)
        if (e->str == v->name) {
          s.cmd.sub = v->value;
          return true;
        }
    diags.error(op.loc, std::string("invalid value for '") + r.subKey + "' of " + ir::opInfo(op.kind).name);
    return false;
  }
  if (e->kind == ExprKind::Symbol || e->kind == ExprKind::String) {
    if (r.subSource == SubSource::NotTruthy && onOff(*e) >= 0) {
      s.cmd.sub = onOff(*e) ? 0 : 1;
      return true;
    }
    diags.error(op.loc, std::string("'") + r.subKey + "' needs a number");
    return false;
  }
  if (isLiteral(*e)) {
    double v = e->kind == ExprKind::Vacant ? vacantValue() : e->num;
    s.cmd.sub = r.subSource == SubSource::Round ? (uint8_t)std::lround(num(v)) : (truthy(v) ? 0 : 1);
    return true;
  }
  s.subRule = r.subSource == SubSource::Round ? CmdSpec::SubRule::Round : CmdSpec::SubRule::NotTruthy;
  s.subExpr = e;
  return true;
}

}  // namespace

bool isLiteral(const Expr &e) {
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Bool:
  case ExprKind::String:
  case ExprKind::Symbol:
  case ExprKind::Vacant: return true;
  default: return false;
  }
}

bool isMachineOp(OpKind k) {
  return k == OpKind::Block || k == OpKind::Comment || k == OpKind::Message || k == OpKind::Mode ||
         k == OpKind::Coolant || k == OpKind::Aux || findRule(k) != nullptr;
}

bool lowerMachineOp(const Op &op, std::vector<CmdSpec> &out, Diagnostics &diags) {
  switch (op.kind) {
  case OpKind::Block: return lowerBlock(op, out, diags);
  case OpKind::Comment: return lowerText(op, CmdKind::Comment, out, diags);
  case OpKind::Message: return lowerText(op, CmdKind::Message, out, diags);
  case OpKind::Mode: return lowerMode(op, out, diags);
  case OpKind::Aux: return lowerAux(op, out, diags);
  case OpKind::Coolant: {
    CmdSpec s;
    s.cmd.kind = CmdKind::Coolant;
    s.cmd.loc = op.loc;
    static const char *kKeys[] = {"flood", "mist"};
    for (unsigned bit = 0; bit < 2; ++bit)
      if (const Expr *e = op.get(kKeys[bit])) {
        int on = onOff(*e);
        if (on < 0) {
          diags.error(op.loc, std::string("'") + kKeys[bit] + "' must be on or off");
          return false;
        }
        s.cmd.sub2 |= (uint8_t)(1u << bit);
        if (on) s.cmd.sub |= (uint8_t)(1u << bit);
      }
    out.push_back(std::move(s));
    return true;
  }
  default: break;
  }
  const MachineOpRule *r = findRule(op.kind);
  if (!r) {
    diags.error(op.loc, std::string("internal error: '") + ir::opInfo(op.kind).name + "' is not a machine op");
    return false;
  }
  CmdSpec s;
  s.cmd.kind = r->cmd;
  s.cmd.loc = op.loc;
  if (r->subKey && !lowerSub(op, *r, s, diags)) return false;
  if (r->valueKey)
    if (const Expr *e = op.get(r->valueKey))
      if (!addWord(s, r->valueWord, *e, diags)) return false;
  if (r->axisWords)
    for (auto &a : op.args) {
      Word w;
      if (a.key.size() == 1 && a.key[0] >= 'A' && a.key[0] <= 'Z' && wordFromLetter(a.key[0], w) && a.value)
        if (!addWord(s, w, *a.value, diags)) return false;
    }
  out.push_back(std::move(s));
  return true;
}

}  // namespace ncc::jit
