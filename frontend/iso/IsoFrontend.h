// ISO G-code front end (Fanuc-compatible, Sinumerik 808D ISO mode) with Fanuc Custom Macro B,
// and the RS274NGC (LinuxCNC) flavour for files ending in .ngc. Lowers source text to NC IR.
//
// Conventions of the produced IR (see frontend/iso/README.md for the full list):
//  - every source block with content starts with `block` (n= when it has an N word);
//  - the ops of one block follow the LinuxCNC rs274 execution order;
//  - dwell `seconds=` and the cycle dwell `P` of `move` are in seconds (Fanuc P without a decimal
//    point is milliseconds; RS274NGC P is seconds);
//  - the canned-cycle repeat count is always `L` (Fanuc writes K).
#pragma once
#include "frontend/ModeSwitch.h"
#include "ir/CmdSink.h"
#include "ir/Diagnostics.h"
#include "ir/ModeTable.h"
#include "ir/NCIR.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::iso {

// Which Fanuc Custom Macro B variables hold the tool offsets (machine [controller]
// offset_memory): none, or tool compensation memory C (#2001… H wear, #2201… H geometry,
// #10001-#13999 H/D wear/geometry; ir/SystemParams.h).
enum class OffsetMemory : uint8_t { None, C };

// A G or M code that calls a program (machine [controller] macro_calls; Fanuc parameters
// 6050-6089, 808D MD10814-MD10817): README.md "Macro calls by code".
struct CodeCall {
  char letter = 'M';       // 'G' or 'M'
  int64_t code10 = 0;      // the code in tenths: G65.1 = 651, M6 = 60
  std::string callee;      // the function: "O9001", "M6_MAKRO"
  bool subprogram = false;  // M98-like (no arguments, after the block), else G65-like
};

struct IsoOptions {
  // How words written without a decimal point are read: "calculator" (X1000 = 1000 mm),
  // "is-b" (x0.001) or "is-c" (x0.0001); see the spec 2.3 for the per-address factors.
  std::string decimalMode = "calculator";
  unsigned blockDeleteMask = 0;         // bit n set = skip level /n active (/ = /0)
  std::vector<std::string> searchDirs;  // subprogram files; default: dir of the main file
  bool axesScaleEnable = false;         // G51 reads I J K (else P): machine [controller]
  double scaleWeighting = 0.001;        // G51 factor unit
  std::vector<ModeValue> startup;       // start-up modes: units, feed mode, motion as the block words' context
  OffsetMemory offsetMemory = OffsetMemory::None;
  bool lathe = false;                   // machine [controller] kind = "lathe": turning codes, T0101, U/W
  char latheSystem = 'A';               // its G-code system: 'A' (U/W incremental), 'B' or 'C'
  bool auxiliaryB = false;              // the machine has no B axis: .nc B<n> is an auxiliary function
  std::vector<std::string> linkedFunctions;  // defined by linked files: calls to them are not searched
  std::vector<CodeCall> codeCalls;      // machine macro_calls
  GuestFactory siemensBlocks;           // G290 … G291: the Sinumerik front end's blocks (null: G290 is an error)
};

// The ISO-mode blocks of a Sinumerik program (G291 … G290, frontend/ModeSwitch.h), lowered by
// this front end into the Sinumerik program's function. Calls (M98, G65, G66) are errors there.
std::unique_ptr<GuestBlocks> isoBlocks(const IsoOptions &opts, Diagnostics &diags);

// Parses the main program file (already in sm) plus the subprograms it calls (same file after
// the main program, or separate files found in searchDirs) into `out`
// (functions[0] = "main", others "O1234"). Returns false when an error was reported.
bool parseIsoProgram(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags,
                     ir::Module &out);

// True when the text can be parsed block by block: no Macro B control flow (IF/WHILE/GOTO/DO/
// END), no M98/M99/G65/G66, no RS274 O-words and no O-number program after the main program.
// With `sm`, the text is `file`'s, whose scanned pages may leave memory (SourceManager::released).
// `byLines`: the pre-scan's line by line walk over the whole text (the unit test's reference for
// the bulk scan that follows the first block otherwise).
bool isoIsStreamable(std::string_view text, const SourceManager *sm = nullptr, uint32_t file = 0, bool byLines = false);

class IsoBlockStream {
public:
  IsoBlockStream(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags);
  ~IsoBlockStream();
  IsoBlockStream(const IsoBlockStream &) = delete;
  IsoBlockStream &operator=(const IsoBlockStream &) = delete;
  // Parses at most maxBlocks source blocks and appends their ops to `out`. Returns false when
  // nothing more was produced: end of file, or a fatal error (a construct that needs the whole
  // program, reported as an error; or `lean` refused a command). With `lean`, plain blocks
  // become machine commands sent to it at once (BlockLowerer::lowerLean), after the ops
  // appended before them have run: the call then returns early.
  bool next(ir::Region &out, size_t maxBlocks, CmdSink *lean = nullptr);
  uint64_t leanReuses() const;  // plain blocks lowered by a decision made for their shape before

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncc::iso
