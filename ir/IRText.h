// Lexical rules of the NC IR text form shared by the printer and the parser, so that whatever
// the printer writes bare is exactly what the parser reads back as the same thing.
// Internal to ir/ (Printer.cpp, Parser.cpp); other code uses printModule/parseModule.
#pragma once
#include "ir/NCIR.h"

#include <cstdint>
#include <string_view>

namespace ncc::ir::text {

inline bool isIdentStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9') || c == '.'; }
inline bool isIdent(std::string_view s) {
  if (s.empty() || !isIdentStart(s[0])) return false;
  for (char c : s)
    if (!isIdentChar(c)) return false;
  return true;
}

// Bare words with a fixed meaning in expression position.
inline bool isExprKeyword(std::string_view s) {
  return s == "true" || s == "false" || s == "vacant" || s == "nan";
}

// The parameter prefixes written as one word with their number: R5, Q5, QL5, QR5, QS5.
// Returns the prefix length (0 = not a parameter prefix) for the identifier's leading letters.
inline unsigned paramPrefix(std::string_view s, VarSpace &space) {
  if (s.size() >= 1 && s[0] == 'R') {
    space = VarSpace::RParam;
    return 1;
  }
  if (s.size() >= 2 && s[0] == 'Q' && (s[1] == 'L' || s[1] == 'R' || s[1] == 'S')) {
    space = VarSpace::QParam;
    return 2;
  }
  if (s.size() >= 1 && s[0] == 'Q') {
    space = VarSpace::QParam;
    return 1;
  }
  return 0;
}

// True when an identifier spells a parameter (R12, QL3) or a bare prefix (R, QS) that the
// parser would read as a variable when followed by '['.
inline bool looksLikeParam(std::string_view s) {
  VarSpace sp;
  unsigned n = paramPrefix(s, sp);
  if (n == 0) return false;
  for (size_t i = n; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

// A symbol prints bare only when the parser reads that word back as the same symbol.
inline bool isBareSymbol(std::string_view s) {
  return isIdent(s) && !isExprKeyword(s) && !looksLikeParam(s) && s != "sym";
}

// Variable indexes print in the short form (#5, R5, Q5) when they are small integral constants.
inline bool isShortIndex(const Expr *e) {
  return e && e->kind == ExprKind::Number && e->type == Type::Int && e->num >= 0 && e->num < 1e15 &&
         e->num == (double)(int64_t)e->num;
}

}  // namespace ncc::ir::text
