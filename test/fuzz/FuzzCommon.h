// Shared by the libFuzzer targets: the paths a user's `ncc run`, `ncc lint`, `ncc compile` and
// `ncc translate` take through the driver's Session, with limits tight enough that one input
// runs in milliseconds. A finding is a sanitizer report, a crash, a timeout or a broken
// invariant (fuzzCheck).
#pragma once
#include "ir/MotionIR.h"
#include "utils/ncc/Driver.h"

#include <string>
#include <string_view>

namespace ncc::fuzz {

// Inputs larger than this are only parsed and checked, not run (keeps executions fast).
constexpr size_t kMaxRunBytes = 4096;

// Aborts with a message: an invariant the pipeline promises does not hold.
[[noreturn]] void fail(const char *what, std::string_view detail = {});
#define fuzzCheck(cond, detail) ((cond) ? (void)0 : ::ncc::fuzz::fail(#cond, detail))

// A session on the default machine whose diagnostics are collected (and rendered at the end,
// as the user would see them) instead of printed, with tight execution limits. Subprogram
// files are looked up in a directory that does not exist, so no input reads the disk.
class Session : public driver::Session {
public:
  Session();
  ~Session();
  // Registers `text` as a file named /nonexistent-ncc-fuzz/<name>.
  uint32_t add(std::string_view name, std::string_view text);
};

// `ncc run` + `ncc translate`: executes the file (streamed when flat) into the sinks a user can
// ask for: planner and summary, canonical and JSONL traces, the ISO and Sinumerik emitters.
// Records go to `out`, the ISO translation to `iso`, when given. Returns whether the run succeeded.
bool run(Session &s, uint32_t file, MotionBuffer *out = nullptr, std::string *iso = nullptr);
// Feeds records to the same sinks (for an already-loaded module's run).
bool feedSinks(Session &s, const MotionBuffer &records);

// `ncc compile --emit=ir` then `ncc opt`: the printed module must parse back and verify, and
// every pass must survive it. Returns the printed text.
std::string roundTrip(Session &s, const ir::Module &m);

// What a user runs on one program file named `name` (its extension picks the front end): ncc lint
// (recovery after front-end errors), then ncc compile / ncc opt (roundTrip) and, for inputs up to
// kMaxRunBytes, ncc run of the module into every sink. Returns whether the module loaded.
bool loadAndRun(std::string_view name, std::string_view text);

// The records as Motion IR text, for comparing two runs.
std::string motionText(const MotionBuffer &b);

}  // namespace ncc::fuzz
