// ADEM CLData records (docs/CLDATA.md, seed 004 §2): each a numeric code with its parameters
// FR[i], read from the text listing `<obj>[<code>] <name>/ <values…>;` or from the binary file
// of 8-byte cells (FR[0] length, FR[1] code, FR[2] route-object ordinal, then FR[3]…).
#pragma once
#include "ir/Diagnostics.h"

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ncc::cld {

struct AdemField {
  bool isText = false;
  double num = 0;
  std::string text;  // UTF-8
  SourceLoc loc;
};

// FR[3]… by index, in index order. A flat vector: a record has a few fields, almost always given
// in index order (appended), and a reader that reuses one record from record to record keeps
// the vector's storage (no allocation per record: the streamed front end, docs/CLDATA.md).
class AdemFields {
public:
  using Entry = std::pair<int, AdemField>;
  // The field at index i, made (empty) at its place when there is none.
  AdemField &operator[](int i);
  const AdemField *find(int i) const;
  std::vector<Entry>::const_iterator begin() const { return v_.begin(); }
  std::vector<Entry>::const_iterator end() const { return v_.end(); }
  std::vector<Entry>::const_reverse_iterator rbegin() const { return v_.rbegin(); }
  bool empty() const { return v_.empty(); }
  size_t size() const { return v_.size(); }
  void clear() { v_.clear(); }

private:
  std::vector<Entry> v_;
};

struct AdemRecord {
  int code = 0;
  int obj = 0;  // FR[2], the route object's ordinal
  // In a listing, where the record starts. In a binary file {file, 0, ordinal} (there is no line
  // to show), and `byte` is its offset.
  SourceLoc loc;
  size_t byte = 0;
  AdemFields fr;  // FR[3]… by index (FR[0..2] are the members above)
  const AdemField *field(int i) const { return fr.find(i); }
  // Back to an empty record, keeping the fields' storage.
  void reset() {
    code = obj = 0;
    loc = {};
    byte = 0;
    fr.clear();
  }
};

// A record code's parameters as the manual's Appendix 2 gives them (the table kLayouts in AdemRecords.cpp,
// shared by the readers (frontend/cldata) and the writers (backends/emit/ClRecords.cpp)).
struct AdemLayout {
  int code;
  const char *names;   // '|'-separated: the manual's names (Russian), then ours (Latin)
  const char *fields;  // the FR indices listing values fill, in order; "t" after an index: text ("3t 4t 5")
  int tailFrom;        // >0: values after `fields` go to FR[tailFrom], FR[tailFrom+1]… (the manual's FR[i+10], FR[i+100])
};
const AdemLayout *ademLayout(int code);
// The code a record name stands for (names compared case-insensitively, Cyrillic look-alike
// letters read as Latin ones); 0 when no record has that name.
int ademCodeByName(std::string_view utf8);
bool ademNameOf(int code, std::string_view utf8);  // one of the code's names
// A value word of the viewer's form (`4 [35] Инструмент/Фреза R 5.000000 Позиция 2;`): it sets
// FR[fr] to `value` (fr 0: nothing), and the number after it goes to FR[numberTo] (0: none).
struct AdemWord {
  int code;
  const char *word;  // as the manual writes it (compared normalised)
  int fr;
  double value;
  int numberTo;
};
const AdemWord *ademWord(int code, const std::string &normalised);
bool ademFieldIsText(const AdemLayout *l, int index);

// Upper case, Cyrillic letters that look like Latin ones (А В Е К М Н О Р С Т Х) as those,
// runs of blanks as one space: how names and value words are compared.
std::string ademNormalise(std::string_view utf8);
// The text of a listing or of binary text fields as UTF-8: valid UTF-8 as it is, else CP866.
std::string ademToUtf8(std::string_view bytes);
// Whether bytes are valid UTF-8 (a listing that is not is read as CP866). Pieces cut before a
// byte that is not a continuation byte (10xxxxxx) are all valid exactly when the whole is.
bool ademIsUtf8(std::string_view bytes);

struct AdemError {
  SourceLoc loc;
  std::string message;
  bool warning = false;
};
// Reports them; false when one was an error.
bool reportAdemErrors(Diagnostics &d, const std::vector<AdemError> &errors);

// Either form, one record at a time (the streamed front end): `next` fills `r` (reused: its
// storage is kept) with the next record read without error and returns false at the end of the
// input; errors and warnings go to `errors` as they are found. `offset` is where reading has got
// to (the bytes before it are not looked at again).
class AdemReader {
public:
  // `utf8`: whether the listing is valid UTF-8 (ademIsUtf8), when the caller found out (a
  // streamed reader does, releasing the pages it has read); -1: the reader looks.
  AdemReader(std::string_view bytes, uint32_t file, int utf8 = -1);
  ~AdemReader();
  AdemReader(const AdemReader &) = delete;
  AdemReader &operator=(const AdemReader &) = delete;
  bool binary() const { return binary_; }
  bool next(AdemRecord &r, std::vector<AdemError> &errors);
  size_t offset() const;
  class Listing;  // the two forms' readers (ir/AdemRecords.cpp)
  class Binary;

private:
  bool binary_;
  std::unique_ptr<Listing> listing_;
  std::unique_ptr<Binary> bin_;
};

// The text listing. Diagnostics point at the record, or at the value that is wrong.
std::vector<AdemRecord> readAdemListing(std::string_view text, uint32_t file, std::vector<AdemError> &errors);

// The binary form: little-endian IEEE-754 doubles, one per cell (docs/CLDATA.md "Binary").
bool looksLikeAdemBinary(std::string_view bytes);
// The records of a binary file (errors say "record N at byte B").
std::vector<AdemRecord> readAdemBinary(std::string_view bytes, uint32_t file, std::vector<AdemError> &errors);
std::string writeAdemBinary(const std::vector<AdemRecord> &records);
// The listing of records, one per line (values in full precision): `ncc-cld --listing`.
std::string writeAdemListing(const std::vector<AdemRecord> &records);

}  // namespace ncc::cld
