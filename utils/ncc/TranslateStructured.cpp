// ncc translate --keep-structure: the NC IR written for another controller with its loops,
// branches, variables and calls (backends/emit/Structured.h, docs/EMIT.md "Structure-keeping
// translation"); --verify runs source and output through the motion pipeline and compares.
#include "utils/ncc/TranslateStructured.h"
#include "backends/emit/Structured.h"
#include "ir/MotionCompare.h"

#include <filesystem>
#include <fstream>

namespace ncc::driver {

namespace fs = std::filesystem;

// Writes the files: the main program to `out` (standard output: the listing of every file),
// the subprograms of a Sinumerik target beside it (docs/EMIT.md "Output layout").
static bool writeFiles(Session &s, const std::string &out, const std::vector<emit::StructuredFile> &files,
                       emit::Target target) {
  if (out.empty() || out == "-") return writeOutput(s, out, emit::structuredListing(files, target));
  if (!writeOutput(s, out, files[0].text)) return false;
  fs::path dir = fs::path(out).parent_path();
  for (size_t i = 1; i < files.size(); ++i)
    if (!writeOutput(s, (dir / files[i].name).string(), files[i].text)) return false;
  return true;
}

// Runs the translation through the target's front end. Several files are written to a fresh
// temporary folder so that the target's subprogram search finds them; it is removed afterwards.
static bool runTranslation(Session &s, const std::vector<emit::StructuredFile> &files, emit::Target target,
                           MotionBuffer &back) {
  static const char *const kExt[] = {".nc", ".mpf", ".h"};
  std::string savedDialect = s.opts.dialect;
  s.opts.dialect = emit::targetName(target);
  bool ok;
  if (files.size() == 1) {
    uint32_t tf = s.sm.addBuffer(std::string("<translated>") + kExt[(size_t)target], files[0].text);
    ok = s.execute(tf, back);
  } else {
    std::error_code ec;
    fs::path dir = fs::temp_directory_path(ec) / ("ncc-structured-" + std::to_string(::getpid()));
    fs::create_directories(dir, ec);
    ok = !ec;
    for (size_t i = 0; ok && i < files.size(); ++i) {
      std::ofstream f(dir / (i ? files[i].name : std::string("TRANSLATED") + kExt[(size_t)target]), std::ios::binary);
      f << files[i].text;
      ok = (bool)f;
    }
    uint32_t tf = ok ? s.open((dir / (std::string("TRANSLATED") + kExt[(size_t)target])).string()) : 0;
    ok = tf && s.execute(tf, back);
    fs::remove_all(dir, ec);
  }
  s.opts.dialect = savedDialect;
  return ok;
}

int translateStructured(Session &s, uint32_t file, const emit::EmitOptions &eo, const std::string &out, bool verify,
                        double tolerance) {
  if (eo.checkTravel) {  // travel is a property of the executed path, which this writer never sees
    s.diags.error({}, "--check-travel checks the executed path: it works on the flat translation only",
                  "unsupported-code");
    return kExitErrors;
  }
  ir::Module m;
  if (!s.load(file, m)) return kExitErrors;
  emit::StructuredOptions so;
  so.target = eo.target;
  so.programName = eo.programName;
  so.comments = eo.comments;
  so.realTolerance = s.machine.controller.realTolerance;
  so.rParams = s.machine.controller.rParams;
  std::vector<emit::StructuredFile> files;
  if (!emit::writeStructured(m, so, files, s.diags)) return kExitErrors;
  if (verify) {
    MotionBuffer source, back;
    if (!s.execute(file, source)) return kExitErrors;
    if (!runTranslation(s, files, eo.target, back)) {
      s.diags.error({}, "verification failed: the translated program does not run");
      return kExitErrors;
    }
    if (!samePaths(s, source, back, tolerance)) return kExitErrors;
    std::fprintf(stderr, "ncc: verified: %s and its structured translation give the same path\n", eo.programName.c_str());
  }
  if (!writeFiles(s, out, files, eo.target)) return kExitErrors;
  return s.exitCode();
}

}  // namespace ncc::driver
