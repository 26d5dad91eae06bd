// Prints NC IR in its generic text form (see docs/IR.md, "Text form"). The printer has no
// per-op code: every op prints as `name key=expr... loc(K:line:col) { region } else { region }`.
#include "ir/IRText.h"
#include "ir/TextQuote.h"
#include "ir/NCIR.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <map>

namespace ncc::ir {

namespace {

std::string quote(std::string_view s) { return ncc::text::quoted(s); }

// A name after a sigil (%, %%, $, @) or as a key: bare when it is an identifier.
std::string nameText(std::string_view s) { return text::isIdent(s) ? std::string(s) : quote(s); }

// Shortest text that reads back as the same double, always with '.' or an exponent so the
// parser types it Real. Infinities print as an overflowing literal, which strtod reads back.
std::string realText(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-1e999" : "1e999";
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string numberText(const Expr &e) {
  if (e.type == Type::Int && std::isfinite(e.num) && std::fabs(e.num) < 9e18 &&
      e.num == (double)(int64_t)e.num)
    return fmt::format("{}", (int64_t)e.num);
  return realText(e.num);
}

void printExprTo(const Expr *e, std::string &o);

void printIndex(const Expr &e, std::string &o) {
  if (e.args.empty() || !e.args[0]) {
    o += "[]";
    return;
  }
  o += '[';
  for (size_t i = 0; i < e.args.size(); ++i) {
    if (i) o += ", ";
    printExprTo(e.args[i].get(), o);
  }
  o += ']';
}

void printVar(const Expr &e, std::string &o) {
  const Expr *idx = e.args.empty() ? nullptr : e.args[0].get();
  switch (e.space) {
  case VarSpace::Numbered:
  case VarSpace::RParam:
  case VarSpace::QParam: {
    std::string prefix = e.space == VarSpace::Numbered ? "#" : e.space == VarSpace::RParam ? "R" : e.str;
    // A QParam prefix other than Q/QL/QR/QS cannot be written: print a form the parser
    // rejects rather than one that reads back as something else.
    if (e.space == VarSpace::QParam && prefix != "Q" && prefix != "QL" && prefix != "QR" && prefix != "QS")
      prefix = "<bad-qparam>";
    o += prefix;
    if (text::isShortIndex(idx)) o += fmt::format("{}", (int64_t)idx->num);
    else printIndex(e, o);
    return;
  }
  case VarSpace::Local: o += '%'; break;
  case VarSpace::Global: o += "%%"; break;
  case VarSpace::System: o += '$'; break;
  }
  o += nameText(e.str);
  if (idx) printIndex(e, o);
}

void printExprTo(const Expr *e, std::string &o) {
  if (!e) {
    o += "<null>";
    return;
  }
  switch (e->kind) {
  case ExprKind::Number: o += numberText(*e); return;
  case ExprKind::String: o += quote(e->str); return;
  case ExprKind::Bool: o += e->num != 0 ? "true" : "false"; return;
  case ExprKind::Symbol:
    if (text::isBareSymbol(e->str)) o += e->str;
    else o += "sym" + quote(e->str);
    return;
  case ExprKind::Vacant: o += "vacant"; return;
  case ExprKind::Var: printVar(*e, o); return;
  case ExprKind::Unary:
  case ExprKind::Binary:
  case ExprKind::Call:
    o += '(';
    if (e->kind == ExprKind::Call) o += text::isIdent(e->str) ? e->str : quote(e->str);
    else o += opCodeName(e->op);
    for (auto &a : e->args) {
      o += ' ';
      printExprTo(a.get(), o);
    }
    o += ')';
    return;
  }
}

std::string typeText(Type t) {
  std::string s = typeName(t);
  for (char &c : s) c = (char)(c - 'a' + 'A');
  return s;
}

class ModulePrinter {
public:
  ModulePrinter(const Module &m, const SourceManager *sm) : m_(m), sm_(sm) {}

  std::string run() {
    for (auto &f : m_.functions) {
      noteFile(f.loc);
      for (auto &op : f.body) collectFiles(op);
    }
    out_ += fmt::format("module {} dialect={}\n", quote(m_.name), dialectName(m_.dialect));
    for (size_t i = 0; i < files_.size(); ++i) {
      std::string path = sm_ ? sm_->name(files_[i]) : fmt::format("file{}", files_[i]);
      out_ += fmt::format("source {} {}\n", i + 1, quote(path));
    }
    for (auto &f : m_.functions) printFunction(f);
    return std::move(out_);
  }

private:
  const Module &m_;
  const SourceManager *sm_;
  std::string out_;
  std::vector<uint32_t> files_;          // text index K-1 -> file id, in order of first use
  std::map<uint32_t, unsigned> index_;   // file id -> K

  void noteFile(SourceLoc l) {
    if (!l.valid() || index_.count(l.file)) return;
    files_.push_back(l.file);
    index_[l.file] = (unsigned)files_.size();
  }
  void collectFiles(const Op &op) {
    noteFile(op.loc);
    for (auto &r : op.regions)
      for (auto &o : r) collectFiles(o);
  }

  void printLoc(SourceLoc l) {
    if (l.valid()) out_ += fmt::format(" loc({}:{}:{})", index_[l.file], l.line, l.col);
  }

  void printFunction(const Function &f) {
    out_ += "func @" + nameText(f.name);
    if (!f.params.empty()) out_ += '(';
    for (size_t i = 0; i < f.params.size(); ++i) {
      auto &p = f.params[i];
      if (i) out_ += ", ";
      if (p.byRef) out_ += "VAR ";
      out_ += typeText(p.type) + " " + nameText(p.name);
      if (p.defaultValue) {
        out_ += " = ";
        printExprTo(p.defaultValue.get(), out_);
      }
    }
    if (!f.params.empty()) out_ += ')';
    if (Dialect d = functionDialect(m_, f); d != m_.dialect) out_ += fmt::format(" dialect={}", dialectName(d));
    if (f.save) out_ += " save";
    printLoc(f.loc);
    out_ += " {\n";
    printRegion(f.body, 1);
    out_ += "}\n";
  }

  void printRegion(const Region &r, unsigned depth) {
    for (auto &op : r) printOp(op, depth);
  }

  void printOp(const Op &op, unsigned depth) {
    std::string indent(2 * depth, ' ');
    out_ += indent;
    out_ += (unsigned)op.kind < (unsigned)OpKind::Count ? opInfo(op.kind).name : "<bad-op>";
    for (auto &a : op.args) {
      out_ += ' ';
      out_ += nameText(a.key);
      out_ += '=';
      printExprTo(a.value.get(), out_);
    }
    printLoc(op.loc);
    for (size_t i = 0; i < op.regions.size(); ++i) {
      out_ += i == 0 ? " {\n" : indent + "} else {\n";
      printRegion(op.regions[i], depth + 1);
    }
    if (!op.regions.empty()) out_ += indent + "}";
    out_ += '\n';
  }
};

}  // namespace

std::string printExpr(const Expr &e) {
  std::string o;
  printExprTo(&e, o);
  return o;
}

std::string printModule(const Module &m) { return ModulePrinter(m, nullptr).run(); }

std::string printModule(const Module &m, const SourceManager &sm) { return ModulePrinter(m, &sm).run(); }

}  // namespace ncc::ir
