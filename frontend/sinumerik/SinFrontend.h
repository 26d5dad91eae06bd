// Sinumerik 840D sl front end: part programs (.MPF) and subprograms (.SPF) in the Siemens
// high-level language, lowered to NC IR (docs/IR.md §8.2, docs/SINUMERIK.md).
#pragma once
#include "frontend/ModeSwitch.h"
#include "ir/CycleCatalog.h"
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"

#include <string>
#include <vector>

namespace ncc::sin {

struct SinOptions {
  unsigned blockDeleteMask = 0;         // bit n set: blocks with skip level /n are left out (/ = /0)
  std::vector<std::string> searchDirs;  // where called subprogram files are looked up, in order
  std::vector<std::string> linkedFunctions;  // defined by linked files: not searched
  CycleLookup cycles = nullptr;         // the cycle library (sin.CYCLE81 …): standard cycle calls
  double realTolerance = 1e-12;         // relative tolerance of REAL comparisons (MD, manual L3284)
  GuestFactory isoBlocks;               // G291 … G290: the ISO front end's blocks (null: G291 is an error)
  bool macroArguments = false;          // the program is part of an ISO program: $C_X reads G65's X
  unsigned geoAxes = 7;                 // bit n: geometry axis n+1 (X, Y, Z) exists (ISAXIS)
};

// The Siemens-mode blocks of an ISO program (G290 … G291, frontend/ModeSwitch.h): lowered by
// this front end into the ISO program's function; the subprograms they call are loaded as here.
std::unique_ptr<GuestBlocks> siemensBlocks(SourceManager &sm, const SinOptions &opts, Diagnostics &diags);

// Parses the main program and every subprogram it calls (looked up in searchDirs as NAME.MPF,
// NAME.SPF, _N_NAME_MPF …) into `out`: functions[0] is "main". False when an error was reported.
bool parseSinumerikProgram(SourceManager &sm, uint32_t fileId, const SinOptions &opts, Diagnostics &diags,
                           ir::Module &out);

}  // namespace ncc::sin
