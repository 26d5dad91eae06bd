// Looking up a called subprogram's file, shared by the front ends: the first of the candidate
// file names found in the first folder that has one.
#pragma once
#include "ir/Diagnostics.h"

#include <string>
#include <vector>

namespace ncc {

// The id of the file (added to sm), 0 when none of the candidates is in any of the folders.
// ignoreCase: a folder's file names also match in any case (Sinumerik names are case-insensitive).
uint32_t findSubprogramFile(SourceManager &sm, const std::vector<std::string> &dirs,
                            const std::vector<std::string> &candidates, bool ignoreCase = false);
// The folders for a message: "a, b".
std::string folderList(const std::vector<std::string> &dirs);

}  // namespace ncc
