// Lexing and parsing of one ISO block (= one line): words, nested comments, block skip, Macro B
// statements and expressions. Works on the line's bytes in place; the only allocations are the
// AST nodes themselves.
#include "frontend/iso/ExactPow10.h"
#include "frontend/iso/Syntax.h"
#include "ir/Builtins.h"

#include <charconv>
#include <fmt/format.h>
#include "ir/SystemVars.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace ncc::iso {

using ir::Expr;
using ir::ExprPtr;
using ir::OpCode;

static inline bool isDigit(char c) { return c >= '0' && c <= '9'; }
static inline bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
static inline char upper(char c) { return (c >= 'a' && c <= 'z') ? (char)(c - 32) : c; }
static inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

static bool equalsUpper(std::string_view s, const char *kw) {
  size_t n = std::strlen(kw);
  if (s.size() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (upper(s[i]) != kw[i]) return false;
  return true;
}

static std::string toUpper(std::string_view s) {
  std::string r(s);
  for (auto &c : r) c = upper(c);
  return r;
}

// Printable form of a byte for messages.
static std::string showChar(char c) {
  unsigned char u = (unsigned char)c;
  if (u >= 32 && u < 127) return std::string("'") + c + "'";
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", u);
  return buf;
}

bool BlockParser::fail(const char *at, std::string msg, const char *rule) {
  if (!failed_) diags_.error(locAt(at < end_ ? at : end_), std::move(msg), rule);
  failed_ = true;
  return false;
}

void BlockParser::skipBlanks() {
  while (p_ < end_ && isBlank(*p_)) ++p_;
}

char BlockParser::peekUpper() const { return p_ < end_ ? upper(*p_) : '\0'; }

std::string_view BlockParser::readLetters() {
  const char *b = p_;
  while (p_ < end_ && isLetter(*p_)) ++p_;
  return std::string_view(b, (size_t)(p_ - b));
}

// Unsigned decimal literal: digits with at most one point ("12", "1.5", "5.", ".5").

bool BlockParser::readNumber(double &v, bool &hasPoint, bool &any) {
  // Locals in the loop: stores through the bool references and p_ would be reloaded per
  // character (a char may alias them).
  const char *b = p_, *q = p_, *end = end_;
  bool point = false;
  int digits = 0;
  // The digits as an integer and the count after the point, while they stay exact (< 2^53).
  constexpr uint64_t kExact = uint64_t(1) << 53;
  uint64_t mantissa = 0;
  int fraction = 0;
  for (; q < end; ++q) {
    if (isDigit(*q)) {
      ++digits;
      if (mantissa < kExact) mantissa = mantissa * 10 + (uint64_t)(*q - '0');
      fraction += point;
    } else if (*q == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  hasPoint = point;
  any = digits > 0;
  if (!any) return false;
  p_ = q;
  // Both operands exact and one correctly rounded division: the same double as from_chars
  // (Clinger's fast path), without its general machinery; typical NC numbers take it.
  if (mantissa < kExact && fraction <= 22) {
    v = (double)mantissa / kExactPow10[fraction];
    return true;
  }
  const char *e = p_;
  if (e[-1] == '.') --e;  // "5." : from_chars needs a digit after the point
  auto r = std::from_chars(b, e, v, std::chars_format::fixed);
  if (r.ec != std::errc() || r.ptr != e) return fail(b, "number out of range");
  return true;
}

bool BlockParser::parseComment(ParsedBlock &out) {
  const char *open = p_;
  int level = 0;
  const char *q = p_;
  for (; q < end_; ++q) {
    if (*q == '(') ++level;
    else if (*q == ')' && --level == 0) break;
  }
  if (q >= end_) return fail(open, "unterminated comment: missing ')'", "syntax");
  std::string_view text(open + 1, (size_t)(q - open - 1));
  p_ = q + 1;
  IsoComment c;
  c.loc = locAt(open);
  size_t i = 0;
  while (i < text.size() && isBlank(text[i])) ++i;
  // (MSG,text); RS274NGC also (DEBUG,text) (PRINT,text) (ABORT,text), whose #n / #<name> are
  // replaced by the values when the block runs (Lower.cpp).
  static const struct {
    const char *word, *kind;
    bool rs274;
  } kMessages[] = {{"MSG", "msg", false}, {"DEBUG", "debug", true}, {"PRINT", "print", true}, {"ABORT", "abort", true}};
  c.text = std::string(text);
  for (auto &m : kMessages) {
    size_t n = std::strlen(m.word);
    if ((m.rs274 && flavour_ != Flavour::RS274) || text.size() - i < n + 1 ||
        !equalsUpper(text.substr(i, n), m.word) || text[i + n] != ',')
      continue;
    c.message = true;
    c.kind = m.kind;
    i += n + 1;
    if (flavour_ != Flavour::RS274)  // rs274 keeps the blanks after the comma
      while (i < text.size() && isBlank(text[i])) ++i;
    c.text = std::string(text.substr(i));
    break;
  }
  out.comments.push_back(std::move(c));
  return true;
}

bool BlockParser::parseSemicolonComment(ParsedBlock &out) {
  const char *at = p_++;
  const char *b = p_, *e = end_;
  while (b < e && isBlank(*b)) ++b;
  while (e > b && isBlank(e[-1])) --e;
  p_ = end_;
  if (b == e) return true;  // a bare `;` is the Fanuc end of block
  IsoComment c;
  c.loc = locAt(at);
  c.text = std::string(b, (size_t)(e - b));
  out.comments.push_back(std::move(c));
  return true;
}

bool BlockParser::parseWordValue(IsoWord &w) {
  skipBlanks();
  bool neg = false;
  if (p_ < end_ && (*p_ == '-' || *p_ == '+')) {
    neg = *p_ == '-';
    ++p_;
    skipBlanks();
  }
  if (p_ < end_ && (isDigit(*p_) || *p_ == '.')) {
    bool any;
    if (!readNumber(w.value, w.hasPoint, any)) {
      if (!failed_) fail(p_, std::string("missing value after '") + w.letter + "'");
      return false;
    }
    if (neg) w.value = -w.value;
    return true;
  }
  bool func = p_ + 1 < end_ && isLetter(p_[0]) && isLetter(p_[1]);  // X SIN[30]
  if (p_ < end_ && (*p_ == '#' || *p_ == '[' || func)) {
    const char *at = p_;
    ExprPtr e = parsePrimary();
    if (!e) return false;
    if (neg) e = Expr::unary(OpCode::Neg, std::move(e), locAt(at));
    w.expr = std::move(e);
    return true;
  }
  return fail(p_, std::string("missing value after '") + w.letter + "'");
}

static bool parseLoopId(BlockParser &, const char *&p, const char *end, int &id) {
  while (p < end && isBlank(*p)) ++p;
  if (p >= end || !isDigit(*p)) return false;
  long v = 0;
  while (p < end && isDigit(*p) && v < 1000000) v = v * 10 + (*p++ - '0');
  id = (int)v;
  return true;
}

// Fanuc Custom Macro B accepts the first two letters of a keyword or function for the whole
// word (WH for WHILE, RO for ROUND, …). Two-letter words that are words of their own (IF, DO,
// OR, EQ, NE, GT, GE, LT, LE, LN) are not abbreviations.
static const struct {
  const char *abbrev, *word;
} kFanucAbbreviations[] = {
    {"GO", "GOTO"}, {"TH", "THEN"}, {"WH", "WHILE"}, {"EN", "END"},  {"AN", "AND"},  {"XO", "XOR"},
    {"MO", "MOD"},  {"SI", "SIN"},  {"CO", "COS"},   {"TA", "TAN"},  {"AS", "ASIN"}, {"AC", "ACOS"},
    {"AT", "ATAN"}, {"SQ", "SQRT"}, {"AB", "ABS"},   {"RO", "ROUND"}, {"FI", "FIX"}, {"FU", "FUP"},
    {"EX", "EXP"}};

std::string_view BlockParser::keyword(std::string_view w) const {
  if (flavour_ == Flavour::Fanuc && w.size() == 2)
    for (auto &a : kFanucAbbreviations)
      if (equalsUpper(w, a.abbrev)) return a.word;
  return w;
}

bool BlockParser::parseStatement(std::string_view kw, const char *at, ParsedBlock &out) {
  kw = keyword(kw);
  if (out.stmt != StmtKind::None) return fail(at, "only one macro statement is allowed per block");
  out.stmtLoc = locAt(at);
  auto gotoTarget = [&]() -> bool {
    skipBlanks();
    const char *t = p_;
    if (p_ < end_ && isDigit(*p_)) {
      double v;
      bool pt, any;
      if (!readNumber(v, pt, any)) return false;
      if (pt) return fail(t, "GOTO needs a block number");
      out.target = Expr::number(v, ir::Type::Int, locAt(t));
      return true;
    }
    if (p_ < end_ && (*p_ == '#' || *p_ == '[')) {
      out.target = parsePrimary();
      return out.target != nullptr;
    }
    return fail(t, "GOTO needs a block number");
  };
  if (equalsUpper(kw, "IF")) {
    skipBlanks();
    if (p_ >= end_ || *p_ != '[') return fail(p_, "IF needs a condition in brackets: IF [...]");
    out.cond = parseBracket();
    if (!out.cond) return false;
    skipBlanks();
    const char *k = p_;
    std::string_view next = keyword(readLetters());
    if (equalsUpper(next, "GOTO")) {
      out.stmt = StmtKind::IfGoto;
      return gotoTarget();
    }
    if (equalsUpper(next, "THEN")) {
      out.stmt = StmtKind::IfThen;
      return true;
    }
    return fail(k, "expected GOTO or THEN after IF [...]");
  }
  if (equalsUpper(kw, "GOTO")) {
    out.stmt = StmtKind::Goto;
    return gotoTarget();
  }
  if (equalsUpper(kw, "WHILE")) {
    skipBlanks();
    if (p_ >= end_ || *p_ != '[') return fail(p_, "WHILE needs a condition in brackets: WHILE [...]");
    out.cond = parseBracket();
    if (!out.cond) return false;
    skipBlanks();
    const char *k = p_;
    if (!equalsUpper(readLetters(), "DO")) return fail(k, "expected DO after WHILE [...]");
    if (!parseLoopId(*this, p_, end_, out.loopId)) return fail(p_, "DO needs a loop number (DO1)");
    out.stmt = StmtKind::While;
    return true;
  }
  if (equalsUpper(kw, "DO") || equalsUpper(kw, "END")) {
    if (!parseLoopId(*this, p_, end_, out.loopId))
      return fail(p_, toUpper(kw) + " needs a loop number (" + toUpper(kw) + "1)");
    out.stmt = equalsUpper(kw, "DO") ? StmtKind::Do : StmtKind::End;
    return true;
  }
  // Fanuc Macro B external output: no device and no file to write to in a run (yet).
  for (const char *out : {"DPRNT", "BPRNT", "POPEN", "PCLOS"})
    if (equalsUpper(kw, out))
      return fail(at, toUpper(kw) + " (Fanuc Macro B data output) is not supported", "unsupported-code");
  return fail(at, "unknown word '" + std::string(kw) + "'", "unknown-code");
}

bool BlockParser::parseAssign(ParsedBlock &out) {
  const char *at = p_;
  IsoAssign a;
  a.loc = locAt(at);
  a.target = parseVariable(true);
  if (!a.target) return false;
  if (a.target->kind == ir::ExprKind::Var && a.target->space == ir::VarSpace::Numbered && !a.target->args.empty() &&
      a.target->args[0]->kind == ir::ExprKind::Number && classifyParameter(map_, (long)a.target->args[0]->num).kind == SystemParam::Alarm)
    a.alarm = (int)a.target->args[0]->num;
  if (a.target->kind == ir::ExprKind::Vacant) return fail(at, "#0 is always vacant and cannot be assigned");
  skipBlanks();
  if (p_ >= end_ || *p_ != '=') return fail(p_, "expected '=' after the variable");
  ++p_;
  a.value = parseExpr(0);
  if (!a.value) return false;
  out.assigns.push_back(std::move(a));
  return true;
}

static const struct {
  const char *name;
  OKeyword kw;
} kOKeywords[] = {
    {"SUB", OKeyword::Sub},         {"ENDSUB", OKeyword::EndSub},       {"CALL", OKeyword::Call},
    {"RETURN", OKeyword::Return},   {"IF", OKeyword::If},               {"ELSEIF", OKeyword::ElseIf},
    {"ELSE", OKeyword::Else},       {"ENDIF", OKeyword::EndIf},         {"WHILE", OKeyword::While},
    {"ENDWHILE", OKeyword::EndWhile}, {"DO", OKeyword::Do},             {"BREAK", OKeyword::Break},
    {"CONTINUE", OKeyword::Continue}, {"REPEAT", OKeyword::Repeat},     {"ENDREPEAT", OKeyword::EndRepeat},
};

bool BlockParser::parseOWord(ParsedBlock &out, const char *at) {
  skipBlanks();
  bool numeric = false;
  if (p_ < end_ && *p_ == '<') {
    const char *b = ++p_;
    while (p_ < end_ && *p_ != '>') ++p_;
    if (p_ >= end_) return fail(b - 1, "unterminated O-word name: missing '>'");
    if (p_ == b) return fail(b - 1, "empty O-word name");
    for (const char *q = b; q < p_; ++q)
      if (!isBlank(*q)) out.oname.push_back((char)std::tolower((unsigned char)*q));
    ++p_;
  } else if (p_ < end_ && isDigit(*p_)) {
    numeric = true;
    while (p_ < end_ && isDigit(*p_)) out.oname.push_back(*p_++);
    if (out.oname.size() > 12) return fail(at, "program number too long");
  } else if (p_ < end_ && (*p_ == '[' || *p_ == '#') && flavour_ == Flavour::RS274) {
    // A computed o-word number (rs274): only `call` may use one (the sub must exist by number).
    if (*p_ == '[') out.ocomputed = parseBracket();
    else out.ocomputed = parseVariable();
    if (!out.ocomputed) return false;
  } else {
    return fail(p_, "O needs a program number");
  }
  skipBlanks();
  const char *k = p_;
  std::string_view kw = readLetters();
  if (kw.empty()) {
    if (!numeric) return fail(p_, "O-word needs a keyword (sub, call, if, while, ...)");
    out.programNumber = std::stoll(out.oname);
    out.oname.clear();
    return true;
  }
  bool found = false;
  for (auto &e : kOKeywords)
    if (equalsUpper(kw, e.name)) {
      out.okw = e.kw;
      found = true;
    }
  if (!found) return fail(k, "unknown O-word keyword '" + std::string(kw) + "'", "unknown-code");
  if (out.ocomputed && out.okw != OKeyword::Call)
    return fail(at, "a computed o-word number can only be called (o[...] call)", "syntax");
  out.stmt = StmtKind::OWord;
  out.stmtLoc = locAt(at);
  skipBlanks();
  switch (out.okw) {
  case OKeyword::If: case OKeyword::ElseIf: case OKeyword::While: case OKeyword::Repeat:
    if (p_ >= end_ || *p_ != '[') return fail(p_, "expected a condition in brackets");
    out.cond = parseBracket();
    return out.cond != nullptr;
  case OKeyword::Return: case OKeyword::EndSub:
    if (p_ < end_ && *p_ == '[') {
      out.cond = parseBracket();
      return out.cond != nullptr;
    }
    return true;
  case OKeyword::Call:
    while (p_ < end_ && (*p_ == '[' || *p_ == '(')) {
      if (*p_ == '(') {  // comments may stand between the arguments
        if (!parseComment(out)) return false;
        skipBlanks();
        continue;
      }
      auto a = parseBracket();
      if (!a) return false;
      out.oargs.push_back(std::move(a));
      skipBlanks();
    }
    return true;
  default:
    return true;
  }
}

bool BlockParser::parseItems(ParsedBlock &out) {
  bool stmtClosed = false;  // after GOTO/WHILE/DO/END only comments may follow
  auto nothingYet = [&] {
    return out.words.empty() && out.comments.empty() && out.assigns.empty() && out.n < 0 &&
           out.stmt == StmtKind::None;
  };
  while (true) {
    skipBlanks();
    if (p_ >= end_) break;
    char c = *p_;
    if (c == '(') {
      if (!parseComment(out)) return false;
      continue;
    }
    if (c == ';') {
      parseSemicolonComment(out);
      break;
    }
    if (c == '/') {
      const char *at = p_++;
      int level = 0;
      if (p_ < end_ && isDigit(*p_)) level = *p_++ - '0';
      if (p_ < end_ && isDigit(*p_)) return fail(at, "invalid block skip level (0..9)", "syntax");
      if (skipMask_ & (1u << level)) break;  // the rest of the block is not executed
      if (nothingYet()) out.skip = level;
      continue;
    }
    if (stmtClosed) return fail(p_, "unexpected text after the macro statement");
    const char *at = p_;
    if (c == '#') {
      if (!parseAssign(out)) return false;
      continue;
    }
    if (c == ':' && flavour_ == Flavour::Fanuc && nothingYet()) {  // Fanuc `:0100` = O0100
      ++p_;
      if (p_ >= end_ || !isDigit(*p_)) return fail(at, "':' (program number) needs a number");
      if (!parseOWord(out, at)) return false;
      if (out.programNumber < 0) return fail(at, "':' gives a program number only (:1234)");
      continue;
    }
    if (c == '$' && flavour_ == Flavour::RS274) {  // spindle selection: ncc has one spindle
      ++p_;
      IsoWord w;
      w.letter = '$';
      w.loc = locAt(at);
      if (!parseWordValue(w)) return false;
      if (w.expr || (w.value != 0 && w.value != -1))
        return fail(at, "spindle selection $n: the machine has one spindle ($0; $-1 = all)", "unsupported-code");
      continue;  // $0 and $-1 name the one spindle
    }
    if ((c == '@' || c == '^') && flavour_ == Flavour::RS274) {  // polar radius / angle
      ++p_;
      IsoWord w;
      w.letter = c;
      w.loc = locAt(at);
      if (!parseWordValue(w)) return false;
      out.words.push_back(std::move(w));
      continue;
    }
    if (c == ',' && flavour_ == Flavour::Fanuc) {  // ,C chamfer  ,R rounding  ,A angle (808D 2.3.1.5)
      ++p_;
      char l = p_ < end_ ? (char)std::toupper((unsigned char)*p_) : 0;
      if (l == 'A') return fail(at, ",A (a line given by its angle) is not supported yet", "unsupported-code");
      if (l != 'C' && l != 'R') return fail(at, "',' starts a chamfer ,C or a rounding ,R", "syntax");
      if (!out.corner.empty()) return fail(at, "one chamfer or rounding per block", "duplicate-word");
      ++p_;
      IsoWord w;
      w.letter = l;
      w.loc = locAt(at);
      if (!parseWordValue(w)) return false;
      out.corner.push_back(std::move(w));
      continue;
    }
    if (!isLetter(c)) return fail(p_, "unexpected character " + showChar(c), "syntax");
    std::string_view letters = readLetters();
    if (letters.size() >= 2) {
      if (!parseStatement(letters, at, out)) return false;
      if (out.stmt != StmtKind::IfThen) stmtClosed = true;
      continue;
    }
    char L = upper(c);
    if (L == 'N') {
      skipBlanks();
      double v;
      bool pt, any;
      if (!readNumber(v, pt, any)) return failed_ ? false : fail(p_, "N needs a block number");
      // rs274 reads N1.5 (the number only labels the block); Fanuc block numbers are integers.
      if ((pt && flavour_ != Flavour::RS274) || v > 1e15)
        return fail(at, "block number must be an integer below 10^15");
      if (pt) v = std::floor(v);
      if (out.n >= 0) return fail(at, "two N words in one block", "duplicate-word");
      out.n = (int64_t)v;
      continue;
    }
    if (L == 'O') {
      if (!out.words.empty() || !out.assigns.empty() || out.stmt != StmtKind::None)
        return fail(at, "O (program number / o-word) must start the block");
      if (!parseOWord(out, at)) return false;
      if (out.stmt == StmtKind::OWord) stmtClosed = true;
      continue;
    }
    IsoWord w;
    w.letter = L;
    w.loc = locAt(at);
    if (!parseWordValue(w)) return false;
    out.words.push_back(std::move(w));
  }
  out.content = !nothingYet() || out.programNumber >= 0;
  return true;
}

ir::ExprPtr namedParameter(std::string_view raw, SourceLoc loc) {
  std::string name;  // names are case-insensitive and blanks do not count
  for (char c : raw)
    if (!isBlank(c)) name.push_back((char)std::tolower((unsigned char)c));
  if (name.empty()) return nullptr;
  // LinuxCNC's predefined parameters (#<_metric>, #<_x>, #<_abs_x> …) are controller state;
  // ncc's other system variables (reached through #5221 …) are not names in LinuxCNC.
  SysVar sv;
  bool predefined = sysVarFromName(name, sv) && (sv < SysVar::G92On || sysVarInfo(sv).family == SysFamily::MachinePos);
  auto space = predefined ? ir::VarSpace::System
               : name[0] == '_'         ? ir::VarSpace::Global
                                        : ir::VarSpace::Local;
  return Expr::var(space, std::move(name), nullptr, loc);
}

// Fanuc Macro B semantics, explicit in the IR: AND/OR/XOR are bitwise on integers in values
// (`[12 OR 3]` = 15) and logical only where they join conditions of IF/WHILE; FIX truncates
// toward zero and FUP rounds away from zero (LinuxCNC floors and ceils).
static bool isLogical(const ir::Expr *e) {
  using ir::OpCode;
  return e && e->kind == ir::ExprKind::Binary &&
         ((e->op >= OpCode::Eq && e->op <= OpCode::Ge) || e->op == OpCode::And || e->op == OpCode::Or ||
          e->op == OpCode::Xor);
}

static void fanucSemantics(ir::Expr *e, bool condition) {
  if (!e) return;
  using ir::OpCode;
  bool logicalOp = e->kind == ir::ExprKind::Binary && (e->op == OpCode::And || e->op == OpCode::Or || e->op == OpCode::Xor);
  for (auto &a : e->args) fanucSemantics(a.get(), logicalOp && condition);
  // Joining two truth values (comparisons, or AND/OR/XOR of them) stays logical anywhere.
  bool joinsTruths = logicalOp && e->args.size() == 2 && isLogical(e->args[0].get()) && isLogical(e->args[1].get());
  if (logicalOp && !condition && !joinsTruths)
    e->op = e->op == OpCode::And ? OpCode::BAnd : e->op == OpCode::Or ? OpCode::BOr : OpCode::BXor;
  if (e->kind == ir::ExprKind::Call && e->str == "FIX") e->str = "TRUNC";
  if (e->kind == ir::ExprKind::Call && e->str == "FUP") e->str = "AWAYFROMZERO";
}

static void fanucSemantics(ParsedBlock &b) {
  for (auto &w : b.words) fanucSemantics(w.expr.get(), false);
  for (auto &a : b.assigns) {
    fanucSemantics(a.target.get(), false);
    fanucSemantics(a.value.get(), false);
  }
  fanucSemantics(b.cond.get(), true);
  fanucSemantics(b.target.get(), false);
  for (auto &a : b.oargs) fanucSemantics(a.get(), false);
}

bool BlockParser::parse(std::string_view line, uint32_t file, uint32_t lineNo, ParsedBlock &out) {
  if (out.plain) out.clearPlain();
  else out.clear();
  begin_ = p_ = line.data();
  end_ = begin_ + line.size();
  file_ = file;
  line_ = lineNo;
  failed_ = false;
  depth_ = 0;
  if (lineNo == 1 && line.size() >= 3 && std::memcmp(p_, "\xEF\xBB\xBF", 3) == 0) p_ += 3;  // UTF-8 BOM
  skipBlanks();
  if (p_ >= end_) return true;
  out.loc = locAt(p_);
  if (*p_ == '%') {
    out.percent = true;
    return true;
  }
  if (parsePlainWords(out)) return true;
  out.words.clear();  // what the fast path read before it gave up
  out.n = -1;
  out.shape = 0;
  bool ok = parseItems(out);
  if (ok && flavour_ == Flavour::Fanuc) fanucSemantics(out);
  return ok && !failed_;
}

// ---------------------------------------------------------------- expressions

ExprPtr BlockParser::parseBracket() {
  const char *open = p_;
  if (p_ >= end_ || *p_ != '[') {
    fail(p_, "expected '['");
    return nullptr;
  }
  ++p_;
  ExprPtr e = parseExpr(0);
  if (!e) return nullptr;
  skipBlanks();
  if (p_ >= end_ || *p_ != ']') {
    if (p_ < end_) fail(p_, "expected ']' (operator or bracket), found " + showChar(*p_));
    else fail(open, "missing ']'");
    return nullptr;
  }
  ++p_;
  return e;
}

// Binary operator at the cursor (not consumed): precedence per flavour.
bool BlockParser::binaryOp(int &prec, OpCode &op, const char *&after) {
  skipBlanks();
  if (p_ >= end_) return false;
  const bool fanuc = flavour_ == Flavour::Fanuc;
  const int cmpP = fanuc ? 1 : 2, addP = fanuc ? 2 : 3, mulP = fanuc ? 3 : 4, logAnd = fanuc ? 3 : 1,
            logOr = fanuc ? 2 : 1;
  char c = *p_;
  after = p_ + 1;
  switch (c) {
  case '+': op = OpCode::Add; prec = addP; return true;
  case '-': op = OpCode::Sub; prec = addP; return true;
  case '/': op = OpCode::Div; prec = mulP; return true;
  case '*':
    if (p_ + 1 < end_ && p_[1] == '*') {
      if (fanuc) return false;
      op = OpCode::Pow;
      prec = 5;
      after = p_ + 2;
      return true;
    }
    op = OpCode::Mul;
    prec = mulP;
    return true;
  default: break;
  }
  if (!isLetter(c)) return false;
  const char *q = p_;
  while (q < end_ && isLetter(*q)) ++q;
  std::string_view w = keyword(std::string_view(p_, (size_t)(q - p_)));
  static const struct {
    const char *name;
    OpCode op;
    int kind;  // 0 compare, 1 and, 2 or/xor, 3 mod
  } kWords[] = {{"EQ", OpCode::Eq, 0}, {"NE", OpCode::Ne, 0},   {"GT", OpCode::Gt, 0},  {"GE", OpCode::Ge, 0},
                {"LT", OpCode::Lt, 0}, {"LE", OpCode::Le, 0},   {"AND", OpCode::And, 1}, {"OR", OpCode::Or, 2},
                {"XOR", OpCode::Xor, 2}, {"MOD", OpCode::Mod, 3}};
  for (auto &k : kWords)
    if (equalsUpper(w, k.name)) {
      op = k.op;
      prec = k.kind == 0 ? cmpP : k.kind == 1 ? logAnd : k.kind == 2 ? logOr : mulP;
      after = q;
      return true;
    }
  return false;
}

ExprPtr BlockParser::parseExpr(int minPrec) {
  if (++depth_ > 100) {
    fail(p_, "expression nested too deeply");
    --depth_;
    return nullptr;
  }
  ExprPtr lhs = parseUnary();
  while (lhs) {
    int prec;
    OpCode op;
    const char *after;
    const char *at = p_;
    if (!binaryOp(prec, op, after) || prec < minPrec) break;
    p_ = after;
    ExprPtr rhs = parseExpr(op == OpCode::Pow ? prec : prec + 1);
    if (!rhs) {
      lhs.reset();
      break;
    }
    lhs = Expr::binary(op, std::move(lhs), std::move(rhs), locAt(at));
  }
  --depth_;
  return lhs;
}

ExprPtr BlockParser::parseUnary() {
  skipBlanks();
  if (p_ < end_ && (*p_ == '-' || *p_ == '+')) {
    const char *at = p_;
    bool neg = *p_++ == '-';
    if (++depth_ > 100) {
      fail(at, "expression nested too deeply");
      return nullptr;
    }
    ExprPtr e = parseUnary();
    --depth_;
    if (!e || !neg) return e;
    if (e->kind == ir::ExprKind::Number) {
      e->num = -e->num;
      e->loc = locAt(at);
      return e;
    }
    return Expr::unary(OpCode::Neg, std::move(e), locAt(at));
  }
  return parsePrimary();
}

ExprPtr BlockParser::parsePrimary() {
  skipBlanks();
  if (p_ >= end_) {
    fail(p_, "expected a value");
    return nullptr;
  }
  const char *at = p_;
  char c = *p_;
  if (isDigit(c) || c == '.') {
    double v;
    bool pt, any;
    if (!readNumber(v, pt, any)) {
      fail(at, "expected a value");
      return nullptr;
    }
    return Expr::number(v, pt ? ir::Type::Real : ir::Type::Int, locAt(at));
  }
  if (c == '#') return parseVariable();
  if (c == '[') {
    if (++depth_ > 100) {
      fail(at, "expression nested too deeply");
      return nullptr;
    }
    ExprPtr e = parseBracket();
    --depth_;
    return e;
  }
  if (isLetter(c)) {
    std::string name = toUpper(keyword(readLetters()));
    return parseFunction(std::move(name), at);
  }
  fail(at, "expected a value, found " + showChar(c));
  return nullptr;
}

ExprPtr BlockParser::parseVariable(bool target) {
  const char *at = p_;
  ++p_;  // '#'
  skipBlanks();
  if (p_ >= end_) {
    fail(at, "'#' needs a variable number");
    return nullptr;
  }
  if (isDigit(*p_)) {
    const char *b = p_;
    double v;
    bool pt, any;
    if (!readNumber(v, pt, any)) return nullptr;
    if (pt) {
      fail(b, "variable number must be an integer");
      return nullptr;
    }
    if (v == 0) return Expr::vacant(locAt(at));
    long n = v > 1e9 ? 1000000000L : (long)v;
    SystemParam sp = classifyParameter(map_, n);
    // Offsets and reference points are written through the executor, which applies them when
    // the controller would (docs/MACHINE.md offset_write); the rest is read-only, as in rs274.
    if (target && sp.kind == SystemParam::System && !sysVarWritable(sp.var.var)) {
      fail(at, readOnlyParameterMessage(n, sp.what), "read-only-parameter");
      return nullptr;
    }
    if (target && sp.kind == SystemParam::Alarm)
      return Expr::var(ir::VarSpace::Numbered, "", Expr::number(v, ir::Type::Int, locAt(b)), locAt(at));
    std::string err;
    ExprPtr e = numberedParameter(map_, n, locAt(at), err);
    if (!e) fail(at, err, "unsupported-code");
    return e;
  }
  if (*p_ == '[' || *p_ == '#') {
    if (++depth_ > 100) {
      fail(at, "expression nested too deeply");
      return nullptr;
    }
    ExprPtr idx = *p_ == '[' ? parseBracket() : parseVariable();
    --depth_;
    if (!idx) return nullptr;
    // A computed number is resolved when the program runs, through the same map as #n.
    return computedParameter(map_, std::move(idx), locAt(at));
  }
  if (*p_ == '<' && flavour_ == Flavour::RS274) {
    const char *b = ++p_;
    while (p_ < end_ && *p_ != '>') ++p_;
    ExprPtr e = p_ < end_ ? namedParameter(std::string_view(b, (size_t)(p_ - b)), locAt(at)) : nullptr;
    if (!e) {
      fail(b - 1, p_ < end_ ? "empty parameter name: #<>" : "unterminated parameter name: missing '>'");
      return nullptr;
    }
    ++p_;
    return e;
  }
  fail(p_, "'#' needs a variable number");
  return nullptr;
}

ExprPtr BlockParser::parseFunction(std::string name, const char *at) {
  static const char *kAllowed[] = {"SIN", "COS",  "TAN", "ASIN",  "ACOS", "ATAN", "SQRT",
                                   "ABS", "ROUND", "FIX", "FUP",  "LN",   "EXP"};
  bool ok = name == "EXISTS" && flavour_ == Flavour::RS274;  // RS274NGC EXISTS[#<name>]
  for (auto *n : kAllowed) ok |= name == n;
  if (!ok || !findBuiltin(name)) {
    fail(at, "unknown function '" + name + "'", "unknown-code");
    return nullptr;
  }
  skipBlanks();
  if (p_ >= end_ || *p_ != '[') {
    fail(p_, name + " needs its argument in brackets: " + name + "[...]");
    return nullptr;
  }
  if (++depth_ > 100) {
    fail(at, "expression nested too deeply");
    return nullptr;
  }
  std::vector<ExprPtr> args;
  ++p_;
  ExprPtr a = parseExpr(0);
  if (a) {
    args.push_back(std::move(a));
    skipBlanks();
    if (name == "ATAN" && p_ < end_ && *p_ == ',') {  // ATAN[y, x]
      ++p_;
      ExprPtr b = parseExpr(0);
      if (b) args.push_back(std::move(b));
      else args.clear();
      skipBlanks();
    }
    if (!args.empty() && (p_ >= end_ || *p_ != ']')) {
      fail(p_ < end_ ? p_ : at, "expected ']' to close " + name + "[");
      args.clear();
    } else if (!args.empty()) {
      ++p_;
    }
  }
  --depth_;
  if (args.empty()) return nullptr;
  if (name == "EXISTS" && args[0]->kind != ir::ExprKind::Var) {
    fail(at, "EXISTS needs a parameter: EXISTS[#<name>]", "syntax");
    return nullptr;
  }
  if (name == "ATAN" && args.size() == 1) {  // ATAN[y]/[x] is the two-argument arc tangent
    const char *save = p_;
    skipBlanks();
    if (p_ < end_ && *p_ == '/') {
      ++p_;
      skipBlanks();
      if (p_ < end_ && *p_ == '[') {
        ExprPtr x = parseBracket();
        if (!x) return nullptr;
        args.push_back(std::move(x));
      } else {
        p_ = save;
      }
    } else {
      p_ = save;
    }
  }
  if (args.size() == 2) name = "ATAN2";
  return Expr::call(std::move(name), std::move(args), locAt(at));
}

}  // namespace ncc::iso
