// Loads an object file from `ncc compile --emit=obj` into memory and links it against the
// runtime in this process (runtime/ncrt.h runtimeSymbols, then libc/libm), without LLVM: what
// `ncc run prog.o` starts with. x86-64 ELF relocatable objects only (what ncc emits on this
// host); anything else, or a malformed file, is an error with the reason, never a crash.
#pragma once
#include <cstddef>
#include <memory>
#include <string>

namespace ncc::driver {

class LoadedObject {
public:
  // Null with the reason in err.
  static std::unique_ptr<LoadedObject> load(const std::string &path, std::string &err);
  ~LoadedObject();
  // A symbol the object defines (null when none), and its size.
  const void *symbol(const std::string &name, size_t *size = nullptr) const;

  struct Impl;

private:
  explicit LoadedObject(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// True when the file starts with the ELF magic: `ncc run` then loads it instead of parsing it.
bool isObjectFile(const std::string &path);

}  // namespace ncc::driver
