// Contour preparation (SIN-CON-01 … -06, SIN-OPS-47; manual ch. 18, L27015-L27731;
// docs/SINUMERIK.md "Contour tables"):
//   CONTPRON(TAB, MODE, NN [, DIR]) … EXECUTE(ERR)   the 11-column table of the blocks between
//   CONTDCON(TAB [, DIR]) … EXECUTE(ERR)             the 6-column coded table
//   EXECTAB(TAB[n])                                   one element of a CONTPRON table as a move
//   S = INTERSEC(T1[a], T2[b], P, MODE)               the intersection of two elements
//   S = CALCDAT(PT, NUM, RES)                         the circle through 3 or 4 points
// The blocks between CONTPRON and EXECUTE run into a contour capture (docs/IR.md §5.6,
// `use=sin_table`): the executor, which has the exact geometry (RND, CHF, CIP, CT, CR=), builds
// the table at EXECUTE (runtime/ExecutorContourTable.cpp) and the program copies it from
// `$_sin_table[i, j]` into its array, every row the array has. INTERSEC and CALCDAT are pure
// geometry: the builtins SIN_INTERSEC and SIN_CALCDAT (ir/ContourMath.cpp) of both engines.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

namespace {
// The copy at EXECUTE is unrolled, one assignment per element: a bound on the program's size.
constexpr uint32_t kMaxTableRows = 1000;
// `$_sin_table[0, 16]`: the undercut elements of the last CONTPRON; `[1, 16]`: EXECUTE's error value.
constexpr int kSummaryColumn = 16;

ExprPtr num(double v, SourceLoc l) { return Expr::number(v, ir::Type::Int, l); }

ExprPtr tableVar(const std::string &name, const VarDecl &d, ExprPtr row, ExprPtr col, SourceLoc l) {
  auto v = Expr::var(d.global ? ir::VarSpace::Global : ir::VarSpace::Local, name, nullptr, l);
  v->args.push_back(std::move(row));
  if (col) v->args.push_back(std::move(col));
  return v;
}

ExprPtr sinTable(ExprPtr row, ExprPtr col, SourceLoc l) {
  auto v = Expr::var(ir::VarSpace::System, "_sin_table", nullptr, l);
  v->args.push_back(std::move(row));
  v->args.push_back(std::move(col));
  return v;
}

// G70 G71 G700 G710 as the tables code them (L27432-L27434): 0 … 3.
int unitsCode(std::string_view g) {
  static const char *kCodes[] = {"G70", "G71", "G700", "G710"};
  for (int i = 0; i < 4; ++i)
    if (g == kCodes[i]) return i;
  return -1;
}
}  // namespace

void FunctionParser::noteUnits(std::string_view gcode) {
  if (int c = unitsCode(gcode); c >= 0) staticUnits = c;
}

// A declared REAL array with two dimensions and `cols` columns, named by the token at the cursor
// (consumed); null with an error.
const VarDecl *BlockParser::contourTableArg(const char *kw, int cols, std::string &name) {
  const Token &t = tok();
  auto d = t.kind == Tok::Name ? f_.vars.find(t.text) : f_.vars.end();
  if (d == f_.vars.end() || d->second.type != ir::Type::Real || d->second.dims.size() != 2 ||
      (cols > 0 && d->second.dims[1] != (uint32_t)cols)) {
    fail(t, cols > 0 ? fmt::format("{}'s table must be a REAL array [rows, {}]", kw, cols)
                     : fmt::format("{}'s table must be a REAL array [rows, columns]", kw));
    return nullptr;
  }
  name = t.text;
  ++i_;
  return &d->second;
}

// Arguments after the table: expressions, empty positions null.
bool BlockParser::contourArgs(std::vector<ExprPtr> &out, std::vector<const Token *> &at) {
  while (tok().is(",")) {
    ++i_;
    at.push_back(&tok());
    if (tok().is(",") || tok().is(")")) {
      out.push_back(nullptr);
      continue;
    }
    ExprPtr e = expr(0);
    if (!e) return false;
    out.push_back(std::move(e));
  }
  return expect(")");
}

bool BlockParser::contourStatement(const std::string &kw) {
  const bool prepare = kw == "CONTPRON" || kw == "CONTDCON";
  if (!prepare && kw != "EXECUTE" && kw != "EXECTAB") return false;
  if (f_.vars.count(kw) || !peek().is("(")) return false;
  if (kw == "EXECUTE" && f_.contourTable.name.empty()) return false;  // not ours (CPROTDEF … EXECUTE)
  const Token &at = tok();
  SourceLoc l = loc(at);
  i_ += 2;
  if (kw == "EXECTAB") return exectab(at);
  if (kw == "EXECUTE") return executeTable(at);
  if (!f_.contourTable.name.empty())
    return fail(at, fmt::format("{} inside the contour preparation opened at line {} (EXECUTE ends it)", kw,
                                f_.contourTable.loc.line));
  if (!f_.ctl.empty())
    return fail(at, fmt::format("{} inside a control structure: its EXECUTE must follow in the same block sequence",
                                kw),
                "unsupported-code");
  const bool coded = kw == "CONTDCON";
  std::string name;
  const VarDecl *d = contourTableArg(kw.c_str(), coded ? 6 : 11, name);
  if (!d) return false;
  std::vector<ExprPtr> args;
  std::vector<const Token *> argAt;
  if (!contourArgs(args, argAt)) return false;
  const size_t most = coded ? 1 : 3;
  if (args.size() > most) return fail(*argAt[most], fmt::format("{} takes at most {} arguments", kw, most + 1));
  if (d->dims[0] > kMaxTableRows)
    return fail(at, fmt::format("{}: a table of more than {} rows is not supported", kw, kMaxTableRows),
                "unsupported-code");
  Op begin(OpKind::Contour, l);
  begin.set("action", Expr::symbol("begin", l));
  begin.set("use", Expr::symbol("sin_table", l));
  begin.set("type", num(coded ? 6 : 11, l));
  begin.set("R", num(d->dims[0], l));
  begin.set("D", num(f_.staticUnits, l));
  ExprPtr undercuts;
  if (!coded) {
    // MODE: "G" "L" "N" "P" (a CHAR), its place in "GLNP" for the executor (-1: another).
    if (args.empty() || !args[0] || !stringy(*args[0]))
      return fail(args.empty() ? tok() : *argAt[0], "CONTPRON's machining mode must be a CHAR: \"G\", \"L\", \"N\" or \"P\"");
    std::vector<ExprPtr> a;
    a.push_back(Expr::string("GLNP", l));
    a.push_back(callOf("TOUPPER", l, std::move(args[0])));
    begin.set("U", Expr::call("INDEX", std::move(a), l));
    if (args.size() < 2 || !args[1] || args[1]->kind != ir::ExprKind::Var)
      return fail(args.size() < 2 ? tok() : *argAt[1], "CONTPRON's third argument must be a variable (the undercut count)");
    undercuts = std::move(args[1]);
    if (args.size() > 2 && args[2]) begin.set("W", std::move(args[2]));
  } else if (!args.empty() && args[0]) {
    begin.set("W", std::move(args[0]));
  }
  pre_.push_back(std::move(begin));
  f_.contourTable.name = name;
  f_.contourTable.decl = *d;
  f_.contourTable.undercuts = std::move(undercuts);
  f_.contourTable.coded = coded;
  f_.contourTable.loc = l;
  return true;
}

// EXECUTE(ERR): the capture ends, the executor builds the table; the array gets every row.
bool BlockParser::executeTable(const Token &at) {
  SourceLoc l = loc(at);
  ExprPtr err;
  if (!tok().is(")")) {
    err = expr(0);
    if (!err) return false;
    if (err->kind != ir::ExprKind::Var) return fail(at, "EXECUTE's argument must be a variable (the error value)");
  }
  if (!expect(")")) return false;
  if (!f_.ctl.empty())
    return fail(at, "EXECUTE of a contour preparation inside a control structure", "unsupported-code");
  auto &tab = f_.contourTable;
  Op end(OpKind::Contour, l);
  end.set("action", Expr::symbol("end", l));
  end.set("use", Expr::symbol("sin_table", l));
  pre_.push_back(std::move(end));
  const uint32_t rows = tab.decl.dims[0], cols = tab.decl.dims[1];
  for (uint32_t i = 0; i < rows; ++i)
    for (uint32_t j = 0; j < cols; ++j)
      pre_.push_back(assignOp(tableVar(tab.name, tab.decl, num(i, l), num(j, l), l),
                              sinTable(num(i, l), num(j, l), l), l));
  if (tab.undercuts) pre_.push_back(assignOp(std::move(tab.undercuts), sinTable(num(0, l), num(kSummaryColumn, l), l), l));
  if (err) pre_.push_back(assignOp(std::move(err), sinTable(num(1, l), num(kSummaryColumn, l), l), l));
  tab = {};
  return true;
}

// EXECTAB(TAB[n]): the element's code, end point and centre (columns 2, 5, 6, 9, 10) to the
// executor, which moves as the element says in the active plane.
bool BlockParser::exectab(const Token &at) {
  SourceLoc l = loc(at);
  std::string name;
  const VarDecl *d = contourTableArg("EXECTAB", 11, name);
  if (!d) return false;
  if (!expect("[")) return false;
  ExprPtr row = expr(0);
  if (!row || !expect("]") || !expect(")")) return false;
  Op run(OpKind::Contour, l);
  run.set("action", Expr::symbol("run", l));
  run.set("use", Expr::symbol("sin_table", l));
  static const struct { const char *key; int col; } kCols[] = {{"type", 2}, {"U", 5}, {"W", 6}, {"D", 9}, {"E", 10}};
  for (auto &c : kCols) run.set(c.key, tableVar(name, *d, row->clone(), num(c.col, l), l));
  pre_.push_back(std::move(run));
  return true;
}

// INTERSEC(T1[a], T2[b], P, MODE) and CALCDAT(PT, NUM, RES) as the whole value of an
// assignment: the results go to P / RES when the status is TRUE, the value is the status.
ExprPtr BlockParser::contourFunction(const Token &at) {
  SourceLoc l = loc(at);
  const bool intersec = at.text == "INTERSEC";
  i_ += 2;  // NAME (
  std::vector<ExprPtr> fnArgs;
  std::string result;
  const VarDecl *resDecl = nullptr;
  int results = 0;
  if (intersec) {
    fnArgs.push_back(nullptr);  // the selector
    fnArgs.push_back(nullptr);  // the mode
    for (int k = 0; k < 2; ++k) {
      std::string name;
      const VarDecl *d = contourTableArg("INTERSEC", 11, name);
      if (!d || !expect("[")) return nullptr;
      ExprPtr row = expr(0);
      if (!row || !expect("]") || !expect(",")) return nullptr;
      for (int col : {2, 3, 4, 5, 6, 9, 10}) fnArgs.push_back(tableVar(name, *d, row->clone(), num(col, l), l));
    }
    results = 2;
  } else {
    std::string name;
    const VarDecl *d = contourTableArg("CALCDAT", 0, name);
    if (!d || !expect(",")) return nullptr;
    const Token &nt = tok();
    ExprPtr n = expr(0);
    if (!n || !expect(",")) return nullptr;
    if (n->kind != ir::ExprKind::Number || (n->num != 3 && n->num != 4)) {
      fail(nt, "CALCDAT's number of points must be the constant 3 or 4", "unsupported-code");
      return nullptr;
    }
    if (d->dims[0] < n->num || d->dims[1] < 2) {
      fail(nt, fmt::format("CALCDAT: {} holds {} points of {} coordinates, {} points of 2 are needed", name, d->dims[0],
                           d->dims[1], n->num));
      return nullptr;
    }
    fnArgs.push_back(nullptr);
    fnArgs.push_back(num(n->num, l));
    for (int p = 0; p < (int)n->num; ++p)
      for (int c = 0; c < 2; ++c) fnArgs.push_back(tableVar(name, *d, num(p, l), num(c, l), l));
    results = 3;
  }
  const Token &rt = tok();
  auto rd = rt.kind == Tok::Name ? f_.vars.find(rt.text) : f_.vars.end();
  if (rd == f_.vars.end() || rd->second.type != ir::Type::Real || rd->second.dims.size() != 1 ||
      rd->second.dims[0] < (uint32_t)results) {
    fail(rt, fmt::format("{}'s result must be a REAL array of at least {} elements", at.text, results));
    return nullptr;
  }
  result = rt.text;
  resDecl = &rd->second;
  ++i_;
  if (intersec) {
    if (!expect(",")) return nullptr;
    ExprPtr mode = expr(0);
    if (!mode) return nullptr;
    fnArgs[1] = std::move(mode);
  }
  if (!expect(")")) return nullptr;
  const char *fn = intersec ? "SIN_INTERSEC" : "SIN_CALCDAT";
  auto call = [&](int sel) {
    std::vector<ExprPtr> a;
    a.push_back(num(sel, l));
    for (size_t i = 1; i < fnArgs.size(); ++i) a.push_back(fnArgs[i]->clone());
    return Expr::call(fn, std::move(a), l);
  };
  // if status { RES[k] = fn(k, …) }; the value: status == 1 (a BOOL)
  Op iff(OpKind::If, l);
  iff.set("cond", Expr::binary(ir::OpCode::Eq, call(results), num(1, l), l));
  iff.regions.emplace_back();
  for (int k = 0; k < results; ++k) {
    auto target = Expr::var(resDecl->global ? ir::VarSpace::Global : ir::VarSpace::Local, result, num(k, l), l);
    iff.regions[0].push_back(assignOp(std::move(target), call(k), l));
  }
  pre_.push_back(std::move(iff));
  return Expr::binary(ir::OpCode::Eq, call(results), num(1, l), l);
}

}  // namespace ncc::sin
