// ncc: check, translate and run CNC part programs. `ncc --help` lists the subcommands.
#include "runtime/ncrt.h"
#include "utils/ncc/Driver.h"

#include <cstdio>
#include <cstring>

using namespace ncc::driver;

#if defined(__SANITIZE_ADDRESS__)
// The sanitizer build (NCC_SANITIZE): GCC 12's LeakSanitizer misreads the dynamic TLS of a
// dlopen'ed library on this glibc and crashes at exit ("Tracer caught signal 11") once the JIT
// module (libncc-jit.so) is loaded; not tracking __tls_get_addr avoids it. Leak checks stay on.
extern "C" const char *__asan_default_options() { return "intercept_tls_get_addr=0"; }
#endif

struct Subcommand {
  const char *name;
  int (*run)(int, char **);
  const char *summary;
};

static const Subcommand kSubcommands[] = {
    {"run", cmdRun, "compile and execute a program, drive the trajectory core, print a summary or a trace"},
    {"compile", cmdCompile, "stop after a stage and print it: --emit=ir|motion|llvm|obj, or link an executable: --emit=exe"},
    {"opt", cmdOpt, "run named passes on a program or textual NC IR (like LLVM's opt)"},
    {"translate", cmdTranslate, "emit the program for another controller or as CL records (--to=iso|sinumerik|heidenhain|apt|cldata), optionally --verify"},
    {"lint", cmdLint, "check programs and report diagnostics"},
    {"canon-diff", cmdCanonDiff, "compare two canonical traces (LinuxCNC rs274 format)"},
    {"machine", cmdMachine, "print or check machine descriptions"},
    {"cycle", cmdCycle, "run one cycle of the library alone (sin.CYCLE83, hei.200, …) and print its Motion IR"},
    {"kinematics", cmdKinematics, "the machine's rotary kinematics on one pose: --tip/--axis (inverse) or --joints (forward)"},
};

static void usage(std::FILE *out) {
  std::fprintf(out, "usage: ncc <command> [options] [files]\n\ncommands:\n");
  for (auto &s : kSubcommands) std::fprintf(out, "  %-11s %s\n", s.name, s.summary);
  std::fprintf(out, "\n`ncc <command> --help` describes a command's options. `ncc --version` prints the version.\n"
                    "Exit codes: 0 success, 1 the program has errors, 2 usage error.\n");
}

int main(int argc, char **argv) {
  if (argc < 2) {
    usage(stderr);
    return kExitUsage;
  }
  if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    usage(stdout);
    return kExitOk;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("ncc %s\n", ncrt_version());
    return kExitOk;
  }
  for (auto &s : kSubcommands)
    if (!std::strcmp(argv[1], s.name)) return s.run(argc - 1, argv + 1);
  std::fprintf(stderr, "ncc: error: unknown command '%s'\n", argv[1]);
  usage(stderr);
  return kExitUsage;
}
