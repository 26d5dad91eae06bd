// PATTERN DEF (all six forms), SEL PATTERN with point tables (.pnt) and CYCL CALL PAT (seed002a
// §3.3, §3.4; manual L1160-L1676; GLOBAL DEF 125's Q345: GlobalDef.cpp). The positions are computed when the call
// runs, by the cycle library's `hei.PATTERN.…` patterns (runtime/cycles/HeiPatternDef.cpp): a
// CYCL CALL PAT is one `cycle action=call pattern=…` per pattern form (a point table: per nine
// rows).
#include "frontend/SubprogramFiles.h"
#include "frontend/heidenhain/Parser.h"
#include "ir/WordList.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace ncc::hei {

const char *const kGlobal125 = "_HEI_Q345";  // GLOBAL DEF 125's Q345
const char *const kCallLevel = "_HEI_PATZ";  // the tool-axis position at the CYCL CALL PAT

namespace {
// The forms and the words each takes (L1280-L1519); POS takes X Y Z, each also incremental.
struct Form {
  const char *word, *entry, *words;
};
const Form kForms[] = {
    {"POS", "hei.PATTERN.POS", "X Y Z"},
    {"ROW", "hei.PATTERN.ROW", "X Y D NUM ROT Z"},
    {"PAT", "hei.PATTERN.PAT", "X Y DX DY NUMX NUMY ROT ROTX ROTY Z"},
    {"FRAME", "hei.PATTERN.FRAME", "X Y DX DY NUMX NUMY ROT ROTX ROTY Z"},
    {"CIRC", "hei.PATTERN.CIRC", "X Y D START NUM Z"},
    {"PITCHCIRC", "hei.PATTERN.PITCHCIRC", "X Y D START STEP NUM Z"},
};


// The call op of one pattern form, its own arguments set.
Op patternOp(const char *entry, SourceLoc l) {
  Op o(OpKind::Cycle, l);
  o.set("pattern", Expr::string(entry, l));
  o.set("action", Expr::symbol("call", l));
  return o;
}

// Nine positions per op (the POS pattern's slots): X1 Y1 Z1 …
void addPositions(std::vector<Op> &ops, const std::vector<std::array<ExprPtr, 3>> &pts, SourceLoc l) {
  for (size_t k = 0; k < pts.size(); ++k) {
    if (k % 9 == 0) ops.push_back(patternOp("hei.PATTERN.POS", l));
    for (int c = 0; c < 3; ++c) ops.back().set(fmt::format("p.{}{}", "XYZ"[c], k % 9 + 1), pts[k][c]->clone());
  }
}
}  // namespace

// PATTERN DEF, then one or more forms: `POS1 (X+10 Y+10 Z+0)` … `POS9`, `ROW1 (X… Y… D… NUM…
// ROT… Z…)` and the others, each with its data in parentheses (on its own line or the same).
// [model] several forms in one PATTERN DEF are machined one after the other; a POS coordinate
// left out keeps the previous position's (POS1: X and Y are required, Z is 0).
bool BlockParser::patternDef() {
  if (!expectWord("DEF")) return false;
  SourceLoc bl = loc(t_[0]);
  std::vector<Op> ops;
  std::vector<std::array<ExprPtr, 3>> pos;
  int lastPos = 0;
  if (atEnd()) return fail(tok(), "PATTERN DEF needs a pattern (POS1 (…), ROW1 (…), PAT1, FRAME1, CIRC1, PITCHCIRC1)");
  while (!atEnd()) {
    const Token &w = tok();
    const Form *form = nullptr;
    for (auto &f : kForms)
      if (w.isWord(f.word)) form = &f;
    if (!form) return fail(w, fmt::format("'{}' is no PATTERN DEF form (POS ROW PAT FRAME CIRC PITCHCIRC)", w.text));
    ++i_;
    const Token &n = tok();
    if (n.kind != Tok::Number || !n.isInt || n.num < 1 || n.num > 9)
      return fail(n, fmt::format("{} needs its number 1..9 (like {}1)", form->word, form->word));
    bool isPos = form->entry == kForms[0].entry;
    if (isPos && (int)n.num != lastPos + 1)
      return fail(n, fmt::format("POS{}: the positions are numbered POS1, POS2, … in order", n.text));
    if (isPos) lastPos = (int)n.num;
    ++i_;
    if (!tok().is("(")) return fail(tok(), fmt::format("'(' expected after {}{}", form->word, n.text));
    ++i_;
    Op o = patternOp(form->entry, loc(w));
    std::array<ExprPtr, 3> at;
    while (!tok().is(")")) {
      const Token &k = tok();
      if (atEnd()) return fail(k, fmt::format("')' expected to close {}{}", form->word, n.text));
      std::string name = k.text;
      bool inc = isPos && name.size() == 2 && name[0] == 'I';
      if (inc) name.erase(0, 1);
      if (k.kind != Tok::Word || !inWordList(form->words, name))
        return fail(k, fmt::format("'{}' is not a word of {} (it takes: {})", k.text, form->word, form->words));
      if (inc && lastPos == 1) return fail(k, "POS1 is absolute (L1283): no incremental coordinates");
      ++i_;
      ExprPtr v = signedValue();
      if (!v) return false;
      if (isPos) {
        int c = name[0] - 'X';
        if (at[c]) return fail(k, fmt::format("{} twice in POS{}", name, lastPos), "duplicate-word");
        at[c] = inc ? Expr::binary(ir::OpCode::Add, pos.back()[c]->clone(), std::move(v), loc(k)) : std::move(v);
      } else {
        if (o.get("p." + name)) return fail(k, fmt::format("{} twice in {}{}", name, form->word, n.text), "duplicate-word");
        o.set("p." + name, std::move(v));
      }
    }
    ++i_;  // )
    if (!isPos) {
      ops.push_back(std::move(o));
      continue;
    }
    for (int c = 0; c < 3; ++c)
      if (!at[c]) {
        if (lastPos == 1 && c < 2) return fail(w, fmt::format("POS1 needs {}", "XY"[c]), "missing-word");
        at[c] = lastPos == 1 ? num(0, loc(w)) : pos.back()[c]->clone();
      }
    pos.push_back(std::move(at));
  }
  addPositions(ops, pos, bl);
  f_.pattern = std::move(ops);
  return true;
}

namespace {
// A point table (L1521-L1606): a header line (`BEGIN TAB1 .PNT MM`, the manual prints `TAB1 PNT
// MM`), the column names (NR X Y Z, optionally FADE and CLEARANCE), a row per point, `[END]`.
// A FADE of Y or 1 hides the point. A row's clearance height is refused: it changes the height
// between all points (L1664-L1676), which is not simulated yet.
bool readPointTable(ProgramParser &pp, uint32_t fid, bool inchProgram, std::vector<std::array<double, 3>> &out) {
  std::string_view text = pp.sm.text(fid);
  std::vector<std::string> cols;
  bool header = false, ended = false;
  uint32_t line = 0;
  for (size_t at = 0; at < text.size();) {
    size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string row(text.substr(at, end - at));
    at = end + 1;
    ++line;
    if (!row.empty() && row.back() == '\r') row.pop_back();
    if (row.empty() || row[0] == ';') continue;
    std::transform(row.begin(), row.end(), row.begin(), [](unsigned char c) { return (char)std::toupper(c); });
    SourceLoc l{fid, line, 1};
    std::istringstream in(row);
    std::vector<std::string> f;
    for (std::string s; in >> s;) f.push_back(s);
    if (f.empty()) continue;
    if (ended) return pp.error(l, "text after [END] in a point table", "syntax");
    if (!header) {
      if (row.find("PNT") == std::string::npos || (f.back() != "MM" && f.back() != "INCH"))
        return pp.error(l, "a point table starts with its header (BEGIN NAME .PNT MM)", "syntax");
      if ((f.back() == "INCH") != inchProgram)
        return pp.error(l, "a point table in other units than the program is not simulated", "unsupported-code");
      header = true;
      continue;
    }
    if (cols.empty()) {
      cols = f;
      for (auto &c : cols)
        if (c != "NR" && c != "X" && c != "Y" && c != "Z" && c != "FADE" && c != "CLEARANCE")
          return pp.error(l, fmt::format("point-table column {} is not simulated (NR X Y Z FADE CLEARANCE)", c), "unsupported-code");
      if (std::find(cols.begin(), cols.end(), "X") == cols.end() || std::find(cols.begin(), cols.end(), "Y") == cols.end())
        return pp.error(l, "a point table needs the columns X and Y", "syntax");
      continue;
    }
    if (f[0] == "[END]") {
      ended = true;
      continue;
    }
    if (f.size() > cols.size()) return pp.error(l, "more values than columns in a point-table row", "syntax");
    std::array<double, 3> p{0, 0, 0};
    bool hidden = false;
    for (size_t k = 0; k < f.size(); ++k) {
      const std::string &c = cols[k];
      if (c == "FADE") {
        hidden = f[k] == "Y" || f[k] == "1";
        continue;
      }
      if (c == "CLEARANCE")
        return pp.error(l, "a point's clearance height (CLEARANCE) is not simulated yet", "unsupported-code");
      char *e = nullptr;
      double v = std::strtod(f[k].c_str(), &e);
      if (e == f[k].c_str() || *e) return pp.error(l, fmt::format("'{}' is not a number (column {})", f[k], c), "syntax");
      if (c != "NR") p[c[0] - 'X'] = v;
    }
    if (f.size() < 3) return pp.error(l, "a point-table row needs its X and Y", "syntax");
    if (!hidden) out.push_back(p);
  }
  if (!ended) return pp.error({fid, line, 1}, "a point table ends with [END]", "syntax");
  if (out.empty()) return pp.error({fid, 1, 1}, "the point table has no (visible) point", "syntax");
  return true;
}
}  // namespace

// SEL PATTERN "name": the point table in the program's folder (then each --include folder),
// `.PNT` added when the name has no extension. [model] ncc reads it when the program is compiled.
bool BlockParser::select() {
  const Token &what = tok();
  if (what.isWord("CONTOUR")) return selContour();
  if (!what.isWord("PATTERN"))
    return fail(what, fmt::format("'SEL {}' is not simulated yet (a Klartext function ncc does not run)", what.text), "unsupported-code");
  ++i_;
  const Token &name = tok();
  if (name.kind != Tok::String) return fail(name, "SEL PATTERN needs the table's name in quotes");
  std::string written = name.text;
  ++i_;
  if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' after SEL PATTERN", tok().text));
  size_t cut = written.find_last_of("\\/:");
  std::string base = cut == std::string::npos ? written : written.substr(cut + 1);
  std::vector<std::string> candidates = base.find('.') != std::string::npos
                                            ? std::vector<std::string>{base}
                                            : std::vector<std::string>{base + ".pnt", base + ".PNT"};
  std::vector<std::string> dirs = f_.pp.folders(f_.file);
  uint32_t fid = findSubprogramFile(f_.pp.sm, dirs, candidates, true);
  if (!fid)
    return f_.error(loc(name), fmt::format("point table {} not found (searched {} for {})", written, folderList(dirs), candidates[0]),
                    "missing-subprogram");
  std::vector<std::array<double, 3>> pts;
  if (!readPointTable(f_.pp, fid, f_.inch, pts)) return false;
  std::vector<std::array<ExprPtr, 3>> exprs;
  for (auto &p : pts) exprs.push_back({num(p[0], loc(name)), num(p[1], loc(name)), num(p[2], loc(name))});
  std::vector<Op> ops;
  addPositions(ops, exprs, loc(t_[0]));
  f_.pattern = std::move(ops);
  return true;
}

// CYCL CALL PAT [F|FMAX|FAUTO] [M…] (L1607-L1623): the stored cycle at every position of the
// last PATTERN DEF or SEL PATTERN of this file; F is the feed between the positions only (none:
// the programmed feed). [model] The pattern is the last one above the call in the file (a table
// selected in a called program, L1661, is not yet seen by the caller: the call is an error).
bool BlockParser::cyclCallPat() {
  SourceLoc bl = loc(t_[0]);
  ++i_;  // PAT
  PathWords w;
  if (!words(w, kFeed | kM, "CYCL CALL PAT")) return false;
  if (f_.pattern.empty())
    return fail(t_[0], "CYCL CALL PAT without a PATTERN DEF or SEL PATTERN before it in this program", "cycle-invalid");
  if ((w.feed || w.fauto) && !inchFeed(w.feedLoc)) return false;
  ExprPtr feed = w.fauto ? hglobal(kFauto, w.feedLoc) : std::move(w.feed);
  if (w.fauto) f_.pp.fauto = true;
  bool fmax = w.fmax;
  w.fauto = w.fmax = false;  // the feed is the call's, not modal
  if (!emitBefore(w)) return false;
  bool split = f_.pattern.size() > 1;
  if (split) {
    f_.pp.callPat = true;
    out().push_back(assignOp(hglobal(kCallLevel, bl), Expr::var(ir::VarSpace::System, "_z", nullptr, bl), bl));
  }
  for (size_t k = 0; k < f_.pattern.size(); ++k) {
    Op o = f_.pattern[k].clone();
    o.loc = bl;
    if (feed) o.set("p.F", feed->clone());
    if (fmax) o.set("p.FMAX", num(1, bl));
    if (f_.pp.global125) o.set("p.Q345", hglobal(kGlobal125, bl));
    if (k > 0) o.set("p.H", hglobal(kCallLevel, bl));
    out().push_back(std::move(o));
  }
  moved_ = false;
  return emitAfter(w);
}

}  // namespace ncc::hei
