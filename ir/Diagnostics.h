// One diagnostics engine for every stage: front ends, passes, runtime, lint.
// Prints `file:line:col: error|warning|note: message [rule-id]`, the source line and a caret,
// or one JSON object per diagnostic.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

// A position in a source file. file is an index into SourceManager; 0 = no file.
struct SourceLoc {
  uint32_t file = 0;
  uint32_t line = 0;  // 1-based; 0 = unknown
  uint32_t col = 0;   // 1-based byte column; 0 = unknown
  bool valid() const { return file != 0 && line != 0; }
};

// Owns the text of every file a compilation reads (main program and subprogram files).
// A regular file is mapped (mmap), not copied: a long program costs its pages, which the kernel
// can drop and read again, not heap memory.
class SourceManager {
public:
  SourceManager();
  ~SourceManager();
  SourceManager(const SourceManager &) = delete;
  SourceManager &operator=(const SourceManager &) = delete;
  // Reads (maps) a file; returns its id, or 0 when it cannot be read.
  uint32_t addFile(const std::string &path);
  // Registers text under a name (tests, stdin, generated programs).
  uint32_t addBuffer(std::string name, std::string text);
  const std::string &name(uint32_t file) const;
  std::string_view text(uint32_t file) const;
  // The text of one line (without newline); empty when out of range.
  std::string_view lineText(uint32_t file, uint32_t line) const;
  uint32_t fileCount() const { return (uint32_t)files_.size(); }
  // A streaming reader is done with the text before `offset`: a mapped file's pages there may
  // leave memory (they are read again if a diagnostic quotes a line).
  void released(uint32_t file, size_t offset) const;

private:
  struct File {
    std::string name, owned;  // owned: the text of a buffer or a file that could not be mapped
    std::string_view text;
    void *map = nullptr;      // the mapping of `text`, if any
    size_t mapSize = 0;
    std::vector<uint32_t> lineStarts;  // computed lazily
    ~File();
  };
  std::vector<std::unique_ptr<File>> files_;
  const File *get(uint32_t file) const;
};

enum class Severity : uint8_t { Note, Warning, Error };

struct Diagnostic {
  Severity severity;
  SourceLoc loc;
  std::string message;
  std::string rule;  // lint rule id or empty
};

class Diagnostics {
public:
  explicit Diagnostics(const SourceManager &sm) : sm_(sm) {}

  enum class Format : uint8_t { Text, Json };
  void setFormat(Format f) { format_ = f; }
  void setWarningsAsErrors(bool on) { werror_ = on; }
  // Diagnostics are printed as they arrive unless collecting (tests, lint JSON).
  void setStream(std::FILE *out) { out_ = out; }
  void setCollect(bool on) { collect_ = on; }
  // Stops reporting (but keeps counting) after this many errors: bad input must not flood.
  void setErrorLimit(unsigned n) { errorLimit_ = n; }

  void report(Severity s, SourceLoc loc, std::string message, std::string rule = {});
  void error(SourceLoc loc, std::string message, std::string rule = {}) {
    report(Severity::Error, loc, std::move(message), std::move(rule));
  }
  void warning(SourceLoc loc, std::string message, std::string rule = {}) {
    report(Severity::Warning, loc, std::move(message), std::move(rule));
  }
  void note(SourceLoc loc, std::string message, std::string rule = {}) {
    report(Severity::Note, loc, std::move(message), std::move(rule));
  }

  unsigned errorCount() const { return errors_; }
  unsigned warningCount() const { return warnings_; }
  bool hasErrors() const { return errors_ > 0; }
  const std::vector<Diagnostic> &collected() const { return collected_; }
  // Renders one diagnostic in the current format (no trailing newline for JSON).
  std::string render(const Diagnostic &d) const;
  const SourceManager &sources() const { return sm_; }

private:
  const SourceManager &sm_;
  Format format_ = Format::Text;
  bool werror_ = false, collect_ = false;
  std::FILE *out_ = stderr;
  unsigned errors_ = 0, warnings_ = 0, errorLimit_ = 50;
  std::vector<Diagnostic> collected_;
};

// Appends `s` to `out` as the body of a JSON string (quotes, backslashes, control characters
// escaped). Shared by the JSON diagnostics and the JSONL trace.
void appendJsonEscaped(std::string &out, std::string_view s);

// Writes a file atomically: the text goes to a temporary file next to the target which is then
// renamed over it, so a failed run never leaves a half-written output. Returns false and sets
// err on failure.
bool writeFileAtomic(const std::string &path, std::string_view data, std::string &err);

// Streams into a temporary file and renames on commit(); the destructor removes an uncommitted
// temporary. For large outputs (traces, samples) that must not be held in memory.
class AtomicFile {
public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  bool ok() const { return f_ != nullptr; }
  std::FILE *stream() { return f_; }
  bool commit(std::string &err);
  const std::string &path() const { return path_; }

private:
  std::string path_, tmp_;
  std::FILE *f_ = nullptr;
};

}  // namespace ncc
