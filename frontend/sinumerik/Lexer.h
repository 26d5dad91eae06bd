// Tokens of one Sinumerik block (one source line). The lexer knows nothing of names: whether
// `X10` is the address X with the value 10 or a variable is the parser's choice (Parser.cpp),
// so a name token keeps where its trailing digits start and the number they spell.
#pragma once
#include "ir/Diagnostics.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::sin {

enum class Tok : uint8_t {
  End,
  Name,     // [A-Za-z_$][A-Za-z0-9_]*, upper-cased in text; `X10.5` is one name with a fraction
  Number,   // 12, 1.5, .5, 1.5EX-3, 'H1F', 'B101'
  String,   // "text" (value without quotes)
  Punct,    // + - * / ( ) [ ] , = == <> < > <= >= << :  (skip levels are read before lexing)
};

struct Token {
  Tok kind = Tok::End;
  std::string text;       // Name: upper case; Punct: the operator; String: the value
  double num = 0;         // Number; Name: the value of its trailing digits (and fraction)
  bool isInt = true;      // Number / trailing digits written without a point or exponent
  uint32_t digitsAt = 0;  // Name: index of the trailing digit run (text.size() when none)
  bool fraction = false;  // Name: the digits went on with `.5` (`X10.5`)
  bool spaceBefore = false;
  uint32_t col = 0;       // 1-based
  bool is(std::string_view p) const { return kind == Tok::Punct && text == p; }
  bool isName(std::string_view n) const { return kind == Tok::Name && text == n; }
};

// Splits `line` into tokens, after the comment (`;`) is cut off. Returns false with `err` and
// `errCol` set on a lexical error (an unterminated string, a bad constant).
bool lexLine(std::string_view line, std::vector<Token> &out, std::string &err, uint32_t &errCol);

// Reads a Sinumerik number at `s` (digits, optional point and digits, optional EX exponent):
// the count of characters used, 0 when there is none.
size_t readSinNumber(std::string_view s, double &v, bool &isInt);

}  // namespace ncc::sin
