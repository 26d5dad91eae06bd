#include "utils/ncc/Driver.h"

#include "backends/emit/ControllerTable.h"
#include "utils/ncc/JitCache.h"
#include "utils/ncc/JitLoader.h"
#include "passes/Eval.h"
#include "passes/Pass.h"
#include "runtime/Executor.h"
#include "runtime/ProbeResults.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace ncc::driver {

void addCommonOptions(po::options_description &desc, CommonOptions &o) {
  addRunTimeOptions(desc, o);
  desc.add_options()
      ("dialect", po::value(&o.dialect), "source dialect: iso|sinumerik|heidenhain|apt|adem|ncir|motion (default: from the file)")
      ("engine", po::value(&o.engine)->default_value("eval"), "execution engine: eval|jit")
      ("decimal-mode", po::value(&o.decimalMode), "numbers without a decimal point: calculator|is-b|is-c (default: the machine's)")
      ("block-delete", po::value(&o.blockDelete)->multitoken(), "activate block-delete levels (0-9)")
      ("include,I", po::value(&o.includeDirs), "folder with subprogram files (after the program's own folder; repeatable)")
      ("link", po::value(&o.linkFiles), "a program or library (any dialect, read by its own front end) whose functions the program may call (repeatable)")
      ("no-cache", po::bool_switch(&o.noCache), "--engine=jit: neither use nor fill the compiled-object cache (docs/JIT.md)")
      ("cache-stats", po::bool_switch(&o.cacheStats), "--engine=jit: report the compiled-object cache's hit or miss on stderr");
}

bool Session::setUp() {
  applyDiagnosticsOptions(opts, diags);
  if (!loadMachine(opts.machine, machine)) return false;
  if (!loadProbeResults(opts, sm, diags, machine)) return false;
  if (opts.engine != "eval" && opts.engine != "jit") {
    diags.error({}, fmt::format("unknown engine '{}' (expected eval or jit)", opts.engine));
    return false;
  }
  return applySandbox(opts, diags);
}

bool Session::loadMachine(const std::string &nameOrPath, Machine &out) {
  std::vector<MachineError> errors;
  if (Machine::load(nameOrPath, out, errors)) return checkEmitSections(nameOrPath, out);
  // Register the file only now, so that a good machine file adds no source to the session.
  uint32_t f = errors[0].line ? sm.addFile(nameOrPath) : 0;
  for (auto &e : errors)
    diags.error(SourceLoc{f, e.line, e.col},
                f ? e.message : fmt::format("cannot load machine '{}': {}", nameOrPath, e.message));
  return false;
}

// The emitters' [emit.*] values are checked when the machine loads, so that a bad one stops every
// command with its place in the file (registered only then, like the file's own errors).
bool Session::checkEmitSections(const std::string &path, Machine &m) {
  if (m.sections.empty()) return true;
  static const emit::Target kTargets[] = {emit::Target::ISO, emit::Target::Sinumerik, emit::Target::Heidenhain};
  Diagnostics quiet(sm);
  quiet.setCollect(true);
  bool ok = true;
  for (emit::Target t : kTargets) {
    emit::ControllerStyle style = emit::defaultStyle(t);
    ok = emit::applyMachineSection(m, style, quiet) && ok;
  }
  if (ok) return true;
  m.sourceFile = sm.addFile(path);
  for (emit::Target t : kTargets) {
    emit::ControllerStyle style = emit::defaultStyle(t);
    emit::applyMachineSection(m, style, diags);
  }
  return false;
}

uint32_t Session::open(const std::string &path) {
  uint32_t f = sm.addFile(path);
  if (!f) diags.error({}, fmt::format("cannot read '{}'", path));
  return f;
}

SourceKind Session::kindOf(uint32_t file) const {
  SourceKind k;
  if (!opts.dialect.empty() && sourceKindFromName(opts.dialect, k)) {
    // "cldata" covers both CL formats (as --to=cldata writes ADEM): the content decides.
    if (k == SourceKind::CLData && opts.dialect == "cldata" && detectSourceKind("", sm.text(file)) == SourceKind::Adem)
      return SourceKind::Adem;
    return k;
  }
  return detectSourceKind(sm.name(file), sm.text(file));
}

FrontendOptions Session::frontendOptions(uint32_t file) const {
  FrontendOptions fo;
  fo.cycles = &cycleSignature;  // runtime/cycles/Library.h
  fo.decimalMode = opts.decimalMode.empty() ? machine.decimalMode : opts.decimalMode;
  fo.axesScaleEnable = machine.controller.axesScaleEnable;
  fo.offsetMemory = machine.controller.offsetMemory;
  fo.scaleWeighting = machine.controller.scaleWeighting;
  fo.startup = machine.controller.startup;
  fo.lathe = machine.controller.lathe();
  fo.latheSystem = machine.controller.gcodeSystem.empty() ? 'A' : machine.controller.gcodeSystem[0];
  fo.startMode = machine.controller.startMode;
  fo.auxiliaryB = !machine.axes[4].present;  // the 808D's B function (manual L2752-2760)
  fo.geoAxes = 0;
  for (int i = 0; i < 3; ++i)
    if (machine.axes[i].present) fo.geoAxes |= 1u << i;
  fo.probe = {machine.controller.probeFeed, machine.controller.probeFmax, machine.controller.probeDist,
              machine.controller.probeSetUp, machine.controller.probePrepos == "machine"};
  for (auto &[n, tool] : machine.toolTable)
    if (!tool.name.empty()) fo.toolNames.emplace(tool.name, n);
  for (auto &[code, call] : machine.controller.macroCalls)
    fo.macroCalls.push_back({code, call.program, call.kind == "subprogram"});
  for (unsigned l : opts.blockDelete)
    if (l <= 9) fo.blockDeleteMask |= 1u << l;
  fo.searchDirs.push_back(std::filesystem::path(sm.name(file)).parent_path().string());
  if (fo.searchDirs.back().empty()) fo.searchDirs.back() = ".";
  for (auto &d : opts.includeDirs) fo.searchDirs.push_back(d);
  return fo;
}

bool Session::load(uint32_t file, ir::Module &out) {
  if (!opts.dialect.empty()) {
    SourceKind k;
    if (!sourceKindFromName(opts.dialect, k)) {
      diags.error({}, fmt::format("unknown dialect '{}'", opts.dialect));
      return false;
    }
  }
  // Count this file's errors only: lint reads several files with one Diagnostics.
  unsigned before = diags.errorCount();
  // --link: each file through its own front end, its functions keeping their dialect (an ISO
  // program calling a Sinumerik cycle, docs/IR.md §5.7); the program's front end then leaves
  // calls to them for the link.
  std::vector<ir::Module> libs;
  FrontendOptions fo = frontendOptions(file);
  for (const std::string &path : opts.linkFiles) {
    uint32_t lf = open(path);
    libs.emplace_back();
    if (!lf || !parseProgram(kindOf(lf), sm, lf, frontendOptions(lf), diags, libs.back()) ||
        diags.errorCount() != before)
      return false;
    for (auto &f : libs.back().functions) fo.linkedFunctions.push_back(f.name);
  }
  if (!parseProgram(kindOf(file), sm, file, fo, diags, out) || diags.errorCount() != before) return false;
  for (ir::Module &lib : libs)
    if (!ir::linkModule(out, std::move(lib), diags)) return false;
  PassContext ctx;
  ctx.machine = &machine;
  ctx.limits = opts.limits;
  return runPasses(out, {"verify", "sema"}, diags, ctx);
}

bool Session::executeModule(const ir::Module &m, MotionSink &sink, uint64_t *blocks) {
  Executor exec(machine, sink, diags);
  if (onExecutor) onExecutor(exec);
  bool ok;
  ExecutorSink es(exec);
  if (opts.engine == "jit" && runCached(*this, m, es, ok)) return finishRun(exec, ok, blocks);
  std::string why;
  const jit::JitApi *jit = opts.engine == "jit" ? jitBackend(diags) : nullptr;
  if (opts.engine == "jit" && !jit) return false;
  if (jit && !jit->compilesQuickly(m, why))
    diags.note({}, fmt::format("running with the eval engine: {}, which the JIT compiles too slowly", why));
  if (jit && why.empty()) {
    jit::JitOptions jo;
    jo.limits = opts.limits;
    ok = jit->runModule(m, es, diags, jo);
  } else {
    Evaluator ev(es, diags, opts.limits);
    ok = ev.run(m);
  }
  return finishRun(exec, ok, blocks);
}

bool Session::finishRun(Executor &exec, bool ok, uint64_t *blocks) {
  ok &= exec.finish(ok);
  if (blocks) *blocks = exec.blockCount();
  return ok && !diags.hasErrors();
}

bool Session::execute(uint32_t file, MotionSink &sink, uint64_t *blocks) {
  if (kindOf(file) == SourceKind::Motion) {  // already executed: the records go to the sink as read
    if (blocks) *blocks = 0;
    return parseMotionText(sm, file, sink, diags) && !diags.hasErrors();
  }
  if (opts.engine == "eval" && opts.linkFiles.empty()) {  // a linked program needs the whole module
    bool streamed = false;
    bool ok = executeStreamed(file, sink, blocks, streamed);
    if (streamed || !ok) return ok;
  }
  ir::Module m;
  if (!load(file, m)) return false;
  mainFile = file;
  return executeModule(m, sink, blocks);
}

bool writeOutput(Session &s, const std::string &path, const std::string &text) {
  if (path.empty() || path == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return true;
  }
  std::string err;
  if (!writeFileAtomic(path, text, err)) {
    s.diags.error({}, err);
    return false;
  }
  return true;
}

}  // namespace ncc::driver
