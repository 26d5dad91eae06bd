// Mode switching (G290/G291, frontend/ModeSwitch.h): the static modes the lowering follows, and
// the ISO-mode blocks of a Sinumerik program.
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Lower.h"

#include <fmt/format.h>

namespace ncc::iso {

void BlockLowerer::followMode(ModeValue m) {
  switch (modeValueInfo(m).group) {
  case ModeGroup::Units: units_ = m; break;
  case ModeGroup::FeedMode: feedMode_ = m; break;
  case ModeGroup::Plane: plane_ = m; break;
  case ModeGroup::Distance: distance_ = m; break;
  case ModeGroup::Motion:
    motion_ = m == ModeValue::CycleOff || m == ModeValue::CycleCancel ? pathMotion_ : m;
    if (isPathMotion(motion_)) pathMotion_ = motion_;
    break;
  default: break;
  }
}

namespace {

class IsoBlocks : public GuestBlocks {
public:
  IsoBlocks(const IsoOptions &opts, Diagnostics &diags)
      : opts_(opts), diags_(diags), parser_(diags, Flavour::Fanuc, opts_.blockDeleteMask, opts_.offsetMemory, opts_.lathe),
        lower_(opts_, Flavour::Fanuc, diags) {
    lower_.callsRefused = "is not available in the ISO-mode blocks of a Sinumerik program";
    lower_.callsRefusedRule = "mode-switch";
  }

  bool block(std::string_view line, uint32_t file, uint32_t lineNo, ir::Region &out) override {
    if (!lower_.optionsValid()) {
      diags_.error({file, lineNo, 1}, fmt::format("unknown decimal mode '{}' (calculator, is-b, is-c)", opts_.decimalMode),
                   "options");
      return false;
    }
    if (!parser_.parse(line, file, lineNo, b_)) return false;
    if (!b_.content || b_.percent) return true;
    if (b_.programNumber >= 0 || b_.stmt != StmtKind::None) {
      diags_.error(b_.loc,
                   b_.programNumber >= 0 ? "an O program number in the ISO-mode blocks of a Sinumerik program"
                                         : "control flow in the ISO-mode blocks of a Sinumerik program (the 808D's ISO "
                                           "mode has none: write it in Siemens mode)",
                   "mode-switch");
      return false;
    }
    out.push_back(lower_.blockOp(b_));
    lower_.lowerComments(b_, out);
    return lower_.lowerActions(b_, out);
  }

  bool leave(SourceLoc) override { return true; }  // ISO blocks open no structure here
  // A whole ISO-dialect program (Sinumerik ISOCALL, SIN-CAL-07) as function `name`: its blocks
  // as the ISO-mode blocks are (no calls, no control flow), M99 (or M17) returns.
  bool program(uint32_t file, const std::string &name) override {
    ir::Function fn;
    fn.name = name;
    fn.loc = {file, 1, 1};
    fn.dialect = ir::Dialect::ISO;
    std::string_view text = diags_.sources().text(file);
    bool good = true;
    uint32_t lineNo = 0;
    for (size_t pos = 0; pos <= text.size();) {
      size_t nl = text.find('\n', pos);
      if (nl == std::string_view::npos) nl = text.size();
      if (!block(text.substr(pos, nl - pos), file, ++lineNo, fn.body)) good = false;
      pos = nl + 1;
    }
    functions_.push_back(std::move(fn));
    return good;
  }
  bool finish(ir::Module &m) override {
    for (auto &f : functions_) m.functions.push_back(std::move(f));
    functions_.clear();
    return true;
  }
  void follow(ModeValue m) override { lower_.followMode(m); }

private:
  IsoOptions opts_;
  Diagnostics &diags_;
  BlockParser parser_;
  BlockLowerer lower_;
  ParsedBlock b_;
  std::vector<ir::Function> functions_;
};

}  // namespace

std::unique_ptr<GuestBlocks> isoBlocks(const IsoOptions &opts, Diagnostics &diags) {
  return std::make_unique<IsoBlocks>(opts, diags);
}

}  // namespace ncc::iso
