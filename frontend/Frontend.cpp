#include "frontend/Frontend.h"

#include "ir/AdemRecords.h"
#include "frontend/cldata/CldFrontend.h"
#include "frontend/heidenhain/HeiFrontend.h"
#include "frontend/iso/IsoFrontend.h"
#include "frontend/sinumerik/SinFrontend.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace ncc {

struct SourceKindInfo {
  SourceKind kind;
  const char *name;
  const char *extensions;  // space-separated, lower case
};
static const SourceKindInfo kKinds[] = {
    {SourceKind::ISO, "iso", ".nc .ngc .tap .cnc .iso .gcode .txt .i"},  // .i: ISO on a TNC
    {SourceKind::Sinumerik, "sinumerik", ".mpf .spf"},
    {SourceKind::Heidenhain, "heidenhain", ".h"},
    {SourceKind::CLData, "apt", ".cl .cls .apt .aptsource"},  // APT CL text (docs/APT.md); .cl before .cls: the first match counts
    {SourceKind::Adem, "adem", ".cld"},  // ADEM CLData, listing or binary (docs/CLDATA.md)
    {SourceKind::NCIR, "ncir", ".ncir"},
    {SourceKind::Motion, "motion", ".motion"},
};

const char *sourceKindName(SourceKind k) {
  for (auto &i : kKinds)
    if (i.kind == k) return i.name;
  return "unknown";
}

bool sourceKindFromName(std::string_view s, SourceKind &out) {
  if (s == "cldata") s = "apt";  // either CL format: the driver picks ADEM by the file's content
  for (auto &i : kKinds)
    if (s == i.name) {
      out = i.kind;
      return true;
    }
  return false;
}

// An ADEM listing: its first record (after `$$` comment lines) starts `[code]` or `<n>[code]`.
static bool looksLikeAdemListing(std::string_view head) {
  size_t i = 0;
  for (;;) {
    while (i < head.size() && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n')) ++i;
    if (head.substr(i, 2) != "$$") break;
    size_t nl = head.find('\n', i);
    if (nl == std::string_view::npos) return false;
    i = nl + 1;
  }
  while (i < head.size() && std::isdigit((unsigned char)head[i])) ++i;
  while (i < head.size() && head[i] == ' ') ++i;
  if (i >= head.size() || head[i] != '[') return false;
  size_t d = ++i;
  while (i < head.size() && std::isdigit((unsigned char)head[i])) ++i;
  return i > d && i < head.size() && head[i] == ']';
}

SourceKind detectSourceKind(const std::string &path, std::string_view text) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return (char)std::tolower(c); });
  if (!ext.empty())
    for (auto &i : kKinds) {
      std::string_view exts = i.extensions;
      size_t pos = exts.find(ext);
      if (pos != std::string_view::npos && (pos + ext.size() == exts.size() || exts[pos + ext.size()] == ' '))
        return i.kind;
    }
  std::string_view head = text.substr(0, 4096);
  if (cld::looksLikeAdemBinary(head) || looksLikeAdemListing(head)) return SourceKind::Adem;
  if (head.find("BEGIN PGM") != std::string_view::npos) return SourceKind::Heidenhain;
  if (head.rfind("module \"", 0) == 0) return SourceKind::NCIR;
  if (head.find("GOTO/") != std::string_view::npos || head.rfind("PARTNO", 0) == 0) return SourceKind::CLData;
  if (head.find("PROC ") != std::string_view::npos || head.find("DEF ") != std::string_view::npos)
    return SourceKind::Sinumerik;
  return SourceKind::ISO;
}

static iso::IsoOptions isoOptions(const FrontendOptions &o) {
  iso::IsoOptions io;
  io.decimalMode = o.decimalMode;
  io.blockDeleteMask = o.blockDeleteMask;
  io.searchDirs = o.searchDirs;
  io.linkedFunctions = o.linkedFunctions;
  io.axesScaleEnable = o.axesScaleEnable;
  io.scaleWeighting = o.scaleWeighting;
  io.startup = o.startup;
  io.offsetMemory = o.offsetMemory == "C" ? iso::OffsetMemory::C : iso::OffsetMemory::None;
  io.lathe = o.lathe;
  io.latheSystem = o.latheSystem;
  io.auxiliaryB = o.auxiliaryB;
  for (auto &c : o.macroCalls) {
    // "O0012" names program O12, as M98 P12 does; other names stay ("M6_MAKRO").
    std::string callee = c.program;
    size_t digits = callee.find_first_not_of('0', 1);
    if (callee.size() > 1 && callee[0] == 'O' && callee.find_first_not_of("0123456789", 1) == std::string::npos)
      callee = "O" + (digits == std::string::npos ? std::string("0") : callee.substr(digits));
    io.codeCalls.push_back({c.code[0], std::llround(std::stod(c.code.substr(1)) * 10), callee, c.subprogram});
  }
  return io;
}

static sin::SinOptions sinOptions(const FrontendOptions &o) {
  sin::SinOptions so;
  so.blockDeleteMask = o.blockDeleteMask;
  so.searchDirs = o.searchDirs;
  so.linkedFunctions = o.linkedFunctions;
  so.cycles = o.cycles;
  so.geoAxes = o.geoAxes;
  return so;
}

bool parseProgram(SourceKind kind, SourceManager &sm, uint32_t file, const FrontendOptions &opts,
                  Diagnostics &diags, ir::Module &out) {
  // The 808D's two languages (G290 Siemens mode, G291 ISO mode): each front end reads the
  // other's blocks through the other's block entry (frontend/ModeSwitch.h). A Siemens program
  // file starts in the machine's start-up mode.
  if (kind == SourceKind::Sinumerik && opts.startMode == "iso") kind = SourceKind::ISO;
  switch (kind) {
  case SourceKind::ISO: {
    iso::IsoOptions io = isoOptions(opts);
    sin::SinOptions so = sinOptions(opts);
    so.isoBlocks = [&diags, iso = io] { return iso::isoBlocks(iso, diags); };  // G291 in a Siemens-mode program it calls
    io.siemensBlocks = [&sm, &diags, so] { return sin::siemensBlocks(sm, so, diags); };
    return iso::parseIsoProgram(sm, file, io, diags, out);
  }
  case SourceKind::Sinumerik: {
    sin::SinOptions so = sinOptions(opts);
    so.isoBlocks = [&diags, io = isoOptions(opts)] { return iso::isoBlocks(io, diags); };
    return sin::parseSinumerikProgram(sm, file, so, diags, out);
  }
  case SourceKind::Heidenhain: {
    hei::HeiOptions ho;
    ho.searchDirs = opts.searchDirs;
    ho.linkedFunctions = opts.linkedFunctions;
    ho.cycles = opts.cycles;
    ho.probe = opts.probe;
    ho.toolNames = opts.toolNames;
    return hei::parseHeidenhainProgram(sm, file, ho, diags, out);
  }
  case SourceKind::CLData: return cld::parseAptProgram(sm, file, diags, out);
  case SourceKind::Adem: return cld::parseAdemProgram(sm, file, diags, out);
  case SourceKind::NCIR: return ir::parseModule(sm.text(file), file, sm, diags, out);
  case SourceKind::Motion:
    diags.error({}, fmt::format("{}: Motion IR text is an executed program without NC IR: only ncc run, ncc "
                                "translate and ncc compile --emit=motion read it",
                                sm.name(file)));
    return false;
  default:
    diags.error({}, fmt::format("{}: the {} front end is not implemented yet", sm.name(file), sourceKindName(kind)));
    return false;
  }
}

namespace {
class IsoStream : public BlockStream {
public:
  IsoStream(SourceManager &sm, uint32_t file, const iso::IsoOptions &o, Diagnostics &d) : s_(sm, file, o, d) {}
  bool next(ir::Region &out, size_t maxBlocks, CmdSink *lean) override { return s_.next(out, maxBlocks, lean); }

private:
  iso::IsoBlockStream s_;
};
}  // namespace

std::unique_ptr<BlockStream> openBlockStream(SourceKind kind, SourceManager &sm, uint32_t file,
                                             const FrontendOptions &opts, Diagnostics &diags) {
  // A code that calls a program needs the whole program (the callee, its nesting rule).
  if (kind == SourceKind::ISO && opts.macroCalls.empty() && iso::isoIsStreamable(sm.text(file), &sm, file))
    return std::make_unique<IsoStream>(sm, file, isoOptions(opts), diags);
  if (kind == SourceKind::Adem) return cld::openAdemStream(sm, file, diags);  // CLData has no control flow
  if (kind == SourceKind::CLData) return cld::openAptStream(sm, file, diags);  // nor has APT CL text
  return nullptr;
}

}  // namespace ncc
