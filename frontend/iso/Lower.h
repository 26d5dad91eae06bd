// Lowering of one parsed ISO block to NC IR ops, in the LinuxCNC rs274 execution order.
// Keeps the little modal state the lowering itself needs (motion mode for cycle words and G53,
// units and feed mode for the decimal-point rule), tracked in source order.
#pragma once
#include "frontend/iso/Codes.h"
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Syntax.h"
#include "ir/CmdSink.h"

namespace ncc::iso {

struct CallRef {
  std::string callee;
  SourceLoc loc;
};

// Puts the labels the contour cycles (G70-G73, LowerTurning.cpp) of `f` name and checks the
// contour blocks; false when an error was reported.
bool placeContourLabels(ir::Function &f, Diagnostics &diags);

// After every program of `m` is read: the 808D call context only where the callee reads it,
// the caller's side of M99 P<n>, the start values of the lowered calls' globals
// (ProgramCalls.cpp). False when an error was reported.
bool finishCalls(ir::Module &m, Diagnostics &diags);

class BlockLowerer {
public:
  BlockLowerer(const IsoOptions &opts, Flavour flavour, Diagnostics &diags);
  bool optionsValid() const { return decimal_ >= 0; }

  ir::Op blockOp(const ParsedBlock &b) const;
  void lowerComments(const ParsedBlock &b, ir::Region &out);
  // Words (G/M codes, addresses) and assignments. Returns false when an error was reported.
  bool lowerActions(ParsedBlock &b, ir::Region &out);

  // The lean path of a streamed flat program (LowerLean.cpp): a plain block (constant words,
  // mode codes, a feed and a move) goes straight to machine commands, the same commands
  // lowerActions and the command templates would give. Fallback: the block needs lowerActions
  // (nothing was done); Held: it fits, but `pending` said ops wait to run first (nothing done);
  // Error: a lowering error was reported; Stopped: the sink refused a command.
  enum class Lean : uint8_t { Done, Fallback, Held, Error, Stopped };
  Lean lowerLean(ParsedBlock &b, CmdSink &sink, bool pending);

  uint64_t leanReuses = 0;  // blocks that took a cached lean decision (tests)

  std::vector<CallRef> calls;  // every callee referenced, for subprogram resolution
  // Set when calls cannot be resolved (a streamed program, the ISO blocks of a Sinumerik
  // program): M98, G65/G66, G05 P and the contour cycles are then errors saying why.
  const char *callsRefused = nullptr;
  const char *callsRefusedRule = "not-streamable";
  // A mode the other language's blocks set (G290 … G291, frontend/ModeSwitch.h).
  void followMode(ModeValue m);
  // The block belongs to the main program (Fanuc M99 there restarts it, ISO-M-04).
  bool inMain = false;

  // Global variables of the lowered calls (LowerCalls.cpp): set while a program called by a
  // code runs (its codes act as themselves), and M99 P's block number for the caller.
  static constexpr const char *kByCodeFlag = "_macro_by_code";
  static constexpr const char *kM99Block = "_m99_block";
  static constexpr const char *kM99Target = "_m99_target";
  static constexpr const char *kMainStart = "_main_start";  // the label M99 in main goes to

private:
  struct Block;  // one block being lowered (Lower.cpp)
  bool lowerPlain(ParsedBlock &b, ir::Region &out);  // the block's own codes, no code calls
  // Macro calls by code (machine macro_calls, LowerCalls.cpp). codeCallOf: the block's calling
  // code (null: none); false when an error was reported.
  bool codeCallOf(const ParsedBlock &b, const CodeCall *&call, const IsoWord *&word);
  bool lowerCodeCall(ParsedBlock &b, const CodeCall &call, const IsoWord &word, ir::Region &out);
  bool plainCode(const ParsedBlock &b, const std::string &code, ir::Region &out);
  struct Modes {
    ModeValue motion, pathMotion, feedMode, units, plane, distance;
    bool polar;
  };
  Modes modes() const { return {motion_, pathMotion_, feedMode_, units_, plane_, distance_, polar_}; }
  void setModes(const Modes &m) {
    motion_ = m.motion, pathMotion_ = m.pathMotion, feedMode_ = m.feedMode, units_ = m.units;
    plane_ = m.plane, distance_ = m.distance, polar_ = m.polar;
  }
  std::vector<CodeCall> codeCalls_;  // a copy: a stream's options are a temporary
  Diagnostics *diags_;  // a pointer: lowerCodeCall swaps in a scratch one
  ir::Region none_;  // the lean path's Block writes no ops
  MachineCmd cmd_;   // the lean path's command, cleared after each use
  MachineCmd leanBlock_, leanMode_;  // leanMove's Block and Mode commands (it passes three at once)
  // A plain move block decided (LowerLean.cpp): what classify, leanFits and trackModes made of
  // its shape in the state before it, reused for the next block of that shape in that state.
  struct LeanMove {
    static constexpr int kMaxWords = 14;  // a motion code and XYZABCUVWIJKR, each once
    static constexpr uint8_t kCode = 0xFF, kRotary = 0x80;
    // The key: ParsedBlock::shape, the motion code's value (its letter is the shape's only G),
    // leanState() before the block.
    uint64_t shape = 0, state = 0;
    double code = 0;
    double linear = 1, rotary = 1;  // the divisors of words without a decimal point
    WordMask mask = 0;              // the move's words
    uint8_t word[kMaxWords];        // per word in order: its Word (| kRotary), or kCode
    int8_t motionWord = -1;         // the motion code's index (-1: none)
    ModeValue mode{}, motionAfter{}, pathMotionAfter{};  // its mode value; the modes after the block
  };
  // Two ways per set (G2 and G3 with the same words share a set): a block that finds neither
  // decides again and takes the first way, the first moving to the second.
  static constexpr int kLeanSets = 32;
  LeanMove leanCache_[kLeanSets][2];
  bool leanMove(const LeanMove &m, ParsedBlock &b, CmdSink &sink);
  [[gnu::noinline]] Lean lowerLeanDecide(ParsedBlock &b, CmdSink &sink, bool pending, LeanMove *set, uint64_t state);
  // Everything the lean path's decision reads of the lowerer, packed: the modes, the decimal
  // mode, the flavour, G16, the lathe and the 808D's B function (the G-code cache only ever
  // gains entries, and each is the same for the same code).
  uint64_t leanState() const {
    return (uint64_t)motion_ | (uint64_t)pathMotion_ << 8 | (uint64_t)feedMode_ << 16 | (uint64_t)units_ << 24 |
           (uint64_t)plane_ << 32 | (uint64_t)distance_ << 40 | (uint64_t)(uint8_t)decimal_ << 48 |
           (uint64_t)((unsigned)flavour_ | (unsigned)polar_ << 2 | (unsigned)lathe_ << 3 | (unsigned)auxiliaryB_ << 4)
               << 56;
  }
  static size_t leanSet(uint64_t shape, uint64_t state) {
    static_assert(kLeanSets == 32);
    return (size_t)((((shape * 0x9E3779B97F4A7C15ull) ^ state) * 0xC2B2AE3D27D4EB4Full) >> 59);
  }
  Flavour flavour_;
  int decimal_ = 0;  // 0 calculator, 1 IS-B, 2 IS-C, -1 invalid
  bool axesScaleEnable_ = false;  // G51 factors: I J K (else P)
  bool lathe_ = false;            // turning codes, T0101, (system A) U/W incremental X/Z
  bool auxiliaryB_ = false;       // .nc on a machine without a B axis: B<n> is an auxiliary output
  char system_ = 'A';             // the lathe's G-code system
  double scaleWeighting_ = 0.001;
  ModeValue motion_ = ModeValue::Rapid;
  ModeValue pathMotion_ = ModeValue::Rapid;  // the last G0-G3 (Fanuc's G80 returns to it)
  ModeValue feedMode_ = ModeValue::PerMinute;
  ModeValue units_ = ModeValue::MM;
  // G16 polar coordinates (808D/Fanuc, ISO-MOT-11) and the modes that decide how its words read.
  bool polar_ = false;
  ModeValue plane_ = ModeValue::XY;
  ModeValue distance_ = ModeValue::Absolute;
  // G0..G99 as classify found them (no error): its table look-ups depend only on the code, the
  // flavour and the lathe's system, all fixed here, so a flat program's G1s look up once.
  static constexpr int kGCacheSize = 100;
  const GCodeInfo *gCache_[kGCacheSize] = {};
  static int gCacheSlot(double code) {
    return code >= 0 && code < kGCacheSize && (double)(int)code == code ? (int)code : -1;
  }
  const GCodeInfo *cachedGCode(double code) const {
    int i = gCacheSlot(code);
    return i >= 0 ? gCache_[i] : nullptr;
  }
  void cacheGCode(double code, const GCodeInfo *gi) {
    if (int i = gCacheSlot(code); i >= 0) gCache_[i] = gi;
  }
};

}  // namespace ncc::iso
