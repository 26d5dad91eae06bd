// Private to backends/emit: work offsets, local shifts and tool length compensation in the
// emitted program (EmitterFrame.cpp, docs/EMIT.md "Work offsets", "Tool length"). The stream is
// in machine coordinates; the written program selects the source's work offset, writes its
// shift (G52 / TRANS) and its tool length (G43 H / D), and its positions are the machine ones
// minus what those codes add on the target. What a target cannot express stays in the positions
// ("baked"), which a comment in the program says.
#pragma once
#include "ir/MotionIR.h"
#include "runtime/Machine.h"

#include <string>

namespace ncc::emit::detail {

// What the source program has in force (from FrameChange, ToolLength and ToolChange records).
struct SourceFrame {
  int selection = 1;        // the FrameChange `wcs`: 1..9 G54…, 0 none
  FrameMatrix matrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  AxisShift axisShift{};    // A B C U V W
  bool started = false;     // a FrameChange was seen (before it: the machine's G54)
  double toolZ = 0, toolX = 0, toolY = 0;
  int toolH = 0;            // the ToolLength record's H (Sinumerik D: the spindle tool)
  int spindleTool = 0;
  // The plane: a Sinumerik target puts a D word's length on the plane's tool axis (docs/SINUMERIK.md
  // "Tool offsets"), so in G18/G19 the length is baked instead.
  bool planeXY = true;
};

// What the written program has in force, and the translation it adds to its positions.
struct WrittenFrame {
  int selection = 1;           // the work offset the set-up (else the reset state, G54) or a block selected
  std::array<double, 3> shift{};  // G52 / TRANS X Y Z as the target reads them back
  double toolZ = 0;            // the tool length the written G43 H / D adds on Z
  int toolWord = 0;            // the H (ISO) or D (Sinumerik) number written, 0 none
  AxisVec offset{};            // machine = written position + offset, per axis
  AxisVec base{};              // what the machine's stored base frames add on the target (in offset)
  std::string baked;           // what the positions hold that no code says (the last note written)
};

// The tool length offset number n gives (ISO G43 H<n>, APT LOADTL/n, ADEM [35]): through the
// machine's offset_numbers when it has them (808D $TC_DPH), else tool n's edge 1. False when the
// machine has none.
bool offsetNumberLength(const Machine &machine, int n, double &length);

// The translation the machine's stored Sinumerik base frames ([offsets] base, nc_base) add to a
// program run on it, as runtime/ExecutorFrames.cpp builds $P_ACTBFRAME: the frames selected by
// base_frame_mask, active once the program selects a work offset (G500, G54…, `selected`), and
// at the start only when reset_mode_mask keeps them (MD20110 bits 0 and 14). The stored frames
// are offsets without rotation, so their chain is the sum. Zero on a machine without them.
AxisVec storedBaseFrames(const Machine &machine, bool selected);

// The translation in force when a run on the machine starts and the program selects nothing
// (the Klartext and CL readers): the stored base frames as above and the G54 offset, unless the
// machine starts a Sinumerik program in G500 (reset_mode_mask without bit 5).
AxisVec startFrame(const Machine &machine);

}  // namespace ncc::emit::detail
