#include "passes/CmdTemplate.h"
#include "ir/FrameTilt.h"
#include "ir/OpSymbols.h"
#include "ir/SystemVars.h"
#include "passes/CycleOp.h"

#include <fmt/format.h>

#include <cstddef>
#include <cstring>
#include <type_traits>

namespace ncc {
using namespace ir;

bool isMachineOp(OpKind k) {
  switch (k) {
  case OpKind::Block: case OpKind::Comment: case OpKind::Message: case OpKind::Mode:
  case OpKind::Feed: case OpKind::Speed: case OpKind::ToolSelect: case OpKind::ToolChange:
  case OpKind::Spindle: case OpKind::Coolant: case OpKind::Dwell: case OpKind::Move:
  case OpKind::Home: case OpKind::MachineMove: case OpKind::ToolLength: case OpKind::CutterComp:
  case OpKind::WorkOffset: case OpKind::SetOffset: case OpKind::Stop: case OpKind::Aux: case OpKind::Frame:
  case OpKind::Contour: case OpKind::Cycle:
    return true;
  default:
    return false;
  }
}

// Which word a scalar argument key fills, per op kind.
struct KeyWord {
  OpKind op;
  const char *key;
  Word word;
};
static const KeyWord kKeyWords[] = {
    {OpKind::Feed, "value", Word::F},       {OpKind::Speed, "value", Word::S},
    {OpKind::ToolSelect, "value", Word::T}, {OpKind::Dwell, "seconds", Word::P},
    {OpKind::ToolLength, "h", Word::H},     {OpKind::CutterComp, "d", Word::D},
    {OpKind::CutterComp, "radius", Word::R}, {OpKind::CutterComp, "orientation", Word::L},
    {OpKind::SetOffset, "index", Word::P},  {OpKind::Aux, "m", Word::P},
    {OpKind::Aux, "b", Word::P},            {OpKind::Aux, "h", Word::P},
    {OpKind::Mode, "tolerance", Word::P},   {OpKind::Mode, "naive_tolerance", Word::Q},
    {OpKind::Spindle, "angle", Word::R},
    {OpKind::Spindle, "wait", Word::Q},      {OpKind::Speed, "limit", Word::D},
    {OpKind::Contour, "type", Word::P},     {OpKind::ToolChange, "number", Word::Q},
    {OpKind::Aux, "index", Word::E},        {OpKind::Aux, "value", Word::Q},
};

static CmdKind cmdKindOf(OpKind k) {
  switch (k) {
  case OpKind::Block: return CmdKind::Block;
  case OpKind::Comment: return CmdKind::Comment;
  case OpKind::Message: return CmdKind::Message;
  case OpKind::Mode: return CmdKind::Mode;
  case OpKind::Feed: return CmdKind::Feed;
  case OpKind::Speed: return CmdKind::Speed;
  case OpKind::ToolSelect: return CmdKind::ToolSelect;
  case OpKind::ToolChange: return CmdKind::ToolChange;
  case OpKind::Spindle: return CmdKind::Spindle;
  case OpKind::Coolant: return CmdKind::Coolant;
  case OpKind::Dwell: return CmdKind::Dwell;
  case OpKind::Move: return CmdKind::Move;
  case OpKind::Home: return CmdKind::Home;
  case OpKind::MachineMove: return CmdKind::MachineMove;
  case OpKind::ToolLength: return CmdKind::ToolLength;
  case OpKind::CutterComp: return CmdKind::CutterComp;
  case OpKind::WorkOffset: return CmdKind::WorkOffset;
  case OpKind::SetOffset: return CmdKind::SetOffset;
  case OpKind::Stop: return CmdKind::Stop;
  case OpKind::Aux: return CmdKind::Aux;
  case OpKind::Frame: return CmdKind::Frame;
  case OpKind::Contour: return CmdKind::Contour;
  case OpKind::Cycle: return CmdKind::Cycle;
  default: return CmdKind::Count;
  }
}

static bool constNumber(const Expr *e, double &v) {
  if (!e) return false;
  if (e->kind == ExprKind::Number || e->kind == ExprKind::Bool) {
    v = e->num;
    return true;
  }
  return false;
}

bool buildCmdTemplate(const Op &op, CmdTemplate &out, Diagnostics &diags) {
  out.base.clear();  // reused: templates are rebuilt per op on the streaming path
  out.slots.clear();  // keeps its capacity: templates are rebuilt per op on the streaming path
  out.text = nullptr;
  MachineCmd &c = out.base;
  c.kind = cmdKindOf(op.kind);
  c.loc = op.loc;
  if (c.kind == CmdKind::Count) {
    diags.error(op.loc, fmt::format("'{}' is not a machine operation", opInfo(op.kind).name));
    return false;
  }
  auto addWord = [&](Word w, const Expr *e) {
    double v;
    if (constNumber(e, v)) c.set(w, v);
    else if (e && e->kind == ExprKind::Vacant) return;  // a vacant word is not programmed
    else out.slots.push_back({w, e});
  };
  auto symbolArg = [&](const char *key, uint16_t &dst) -> bool {
    const Expr *e = op.get(key);
    if (!e) return true;
    std::string_view s = e->str;
    if (uint8_t code; opSymbolCode(op.kind, key, s, code)) {
      dst = code;
      return true;
    }
    diags.error(op.loc, fmt::format("'{}' has an invalid value for '{}'", opInfo(op.kind).name, key));
    return false;
  };

  auto perWordBits = [&](const char *key, uint16_t &bits) -> bool {
    const Expr *e = op.get(key);
    if (!e) return true;
    for (char l : e->str) {
      Word w;
      if (e->kind != ExprKind::Symbol || !wordFromLetter(l, w) || !(wordBit(w) & kPerWordDistance)) {
        diags.error(op.loc, fmt::format("'{}' {}= names the words X Y Z A B C U V W I J K (as in {}=XZ)", opInfo(op.kind).name, key, key));
        return false;
      }
      bits |= (uint16_t)wordBit(w);  // kPerWordDistance words are the low 16
    }
    return true;
  };

  switch (op.kind) {
  case OpKind::Block: {
    double n;
    if (const Expr *e = op.get("n"); constNumber(e, n)) c.blockNumber = (int64_t)n;
    return true;
  }
  case OpKind::Comment:
  case OpKind::Message:
    if (op.kind == OpKind::Message && !symbolArg("kind", c.sub)) return false;
    if (const Expr *e = op.get("text")) {
      if (e->kind == ExprKind::String) c.text = e->str.c_str();
      else out.text = e;  // evaluated at run time (the verifier allows this for messages only)
    }
    return true;
  case OpKind::Mode:
    for (auto &a : op.args) {
      if (a.key == "tolerance" || a.key == "naive_tolerance") continue;  // words, below
      ModeValue v;
      ModeGroup g;
      if (!a.value || !modeGroupFromName(a.key, g) || !modeValueFromName(a.value->str, v) ||
          modeValueInfo(v).group != g || c.nmodes == kMaxModes) {
        diags.error(op.loc, fmt::format("invalid mode '{}'", a.key));
        return false;
      }
      c.modes[c.nmodes++] = v;
    }
    break;
  case OpKind::Spindle:
    if (!symbolArg("dir", c.sub) || !symbolArg("way", c.sub2)) return false;
    break;  // an orientation's angle and wait: words, below
  case OpKind::CutterComp: {  // d_default in the low four bits of sub2, entry above
    uint16_t entry = 0;
    if (!symbolArg("side", c.sub) || !symbolArg("d_default", c.sub2) || !symbolArg("entry", entry)) return false;
    c.sub2 |= (uint16_t)(entry << 4);
    break;
  }
  case OpKind::Speed:
    if (!symbolArg("mode", c.sub) || !symbolArg("after_css", c.sub2)) return false;
    break;
  case OpKind::Stop: return symbolArg("kind", c.sub);
  case OpKind::ToolLength:  // G43.1/G43.2 axis values: the words' own keys, below
    if (!symbolArg("form", c.sub)) return false;
    break;
  case OpKind::SetOffset:
    if (!symbolArg("kind", c.sub)) return false;
    break;
  case OpKind::Frame: {
    uint16_t action = 0, form = 0, combine = 0, tilt = 0, position = 0;
    if (!symbolArg("slot", c.sub) || !symbolArg("action", action) || !symbolArg("form", form) ||
        !symbolArg("combine", combine) || !symbolArg("tilt", tilt) || !symbolArg("position", position))
      return false;
    c.sub2 = (uint16_t)(action | form | combine | tilt << kTiltFormShift | position << kTiltMoveShift);
    break;
  }
  case OpKind::Contour:
    if (!symbolArg("action", c.sub) || !symbolArg("use", c.sub2)) return false;
    break;
  case OpKind::Cycle: {  // the entries' places in the library, each argument in its positional word
    CycleOpShape shape;
    std::string err;
    if (!resolveCycleOp(op, shape, err)) {
      diags.error(op.loc, err);
      return false;
    }
    auto &lib = cycleLibrary();
    c.sub = shape.entry ? (uint16_t)(shape.entry - lib.data() + 1) : 0;
    c.sub2 = (uint16_t)((shape.pattern ? shape.pattern - lib.data() + 1 : 0) | (unsigned)shape.action << kCycleActionShift);
    for (auto &a : op.args) {
      bool ofPattern = a.key.rfind("p.", 0) == 0;
      if (!ofPattern && a.key.rfind("a.", 0) != 0) continue;
      int i = cycleParamIndex(ofPattern ? *shape.pattern : *shape.entry, std::string_view(a.key).substr(2));
      Word w = cycleArgWord(shape, ofPattern, i);
      if ((int)w == shape.textWord) {  // the constant STRING argument: the command's text
        c.text = a.value->str.c_str();
        c.sub |= (uint16_t)((shape.textWord + 1) << kCycleTextShift);
      } else {
        addWord(w, a.value.get());
      }
    }
    return true;
  }
  case OpKind::WorkOffset: {
    double v = 1;
    if (!constNumber(op.get("index"), v) || v < 0 || v >= kUserFrames) {
      diags.error(op.loc, "work offset index must be a constant 0..99");
      return false;
    }
    c.sub = (uint8_t)v;
    return true;
  }
  case OpKind::MachineMove: {
    double v = 1;
    constNumber(op.get("rapid"), v);
    c.sub = v != 0 ? 0 : 1;
    break;
  }
  case OpKind::Coolant:
    for (const char *key : {"flood", "mist"}) {
      const Expr *e = op.get(key);
      if (!e) continue;
      uint8_t bit = key[0] == 'f' ? 1 : 2;
      c.sub2 |= bit;
      if (e->str == "on") c.sub |= bit;
    }
    return true;
  case OpKind::Aux:
    // The letter is the key (m, b or h; the verifier requires exactly one); its value goes to P.
    c.sub = 'M';
    for (const char *key : {"b", "h"})
      if (op.get(key)) c.sub = (uint8_t)(key[0] - 'a' + 'A');
    if (!symbolArg("input", c.sub2)) return false;  // LinuxCNC M66: 0 digital (P), 1 analog (E)
    break;
  case OpKind::Move:
    // ic=XZ / ac=Y: the axis words that are incremental / absolute whatever the mode is.
    if (!perWordBits("ic", c.sub) || !perWordBits("ac", c.sub2)) return false;
    break;
  case OpKind::Home: {
    double v = 1;
    constNumber(op.get("ref"), v);
    c.sub = v == 2 ? 2 : 1;
    if (!perWordBits("ic", c.sub2)) return false;  // the lathe's G28 U W: an incremental intermediate point
    break;
  }
  default:
    break;
  }
  // Scalar words: named keys per kKeyWords, the words' own keys (kWordKeys) for motion ops.
  bool letters = op.kind == OpKind::Move || op.kind == OpKind::Home || op.kind == OpKind::MachineMove ||
                 op.kind == OpKind::SetOffset || op.kind == OpKind::Frame || op.kind == OpKind::Contour ||
                 op.kind == OpKind::ToolLength;
  for (auto &a : op.args) {
    Word w;
    if (letters && wordFromKey(a.key, w)) {
      addWord(w, a.value.get());
      continue;
    }
    for (auto &kw : kKeyWords)
      if (kw.op == op.kind && a.key == kw.key) addWord(kw.word, a.value.get());
  }
  return true;
}

Op cmdToOp(const MachineCmd &c) {
  static const OpKind kinds[] = {OpKind::Block, OpKind::Comment, OpKind::Message, OpKind::Mode,
                                 OpKind::Feed, OpKind::Speed, OpKind::ToolSelect, OpKind::ToolChange,
                                 OpKind::Spindle, OpKind::Coolant, OpKind::Dwell, OpKind::Move,
                                 OpKind::Home, OpKind::MachineMove, OpKind::ToolLength, OpKind::CutterComp,
                                 OpKind::WorkOffset, OpKind::SetOffset, OpKind::Stop, OpKind::Aux,
                                 OpKind::Frame, OpKind::Contour, OpKind::Cycle};
  static_assert(sizeof(kinds) / sizeof(kinds[0]) == (size_t)CmdKind::Count);
  Op op(kinds[(unsigned)c.kind], c.loc);
  auto real = [](double v) { return Expr::number(v, Type::Real); };
  switch (c.kind) {
  case CmdKind::Block:
    if (c.blockNumber >= 0) op.set("n", Expr::number((double)c.blockNumber, Type::Int));
    return op;
  case CmdKind::Comment:
  case CmdKind::Message:
    op.set("text", Expr::string(c.text ? c.text : ""));
    if (c.kind == CmdKind::Message && c.sub) op.set("kind", Expr::symbol(opSymbolName(op.kind, "kind", c.sub)));
    return op;
  case CmdKind::Mode:
    for (unsigned i = 0; i < c.nmodes; ++i) {
      auto &info = modeValueInfo(c.modes[i]);
      op.set(modeGroupName(info.group), Expr::symbol(info.name));
    }
    break;  // G64 tolerances below
  case CmdKind::Spindle:
    op.set("dir", Expr::symbol(opSymbolName(op.kind, "dir", c.sub)));
    if (c.sub != 3) return op;
    op.set("way", Expr::symbol(opSymbolName(op.kind, "way", c.sub2)));
    break;
  case CmdKind::Speed:
    if (c.sub) op.set("mode", Expr::symbol(opSymbolName(op.kind, "mode", c.sub)));
    if (c.sub2) op.set("after_css", Expr::symbol(opSymbolName(op.kind, "after_css", c.sub2)));
    break;
  case CmdKind::Stop: op.set("kind", Expr::symbol(opSymbolName(op.kind, "kind", c.sub))); return op;
  case CmdKind::CutterComp:
    op.set("side", Expr::symbol(opSymbolName(op.kind, "side", c.sub)));
    if (c.sub2 & 0x0f) op.set("d_default", Expr::symbol(opSymbolName(op.kind, "d_default", c.sub2 & 0x0f)));
    if (c.sub2 >> 4) op.set("entry", Expr::symbol(opSymbolName(op.kind, "entry", c.sub2 >> 4)));
    break;
  case CmdKind::SetOffset: op.set("kind", Expr::symbol(opSymbolName(op.kind, "kind", c.sub))); break;
  case CmdKind::Frame:
    op.set("slot", Expr::symbol(opSymbolName(op.kind, "slot", c.sub)));
    op.set("action", Expr::symbol(opSymbolName(op.kind, "action", c.sub2 & 0x0f)));
    if (c.sub == (uint8_t)FrameSlot::Rotation && (c.sub2 & 0x0f) == (uint8_t)FrameAction::Set)
      op.set("form", Expr::symbol(opSymbolName(op.kind, "form", c.sub2 & kFrameFormAxis)));
    if (c.sub2 & kFrameCombine) op.set("combine", Expr::symbol("ordered"));
    if (c.sub == kFrameSlotTilt && tiltForm(c.sub2) != TiltForm::None) {
      op.set("tilt", Expr::symbol(opSymbolName(op.kind, "tilt", (uint8_t)tiltForm(c.sub2))));
      op.set("position", Expr::symbol(opSymbolName(op.kind, "position", (uint8_t)tiltMove(c.sub2))));
    }
    break;
  case CmdKind::Contour:
    op.set("action", Expr::symbol(opSymbolName(op.kind, "action", c.sub)));
    if (c.sub != (uint16_t)ContourAction::Begin || c.sub2 != 0) op.set("use", Expr::symbol(opSymbolName(op.kind, "use", c.sub2)));
    break;
  case CmdKind::WorkOffset: op.set("index", Expr::number(c.sub, Type::Int)); return op;
  case CmdKind::MachineMove: op.set("rapid", Expr::boolean(c.sub == 0)); break;
  case CmdKind::Move:
  case CmdKind::Home:
    for (int k = 0; k < 2; ++k) {
      if (c.kind == CmdKind::Home && k == 0) continue;  // sub is the reference; sub2 its ic
      uint16_t bits = k == 0 ? c.sub : c.sub2;
      std::string axes;
      for (int i = 0; i < kWords; ++i)
        if (bits & wordBit((Word)i) & kPerWordDistance) axes += wordLetter((Word)i);
      if (!axes.empty()) op.set(k == 0 || c.kind == CmdKind::Home ? "ic" : "ac", Expr::symbol(axes));
    }
    if (c.kind == CmdKind::Home) op.set("ref", Expr::number(c.sub, Type::Int));
    break;
  case CmdKind::Coolant:
    if (c.sub2 & 1) op.set("flood", Expr::symbol(c.sub & 1 ? "on" : "off"));
    if (c.sub2 & 2) op.set("mist", Expr::symbol(c.sub & 2 ? "on" : "off"));
    return op;
  case CmdKind::ToolChange: return op;
  case CmdKind::Cycle: {
    auto &lib = cycleLibrary();
    CycleOpShape shape;
    shape.action = cycleAction(c.sub2);
    if (c.sub & 0xff) shape.entry = &lib[(c.sub & 0xff) - 1];
    const int textWord = (c.sub >> kCycleTextShift) - 1;
    if (c.sub2 & kCyclePatternMask) shape.pattern = &lib[(c.sub2 & kCyclePatternMask) - 1];
    if (shape.action != CycleAction::Run) op.set("action", Expr::symbol(opSymbolName(op.kind, "action", (uint8_t)shape.action)));
    for (const CycleDef *d : {shape.entry, shape.pattern}) {
      if (!d) continue;
      bool ofPattern = d == shape.pattern;
      op.set(ofPattern ? "pattern" : "entry", Expr::string(d->name));
      auto names = cycleParamNames(*d);
      for (size_t i = 0; i < names.size(); ++i)
        if (Word w = cycleArgWord(shape, ofPattern, (int)i); c.has(w) || (int)w == textWord)
          op.set((ofPattern ? "p." : "a.") + std::string(names[i]),
                 (int)w == textWord ? Expr::string(c.text ? c.text : "") : real(c.get(w)));
    }
    return op;
  }
  default: break;
  }
  for (auto &kw : kKeyWords)
    if (kw.op == op.kind && c.has(kw.word) &&
        (op.kind != OpKind::Aux || kw.word != Word::P || kw.key[0] == (c.sub ? c.sub : 'M') - 'A' + 'a')) {
      bool isInt = kw.word == Word::T || kw.word == Word::H || (kw.word == Word::D && op.kind != OpKind::Speed) ||
                   (op.kind == OpKind::SetOffset) || (op.kind == OpKind::Aux && kw.word != Word::Q) ||
                   op.kind == OpKind::Contour;
      op.set(kw.key, isInt ? Expr::number(c.get(kw.word), Type::Int) : real(c.get(kw.word)));
    }
  if (op.kind == OpKind::Move || op.kind == OpKind::Home || op.kind == OpKind::MachineMove ||
      op.kind == OpKind::SetOffset || op.kind == OpKind::Frame || op.kind == OpKind::Contour)
    for (int i = 0; i < kWords; ++i) {
      Word w = (Word)i;
      if (!c.has(w)) continue;
      if ((op.kind == OpKind::SetOffset || op.kind == OpKind::Contour) && w == Word::P) continue;
      op.set(kWordKeys[i], real(c.get(w)));
    }
  return op;
}

}  // namespace ncc
