// MachineCmd: one machine-level NC IR op with every operand evaluated to a number. This is the
// boundary between program evaluation (the eval engine or JIT-compiled code) and the executor
// (runtime/Executor), which gives the commands their modal meaning and produces Motion IR.
// It is a plain struct so JIT code can build it on the stack or store long runs as constant
// tables.
#pragma once
#include "ir/Diagnostics.h"
#include "ir/ModeTable.h"

#include <cstdint>
#include <string_view>

namespace ncc {

// The words a machine op can carry, one table: a word's slot in `w`, its key in NC IR (an
// address letter, or a name for words without one) and the character messages use. PolarR and
// PolarA are RS274NGC's `@` (polar radius) and `^` (polar angle, degrees); Chamfer and Round the
// corner after a move (ISO `,C` `,R`, Sinumerik CHF RND, Heidenhain CHF RND); ViaX ViaY ViaZ the
// intermediate point of an arc through three points (Sinumerik CIP I1 J1 K1), read like X Y Z.
// A dialect's new word is one row here (and one in kWordKeys); a command holds up to 64.
// Depth … RoughFeed are the region pocket's parameters (contour action=run use=pocket,
// docs/IR.md §5.6). Opening is an arc's opening angle in degrees (Sinumerik AR=),
// ChamferLeg a chamfer given by its legs, the distance from the corner along each move (CHR=).
enum class Word : uint8_t {
  X, Y, Z, A, B, C, U, V, W, I, J, K, R, P, Q, L, F, S, T, H, D, E, PolarR, PolarA, Chamfer, Round,
  ViaX, ViaY, ViaZ, Depth, Infeed, Surface, Clearance, Height, Stepover, Overlap, SideAllowance,
  FloorAllowance, Direction, PlungeFeed, RoughFeed, Opening, ChamferLeg,
  SplineWeight, SplineDegree,  // Sinumerik BSPLINE PW= (a point's weight) and SD= (the degree)
  // Sinumerik POLY: a move with PolyIndex k carries the coefficients a_k (X Y Z) and b_k (weight)
  // of the block's polynomials; the block's move then has the end point and PL (PolyInterval).
  PolyIndex, PolyInterval, PolyDenominator,
  LeadChange,  // Sinumerik G34/G35: the thread lead's change per revolution (signed), mm/rev^2
  RetractFeed, CornerRadius,  // region cycles: the feed out at the end, the rounding of inner corners
  AddOffset,  // Sinumerik DL: the additive offset set of the edge (tool_length)
  FinishAllowance, Extension,  // Heidenhain 24 Q14 (left after side finishing), 25 Q448 (path extension)
  FanucCycle,  // 808D/Fanuc drilling cycle (.nc G73, G74, G84): the manual's steps, not rs274's
  Count
};
constexpr int kWords = (int)Word::Count;
static_assert(kWords <= 64, "MachineCmd::mask has 64 bits");
constexpr const char *kWordKeys[kWords] = {
    "X", "Y", "Z", "A", "B", "C", "U", "V", "W", "I", "J", "K", "R", "P", "Q", "L", "F", "S", "T", "H", "D", "E",
    "polar_r", "polar_a", "chamfer", "round", "via_x", "via_y", "via_z", "depth", "infeed", "surface",
    "clearance", "height", "stepover", "overlap", "side_allowance", "floor_allowance", "direction",
    "plunge_feed", "feed", "opening", "chamfer_leg", "weight", "degree", "poly_index", "interval", "denominator", "dlead",
    "retract_feed", "corner_radius", "dl", "finish_allowance", "extension", "fanuc_cycle"};
// A word's address letter (the key's one character), 0 for a named word.
constexpr char wordLetter(Word w) { return kWordKeys[(int)w][1] == 0 ? kWordKeys[(int)w][0] : 0; }
using WordMask = uint64_t;
constexpr WordMask wordBit(Word w) { return WordMask(1) << (unsigned)w; }
// The words a move may make absolute or incremental on their own (MachineCmd sub/sub2, 16
// bits): the axes X..W and I J K.
constexpr uint16_t kPerWordDistance = 0x1ff | 1u << (unsigned)Word::I | 1u << (unsigned)Word::J | 1u << (unsigned)Word::K;
// Returns false for letters that are not words of a machine op.
bool wordFromLetter(char c, Word &out);
// The word of an NC IR key: a letter (either case) or a named key of kWordKeys.
bool wordFromKey(std::string_view key, Word &out);

enum class CmdKind : uint8_t {
  Block,        // start of a source block: blockNumber, loc
  Comment,      // text
  Message,      // text; sub: MessageKind
  Mode,         // modes[0..nmodes)
  Feed,         // w[F]
  Speed,        // w[S]
  ToolSelect,   // w[T]
  ToolChange,
  Spindle,      // sub: 0 stop, 1 cw, 2 ccw, 3 orient (w[R] angle, w[Q] wait s, sub2 way 0 cw 1 ccw 2 shortest)
  Coolant,      // sub: bit0 flood on, bit1 mist on; sub2 = bit0 flood given, bit1 mist given
  Dwell,        // w[P] seconds
  Move,         // words in mask; sub / sub2: bits (wordBit, X..C and I J K) of the words that are
                //   incremental / absolute whatever G90/G91 (G90.1/G91.1 for I J K) says
                //   (Sinumerik IC()/AC(), Heidenhain IX)
  Home,         // sub: reference 1 (G28) or 2 (G30); intermediate point in mask words; sub2: bits
                //   of its incremental words (a lathe's G28 U W)
  MachineMove,  // sub: 0 rapid, 1 feed; G53 target in mask words
  ToolLength,   // w[H] offset number, 0 cancels; sub: ToolLengthForm (G43.1/G43.2 axis words in the mask)
  CutterComp,   // sub: 0 off, 1 left, 2 right; w[D] when in mask
  WorkOffset,   // sub: 1..9 (G54..G59.3)
  SetOffset,    // sub: SetOffsetKind; index in w[P]; values in mask words
  Stop,         // sub: StopKind
  Aux,          // w[P] the M number (or other aux value); sub: letter ('M', 'B', 'H')
  Frame,        // sub: FrameSlot; sub2: FrameAction | FrameFlag bits; values in mask words
  Contour,      // sub: ContourAction; sub2: ContourUse; the consumer's parameters in U W R (the
                //   region pocket's in its own words, kPocketParams)
  Cycle,        // a cycle-library entry (docs/IR.md §5.8): sub the machining entry's index in
                //   cycleLibrary() + 1 (0 none: the stored one) in its low byte, the word of the one
                //   STRING argument + 1 in its high byte (its value: text), sub2 the position pattern's index
                //   + 1 (0 none) | CycleAction << 12; the words are positional, not letters: word i
                //   is parameter i of the machining entry, the pattern's follow (kCycleArgSlots)
  Count
};

enum class StopKind : uint8_t { Program, Optional, End, EndRewind };
// Operator message (Sinumerik MSG, Fanuc #3006, LinuxCNC MSG) or LinuxCNC's DEBUG (to the trace),
// PRINT (to stderr) and ABORT (stops the run). Numbers in DEBUG/PRINT/ABORT texts print "%f".
// NotSimulated: a machine-specific construct the front end parsed and checked but ncc does not
// simulate (a Sinumerik synchronized action, channel coordination …): a run stops there with
// its text (rule not-simulated), lint notes it and goes on.
enum class MessageKind : uint8_t { Msg, Debug, Print, Abort, NotSimulated };
// G92.2 zeroes the G92 offsets but keeps them for G92.3 to restore; G28.1/G30.1 store the
// current position as reference point 1/2.
// G52 in RS274NGC sets the G92 offsets of the named axes (LinuxCNC keeps both in one register).
// Tool offsets (T/H/D number in w[P]): ToolSet is LinuxCNC's G10 L1 (Z length, R radius);
// ToolTouch/ToolTouchG593 its G10 L10/L11 (the length that makes the current position the Z word
// in the current system / in G59.3); ToolLength… the Fanuc/808D G10 L10-L13 (one value, R).
enum class SetOffsetKind : uint8_t {
  G92, G92Cancel, G10L2, G10L20, G92Suspend, G92Restore, StoreHome1, StoreHome2, G52,
  ToolSet, ToolTouch, ToolTouchG593, ToolLength, ToolLengthWear, ToolRadius, ToolRadiusWear,
  // The 808D turning G10 P X(U) Z(W) R(C): P1-P99 the wear, P101-P1600 the geometry of offset
  // P (- 100); X Z R absolute, U W C added (runtime/ExecutorState.cpp).
  LatheTool,
  // Sinumerik DELDL (runtime/ExecutorSinTool.cpp): the additive offsets of tool P's edge D go
  // (P absent: every tool; D absent: every edge); Q 1: the program reads the status.
  DeleteAdditive
};
// The programmable frame (runtime/Frame.h): its slots, what a `frame` op does to one, and how a
// rotation reads its words. form=plane is the ISO 2-D G68 (about the active plane's normal axis,
// R absolute or incremental by G90/G91, an omitted centre word = the current position); form=axis
// the 3-D G68 (about the vector I J K, R absolute, an omitted centre word = 0).
enum class FrameSlot : uint8_t { Local, Rotation, Scale, Mirror, Count };
// tool_length form=: the tool table's length (G43 H), LinuxCNC G43.1 (each given axis's offset
// set to its word), G43.2 (H's length or the axis values added to the active offsets).
enum class ToolLengthForm : uint8_t { Table, Dynamic, Add };
enum class FrameAction : uint8_t { Cancel, Set };
constexpr uint8_t kFrameFormAxis = 0x10;  // in sub2, beside the FrameAction
// combine=ordered (Heidenhain's cycles 8/10/11/26): the slot may be set while others are, and they
// compose scale, then mirror, then rotation (ProgrammableFrame::update); without it (ISO G51,
// G51.1, G68, whose manuals give no order) a second kind is an error.
constexpr uint8_t kFrameCombine = 0x20;

// Contour capture (runtime/ExecutorContour.cpp): `Begin` makes the following motion a contour
// (records go to the capture, not the sinks), `End` hands it to a consumer (`ContourUse`) with
// its parameters; `Data` sets a consumer's modal data (the ISO G71/G72 `U R` and G73 `U W R`
// first blocks).
// `Run` runs a consumer on what earlier captures collected (the region pocket: `Outline` and
// `Island` captures collect the region, `Pocket` roughs it out; runtime/ExecutorRegion.cpp).
enum class ContourAction : uint8_t { Data, Begin, End, Run };
// `Sub` (Heidenhain SL): a sub-contour whose RL/RR and direction make it a pocket or an island
// (the capture notes RL/RR instead of compensating: begin says use=subcontour); `Pilot` and
// `Floor` run on the region as `Pocket` does (cycles 21 and 23); `Side` finishes its walls
// (cycle 24); `Train` (cycle 25) mills a captured open contour on its RL/RR side, noted as `Sub`'s.
// Rs274*: LinuxCNC's G70, G71 and G72 (runtime/cycles/TurningRs274.h).
enum class ContourUse : uint8_t {
  Finish, RoughAlongZ, RoughAlongX, PatternRepeat, Outline, Island, Pocket, Sub, Pilot, Floor,
  Side, Train, Rs274Finish, Rs274RoughZ, Rs274RoughX,
  Keep,  // the captured contour is kept for the next library cycle (Sinumerik CYCLE95's NPP)
  // Sinumerik contour tables (runtime/ExecutorContourTable.cpp): begin/end CONTPRON or CONTDCON
  // (the captured moves become the table the program reads back as $_sin_table), run EXECTAB.
  SinTable
};
// What a `cycle` op does (docs/IR.md §5.8): Run the entry here (at each position of its
// pattern), Define store it for Call (Heidenhain CYCL DEF), Modal store it and run it after each
// following move (Sinumerik MCALL), Call run the stored one here, Cancel end Modal; Trigger (no
// op: the engines send it for modal_trigger) runs the modal one as after a move.
enum class CycleAction : uint8_t { Run, Define, Modal, Call, Cancel, Trigger };
constexpr unsigned kCycleActionShift = 12;
constexpr uint16_t kCyclePatternMask = (1u << kCycleActionShift) - 1;
constexpr unsigned kCycleTextShift = 8;  // sub: entry index + 1 | (STRING argument's word + 1) << 8
constexpr int kCycleArgSlots = kWords;  // the words of a command: parameters of entry and pattern together
inline CycleAction cycleAction(uint16_t sub2) { return (CycleAction)(sub2 >> kCycleActionShift); }

// The region pocket's parameters (docs/IR.md §5.6): their words and their names in the Motion IR
// cycle_begin record (at most 7 characters).
enum class PocketParam : uint8_t {
  Depth, Infeed, Surface, Clearance, Height, Stepover, Overlap, SideAllowance, FloorAllowance, Direction,
  PlungeFeed, Feed, RetractFeed, CornerRadius, Count
};
struct PocketParamSlot {
  Word word;
  const char *bracket;
  const char *key() const { return kWordKeys[(int)word]; }
};
inline constexpr PocketParamSlot kPocketParams[(int)PocketParam::Count] = {
    {Word::Depth, "depth"},      {Word::Infeed, "infeed"},       {Word::Surface, "surface"},
    {Word::Clearance, "clear"},  {Word::Height, "height"},       {Word::Stepover, "step"},
    {Word::Overlap, "overlap"},  {Word::SideAllowance, "side"},  {Word::FloorAllowance, "floor"},
    {Word::Direction, "dir"},    {Word::PlungeFeed, "fplunge"},  {Word::RoughFeed, "feed"},
    {Word::RetractFeed, "fout"},  {Word::CornerRadius, "round"},
};

// One slot per mode group: a `mode` op sets at most one value per group (the verifier rejects a
// key given twice), so every key of the op fits.
constexpr int kMaxModes = (int)ModeGroup::Count;

struct MachineCmd {
  CmdKind kind = CmdKind::Block;
  uint16_t sub = 0;
  uint16_t sub2 = 0;
  uint8_t nmodes = 0;
  ModeValue modes[kMaxModes] = {};
  WordMask mask = 0;        // wordBit(...) of the words present
  int64_t blockNumber = -1; // for Block: the N word, -1 when none
  SourceLoc loc;
  const char *text = nullptr;  // Comment/Message; owned by the module or a string pool
  double w[kWords] = {};

  bool has(Word x) const { return mask & wordBit(x); }
  double get(Word x) const { return w[(unsigned)x]; }
  void set(Word x, double v) {
    w[(unsigned)x] = v;
    mask |= wordBit(x);
  }
  // Back to MachineCmd{}: the fields before the words, and only the words the mask says were set
  // (set() is the only writer), not all of them. For commands reused per block.
  void clear() {
    clearWords();
    kind = CmdKind::Block;
    sub = sub2 = 0;
    for (uint8_t i = 0; i < nmodes; ++i) modes[i] = {};
    nmodes = 0;
    blockNumber = -1;
    loc = {};
    text = nullptr;
  }
  void clearWords() {  // the words only, back to none set
    for (WordMask m = mask; m; m &= m - 1) w[__builtin_ctzll(m)] = 0;
    mask = 0;
  }
};

// The command the engines send for a `modal_trigger` op: the executor runs its modal cycle as
// after a move (none set: nothing), as the engines run a modal_call.
inline MachineCmd cycleTriggerCmd(SourceLoc loc) {
  MachineCmd c;
  c.kind = CmdKind::Cycle;
  c.sub2 = (uint16_t)((unsigned)CycleAction::Trigger << kCycleActionShift);
  c.loc = loc;
  return c;
}

}  // namespace ncc
