// Klartext blocks: a numbered line and its un-numbered continuation lines (cycle parameters,
// `~` continuations) read as one token list. Words are letters only: `X+10` is the word X,
// the sign and the number, `Q200=2` the word Q, 200, `=` and 2; the parser puts them together.
#pragma once
#include "ir/Diagnostics.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::hei {

enum class Tok : uint8_t { End, Word, Number, String, Punct };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // Word: upper case; Punct: the character; String: the value; Number: as written
  double num = 0;
  bool isInt = true;   // a Number written without a decimal point
  uint32_t line = 0, col = 0;
  bool is(std::string_view p) const { return kind == Tok::Punct && text == p; }
  bool isWord(std::string_view w) const { return kind == Tok::Word && text == w; }
};

struct Block {
  uint32_t number = 0;      // the block number written at its start
  uint32_t line = 0;        // its first line
  std::string comment;      // `*` block: the text; else the first line's `;` comment
  bool star = false;        // a `*` comment block
  std::vector<Token> toks;  // ends with an End token
};

struct LexResult {
  std::vector<Block> blocks;
  std::vector<std::pair<SourceLoc, std::string>> errors;    // garbage lines
  std::vector<SourceLoc> decimalCommas;                      // numbers written with `,`
};

// Splits a whole file into blocks. Lines before the first block that hold only a comment are
// skipped; any other text outside a block is an error.
LexResult lexFile(std::string_view text, uint32_t file);

}  // namespace ncc::hei
