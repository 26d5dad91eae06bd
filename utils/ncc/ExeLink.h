// `ncc compile --emit=exe`: links an object from --emit=obj with the static runtime (libncc_main,
// libncc_aotrun, libncc_runtime, libncc_ir; no LLVM) into an executable, with the system's
// C++ compiler driver as the linker.
#pragma once
#include "ir/Diagnostics.h"

#include <string>
#include <vector>

namespace ncc::driver {

// False after reporting (no linker on PATH, runtime libraries not found, the link failed).
bool linkExecutable(const std::string &object, const std::string &out, Diagnostics &diags);

// Where ncc's libraries may be, best first: the build tree's lib folder (beside utils/ncc), the
// install tree's (from bin/ncc), the binary's own folder.
std::vector<std::string> nccLibraryDirs();
// The one of them with the runtime libraries; empty when none has them.
std::string runtimeLibraryDir();
// The first of c++, g++, clang++ on PATH; empty when none.
std::string findLinker();

}  // namespace ncc::driver
