// Running a compiled program: its description (runtime/ncrt.h ProgramInfo) gives the machine
// and the source names, the entry runs against the executor, the outputs are `ncc run`'s.
// `ncc run prog.o` (after utils/ncc/ObjectLoader) and executables (ncrt_main) come here.
#pragma once
#include "runtime/ncrt.h"
#include "utils/ncc/RunOutput.h"

#include <string>

namespace ncc::driver {

struct CompiledProgram {
  ncrt_entry entry = nullptr;
  const unsigned char *info = nullptr;
  size_t infoSize = 0;   // the bytes that may be read at info
  std::string name;      // the object or executable, for messages
};

// The text of a machine description: the embedded default's or the file's; false when unreadable.
bool readMachineText(const std::string &nameOrPath, std::string &text);

// machineGiven: --machine was on the command line, so it must be the machine the program was
// compiled for; else that machine (embedded) is used. Returns the exit code.
int runCompiled(const CompiledProgram &p, const RunTimeOptions &rt, bool machineGiven, const RunOutputArgs &out);

}  // namespace ncc::driver
