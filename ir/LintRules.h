// The registry of diagnostic rule ids: every `[rule]` a diagnostic carries is listed here with
// its severity, the stage that reports it and when it fires. docs/LINT.md's table is generated
// from it (`ncc lint --list-rules`); with NCC_CHECK_RULES set (the lit suite sets it) a
// diagnostic with an unlisted rule stops the program, so the table cannot fall behind.
#pragma once
#include "ir/Diagnostics.h"

#include <cstddef>
#include <string_view>

namespace ncc {

struct LintRule {
  const char *id;
  Severity severity;
  const char *stage;  // front end, verifier, executor, lint, driver, emitter
  const char *fires;  // when it fires (Markdown)
};

const LintRule *findLintRule(std::string_view id);
const LintRule *lintRules(size_t &count);

}  // namespace ncc
