// Heidenhain Klartext front end (TNC 620/640 conversational programs, .h/.H): the program
// frame, path blocks, Q parameters, labels and program calls, lowered to NC IR (docs/IR.md
// §8.3, docs/HEIDENHAIN.md).
#pragma once
#include "ir/CycleCatalog.h"
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"

#include <map>
#include <string>
#include <vector>

namespace ncc::hei {

struct HeiOptions {
  std::vector<std::string> searchDirs;       // where CALL PGM looks after the program's folder
  std::vector<std::string> linkedFunctions;  // defined by linked files: not searched
  CycleLookup cycles = nullptr;              // the cycle library's hei.* entries (null: none)
  ProbeTable probe;                          // the touch probe's table values (Probe.cpp)
  std::multimap<std::string, int> toolNames;  // the machine's tool names -> numbers (TOOL CALL "name")
};

// Parses the main program and every program it calls (CALL PGM) into `out`: functions[0] is
// "main". False when an error was reported.
bool parseHeidenhainProgram(SourceManager &sm, uint32_t fileId, const HeiOptions &opts, Diagnostics &diags,
                            ir::Module &out);

}  // namespace ncc::hei
