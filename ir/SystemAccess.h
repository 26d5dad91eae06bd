// Reading and writing a system variable as a value, the one path both engines take (passes/Eval
// and runtime/ncrt for the JIT): numbers go through CmdSink::readSystem/writeSystem, FRAMEs
// (sysVarIsFrame) through readFrame/writeFrame and the run's pool. A handle written to a numeric
// variable, or a non-frame to a frame variable, is an error here, with the same text in both engines.
#pragma once
#include "ir/CmdSink.h"
#include "ir/Strings.h"

namespace ncc {

// False with `err` set, or with `err` empty when the sink has no such variable (the engine
// reports RunError::SysVar).
bool readSystemValue(CmdSink &sink, ValuePool &pool, const SysRef &ref, double &out, std::string &err);
bool writeSystemValue(CmdSink &sink, ValuePool &pool, const SysRef &ref, double v, SourceLoc loc, std::string &err);

}  // namespace ncc
