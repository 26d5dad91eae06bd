// The program: the main file, the subprogram files it calls (found on the search path), the
// lines of each file and their control structures.
#include "frontend/SubprogramFiles.h"
#include "frontend/sinumerik/Parser.h"
#include "ir/Builtins.h"
#include "ir/FileCommands.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace ncc::sin {

FunctionParser::FunctionParser(ProgramParser &pp, uint32_t file, std::string name, bool isMain)
    : pp(pp), file(file), isMain(isMain), vars(pp.guds), distance(isMain ? ModeValue::Absolute : ModeValue::Count) {
  fn.name = std::move(name);
  fn.loc = {file, 1, 1};
  regions.push_back(&fn.body);
}

// A header line `%_N_NAME_MPF` (punched-tape form) or `%` alone, or the folder line `$PATH=…`
// (L866, L9246): no block.
static bool headerLine(std::string_view s) {
  size_t i = s.find_first_not_of(" \t");
  return i != std::string_view::npos && (s[i] == '%' || s.substr(i, 6) == "$PATH=");
}

// Jump targets of a function: label names and block numbers.
static void collectTargets(const ir::Region &r, std::set<std::string> &labels, std::set<double> &blocks) {
  for (auto &op : r) {
    if (op.kind == ir::OpKind::Label) labels.insert(op.get("name")->str);
    if (op.kind == ir::OpKind::Block && op.get("n")) blocks.insert(op.get("n")->num);
    for (auto &sub : op.regions) collectTargets(sub, labels, blocks);
  }
}

// GOTOC continues with the next block when its target is missing (L4414): such a goto (marked
// by the comment before it) is dropped.
static void dropMissingGotoc(ir::Region &r, const std::set<std::string> &labels, const std::set<double> &blocks) {
  for (size_t i = 0; i < r.size(); ++i) {
    for (auto &sub : r[i].regions) dropMissingGotoc(sub, labels, blocks);
    const ir::Expr *text = r[i].kind == ir::OpKind::Comment ? r[i].get("text") : nullptr;
    if (!text || text->str != "GOTOC" || i + 1 >= r.size() || r[i + 1].kind != ir::OpKind::Goto) continue;
    const ir::Expr *n = r[i + 1].get("n"), *l = r[i + 1].get("label");
    bool found = n ? blocks.count(n->num) > 0 : labels.count(l->str) > 0;
    if (!found) {
      r[i].set("text", ir::Expr::string("GOTOC: target not found, continues"));
      r.erase(r.begin() + (long)i + 1);
    }
  }
}

// A section's end label stands before its block op; the section ends with that block, so the
// call's `to` names a label put after the block op (docs/IR.md §5.3: the block of `to` ends
// before the next block or label).
static void sectionEndLabels(ir::Region &body) {
  std::set<std::string> ends;
  auto collect = [&](auto &self, ir::Region &r) -> void {
    for (auto &op : r) {
      if (op.kind == ir::OpKind::CallSection && op.get("to")) {
        ends.insert(op.get("to")->str);
        op.set("to", ir::Expr::string(op.get("to")->str + "@end"));
      }
      for (auto &sub : op.regions) self(self, sub);
    }
  };
  collect(collect, body);
  auto place = [&](auto &self, ir::Region &r) -> void {
    for (size_t i = 0; i < r.size(); ++i) {
      for (auto &sub : r[i].regions) self(self, sub);
      if (r[i].kind != ir::OpKind::Label || !ends.count(r[i].get("name")->str)) continue;
      ir::Op l(ir::OpKind::Label, r[i].loc);
      l.set("name", ir::Expr::string(r[i].get("name")->str + "@end"));
      size_t at = i + 1 < r.size() && r[i + 1].kind == ir::OpKind::Block ? i + 2 : i + 1;
      r.insert(r.begin() + (long)at, std::move(l));
    }
  };
  place(place, body);
}

// The labels a section repetition (REPEAT, CALL BLOCK) names must be in the program: an error
// at the statement, not the verifier's.
bool FunctionParser::sectionLabelsExist(const ir::Region &r, const std::set<std::string> &labels) {
  bool good = true;
  for (auto &op : r) {
    for (auto &sub : op.regions) good = sectionLabelsExist(sub, labels) && good;
    if (op.kind != ir::OpKind::CallSection) continue;
    for (const char *key : {"from", "to"})
      if (const ir::Expr *e = op.get(key); e && !labels.count(e->str))
        good = pp.error(op.loc,
                        op.loc.file == file ? fmt::format("label '{}' is not in this program", e->str)
                                            : fmt::format("label '{}' is not in program {}", e->str, pp.sm.name(file)),
                        "missing-block");
  }
  return good;
}

bool mentionsMcall(std::string_view text) {
  std::string up(text);
  for (auto &c : up) c = (char)std::toupper((unsigned char)c);
  return up.find("MCALL") != std::string::npos;
}

bool FunctionParser::macroLine(std::vector<Token> &toks, uint32_t line, bool &defined) {
  defined = false;
  size_t k = toks[0].kind == Tok::Name && toks[0].text[0] == 'N' && toks[0].digitsAt == 1 ? 1 : 0;  // N10 DEFINE
  if (toks[k].isName("DEFINE")) {
    defined = true;
    if (toks.size() < k + 4 || toks[k + 1].kind != Tok::Name || !toks[k + 2].isName("AS"))
      return pp.error({file, line, toks[k].col}, "a macro is written DEFINE NAME AS text");
    static const char *kReserved[] = {"IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "ENDFOR", "LOOP",
                                      "ENDLOOP", "REPEAT", "UNTIL", "GOTO", "GOTOF", "GOTOB", "GOTOC", "DEFINE"};
    for (const char *r : kReserved)
      if (toks[k + 1].text == r)  // L4936: control keywords and jump targets are no macros
        return pp.error({file, line, toks[k + 1].col}, fmt::format("'{}' cannot be redefined by a macro", r));
    macros[toks[k + 1].text] = std::vector<Token>(toks.begin() + (long)k + 3, toks.end() - 1);
    return true;
  }
  if (macros.empty()) return true;
  std::vector<Token> out;
  for (auto &t : toks) {
    auto it = t.kind == Tok::Name ? macros.find(t.text) : macros.end();
    if (it == macros.end()) {
      out.push_back(t);
      continue;
    }
    for (Token m : it->second) {  // the macro's tokens stand where its name stood
      m.col = t.col;
      out.push_back(std::move(m));
    }
  }
  toks = std::move(out);
  return true;
}

bool FunctionParser::line(std::string_view line, uint32_t lineNo) {
  if (headerLine(line)) return true;
  // Skip level: `/` or `/0`…`/9` before the block (the Fundamentals manual). Blanked out
  // in a copy so that columns stay those of the source line.
  std::string copy(line);
  if (lineNo == 1 && copy.rfind("\xEF\xBB\xBF", 0) == 0) copy.replace(0, 3, "   ");  // a UTF-8 byte order mark
  size_t first = copy.find_first_not_of(" \t");
  if (first != std::string::npos && copy[first] == '/') {
    int skip = 0;
    copy[first] = ' ';
    if (first + 1 < copy.size() && copy[first + 1] >= '0' && copy[first + 1] <= '9') {
      skip = copy[first + 1] - '0';
      copy[first + 1] = ' ';
    }
    if (pp.opts.blockDeleteMask & (1u << skip)) return true;
  }
  std::string err;
  uint32_t errCol = 0;
  std::vector<Token> &toks = lineTokens;
  if (!lexLine(copy, toks, err, errCol)) return pp.error({file, lineNo, errCol}, err);
  bool def = false;
  if (toks.size() > 1 && !macroLine(toks, lineNo, def)) return false;
  if (toks.size() > 1 && !def) {
    BlockParser bp(*this, toks, lineNo);
    return bp.parse();
  }
  return true;
}

bool FunctionParser::run() {
  std::string_view text = pp.sm.text(file);
  pp.modalCalls = pp.modalCalls || mentionsMcall(text);
  // G291 … G290: ISO blocks through the ISO front end (frontend/ModeSwitch.h).
  MixedProgram mixed(Language::Siemens, pp.opts.isoBlocks, pp.opts.blockDeleteMask, pp.diags);
  const std::function<void(ModeValue)> follow = [this](ModeValue m) { followMode(m); };
  size_t pos = 0;
  uint32_t lineNo = 0;
  bool ok = true;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    std::string_view src(text.data() + pos, nl - pos);
    ++lineNo;
    pos = nl + 1;
    if (!mixed.take(src, file, lineNo, cur(), ok, follow) && !line(src, lineNo)) ok = false;
    if (nl >= text.size()) break;
  }
  if (!mixed.endFile({file, lineNo, 1})) ok = false;
  std::set<std::string> targets;
  std::set<double> blocks;
  collectTargets(fn.body, targets, blocks);
  dropMissingGotoc(fn.body, targets, blocks);
  if (!sectionLabelsExist(fn.body, targets)) ok = false;
  for (auto &[name, at] : laterLabels)
    if (!targets.count(name)) ok = pp.error(at, fmt::format("label '{}' is not in this program", name), "missing-block");
  sectionEndLabels(fn.body);
  for (auto &c : ctl) {
    static const char *kOpen[] = {"IF", "IF … ELSE", "WHILE", "FOR", "LOOP", "REPEAT"};
    static const char *kClose[] = {"ENDIF", "ENDIF", "ENDWHILE", "ENDFOR", "ENDLOOP", "UNTIL"};
    pp.error(c.loc, fmt::format("{} without {}", kOpen[(int)c.kind], kClose[(int)c.kind]), "loop-mismatch");
    ok = false;
  }
  if (!contourTable.name.empty())  // Contour.cpp
    ok = pp.error(contourTable.loc, fmt::format("{} without EXECUTE in the same program",
                                                contourTable.coded ? "CONTDCON" : "CONTPRON"),
                  "loop-mismatch");
  return ok;
}

// Files a called name may be in (L6859-L6898: the control adds _N_ and _SPF / _MPF); `type`
// "MPF" or "SPF" when the call named it, which then is the only one looked for.
static std::vector<std::string> candidateFiles(const std::string &name, const std::string &type) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return (char)std::tolower(c); });
  std::vector<std::string> out;
  for (const char *t : {"MPF", "SPF"}) {  // MPF first (L8307)
    if (!type.empty() && type != t) continue;
    std::string upper = t, low = lower.empty() ? "" : t;
    std::transform(low.begin(), low.end(), low.begin(), [](unsigned char c) { return (char)std::tolower(c); });
    out.push_back(name + "." + upper);
    out.push_back(lower + "." + low);
    out.push_back("_N_" + name + "_" + upper);
  }
  return out;
}

std::string calledProgram(const std::string &written, std::string &type) {
  return sinumerikProgramName(written, type);
}

// The names of the Siemens standard cycles (CYCLE81, POCKET3, HOLES1 …).
static bool siemensCycle(const std::string &name) {
  static const char *kPrefixes[] = {"CYCLE", "POCKET", "SLOT", "HOLES", "LONGHOLE"};
  for (const char *p : kPrefixes) {
    std::string_view n(name), pre(p);
    if (n.substr(0, pre.size()) != pre) continue;
    std::string_view rest = n.substr(pre.size());
    if (rest.empty() ? pre == "LONGHOLE" : rest.find_first_not_of("0123456789") == std::string_view::npos) return true;
  }
  return false;
}

std::vector<std::string> ProgramParser::searchPath() const {
  std::vector<std::string> dirs = opts.searchDirs;
  if (!callPath.empty()) dirs.push_back(callPath);
  return dirs;
}

uint32_t ProgramParser::programFile(const std::string &base, const std::string &type) {
  return findSubprogramFile(sm, searchPath(), candidateFiles(base, type), true);
}

std::string ProgramParser::programFolder(const std::string &path) const {
  std::string_view p(path);
  if (p.substr(0, 5) == "//NC:") p.remove_prefix(5);  // the NC's own memory (L8790)
  std::filesystem::path native, written;
  for (size_t at = 0; at <= p.size();) {
    size_t slash = p.find('/', at);
    if (slash == std::string_view::npos) slash = p.size();
    std::string_view c = p.substr(at, slash - at);
    if (c == "..") return "";
    if (!c.empty() && c != ".") {
      native /= sinumerikPathComponent(c, false);
      written /= std::string(c);
    }
    at = slash + 1;
  }
  for (auto &d : opts.searchDirs)
    for (auto *rel : {&native, &written}) {
      std::error_code ec;
      std::filesystem::path dir = std::filesystem::path(d) / *rel;
      if (!rel->empty() && std::filesystem::is_directory(dir, ec)) return dir.string();
    }
  return "";
}

// ISOCALL: the program's file on the search path (as a call finds it), read by the ISO front end.
const std::string *ProgramParser::isoProgram(const std::string &written, SourceLoc loc) {
  std::string type, name = calledProgram(written, type);
  std::string key = name + " (ISO)";
  if (auto it = isoPrograms.find(key); it != isoPrograms.end()) return &*it;
  if (!opts.isoBlocks) {
    error(loc, "ISOCALL: no ISO front end for this program", "unsupported-code");
    return nullptr;
  }
  uint32_t fid = programFile(name, type);
  if (!fid) {
    missingProgram(name, loc);
    return nullptr;
  }
  if (!isoGuest) isoGuest = opts.isoBlocks();
  if (!isoGuest->program(fid, key)) {
    ok = false;
    return nullptr;
  }
  return &*isoPrograms.insert(key).first;
}

void ProgramParser::missingProgram(const std::string &name, SourceLoc loc) {
  if (const PredefinedName *p = findPredefined(name))
    error(loc, fmt::format("{} ({}) is a predefined {} of the control: ncc does not simulate it in this form", name, p->meaning, p->kind),
          "unsupported-code");
  else if (!missing.count(name))
    error(loc, fmt::format("subprogram {} not found (searched {} for {}.MPF, {}.SPF)", name,
                           folderList(searchPath()), name, name),
          "missing-subprogram");
  else
    error(loc, fmt::format("subprogram {} not found", name), "missing-subprogram");
  missing.insert(name);
}

// CALL "P" BLOCK A TO B (SIN-CAL-06): a function of its own made of P's text, starting with the
// section call from A through B's block and a return, so the section runs in P's context.
const std::string *ProgramParser::sectionFunction(const std::string &name, const std::string &type,
                                                  const std::string &from, const std::string &to, SourceLoc loc) {
  std::string key = fmt::format("{} BLOCK {} TO {}", type.empty() ? name : "_N_" + name + "_" + type, from, to);
  if (from.empty()) key = fmt::format("{} BLOCK", type.empty() ? name : "_N_" + name + "_" + type);  // labels named at run time
  if (auto it = sections.find(key); it != sections.end()) return &it->first;
  uint32_t fid = programFile(name, type);
  if (!fid) {
    missingProgram(name, loc);
    return nullptr;
  }
  FunctionParser fp(*this, fid, key, false);
  if (!from.empty()) {
    ir::Op s(ir::OpKind::CallSection, loc);
    s.set("from", ir::Expr::string(from));
    s.set("to", ir::Expr::string(to));
    fp.fn.body.push_back(std::move(s));
    fp.fn.body.push_back(ir::Op(ir::OpKind::Return, loc));
  }
  ir::Op text(ir::OpKind::Label, loc);  // P's text is reached through the section's labels (not dead code)
  text.set("name", ir::Expr::string("@text"));
  fp.fn.body.push_back(std::move(text));
  bool good = fp.run();
  if (from.empty()) namedSectionFunction(fp.fn, loc);
  fp.fn.dialect = ir::Dialect::Unknown;
  done.push_back(std::move(fp.fn));
  if (!good) return nullptr;
  return &sections.emplace(key, fp.retTarget).first->first;
}

const Signature *ProgramParser::callee(const std::string &name, SourceLoc loc, CycleSignature *libCycle,
                                       const std::string &type) {
  auto it = procs.find(name);
  if (it != procs.end()) return &it->second;
  if (std::find(opts.linkedFunctions.begin(), opts.linkedFunctions.end(), name) != opts.linkedFunctions.end()) {
    procs[name].ready = true;  // a linked file defines it; its parameters are passed by position there
    return &procs[name];
  }
  // A call that named the type is kept apart (_N_TEIL1_SPF) from one that did not (TEIL1: MPF first).
  std::string base = type.empty() ? name : name.substr(3, name.size() - 7);
  uint32_t fid = programFile(base, type);
  if (!fid && siemensCycle(base)) {
    // A standard cycle without a user subprogram of that name (which would override it): the
    // cycle library's entry.
    if (libCycle && opts.cycles && opts.cycles("sin." + base, *libCycle)) return nullptr;
    if (!missing.count(name))
      error(loc, fmt::format("{} is a Siemens standard cycle the cycle library does not have yet (no {}.SPF in {}; "
                             "`ncc cycle --list` shows the library)",
                             name, name, folderList(opts.searchDirs)),
            "unsupported-code");
    missing.insert(name);
    return nullptr;
  }
  if (!fid) {
    missingProgram(name, loc);
    return nullptr;
  }
  // Parse the file now: its PROC line gives the signature the call's arguments need.
  procs[name];
  FunctionParser fp(*this, fid, name, false);
  bool good = fp.run();
  Signature &s = procs[name];
  s.params.clear();
  for (auto &p : fp.fn.params) {
    ir::Param c;
    c.name = p.name;
    c.type = p.type;
    c.byRef = p.byRef;
    s.params.push_back(std::move(c));
  }
  s.ready = true;
  s.retTarget = fp.retTarget;
  fp.fn.dialect = ir::Dialect::Unknown;
  done.push_back(std::move(fp.fn));
  if (!good) ok = false;
  return &procs[name];
}

bool ProgramParser::loadSearchPath(SourceLoc loc) {
  if (searchPathLoaded) return true;
  searchPathLoaded = true;
  std::set<std::string> names;
  for (auto &d : searchPath()) {
    std::error_code ec;
    for (auto &e : std::filesystem::directory_iterator(d, ec)) {
      if (!e.is_regular_file(ec)) continue;
      std::string type, name = calledProgram(e.path().filename().string(), type);
      if (type == "SPF" && name.size() >= 2) names.insert(name);
    }
  }
  bool before = ok, good = true;
  ok = true;
  for (auto &n : names)
    if (!procs.count(n) && !callee(n, loc)) good = false;
  good = good && ok;
  ok = before && ok;
  return good;
}

bool parseSinumerikProgram(SourceManager &sm, uint32_t fileId, const SinOptions &opts, Diagnostics &diags,
                           ir::Module &out) {
  out.dialect = ir::Dialect::Sinumerik;
  out.name = sm.name(fileId);
  ProgramParser pp(sm, opts, diags, out);
  bool ok = pp.loadDefinitionFiles();
  FunctionParser main(pp, fileId, "main", true);
  ok = main.run() && ok;
  main.fn.body.insert(main.fn.body.begin(), std::make_move_iterator(pp.gudOps.begin()),
                      std::make_move_iterator(pp.gudOps.end()));
  if (pp.polar) declarePolarState(main.fn.body);
  if (pp.globalR) declareGlobalR(main.fn.body);
  if (pp.retTargets) declareReturnTargets(main.fn.body);
  if (pp.namedSections) declareNamedSections(main.fn.body);
  out.functions.clear();
  out.functions.push_back(std::move(main.fn));
  for (auto &f : pp.done) out.functions.push_back(std::move(f));
  if (pp.isoGuest && !pp.isoGuest->finish(out)) ok = false;
  return ok && pp.ok;
}

}  // namespace ncc::sin
