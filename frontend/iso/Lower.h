// Lowering of one parsed ISO block to NC IR ops, in the LinuxCNC rs274 execution order.
// Keeps the little modal state the lowering itself needs (motion mode for cycle words and G53,
// units and feed mode for the decimal-point rule), tracked in source order.
#pragma once
#include "frontend/iso/Codes.h"
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Syntax.h"

namespace ncc::iso {

struct CallRef {
  std::string callee;
  SourceLoc loc;
};

// Puts the labels the contour cycles (G70-G73, LowerTurning.cpp) of `f` name and checks the
// contour blocks; false when an error was reported.
bool placeContourLabels(ir::Function &f, Diagnostics &diags);

class BlockLowerer {
public:
  BlockLowerer(const IsoOptions &opts, Flavour flavour, Diagnostics &diags);
  bool optionsValid() const { return decimal_ >= 0; }

  ir::Op blockOp(const ParsedBlock &b) const;
  void lowerComments(const ParsedBlock &b, ir::Region &out);
  // Words (G/M codes, addresses) and assignments. Returns false when an error was reported.
  bool lowerActions(ParsedBlock &b, ir::Region &out);

  std::vector<CallRef> calls;  // every callee referenced, for subprogram resolution
  bool allowCalls = true;      // false when streaming: M98/G65 are then errors

private:
  struct Block;  // one block being lowered (Lower.cpp)
  Diagnostics &diags_;
  Flavour flavour_;
  int decimal_ = 0;  // 0 calculator, 1 IS-B, 2 IS-C, -1 invalid
  bool axesScaleEnable_ = false;  // G51 factors: I J K (else P)
  bool lathe_ = false;            // turning codes, T0101, (system A) U/W incremental X/Z
  char system_ = 'A';             // the lathe's G-code system
  double scaleWeighting_ = 0.001;
  ModeValue motion_ = ModeValue::Rapid;
  ModeValue pathMotion_ = ModeValue::Rapid;  // the last G0-G3 (Fanuc's G80 returns to it)
  ModeValue feedMode_ = ModeValue::PerMinute;
  ModeValue units_ = ModeValue::MM;
};

}  // namespace ncc::iso
