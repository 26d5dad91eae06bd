// APT CL records: the logical lines of a CL file (`$` joins the next line, `$$` starts a
// comment), each a major word, and after `/` its comma-separated parameters.
#pragma once
#include "ir/Diagnostics.h"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::cld {

struct Param {
  std::string text;  // upper case, trimmed
  SourceLoc loc;
  bool isNumber = false;
  double value = 0;
};

struct Record {
  std::string word;  // the major word, upper case: GOTO, CIRCLE …; empty for a `$$` comment line
  SourceLoc loc;
  bool slash = false;         // parameters follow a `/`
  std::vector<Param> params;  // after the `/`
  std::string rest;           // the text after the word (or after the `/`), as written: PARTNO, PPRINT
};

struct RecordError {
  SourceLoc loc;
  std::string message;
};

// A logical record being joined: its characters and where each one was written.
struct LogicalRecord {
  std::string text;
  std::vector<SourceLoc> locs;
  SourceLoc at(size_t i) const { return locs.empty() ? SourceLoc{} : locs[std::min(i, locs.size() - 1)]; }
};

// The records of a CL file one at a time (the streamed front end reads a chunk, lowers it and
// drops it): `$$` comment lines and joined `$` continuations, in order.
class RecordReader {
public:
  RecordReader(std::string_view text, uint32_t file) : text_(text), file_(file) {}
  // The next record into out; false at the end (a file ending inside a continuation adds the
  // error then, once).
  bool next(Record &out, std::vector<RecordError> &errors);
  size_t offset() const { return pos_; }  // bytes read so far

private:
  std::string_view text_;
  uint32_t file_;
  size_t pos_ = 0;
  uint32_t line_ = 0;
  LogicalRecord cur_;
  bool continuing_ = false, reported_ = false;
};

// The whole file's records.
std::vector<Record> readRecords(std::string_view text, uint32_t file, std::vector<RecordError> &errors);

}  // namespace ncc::cld
