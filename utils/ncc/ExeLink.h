// `ncc compile --emit=exe`: links an object from --emit=obj with the static runtime (libncc_main,
// libncc_aotrun, libncc_runtime, libncc_ir; no LLVM) into an executable, with the system's
// C++ compiler driver as the linker.
#pragma once
#include "ir/Diagnostics.h"

#include <string>

namespace ncc::driver {

// False after reporting (no linker on PATH, runtime libraries not found, the link failed).
bool linkExecutable(const std::string &object, const std::string &out, Diagnostics &diags);

// The folder with the runtime libraries: beside the build tree's ncc or in its install tree;
// empty when neither has them.
std::string runtimeLibraryDir();
// The first of c++, g++, clang++ on PATH; empty when none.
std::string findLinker();

}  // namespace ncc::driver
