// Front-end dispatch: picks the dialect of a source file and runs its front end. Every front
// end produces NC IR (ir/NCIR.h); the textual IR (.ncir) is read by the IR parser.
#pragma once
#include "ir/CycleCatalog.h"
#include "ir/ModeTable.h"
#include "ir/NCIR.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ncc {
class CmdSink;

struct FrontendOptions {
  std::string decimalMode = "calculator";  // numbers without '.', see docs/MACHINE.md
  unsigned blockDeleteMask = 0;            // active block-delete levels (bit n = /n)
  std::vector<std::string> searchDirs;     // where called subprogram files are looked up
  bool axesScaleEnable = false;            // ISO G51: per-axis factors I J K (else P), machine [controller]
  std::vector<ModeValue> startup;         // the controller's start-up modes (units, feed mode, motion)
  double scaleWeighting = 0.001;           // ISO G51: unit of the factors
  std::string offsetMemory = "none";       // Fanuc tool offset variables: "none" or "C", machine [controller]
  bool lathe = false;                      // machine [controller] kind = "lathe"
  bool auxiliaryB = false;                 // ISO .nc: no B axis, B<n> is the 808D auxiliary function (H1=n)
  char latheSystem = 'A';                  // its gcode_system
  std::vector<std::string> linkedFunctions;  // defined by linked files (driver --link): not searched
  CycleLookup cycles = nullptr;            // the cycle library's entries (the driver's; null: none)
  ProbeTable probe;                        // Heidenhain touch-probe cycles: machine [controller] probe_*
  std::multimap<std::string, int> toolNames;  // the machine's tool names (Klartext TOOL CALL "name")
  // The mode a Sinumerik program file (.mpf/.spf) starts in: "siemens" (G290), or "iso" (G291:
  // the 808D's ISO default mode, machine [controller] start_mode; the ISO front end reads it).
  std::string startMode = "siemens";
  // Machine [controller] macro_calls: a G or M code ("M6", "G65.1") that calls `program`, with the
  // block's addresses as arguments (G65) or, `subprogram`, as M98 after the block.
  struct CodeCall {
    std::string code, program;
    bool subprogram = false;
  };
  std::vector<CodeCall> macroCalls;
  unsigned geoAxes = 7;  // bit n: the machine has geometry axis n+1 (X, Y, Z): Sinumerik ISAXIS
};

// What a file holds: a dialect, or textual NC IR.
// Motion: Motion IR text (.motion), the executed form: the driver feeds it to the sinks directly
// (ncc run, translate, compile --emit=motion); it has no NC IR, so parseProgram rejects it.
enum class SourceKind : uint8_t { ISO, Sinumerik, Heidenhain, CLData, Adem, NCIR, Motion, Unknown };
const char *sourceKindName(SourceKind k);
bool sourceKindFromName(std::string_view s, SourceKind &out);
// From the extension first, then from the content.
SourceKind detectSourceKind(const std::string &path, std::string_view text);

// Parses a whole program (main file plus the subprogram files it calls).
bool parseProgram(SourceKind kind, SourceManager &sm, uint32_t file, const FrontendOptions &opts,
                  Diagnostics &diags, ir::Module &out);

// Block-by-block parsing of huge flat programs, so memory stays bounded. Null when the program
// needs whole-program parsing (control flow, subprograms) or the dialect has no streaming.
class BlockStream {
public:
  virtual ~BlockStream() = default;
  // Appends up to maxBlocks blocks' ops; false at end of input. With `lean`, blocks that need no
  // evaluation may go to it as machine commands instead (after `out` has run: the call then
  // returns early); false also when it refused one.
  virtual bool next(ir::Region &out, size_t maxBlocks, CmdSink *lean = nullptr) = 0;
};
std::unique_ptr<BlockStream> openBlockStream(SourceKind kind, SourceManager &sm, uint32_t file,
                                             const FrontendOptions &opts, Diagnostics &diags);

}  // namespace ncc
