#include "utils/ncc/JitLoader.h"

#include "utils/ncc/ExeLink.h"

#include <fmt/format.h>

#include <dlfcn.h>

#include <filesystem>

namespace ncc::driver {

static const jit::JitApi *load(std::string &err) {
  std::vector<std::string> tried;
  for (const std::string &dir : nccLibraryDirs()) {
    std::string path = dir + "/ncc/libncc-jit.so";
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
      tried.push_back(path);
      continue;
    }
    // RTLD_NOW: a symbol the binary lacks is an error here, not a crash in the middle of a run.
    void *handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      err = fmt::format("cannot load the JIT ('{}'): {}", path, dlerror());
      return nullptr;
    }
    auto entry = reinterpret_cast<const jit::JitApi *(*)()>(dlsym(handle, NCC_JIT_API_SYMBOL));
    const jit::JitApi *api = entry ? entry() : nullptr;
    if (!api || api->stamp != jit::jitApiStamp()) {
      err = fmt::format("cannot load the JIT: '{}' belongs to another build of ncc", path);
      return nullptr;
    }
    return api;  // stays loaded: the process may compile again
  }
  err = "cannot load the JIT: libncc-jit.so is not in " + fmt::format("{}", fmt::join(tried, " nor "));
  return nullptr;
}

const jit::JitApi *jitBackend(Diagnostics &diags) {
  static std::string err;
  static const jit::JitApi *api = load(err);
  if (!api) diags.error({}, err);
  return api;
}

}  // namespace ncc::driver
