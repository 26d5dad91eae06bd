// CL data front ends: APT CL text (ISO 4343-style cutter-location files, the postprocessor input
// of NX, CATIA and Mastercam: .apt .cls .cl, docs/APT.md) and ADEM CLData (.cld, docs/CLDATA.md):
// records lowered to NC IR (docs/IR.md §8.4).
#pragma once
#include "frontend/Frontend.h"
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"

#include <memory>

namespace ncc::cld {

// Parses the file into `out` (functions[0] is "main"). False when an error was reported.
bool parseAptProgram(SourceManager &sm, uint32_t fileId, Diagnostics &diags, ir::Module &out);
// ADEM CLData (.cld): the text listing or the binary record file (docs/CLDATA.md).
bool parseAdemProgram(SourceManager &sm, uint32_t fileId, Diagnostics &diags, ir::Module &out);

// The same programs a chunk of records at a time, in bounded memory (docs/CLDATA.md
// "Streaming"): the ops of the whole-program front end, chunk by chunk.
std::unique_ptr<BlockStream> openAdemStream(SourceManager &sm, uint32_t file, Diagnostics &diags);
// APT CL text the same way (docs/APT.md "Streaming").
std::unique_ptr<BlockStream> openAptStream(SourceManager &sm, uint32_t file, Diagnostics &diags);

}  // namespace ncc::cld
