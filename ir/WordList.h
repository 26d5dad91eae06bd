#pragma once
// Word lists: the tables' space-separated names ("Q200 Q201 Q206", "callee count").
#include <string_view>

namespace ncc {

// True when `word` is one of the space-separated words of `list`.
inline bool inWordList(std::string_view list, std::string_view word) {
  for (size_t i = 0; i <= list.size();) {
    size_t j = list.find(' ', i);
    if (j == std::string_view::npos) j = list.size();
    if (j > i && list.substr(i, j - i) == word) return true;
    i = j + 1;
  }
  return false;
}

}  // namespace ncc
