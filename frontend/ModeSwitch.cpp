#include "frontend/ModeSwitch.h"

#include <fmt/format.h>

#include <cctype>
#include <string>

namespace ncc {

namespace {

// The G290/G291 of one source line, read outside comments.
struct SwitchWord {
  bool found = false;
  Language to = Language::Iso;
  uint32_t col = 0;
  uint32_t otherCol = 0;  // another word in the block (0: none)
  uint32_t startCol = 0;  // the block's first character
  int64_t n = -1;         // its block number
  std::string label;      // a Siemens label before the switch (`label_end: G290`), upper case
  uint32_t labelCol = 0;
};

bool wordChar(char c) { return std::isalnum((unsigned char)c) || c == '_' || c == '$'; }

SwitchWord findSwitch(std::string_view s, unsigned mask) {
  SwitchWord w;
  size_t i = s.find_first_not_of(" \t\r");
  if (i == std::string_view::npos) return w;
  if (s[i] == '/') {  // block skip: an active level leaves the line out (the host skips it)
    int level = 0;
    if (++i < s.size() && std::isdigit((unsigned char)s[i])) level = s[i++] - '0';
    if (mask & (1u << level)) return w;
  }
  i = s.find_first_not_of(" \t\r", i);
  if (i == std::string_view::npos) return w;
  w.startCol = (uint32_t)i + 1;
  // The block number: N10 or (Siemens main block) :10.
  if ((s[i] == 'N' || s[i] == 'n' || s[i] == ':') && i + 1 < s.size() && std::isdigit((unsigned char)s[i + 1]))
    for (w.n = 0, ++i; i < s.size() && std::isdigit((unsigned char)s[i]) && w.n < (int64_t)1e15;)
      w.n = w.n * 10 + (s[i++] - '0');
  int depth = 0;
  for (; i < s.size(); ++i) {
    char c = s[i];
    if (c == ';') break;  // a comment to the end of the line (both languages)
    if (c == '(') ++depth;
    if (depth) {
      if (c == ')') --depth;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') continue;
    bool isSwitch = (c == 'G' || c == 'g') && s.substr(i + 1, 2) == "29" &&
                    i + 3 < s.size() && (s[i + 3] == '0' || s[i + 3] == '1') &&
                    (i + 4 == s.size() || (!std::isdigit((unsigned char)s[i + 4]) && s[i + 4] != '.'));
    if (isSwitch && !w.found) {
      w.found = true;
      w.to = s[i + 3] == '0' ? Language::Siemens : Language::Iso;
      w.col = (uint32_t)i + 1;
      i += 3;
      continue;
    }
    // The rest of this word: a name (CDON, R1, MYVAR) or an address letter and its digits
    // (X1G291 is two ISO words).
    size_t start = i;
    bool name = std::isalpha((unsigned char)c) && i + 1 < s.size() && (std::isalpha((unsigned char)s[i + 1]) || s[i + 1] == '_');
    if (name || c == '$' || c == '_')
      while (i + 1 < s.size() && wordChar(s[i + 1])) ++i;
    else if (std::isalpha((unsigned char)c))
      while (i + 1 < s.size() && (std::isdigit((unsigned char)s[i + 1]) || s[i + 1] == '.')) ++i;
    // A Siemens label first in the block (after the number) is no word: `N4000 label_end: G290`
    // (seed001 L9984).
    if (name && w.label.empty() && !w.found && !w.otherCol && i + 1 < s.size() && s[i + 1] == ':') {
      for (size_t k = start; k <= i; ++k) w.label += (char)std::toupper((unsigned char)s[k]);
      w.labelCol = (uint32_t)start + 1;
      ++i;
      continue;
    }
    if (!w.otherCol) w.otherCol = (uint32_t)start + 1;
  }
  return w;
}

const char *modeName(Language l) { return l == Language::Siemens ? "Siemens mode (G290)" : "ISO mode (G291)"; }

}  // namespace

void forEachMode(const ir::Region &r, size_t from, const std::function<void(ModeValue)> &f) {
  for (size_t i = from; i < r.size(); ++i) {
    const ir::Op &op = r[i];
    if (op.kind == ir::OpKind::Mode)
      for (auto &a : op.args) {
        ModeValue m;
        if (a.value && a.value->kind == ir::ExprKind::Symbol && modeValueFromName(a.value->str, m)) f(m);
      }
    for (auto &sub : op.regions) forEachMode(sub, 0, f);
  }
}

MixedProgram::MixedProgram(Language host, GuestFactory guest, unsigned blockDeleteMask, Diagnostics &diags)
    : host_(host), mode_(host), factory_(std::move(guest)), mask_(blockDeleteMask), diags_(diags) {}
MixedProgram::~MixedProgram() = default;

// The modes of the ops written since the mark (the whole region when the section began in
// another one: a structure of the host opened or closed in between).
void MixedProgram::follow(const ir::Region &out, const std::function<void(ModeValue)> &f) {
  forEachMode(out, mark_ == &out ? markAt_ : 0, f);
}

bool MixedProgram::take(std::string_view line, uint32_t file, uint32_t lineNo, ir::Region &out, bool &ok,
                        const std::function<void(ModeValue)> &hostFollow) {
  // Most lines of the host's mode name no G290/G291: one search for "29" clears them.
  if (mode_ == host_ && line.find("29") == std::string_view::npos) return false;
  SwitchWord w = findSwitch(line, mask_);
  if (w.found && w.otherCol) {
    diags_.error({file, lineNo, w.otherCol},
                 fmt::format("G29{} must stand in a block of its own: ISO and Siemens language cannot be mixed in one block",
                             w.to == Language::Siemens ? 0 : 1),
                 "mode-switch");
    ok = false;
    return true;
  }
  if (w.found) {
    // The switch is a block of its own (its number and label can be jumped to; the label
    // before the block op, as the Sinumerik front end puts it).
    if (!w.label.empty()) {
      ir::Op label(ir::OpKind::Label, {file, lineNo, w.labelCol});
      label.set("name", ir::Expr::string(w.label, label.loc));
      out.push_back(std::move(label));
    }
    ir::Op block(ir::OpKind::Block, {file, lineNo, w.startCol});
    if (w.n >= 0) block.set("n", ir::Expr::number((double)w.n, ir::Type::Int, block.loc));
    out.push_back(std::move(block));
    if (w.to == mode_) return true;  // the mode already active: nothing changes
    if (!factory_) {
      diags_.error({file, lineNo, w.col}, fmt::format("{} is not available in this program", modeName(w.to)),
                   "mode-switch");
      ok = false;
      return true;
    }
    guest();
    if (w.to == host_) {
      if (!guest_->leave({file, lineNo, w.col})) ok = false;
      follow(out, hostFollow);
    } else {
      follow(out, [&](ModeValue m) { guest_->follow(m); });
    }
    mode_ = w.to;
    mark_ = &out;
    markAt_ = out.size();
    return true;
  }
  if (mode_ == host_) return false;
  if (!guest_->block(line, file, lineNo, out)) ok = false;
  return true;
}

GuestBlocks *MixedProgram::guest() {
  if (!guest_ && factory_) guest_ = factory_();
  return guest_.get();
}

bool MixedProgram::endFile(SourceLoc at) {
  bool ok = true;
  if (mode_ != host_ && guest_) ok = guest_->leave(at);
  mode_ = host_;
  mark_ = nullptr;
  markAt_ = 0;
  return ok;
}

}  // namespace ncc
