// Program emitters: print a Motion IR stream (machine coordinates, mm) as an NC program for
// another controller. Three writer families: word-address programs (ISO, Sinumerik: Emitter.cpp),
// Heidenhain Klartext (Klartext.cpp) and CL records (APT CL, ADEM CLData: ClRecords.cpp). The controller's word formats, codes, numbering and arc
// style come from a table per target (ControllerTable.cpp) that the machine description's
// [emit.iso] / [emit.sinumerik] / [emit.heidenhain] sections override key by key (docs/EMIT.md),
// in the spirit of a postprocessor passport: data, not per-controller code forks.
#pragma once
#include "ir/MotionIR.h"
#include "runtime/Machine.h"

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace ncc::emit {

// Word-address (ISO, Sinumerik, Balt-System NC-200), Klartext (Heidenhain) and CL records (APT CL
// text, ADEM CLData). NC-200 has no front end in ncc: its output cannot be verified (docs/EMIT.md).
enum class Target { ISO, Sinumerik, Heidenhain, Apt, Adem, Nc200 };

// Accepts "iso" / "fanuc", "sinumerik" / "siemens", "heidenhain" / "klartext" / "tnc", "apt",
// "cldata" / "adem" and "nc200" / "nc210" / "nc110" / "nc100" (one language, seed 003; any case). Returns false otherwise. targetName gives the dialect name the
// target's front end reads (--verify).
bool targetFromName(std::string_view name, Target &out);
const char *targetName(Target t);

struct EmitOptions {
  Target target = Target::ISO;
  std::string programName;  // ISO: digits become the O number; otherwise a header comment
  bool comments = true;     // copy Comment records
  bool checkTravel = false;
  bool binary = false;       // ADEM CLData: the binary record file instead of the listing  // --check-travel: a move outside the machine's axis limits is an error (docs/EMIT.md "Travel")
};

// A MotionSink that writes the program as records arrive: one block at a time, so memory stays
// bounded whatever the program length (with the FILE* form). finish() writes the program end.
class ProgramEmitter : public MotionSink {
public:
  ~ProgramEmitter() override = default;

  // Returns nullptr (after reporting to diags) when the machine's [emit.*] section is invalid.
  static std::unique_ptr<ProgramEmitter> create(const Machine &machine, const EmitOptions &opts,
                                                std::string &out, Diagnostics &diags);
  static std::unique_ptr<ProgramEmitter> create(const Machine &machine, const EmitOptions &opts,
                                                std::FILE *out, Diagnostics &diags);

  // Number of blocks (lines) written so far.
  virtual uint64_t blocksWritten() const = 0;

protected:
  ProgramEmitter() = default;
};

// Convenience for tests and small programs: emits a whole record list into a string.
// Returns false when errors were reported.
bool emitProgram(const Machine &machine, const EmitOptions &opts,
                 const std::vector<MotionRecord> &records, std::string &out, Diagnostics &diags);

}  // namespace ncc::emit
