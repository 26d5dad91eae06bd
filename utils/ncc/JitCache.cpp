#include "utils/ncc/JitCache.h"

#include "utils/ncc/AotRun.h"
#include "utils/ncc/ExeLink.h"
#include "utils/ncc/JitLoader.h"
#include "utils/ncc/ObjectLoader.h"

#include <fmt/format.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

namespace ncc::driver {

namespace fs = std::filesystem;

std::string cacheDirectory() {
  if (const char *d = std::getenv("NCC_CACHE_DIR"); d && *d) return d;
  if (const char *d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::string(d) + "/ncc";
  if (const char *d = std::getenv("HOME"); d && *d) return std::string(d) + "/.cache/ncc";
  return {};
}

uintmax_t cacheLimitBytes() {
  const char *mb = std::getenv("NCC_CACHE_MAX_MB");
  uintmax_t n = mb && *mb ? std::strtoull(mb, nullptr, 10) : 64;
  return n << 20;
}

// This build of ncc: the binary and the JIT module by size and modification time, so that a
// rebuilt code generator never meets an object of its predecessor.
static std::string buildId() {
  std::string id = fmt::format("{} abi {:x} jit {:x}", ncrt_version(), ncrt::abiFingerprint(), jit::jitApiStamp());
  std::vector<std::string> files{"/proc/self/exe"};
  for (const std::string &dir : nccLibraryDirs()) files.push_back(dir + "/ncc/libncc-jit.so");
  for (const std::string &f : files) {
    struct stat st;
    if (stat(f.c_str(), &st) == 0)
      id += fmt::format(" {}:{}:{}.{}", f, (long long)st.st_size, (long long)st.st_mtim.tv_sec, st.st_mtim.tv_nsec);
  }
  return id;
}

// Everything that changes the generated code: the build, the machine description (the front end
// reads with its settings), the options that reach the front end, and every file the load read
// (program, subprograms, linked files) by name and text.
static bool cacheKey(Session &s, std::string &key) {
  std::string text = buildId();
  std::string machine;
  if (!readMachineText(s.opts.machine, machine)) return false;
  text += fmt::format("\nmachine {} {}\n{}", s.opts.machine, machine.size(), machine);
  text += fmt::format("\ndialect {} decimal {} delete {} include {} link {}", s.opts.dialect, s.opts.decimalMode,
                      fmt::join(s.opts.blockDelete, ","), fmt::join(s.opts.includeDirs, "\x1f"),
                      fmt::join(s.opts.linkFiles, "\x1f"));
  text += fmt::format("\nmain {}", s.mainFile);
  for (uint32_t f = 1; f <= s.sm.fileCount(); ++f)
    text += fmt::format("\nfile {} {}\n{}", s.sm.name(f), s.sm.text(f).size(), s.sm.text(f));
  // Two FNV-1a hashes (the second over a salted text): 128 bits name the entry.
  key = fmt::format("{:016x}{:016x}", ncrt::textHash(text), ncrt::textHash("ncc-cache\n" + text));
  return true;
}

// Removes the least recently used entries (a hit refreshes an entry's time) beyond the limit.
static void evict(const std::string &dir, uintmax_t limit) {
  struct Entry {
    fs::file_time_type time;
    uintmax_t size;
    fs::path path;
  };
  std::vector<Entry> entries;
  uintmax_t total = 0;
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    if (it->path().extension() != ".o") continue;
    std::error_code e1, e2;
    Entry e{it->last_write_time(e1), it->file_size(e2), it->path()};
    if (e1 || e2) continue;  // removed by another run meanwhile
    total += e.size;
    entries.push_back(std::move(e));
  }
  if (total <= limit) return;
  std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) { return a.time < b.time; });
  for (const Entry &e : entries) {
    if (total <= limit) break;
    fs::remove(e.path, ec);
    total -= e.size;
  }
}

// Whether LLVM is in this process (a hit must not load it; the tests check it here).
static bool llvmMapped() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find("libLLVM") != std::string::npos) return true;
  return false;
}

static void report(const Session &s, const std::string &what, const std::string &path) {
  if (s.opts.cacheStats)
    std::fprintf(stderr, "ncc: jit cache: %s %s (LLVM %s)\n", what.c_str(), path.c_str(),
                 llvmMapped() ? "loaded" : "not loaded");
}

// The loaded object's entry; null with the reason in err.
static ncrt_entry entryOf(const std::unique_ptr<LoadedObject> &obj, std::string &err) {
  if (!obj) return nullptr;
  auto entry = reinterpret_cast<ncrt_entry>(const_cast<void *>(obj->symbol("ncc_program_main")));
  if (!entry) err = "no ncc_program_main";
  return entry;
}

// Compiles `m` into the cache entry `path` at optLevel and loads it; null when that fails (the
// reason reported with --cache-stats): the caller runs without the cache.
static std::unique_ptr<LoadedObject> store(Session &s, const ir::Module &m, const jit::JitApi &jit,
                                           const std::string &dir, const std::string &path, int optLevel) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  ncrt::ProgramInfo info;
  // A cache folder that cannot be written (read-only, not a folder): run as without a cache.
  if (!fs::is_directory(dir, ec) || access(dir.c_str(), W_OK) != 0 || !programInfo(s, s.mainFile ? s.mainFile : 1, info))
    return nullptr;
  // A store that fails (a full disk, …) is not the program's error: run as without a cache.
  Diagnostics storeDiags(s.diags.sources());
  storeDiags.setCollect(true);
  if (!jit.emitObject(m, path, storeDiags, info, optLevel)) {
    report(s, "cannot store the object, running without the cache:", path);
    return nullptr;
  }
  std::string err;
  std::unique_ptr<LoadedObject> obj = LoadedObject::load(path, err);
  if (!entryOf(obj, err)) {  // an object the loader refuses: run in the JIT as without a cache
    report(s, "cannot load the stored object (" + err + "):", path);
    return nullptr;
  }
  evict(dir, cacheLimitBytes());
  return obj;
}

// Whether a loop of `m` visibly runs hot: a while condition or loop count that holds a literal of
// at least NCRT_POLL_INTERVAL, or a plain variable the program assigns such a literal (Macro B's
// `#1=1000000 … WHILE [#2 LT #1]`). Such a program is compiled at O2 at once, not twice.
namespace {
struct HotScan {
  std::set<std::string> bigVars;  // plain variables assigned a literal >= NCRT_POLL_INTERVAL
  bool hot = false;
  // A variable with a constant name and index (`#1` is space Numbered with index 1): its key, else "".
  static std::string key(const ir::Expr &v) {
    if (v.kind != ir::ExprKind::Var || v.args.size() > 1) return {};
    if (v.args.size() == 1 && (!v.args[0] || v.args[0]->kind != ir::ExprKind::Number)) return {};
    return fmt::format("{}:{}:{}", (int)v.space, v.str, v.args.empty() ? 0.0 : v.args[0]->num);
  }
  static bool big(const ir::Expr &e) { return e.kind == ir::ExprKind::Number && e.num >= NCRT_POLL_INTERVAL; }
  void assigns(const ir::Region &r) {
    for (const ir::Op &op : r) {
      const ir::Expr *t = op.get("target"), *v = op.get("value");
      if (op.kind == ir::OpKind::Assign && t && v && big(*v) && !key(*t).empty()) bigVars.insert(key(*t));
      for (const ir::Region &sub : op.regions) assigns(sub);
    }
  }
  bool bound(const ir::Expr &e) const {
    if (big(e) || (!key(e).empty() && bigVars.count(key(e)))) return true;
    for (const ir::ExprPtr &a : e.args)
      if (a && bound(*a)) return true;
    return false;
  }
  void loops(const ir::Region &r) {
    for (const ir::Op &op : r) {
      const ir::Expr *b = op.kind == ir::OpKind::While ? op.get("cond") : op.kind == ir::OpKind::Loop ? op.get("count") : nullptr;
      if (b && bound(*b)) hot = true;
      for (const ir::Region &sub : op.regions) loops(sub);
    }
  }
};
}  // namespace

static bool looksHot(const ir::Module &m) {
  HotScan scan;
  for (const ir::Function &f : m.functions) scan.assigns(f.body);
  for (const ir::Function &f : m.functions) scan.loops(f.body);
  return scan.hot;
}

// Two tiers: a program is first compiled without optimisation (`<key>.quick.o`, a quarter of the
// O2 compile time, which is most of a short program's run) unless it looks hot; a run of that code
// that turns out hot (NCRT_POLL_INTERVAL loop iterations or backward jumps) compiles it again at O2
// (`<key>.o`), which later runs use.
bool runCached(Session &s, const ir::Module &m, CmdSink &sink, bool &ok) {
  std::string dir = s.opts.noCache ? std::string() : cacheDirectory();
  std::string key;
  if (dir.empty() || !cacheKey(s, key)) return false;
  const std::string optimised = dir + "/" + key + ".o", quick = dir + "/" + key + ".quick.o";
  std::string err, path;
  std::unique_ptr<LoadedObject> obj;
  std::error_code ec;
  for (const std::string &p : {optimised, quick}) {
    if (obj || !fs::exists(p, ec)) continue;
    obj = LoadedObject::load(p, err);
    if (entryOf(obj, err)) {
      fs::last_write_time(p, fs::file_time_type::clock::now(), ec);  // recently used
      report(s, "hit", p);
      path = p;
    } else {
      report(s, "damaged entry, compiling again (" + err + "):", p);
      obj.reset();
    }
  }
  if (!obj) {
    const jit::JitApi *jit = jitBackend(s.diags);
    std::string why;
    if (!jit || !jit->compilesQuickly(m, why)) return false;  // the caller reports / uses the eval engine
    path = looksHot(m) ? optimised : quick;
    obj = store(s, m, *jit, dir, path, path == optimised ? 2 : 0);
    if (!obj) return false;
    report(s, "miss, stored", path);
  }
  bool hot = false;
  ok = ncrt::runEntry(entryOf(obj, err), sink, s.diags, s.opts.limits, &hot);
  if (ok && hot && path == quick) {
    obj.reset();
    const jit::JitApi *jit = jitBackend(s.diags);
    if (jit && store(s, m, *jit, dir, optimised, 2)) {
      fs::remove(quick, ec);
      report(s, "hot, optimised", optimised);
    }
  }
  return true;
}

}  // namespace ncc::driver
