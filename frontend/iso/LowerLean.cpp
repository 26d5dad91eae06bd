// The lean path of a streamed flat program (issue 6): a plain block goes from the parsed words
// straight to machine commands, with no NC IR ops, argument vectors, keys or expressions in
// between. A plain block has constant words only and nothing but mode codes, F and a move (the
// axis words, and I J K R of an arc); anything else falls back to lowerActions. The classification
// (the G/M code tables, conflicts, duplicate words), the modal tracking, the word scaling and the
// mode values are lowerActions' own (LowerBlock.h); the commands are the ones buildCmdTemplate
// makes of lowerActions' ops, in the same order (test/unit/LeanLowerTest.cpp compares both).
#include "frontend/iso/LowerBlock.h"

#include <array>
#include <utility>

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

namespace {
// A move word's command word and scale by its letter's slot (Block::Words::slot: A-Z are 0-25;
// the letters leanFits lets through).
struct MoveWord {
  Word word;
  Scale scale;
};
constexpr auto kMoveWords = [] {
  std::array<MoveWord, 28> t{};
  const char *letters = "XYZABCUVWIJKR";
  for (int i = 0; letters[i]; ++i) t[letters[i] - 'A'] = {(Word)((int)Word::X + i), scaleOf(letters[i])};
  return t;
}();
static_assert(Word::R == (Word)((int)Word::X + 12));
}  // namespace

void BlockLowerer::Block::leanMoveWords(MachineCmd &c, uint32_t moveWords) {
  static_assert(Words::slot('A') == 0 && Words::slot('Z') == 25);
  c.kind = CmdKind::Move;
  c.loc = G(GGroup::Motion) ? gloc(GGroup::Motion) : b.loc;
  for (uint32_t m = moveWords; m; m &= m - 1) {
    const int slot = __builtin_ctz(m);
    c.set(kMoveWords[slot].word, constValue(*bw.w[slot], factor(kMoveWords[slot].scale)));
  }
}

// Most lines of a flat program: a block that is a move and at most its motion code. Decided
// once (classify, leanFits, trackModes, the factors) per shape and state: each word's command
// word and divisor by its place in the block. False: not such a block (leanEmit does it).
bool BlockLowerer::Block::decideMove(LeanMove &m) {
  const uint32_t moveWords = bw.present & ~Words::bit('F');
  if (!moveWords || moveWords != bw.present || (groups & ~groupBit(GGroup::Motion)) ||
      b.words.size() > (size_t)LeanMove::kMaxWords)
    return false;
  static_assert(kWords < LeanMove::kRotary);
  m.mask = 0;
  for (size_t i = 0; i < b.words.size(); ++i) {
    const IsoWord &w = b.words[i];
    if (w.letter == 'G') {
      if (!G(GGroup::Motion) || gs[(size_t)GGroup::Motion].word != &w) return false;
      m.word[i] = LeanMove::kCode;
    } else {
      const MoveWord &mw = kMoveWords[Words::slot(w.letter)];
      if (bw.w[Words::slot(w.letter)] != &w || mw.scale == Scale::None) return false;
      m.word[i] = (uint8_t)((unsigned)mw.word | (mw.scale == Scale::Rotary ? LeanMove::kRotary : 0));
      m.mask |= wordBit(mw.word);
    }
  }
  trackModes();
  m.motionWord = -1;
  if (G(GGroup::Motion)) {
    m.motionWord = (int8_t)(gs[(size_t)GGroup::Motion].word - b.words.data());
    m.mode = modeValue(GGroup::Motion);
    m.code = gs[(size_t)GGroup::Motion].word->value;  // G01 and G1.0 are G1: classify looks up the value
  }
  m.linear = factor(Scale::Linear);
  m.rotary = factor(Scale::Rotary);
  m.motionAfter = L.motion_;
  m.pathMotionAfter = L.pathMotion_;
  return true;
}

// The Block, the motion mode if the block has one, and the move, in one call
// (CmdSink::execMove; the executor skips a mode that is in force).
inline bool BlockLowerer::leanMove(const LeanMove &m, ParsedBlock &b, CmdSink &sink) {
  motion_ = m.motionAfter;  // trackModes: a motion code is the only code here
  pathMotion_ = m.pathMotionAfter;
  MachineCmd &blk = leanBlock_, &mode = leanMode_, &c = cmd_;
  blk.loc = b.loc;
  blk.blockNumber = b.n;
  c.kind = CmdKind::Move;
  c.loc = b.loc;
  if (m.motionWord >= 0) {
    mode.kind = CmdKind::Mode;
    mode.loc = c.loc = b.words[(size_t)m.motionWord].loc;
    mode.nmodes = 1;
    mode.modes[0] = m.mode;
  }
  // c.set for each word, the mask at once (c has no word set here).
  const IsoWord *w = b.words.data();
  for (size_t i = 0, n = b.words.size(); i < n; ++i) {
    const unsigned word = m.word[i];
    if (word == LeanMove::kCode) continue;
    c.w[word & ~LeanMove::kRotary] = Block::constValue(w[i], word & LeanMove::kRotary ? m.rotary : m.linear);
  }
  c.mask |= m.mask;
  const bool ok = sink.execMove(&blk, 1, m.motionWord >= 0 ? &mode : nullptr, c);
  c.kind = CmdKind::Block;
  c.loc = {};
  c.clearWords();
  return ok;
}

BlockLowerer::Lean BlockLowerer::lowerLean(ParsedBlock &b, CmdSink &sink, bool pending) {
  if (lathe_ || polar_ || !plainWords(b)) return Lean::Fallback;
  // A move block whose shape was decided in this state: the same decision (leanState has all
  // the decision reads of the lowerer; the shape and the code all it reads of the block but
  // the values, in order).
  const uint64_t state = leanState();
  if (!b.shape) return lowerLeanDecide(b, sink, pending, nullptr, state);
  LeanMove *set = leanCache_[leanSet(b.shape, state)];
  auto fits = [&](const LeanMove &m) {
    return m.shape == b.shape && m.state == state && (m.motionWord < 0 || b.words[(size_t)m.motionWord].value == m.code);
  };
  if (!fits(set[0])) {
    if (!fits(set[1])) return lowerLeanDecide(b, sink, pending, set, state);
    std::swap(set[0], set[1]);  // the first way holds the latest used
  }
  if (pending) return Lean::Held;
  ++leanReuses;
  return leanMove(set[0], b, sink) ? Lean::Done : Lean::Stopped;
}

// A block the cache does not know: classify and check it, and decide it for the cache (`set`,
// with `state` the lowerer's before it) when it is a move.
BlockLowerer::Lean BlockLowerer::lowerLeanDecide(ParsedBlock &b, CmdSink &sink, bool pending, LeanMove *set,
                                                 uint64_t state) {
  Block blk(*this, b, none_);
  if (!blk.leanClassify() && !blk.classify()) return Lean::Error;
  if (!blk.leanFits()) return Lean::Fallback;
  if (pending) return Lean::Held;
  LeanMove local;
  if (set) set[1] = set[0];
  LeanMove &m = set ? set[0] : local;
  m.shape = 0;  // an entry half rewritten is no entry
  if (blk.decideMove(m)) {
    m.shape = b.shape;
    m.state = state;
    return leanMove(m, b, sink) ? Lean::Done : Lean::Stopped;
  }
  return blk.leanEmit(sink) ? Lean::Done : Lean::Stopped;
}

}  // namespace ncc::iso
