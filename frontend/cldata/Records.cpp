#include "frontend/cldata/Records.h"

#include <cctype>
#include <cstdlib>

namespace ncc::cld {

namespace {
using Logical = LogicalRecord;

std::string upper(std::string_view s) {
  std::string r(s);
  for (auto &c : r) c = (char)std::toupper((unsigned char)c);
  return r;
}

size_t skipSpace(const std::string &s, size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  return i;
}

Param param(const Logical &l, size_t b, size_t e) {
  b = skipSpace(l.text, b);
  while (e > b && (l.text[e - 1] == ' ' || l.text[e - 1] == '\t')) --e;
  Param p;
  p.text = upper(std::string_view(l.text).substr(b, e - b));
  p.loc = l.at(b);
  if (!p.text.empty()) {
    char *end = nullptr;
    p.value = std::strtod(p.text.c_str(), &end);
    p.isNumber = end == p.text.c_str() + p.text.size() && !std::isalpha((unsigned char)p.text[0]);
  }
  return p;
}

Record record(const Logical &l) {
  Record r;
  size_t i = skipSpace(l.text, 0);
  r.loc = l.at(i);
  size_t w = i;
  while (w < l.text.size() && (std::isalnum((unsigned char)l.text[w]) || l.text[w] == '_')) ++w;
  r.word = upper(std::string_view(l.text).substr(i, w - i));
  size_t j = skipSpace(l.text, w);
  r.slash = j < l.text.size() && l.text[j] == '/';
  size_t restAt = r.slash ? j + 1 : j;
  r.rest = l.text.substr(std::min(restAt, l.text.size()));
  while (!r.rest.empty() && (r.rest.back() == ' ' || r.rest.back() == '\t' || r.rest.back() == '\r')) r.rest.pop_back();
  if (r.slash) {
    size_t b = j + 1;
    for (size_t k = b;; ++k)
      if (k == l.text.size() || l.text[k] == ',') {
        r.params.push_back(param(l, b, k));
        if (k == l.text.size()) break;
        b = k + 1;
      }
  }
  return r;
}
}  // namespace

bool RecordReader::next(Record &out, std::vector<RecordError> &errors) {
  while (pos_ < text_.size()) {
    size_t nl = text_.find('\n', pos_);
    std::string_view ln = text_.substr(pos_, nl == std::string_view::npos ? text_.size() - pos_ : nl - pos_);
    pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
    ++line_;
    if (!ln.empty() && ln.back() == '\r') ln.remove_suffix(1);
    size_t cmt = ln.find("$$");
    std::string_view code = ln.substr(0, cmt);
    if (cmt != std::string_view::npos && code.find_first_not_of(" \t") == std::string_view::npos) {
      if (continuing_) continue;  // a comment line inside a continued record
      Record c;  // a comment line: kept as a comment
      c.loc = {file_, line_, (uint32_t)cmt + 1};
      c.rest = std::string(ln.substr(cmt + 2));
      while (!c.rest.empty() && c.rest.front() == ' ') c.rest.erase(0, 1);
      out = std::move(c);
      return true;
    }
    size_t last = code.find_last_not_of(" \t");
    bool more = last != std::string_view::npos && code[last] == '$';
    if (more) code = code.substr(0, last);
    for (size_t k = 0; k < code.size(); ++k) {
      cur_.text.push_back(code[k]);
      cur_.locs.push_back({file_, line_, (uint32_t)k + 1});
    }
    continuing_ = more;
    if (more) continue;
    const bool any = cur_.text.find_first_not_of(" \t") != std::string::npos;
    if (any) out = record(cur_);
    cur_.text.clear();
    cur_.locs.clear();
    if (any) return true;
  }
  if (continuing_ && !reported_) errors.push_back({{file_, line_, 1}, "the file ends inside a `$` continuation"});
  reported_ = true;
  return false;
}

std::vector<Record> readRecords(std::string_view text, uint32_t file, std::vector<RecordError> &errors) {
  std::vector<Record> out;
  RecordReader reader(text, file);
  Record r;
  while (reader.next(r, errors)) out.push_back(std::move(r));
  return out;
}

}  // namespace ncc::cld
