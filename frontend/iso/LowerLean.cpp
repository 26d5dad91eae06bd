// The lean path of a streamed flat program (issue 6): a plain block goes from the parsed words
// straight to machine commands, with no NC IR ops, argument vectors, keys or expressions in
// between. A plain block has constant words only and nothing but mode codes, F and a move (the
// axis words, and I J K R of an arc); anything else falls back to lowerActions. The classification
// (the G/M code tables, conflicts, duplicate words), the modal tracking, the word scaling and the
// mode values are lowerActions' own (LowerBlock.h); the commands are the ones buildCmdTemplate
// makes of lowerActions' ops, in the same order (test/unit/LeanLowerTest.cpp compares both).
#include "frontend/iso/LowerBlock.h"

#include <array>

namespace ncc::iso {

namespace {
// The mode groups of a plain block, in lowerActions' order: setup() emits these before the
// motion mode (feed mode first, then the feed), motion() the motion mode before the move.
constexpr GGroup kModesBeforeMotion[] = {GGroup::Plane, GGroup::Units, GGroup::PathMode, GGroup::Distance,
                                         GGroup::ArcDistance, GGroup::Retract};
constexpr uint32_t groupBit(GGroup g) { return 1u << (unsigned)g; }
constexpr uint32_t kModesBeforeMotionBits = [] {
  uint32_t bits = 0;
  for (GGroup g : kModesBeforeMotion) bits |= groupBit(g);
  return bits;
}();
constexpr uint32_t kLeanGroups = groupBit(GGroup::FeedMode) | groupBit(GGroup::Plane) | groupBit(GGroup::Units) |
                                 groupBit(GGroup::PathMode) | groupBit(GGroup::Distance) |
                                 groupBit(GGroup::ArcDistance) | groupBit(GGroup::Retract) | groupBit(GGroup::Motion);
static_assert((size_t)GGroup::Count <= 32);

bool plainMotion(ModeValue m) {
  return m == ModeValue::Rapid || m == ModeValue::Linear || m == ModeValue::ArcCW || m == ModeValue::ArcCCW;
}
bool isArc(ModeValue m) { return m == ModeValue::ArcCW || m == ModeValue::ArcCCW; }
}  // namespace

// Every word constant, no assignment, comment, corner or statement: checked on the parsed block.
static bool plainWords(const ParsedBlock &b) {
  if (b.plain) return true;  // the parser's fast path read nothing else
  if (!b.assigns.empty() || !b.comments.empty() || !b.corner.empty() || b.stmt != StmtKind::None ||
      b.programNumber >= 0)
    return false;
  for (const IsoWord &w : b.words)
    if (w.expr) return false;
  return true;
}

bool BlockLowerer::Block::leanClassify() {
  uint32_t g = 0, present = 0;  // groups and bw.present, kept in registers
  for (IsoWord &w : b.words) {
    if (w.letter == 'G') {
      const int code = L.gCacheSlot(w.value);
      if (code < 0 || code == 65 || code == 66) return false;  // a macro call makes every word an argument
      const GCodeInfo *gi = L.gCache_[code];
      if (!gi) return false;
      const uint32_t bit = groupBit(gi->group);
      if (g & bit) return false;  // two codes of a group: classify's rules and messages
      gs[(size_t)gi->group] = {gi, &w};
      g |= bit;
    } else {
      if (w.letter < 'A' || w.letter > 'Z' || w.letter == 'M') return false;
      const uint32_t bit = Words::bit(w.letter);
      if (present & bit) return false;  // a duplicate word: classify's message
      bw.w[Words::slot(w.letter)] = &w;
      present |= bit;
    }
  }
  groups = g, bw.present = present;
  return true;
}

// After classify(): only mode codes of the lean groups, no M code, a plain motion mode, and words
// the block's mode and move use (an unused word takes lowerActions, which reports it).
bool BlockLowerer::Block::leanFits() const {
  if (nm || macroCall || (groups & ~kLeanGroups)) return false;
  if (L.flavour_ == Flavour::Fanuc && !L.lathe_ && bw.hasAny("UVW")) return false;  // setup's parallelAxesOk
  if (L.auxiliaryB_ && bw.has('B')) return false;  // the 808D's B function: setup()
  for (uint32_t g = groups; g; g &= g - 1)
    if (gs[__builtin_ctz(g)].info->kind != GKind::Mode) return false;
  const ModeValue m = G(GGroup::Motion) ? G(GGroup::Motion)->mode : L.motion_;
  if (!plainMotion(m)) return false;
  constexpr uint32_t kPlain = Words::bits("XYZABCUVWF"), kArc = Words::bits("IJKR");
  return (bw.present & ~(isArc(m) ? kPlain | kArc : kPlain)) == 0;
}

bool BlockLowerer::Block::leanEmit(CmdSink &sink) {
  const uint32_t moveWords = bw.present & ~Words::bit('F');
  if (moveWords && moveWords == bw.present && !(groups & ~groupBit(GGroup::Motion))) return leanMove(sink, moveWords);
  // The command is back to MachineCmd{} after each use: each kind resets the fields it set
  // (kind, loc, and its own: the block number, the mode, the words), not all of them.
  MachineCmd &c = L.cmd_;
  auto issue = [&] {
    bool ok = sink.exec(c);
    c.kind = CmdKind::Block;
    c.loc = {};
    return ok;
  };
  auto mode = [&](GGroup g) {
    if (!G(g)) return true;
    c.kind = CmdKind::Mode;
    c.loc = gloc(g);
    c.nmodes = 1;
    c.modes[0] = modeValue(g);
    bool ok = issue();
    c.nmodes = 0;
    c.modes[0] = {};
    return ok;
  };
  c.kind = CmdKind::Block;
  c.loc = b.loc;
  c.blockNumber = b.n;
  bool ok = issue();
  c.blockNumber = -1;
  if (!ok) return false;
  trackModes();
  if (!mode(GGroup::FeedMode)) return false;
  if (IsoWord *f = bw.get('F')) {
    checkFeed(*f);
    c.kind = CmdKind::Feed;
    c.loc = f->loc;
    c.set(Word::F, constValue(*f, factor(Scale::Feed)));
    ok = issue();
    c.clearWords();
    if (!ok) return false;
  }
  if (groups & kModesBeforeMotionBits)
    for (GGroup g : kModesBeforeMotion)
      if (!mode(g)) return false;
  if (!mode(GGroup::Motion)) return false;
  if (!moveWords) return true;  // I J K R alone still move an arc (as motion()); F alone does not
  leanMoveWords(c, moveWords);
  ok = issue();
  c.clearWords();
  return ok;
}

// Most lines of a flat program: the Block, the motion mode if the block has one, and the move,
// in one call (CmdSink::execMove; the executor skips a mode that is in force).
bool BlockLowerer::Block::leanMove(CmdSink &sink, uint32_t moveWords) {
  MachineCmd &blk = L.leanBlock_, &mode = L.leanMode_, &c = L.cmd_;
  blk.loc = b.loc;
  blk.blockNumber = b.n;
  trackModes();
  if (G(GGroup::Motion)) {
    mode.kind = CmdKind::Mode;
    mode.loc = gloc(GGroup::Motion);
    mode.nmodes = 1;
    mode.modes[0] = modeValue(GGroup::Motion);
  }
  leanMoveWords(c, moveWords);
  const bool ok = sink.execMove(&blk, 1, G(GGroup::Motion) ? &mode : nullptr, c);
  c.kind = CmdKind::Block;
  c.loc = {};
  c.clearWords();
  return ok;
}

void BlockLowerer::Block::leanMoveWords(MachineCmd &c, uint32_t moveWords) {
  c.kind = CmdKind::Move;
  c.loc = G(GGroup::Motion) ? gloc(GGroup::Motion) : b.loc;
  // A move word's command word and scale by its slot (the letters leanFits lets through).
  struct MoveWord {
    Word word;
    Scale scale;
  };
  static constexpr auto kMoveWords = [] {
    std::array<MoveWord, 28> t{};
    const char *letters = "XYZABCUVWIJKR";
    for (int i = 0; letters[i]; ++i) t[Words::slot(letters[i])] = {(Word)((int)Word::X + i), scaleOf(letters[i])};
    return t;
  }();
  static_assert(Word::R == (Word)((int)Word::X + 12));
  for (uint32_t m = moveWords; m; m &= m - 1) {
    const int slot = __builtin_ctz(m);
    c.set(kMoveWords[slot].word, constValue(*bw.w[slot], factor(kMoveWords[slot].scale)));
  }
}

BlockLowerer::Lean BlockLowerer::lowerLean(ParsedBlock &b, CmdSink &sink, bool pending) {
  if (lathe_ || polar_ || !plainWords(b)) return Lean::Fallback;
  Block blk(*this, b, none_);
  if (!blk.leanClassify() && !blk.classify()) return Lean::Error;
  if (!blk.leanFits()) return Lean::Fallback;
  if (pending) return Lean::Held;
  return blk.leanEmit(sink) ? Lean::Done : Lean::Stopped;
}

}  // namespace ncc::iso
