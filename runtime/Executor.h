// The executor gives machine commands their meaning: it keeps the modal state (ModalState),
// resolves implicit motion modes, expands canned cycles, normalises units and incremental
// values, applies work and tool offsets, and pushes Motion IR records into a sink.
// Both engines feed it: the eval engine (passes/Eval) and JIT-compiled code (through ncrt_*).
#pragma once
#include "ir/CmdSink.h"
#include "ir/MachineCmd.h"
#include "ir/MotionIR.h"
#include "ir/SystemVars.h"
#include "runtime/Machine.h"
#include "runtime/cycles/Library.h"

namespace ncc {

struct ModalState {
  ModeValue motion = ModeValue::Rapid;
  ModeValue pathMotion = ModeValue::Rapid;  // the last G0-G3 mode (what Fanuc's G80 returns to)
  ModeValue plane = ModeValue::XY;
  ModeValue units = ModeValue::MM;
  ModeValue distance = ModeValue::Absolute;
  ModeValue arcDistance = ModeValue::ArcIncremental;
  ModeValue feedMode = ModeValue::PerMinute;
  ModeValue retract = ModeValue::RetractInitial;
  ModeValue pathMode = ModeValue::Continuous;
  ModeValue splineStart = ModeValue::StartNatural, splineEnd = ModeValue::EndNatural;  // Sinumerik BNAT ENAT
  ModeValue wearSystem = ModeValue::WearMachine;  // Sinumerik G group 56: TOWSTD …, TOWWCS
  double feed = 0;          // program units per minute (or rev)
  double speed = 0;
  int spindle = 0;          // 0 stop, 1 cw, 2 ccw
  int toolSelected = 0, toolInSpindle = 0;
  int workOffset = 1;       // 1..9
  int cutterComp = 0;       // 0 off, 1 left, 2 right
  int toolLengthH = 0;
  bool flood = false, mist = false;
  bool ended = false;       // after M2/M30
  AxisVec position{};       // current position, machine coordinates mm
  // Constant surface speed (G96, runtime/ExecutorSpindle.cpp): `speed` is then the surface
  // speed as programmed (m/min or ft/min); speedLimit the G96 D / G50 S / G92 S limit (rpm, 0 none).
  bool css = false;
  double surface = 0;     // CSS surface speed, m/min
  double speedLimit = 0;
};

class Executor {
public:
  Executor(const Machine &machine, MotionSink &sink, Diagnostics &diags);
  ~Executor();
  // Executes one command. Errors go to diags (with the command's loc); returns false on error,
  // after which the caller stops the program.
  bool exec(const MachineCmd &cmd);
  // `count` Block commands in a row ending with `last`: the state they leave (CmdSink::execBlocks).
  bool execBlocks(const MachineCmd &last, uint64_t count);
  // CmdSink::execMode: the blocks, then the mode unless it is in force already.
  bool execMode(const MachineCmd *last, uint64_t blocks, const MachineCmd &mode);
  // CmdSink::execMove: the blocks, the mode (when given and not in force), then the move.
  bool execMove(const MachineCmd *last, uint64_t blocks, const MachineCmd *mode, const MachineCmd &move);
  // Flushes pending state at program end; returns false on error. ranToEnd: the program ran
  // to its end (not stopped by an error), so a missing M2/M30 is worth a warning.
  bool finish(bool ranToEnd = true);
  // ncc lint's run: constructs that are not simulated (message kind=not_simulated) are noted and
  // passed over instead of stopping the run.
  void setLintRun(bool on);
  // Runs a cycle of the library (runtime/cycles/Library.h) at the current position: `cycle`
  // alone, or the position pattern `pattern` with `cycle` at each position. Errors go to diags
  // at `loc`.
  bool runCycle(const CycleDef &cycle, const CycleArgs &args, const CycleDef *pattern, const CycleArgs *patternArgs,
                SourceLoc loc);
  // Sinumerik SAVE: remembers the modal G groups; restoreModal puts back the last remembered ones
  // (executing the mode changes, so their records follow).
  bool saveModal();
  bool restoreModal(SourceLoc loc);
  // The value of a system variable (ir/SystemVars.h) in the current state.
  bool readSystem(const SysRef &v, double &out, std::string &err) const;
  // Writes one (ir/SystemVars.h sysVarWritable); false with the reason in err.
  bool writeSystem(const SysRef &v, double value, SourceLoc loc, std::string &err);
  // FRAME-valued system variables (ir/SystemVars.h sysVarIsFrame; ExecutorFrames.cpp).
  bool readFrame(const SysRef &v, FrameValue &out, std::string &err) const;
  bool writeFrame(const SysRef &v, const FrameValue &f, SourceLoc loc, std::string &err);
  const ModalState &state() const;
  // Source blocks executed so far (a block in a loop counts each time it runs).
  uint64_t blockCount() const;

  struct Impl;  // the state, shared by runtime/Executor*.cpp (ExecutorImpl.h)

private:
  bool restoreModes(SourceLoc loc);  // the mode groups of a SAVE call (restoreModal)
  Impl *impl_;
};

// Forwards an engine's commands to an Executor.
class ExecutorSink : public CmdSink {
public:
  explicit ExecutorSink(Executor &e) : exec_(e) {}
  bool exec(const MachineCmd &cmd) override { return exec_.exec(cmd); }
  bool mergesBlocks() const override { return true; }
  bool execBlocks(const MachineCmd &last, uint64_t count) override { return exec_.execBlocks(last, count); }
  bool execMode(const MachineCmd *last, uint64_t blocks, const MachineCmd &mode) override {
    return exec_.execMode(last, blocks, mode);
  }
  bool execMove(const MachineCmd *last, uint64_t blocks, const MachineCmd *mode, const MachineCmd &move) override {
    return exec_.execMove(last, blocks, mode, move);
  }
  bool readSystem(const SysRef &v, double &out, std::string &err) override { return exec_.readSystem(v, out, err); }
  bool writeSystem(const SysRef &v, double value, SourceLoc loc, std::string &err) override {
    return exec_.writeSystem(v, value, loc, err);
  }
  bool readFrame(const SysRef &v, FrameValue &out, std::string &err) override { return exec_.readFrame(v, out, err); }
  bool writeFrame(const SysRef &v, const FrameValue &f, SourceLoc loc, std::string &err) override {
    return exec_.writeFrame(v, f, loc, err);
  }
  bool saveModal() override { return exec_.saveModal(); }
  bool restoreModal(SourceLoc loc) override { return exec_.restoreModal(loc); }

private:
  Executor &exec_;
};

}  // namespace ncc
