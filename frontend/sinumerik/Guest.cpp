// Mode switching (G290/G291, frontend/ModeSwitch.h): the static modes a function follows, and
// the Siemens-mode blocks of an ISO program.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

void FunctionParser::followMode(ModeValue m) {
  switch (modeValueInfo(m).group) {
  case ModeGroup::Plane:
    if (m != plane) poleKnown = apKnown = false;  // polar: PGsl
    plane = m;
    break;
  case ModeGroup::Motion:  // an ISO cycle cancel leaves a motion this front end cannot name
    motion = m == ModeValue::CycleCancel || m == ModeValue::CycleOff ? ModeValue::Count : m;
    break;
  case ModeGroup::Distance: distance = m; break;
  default: break;
  }
}

namespace {

class SiemensBlocks : public GuestBlocks {
public:
  SiemensBlocks(SourceManager &sm, const SinOptions &opts, Diagnostics &diags)
      : opts_(opts), pp_(sm, opts_, diags, scratch_) {
    opts_.macroArguments = true;
  }

  bool block(std::string_view line, uint32_t file, uint32_t lineNo, ir::Region &out) override {
    if (!fp_ || fp_->file != file) {  // a file's declarations (DEF) are its own
      fp_ = std::make_unique<FunctionParser>(pp_, file, "main", true);
      fp_->distance = ModeValue::Count;  // G90/G91 unknown until a block of the section sets it
      fp_->motion = ModeValue::Count;
      for (ModeValue m : pending_) fp_->followMode(m);
      pending_.clear();
    }
    pp_.modalCalls = pp_.modalCalls || mentionsMcall(line);
    // The ISO function's region is the base; structures the block opens stack on it.
    fp_->regions[0] = &out;
    ir::Region *at = &fp_->cur();
    size_t before = at->size(), depth = fp_->regions.size();
    if (!fp_->line(line, lineNo)) return false;
    // A line that opened or closed a structure (its region may be gone) holds no REPEAT or GOTOC.
    if (fp_->regions.size() != depth || &fp_->cur() != at) return true;
    // Section repetitions and GOTOC need the whole function's labels, which this front end
    // resolves at the end of its own files only.
    ir::Region &cur = *at;
    for (size_t i = before; i < cur.size(); ++i) {
      const ir::Expr *text = cur[i].kind == ir::OpKind::Comment ? cur[i].get("text") : nullptr;
      if (cur[i].kind != ir::OpKind::CallSection && !(text && text->str == "GOTOC")) continue;
      pp_.error(cur[i].loc,
                fmt::format("{} in the Siemens-mode blocks of an ISO program is not supported",
                            text ? "GOTOC" : "REPEAT (a section repetition)"),
                "unsupported-code");
      cur.erase(cur.begin() + (long)before, cur.end());  // no later error about its target
      return false;
    }
    return true;
  }

  bool leave(SourceLoc at) override {
    if (!fp_ || fp_->ctl.empty()) return true;
    static const char *kOpen[] = {"IF", "IF … ELSE", "WHILE", "FOR", "LOOP", "REPEAT"};
    for (auto &c : fp_->ctl)
      pp_.error(c.loc, fmt::format("{} is still open when Siemens mode ends (line {})", kOpen[(int)c.kind], at.line),
                "loop-mismatch");
    fp_->ctl.clear();
    fp_->regions.resize(1);
    return false;
  }

  void follow(ModeValue m) override {
    if (fp_) fp_->followMode(m);
    else pending_.push_back(m);
  }

  bool program(uint32_t file, const std::string &name) override {
    FunctionParser fp(pp_, file, name, false);
    bool good = fp.run();
    fp.fn.dialect = ir::Dialect::Sinumerik;
    pp_.done.push_back(std::move(fp.fn));
    return good;
  }

  bool finish(ir::Module &m) override {
    if (pp_.polar && !m.functions.empty()) declarePolarState(m.functions[0].body);
    if (pp_.globalR && !m.functions.empty()) declareGlobalR(m.functions[0].body);
    if (pp_.retTargets && !m.functions.empty()) declareReturnTargets(m.functions[0].body);
    if (pp_.namedSections && !m.functions.empty()) declareNamedSections(m.functions[0].body);
    for (auto &f : pp_.done) {
      f.dialect = ir::Dialect::Sinumerik;
      m.functions.push_back(std::move(f));
    }
    pp_.done.clear();
    if (pp_.isoGuest && !pp_.isoGuest->finish(m)) return false;
    return pp_.ok;
  }

private:
  SinOptions opts_;
  ir::Module scratch_;
  ProgramParser pp_;
  std::unique_ptr<FunctionParser> fp_;
  std::vector<ModeValue> pending_;
};

}  // namespace

std::unique_ptr<GuestBlocks> siemensBlocks(SourceManager &sm, const SinOptions &opts, Diagnostics &diags) {
  return std::make_unique<SiemensBlocks>(sm, opts, diags);
}

}  // namespace ncc::sin
