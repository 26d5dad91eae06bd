#include "frontend/SubprogramFiles.h"

#include <filesystem>

namespace ncc {

uint32_t findSubprogramFile(SourceManager &sm, const std::vector<std::string> &dirs,
                            const std::vector<std::string> &candidates) {
  for (auto &d : dirs)
    for (auto &f : candidates) {
      std::filesystem::path path = std::filesystem::path(d) / f;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) continue;
      if (uint32_t fid = sm.addFile(path.string())) return fid;
    }
  return 0;
}

std::string folderList(const std::vector<std::string> &dirs) {
  std::string where;
  for (auto &d : dirs) where += (where.empty() ? "" : ", ") + d;
  return where;
}

}  // namespace ncc
