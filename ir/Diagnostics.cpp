#include "ir/Diagnostics.h"
#include "ir/LintRules.h"
#include "ir/TextQuote.h"

#include <cstdlib>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ncc {

SourceManager::SourceManager() = default;
SourceManager::~SourceManager() = default;

SourceManager::File::~File() {
  if (map) munmap(map, mapSize);
}

uint32_t SourceManager::addFile(const std::string &path) {
  int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  struct stat st;
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    void *m = mmap(nullptr, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (m != MAP_FAILED) {
      close(fd);
      madvise(m, (size_t)st.st_size, MADV_SEQUENTIAL);  // read once from the front: read ahead
      auto f = std::make_unique<File>();
      f->name = path;
      f->map = m;
      f->mapSize = (size_t)st.st_size;
      f->text = std::string_view(static_cast<const char *>(m), f->mapSize);
      files_.push_back(std::move(f));
      return (uint32_t)files_.size();
    }
  }
  // Pipes, empty files, or no mapping: read.
  std::string text;
  char buf[1 << 16];
  for (ssize_t n; (n = read(fd, buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      close(fd);
      return 0;
    }
    text.append(buf, (size_t)n);
  }
  close(fd);
  return addBuffer(path, std::move(text));
}

uint32_t SourceManager::addBuffer(std::string name, std::string text) {
  auto f = std::make_unique<File>();
  f->name = std::move(name);
  f->owned = std::move(text);
  f->text = f->owned;
  files_.push_back(std::move(f));
  return (uint32_t)files_.size();
}

void SourceManager::released(uint32_t file, size_t offset) const {
  auto *f = get(file);
  if (!f || !f->map) return;
  static const size_t page = (size_t)sysconf(_SC_PAGESIZE);
  size_t n = std::min(offset, f->mapSize) / page * page;
  if (n) madvise(f->map, n, MADV_DONTNEED);  // clean private pages: dropped, read again on use
}

const SourceManager::File *SourceManager::get(uint32_t file) const {
  if (file == 0 || file > files_.size()) return nullptr;
  return files_[file - 1].get();
}

const std::string &SourceManager::name(uint32_t file) const {
  static const std::string none = "<unknown>";
  auto *f = get(file);
  return f ? f->name : none;
}

std::string_view SourceManager::text(uint32_t file) const {
  auto *f = get(file);
  return f ? f->text : std::string_view();
}

std::string_view SourceManager::lineText(uint32_t file, uint32_t line) const {
  auto *f = get(file);
  if (!f || line == 0) return {};
  // Indexed only as far as asked (up to the start of the line after `line`): a streamed file's
  // early diagnostic neither reads the rest of the file nor holds an index of all its lines.
  auto &ls = const_cast<File *>(f)->lineStarts;
  if (ls.empty()) ls.push_back(0);
  for (uint32_t i = ls.back(); ls.size() <= line && i < f->text.size(); ++i)
    if (f->text[i] == '\n') ls.push_back(i + 1);
  if (line > f->lineStarts.size()) return {};
  uint32_t b = f->lineStarts[line - 1];
  uint32_t e = line < f->lineStarts.size() ? f->lineStarts[line] - 1 : (uint32_t)f->text.size();
  if (e > b && f->text[e - 1] == '\r') --e;
  if (e < b) e = b;
  return f->text.substr(b, e - b);
}

static const char *severityName(Severity s) {
  switch (s) {
  case Severity::Note: return "note";
  case Severity::Warning: return "warning";
  case Severity::Error: return "error";
  }
  return "error";
}

void appendJsonEscaped(std::string &o, std::string_view s) { text::appendEscaped(o, s, true); }

static std::string jsonEscape(std::string_view s) {
  std::string o;
  appendJsonEscaped(o, s);
  return o;
}

// The length of the well-formed UTF-8 sequence at s[i] (2-4), or 0.
static size_t utf8Length(std::string_view s, size_t i) {
  unsigned char c = (unsigned char)s[i];
  size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (!n || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if (((unsigned char)s[i + k] & 0xC0) != 0x80) return 0;
  return n;
}

// A quoted source line as the terminal should show it: UTF-8 text (Cyrillic or German comments)
// as it is, control characters and bytes that are not UTF-8 (a Latin-1 file) as '?', so they
// cannot garble the terminal. `caret` receives the padding up to byte column `col`: one space
// (or the tab) per character shown, so the caret stands under the character the column names.
static std::string printable(std::string_view s, uint32_t col, std::string &caret) {
  std::string o;
  for (size_t i = 0; i < s.size();) {
    size_t n = (unsigned char)s[i] >= 0x80 ? utf8Length(s, i) : 1;
    if (i + 1 < col) caret += s[i] == '\t' ? '\t' : ' ';
    if (n > 1) {
      o.append(s.substr(i, n));
      i += n;
      continue;
    }
    unsigned char c = (unsigned char)s[i++];
    o += (c < 0x20 && c != '\t') || c >= 0x7f ? '?' : (char)c;
  }
  return o;
}

std::string Diagnostics::render(const Diagnostic &d) const {
  std::string file = d.loc.file ? sm_.name(d.loc.file) : "ncc";
  if (format_ == Format::Json) {
    return fmt::format(R"({{"file":"{}","line":{},"column":{},"severity":"{}","message":"{}","rule":"{}"}})",
                       jsonEscape(file), d.loc.line, d.loc.col, severityName(d.severity),
                       jsonEscape(d.message), jsonEscape(d.rule));
  }
  std::string out;
  if (d.loc.valid())
    out = fmt::format("{}:{}:{}: {}: {}", file, d.loc.line, d.loc.col ? d.loc.col : 1,
                      severityName(d.severity), d.message);
  else
    out = fmt::format("{}: {}: {}", file, severityName(d.severity), d.message);
  if (!d.rule.empty()) out += fmt::format(" [{}]", d.rule);
  out += '\n';
  // A file registered without its text (a compiled program whose source changed) has no line to show.
  if (d.loc.valid() && !sm_.text(d.loc.file).empty()) {
    std::string_view line = sm_.lineText(d.loc.file, d.loc.line);
    if (line.size() > 300) line = line.substr(0, 300);
    std::string pad;
    out += printable(line, d.loc.col ? d.loc.col : 1, pad);
    out += '\n';
    out += pad + "^\n";
  }
  return out;
}

void Diagnostics::report(Severity s, SourceLoc loc, std::string message, std::string rule) {
  // The test suite sets NCC_CHECK_RULES: a rule missing from the registry is a bug there.
  static const bool checkRules = std::getenv("NCC_CHECK_RULES") != nullptr;
  if (checkRules && !rule.empty() && !findLintRule(rule)) {
    std::fprintf(stderr, "ncc: internal error: rule '%s' is not in ir/LintRules.cpp\n", rule.c_str());
    std::abort();
  }
  if (s == Severity::Warning && werror_) s = Severity::Error;
  if (s == Severity::Error) ++errors_;
  if (s == Severity::Warning) ++warnings_;
  Diagnostic d{s, loc, std::move(message), std::move(rule)};
  if (s == Severity::Error && errors_ > errorLimit_) {
    if (errors_ == errorLimit_ + 1 && out_ && !collect_)
      std::fprintf(out_, "ncc: note: too many errors, stopping here\n");
    return;
  }
  if (collect_) {
    collected_.push_back(std::move(d));
    return;
  }
  if (out_) {
    std::string text = render(d);
    if (format_ == Format::Json) text += '\n';
    std::fputs(text.c_str(), out_);
  }
}

bool writeFileAtomic(const std::string &path, std::string_view data, std::string &err) {
  AtomicFile f(path);
  if (!f.ok()) {
    err = fmt::format("cannot create '{}'", path);
    return false;
  }
  if (std::fwrite(data.data(), 1, data.size(), f.stream()) != data.size()) {
    err = fmt::format("cannot write '{}'", path);
    return false;
  }
  return f.commit(err);
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  tmp_ = path_ + fmt::format(".tmp{}", (long)getpid());
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (f_) std::setvbuf(f_, nullptr, _IOFBF, 1 << 16);
}

AtomicFile::~AtomicFile() {
  if (f_) {
    std::fclose(f_);
    std::remove(tmp_.c_str());
  }
}

bool AtomicFile::commit(std::string &err) {
  if (!f_) {
    err = fmt::format("cannot create '{}'", path_);
    return false;
  }
  bool bad = std::ferror(f_) != 0;
  bad |= std::fclose(f_) != 0;
  f_ = nullptr;
  if (bad) {
    std::remove(tmp_.c_str());
    err = fmt::format("cannot write '{}'", path_);
    return false;
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    std::remove(tmp_.c_str());
    err = fmt::format("cannot rename to '{}'", path_);
    return false;
  }
  return true;
}

}  // namespace ncc
