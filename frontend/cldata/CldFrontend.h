// APT CL text front end (ISO 4343-style cutter-location files, the postprocessor input of NX,
// CATIA and Mastercam: .apt .cls .cl): records lowered to NC IR (docs/APT.md, docs/IR.md §8.4).
#pragma once
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"

namespace ncc::cld {

// Parses the file into `out` (functions[0] is "main"). False when an error was reported.
bool parseAptProgram(SourceManager &sm, uint32_t fileId, Diagnostics &diags, ir::Module &out);

}  // namespace ncc::cld
