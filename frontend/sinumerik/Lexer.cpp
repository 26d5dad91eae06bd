#include "frontend/sinumerik/Lexer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace ncc::sin {

static bool isDigit(char c) { return c >= '0' && c <= '9'; }
static bool nameStart(char c) { return std::isalpha((unsigned char)c) || c == '_' || c == '$'; }
static bool nameChar(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

size_t readSinNumber(std::string_view s, double &v, bool &isInt) {
  size_t i = 0, n = s.size();
  std::string digits;
  while (i < n && isDigit(s[i])) digits += s[i++];
  isInt = true;
  if (i < n && s[i] == '.') {
    size_t j = i + 1;
    std::string frac;
    while (j < n && isDigit(s[j])) frac += s[j++];
    if (digits.empty() && frac.empty()) return 0;
    digits += '.' + frac;
    i = j;
    isInt = false;
  }
  if (digits.empty()) return 0;
  // The manual's exponent: EX, either case, optional sign (1.5EX-3).
  if (i + 2 < n + 0 && (s[i] == 'E' || s[i] == 'e') && (s[i + 1] == 'X' || s[i + 1] == 'x')) {
    size_t j = i + 2;
    std::string ex;
    if (j < n && (s[j] == '+' || s[j] == '-')) ex += s[j++];
    size_t d0 = j;
    while (j < n && isDigit(s[j])) ex += s[j++];
    if (j > d0) {
      digits += 'e' + ex;
      i = j;
      isInt = false;
    }
  }
  v = std::strtod(digits.c_str(), nullptr);
  return i;
}

// 'H1F' (hexadecimal) and 'B101' (binary) constants.
static bool readQuoted(std::string_view s, size_t &i, Token &t, std::string &err) {
  size_t j = i + 1;
  if (j >= s.size()) return err = "a constant 'H…' or 'B…' is not closed", false;
  char kind = (char)std::toupper((unsigned char)s[j]);
  if (kind != 'H' && kind != 'B') return err = "expected 'H<hex digits>' or 'B<binary digits>' after '", false;
  ++j;
  size_t d0 = j;
  double v = 0;
  while (j < s.size() && s[j] != '\'') {
    int d = std::isxdigit((unsigned char)s[j]) ? (isDigit(s[j]) ? s[j] - '0' : std::toupper(s[j]) - 'A' + 10) : -1;
    if (d < 0 || (kind == 'B' && d > 1))
      return err = std::string("invalid digit '") + s[j] + "' in a " + (kind == 'H' ? "hexadecimal" : "binary") +
                   " constant",
             false;
    v = v * (kind == 'H' ? 16 : 2) + d;
    ++j;
  }
  if (j >= s.size()) return err = "a constant 'H…' or 'B…' is not closed", false;
  if (j == d0) return err = "a constant 'H…' or 'B…' has no digits", false;
  t.kind = Tok::Number;
  t.num = v;
  t.isInt = true;
  i = j + 1;
  return true;
}

bool lexLine(std::string_view s, std::vector<Token> &out, std::string &err, uint32_t &errCol) {
  out.clear();
  size_t i = 0, n = s.size();
  bool space = true;
  while (i < n) {
    char c = s[i];
    // `&` acts as a blank; control characters too (Fundamentals, character set).
    if (c == ' ' || c == '\t' || c == '\r' || c == '&' || (unsigned char)c < 32) {
      ++i;
      space = true;
      continue;
    }
    if (c == ';') break;
    Token t;
    t.col = (uint32_t)i + 1;
    t.spaceBefore = space;
    space = false;
    if (nameStart(c)) {
      size_t j = i + 1;
      if (c == '$' && j < n && s[j] == '$') ++j;  // $$M…: main-run access to machine data (one name)
      while (j < n && nameChar(s[j])) ++j;
      std::string text(s.substr(i, j - i));
      for (auto &ch : text) ch = (char)std::toupper((unsigned char)ch);
      size_t d = text.size();
      while (d > 0 && isDigit(text[d - 1])) --d;
      t.kind = Tok::Name;
      t.digitsAt = (uint32_t)(d == 0 ? text.size() : d);
      if (d < text.size() && d > 0) {
        // Trailing digits: maybe an address value. `X10.5` and `X1.5EX3` continue here.
        double v;
        bool isInt;
        size_t used = readSinNumber(s.substr(i + d), v, isInt);
        t.num = v;
        t.isInt = isInt;
        if (used > j - i - d) {
          t.fraction = true;
          j = i + d + used;
        }
      }
      t.text = std::move(text);
      i = j;
    } else if (isDigit(c) || (c == '.' && i + 1 < n && isDigit(s[i + 1]))) {
      size_t used = readSinNumber(s.substr(i), t.num, t.isInt);
      t.kind = Tok::Number;
      i += used;
    } else if (c == '"') {
      size_t j = i + 1;
      std::string v;
      while (j < n && s[j] != '"') v += s[j++];
      if (j >= n) return err = "missing closing '\"' of a string", errCol = t.col, false;
      t.kind = Tok::String;
      t.text = std::move(v);
      i = j + 1;
    } else if (c == '\'') {
      if (!readQuoted(s, i, t, err)) return errCol = t.col, false;
    } else {
      static const char *kTwo[] = {"==", "<>", "<=", ">=", "<<"};
      t.kind = Tok::Punct;
      for (const char *p : kTwo)
        if (s.substr(i, 2) == p) t.text = p;
      if (t.text.empty()) {
        if (std::string_view("+-*/()[],=<>:").find(c) == std::string_view::npos)
          return err = std::string("unexpected character '") + c + "'", errCol = t.col, false;
        t.text = std::string(1, c);
      }
      i += t.text.size();
    }
    out.push_back(std::move(t));
  }
  Token e;
  e.kind = Tok::End;
  e.col = (uint32_t)std::min(n, i) + 1;
  e.spaceBefore = true;
  out.push_back(e);
  return true;
}

}  // namespace ncc::sin
