// Private to the ISO front end's lowering (Lower.cpp, LowerFrames.cpp): one block being lowered.
#pragma once
#include "frontend/iso/Lower.h"
#include "ir/CmdSink.h"
#include "ir/MachineCmd.h"

#include <algorithm>
#include <fmt/format.h>

namespace ncc::iso {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;
using ir::Region;

// The axis words of offsets, homing and G53: U V W are axes too, except on lathes, where they
// are the incremental X Y Z.
inline const char *offsetAxes(bool lathe) { return lathe ? "XYZABC" : "XYZABCUVW"; }

// Increment: a length that is always in least input increments without a decimal point, even in
// calculator mode (the 808D's G74-G76 P and Q, seed L3842-3843).
enum class Scale : uint8_t { None, Linear, Rotary, Feed, DwellX, Increment };

constexpr Scale scaleOf(char letter) {
  switch (letter) {
  case 'X': case 'Y': case 'Z': case 'U': case 'V': case 'W': case 'I': case 'J': case 'K': case 'Q': case 'R':
    return Scale::Linear;
  case 'A': case 'B': case 'C': return Scale::Rotary;
  case 'F': return Scale::Feed;
  default: return Scale::None;
  }
}

// "G5.1", "G68": a code for messages.
std::string gName(int32_t code10);

// One block being lowered: its words by letter, the G and M codes found, the phases that emit
// ops in execution order. Members of BlockLowerer (modal tracking, diagnostics) are reached via L.
struct BlockLowerer::Block {
  // The slots below are not cleared per block (a plain block would pay for all of them): a G
  // slot is valid where `groups` has its bit, a word slot where `present` has it, an M slot
  // below nm.
  struct GUse {
    const GCodeInfo *info;
    const IsoWord *word;
  };
  struct MUse {
    MCodeInfo info;
    const IsoWord *word;
  };
  // Which words are present, which were consumed. Slots: A-Z, then RS274NGC's polar `@` `^`.
  struct Words {
    static constexpr int slot(char c) { return c == '@' ? 26 : c == '^' ? 27 : c - 'A'; }
    static constexpr char letter(int slot) { return slot == 26 ? '@' : slot == 27 ? '^' : (char)('A' + slot); }
    static constexpr uint32_t bit(char c) { return 1u << slot(c); }
    static constexpr uint32_t bits(const char *letters) {
      uint32_t m = 0;
      for (; *letters; ++letters) m |= bit(*letters);
      return m;
    }
    IsoWord *w[28];  // valid where present has the bit
    uint32_t used = 0, present = 0;
    IsoWord *get(char c) { return has(c) ? w[slot(c)] : nullptr; }
    bool has(char c) const { return (present & bit(c)) != 0; }
    bool hasAny(const char *letters) const { return (present & bits(letters)) != 0; }
  };

  BlockLowerer &L;
  ParsedBlock &b;
  Region &out;
  Words bw;
  GUse gs[(size_t)GGroup::Count];
  uint32_t groups = 0;  // bit per GGroup with a code in gs
  MUse ms[8];
  int nm = 0;
  bool macroCall = false;  // G65, G66: every other address is an argument (M too)
  bool axesTaken = false;  // a non-modal code took the axis words
  ExprPtr auxB;            // the 808D's B function of the block (stops() emits it)
  bool dwellTookAxis = false;  // Fanuc G4 X<seconds>
  bool offsetTookAxes = false;  // LinuxCNC G43.1/G43.2 axis words in a block without a motion code
  ModeValue motionBefore = ModeValue::Rapid;  // the motion mode a G5/G5.1 block gives back
  const GCodeInfo *nonModal = nullptr;

  Block(BlockLowerer &l, ParsedBlock &blk, Region &o) : L(l), b(blk), out(o) {}
  bool standAloneOk();
  bool parallelAxesOk();

  // Divisor of a word written without a decimal point (spec 2.3, tables 1-1 / 2-1). Dividing
  // by a power of ten keeps X1234 in IS-B exactly 1.234.
  double factor(Scale s) const {
    bool inch = L.units_ == ModeValue::Inch;
    if (s == Scale::Increment) return L.decimal_ == 2 ? (inch ? 1e5 : 1e4) : (inch ? 1e4 : 1e3);
    if (L.decimal_ == 0) return 1.0;
    switch (s) {
    case Scale::Linear: return L.decimal_ == 1 ? (inch ? 1e4 : 1e3) : (inch ? 1e5 : 1e4);
    case Scale::Rotary: return L.decimal_ == 1 ? 1e3 : 1e4;
    case Scale::DwellX: return 1e3;
    case Scale::Feed:
      if (L.feedMode_ == ModeValue::PerRev) return inch ? 1e4 : 1e2;
      if (L.feedMode_ == ModeValue::PerMinute) return inch ? 1e2 : 1.0;
      return 1.0;
    default: return 1.0;
    }
  }
  // A constant word's value: without a decimal point divided by the factor.
  static double constValue(const IsoWord &w, double f) { return !w.hasPoint && f != 1.0 ? w.value / f : w.value; }
  static ExprPtr literal(const IsoWord &w, double f) {
    if (w.expr) return w.expr->clone();
    if (!w.hasPoint && f != 1.0) return Expr::number(constValue(w, f), ir::Type::Real, w.loc);
    return Expr::number(w.value, w.hasPoint ? ir::Type::Real : ir::Type::Int, w.loc);
  }
  const GCodeInfo *G(GGroup g) const { return groups & (1u << (unsigned)g) ? gs[(size_t)g].info : nullptr; }
  SourceLoc gloc(GGroup g) const { return gs[(size_t)g].word->loc; }
  ExprPtr take(char c, Scale s) {
    IsoWord *w = bw.get(c);
    bw.used |= Words::bit(c);
    return literal(*w, factor(s));
  }
  Op &emit(OpKind k, SourceLoc loc) {
    out.emplace_back(k, loc);
    return out.back();
  }
  // The value a mode code of group g sets (its GKind is Mode).
  ModeValue modeValue(GGroup g) const {
    // Fanuc's G80 returns to the group-01 mode before the cycle; LinuxCNC's leaves none.
    const GCodeInfo *gi = G(g);
    return gi->mode == ModeValue::CycleOff && L.flavour_ == Flavour::Fanuc ? ModeValue::CycleCancel : gi->mode;
  }
  void modeOp(GGroup g, const char *key) {
    auto *gi = G(g);
    if (!gi || gi->kind != GKind::Mode) return;
    add(emit(OpKind::Mode, gloc(g)), key, Expr::symbol(modeValueInfo(modeValue(g)).name, gloc(g)));
  }
  void trackModes();                 // the block's units, feed mode and motion mode, for its words
  void checkFeed(const IsoWord &f);  // F <= 0 (a warning on Fanuc)
  // Keys are unique here, so args are appended directly (Op::set would search).
  static void add(Op &op, char key, ExprPtr v) { op.args.push_back({std::string(1, key), std::move(v)}); }
  static void add(Op &op, const char *key, ExprPtr v) { op.args.push_back({key, std::move(v)}); }
  bool toolOffsetOp(Op &op, int lv, IsoWord *l, SourceLoc loc);
  bool orientWords(Op &op, SourceLoc loc);
  bool polarWords(Op &op, ModeValue m, SourceLoc loc);
  bool skipMove();  // G31 (ISO-MEAS-01)  // a move in G16 (ISO-MOT-11)
  bool offsetToolLength(bool add, SourceLoc loc);
  bool extendedWorkOffset(int &index);  // 808D G54 P1…P93
  bool fanucWorkOffsetWrite(SourceLoc loc);  // 808D G10 L2: P0 and G91 refused
  void axisWords(Op &op, const char *axes) {
    for (const char *a = axes; *a; ++a)
      if (bw.has(*a)) add(op, *a, take(*a, scaleOf(*a)));
  }
  const MUse *findM(MKind k) const {
    for (int i = 0; i < nm; ++i)
      if (ms[i].info.kind == k) return &ms[i];
    return nullptr;
  }
  bool programNumber(SourceLoc at, const char *what, long long &prog) {
    IsoWord *p = bw.get('P');
    if (!p) {
      L.diags_->error(at, fmt::format("{} needs a P word (program number)", what), "missing-word");
      return false;
    }
    if (p->expr || p->value < 0 || p->value != std::floor(p->value) || p->value > 99999999) {
      L.diags_->error(p->loc, fmt::format("{} P must be a constant program number", what), "syntax");
      return false;
    }
    bw.used |= 1u << ('P' - 'A');
    prog = (long long)p->value;
    return true;
  }
  Op &callOp(SourceLoc loc, long long prog, ExprPtr count, const char *frame) {
    std::string callee = fmt::format("O{}", prog);
    L.calls.push_back({callee, loc});
    Op &op = emit(OpKind::Call, loc);
    op.set("callee", Expr::string(callee, loc));
    op.set("count", std::move(count));
    op.set("frame", Expr::symbol(frame, loc));
    return op;
  }

  Op &modalCallOp(SourceLoc loc, long long prog, ExprPtr count) {
    std::string callee = fmt::format("O{}", prog);
    L.calls.push_back({callee, loc});
    Op &op = emit(OpKind::ModalCall, loc);
    op.set("callee", Expr::string(callee, loc));
    op.set("count", std::move(count));
    return op;
  }
  const char *macroName() const { return b.words.end() != std::find_if(b.words.begin(), b.words.end(), [](auto &w) {
                                           return w.letter == 'G' && !w.expr && w.value == 66;
                                         }) ? "G66" : "G65"; }

  bool latheTool();                 // T0101 on a lathe
  bool latheToolOffset(Op &op, SourceLoc loc);  // G10 P X Z R on a lathe (LowerFrames.cpp)
  bool workpieceShift(Op &op, SourceLoc loc);   // G10 P00 X Z C on a lathe (LowerFrames.cpp)
  bool setOrAdd(const char *pairs, const char *code, const char *what);  // X with U … (LowerFrames.cpp)
  bool latheAxisWords(Op &op);      // U W on a lathe (system A)
  const GCodeInfo *lookupG(const IsoWord &w);  // a constant G word's table entry (null: reported)
  bool classify();       // G and M codes through the tables; conflicts and duplicates
  bool setup();          // feed mode ... return level
  bool cornerTaken = false;  // a ,C / ,R went to the move
  bool coordinateOps();  // G10/G92, G28/G30, G53
  bool turnCycle();      // G70-G73 (LowerTurning.cpp)
  bool rs274TurnCycle(); // LinuxCNC G70, G71 (.1 .2), G72 (.1 .2) (LowerTurning.cpp)
  bool speedOp();        // S, G96/G97, G50 S / G92 S (LowerTurning.cpp)
  bool frameOps();       // G52, G68/G69, G51/G50, G51.1/G50.1
  bool transformOp();    // G12.1/G13.1, G07.1 (LowerTransform.cpp)
  bool motion();
  bool threadWords(Op &op, ModeValue m);  // the words of G32/G33/G33.1/G76/G92/G78
  void peckWords(Op &op);                  // P Q R of the lathe's G74/G75 (LowerTurning.cpp)
  bool stops();
  bool ioCode(const MUse &m);       // LinuxCNC M62-M68
  bool callsAndReturn();
  bool returnOp(SourceLoc loc);  // M99 [P] (LowerCalls.cpp)
  bool contourCopy();            // G72.1 / G72.2 (LowerCopy.cpp)
  // False, reported, when the lowerer refuses calls (BlockLowerer::callsRefused).
  bool callAllowed(SourceLoc loc, std::string_view what) {
    if (!L.callsRefused) return true;
    L.diags_->error(loc, fmt::format("{} {}", what, L.callsRefused), L.callsRefusedRule);
    return false;
  }
  bool finish();         // assignments, unused words
  // The lean path (LowerLean.cpp), after classify().
  // classify() of the usual plain block (G codes already in the lowerer's cache, one per group,
  // no G65/G66, no M code, each other letter once), else false (the masks untouched) and
  // classify() decides.
  bool leanClassify();
  bool leanFits() const;
  bool leanEmit(CmdSink &sink);
  bool decideMove(LeanMove &m);  // a block that is a move and its motion mode: decided for reuse
  void leanMoveWords(MachineCmd &c, uint32_t moveWords);
};

// The arguments of a macro call (G65, G66, a macro called by code) from the block's words whose
// letters are not in `skip` (LowerCalls.cpp): Fanuc argument specification I or II as #1-#33
// (`a.<n>`), and the 808D call context `a._C_ALL_PROG`, `a._C_TYP_PROG` (ISO-MAC-03).
bool macroArguments(const std::vector<IsoWord> &words, const char *skip, Op &op, Diagnostics &diags);

}  // namespace ncc::iso
