// APT CL records: the logical lines of a CL file (`$` joins the next line, `$$` starts a
// comment), each a major word, and after `/` its comma-separated parameters.
#pragma once
#include "ir/Diagnostics.h"

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

std::vector<Record> readRecords(std::string_view text, uint32_t file, std::vector<RecordError> &errors);

}  // namespace ncc::cld
