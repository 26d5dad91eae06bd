// ncc-cld: converts ADEM CLData between its text listing and its binary record file, with the
// front end's own reader and code table (docs/CLDATA.md), so binary test files are made from
// listings anyone can read.
//   ncc-cld --binary LISTING -o FILE.cld     the listing as binary records
//   ncc-cld --listing FILE.cld [-o OUT]      any .cld (binary or listing) as a listing
#include "ir/AdemRecords.h"
#include "ir/Diagnostics.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace ncc;

int main(int argc, char **argv) {
  std::string mode, in, out;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--binary" || a == "--listing") mode = a;
    else if (a == "-o" && i + 1 < argc) out = argv[++i];
    else if (in.empty() && a[0] != '-') in = a;
    else mode.clear(), i = argc;
  }
  if (mode.empty() || in.empty() || (mode == "--binary" && out.empty())) {
    std::fprintf(stderr, "usage: ncc-cld --binary LISTING -o FILE.cld | ncc-cld --listing FILE.cld [-o OUT]\n");
    return 2;
  }
  SourceManager sm;
  uint32_t f = sm.addFile(in);
  if (!f) {
    std::fprintf(stderr, "ncc-cld: cannot read '%s'\n", in.c_str());
    return 1;
  }
  Diagnostics diags(sm);
  std::vector<cld::AdemError> errs;
  std::string_view text = sm.text(f);
  auto recs = cld::looksLikeAdemBinary(text) ? cld::readAdemBinary(text, f, errs) : cld::readAdemListing(text, f, errs);
  if (!cld::reportAdemErrors(diags, errs)) return 1;
  std::string data = mode == "--binary" ? cld::writeAdemBinary(recs) : cld::writeAdemListing(recs);
  if (out.empty()) return std::fwrite(data.data(), 1, data.size(), stdout) == data.size() ? 0 : 1;
  std::string err;
  if (!writeFileAtomic(out, data, err)) {
    std::fprintf(stderr, "ncc-cld: %s\n", err.c_str());
    return 1;
  }
  return 0;
}
