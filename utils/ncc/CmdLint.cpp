// ncc lint: front-end, verifier and sema diagnostics, static lint rules, then a run through the
// executor (discarding motion) for the rules that need modal state. Each rule fires once per
// source location.
#include "ir/FileCommands.h"
#include "ir/LintRules.h"
#include "passes/Eval.h"
#include "passes/Pass.h"
#include "runtime/Executor.h"
#include "utils/ncc/Driver.h"

#include <fmt/format.h>

#include <algorithm>

namespace ncc::driver {

namespace {
constexpr size_t kMaxLintDiagnostics = 100;

class NullSink : public MotionSink {
public:
  void record(const MotionRecord &) override {}
};

// Lint keeps running after an executor error so one run reports every rule it can; system
// variables and frames go to the executor as in a run (ExecutorSink).
class KeepGoingSink : public ExecutorSink {
public:
  explicit KeepGoingSink(Executor &e) : ExecutorSink(e), exec_(e) {}
  bool exec(const MachineCmd &c) override {
    exec_.exec(c);
    return true;
  }
  bool restoreModal(SourceLoc loc) override {
    exec_.restoreModal(loc);
    return true;
  }

private:
  Executor &exec_;
};
}  // namespace

bool Session::lint(uint32_t file) {
  unsigned before = diags.errorCount();
  ir::Module m;
  PassContext ctx;
  ctx.machine = &machine;
  ctx.limits = opts.limits;
  // Front-end errors drop only the words of their block after the error: the rest of the
  // program still gets the verifier, the static rules and a run, so one lint run reports
  // every problem it can find (the issue 7 recovery). A module the verifier rejects is not run.
  if (!load(file, m)) {
    if (m.functions.empty() || !runPasses(m, {"verify", "sema"}, diags, ctx)) return false;
  }
  runLint(m, diags, ctx);
  NullSink sink;
  Executor exec(machine, sink, diags);
  exec.setLintRun(true);
  setFileLintMode(true);  // lint writes and deletes no files
  KeepGoingSink es(exec);
  Evaluator ev(es, diags, opts.limits);
  exec.finish(ev.run(m));
  return diags.errorCount() == before;
}

int cmdLint(int argc, char **argv) {
  Session s;
  std::vector<std::string> files;
  po::options_description desc("ncc lint options");
  bool listRules = false;
  desc.add_options()("file", po::value(&files)->multitoken(), "programs to check")(
      "list-rules", po::bool_switch(&listRules), "print the rule table (docs/LINT.md) and exit");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  pos.add("file", -1);
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm, "ncc lint FILE... [--diagnostics-format=text|json] [-Werror]");
  if (rc >= 0) return rc;
  if (listRules) {
    static const char *kSeverity[] = {"note", "warning", "error"};
    size_t n;
    const LintRule *rules = lintRules(n);
    std::printf("| rule id | severity | stage | fires when |\n|---|---|---|---|\n");
    for (size_t i = 0; i < n; ++i)
      std::printf("| `%s` | %s | %s | %s |\n", rules[i].id, kSeverity[(int)rules[i].severity], rules[i].stage,
                  rules[i].fires);
    return kExitOk;
  }
  if (files.empty()) {
    std::fprintf(stderr, "ncc: error: no input files\n");
    return kExitUsage;
  }
  s.diags.setCollect(true);
  // Collect far more than are shown (repeats of one rule at one location fold into one line);
  // the bound keeps a runaway loop's repeated errors from filling memory.
  s.diags.setErrorLimit(100000);
  if (!s.setUp()) {
    for (auto &d : s.diags.collected()) std::fprintf(stderr, "%s\n", s.diags.render(d).c_str());
    return kExitErrors;
  }
  for (auto &path : files)
    if (uint32_t f = s.open(path)) s.lint(f);
  // Print, dropping repeats of one rule at one location (a loop reports once).
  // In source order, whichever stage found them.
  std::vector<Diagnostic> all = s.diags.collected();
  std::stable_sort(all.begin(), all.end(), [](const Diagnostic &a, const Diagnostic &b) {
    if (a.loc.file != b.loc.file) return a.loc.file < b.loc.file;
    if (a.loc.line != b.loc.line) return a.loc.line < b.loc.line;
    return a.loc.col < b.loc.col;
  });
  std::vector<std::string> seen;
  bool json = s.opts.diagnosticsFormat == "json";
  if (json) std::printf("[");
  bool first = true;
  size_t shown = 0, hidden = 0;
  for (auto &d : all) {
    std::string key = fmt::format("{}:{}:{}:{}:{}", d.loc.file, d.loc.line, d.loc.col, d.rule, d.message);
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    if (shown == kMaxLintDiagnostics) {
      ++hidden;
      continue;
    }
    ++shown;
    std::string text = s.diags.render(d);
    if (json) {
      std::printf("%s\n  %s", first ? "" : ",", text.c_str());
      first = false;
    } else {
      std::fputs(text.c_str(), stderr);
    }
  }
  if (hidden) {
    std::string note = fmt::format("{} more diagnostics not shown (ncc lint shows the first {})", hidden,
                                   kMaxLintDiagnostics);
    if (json) std::printf(",\n  {\"severity\": \"note\", \"message\": \"%s\"}", note.c_str());
    else std::fprintf(stderr, "ncc: note: %s\n", note.c_str());
  }
  if (json) std::printf("\n]\n");
  return s.diags.hasErrors() ? kExitErrors : kExitOk;
}

}  // namespace ncc::driver
