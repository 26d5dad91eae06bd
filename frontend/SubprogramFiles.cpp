#include "frontend/SubprogramFiles.h"

#include <cctype>
#include <filesystem>

namespace ncc {

static std::string upper(std::string s) {
  for (auto &c : s) c = (char)std::toupper((unsigned char)c);
  return s;
}

uint32_t findSubprogramFile(SourceManager &sm, const std::vector<std::string> &dirs,
                            const std::vector<std::string> &candidates, bool ignoreCase) {
  for (auto &d : dirs) {
    for (auto &f : candidates) {
      // Normalised: "./P.SPF" is named as "P.SPF", the way the main program in that folder is.
      std::filesystem::path path = (std::filesystem::path(d) / f).lexically_normal();
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) continue;
      if (uint32_t fid = sm.addFile(path.string())) return fid;
    }
    if (!ignoreCase) continue;
    std::error_code ec;
    for (auto &e : std::filesystem::directory_iterator(d, ec)) {
      std::string name = upper(e.path().filename().string());
      for (auto &f : candidates)
        if (name == upper(f) && e.is_regular_file(ec))
          if (uint32_t fid = sm.addFile(e.path().lexically_normal().string())) return fid;
    }
  }
  return 0;
}

std::string folderList(const std::vector<std::string> &dirs) {
  std::string where;
  for (auto &d : dirs) where += (where.empty() ? "" : ", ") + d;
  return where;
}

}  // namespace ncc
