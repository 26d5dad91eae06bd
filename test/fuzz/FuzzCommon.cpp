#include "test/fuzz/FuzzCommon.h"

#include "backends/emit/Emitter.h"
#include "passes/Pass.h"
#include "runtime/CanonTrace.h"
#include "runtime/RunOutputs.h"
#include "runtime/Sinks.h"

#include <cstdio>
#include <cstdlib>

namespace ncc::fuzz {

void fail(const char *what, std::string_view detail) {
  std::fprintf(stderr, "fuzz invariant failed: %s\n%.*s\n", what, (int)detail.size(), detail.data());
  std::abort();
}

static std::FILE *devNull() {
  static std::FILE *f = std::fopen("/dev/null", "w");
  return f;
}

Session::Session() {
  diags.setCollect(true);
  opts.limits.maxLoopIterations = 200;
  opts.limits.maxCallDepth = 16;
  opts.limits.maxSeconds = 2;
  // Tiny chunks so streamed programs cross chunk boundaries; verify every chunk.
  streamChunkBlocks = 3;
  setenv("NCC_VERIFY_CHUNKS", "1", 1);
  fuzzCheck(setUp(), "the default machine must load");
}

Session::~Session() {
  // What the user would see: every diagnostic rendered, in both formats.
  for (auto &d : diags.collected()) {
    diags.setFormat(Diagnostics::Format::Text);
    std::string t = diags.render(d);
    diags.setFormat(Diagnostics::Format::Json);
    t += diags.render(d);
    std::fputs(t.c_str(), devNull());
  }
}

uint32_t Session::add(std::string_view name, std::string_view text) {
  return sm.addBuffer("/nonexistent-ncc-fuzz/" + std::string(name), std::string(text));
}

namespace {
// The sinks of `ncc run` (planner, summary, traces) and `ncc translate` (the word-address
// emitters and the CL record writers: APT CL, ADEM CLData binary).
struct Sinks {
  explicit Sinks(Session &s) : outputs(s.machine, RunOutputOptions{}), canon(devNull()), jsonl(devNull()) {
    tee.add(&outputs);
    tee.add(&canon);
    tee.add(&jsonl);
    emit::EmitOptions eo;
    eo.programName = "1234";
    iso = emit::ProgramEmitter::create(s.machine, eo, isoText, s.diags);
    eo.target = emit::Target::Sinumerik;
    sinumerik = emit::ProgramEmitter::create(s.machine, eo, sinumerikText, s.diags);
    eo.target = emit::Target::Apt;
    apt = emit::ProgramEmitter::create(s.machine, eo, aptText, s.diags);
    eo.target = emit::Target::Adem;
    eo.binary = true;
    adem = emit::ProgramEmitter::create(s.machine, eo, ademBytes, s.diags);
    for (auto *e : {iso.get(), sinumerik.get(), apt.get(), adem.get()})
      if (e) tee.add(e);
  }
  bool finish(Session &s) {
    bool ok = tee.finish(s.diags);
    std::fputs(outputs.summaryText().c_str(), devNull());
    return ok;
  }
  RunOutputs outputs;
  CanonTraceWriter canon;
  JsonlTraceWriter jsonl;
  std::string isoText, sinumerikText, aptText, ademBytes;
  std::unique_ptr<emit::ProgramEmitter> iso, sinumerik, apt, adem;
  MotionTee tee;
};
}  // namespace

bool run(Session &s, uint32_t file, MotionBuffer *out, std::string *iso) {
  Sinks sinks(s);
  MotionBuffer local;
  MotionTee tee;
  tee.add(&sinks.tee);
  tee.add(out ? out : &local);
  bool ok = s.execute(file, tee);
  ok &= sinks.finish(s);
  if (iso) *iso = sinks.iso ? sinks.isoText : std::string();
  return ok && !s.diags.hasErrors();
}

bool feedSinks(Session &s, const MotionBuffer &records) {
  Sinks sinks(s);
  for (auto &r : records.records) sinks.tee.record(r);
  return sinks.finish(s);
}

std::string roundTrip(Session &s, const ir::Module &m) {
  std::string text = ir::printModule(m, s.sm);
  for (const char *pass : {"fold", "lint", "eval", "lower-motion"}) {
    uint32_t f = s.add("roundtrip.ncir", text);
    ir::Module back;
    unsigned errors = s.diags.errorCount();
    bool parsed = ir::parseModule(text, f, s.sm, s.diags, back);
    fuzzCheck(parsed && s.diags.errorCount() == errors, "the printed module must parse back:\n" + text);
    PassContext ctx;
    ctx.machine = &s.machine;
    ctx.limits = s.opts.limits;
    std::string motion;
    ctx.motionText = &motion;
    fuzzCheck(runPasses(back, {"verify"}, s.diags, ctx), "the printed module must verify:\n" + text);
    if (runPasses(back, {pass}, s.diags, ctx) && std::string_view(pass) != "lower-motion")
      std::fputs(ir::printModule(back, s.sm).c_str(), devNull());
  }
  return text;
}

bool loadAndRun(std::string_view name, std::string_view text) {
  bool small = text.size() <= kMaxRunBytes;
  {
    Session s;
    s.diags.setErrorLimit(100000);
    uint32_t f = s.add(name, text);
    if (small) s.lint(f);
  }
  Session s;
  uint32_t f = s.add(name, text);
  ir::Module m;
  if (!s.load(f, m)) return false;
  roundTrip(s, m);
  MotionBuffer whole;
  if (small && s.executeModule(m, whole)) feedSinks(s, whole);
  return true;
}

std::string motionText(const MotionBuffer &b) {
  std::string t;
  for (auto &r : b.records) t += printMotionRecord(r) + "\n";
  return t;
}

}  // namespace ncc::fuzz
