#include "ir/FileCommands.h"

#include "ir/StrArgs.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <vector>

namespace ncc {

namespace fs = std::filesystem;

std::string sinumerikPathComponent(std::string_view c, bool last) {
  if (c.size() > 3 && c.substr(0, 3) == "_N_") {
    size_t u = c.rfind('_');
    if (u > 2) return fmt::format("{}.{}", c.substr(3, u - 3), c.substr(u + 1));
  }
  if (last && c.find('.') == std::string_view::npos) return fmt::format("{}.MPF", c);
  return std::string(c);
}

namespace {
std::string &sandbox() {
  static std::string dir;
  return dir;
}
bool &lintMode() {
  static bool on = false;
  return on;
}

// Error codes of the manual (L6287-L6787).
enum FileError { kOk = 0, kPathNotFound = 2, kFileNotFound = 3, kWrongType = 4, kLineMissing = 21,
                 kResultTooShort = 22, kRangeTooLarge = 23 };

std::string component(std::string_view c, bool last) { return sinumerikPathComponent(c, last); }

// The sandbox path of a file name; false with `error` without a sandbox or for a name that
// leaves it (a `..` component, a device `NC:`, a link pointing out).
bool sandboxPath(const char *cmd, std::string_view name, fs::path &out, std::string &error) {
  if (sandbox().empty()) {
    error = fmt::format("{} needs a sandbox folder for its files: run with --sandbox DIR", cmd);
    return false;
  }
  std::vector<std::string_view> parts;
  for (size_t a = 0; a <= name.size();) {
    size_t b = name.find('/', a);
    if (b == std::string_view::npos) b = name.size();
    if (b > a) parts.push_back(name.substr(a, b - a));
    a = b + 1;
  }
  auto leaves = [&] {
    error = fmt::format("{}: the file \"{}\" is outside the sandbox folder {}", cmd, name, sandbox());
    return false;
  };
  if (parts.empty()) return leaves();
  fs::path p = sandbox();
  for (size_t i = 0; i < parts.size(); ++i) {
    std::string_view c = parts[i];
    if (c == "." || c == ".." || c.find_first_of("\\:") != std::string_view::npos) return leaves();
    p /= component(c, i + 1 == parts.size());
  }
  std::error_code ec;
  // A link that points nowhere would be followed by a write: refused like one pointing out.
  if (fs::is_symlink(fs::symlink_status(p, ec)) && !fs::exists(p, ec)) return leaves();
  fs::path root = fs::weakly_canonical(sandbox(), ec), real = fs::weakly_canonical(p, ec);
  std::string r = root.string(), f = real.string();
  if (ec || f.size() <= r.size() || f.compare(0, r.size(), r) != 0 || f[r.size()] != '/') return leaves();
  out = p;
  return true;
}

// A file to read: 0, or the manual's code (2 folder missing, 3 file missing, 4 binary type).
int readable(const fs::path &p) {
  std::error_code ec;
  if (!fs::is_directory(p.parent_path(), ec)) return kPathNotFound;
  if (!fs::is_regular_file(p, ec)) return kFileNotFound;
  static const char *kBinary[] = {"BIN", "EXE", "OBJ", "LIB", "BOT", "TRC", "ACC", "CYC", "NCK"};
  std::string ext = p.extension().string();
  for (const char *b : kBinary)
    if (ext == std::string(".") + b) return kWrongType;
  return kOk;
}

std::vector<std::string> lines(const fs::path &p) {
  std::vector<std::string> out;
  std::ifstream in(p, std::ios::binary);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();  // CR LF: the end is not stored (L6586)
    out.push_back(std::move(l));
  }
  return out;
}

std::string stamp(const fs::path &p, const char *format) {
  struct stat st {};
  if (stat(p.c_str(), &st) != 0) return {};
  std::tm tm{};
  localtime_r(&st.st_mtime, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, format, &tm);
  return buf;
}

struct FileArgs : StrArgs {
  FileArgs(ValuePool &p, const double *a, unsigned n, std::string &e, const char *fn) : StrArgs{p, a, n, e, fn} {}
  std::string cmd;
  fs::path path;
  bool none = false;  // lint without a sandbox: no folder, every file missing
  // The command name and the file of arguments 0 and 1.
  bool open() {
    std::string_view c, name;
    if (!str(0, c) || !str(1, name)) return false;
    cmd = c;
    if (sandbox().empty() && lintMode()) return none = true;
    return sandboxPath(cmd.c_str(), name, path, error);
  }
};
}  // namespace

void setFileSandbox(std::string dir) { sandbox() = std::move(dir); }
void setFileLintMode(bool on) { lintMode() = on; }
const std::string &fileSandbox() { return sandbox(); }

bool fileWrite(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_WRITE");
  std::string_view text;
  if (!a.open() || !a.str(2, text)) return false;
  if (lintMode()) return out = kOk, true;  // lint writes nothing
  std::error_code ec;
  if (!fs::is_directory(a.path.parent_path(), ec)) return out = kPathNotFound, true;
  if (fs::exists(a.path, ec) && !fs::is_regular_file(a.path, ec)) return out = kWrongType, true;
  std::ofstream f(a.path, std::ios::binary | std::ios::app);
  f << text << '\n';  // the passive file system adds the line feed (L6356)
  f.flush();
  if (!f) {
    error = fmt::format("{}: cannot write {}", a.cmd, a.path.string());
    return false;
  }
  out = kOk;
  return true;
}

bool fileDelete(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_DELETE");
  if (!a.open()) return false;
  if (lintMode()) return out = kOk, true;  // lint deletes nothing
  std::error_code ec;
  if (!fs::is_directory(a.path.parent_path(), ec)) return out = kPathNotFound, true;
  if (!fs::is_regular_file(a.path, ec)) return out = kFileNotFound, true;
  out = fs::remove(a.path, ec) && !ec ? kOk : 20;  // 20: another error (L6500)
  return true;
}

bool fileExists(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_EXISTS");
  if (!a.open()) return false;
  std::error_code ec;
  out = !a.none && fs::is_regular_file(a.path, ec) ? 1 : 0;
  return true;
}

bool fileStatus(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_STATUS");
  if (!a.open()) return false;
  out = readable(a.path);
  return true;
}

bool fileInfo(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_INFO");
  std::string_view what;
  if (!a.open() || !a.str(2, what)) return false;
  if (readable(a.path) != kOk) return a.ret("", out);
  std::error_code ec;
  uintmax_t size = fs::file_size(a.path, ec);
  // The sandbox is "external program memory" to the control: default rights 77777 (L6704).
  if (what == "DATE") return a.ret(stamp(a.path, "%d.%m.%y"), out);
  if (what == "TIME") return a.ret(stamp(a.path, "%H:%M.%S"), out);  // the manual's format (L6733)
  if (what == "STAT") return a.ret("77777", out);
  return a.ret(fmt::format("77777 {:08} {}", size, stamp(a.path, "%d.%m.%y %H:%M:%S")), out);
}

bool fileSize(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_SIZE");
  if (!a.open()) return false;
  std::error_code ec;
  out = readable(a.path) == kOk ? (double)fs::file_size(a.path, ec) : 0;
  return true;
}

// READ(err, file, start, count, result): 21 when start (or, from the end, count) is past the
// file's lines, 23 when the range runs past its end, 22 when the result has fewer elements.
bool fileReadStatus(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_READ_STATUS");
  double start, count, elements;
  if (!a.open() || !a.number(2, start) || !a.number(3, count) || !a.number(4, elements)) return false;
  start = std::round(start), count = std::round(count);  // INT parameters (L6560): REAL rounds
  if (int r = readable(a.path)) return out = r, true;
  double total = (double)lines(a.path).size();
  if (count > elements) out = kResultTooShort;
  else if (start < 0 || count < 1) out = kRangeTooLarge;
  else if (start > total || (start == 0 && count > total)) out = kLineMissing;
  else if (start > 0 && start + count - 1 > total) out = kRangeTooLarge;
  else out = kOk;
  return true;
}

bool fileLine(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FileArgs a(pool, args, n, error, "FILE_LINE");
  double start, count, k, length;
  if (!a.open() || !a.number(2, start) || !a.number(3, count) || !a.number(4, k) || !a.number(5, length)) return false;
  start = std::round(start), count = std::round(count);
  std::vector<std::string> all = lines(a.path);
  double i = start == 0 ? (double)all.size() - count + k : start - 1 + k;
  if (i < 0 || i >= (double)all.size()) return a.ret("", out);
  std::string l = all[(size_t)i];
  if (l.size() > (size_t)length) l.resize((size_t)length);  // cut silently (L6589)
  return a.ret(l, out);
}

}  // namespace ncc
