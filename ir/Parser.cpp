// Parses the NC IR text form written by Printer.cpp (grammar in docs/IR.md, "Text form").
// Bad input gives one diagnostic at the offending line:col of the .ncir text and `false`;
// nesting depth is bounded so hostile input cannot exhaust the stack.
#include "ir/IRText.h"
#include "ir/TextQuote.h"
#include "ir/NCIR.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <deque>
#include <cstdlib>
#include <map>

namespace ncc::ir {

namespace {

constexpr unsigned kMaxDepth = 200;

enum class Tok : uint8_t { End, Ident, Number, String, QSymbol, Punct };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // identifier, punctuation char, decoded string, number spelling
  double num = 0;
  bool isInt = false;
  bool adjacent = false;  // no whitespace before this token
  uint32_t line = 0, col = 0;
};

struct ParseError {
  uint32_t line, col;
  std::string message;
};

class Lexer {
public:
  explicit Lexer(std::string_view s) : s_(s) {}

  // Returns the next token; at the end of input, End tokens forever.
  Token next() {
    bool ws = skipSpace();
    Token t;
    t.adjacent = !ws;
    t.line = line_;
    t.col = (uint32_t)(pos_ - lineStart_ + 1);
    if (pos_ >= s_.size()) return t;
    char c = s_[pos_];
    if (text::isIdentStart(c)) {
      size_t b = pos_;
      while (pos_ < s_.size() && text::isIdentChar(s_[pos_])) ++pos_;
      t.kind = Tok::Ident;
      t.text = std::string(s_.substr(b, pos_ - b));
      if (t.text == "sym" && pos_ < s_.size() && s_[pos_] == '"') {
        t.kind = Tok::QSymbol;
        t.text = readString(t);
      }
    } else if (isDigit(c) || (c == '-' && pos_ + 1 < s_.size() && isDigit(s_[pos_ + 1]))) {
      readNumber(t);
    } else if (c == '"') {
      t.kind = Tok::String;
      t.text = readString(t);
    } else if (std::string_view("()[]{}=,@#%$:").find(c) != std::string_view::npos) {
      t.kind = Tok::Punct;
      t.text = std::string(1, c);
      ++pos_;
    } else {
      throw ParseError{t.line, t.col, printableChar(c)};
    }
    return t;
  }

private:
  std::string_view s_;
  size_t pos_ = 0, lineStart_ = 0;
  uint32_t line_ = 1;

  static bool isDigit(char c) { return c >= '0' && c <= '9'; }

  static std::string printableChar(char c) {
    unsigned char u = (unsigned char)c;
    if (u >= 0x21 && u < 0x7f) return fmt::format("unexpected character '{}'", c);
    return fmt::format("unexpected byte 0x{:02x}", u);
  }

  // Skips blanks, newlines and `;` comments; returns whether anything was skipped.
  bool skipSpace() {
    size_t start = pos_;
    while (pos_ < s_.size()) {
      char c = s_[pos_];
      if (c == '\n') {
        ++pos_;
        ++line_;
        lineStart_ = pos_;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++pos_;
      } else if (c == ';') {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
      } else {
        break;
      }
    }
    return pos_ != start;
  }

  void readNumber(Token &t) {
    size_t b = pos_;
    bool isInt = true;
    if (s_[pos_] == '-') ++pos_;
    while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;
    if (pos_ < s_.size() && s_[pos_] == '.') {
      isInt = false;
      ++pos_;
      while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      size_t e = pos_ + 1;
      if (e < s_.size() && (s_[e] == '+' || s_[e] == '-')) ++e;
      if (e < s_.size() && isDigit(s_[e])) {
        isInt = false;
        pos_ = e;
        while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;
      }
    }
    if (pos_ < s_.size() && text::isIdentChar(s_[pos_]))
      throw ParseError{t.line, t.col, "malformed number"};
    t.kind = Tok::Number;
    t.text = std::string(s_.substr(b, pos_ - b));
    t.isInt = isInt;
    t.num = std::strtod(t.text.c_str(), nullptr);  // overflow gives ±inf, which is what we want
  }

  // At the opening quote; returns the decoded text.
  std::string readString(const Token &t) {
    std::string o;
    ++pos_;
    for (;;) {
      if (pos_ >= s_.size() || s_[pos_] == '\n') throw ParseError{t.line, t.col, "unterminated string"};
      char c = s_[pos_++];
      if (c == '"') return o;
      if (c != '\\') {
        o += c;
        continue;
      }
      uint32_t ecol = (uint32_t)(pos_ - lineStart_);
      const char *error = nullptr;
      if (!ncc::text::decodeEscape(s_, pos_, o, error)) throw ParseError{line_, ecol, error};
    }
  }
};

const char *tokDescription(const Token &t) {
  switch (t.kind) {
  case Tok::End: return "end of input";
  case Tok::Ident: return "identifier";
  case Tok::Number: return "number";
  case Tok::String: return "string";
  case Tok::QSymbol: return "symbol";
  case Tok::Punct: return "punctuation";
  }
  return "token";
}

class Parser {
public:
  Parser(std::string_view text, SourceManager &sm) : lx_(text), sm_(sm) {}

  void parseModule(Module &m) {
    expectIdent("module");
    m.name = expectString("module name");
    if (isIdent("dialect")) {
      next();
      expectPunct('=');
      Token d = expectKind(Tok::Ident, "dialect name");
      if (d.text == "unknown") m.dialect = Dialect::Unknown;
      else if (!dialectFromName(d.text, m.dialect)) fail(d, fmt::format("unknown dialect '{}'", d.text));
    }
    while (isIdent("source")) parseSource();
    while (isIdent("func")) m.functions.push_back(parseFunction(m));
    if (peek().kind != Tok::End) fail(peek(), fmt::format("expected 'func' or end of input, found {}", describe(peek())));
  }

private:
  // Tokens are lexed on demand with a small lookahead, so a large .ncir file is never held
  // as a token array.
  Lexer lx_;
  std::deque<Token> la_;
  SourceManager &sm_;
  std::map<uint64_t, uint32_t> files_;  // K -> SourceManager id
  unsigned depth_ = 0;

  struct DepthGuard {
    Parser &p;
    DepthGuard(Parser &p, const Token &at) : p(p) {
      if (++p.depth_ > kMaxDepth) p.fail(at, "nesting too deep");
    }
    ~DepthGuard() { --p.depth_; }
  };

  const Token &peek(size_t ahead = 0) {
    while (la_.size() <= ahead) la_.push_back(lx_.next());
    return la_[ahead];
  }
  Token next() {
    peek();
    Token t = std::move(la_.front());
    la_.pop_front();
    return t;
  }
  [[noreturn]] void fail(const Token &at, std::string msg) { throw ParseError{at.line, at.col, std::move(msg)}; }

  static std::string describe(const Token &t) {
    if (t.kind == Tok::Ident || t.kind == Tok::Punct || t.kind == Tok::Number)
      return fmt::format("'{}'", t.text.size() > 40 ? t.text.substr(0, 40) + "..." : t.text);
    return tokDescription(t);
  }

  bool isPunct(char c, size_t ahead = 0) {
    const Token &t = peek(ahead);
    return t.kind == Tok::Punct && t.text[0] == c;
  }
  bool isIdent(std::string_view s) { return peek().kind == Tok::Ident && peek().text == s; }

  void expectPunct(char c) {
    if (!isPunct(c)) fail(peek(), fmt::format("expected '{}', found {}", c, describe(peek())));
    next();
  }
  void expectIdent(std::string_view s) {
    if (!isIdent(s)) fail(peek(), fmt::format("expected '{}', found {}", s, describe(peek())));
    next();
  }
  Token expectKind(Tok k, const char *what) {
    if (peek().kind != k) fail(peek(), fmt::format("expected {}, found {}", what, describe(peek())));
    return next();
  }
  std::string expectString(const char *what) { return expectKind(Tok::String, what).text; }

  uint32_t expectUInt(const char *what) {
    Token t = expectKind(Tok::Number, what);
    if (!t.isInt || t.num < 0 || t.num > 4294967295.0) fail(t, fmt::format("{} must be a non-negative integer", what));
    return (uint32_t)t.num;
  }

  // A name: identifier or quoted string (for names that are not identifiers).
  std::string expectName(const char *what) {
    Token t = peek();
    if (t.kind != Tok::Ident && t.kind != Tok::String) fail(t, fmt::format("expected {}, found {}", what, describe(t)));
    return next().text;
  }

  void parseSource() {
    next();
    Token kt = peek();
    uint32_t k = expectUInt("source index");
    if (k == 0) fail(kt, "source index must be at least 1");
    if (files_.count(k)) fail(kt, fmt::format("source {} is defined twice", k));
    std::string path = expectString("source path");
    files_[k] = fileFor(path);
  }

  // Reuses a file the SourceManager already holds, else reads it (so diagnostics can quote
  // the line), else registers the name with no text.
  uint32_t fileFor(const std::string &path) {
    for (uint32_t i = 1; i <= sm_.fileCount(); ++i)
      if (sm_.name(i) == path) return i;
    uint32_t id = sm_.addFile(path);
    return id ? id : sm_.addBuffer(path, "");
  }

  SourceLoc parseLocOpt() {
    SourceLoc l;
    if (!(isIdent("loc") && isPunct('(', 1))) return l;
    next();
    next();
    Token kt = peek();
    uint32_t k = expectUInt("source index");
    auto it = files_.find(k);
    if (it == files_.end()) fail(kt, fmt::format("loc refers to undefined source {}", k));
    expectPunct(':');
    Token lt = peek();
    l.line = expectUInt("line");
    if (l.line == 0) fail(lt, "line must be at least 1");
    expectPunct(':');
    l.col = expectUInt("column");
    expectPunct(')');
    l.file = it->second;
    return l;
  }

  static bool typeFromText(std::string_view s, Type &out) {
    for (unsigned i = 0; i <= (unsigned)Type::Frame; ++i) {
      std::string n = typeName((Type)i);
      for (char &c : n) c = (char)(c - 'a' + 'A');
      if (s == n) {
        out = (Type)i;
        return true;
      }
    }
    return false;
  }

  Function parseFunction(const Module &m) {
    next();
    expectPunct('@');
    Token nt = peek();
    Function f;
    f.name = expectName("function name");
    if (m.find(f.name)) fail(nt, fmt::format("function '@{}' is defined twice", f.name));
    if (isPunct('(')) {  // the parameter list is optional when empty
      next();
      while (!isPunct(')')) {
        f.params.push_back(parseParam());
        if (!isPunct(',')) break;
        next();
      }
      expectPunct(')');
    }
    if (isIdent("dialect")) {  // function attributes
      next();
      expectPunct('=');
      Token d = expectKind(Tok::Ident, "dialect name");
      Dialect fd;
      if (!dialectFromName(d.text, fd)) fail(d, fmt::format("unknown dialect '{}'", d.text));
      if (fd != m.dialect) f.dialect = fd;
    }
    if (isIdent("save")) {
      next();
      f.save = true;
    }
    f.loc = parseLocOpt();
    f.body = parseRegion();
    return f;
  }

  Param parseParam() {
    Param p;
    if (isIdent("VAR")) {
      next();
      p.byRef = true;
    }
    Token tt = expectKind(Tok::Ident, "parameter type");
    if (!typeFromText(tt.text, p.type)) fail(tt, fmt::format("unknown type '{}'", tt.text));
    p.name = expectName("parameter name");
    if (isPunct('=')) {
      next();
      p.defaultValue = parseExpr();
    }
    return p;
  }

  Region parseRegion() {
    DepthGuard g(*this, peek());
    expectPunct('{');
    Region r;
    while (!isPunct('}')) {
      if (peek().kind == Tok::End) fail(peek(), "expected '}' before end of input");
      r.push_back(parseOp());
    }
    next();
    return r;
  }

  Op parseOp() {
    Token nt = peek();
    if (nt.kind != Tok::Ident) fail(nt, fmt::format("expected an op name, found {}", describe(nt)));
    Op op;
    if (!opKindFromName(nt.text, op.kind)) fail(nt, fmt::format("unknown op '{}'", nt.text));
    next();
    // Arguments: a key is an identifier or a quoted name followed by '='.
    while ((peek().kind == Tok::Ident || peek().kind == Tok::String) && isPunct('=', 1)) {
      std::string key = next().text;
      next();
      ExprPtr v = parseExpr();
      op.args.push_back({std::move(key), std::move(v)});
    }
    op.loc = parseLocOpt();
    if (isPunct('{')) {
      op.regions.push_back(parseRegion());
      while (isIdent("else")) {
        next();
        op.regions.push_back(parseRegion());
      }
    }
    return op;
  }

  ExprPtr parseIndexOpt() {
    if (!isPunct('[')) return nullptr;
    next();
    ExprPtr e;
    if (!isPunct(']')) e = parseExpr();
    expectPunct(']');
    return e;
  }
  // A named variable's indices: '[' expr {',' expr} ']' (declared arrays have up to 3).
  void parseIndices(Expr &v) {
    if (!isPunct('[')) return;
    next();
    if (isPunct(']')) {  // '[]' is no index, as for the other spaces
      next();
      return;
    }
    v.args.push_back(parseExpr());
    while (isPunct(',')) {
      next();
      v.args.push_back(parseExpr());
    }
    expectPunct(']');
  }

  ExprPtr intConst(double v) { return Expr::number(v, Type::Int); }

  ExprPtr parseExpr() {
    DepthGuard g(*this, peek());
    Token t = peek();
    switch (t.kind) {
    case Tok::Number: next(); return Expr::number(t.num, t.isInt ? Type::Int : Type::Real);
    case Tok::String: next(); return Expr::string(t.text);
    case Tok::QSymbol: next(); return Expr::symbol(t.text);
    case Tok::Ident: return parseWord();
    case Tok::End: fail(t, "expected an expression, found end of input");
    case Tok::Punct: break;
    }
    char c = t.text[0];
    if (c == '(') return parseCompound();
    if (c == '#') {
      next();
      if (isPunct('[')) return Expr::var(VarSpace::Numbered, "", parseIndexOpt());
      Token n = expectKind(Tok::Number, "parameter number or '['");
      if (!n.isInt) fail(n, "parameter number must be an integer");
      return Expr::var(VarSpace::Numbered, "", intConst(n.num));
    }
    if (c == '%') {
      next();
      VarSpace sp = VarSpace::Local;
      if (isPunct('%') && peek().adjacent) {
        next();
        sp = VarSpace::Global;
      }
      std::string name = expectName("variable name");
      ExprPtr v = Expr::var(sp, std::move(name));
      parseIndices(*v);
      return v;
    }
    if (c == '$') {
      next();
      std::string name = expectName("system variable name");
      ExprPtr v = Expr::var(VarSpace::System, std::move(name));
      parseIndices(*v);  // a family's indices ($_work_offset[1, X])
      return v;
    }
    fail(t, fmt::format("expected an expression, found {}", describe(t)));
  }

  // A bare word: keyword, parameter (R5, QL[..]) or symbol.
  ExprPtr parseWord() {
    Token t = next();
    const std::string &w = t.text;
    if (w == "true" || w == "false") return Expr::boolean(w == "true");
    if (w == "vacant") return Expr::vacant();
    if (w == "nan") return Expr::number(std::nan(""), Type::Real);
    VarSpace sp;
    unsigned n = text::paramPrefix(w, sp);
    if (n && text::looksLikeParam(w)) {
      std::string prefix = sp == VarSpace::QParam ? w.substr(0, n) : "";
      if (w.size() > n) return Expr::var(sp, prefix, intConst(std::strtod(w.c_str() + n, nullptr)));
      if (isPunct('[')) return Expr::var(sp, prefix, parseIndexOpt());
    }
    return Expr::symbol(w);
  }

  // (op a b) or (FUNC a ...)
  ExprPtr parseCompound() {
    next();
    Token h = peek();
    if (h.kind != Tok::Ident && h.kind != Tok::String)
      fail(h, fmt::format("expected an operator or function name, found {}", describe(h)));
    next();
    std::vector<ExprPtr> args;
    while (!isPunct(')')) {
      if (peek().kind == Tok::End) fail(peek(), "expected ')' before end of input");
      args.push_back(parseExpr());
    }
    next();
    OpCode op = OpCode::None;
    if (h.kind == Tok::Ident)
      for (unsigned i = 1; i <= (unsigned)OpCode::BXor; ++i)
        if (h.text == opCodeName((OpCode)i)) op = (OpCode)i;
    if (op == OpCode::None) return Expr::call(h.text, std::move(args));
    if (args.size() == 1) return Expr::unary(op, std::move(args[0]));
    if (args.size() == 2) return Expr::binary(op, std::move(args[0]), std::move(args[1]));
    fail(h, fmt::format("operator '{}' takes 1 or 2 operands, found {}", h.text, args.size()));
  }
};

// Expressions carry the loc of the op they belong to, so evaluation errors point at the source.
void setExprLocs(Expr *e, SourceLoc l) {
  if (!e) return;
  e->loc = l;
  for (auto &a : e->args) setExprLocs(a.get(), l);
}
void setLocs(Region &r) {
  for (auto &op : r) {
    for (auto &a : op.args) setExprLocs(a.value.get(), op.loc);
    for (auto &sub : op.regions) setLocs(sub);
  }
}

}  // namespace

bool parseModule(std::string_view text, uint32_t fileId, SourceManager &sm, Diagnostics &diags, Module &out) {
  try {
    Parser p(text, sm);
    Module m;
    p.parseModule(m);
    for (auto &f : m.functions) {
      for (auto &prm : f.params) setExprLocs(prm.defaultValue.get(), f.loc);
      setLocs(f.body);
    }
    out = std::move(m);
    return true;
  } catch (const ParseError &e) {
    diags.error(SourceLoc{fileId, e.line, e.col}, e.message);
    return false;
  }
}

}  // namespace ncc::ir
