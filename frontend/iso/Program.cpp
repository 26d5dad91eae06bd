// Whole-program parsing: splits the file into blocks, builds the control structure (Macro B
// WHILE/DO/END, IF, GOTO; RS274 O-words), separates the main program from O-number
// subprograms and loads subprogram files for the calls that are not defined in the main file.
#include "frontend/SubprogramFiles.h"
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Lower.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <set>

namespace ncc::iso {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;
using ir::Region;

Flavour flavourForFile(std::string_view name) {
  auto dot = name.rfind('.');
  if (dot == std::string_view::npos) return Flavour::Fanuc;
  std::string ext(name.substr(dot + 1));
  for (auto &c : ext) c = (char)std::tolower((unsigned char)c);
  return ext == "ngc" ? Flavour::RS274 : Flavour::Fanuc;
}

namespace {

// An open control structure whose body is being filled.
struct Pending {
  enum Kind : uint8_t { MacroLoop, OIf, OWhile, ODo, ORepeat } kind;
  Op op;
  int id = 0;            // Macro B DO number
  std::string oname;     // O-word name
  bool chained = false;  // an elseif's nested if: closed together with its head by endif
};

class ProgramParser {
public:
  ProgramParser(SourceManager &sm, const IsoOptions &opts, Diagnostics &diags, ir::Module &m)
      : sm_(sm), opts_(opts), diags_(diags), module_(m), mixed_(Language::Iso, opts.siemensBlocks, opts.blockDeleteMask, diags) {}

  // Parses one file. The first section becomes function `firstName` (created when missing).
  bool parseFile(uint32_t fileId, const std::string &firstName);
  bool ok() const { return ok_; }
  std::vector<CallRef> calls;
  // The functions the Siemens-mode blocks loaded, into the module.
  bool finishMixed() { return mixed_.finish(module_); }
  // A called program file in Siemens mode (its first block is PROC): the Sinumerik front end
  // reads it as function `name`. False when the program has no Siemens mode.
  bool siemensProgram(uint32_t fileId, const std::string &name, bool &ok) {
    GuestBlocks *g = mixed_.guest();
    if (g && !g->program(fileId, name)) ok = false;
    return g != nullptr;
  }

private:
  SourceManager &sm_;
  const IsoOptions &opts_;
  Diagnostics &diags_;
  ir::Module &module_;
  MixedProgram mixed_;  // G290 … G291: Siemens-mode blocks (Fanuc flavour only)
  bool ok_ = true;

  // Per-file state.
  size_t fn_ = 0;                     // index of the function being filled
  std::vector<Pending> stack_;
  struct OpenSub {
    size_t outer, depth;  // function to return to, control stack depth at `sub`
    std::string oname;
  };
  std::vector<OpenSub> subStack_;  // RS274 o-word subs being defined
  size_t fileFn_ = SIZE_MAX;        // the function of a subprogram file being parsed
  bool sectionContent_ = false, ended_ = false;  // section has code; closing '%' seen

  Region &region() {
    return stack_.size() <= baseDepth() ? module_.functions[fn_].body : stack_.back().op.regions.back();
  }
  size_t baseDepth() const { return subStack_.empty() ? 0 : subStack_.back().depth; }
  void error(SourceLoc loc, std::string msg, const char *rule = "syntax") {
    diags_.error(loc, std::move(msg), rule);
    ok_ = false;
  }
  size_t startFunction(const std::string &name, SourceLoc loc);
  void closeOpen(size_t depth);
  // `#<name> = value` for rs274's call results (#<_value>, #<_value_returned>).
  static Op valueAssign(const char *name, ir::ExprPtr value, SourceLoc loc) {
    Op op(OpKind::Assign, loc);
    op.set("target", Expr::var(ir::VarSpace::Global, name, nullptr, loc));
    op.set("value", std::move(value));
    return op;
  }
  // `return [v]` / `endsub [v]`: the caller reads v as #<_value>, with #<_value_returned> = 1.
  void returnOps(SourceLoc loc, ir::ExprPtr value) {
    if (value) {
      region().push_back(valueAssign("_value", std::move(value), loc));
      region().push_back(valueAssign("_value_returned", Expr::number(1, ir::Type::Int, loc), loc));
    }
    region().push_back(Op(OpKind::Return, loc));
  }
  void pop();
  void statement(ParsedBlock &b, BlockLowerer &lower);
  void oword(ParsedBlock &b, BlockLowerer &lower);
};

size_t ProgramParser::startFunction(const std::string &name, SourceLoc loc) {
  if (module_.find(name)) {
    error(loc, fmt::format("program {} is defined twice", name), "duplicate-program");
  }
  ir::Function f;
  f.name = name;
  f.loc = loc;
  module_.functions.push_back(std::move(f));
  return module_.functions.size() - 1;
}

// Moves the innermost open structure into its parent.
void ProgramParser::pop() {
  Pending p = std::move(stack_.back());
  stack_.pop_back();
  region().push_back(std::move(p.op));
}

// Reports and closes structures left open (end of file, end of a subprogram).
void ProgramParser::closeOpen(size_t depth) {
  while (stack_.size() > depth) {
    auto &p = stack_.back();
    if (p.kind == Pending::MacroLoop)
      error(p.op.loc, fmt::format("DO{} without END{}", p.id, p.id), "loop-mismatch");
    else if (!p.chained)
      error(p.op.loc, fmt::format("o{} is not closed", p.oname), "loop-mismatch");
    pop();
  }
}

void ProgramParser::statement(ParsedBlock &b, BlockLowerer &lower) {
  if (b.stmt == StmtKind::OWord) return oword(b, lower);  // places its own block op
  Region &r = region();
  r.push_back(lower.blockOp(b));
  lower.lowerComments(b, r);
  switch (b.stmt) {
  case StmtKind::None:
    if (!lower.lowerActions(b, r)) ok_ = false;
    return;
  case StmtKind::IfGoto:
  case StmtKind::IfThen: {
    Op op(OpKind::If, b.stmtLoc);
    op.set("cond", std::move(b.cond));
    op.regions.emplace_back();
    if (b.stmt == StmtKind::IfGoto) {
      Op g(OpKind::Goto, b.stmtLoc);
      g.set("n", std::move(b.target));
      op.regions[0].push_back(std::move(g));
    } else if (!lower.lowerActions(b, op.regions[0])) {
      ok_ = false;
    }
    region().push_back(std::move(op));
    return;
  }
  case StmtKind::Goto: {
    if (!lower.lowerActions(b, r)) ok_ = false;
    Op g(OpKind::Goto, b.stmtLoc);
    g.set("n", std::move(b.target));
    region().push_back(std::move(g));
    return;
  }
  case StmtKind::While:
  case StmtKind::Do: {
    if (!lower.lowerActions(b, r)) ok_ = false;
    Pending p{Pending::MacroLoop, Op(OpKind::While, b.stmtLoc), 0, {}, false};
    p.id = b.loopId;
    p.op.set("cond", b.stmt == StmtKind::While ? std::move(b.cond) : Expr::boolean(true, b.stmtLoc));
    p.op.set("id", Expr::number(b.loopId, ir::Type::Int, b.stmtLoc));
    p.op.regions.emplace_back();
    stack_.push_back(std::move(p));
    return;
  }
  case StmtKind::End: {
    if (!lower.lowerActions(b, r)) ok_ = false;
    if (stack_.size() <= baseDepth() || stack_.back().kind != Pending::MacroLoop) {
      error(b.stmtLoc, fmt::format("END{} without WHILE ... DO{}", b.loopId, b.loopId), "loop-mismatch");
      return;
    }
    if (stack_.back().id != b.loopId) {
      error(b.stmtLoc, fmt::format("END{} does not match DO{}", b.loopId, stack_.back().id), "loop-mismatch");
      return;
    }
    pop();
    return;
  }
  case StmtKind::OWord:
    return;
  }
}

static std::string oFunctionName(const std::string &oname) {
  bool numeric = !oname.empty() && std::isdigit((unsigned char)oname[0]);
  if (!numeric) return oname;
  size_t i = 0;
  while (i + 1 < oname.size() && oname[i] == '0') ++i;
  return "O" + oname.substr(i);
}

void ProgramParser::oword(ParsedBlock &b, BlockLowerer &lower) {
  SourceLoc loc = b.stmtLoc;
  // The line's block op goes where the line belongs: inside a new sub or else branch.
  auto head = [&] {
    region().push_back(lower.blockOp(b));
    lower.lowerComments(b, region());
  };
  auto top = [&](std::initializer_list<Pending::Kind> kinds) -> Pending * {
    if (stack_.size() <= baseDepth()) return nullptr;
    Pending &p = stack_.back();
    for (auto k : kinds)
      if (p.kind == k && p.oname == b.oname) return &p;
    return nullptr;
  };
  auto mismatch = [&](const char *what) {
    error(loc, fmt::format("o{} {} does not close an open o{} block", b.oname, what, b.oname), "loop-mismatch");
  };
  auto open = [&](Pending::Kind k, Op op) {
    Pending p{k, std::move(op), 0, {}, false};
    p.oname = b.oname;
    p.op.regions.emplace_back();
    stack_.push_back(std::move(p));
  };
  switch (b.okw) {
  case OKeyword::Sub: {
    if (stack_.size() > baseDepth()) {
      error(loc, "o-word sub inside a control structure", "syntax");
      return;
    }
    size_t outer = fn_;
    // A subroutine file name.ngc that starts with `o<name> sub`: the file's function is the sub.
    ir::Function &cur = module_.functions[fn_];
    bool fileIsSub = fn_ == fileFn_ && subStack_.empty() && cur.name == oFunctionName(b.oname) &&
                     std::all_of(cur.body.begin(), cur.body.end(), [](const Op &op) {
                       return op.kind == OpKind::Block || op.kind == OpKind::Comment;
                     });
    if (!fileIsSub) fn_ = startFunction(oFunctionName(b.oname), loc);
    subStack_.push_back({outer, stack_.size(), b.oname});
    head();
    return;
  }
  case OKeyword::EndSub: {
    if (subStack_.empty() || subStack_.back().oname != b.oname) {
      error(loc, fmt::format("o{} endsub without o{} sub", b.oname, b.oname), "loop-mismatch");
      return;
    }
    closeOpen(subStack_.back().depth);
    head();
    returnOps(loc, std::move(b.cond));
    fn_ = subStack_.back().outer;
    subStack_.pop_back();
    return;
  }
  case OKeyword::Call: {
    head();
    std::string callee = b.ocomputed ? std::string() : oFunctionName(b.oname);
    if (!b.ocomputed) lower.calls.push_back({callee, loc});
    // rs274: #<_value_returned> is 0 after a call whose sub returned no value.
    region().push_back(valueAssign("_value_returned", Expr::number(0, ir::Type::Int, loc), loc));
    Op op(OpKind::Call, loc);
    // A computed number n calls the sub `o<n>` (function O<n>), found when the call runs.
    op.set("callee", b.ocomputed ? std::move(b.ocomputed) : Expr::string(callee, loc));
    op.set("frame", Expr::symbol("new", loc));
    for (size_t i = 0; i < b.oargs.size(); ++i) op.set(fmt::format("a.{}", i + 1), std::move(b.oargs[i]));
    region().push_back(std::move(op));
    return;
  }
  case OKeyword::Return: {
    head();
    returnOps(loc, std::move(b.cond));
    return;
  }
  case OKeyword::If: {
    head();
    Op op(OpKind::If, loc);
    op.set("cond", std::move(b.cond));
    open(Pending::OIf, std::move(op));
    return;
  }
  case OKeyword::ElseIf:
  case OKeyword::Else: {
    Pending *p = top({Pending::OIf});
    if (!p || p->op.regions.size() > 1) {
      mismatch(b.okw == OKeyword::Else ? "else" : "elseif");
      return;
    }
    p->op.regions.emplace_back();
    head();
    if (b.okw == OKeyword::ElseIf) {  // else { if cond { ... } } closed together by endif
      Op op(OpKind::If, loc);
      op.set("cond", std::move(b.cond));
      open(Pending::OIf, std::move(op));
      stack_.back().chained = true;
    }
    return;
  }
  case OKeyword::EndIf: {
    head();
    if (!top({Pending::OIf})) {
      mismatch("endif");
      return;
    }
    while (stack_.back().chained) pop();
    pop();
    return;
  }
  case OKeyword::While: {
    head();
    if (Pending *p = top({Pending::ODo})) {  // do ... while [c]: loop until !c
      Op brk(OpKind::If, loc);
      brk.set("cond", Expr::unary(ir::OpCode::Not, std::move(b.cond), loc));
      brk.regions.emplace_back();
      brk.regions[0].push_back(Op(OpKind::Break, loc));
      p->op.regions[0].push_back(std::move(brk));
      pop();
      return;
    }
    Op op(OpKind::While, loc);
    op.set("cond", std::move(b.cond));
    open(Pending::OWhile, std::move(op));
    return;
  }
  case OKeyword::EndWhile:
    head();
    if (!top({Pending::OWhile})) return mismatch("endwhile");
    pop();
    return;
  case OKeyword::Do: {
    head();
    Op op(OpKind::While, loc);
    op.set("cond", Expr::boolean(true, loc));
    open(Pending::ODo, std::move(op));
    return;
  }
  case OKeyword::Repeat: {
    head();
    Op op(OpKind::Loop, loc);
    op.set("count", std::move(b.cond));
    open(Pending::ORepeat, std::move(op));
    return;
  }
  case OKeyword::EndRepeat:
    head();
    if (!top({Pending::ORepeat})) return mismatch("endrepeat");
    pop();
    return;
  case OKeyword::Break:
  case OKeyword::Continue: {
    head();
    bool inLoop = false;
    for (size_t i = baseDepth(); i < stack_.size(); ++i)
      inLoop |= stack_[i].kind != Pending::OIf;
    if (!inLoop) {
      error(loc, b.okw == OKeyword::Break ? "break outside a loop" : "continue outside a loop", "syntax");
      return;
    }
    region().push_back(Op(b.okw == OKeyword::Break ? OpKind::Break : OpKind::Continue, loc));
    return;
  }
  }
}

bool ProgramParser::parseFile(uint32_t fileId, const std::string &firstName) {
  std::string_view text = sm_.text(fileId);
  Flavour flavour = flavourForFile(sm_.name(fileId));
  BlockParser parser(diags_, flavour, opts_.blockDeleteMask, opts_.offsetMemory, opts_.lathe);
  BlockLowerer lower(opts_, flavour, diags_);
  if (!lower.optionsValid()) {
    error({}, fmt::format("unknown decimal mode '{}' (calculator, is-b, is-c)", opts_.decimalMode), "options");
    return false;
  }
  ir::Function *first = module_.find(firstName);
  fn_ = first ? (size_t)(first - module_.functions.data()) : startFunction(firstName, {fileId, 1, 1});
  fileFn_ = firstName == "main" ? SIZE_MAX : fn_;
  stack_.clear();
  subStack_.clear();
  sectionContent_ = ended_ = false;

  ParsedBlock b;
  const std::function<void(ModeValue)> followModes = [&](ModeValue m) { lower.followMode(m); };
  const char *p = text.data(), *end = p + text.size();
  uint32_t lineNo = 0;
  bool afterEnd = false;  // RS274NGC: the main program's M2/M30 has been read
  while (p < end) {
    const char *nl = static_cast<const char *>(std::memchr(p, '\n', (size_t)(end - p)));
    const char *le = nl ? nl : end;
    ++lineNo;
    std::string_view line(p, (size_t)(le - p));
    p = nl ? nl + 1 : end;
    // rs274 never reads past M2/M30 except to find a called sub: only o-word lines matter there.
    if (afterEnd && subStack_.empty()) {
      size_t i = line.find_first_not_of(" \t\r");
      if (i == std::string_view::npos || (line[i] != 'o' && line[i] != 'O')) continue;
    }
    if (flavour == Flavour::Fanuc && !ended_ && mixed_.take(line, fileId, lineNo, region(), ok_, followModes)) {
      sectionContent_ = true;
      continue;
    }
    if (!parser.parse(line, fileId, lineNo, b)) {
      ok_ = false;
      continue;
    }
    if (b.percent) {
      if (sectionContent_) {
        closeOpen(0);
        ended_ = true;
        sectionContent_ = false;
      }
      continue;
    }
    if (!b.content) continue;
    if (b.programNumber >= 0) {  // Fanuc O<number>: names the program or starts a subprogram
      bool namesCurrent = !sectionContent_ && !ended_;
      if (!namesCurrent) {
        closeOpen(0);
        if (!subStack_.empty()) error(b.loc, "O-number program inside an o-word sub", "syntax");
        subStack_.clear();
        fn_ = startFunction(fmt::format("O{}", b.programNumber), b.loc);
        ended_ = false;
      }
      sectionContent_ = true;
      if (!b.comments.empty()) {
        region().push_back(lower.blockOp(b));
        lower.lowerComments(b, region());
      }
      continue;
    }
    if (ended_) continue;  // text after the closing '%' is not part of the program
    if (!b.words.empty() || !b.assigns.empty() || b.stmt != StmtKind::None) sectionContent_ = true;
    lower.inMain = fn_ == 0 && subStack_.empty() && module_.functions[0].name == "main";
    statement(b, lower);
    if (flavour == Flavour::RS274 && fn_ == 0 && subStack_.empty() && stack_.empty())
      for (auto &w : b.words)
        if (w.letter == 'M' && !w.expr && (w.value == 2 || w.value == 30)) afterEnd = true;
  }
  if (!mixed_.endFile({fileId, lineNo, 1})) ok_ = false;
  closeOpen(0);
  if (!subStack_.empty()) {
    error(module_.functions[fn_].loc, "o-word sub without endsub", "loop-mismatch");
    subStack_.clear();
  }
  for (auto &c : lower.calls) calls.push_back(c);
  return ok_;
}

// Candidate file names for program `name` ("O12" -> O12.nc, 12.nc, 0012.mpf, ...).
static std::vector<std::string> candidateFiles(const std::string &name) {
  std::vector<std::string> out;
  if (name.size() > 1 && name[0] == 'O' && std::isdigit((unsigned char)name[1])) {
    std::string num = name.substr(1);
    std::vector<std::string> nums{num};
    if (num.size() < 4) nums.push_back(std::string(4 - num.size(), '0') + num);
    for (auto &n : nums)
      for (const char *fmtStr : {"O{}.nc", "{}.nc", "O{}.ngc", "{}.ngc", "{}.mpf", "{}.spf", "O{}", "{}.NC",
                                 "O{}.NC", "{}.MPF", "{}.SPF"})
        out.push_back(fmt::format(fmt::runtime(fmtStr), n));
  } else {  // o<name> call; an 808D macro called by code (M6_MAKRO.spf)
    for (const char *ext : {".ngc", ".nc", ".spf", ".mpf", ".SPF", ".MPF"}) out.push_back(name + ext);
  }
  return out;
}

// Goto targets must be blocks of the same program (Macro B searches only the current program).
static void collectBlocks(const Region &r, std::set<double> &blocks, std::vector<const Op *> &gotos) {
  for (auto &op : r) {
    if (op.kind == OpKind::Block) {
      if (auto *n = op.get("n")) blocks.insert(n->num);
    } else if (op.kind == OpKind::Goto) {
      gotos.push_back(&op);
    }
    for (auto &sub : op.regions) collectBlocks(sub, blocks, gotos);
  }
}

// The first block of a program file is PROC (comments, `;` lines and `%` headers before it
// do not count).
static bool startsWithProc(std::string_view text) {
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    size_t i = line.find_first_not_of(" \t\r");
    if (i == std::string_view::npos || line[i] == ';' || line[i] == '%' || line[i] == '(') continue;
    if (line[i] == 'N' || line[i] == 'n')  // a block number before PROC
      for (++i; i < line.size() && (std::isdigit((unsigned char)line[i]) || line[i] == ' ');) ++i;
    std::string_view rest = line.substr(i);
    return rest.size() > 5 && (rest.substr(0, 5) == "PROC " || rest.substr(0, 5) == "PROC\t");
  }
  return false;
}

static bool checkGotoTargets(const ir::Module &m, Diagnostics &diags) {
  bool ok = true;
  for (auto &f : m.functions) {
    std::set<double> blocks;
    std::vector<const Op *> gotos;
    collectBlocks(f.body, blocks, gotos);
    for (auto *g : gotos) {
      const ir::Expr *n = g->get("n");
      if (!n || n->kind != ir::ExprKind::Number || blocks.count(n->num)) continue;
      diags.error(g->loc, fmt::format("GOTO {}: there is no block N{} in this program", n->num, n->num),
                  "missing-block");
      ok = false;
    }
  }
  return ok;
}

}  // namespace

bool parseIsoProgram(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags,
                     ir::Module &out) {
  out.dialect = ir::Dialect::ISO;
  out.name = sm.name(fileId);
  ProgramParser pp(sm, opts, diags, out);
  pp.parseFile(fileId, "main");

  std::vector<std::string> dirs = opts.searchDirs;
  if (dirs.empty()) {
    std::filesystem::path mp(sm.name(fileId));
    dirs.push_back(mp.has_parent_path() ? mp.parent_path().string() : std::string("."));
  }
  std::set<std::string> missing, siemens;  // siemens: read by the Sinumerik front end (not in `out` yet)
  bool ok = pp.ok();
  // Resolve calls; parsing a subprogram file can add more calls.
  for (size_t i = 0; i < pp.calls.size(); ++i) {
    CallRef c = pp.calls[i];
    if (out.find(c.callee) || siemens.count(c.callee)) continue;
    if (std::find(opts.linkedFunctions.begin(), opts.linkedFunctions.end(), c.callee) != opts.linkedFunctions.end())
      continue;  // a linked file defines it (the driver links it after parsing)
    if (missing.count(c.callee)) {
      diags.error(c.loc, fmt::format("subprogram {} not found", c.callee), "missing-subprogram");
      ok = false;
      continue;
    }
    uint32_t fid = findSubprogramFile(sm, dirs, candidateFiles(c.callee));
    if (!fid) {
      diags.error(c.loc, fmt::format("subprogram {} not found (searched {})", c.callee, folderList(dirs)),
                  "missing-subprogram");
      missing.insert(c.callee);
      ok = false;
      continue;
    }
    // 808D: a first block PROC switches the called program to Siemens mode (seed001 L9787-9791).
    if (startsWithProc(sm.text(fid)) && pp.siemensProgram(fid, c.callee, ok)) {
      siemens.insert(c.callee);
      continue;
    }
    if (!pp.parseFile(fid, c.callee)) ok = false;
  }
  ok &= pp.finishMixed();
  for (auto &f : out.functions) ok &= placeContourLabels(f, diags);
  ok &= finishCalls(out, diags);
  ok &= checkGotoTargets(out, diags);
  return ok && pp.ok();
}

}  // namespace ncc::iso
