#include "ir/AdemRecords.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>

namespace ncc::cld {

// ---- text: encodings and names ----

namespace {
bool validUtf8(std::string_view s) {
  for (size_t i = 0; i < s.size();) {
    unsigned char c = (unsigned char)s[i];
    size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (size_t k = 1; k < n; ++k)
      if (((unsigned char)s[i + k] >> 6) != 2) return false;
    i += n;
  }
  return true;
}

void putUtf8(std::string &o, char32_t c) {
  if (c < 0x80) o += (char)c;
  else if (c < 0x800) o += (char)(0xC0 | (c >> 6)), o += (char)(0x80 | (c & 0x3F));
  else if (c < 0x10000) o += (char)(0xE0 | (c >> 12)), o += (char)(0x80 | ((c >> 6) & 0x3F)), o += (char)(0x80 | (c & 0x3F));
  else
    o += (char)(0xF0 | (c >> 18)), o += (char)(0x80 | ((c >> 12) & 0x3F)), o += (char)(0x80 | ((c >> 6) & 0x3F)),
        o += (char)(0x80 | (c & 0x3F));
}

// CP866 (DOS Cyrillic), the upper half: the letters and Ё ё; box drawing and the rest as '?'.
char32_t cp866(unsigned char c) {
  if (c < 0x80) return c;
  if (c <= 0xAF) return 0x0410 + (c - 0x80);  // А…Я а…п
  if (c >= 0xE0 && c <= 0xEF) return 0x0440 + (c - 0xE0);  // р…я
  if (c == 0xF0) return 0x0401;
  if (c == 0xF1) return 0x0451;
  if (c == 0xFF) return ' ';  // no-break space
  return '?';
}

std::u32string decode(std::string_view utf8) {
  std::u32string o;
  for (size_t i = 0; i < utf8.size();) {
    unsigned char c = (unsigned char)utf8[i];
    size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : 4;
    char32_t v = n == 1 ? c : n == 2 ? c & 0x1F : n == 3 ? c & 0x0F : c & 0x07;
    for (size_t k = 1; k < n && i + k < utf8.size(); ++k) v = (v << 6) | ((unsigned char)utf8[i + k] & 0x3F);
    o += v;
    i += n;
  }
  return o;
}

// Cyrillic capitals that look like Latin ones (seed 004 §2.9 item 10).
struct Homoglyph {
  char32_t cyr;
  char lat;
};
const Homoglyph kHomoglyphs[] = {{0x0410, 'A'}, {0x0412, 'B'}, {0x0415, 'E'}, {0x041A, 'K'}, {0x041C, 'M'}, {0x041D, 'H'},
                                 {0x041E, 'O'}, {0x0420, 'P'}, {0x0421, 'C'}, {0x0422, 'T'}, {0x0425, 'X'}};
}  // namespace

bool ademIsUtf8(std::string_view bytes) { return validUtf8(bytes); }

std::string ademToUtf8(std::string_view bytes) {
  if (validUtf8(bytes)) return std::string(bytes);
  std::string o;
  for (unsigned char c : bytes) putUtf8(o, cp866(c));
  return o;
}

std::string ademNormalise(std::string_view utf8) {
  std::string o;
  bool blank = false;
  for (char32_t c : decode(utf8)) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      blank = !o.empty();
      continue;
    }
    if (blank) o += ' ', blank = false;
    if (c >= 'a' && c <= 'z') c -= 32;
    else if (c >= 0x0430 && c <= 0x044F) c -= 0x20;  // а…я
    if (c == 0x0451 || c == 0x0401) c = 0x0415;       // ё Ё: Е
    for (auto &h : kHomoglyphs)
      if (c == h.cyr) c = (char32_t)h.lat;
    putUtf8(o, c);
  }
  return o;
}

bool ademFieldIsText(const AdemLayout *l, int index) {
  if (!l) return false;
  for (const char *p = l->fields; *p;) {
    char *end = nullptr;
    long i = std::strtol(p, &end, 10);
    if (end == p) break;
    if (i == index) return *end == 't';
    p = end;
    while (*p == 't' || *p == ' ') ++p;
  }
  return false;
}

namespace {
// The FR indices a layout's listing values fill, in order.
std::vector<int> positional(const AdemLayout *l) {
  std::vector<int> v;
  if (!l) return v;
  for (const char *p = l->fields; *p;) {
    char *end = nullptr;
    long i = std::strtol(p, &end, 10);
    if (end == p) break;
    v.push_back((int)i);
    p = end;
    while (*p == 't' || *p == ' ') ++p;
  }
  return v;
}
bool freeWords(const AdemLayout *l) { return l && std::strcmp(l->fields, "*") == 0; }

// What the readers need of a code's layout, worked out once per code instead of per record:
// the positional FR indices, which fields are texts, whether values are free words.
struct LayoutInfo {
  int code = 0;
  const AdemLayout *lay = nullptr;  // null: a code the table does not have
  std::vector<int> order;
  std::vector<int> texts;  // the text fields' indices (a few)
  bool free = false;
  bool isText(int i) const { return std::find(texts.begin(), texts.end(), i) != texts.end(); }
};
const LayoutInfo &layoutInfo(int code);

// A whole number of at most nine digits (what atoi of those digits gives).
int digitsValue(std::string_view s) {
  int v = 0;
  for (char c : s) v = v * 10 + (c - '0');
  return v;
}

// A listing value: the number it is, as strtod reads all of it. from_chars (correctly rounded,
// as glibc's strtod) takes the common forms without a copy; strtod the rest ('+', hex, overflow).
bool listingNumber(std::string_view tok, double &v) {
  if (tok.empty() || !(std::isdigit((unsigned char)tok[0]) || tok[0] == '-' || tok[0] == '+' || tok[0] == '.'))
    return false;
  if (tok[0] != '+') {
    auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec == std::errc() && p == tok.data() + tok.size()) return true;
  }
  std::string s(tok);
  char *end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

}  // namespace

// ---- the listing ----

class AdemReader::Listing {
public:
  Listing(std::string_view t, uint32_t file, int utf8 = -1) : t_(t), file_(file), utf8_(utf8 < 0 ? validUtf8(t) : utf8 != 0) {}
  bool next(AdemRecord &r, std::vector<AdemError> &errs) {
    errs_ = &errs;
    for (;;) {
      skipBlanks(true);
      if (i_ >= t_.size()) return false;
      r.reset();
      if (record(r)) return true;
      resync();
    }
  }
  size_t offset() const { return i_; }

private:
  SourceLoc loc() const { return {file_, line_, (uint32_t)(i_ - lineStart_ + 1)}; }
  bool fail(SourceLoc l, std::string m) {
    errs_->push_back({l, std::move(m)});
    return false;
  }
  char peek(size_t k = 0) const { return i_ + k < t_.size() ? t_[i_ + k] : '\0'; }
  void advance() {
    if (t_[i_] == '\n') ++line_, lineStart_ = i_ + 1;
    ++i_;
  }
  // Blanks and `$$` comments; newlines too when `lines`.
  void skipBlanks(bool lines) {
    while (i_ < t_.size()) {
      char c = t_[i_];
      if (c == ' ' || c == '\t' || c == '\r' || (lines && c == '\n')) advance();
      else if (c == '$' && peek(1) == '$')
        while (i_ < t_.size() && t_[i_] != '\n') advance();
      else break;
    }
  }
  // After an error: past the next ';', or to the next line that starts a record with [code].
  void resync() {
    if (atRecordStart()) return;
    if (nextLine_) {
      nextLine_ = false;
      while (i_ < t_.size() && t_[i_] != '\n') advance();
      return;
    }
    while (i_ < t_.size()) {
      if (t_[i_] == ';') return advance();
      if (t_[i_] == '$' && peek(1) == '$') {  // a comment: its ';' ends nothing
        while (i_ < t_.size() && t_[i_] != '\n') advance();
        continue;
      }
      if (t_[i_] == '\n') {
        advance();
        size_t k = i_;
        while (k < t_.size() && (digit(t_[k]) || t_[k] == ' ' || t_[k] == '\t')) ++k;
        if (k < t_.size() && t_[k] == '[') return;
        continue;
      }
      advance();
    }
  }
  static bool digit(char c) { return c >= '0' && c <= '9'; }
  // At a '[' with only an ordinal or blanks before it on its line: a record starts here.
  bool atRecordStart() const {
    if (peek() != '[') return false;
    for (size_t k = lineStart_; k < i_; ++k)
      if (!digit(t_[k]) && t_[k] != ' ' && t_[k] != '\t') return false;
    return true;
  }
  std::string text(std::string_view raw) const { return utf8_ ? std::string(raw) : ademToUtf8(raw); }
  bool integer(int &v) {
    size_t b = i_;
    while (digit(peek())) advance();
    if (b == i_ || i_ - b > 9) return false;
    v = digitsValue(t_.substr(b, i_ - b));
    return true;
  }
  // The end of a value written without quotes.
  bool valueEnds(bool comment) const {
    char c = t_[i_];
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ';' || (comment && c == '$' && peek(1) == '$');
  }

  bool record(AdemRecord &r) {
    r.loc = loc();
    if (digit(peek()) && !integer(r.obj)) return fail(r.loc, "the route object's ordinal has more than 9 digits");  // FR[2]
    skipBlanks(false);
    bool coded = false;
    if (peek() == '[') {
      advance();
      skipBlanks(false);
      SourceLoc cl = loc();
      if (!integer(r.code) || r.code <= 0) return fail(cl, "a record code (a whole number from 1) expected after '['");
      skipBlanks(false);
      if (peek() != ']') return fail(loc(), "']' expected after the record code");
      advance();
      coded = true;
    }
    // The name: up to '/' or ';' on the same line.
    skipBlanks(false);
    SourceLoc nl = loc();
    size_t nb = i_;
    while (i_ < t_.size() && peek() != '/' && peek() != ';' && peek() != '\n' && !(peek() == '$' && peek(1) == '$')) advance();
    std::string_view raw = t_.substr(nb, i_ - nb);
    // Trailing blanks are ASCII in either encoding: trimmed before the text is converted.
    while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\t' || raw.back() == '\r')) raw.remove_suffix(1);
    if (!raw.empty()) {
      // A listing repeats a few names, each with its code: what a name gave is remembered per
      // code (a slot by the code's low bits), so that LINE ARC LINE ARC look up no name twice.
      Named &n = named_[(unsigned)r.code % std::size(named_)];
      if (!n.valid || raw != n.name || coded != n.coded || r.code != n.code) {
        std::string name = text(raw);
        n.byName = ademCodeByName(name);
        n.other = coded && n.byName && n.byName != r.code && !ademNameOf(r.code, name);
        n.name.assign(raw);
        n.coded = coded, n.code = r.code, n.valid = true;
      }
      if (!coded) {
        if (!n.byName) return fail(nl, fmt::format("'{}' is not the name of a record ncc knows; write its code as [code]", text(raw)));
        r.code = n.byName;
      } else if (n.other) {
        errs_->push_back({nl, fmt::format("'{}' names record [{}], not [{}]: the code counts", text(raw), n.byName, r.code), true});
      }
    } else if (!coded) {
      return fail(r.loc, "a record starts with [code] or a record name");
    }
    if (!info_ || info_->code != r.code) info_ = &layoutInfo(r.code);
    if (peek() == '/') {
      advance();
      if (!values(r, *info_)) return false;
    }
    skipBlanks(false);
    if (peek() != ';') {
      nextLine_ = true;  // the record ended with its line: the next line is the next record
      return fail(r.loc, fmt::format("record [{}] does not end with ';'", r.code));
    }
    advance();
    return true;
  }

  bool values(AdemRecord &r, const LayoutInfo &li) {
    const AdemLayout *lay = li.lay;
    const std::vector<int> &order = li.order;  // an unknown code: FR[3], FR[4]… in order
    size_t next = 0;       // the next positional field
    int nextTail = 0;
    auto nextIndex = [&]() -> int {
      if (next < order.size()) return order[next++];
      if (!lay) return 3 + (int)next++;
      if (lay->tailFrom > 0) return lay->tailFrom + nextTail++;
      return -1;
    };
    for (;;) {
      skipBlanks(true);
      if (i_ >= t_.size() || peek() == ';') return true;
      if (atRecordStart()) return fail(loc(), fmt::format("record [{}] does not end with ';' before the next record", r.code));
      SourceLoc vl = loc();
      int explicitIndex = -1;
      if ((peek() == 'F' || peek() == 'f') && (peek(1) == 'R' || peek(1) == 'r') && peek(2) == '[') {
        // FR[i]=value: a field by its index (ours; what `ncc-cld --listing` writes for fields
        // the order does not reach).
        i_ += 3;
        if (!integer(explicitIndex) || explicitIndex < 3 || peek() != ']' || peek(1) != '=')
          return fail(vl, "FR[i]=value expected, i from 3");
        i_ += 2;
      }
      SourceLoc fl = loc();
      bool isText = false;
      double num = 0;
      std::string_view tok;  // a value as written
      if (peek() == '\'') {
        advance();
        text_.clear();
        for (;;) {
          if (i_ >= t_.size() || peek() == '\n') return fail(fl, "the text does not end with ' on its line");
          if (peek() == '\'') {
            advance();
            if (peek() != '\'') break;  // '' is one quote
          }
          text_ += t_[i_];
          advance();
        }
        isText = true;
      } else {
        size_t b = i_;
        while (i_ < t_.size() && !valueEnds(true)) advance();
        tok = t_.substr(b, i_ - b);
        if (listingNumber(tok, num)) {
          if (!std::isfinite(num)) return fail(fl, fmt::format("'{}' is too large", tok));
        } else if (explicitIndex < 0) {
          if (li.free) continue;  // a step's words: the code says which step it is
          if (!word(r, text(tok), fl)) return false;
          continue;
        } else {
          return fail(fl, fmt::format("a number or a 'text' expected, not '{}'", text(tok)));
        }
      }
      int idx = explicitIndex >= 0 ? explicitIndex : nextIndex();
      if (idx < 0) return fail(fl, fmt::format("record [{}] takes {} value{}", r.code, order.size(), order.size() == 1 ? "" : "s"));
      if (idx > 300000) return fail(vl, "FR index too large");
      bool wantText = li.isText(idx);
      if (isText && !wantText) return fail(fl, fmt::format("FR[{}] of record [{}] is a number, not a text", idx, r.code));
      AdemField &f = r.fr[idx];
      f.loc = fl;
      f.isText = isText || wantText;
      f.num = isText ? 0 : num;
      if (isText) f.text = text(text_);
      else if (wantText) f.text = text(tok);  // a name written as a number: its text as written
      else f.text.clear();
    }
  }

  // A value word of the viewer's form (`Фреза R 5.000000 Позиция 2`): sets its field, or takes
  // the number after it.
  bool word(AdemRecord &r, const std::string &w, SourceLoc wl) {
    const AdemWord *aw = ademWord(r.code, ademNormalise(w));
    if (!aw) return fail(wl, fmt::format("'{}' is neither a number nor a value of record [{}]", w, r.code));
    if (aw->fr) r.fr[aw->fr] = AdemField{false, aw->value, {}, wl};
    if (aw->numberTo) {
      skipBlanks(true);
      SourceLoc nl = loc();
      size_t b = i_;
      while (i_ < t_.size() && !valueEnds(false)) advance();
      std::string tok(t_.substr(b, i_ - b));
      char *end = nullptr;
      double v = std::strtod(tok.c_str(), &end);
      if (tok.empty() || end != tok.c_str() + tok.size() || !std::isfinite(v))
        return fail(nl, fmt::format("a number expected after '{}'", w));
      r.fr[aw->numberTo] = AdemField{false, v, {}, nl};
    }
    return true;
  }

  std::string_view t_;
  uint32_t file_;
  std::vector<AdemError> *errs_ = nullptr;
  bool utf8_;
  size_t i_ = 0, lineStart_ = 0;
  bool nextLine_ = false;
  uint32_t line_ = 1;
  std::string text_;  // a quoted value's bytes
  const LayoutInfo *info_ = nullptr;  // the last record's code
  // A record name and what it gave: ademCodeByName, and whether it names another code.
  struct Named {
    std::string name;
    bool valid = false, coded = false, other = false;
    int code = 0, byName = 0;
  };
  Named named_[16];
};

bool reportAdemErrors(Diagnostics &d, const std::vector<AdemError> &errors) {
  bool ok = true;
  for (auto &e : errors) {
    if (e.warning) d.warning(e.loc, e.message, "lenient-syntax");
    else d.error(e.loc, e.message, "syntax"), ok = false;
  }
  return ok;
}

std::vector<AdemRecord> readAdemListing(std::string_view text, uint32_t file, std::vector<AdemError> &errors) {
  AdemReader::Listing reader(text, file);
  std::vector<AdemRecord> out;
  AdemRecord r;
  while (reader.next(r, errors)) out.push_back(r);
  return out;
}

// ---- the binary form ----

namespace {
constexpr size_t kCell = 8;
constexpr double kMaxCells = 1 << 22;  // 32 MB in one record: beyond that the length is garbage

double cellAt(std::string_view b, size_t off) {
  unsigned char c[8];
  std::memcpy(c, b.data() + off, 8);
  uint64_t u = 0;
  for (int k = 7; k >= 0; --k) u = (u << 8) | c[k];  // little-endian
  double d;
  std::memcpy(&d, &u, 8);
  return d;
}

void putCell(std::string &o, double d) {
  uint64_t u;
  std::memcpy(&u, &d, 8);
  for (int k = 0; k < 8; ++k) o += (char)((u >> (8 * k)) & 0xFF);
}

bool whole(double d) { return std::isfinite(d) && d == std::floor(d); }
}  // namespace

bool looksLikeAdemBinary(std::string_view bytes) {
  // A listing is text: no NUL. A binary record's first cell (its length, a small whole number
  // as a double) has NUL bytes in its low half.
  return bytes.substr(0, 64).find('\0') != std::string_view::npos;
}

class AdemReader::Binary {
public:
  Binary(std::string_view b, uint32_t file) : b_(b), file_(file) {}
  size_t offset() const { return pos_; }
  // The next record read without error; a record with an error is skipped (its length is
  // known), a broken length ends the file.
  bool next(AdemRecord &r, std::vector<AdemError> &errors) {
    while (!done_ && pos_ < b_.size()) {
      bool ok = one(r, errors);
      ++n_;
      if (ok) return true;
    }
    return false;
  }

private:
  bool one(AdemRecord &r, std::vector<AdemError> &errors) {
    const size_t pos = pos_;
    auto fail = [&](std::string m) { errors.push_back({{file_, 0, 0}, fmt::format("record {} at byte {}: {}", n_, pos, m)}); };
    if (b_.size() - pos < 3 * kCell) {
      fail(fmt::format("the file ends {} bytes into the record, before its first three cells (FR[0] FR[1] FR[2])", b_.size() - pos));
      return done_ = true, false;
    }
    double len = cellAt(b_, pos), code = cellAt(b_, pos + 8), obj = cellAt(b_, pos + 16);
    if (!whole(len) || len < 3 || len > kMaxCells) {
      fail(fmt::format("FR[0], the record's length in cells, is {} (a whole number from 3 expected)", len));
      return done_ = true, false;
    }
    size_t cells = (size_t)len;
    if (cells * kCell > b_.size() - pos) {
      fail(fmt::format("FR[0] says {} cells ({} bytes), the file has {} bytes left", cells, cells * kCell, b_.size() - pos));
      return done_ = true, false;
    }
    pos_ += cells * kCell;
    r.reset();
    r.loc = {file_, 0, n_};
    r.byte = pos;
    bool ok = true;
    if (!whole(code) || code < 1 || code > 1e9) ok = false, fail(fmt::format("FR[1], the record code, is {}", code));
    if (!whole(obj) || std::fabs(obj) > 1e9) ok = false, fail(fmt::format("FR[2], the route object's ordinal, is {}", obj));
    r.code = ok ? (int)code : 0;
    r.obj = ok ? (int)obj : 0;
    if (ok && (!info_ || info_->code != r.code)) info_ = &layoutInfo(r.code);
    for (size_t k = 3, fi = 3; ok && k < cells; ++fi) {
      double v = cellAt(b_, pos + k * kCell);
      if (info_->isText((int)fi)) {
        // A text field: its byte count, then the bytes in as many cells as they fill.
        size_t room = (cells - k - 1) * kCell;
        if (!whole(v) || v < 0 || v > (double)room) {
          fail(fmt::format("FR[{}] of record [{}] is a text of {} bytes, the record has {} bytes left", fi, r.code, v, room));
          return false;
        }
        size_t len8 = (size_t)v;
        r.fr[(int)fi] = AdemField{true, 0, ademToUtf8(b_.substr(pos + (k + 1) * kCell, len8)), r.loc};
        k += 1 + (len8 + kCell - 1) / kCell;
      } else {
        if (!std::isfinite(v)) {
          fail(fmt::format("FR[{}] of record [{}] is not a finite number", fi, r.code));
          return false;
        }
        AdemField &f = r.fr[(int)fi];  // zeros too: the record has the field
        f.num = v, f.loc = r.loc;
        ++k;
      }
    }
    return ok;
  }

  std::string_view b_;
  uint32_t file_;
  size_t pos_ = 0;
  uint32_t n_ = 1;  // the record's ordinal
  bool done_ = false;
  const LayoutInfo *info_ = nullptr;
};

AdemReader::AdemReader(std::string_view bytes, uint32_t file, int utf8) : binary_(looksLikeAdemBinary(bytes)) {
  if (binary_) bin_ = std::make_unique<Binary>(bytes, file);
  else listing_ = std::make_unique<Listing>(bytes, file, utf8);
}
AdemReader::~AdemReader() = default;
bool AdemReader::next(AdemRecord &r, std::vector<AdemError> &errors) {
  return binary_ ? bin_->next(r, errors) : listing_->next(r, errors);
}
size_t AdemReader::offset() const { return binary_ ? bin_->offset() : listing_->offset(); }

std::vector<AdemRecord> readAdemBinary(std::string_view b, uint32_t file, std::vector<AdemError> &errors) {
  AdemReader::Binary reader(b, file);
  std::vector<AdemRecord> out;
  AdemRecord r;
  while (reader.next(r, errors)) out.push_back(r);
  return out;
}

std::string writeAdemBinary(const std::vector<AdemRecord> &records) {
  std::string o;
  for (auto &r : records) {
    std::string body;
    int last = r.fr.empty() ? 2 : r.fr.rbegin()->first;
    for (int i = 3; i <= last; ++i) {
      const AdemField *f = r.field(i);
      if (f && f->isText) {
        putCell(body, (double)f->text.size());
        body += f->text;
        body.append((kCell - f->text.size() % kCell) % kCell, '\0');
      } else {
        putCell(body, f ? f->num : 0.0);
      }
    }
    putCell(o, (double)(3 + body.size() / kCell));
    putCell(o, r.code);
    putCell(o, r.obj);
    o += body;
  }
  return o;
}

std::string writeAdemListing(const std::vector<AdemRecord> &records) {
  std::string o;
  for (auto &r : records) {
    const AdemLayout *lay = ademLayout(r.code);
    std::string name;
    if (lay) name = std::string(std::string_view(lay->names).substr(0, std::string_view(lay->names).find('|')));
    o += fmt::format("{}[{}] {}/", r.obj, r.code, name);
    std::vector<int> order = positional(lay);
    size_t k = 0;
    auto value = [](const AdemField &f) {
      if (!f.isText) return fmt::format("{}", f.num);  // the shortest text that reads back to the same double
      std::string s = "'";
      for (char c : f.text)  // a line break would end the text: written as a blank
        s += c == '\'' ? std::string("''") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
      return s + "'";
    };
    for (auto &[i, f] : r.fr) {
      if (lay && !f.isText && f.num == 0 && !ademFieldIsText(lay, i) && std::find(order.begin(), order.end(), i) == order.end())
        continue;  // a binary record's padding before fields such as FR[10]: the binary has it anyway
      // In the layout's order while the fields follow it, by index after that.
      bool inOrder = lay ? (k < order.size() && order[k] == i) : i == (int)k + 3;
      if (inOrder && !freeWords(lay)) ++k, o += " " + value(f);
      else k = order.size() + 1, o += fmt::format(" FR[{}]={}", i, value(f));
    }
    o += ";\n";
  }
  return o;
}

// ---- the code table (both directions: the readers' names and fields, the writers' too) ----

namespace {
// The codes of seed 004 Appendix 1 with their Appendix 2 fields. Names: the manual's (the
// catalogue's, the phrase's and the viewer's), then ours in Latin letters. The first name is the
// one the listing writer prints. frontend/cldata/AdemLower.cpp lowers each code.
const AdemLayout kLayouts[] = {
    {1, "Программа|ПРОГРАМ|Учетные данные программы|PROGRAM", "3t 4t 5t 6t 7t 8", 0},
    {2, "Деталь|Учетные данные детали|PART", "3 4t 5t 6t", 0},
    {3, "Станок|Учетные данные станка|MACHINE", "3 4 5t", 100},
    {4, "Конец программы|Конец УП|END", "", 0},
    {6, "Начало|НАЧАЛО|START", "", 0},
    {22, "Стоп программы|Стоп|STOP", "", 0},
    {23, "Включить рабочую подачу|Включение рабочей подачи|FEED", "3 4", 0},
    {24, "Включить шпиндель|Включение шпинделя|SPINDLE", "3 4 5 6 7 8 9 10 11", 0},
    {25, "Включить ускоренную подачу|Включение холостого хода|RAPID", "", 0},
    {26, "Включить СОЖ|Включение СОЖ|COOLANT", "3 4", 0},
    {27, "Выстой|DWELL", "3 4", 0},
    {28, "Отвести инструмент|ОТВОД|RETRACT", "", 0},
    {29, "Перезахват|Перехват|RECLAMP", "3 4 5", 0},
    {33, "Условный останов|Условный останов программы|OPSTOP", "", 0},
    {34, "Смена стола|СТОЛ|TABLE", "3", 0},
    {35, "Загрузка инструмента|Загрузить инструмент|Инструмент|TOOL", "3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29t 30 31", 0},
    {36, "Цикл|ЦИКЛ|CYCLE", "3 4 5t 6", 10},
    {39, "Коррекция инструмента", "", 0},
    {40, "Поворот|ПОВОРОТ|ROTATE", "3 4 5 6 7 8 9", 0},
    {41, "Совмещенные мультиперемещения|Мультиперемещения|МУЛЬТИ|MULTI", "3 4 5 6 7 8 9 10 11 12", 0},
    {45, "Контрольная точка|CONTROL POINT", "3", 0},
    {94, "Резьба токарная|THREAD", "3 4 5 6 7 8 9 10 11 12 13", 0},
    {181, "Линейная интерполяция|Линейные перемещения|Идти в точку|ИДИ|LINE", "3 4 5", 0},
    {182, "Линейное векторное перемещение|Линейные векторные перемещения|VECTOR LINE", "", 0},
    {183, "Круговая интерполяция|Круговые перемещения|ИДИ ОКР|ARC", "3 4 5 6 7 8 9", 0},
    {184, "Векторное круговое перемещение|Векторные круговые перемещения", "3 4 5 6 7 8 9 10 11 12 13", 0},
    {185, "Совмещённое линейное перемещение|Дополнительное линейное перемещение", "3 4 5", 0},
    {187, "Совмещённое перемещение по дуге|Дополнительное круговое перемещение", "3 4 5 6 7 8 9", 0},
    {189, "Векторное линейное перемещение с коррекцией|Векторные линейные перемещения с коррекцией", "3 4 5 6 7 8 9 10 11", 0},
    {190, "Криволинейное перемещение|ИДИ КРИВАЯ|CURVE", "3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18", 0},
    {191, "Дополнительное криволинейное перемещение", "3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18", 0},
    {223, "Вызов подпрограммы|CALL", "3 4", 0},
    {227, "Строка|СТРОКА", "", 0},
    {252, "Начало подпрограммы|Начало/конец подпрограммы", "", 0},
    {301, "Технологический переход «Фрезеровать»|Переход|STEP", "*", 0},
    {302, "Технологический переход «Точить»|Переход|STEP", "*", 0},
    {303, "Технологический переход «Расточить (токарный)»|Переход|STEP", "*", 0},
    {304, "Технологический переход «Нарезать резьбу метчиком»|Переход|STEP", "*", 0},
    {305, "Технологический переход «Отрезать»|Переход|STEP", "*", 0},
    {306, "Технологический переход «Пробить»|Переход|STEP", "*", 0},
    {307, "Технологический переход «Центровать»|Переход|STEP", "*", 0},
    {308, "Технологический переход «Сверлить»|Переход|STEP", "*", 0},
    {309, "Технологический переход «Развернуть»|Переход|STEP", "*", 0},
    {310, "Технологический переход «Подрезать»|Переход|STEP", "*", 0},
    {311, "Технологический переход «Зенкеровать»|Переход|STEP", "*", 0},
    {312, "Технологический переход «Гравировать»|Переход|STEP", "*", 0},
    {314, "Технологический переход «Расточить (сверлильный)»|Переход|STEP", "*", 0},
    {315, "Технологический переход «Резать»|Переход|STEP", "*", 0},
    {316, "Технологический переход «Нарезать резьбу резцом (токарный)»|Переход|STEP", "*", 0},
    {401, "Начало цикла|CYCLE START", "10 11 12 20 21 22 30", 0},
    {402, "Трансформ зоны|ТРАНСФОРМ ЗОНЫ", "", 0},
    {404, "Ноль УП для текущей зоны обработки", "", 0},
    {405, "Трансформ осей поворота|ТРАНСФОРМ ОСЕЙ ПОВОРОТА", "", 0},
    {406, "Начальная точка обработки|НТО", "", 0},
    {451, "Безопасная позиция|БЕЗПОЗ|SAFE POSITION", "10 11 12 13 14 15", 0},
    {452, "Плоскость холостого хода|Плоскость холостых ходов|ПХХ|CLEARANCE", "10 11", 0},
    {458, "Вставка УП|INSERT", "10t", 0},
    {459, "Команда пользователя|USER", "3", 10},
    {460, "Параметры пользователя", "3", 100},
    {491, "Величина аппроксимации|TOLERANCE", "10", 0},
    {493, "Турета|TURRET", "10", 0},
    {582, "Комментарий программы|Комментарий|COMMENT", "10t", 0},
    {700, "Выключить СОЖ|COOLANT OFF", "", 0},
    {701, "Выключить шпиндель|SPINDLE OFF", "", 0},
    {703, "Включить корректор по оси X", "", 0},
    {704, "Включить корректор по оси Y", "", 0},
    {705, "Включить корректор по оси Z", "", 0},
    {706, "Включить радиусный корректор", "", 0},
    {707, "Выключить корректор по оси X", "", 0},
    {708, "Выключить корректор по оси Y", "", 0},
    {709, "Выключить корректор по оси Z", "", 0},
    {710, "Выключить радиусный корректор", "", 0},
    {711, "Ориентированный останов шпинделя", "", 0},
    {713, "Конец подпрограммы", "", 0},
    {799, "", "", 0},
    {900, "Глубина резания", "10", 0},
    {901, "Плоскость интерполяции|ПЛОСК|PLANE", "10 11", 0},
    {902, "ЗОНА|ZONE", "", 0},
    {10123, "Трансформ|TRANSFORM", "3 4 5 6 7 8 9 10 11 12 13 14", 0},
};

// The viewer's value words (`Фреза R 5.000000 Позиция 2`, seed 004 L515).
// Позиция: the pocket, in FR[4] (the manual lists no field for it: docs/CLDATA.md).
const AdemWord kWords[] = {
    {35, "Фреза", 3, 1, 0},     {35, "Сверло", 3, 2, 0}, {35, "Центровка", 3, 3, 0}, {35, "Зенкер", 3, 4, 0},
    {35, "Развертка", 3, 5, 0}, {35, "Метчик", 3, 6, 0}, {35, "Резец", 3, 7, 0},     {35, "Пуансон", 3, 8, 0},
    {35, "Проволока", 3, 9, 0}, {35, "Лазер", 3, 10, 0}, {35, "Резак", 3, 11, 0},    {35, "R", 19, 1, 20},
    {35, "D", 19, 2, 20},       {35, "Позиция", 0, 0, 4},
};

// Every name of every code, normalised once: (name, code) in the table's order.
const std::vector<std::pair<std::string, int>> &allNames() {
  static const std::vector<std::pair<std::string, int>> names = [] {
    std::vector<std::pair<std::string, int>> v;
    for (auto &c : kLayouts) {
      std::string_view all = c.names;
      for (size_t b = 0; b < all.size();) {
        size_t e = all.find('|', b);
        if (e == std::string_view::npos) e = all.size();
        v.emplace_back(ademNormalise(all.substr(b, e - b)), c.code);
        b = e + 1;
      }
    }
    return v;
  }();
  return names;
}

const LayoutInfo &layoutInfo(int code) {
  static const std::vector<LayoutInfo> infos = [] {
    std::vector<LayoutInfo> v;
    for (auto &l : kLayouts) {
      LayoutInfo i;
      i.code = l.code;
      i.lay = &l;
      i.order = positional(&l);
      for (int f : i.order)
        if (ademFieldIsText(&l, f)) i.texts.push_back(f);
      i.free = freeWords(&l);
      v.push_back(std::move(i));
    }
    std::sort(v.begin(), v.end(), [](const LayoutInfo &a, const LayoutInfo &b) { return a.code < b.code; });
    return v;
  }();
  static const LayoutInfo unknown;
  auto it = std::lower_bound(infos.begin(), infos.end(), code, [](const LayoutInfo &i, int c) { return i.code < c; });
  if (it == infos.end() || it->code != code) return unknown;
  return *it;
}
}  // namespace

const AdemLayout *ademLayout(int code) { return layoutInfo(code).lay; }

AdemField &AdemFields::operator[](int i) {
  if (v_.empty() || v_.back().first < i) return v_.emplace_back(i, AdemField{}).second;
  auto it = std::lower_bound(v_.begin(), v_.end(), i, [](const Entry &e, int k) { return e.first < k; });
  if (it == v_.end() || it->first != i) it = v_.emplace(it, i, AdemField{});
  return it->second;
}

const AdemField *AdemFields::find(int i) const {
  auto it = std::lower_bound(v_.begin(), v_.end(), i, [](const Entry &e, int k) { return e.first < k; });
  return it == v_.end() || it->first != i ? nullptr : &it->second;
}

int ademCodeByName(std::string_view utf8) {
  std::string n = ademNormalise(utf8);
  for (auto &[name, code] : allNames())
    if (!n.empty() && name == n) return code;
  return 0;
}

bool ademNameOf(int code, std::string_view utf8) {
  std::string n = ademNormalise(utf8);
  for (auto &[name, c] : allNames())
    if (c == code && name == n) return true;
  return false;
}

const AdemWord *ademWord(int code, const std::string &normalised) {
  for (auto &w : kWords)
    if (w.code == code && ademNormalise(w.word) == normalised) return &w;
  return nullptr;
}

}  // namespace ncc::cld
