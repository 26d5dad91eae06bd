// The block parser's fast path for lines of plain words (G1 Y.25), the bulk of a flat
// program: read in one pass from the mapped text, with no line search and no parse() set-up.
// Anything else falls back to the general parser in BlockParser.cpp, which gives every message.
#include "frontend/iso/ExactPow10.h"
#include "frontend/iso/Syntax.h"

#include <cstdint>

namespace ncc::iso {

// The fast path's byte classes: one table look-up per byte.
namespace {
enum PlainClass : uint8_t { kDigit = 1, kLetter = 2, kBlank = 4, kSign = 8 };
struct PlainClasses {
  uint8_t c[256];
  constexpr PlainClasses() : c{} {
    for (int i = '0'; i <= '9'; ++i) c[i] = kDigit;
    for (int i = 'A'; i <= 'Z'; ++i) c[i] = c[i + 32] = kLetter;
    for (const char *b = " \t\r\f\v"; *b; ++b) c[(unsigned char)*b] = kBlank;  // isBlank's bytes
    c[(unsigned char)'-'] = c[(unsigned char)'+'] = kSign;
  }
};
constexpr PlainClasses kPlain;
}  // namespace

// The fast path of a block of plain words, the bulk of a flat program: letters each with an
// optional sign and an unsigned decimal number of at most 15 digits (exact in a double, so the
// value is readNumber's: G1 Y.25), and an N with an integer. Anything else (comments,
// O, parameters, expressions, statements, block skip, long numbers, a second N, anything
// malformed) returns null before a diagnostic: parseItems then reads the block from its start,
// so every message and its location stay the general path's. Reads from q to the first newline
// or `end` and returns where it stopped. kSentinel: a newline is known to come before `end`, so
// no scan needs the bounds check (the newline is in no class and stops every loop).
template <bool kSentinel>
const char *BlockParser::plainWords(const char *q, const char *end, ParsedBlock &out) {
  auto ch = [end](const char *r) { return !kSentinel && r >= end ? (unsigned char)'\n' : (unsigned char)*r; };
  auto cls = [&](const char *r) { return kPlain.c[ch(r)]; };
  // Locals: the stores into `out` may alias the parser's members, which would be reloaded per word.
  const uint32_t file = file_, line = line_;
  const char *const begin = begin_;
  uint64_t shape = 0;  // ParsedBlock::shape, in a register
  for (;;) {
    const unsigned char c = ch(q);
    if (c == '\n') {
      out.shape = out.words.size() <= 8 ? shape : 0;
      return q;
    }
    if (!(kPlain.c[c] & kLetter)) return nullptr;
    const char *at = q++;
    const char letter = char(c & 0xDF);  // upper case
    uint8_t k = cls(q);
    if (k & kLetter) return nullptr;  // a statement or function name
    while (k & kBlank) k = cls(++q);
    bool neg = false;
    if ((k & kSign) && letter != 'N') {
      neg = *q == '-';
      while (cls(++q) & kBlank) {
      }
    }
    const char *first = q;
    uint64_t mantissa = 0;  // wraps past 15 digits, which are refused below
    for (unsigned d; (d = unsigned(ch(q)) - '0') <= 9; ++q) mantissa = mantissa * 10 + d;
    ptrdiff_t digits = q - first, fraction = 0;
    const bool point = ch(q) == '.';
    if (point) {
      const char *f = ++q;
      for (unsigned d; (d = unsigned(ch(q)) - '0') <= 9; ++q) mantissa = mantissa * 10 + d;
      fraction = q - f;
      digits += fraction;
    }
    if (digits == 0 || digits > 15) return nullptr;  // 10^15 < 2^53: the quotient below is exact
    k = cls(q);
    if (!(k & (kBlank | kLetter)) && ch(q) != '\n') return nullptr;
    if (letter == 'N') {  // a block number: an integer, once (parseItems reports the rest)
      if (point || out.n >= 0) return nullptr;
      out.n = (int64_t)mantissa;
    } else if (letter == 'O') {
      return nullptr;
    } else {
      IsoWord &w = out.words.emplace_back();
      w.letter = letter;
      w.hasPoint = point;
      const double v = (double)(int64_t)mantissa / kExactPow10[fraction];
      w.value = neg ? -v : v;
      w.loc = {file, line, (uint32_t)(at - begin + 1)};  // locAt(at)
      shape = shape << 8 | (unsigned char)letter;
    }
    while (k & kBlank) k = cls(++q);
  }
}

bool BlockParser::parsePlainWords(ParsedBlock &out) {
  const char *q = plainWords<false>(p_, end_, out);
  if (q != end_) return false;  // not plain, or a newline inside the line: the general path
  p_ = q;
  out.content = true;
  out.plain = true;
  return true;
}

bool BlockParser::parsePlainLine(const char *line, const char *end, uint32_t file, uint32_t lineNo, ParsedBlock &out,
                                 const char *&newline) {
  if (out.plain) out.clearPlain();
  else out.clear();
  const char *q = line;
  while (kPlain.c[(unsigned char)*q] & kBlank) ++q;
  if (*q == '\n') return false;  // no content: parse()
  begin_ = line;
  end_ = end;
  file_ = file;
  line_ = lineNo;
  out.loc = locAt(q);
  if (!(q = plainWords<true>(q, end, out))) return false;
  newline = q;
  out.content = true;
  out.plain = true;
  return true;
}

}  // namespace ncc::iso
