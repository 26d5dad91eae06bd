// A small static linker for one relocatable object: lays out its allocated sections in one
// mapping (code, then call stubs; data, then GOT slots), resolves its undefined symbols against
// the runtime table and the process, applies the x86-64 relocations LLVM emits for PIC code and
// seals the code read+execute. Every offset and index of the file is checked before use.
#include "utils/ncc/ObjectLoader.h"

#include "runtime/ncrt.h"

#include <fmt/format.h>

#include <dlfcn.h>
#include <elf.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace ncc::driver {

struct LoadedObject::Impl {
  void *base = MAP_FAILED;
  size_t size = 0;
  std::map<std::string, std::pair<const void *, size_t>, std::less<>> defined;
  ~Impl() {
    if (base != MAP_FAILED) munmap(base, size);
  }
};

LoadedObject::LoadedObject(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LoadedObject::~LoadedObject() = default;

const void *LoadedObject::symbol(const std::string &name, size_t *size) const {
  auto it = impl_->defined.find(name);
  if (it == impl_->defined.end()) return nullptr;
  if (size) *size = it->second.second;
  return it->second.first;
}

bool isObjectFile(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  char magic[SELFMAG] = {};
  return in.read(magic, SELFMAG) && !std::memcmp(magic, ELFMAG, SELFMAG);
}

namespace {

// An indirect jump through the 8 bytes that follow it: a call to a function anywhere in the
// address space (the runtime lives in the ncc binary, libc further away than ±2 GB).
constexpr size_t kStubSize = 16;
constexpr unsigned char kStubCode[6] = {0xff, 0x25, 0, 0, 0, 0};  // jmp *0(%rip)

class Linker {
public:
  Linker(const std::string &file, std::string &err) : file_(file), err_(err) {}

  std::unique_ptr<LoadedObject::Impl> link() {
    if (!readHeaders() || !layOut() || !resolveSymbols() || !relocate()) return nullptr;
    if (mprotect(impl_->base, codeSize_, PROT_READ | PROT_EXEC) != 0) return fail("cannot make its code executable");
    return std::move(impl_);
  }

private:
  const std::string &file_;
  std::string &err_;
  std::unique_ptr<LoadedObject::Impl> impl_ = std::make_unique<LoadedObject::Impl>();
  Elf64_Ehdr eh_{};
  std::vector<Elf64_Shdr> sh_;
  std::vector<uint64_t> sectionAddr_;  // 0: not loaded
  std::vector<Elf64_Sym> syms_;
  std::vector<uint64_t> symAddr_;
  uint32_t symtab_ = 0;
  size_t codeSize_ = 0, stubs_ = 0, got_ = 0;

  std::nullptr_t fail(const std::string &why) {
    err_ = why;
    return nullptr;
  }
  bool bad(const std::string &why) {
    err_ = "it is not a valid object file (" + why + ")";
    return false;
  }
  bool inFile(uint64_t off, uint64_t n) const { return off <= file_.size() && n <= file_.size() - off; }
  const char *name(uint32_t strtab, uint32_t off) const {
    const Elf64_Shdr &s = sh_[strtab];
    if (off >= s.sh_size) return "";
    const char *p = file_.data() + s.sh_offset + off;
    return std::memchr(p, 0, s.sh_size - off) ? p : "";
  }

  bool readHeaders() {
    if (file_.size() < sizeof eh_ || std::memcmp(file_.data(), ELFMAG, SELFMAG)) return bad("no ELF header");
    std::memcpy(&eh_, file_.data(), sizeof eh_);
    if (eh_.e_ident[EI_CLASS] != ELFCLASS64 || eh_.e_ident[EI_DATA] != ELFDATA2LSB || eh_.e_machine != EM_X86_64)
      return (err_ = fmt::format("it is an object for another machine (ELF machine {}); this ncc runs x86-64 objects",
                                 eh_.e_machine)),
             false;
    if (eh_.e_type != ET_REL) return (err_ = "it is not a relocatable object (ncc compile --emit=obj writes those)"), false;
    if (eh_.e_shentsize != sizeof(Elf64_Shdr) || eh_.e_shnum == 0 || !inFile(eh_.e_shoff, (uint64_t)eh_.e_shnum * sizeof(Elf64_Shdr)))
      return bad("section headers");
    sh_.resize(eh_.e_shnum);
    std::memcpy(sh_.data(), file_.data() + eh_.e_shoff, sh_.size() * sizeof(Elf64_Shdr));
    for (size_t i = 0; i < sh_.size(); ++i) {
      const Elf64_Shdr &s = sh_[i];
      if (s.sh_type != SHT_NOBITS && s.sh_type != SHT_NULL && !inFile(s.sh_offset, s.sh_size))
        return bad(fmt::format("section {} lies outside the file", i));
      if (s.sh_type == SHT_SYMTAB) {
        if (symtab_) return bad("two symbol tables");
        symtab_ = (uint32_t)i;
      }
      if (s.sh_addralign > 4096 || (s.sh_addralign & (s.sh_addralign - 1))) return bad("section alignment");
    }
    if (!symtab_) return bad("no symbol table");
    const Elf64_Shdr &st = sh_[symtab_];
    if (st.sh_entsize != sizeof(Elf64_Sym) || st.sh_link == 0 || st.sh_link >= sh_.size() ||
        sh_[st.sh_link].sh_type != SHT_STRTAB || eh_.e_shstrndx >= sh_.size() ||
        sh_[eh_.e_shstrndx].sh_type != SHT_STRTAB)
      return bad("string tables");
    syms_.resize(st.sh_size / sizeof(Elf64_Sym));
    std::memcpy(syms_.data(), file_.data() + st.sh_offset, syms_.size() * sizeof(Elf64_Sym));
    return true;
  }

  // Sections the program needs at run time: allocated ones except the unwind tables (nothing
  // unwinds through compiled NC code).
  bool loadable(const Elf64_Shdr &s) const {
    return (s.sh_flags & SHF_ALLOC) && s.sh_type != SHT_X86_64_UNWIND &&
           std::strcmp(name(eh_.e_shstrndx, s.sh_name), ".eh_frame") != 0;
  }

  bool layOut() {
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    sectionAddr_.assign(sh_.size(), 0);
    std::vector<uint64_t> offset(sh_.size(), 0);
    uint64_t at = 0;
    auto place = [&](bool code) {
      for (size_t i = 0; i < sh_.size(); ++i) {
        const Elf64_Shdr &s = sh_[i];
        if (!loadable(s) || ((s.sh_flags & SHF_EXECINSTR) != 0) != code) continue;
        uint64_t align = s.sh_addralign ? s.sh_addralign : 1;
        at = (at + align - 1) / align * align;
        offset[i] = at;
        at += s.sh_size;
      }
    };
    for (auto &s : sh_)
      if ((s.sh_flags & SHF_ALLOC) && (s.sh_flags & SHF_TLS)) return (err_ = "it uses thread-local storage"), false;
      else if (s.sh_type == SHT_INIT_ARRAY || s.sh_type == SHT_FINI_ARRAY || s.sh_type == SHT_REL)
        return bad("constructors or REL relocations, which ncc does not emit");
    place(true);
    at = (at + 15) / 16 * 16;
    stubs_ = at;
    at += syms_.size() * kStubSize;
    codeSize_ = (at + page - 1) / page * page;
    at = codeSize_;
    place(false);
    at = (at + 7) / 8 * 8;
    got_ = at;
    at += syms_.size() * 8;
    impl_->size = (at + page - 1) / page * page;
    if (at > (1ull << 30)) return bad("too large");
    impl_->base = mmap(nullptr, impl_->size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (impl_->base == MAP_FAILED) return (err_ = "cannot map memory for it"), false;
    auto *base = static_cast<unsigned char *>(impl_->base);
    for (size_t i = 0; i < sh_.size(); ++i) {
      if (!loadable(sh_[i])) continue;
      sectionAddr_[i] = (uint64_t)(base + offset[i]);
      if (sh_[i].sh_type != SHT_NOBITS) std::memcpy(base + offset[i], file_.data() + sh_[i].sh_offset, sh_[i].sh_size);
    }
    return true;
  }

  bool resolveSymbols() {
    static const std::unordered_map<std::string_view, void *> runtime = [] {
      std::unordered_map<std::string_view, void *> m;
      for (auto &s : ncrt::runtimeSymbols()) m.emplace(s.name, s.address);
      return m;
    }();
    symAddr_.assign(syms_.size(), 0);
    uint32_t strtab = sh_[symtab_].sh_link;
    for (size_t i = 1; i < syms_.size(); ++i) {
      const Elf64_Sym &s = syms_[i];
      std::string nm = name(strtab, s.st_name);
      if (s.st_shndx == SHN_UNDEF && nm == "_GLOBAL_OFFSET_TABLE_") {
        symAddr_[i] = gotBase();  // the large code model's GOT-relative addressing
      } else if (s.st_shndx == SHN_UNDEF) {
        auto it = runtime.find(nm);
        void *p = it != runtime.end() ? it->second : dlsym(RTLD_DEFAULT, nm.c_str());
        if (!p) return (err_ = fmt::format("it needs '{}', which this ncc's runtime does not provide", nm)), false;
        symAddr_[i] = (uint64_t)p;
      } else if (s.st_shndx == SHN_ABS) {
        symAddr_[i] = s.st_value;
      } else if (s.st_shndx >= SHN_LORESERVE || s.st_shndx >= sh_.size()) {
        return bad(fmt::format("symbol '{}' in section {:#x}", nm, s.st_shndx));
      } else if (sectionAddr_[s.st_shndx]) {
        if (s.st_value > sh_[s.st_shndx].sh_size) return bad(fmt::format("symbol '{}' outside its section", nm));
        symAddr_[i] = sectionAddr_[s.st_shndx] + s.st_value;
        if (ELF64_ST_BIND(s.st_info) != STB_LOCAL && !nm.empty())
          impl_->defined[nm] = {(const void *)symAddr_[i], (size_t)s.st_size};
      }
    }
    return true;
  }

  // The address a call may reach an undefined symbol through: a stub beside the code.
  uint64_t stub(size_t sym) {
    auto *p = static_cast<unsigned char *>(impl_->base) + stubs_ + sym * kStubSize;
    std::memcpy(p, kStubCode, sizeof kStubCode);
    std::memcpy(p + sizeof kStubCode, &symAddr_[sym], 8);
    return (uint64_t)p;
  }
  uint64_t gotSlot(size_t sym) {
    auto *p = static_cast<unsigned char *>(impl_->base) + got_ + sym * 8;
    std::memcpy(p, &symAddr_[sym], 8);
    return (uint64_t)p;
  }
  uint64_t gotBase() const { return (uint64_t)impl_->base + got_; }

  bool relocate() {
    for (size_t r = 0; r < sh_.size(); ++r) {
      const Elf64_Shdr &rs = sh_[r];
      if (rs.sh_type != SHT_RELA) continue;
      if (rs.sh_info >= sh_.size() || !sectionAddr_[rs.sh_info]) continue;  // relocates a section not loaded
      if (rs.sh_link != symtab_ || rs.sh_entsize != sizeof(Elf64_Rela)) return bad("relocation section");
      const Elf64_Shdr &target = sh_[rs.sh_info];
      for (uint64_t k = 0; k < rs.sh_size / sizeof(Elf64_Rela); ++k) {
        Elf64_Rela rel;
        std::memcpy(&rel, file_.data() + rs.sh_offset + k * sizeof rel, sizeof rel);
        if (!apply(rel, target, sectionAddr_[rs.sh_info])) return false;
      }
    }
    return true;
  }

  bool apply(const Elf64_Rela &rel, const Elf64_Shdr &target, uint64_t targetAddr) {
    uint32_t type = ELF64_R_TYPE(rel.r_info);
    size_t sym = ELF64_R_SYM(rel.r_info);
    if (sym >= syms_.size()) return bad("relocation symbol");
    const Elf64_Sym &s = syms_[sym];
    bool undefined = s.st_shndx == SHN_UNDEF;
    if (sym && !undefined && s.st_shndx < sh_.size() && s.st_shndx < SHN_LORESERVE && !sectionAddr_[s.st_shndx])
      return bad("a relocation against a section that is not loaded");
    uint64_t S = symAddr_[sym], P = targetAddr + rel.r_offset;
    int64_t A = rel.r_addend;
    bool wide = type == R_X86_64_64 || type == R_X86_64_PC64 || type == R_X86_64_GOT64 || type == R_X86_64_GOTOFF64 ||
                type == R_X86_64_GOTPC64;
    unsigned width = wide ? 8 : 4;
    if (type == R_X86_64_NONE) return true;
    if (rel.r_offset > target.sh_size || target.sh_size - rel.r_offset < width) return bad("relocation offset");
    auto put32 = [&](int64_t v, bool isSigned) {
      bool fits = isSigned ? v == (int64_t)(int32_t)v : (uint64_t)v == (uint32_t)v;
      if (!fits) return (err_ = fmt::format("a relocation (type {}) is out of range", type)), false;
      uint32_t u = (uint32_t)v;
      std::memcpy((void *)P, &u, 4);
      return true;
    };
    auto put64 = [&](uint64_t v) {
      std::memcpy((void *)P, &v, 8);
      return true;
    };
    switch (type) {
    case R_X86_64_64:
      return put64(S + A);
    case R_X86_64_PC64:
    case R_X86_64_GOTPC64:  // S is the GOT
      return put64(S + A - P);
    case R_X86_64_GOTOFF64:
      return put64(S + A - gotBase());
    case R_X86_64_GOT64:
      return put64(gotSlot(sym) - gotBase() + A);
    case R_X86_64_PC32:
    case R_X86_64_PLT32:
      return put32((int64_t)((undefined && type == R_X86_64_PLT32 ? stub(sym) : S) + A - P), true);
    case R_X86_64_GOTPCREL:
    case R_X86_64_GOTPCRELX:
    case R_X86_64_REX_GOTPCRELX:
      return put32((int64_t)(gotSlot(sym) + A - P), true);
    case R_X86_64_32:
      return put32((int64_t)(S + A), false);
    case R_X86_64_32S:
      return put32((int64_t)(S + A), true);
    default:
      err_ = fmt::format("it has a relocation of type {}, which this loader does not handle", type);
      return false;
    }
  }
};

}  // namespace

std::unique_ptr<LoadedObject> LoadedObject::load(const std::string &path, std::string &err) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    err = "cannot read it";
    return nullptr;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string bytes = ss.str();
  if (bytes.compare(0, SELFMAG, ELFMAG) == 0 && !ncrt::hasObjectTrailer(bytes)) {
    err = "it is damaged or was not written by ncc compile --emit=obj (its checksum does not match)";
    return nullptr;
  }
  auto impl = Linker(bytes, err).link();
  if (!impl) return nullptr;
  return std::unique_ptr<LoadedObject>(new LoadedObject(std::move(impl)));
}

}  // namespace ncc::driver
