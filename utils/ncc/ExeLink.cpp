#include "utils/ncc/ExeLink.h"

#include <fmt/format.h>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

extern char **environ;

namespace ncc::driver {

namespace fs = std::filesystem;

// Where the runtime libraries are, relative to the folder of the ncc binary: the build tree
// (build/utils/ncc, build/lib) and the install tree (bin/ncc, the install's lib folder). Both
// from CMake (utils/CMakeLists.txt).
static const char *const kLibraryDirs[] = {NCC_BUILD_LIBDIR_FROM_BIN, NCC_INSTALL_LIBDIR_FROM_BIN};

std::vector<std::string> nccLibraryDirs() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  std::vector<std::string> dirs;
  for (const char *rel : kLibraryDirs) dirs.push_back((self.parent_path() / rel).lexically_normal().string());
  dirs.push_back(self.parent_path().string());
  return dirs;
}

std::string runtimeLibraryDir() {
  std::error_code ec;
  for (const std::string &dir : nccLibraryDirs())
    if (fs::exists(fs::path(dir) / "libncc_main.a", ec)) return dir;
  return "";
}

std::string findLinker() {
  const char *path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::vector<std::string> folders;
  for (std::string d; std::getline(dirs, d, ':');) folders.push_back(d.empty() ? "." : d);
  for (const char *name : {"c++", "g++", "clang++"})
    for (auto &d : folders) {
      std::string p = d + "/" + name;
      if (access(p.c_str(), X_OK) == 0) return p;
    }
  return "";
}

// Runs argv[0] with argv; its exit status, or -1 when it could not start.
static int runProgram(const std::vector<std::string> &args) {
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(const_cast<char *>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool linkExecutable(const std::string &object, const std::string &out, Diagnostics &diags) {
  std::string linker = findLinker();
  if (linker.empty()) {
    diags.error({}, "cannot link an executable: no C++ compiler driver (c++, g++ or clang++) on PATH");
    return false;
  }
  std::string libdir = runtimeLibraryDir();
  if (libdir.empty()) {
    diags.error({}, "cannot link an executable: the ncc runtime libraries (libncc_main.a) are neither beside this "
                    "ncc's build tree nor in its install tree");
    return false;
  }
  std::vector<std::string> args = {linker, object, "-o", out, "-L" + libdir,
                                   "-lncc_main", "-lncc_aotrun", "-lncc_runtime", "-lncc_ir"};
  // What the runtime needs from the system (absolute paths) and the sanitizer flags of this build.
  std::stringstream extra(NCC_AOT_LINK_LIBS);
  for (std::string a; extra >> a;) args.push_back(a);
  int rc = runProgram(args);
  if (rc == 0) return true;
  std::string cmd;
  for (auto &a : args) cmd += (cmd.empty() ? "" : " ") + a;
  diags.error({}, rc < 0 ? fmt::format("cannot start the linker '{}'", linker)
                         : fmt::format("linking '{}' failed (exit status {}): {}", out, rc, cmd));
  return false;
}

}  // namespace ncc::driver
