// Structure-keeping translation (docs/EMIT.md "Structure-keeping translation"): writes the NC IR
// of an ISO (Fanuc Macro B, LinuxCNC) or Sinumerik program as a program of the other family,
// keeping its variables, expressions, loops, branches, jumps and subprogram calls instead of the
// executed path. What the target cannot say exactly is a located error naming the construct.
#pragma once
#include "backends/emit/Emitter.h"
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"

#include <string>
#include <vector>

namespace ncc::emit {

struct StructuredOptions {
  Target target = Target::Sinumerik;
  std::string programName;      // the source file: names the main program
  bool comments = true;
  double realTolerance = 1e-12;  // the machine's Sinumerik REAL comparison tolerance
  int rParams = 100;             // the machine's Sinumerik R parameters R0..R(n-1)
};

// One output file. files[0] is the main program (`name` its file name when the target needs
// separate files, else empty); Sinumerik subprograms follow as `L1234.SPF`, `NAME.SPF`.
struct StructuredFile {
  std::string name;
  std::string text;
};

// Writes `m` (verified front-end output) for opts.target. False after reporting errors.
bool writeStructured(const ir::Module &m, const StructuredOptions &opts, std::vector<StructuredFile> &files,
                     Diagnostics &diags);

// The listing of several files on one stream: each file after the first behind a comment line
// naming it (`; ---- file L1234.SPF`), so that standard output shows the whole translation.
std::string structuredListing(const std::vector<StructuredFile> &files, Target target);

}  // namespace ncc::emit
