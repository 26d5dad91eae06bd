// The program: the main file, the programs it calls (CALL PGM, found in its folder, then on the
// search path), each file's frame (BEGIN PGM … END PGM) and its labels.
#include "frontend/SubprogramFiles.h"
#include "frontend/heidenhain/Fk.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace ncc::hei {

FileParser::FileParser(ProgramParser &pp, uint32_t file, std::string name, bool isMain)
    : pp(pp), file(file), isMain(isMain) {
  fn.name = std::move(name);
  fn.loc = {file, 1, 1};
}

bool FileParser::error(SourceLoc loc, std::string msg, const char *rule) {
  pp.diags.error(loc, std::move(msg), rule);
  pp.ok = false;
  return false;
}

bool FileParser::run() {
  LexResult lr = lexFile(pp.sm.text(file), file);
  bool ok = true;
  for (auto &[l, msg] : lr.errors) ok = error(l, msg);
  for (auto &l : lr.decimalCommas)
    pp.diags.warning(l, "a decimal comma, read as a decimal point (the control writes '.')", "lenient-syntax");
  if (lr.blocks.empty()) return error({file, 1, 1}, "no Klartext block: a program starts with BEGIN PGM <name> MM|INCH", "program-frame");
  for (auto &b : lr.blocks)
    if (!b.toks.empty() && b.toks[0].isWord("DEP")) usesDep = true;
  for (auto &b : lr.blocks) {
    const Token &first = b.toks[0];
    bool comment = b.star || first.kind == Tok::End;
    if (approach && !comment && !first.isWord("L") && !first.isWord("C")) {  // APPR needs the element's direction
      approach.reset();
      ok = error({file, first.line, first.col},
                 "after APPR the first contour element must be a straight line L or a circle C (CR, CT, polar: not simulated yet)",
                 "unsupported-code");
    }
    // FK: a block other than FL FLT FC FCT FPOL FSELECT needs the FK contour before it solved;
    // the position is known statically only after an L or FK element (Fk.cpp).
    static const char *const kFk[] = {"FL", "FLT", "FC", "FCT", "FPOL", "FSELECT"};
    bool fkBlock = std::any_of(std::begin(kFk), std::end(kFk), [&](const char *k) { return first.isWord(k); });
    if (!comment && !fkBlock && !fkFinish({file, first.line, first.col}, first.text)) ok = false;
    // The parser may rewrite the block's tokens (FK lowering): `first` is read before it runs.
    const bool isLine = first.isWord("L"), isCircle = first.isWord("C");
    BlockParser bp(*this, b);
    if (!bp.parse()) ok = false;
    if (!comment && !fkBlock && !isLine && fk) fk->here = fk->heading = std::nullopt;
    if (!comment) lastWasLine = isLine;
    if (!comment) lastArcDir = isCircle ? bp.arcDir() : 0;
  }
  if (approach) ok = error({file, lr.blocks.back().line, 1}, "APPR without a contour element after it", "syntax");
  if (!fkFinish({file, lr.blocks.back().line, 1}, "the end of the file")) ok = false;
  if (begun && !ended) ok = error(beginLoc, fmt::format("BEGIN PGM {} has no END PGM", pgmName), "program-frame");
  if (!resolveLabels()) ok = false;
  if (usesQL) {  // QL0…QL499: local to this program, 0 at its start
    Op d(OpKind::Declare, fn.loc);
    d.set("var", Expr::var(ir::VarSpace::Local, "QL", Expr::number(500, ir::Type::Int)));
    d.set("type", Expr::symbol("real"));
    fn.body.insert(fn.body.begin(), std::move(d));
  }
  return ok;
}

// CALL LBL n: with REP, a program-section repeat back to LBL n above it (the section runs REP
// more times); without, the subprogram LBL n … LBL 0 (the first LBL 0 after it).
bool FileParser::resolveLabels() {
  bool ok = true;
  for (auto &[name, l] : gotos)
    if (!labels.count(name)) ok = error(l, fmt::format("jump to {} that is not defined in this program", name), "missing-block");
  for (auto &c : calls) {
    auto it = labels.find(c.label);
    if (it == labels.end()) {
      ok = error(c.loc, fmt::format("CALL LBL to {} that is not defined in this program", c.label), "missing-block");
      continue;
    }
    size_t from = it->second;
    auto end = std::upper_bound(lbl0.begin(), lbl0.end(), from);
    if (c.rep) {
      if (from > c.at) {
        ok = error(c.loc, "CALL LBL … REP repeats the section above it: the label must come before the call");
      } else if (end != lbl0.end() && *end < c.at) {
        ok = error(c.loc, "REP repeats a program section, but this label starts a subprogram (LBL 0 before the call)",
                   "unsupported-code");
      }
      continue;
    }
    if (end == lbl0.end()) {
      ok = error(c.loc, "the subprogram has no LBL 0 after its label (a section repeat needs REP)");
      continue;
    }
    if (from < c.at && c.at < *end) {
      ok = error(c.loc, "CALL LBL inside the subprogram it calls");
      continue;
    }
    fn.body[c.at].set("to", Expr::string(fn.body[*end].get("name")->str));
  }
  return ok;
}

std::vector<std::string> ProgramParser::folders(uint32_t fromFile) const {
  std::vector<std::string> dirs;
  std::filesystem::path here = std::filesystem::path(sm.name(fromFile)).parent_path();
  dirs.push_back(here.empty() ? "." : here.string());
  for (auto &d : opts.searchDirs)
    if (std::find(dirs.begin(), dirs.end(), d) == dirs.end()) dirs.push_back(d);
  return dirs;
}

std::string ProgramParser::program(const std::string &written, uint32_t fromFile, SourceLoc loc) {
  // `TNC:\DIR\NAME.H`: the file name; without an extension the control adds .H.
  std::string base = written.substr(written.find_last_of("\\/:") == std::string::npos ? 0 : written.find_last_of("\\/:") + 1);
  std::vector<std::string> candidates;
  if (base.find('.') != std::string::npos) candidates = {base};
  else candidates = {base + ".h", base + ".H"};
  std::vector<std::string> dirs = folders(fromFile);
  uint32_t fid = findSubprogramFile(sm, dirs, candidates, true);
  if (!fid) {
    error(loc, fmt::format("program {} not found (searched {} for {})", written, folderList(dirs), candidates[0]), "missing-subprogram");
    return {};
  }
  std::string path = std::filesystem::path(sm.name(fid)).lexically_normal().string();
  if (auto it = loaded.find(path); it != loaded.end()) return it->second;
  std::string name = std::filesystem::path(path).stem().string();
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return (char)std::toupper(c); });
  name = "PGM_" + name;
  for (int k = 2; std::any_of(loaded.begin(), loaded.end(), [&](auto &e) { return e.second == name; }); ++k)
    name = fmt::format("{}_{}", name, k);
  loaded[path] = name;
  FileParser fp(*this, fid, name, false);
  fp.contourProgram = loadingContourProgram;
  loadingContourProgram = false;
  if (!fp.run()) ok = false;
  fp.fn.dialect = ir::Dialect::Unknown;
  done.push_back(std::move(fp.fn));
  return name;
}

bool parseHeidenhainProgram(SourceManager &sm, uint32_t fileId, const HeiOptions &opts, Diagnostics &diags, ir::Module &out) {
  out.dialect = ir::Dialect::Heidenhain;
  out.name = sm.name(fileId);
  ProgramParser pp(sm, opts, diags);
  FileParser main(pp, fileId, "main", true);
  bool ok = main.run();
  std::vector<std::pair<const char *, double>> globals;  // name, initial value
  if (pp.polar)
    for (const char *g : {kCcX, kCcY, kPr, kPa}) globals.push_back({g, 0});
  if (pp.fauto) globals.push_back({kFauto, 0});
  if (pp.surface) globals.push_back({kSurface, 0});
  if (pp.global125) globals.push_back({kGlobal125, 0});
  if (pp.callPat) globals.push_back({kCallLevel, 0});
  if (pp.callFeed) globals.push_back({kModalFeed, 0});
  if (pp.approach)
    for (const char *const *v = kApproachVars; *v; ++v) globals.push_back({*v, 0});
  if (pp.frames) {
    for (const char *g : {kShiftX, kShiftY, kShiftZ, kRot, kMirror[0], kMirror[1], kAxisCc[0], kAxisCc[1], kAxisCc[2]})
      globals.push_back({g, 0});
    for (const char *g : {kScl, kAxisScl[0], kAxisScl[1], kAxisScl[2]}) globals.push_back({g, 1});
  }
  for (const std::string &v : pp.probeVars) globals.push_back({v.c_str(), 0});
  for (const std::string &v : pp.slVars) globals.push_back({v.c_str(), 0});
  for (const std::string &v : pp.globalDefVars) globals.push_back({v.c_str(), globalDefUnset()});
  std::vector<Op> decls;
  for (auto [g, init] : globals) {
    Op d(OpKind::Declare, {});
    d.set("var", hglobal(g));
    d.set("type", Expr::symbol("real"));
    d.set("init", Expr::number(init, ir::Type::Real));
    decls.push_back(std::move(d));
  }
  main.fn.body.insert(main.fn.body.begin(), std::make_move_iterator(decls.begin()), std::make_move_iterator(decls.end()));
  out.functions.clear();
  out.functions.push_back(std::move(main.fn));
  for (auto &f : pp.done) out.functions.push_back(std::move(f));
  return ok && pp.ok;
}

}  // namespace ncc::hei
