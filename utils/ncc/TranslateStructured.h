// ncc translate --keep-structure (utils/ncc/TranslateStructured.cpp).
#pragma once
#include "backends/emit/Emitter.h"
#include "utils/ncc/Driver.h"

namespace ncc::driver {

// Translates `file` keeping its structure; writes `out` (and the subprogram files beside it);
// with `verify` compares the two paths. Returns the exit code.
// --verify's comparison (CmdTranslate.cpp): false, with the first difference reported, when the
// translation's path differs from the source's.
bool samePaths(Session &s, const MotionBuffer &source, const MotionBuffer &back, double tolerance, bool rapidLegs = false);

int translateStructured(Session &s, uint32_t file, const emit::EmitOptions &eo, const std::string &out, bool verify,
                        double tolerance);

}  // namespace ncc::driver
