// CmdSink: where an engine sends the machine commands of a running program (the Executor, a
// recorder in tests) and asks for controller state. The boundary between the engines (passes/Eval,
// backends/jit) and the executor (runtime/), so that runtime/ depends on ir/ only.
#pragma once
#include "ir/FrameValue.h"
#include "ir/MachineCmd.h"
#include "ir/SystemVars.h"

#include <string>

namespace ncc {

class CmdSink {
public:
  virtual ~CmdSink() = default;
  // Returns false to stop the program (the sink has reported why).
  virtual bool exec(const MachineCmd &cmd) = 0;
  // A sink that answers true takes a run of Block commands with no other command between them
  // as execBlocks(last, count): the compiled engine (backends/jit) then counts the blocks of a
  // loop without a call per block. The earlier blocks' numbers and locations are not passed.
  virtual bool mergesBlocks() const { return false; }
  virtual bool execBlocks(const MachineCmd &last, uint64_t count) {
    for (uint64_t i = 0; i < count; ++i)
      if (!exec(last)) return false;
    return true;
  }
  // `blocks` Block commands ending with *last (execBlocks; none when 0), then the Mode command
  // `mode` (ncrt_exec_mode: a loop's `G1 X[…]` line). A sink may skip a mode that is in force
  // and changes nothing.
  virtual bool execMode(const MachineCmd *last, uint64_t blocks, const MachineCmd &mode) {
    return (!blocks || execBlocks(*last, blocks)) && exec(mode);
  }
  // A move with what waits before it, in one call: `blocks` Block commands ending with *last
  // (none when 0), then *mode when not null (as execMode), then `move` (ncrt_exec_move: a loop's
  // `G1 X[…]` line; the flat path's plain block). The executor answers it without a call per
  // command (Executor::execMove).
  virtual bool execMove(const MachineCmd *last, uint64_t blocks, const MachineCmd *mode, const MachineCmd &move) {
    if (mode ? !execMode(last, blocks, *mode) : blocks && !execBlocks(*last, blocks)) return false;
    return exec(move);
  }
  // A system variable's current value (ir/SystemVars.h); false when this sink has none (err
  // empty: the engine reports RunError::SysVar) or it does not exist (a tool or edge the
  // machine lacks: the reason in err, which the engine reports).
  virtual bool readSystem(const SysRef &v, double &out, std::string &err) { return false; }
  // Assigns one (sysVarWritable) by the assignment at `loc`; false with the reason in err, which
  // the engine reports.
  virtual bool writeSystem(const SysRef &v, double value, SourceLoc loc, std::string &err) {
    err = "system variable '" + sysRefText(v) + "' cannot be written here";
    return false;
  }
  // The same for the FRAME-valued ones (sysVarIsFrame); the engines turn them into handles
  // (ir/SystemAccess.h).
  virtual bool readFrame(const SysRef &v, FrameValue &out, std::string &err) { return false; }
  virtual bool writeFrame(const SysRef &v, const FrameValue &f, SourceLoc loc, std::string &err) {
    err = "system variable '" + sysRefText(v) + "' cannot be written here";
    return false;
  }
  // A call of a function with the SAVE attribute: saveModal before it runs, restoreModal after
  // it returned (nested calls nest), which puts the modal state back with the records that
  // changes (docs/IR.md §5.4). Sinks without modal state ignore both. False: an error was reported.
  virtual bool saveModal() { return true; }
  virtual bool restoreModal(SourceLoc loc) { return true; }
};

}  // namespace ncc
