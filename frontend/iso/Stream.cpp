// Streaming parse of flat programs (no control flow, calls or subprograms), block by block, so a
// million-line file never exists as one IR module.
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Lower.h"

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <string_view>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define NCC_BULK_AVX2 1
#endif

namespace ncc::iso {

static inline char up(char c) { return (c >= 'a' && c <= 'z') ? (char)(c - 32) : c; }
static inline bool letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// The pre-scan's byte classes. Most bytes of a part program are digits, signs, points, blanks
// and address letters that cannot begin anything needing the whole program: one table lookup
// skips them. Word: the letters of M and G codes and the initials of the statements (IF, DO,
// END, GOTO, WHILE), which are looked at more closely.
enum class ScanClass : uint8_t { Skip, Word, Comment, EndOfBlock, EndOfLine };
struct ScanClasses {
  ScanClass c[256];
  constexpr ScanClasses() : c{} {
    for (const char *w = "DEGIMWdegimw"; *w; ++w) c[(unsigned char)*w] = ScanClass::Word;
    c[(unsigned char)'('] = ScanClass::Comment;
    c[(unsigned char)';'] = ScanClass::EndOfBlock;
    c[(unsigned char)'\n'] = ScanClass::EndOfLine;
  }
};
static constexpr ScanClasses kScan;

// The pre-scan and the stream release the pages of a mapped text they have read every megabyte.
constexpr size_t kReleaseEvery = 1 << 20;

// Whether a line (after its block number) holds anything but blanks, '%' and comments.
static bool lineHasContent(const char *q, const char *le) {
  int depth = 0;
  for (; q < le; ++q) {
    char c = *q;
    if (c == '(') ++depth;
    else if (c == ')') depth -= depth > 0;
    else if (depth == 0 && c == ';') return false;
    else if (depth == 0 && c != ' ' && c != '\t' && c != '\r' && c != '%') return true;
  }
  return false;
}

// The words that start a statement, with Fanuc's two-letter abbreviations (GO 10 is a GOTO).
static constexpr std::string_view kStatementWords[] = {"IF", "DO", "END", "EN", "GOTO", "GO", "WHILE", "WH"};

// A word starting at b (a Word letter, not inside a longer word) that needs the whole program:
// a statement keyword, a call or return, a macro call, a lathe contour cycle, a computed code.
// q is left on the word's last letter.
static bool needsWholeProgram(const char *&q, const char *le) {
  const char *b = q;
  while (q + 1 < le && letter(q[1])) ++q;
  size_t n = (size_t)(q - b + 1);
  char k0 = up(b[0]);
  if (n >= 2) {  // statements need the whole program; function names and operators are fine
    for (std::string_view k : kStatementWords)
      if (k.size() == n && std::equal(k.begin(), k.end(), b, [](char a, char c) { return a == up(c); })) return true;
    return false;
  }
  if (k0 != 'M' && k0 != 'G') return false;
  const char *r = q + 1;
  while (r < le && (*r == ' ' || *r == '\t')) ++r;
  if (r < le && (*r == '#' || *r == '[')) return true;  // computed code: play safe
  long v = 0;
  int digits = 0;
  while (r < le && *r >= '0' && *r <= '9' && digits < 9) v = v * 10 + (*r++ - '0'), ++digits;
  const bool point = r < le && *r == '.';
  if (k0 == 'M') return v == 98 || v == 99;
  // G65/G66 macro calls, G5 (high-speed cycle call); the lathe contour cycles G70-G73 run a
  // block range (also G73 of a mill: playing safe), the 808D's G72.1/G72.2 call a subprogram
  // (with a point: LinuxCNC's G71.1 … too, playing safe); G290 Siemens-mode blocks.
  return (v >= 70 && v <= 73) || (!point && (v == 65 || v == 66 || v == 5 || v == 290));
}

// The first byte at or after q that is not ScanClass::Skip (end if none): sixteen bytes at a
// time where SSE2 is there (every x86-64), then the table. The same classes as kScan: letters
// fold to lower case with 0x20, which maps no other byte onto a letter.
static const char *skipPlain(const char *q, const char *end) {
#if defined(__SSE2__)
  auto eq = [](__m128i v, char c) { return _mm_cmpeq_epi8(v, _mm_set1_epi8(c)); };
  for (; end - q >= 16; q += 16) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i *>(q));
    const __m128i l = _mm_or_si128(x, _mm_set1_epi8(0x20));
    const __m128i marks = _mm_or_si128(_mm_or_si128(eq(x, '\n'), eq(x, '(')), eq(x, ';'));
    const __m128i words = _mm_or_si128(_mm_or_si128(_mm_or_si128(eq(l, 'd'), eq(l, 'e')), _mm_or_si128(eq(l, 'g'), eq(l, 'i'))),
                                       _mm_or_si128(eq(l, 'm'), eq(l, 'w')));
    if (const int hit = _mm_movemask_epi8(_mm_or_si128(marks, words))) return q + __builtin_ctz((unsigned)hit);
  }
#endif
  while (q < end && kScan.c[(unsigned char)*q] == ScanClass::Skip) ++q;
  return q;
}

static const char *lineEnd(const char *q, const char *end) {
  const char *nl = static_cast<const char *>(std::memchr(q, '\n', (size_t)(end - q)));
  return nl ? nl : end;
}

// A comment from its '(' at q to after its closing parenthesis (they nest), or to the line's end.
static const char *skipComment(const char *q, const char *end) {
  for (int depth = 1; ++q < end && *q != '\n';)
    if (*q == '(') {
      ++depth;
    } else if (*q == ')' && --depth == 0) {
      return q + 1;
    }
  return q;
}

// The rest of a block from q (after its block number): null when it needs the whole program,
// else where it ends (its newline, or the end of the text).
static const char *scanBlock(const char *q, const char *end) {
  for (const char *body = q;;) {
    if ((q = skipPlain(q, end)) >= end) return end;
    switch (kScan.c[(unsigned char)*q]) {
    case ScanClass::Skip: ++q; break;  // not reached: skipPlain stops at the other classes only
    case ScanClass::EndOfLine: return q;
    case ScanClass::EndOfBlock: return lineEnd(q, end);
    case ScanClass::Comment: q = skipComment(q, end); break;
    case ScanClass::Word:
      if (q > body && letter(q[-1])) {  // inside a word that starts with a skipped letter: no keyword
        while (q + 1 < end && letter(q[1])) ++q;
      } else if (needsWholeProgram(q, end)) {
        return nullptr;
      }
      ++q;
      break;
    }
  }
}

// After the first block the pre-scan no longer walks line by line (most lines of a flat program
// need no look at all): it stops only at a byte that may begin something needing the whole
// program, where the line by line walk would look closer. Those are the Word letters but G,
// comments, ';', and O and ':' (a program number at a line's start); a G only when the byte after
// it is not 1-4, 8 or 9 (no code that begins with these digits needs the whole program: G1,
// G17, G40, G80, ... go; G0 stops, as G05 is G5), and not "29" (G290/G291 switch the mode).
static bool stopsBulk(unsigned char c, unsigned char next, unsigned char next2) {
  const ScanClass k = kScan.c[c];
  if (k == ScanClass::Word) {
    if ((c | 0x20) != 'g') return true;
    if (next == '2' && next2 == '9') return true;
    return !((next >= '1' && next <= '4') || next == '8' || next == '9');
  }
  return k == ScanClass::Comment || k == ScanClass::EndOfBlock || (c | 0x20) == 'o' || c == ':';
}

#if NCC_BULK_AVX2
// skipBulk's loop thirty-two bytes at a time where the processor has AVX2 (the same classes and
// the same G rule; three-operand instructions, no register copies): about half the SSE2
// loop's instructions per byte. What is left goes to skipBulk.
[[gnu::target("avx2")]] static inline __m256i eq32(__m256i v, char c) { return _mm256_cmpeq_epi8(v, _mm256_set1_epi8(c)); }
[[gnu::target("avx2")]] static const char *skipBulkAvx2(const char *q, const char *limit, const char *end) {
  const auto eq = eq32;
  for (; limit - q >= 32 && end - q >= 34; q += 32) {
    const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(q));
    const __m256i n = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(q + 1));
    const __m256i n2 = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(q + 2));
    const __m256i l = _mm256_or_si256(x, _mm256_set1_epi8(0x20));
    const __m256i marks = _mm256_or_si256(_mm256_or_si256(eq(x, '('), eq(x, ';')), _mm256_or_si256(eq(x, ':'), eq(l, 'o')));
    const __m256i words = _mm256_or_si256(
        _mm256_or_si256(_mm256_or_si256(eq(l, 'd'), eq(l, 'e')), _mm256_or_si256(eq(l, 'i'), eq(l, 'm'))), eq(l, 'w'));
    const __m256i d = _mm256_sub_epi8(n, _mm256_set1_epi8('1'));
    const __m256i low = _mm256_cmpeq_epi8(_mm256_min_epu8(d, _mm256_set1_epi8(3)), d);
    const __m256i safe = _mm256_andnot_si256(_mm256_and_si256(eq(n, '2'), eq(n2, '9')),
                                             _mm256_or_si256(low, _mm256_or_si256(eq(n, '8'), eq(n, '9'))));
    const __m256i g = _mm256_andnot_si256(safe, eq(l, 'g'));
    if (const unsigned hit = (unsigned)_mm256_movemask_epi8(_mm256_or_si256(_mm256_or_si256(marks, words), g)))
      return q + __builtin_ctz(hit);
  }
  return q;
}
static const bool kHaveAvx2 = [] {
  __builtin_cpu_init();  // this runs as a static constructor, perhaps before libgcc's
  return __builtin_cpu_supports("avx2") != 0;
}();
#endif

// The first byte at or after q (before limit) where stopsBulk holds, or limit: thirty-two bytes
// at a time with AVX2 (skipBulkAvx2), sixteen with SSE2 (the two bytes after each G from a second
// and third load), then byte by byte.
static const char *skipBulk(const char *q, const char *limit, const char *end) {
#if NCC_BULK_AVX2
  if (kHaveAvx2 && (q = skipBulkAvx2(q, limit, end)) < limit && end - q >= 34 && limit - q >= 32) return q;
#endif
#if defined(__SSE2__)
  auto eq = [](__m128i v, char c) { return _mm_cmpeq_epi8(v, _mm_set1_epi8(c)); };
  for (; limit - q >= 16 && end - q >= 18; q += 16) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i *>(q));
    const __m128i n = _mm_loadu_si128(reinterpret_cast<const __m128i *>(q + 1));
    const __m128i n2 = _mm_loadu_si128(reinterpret_cast<const __m128i *>(q + 2));
    const __m128i l = _mm_or_si128(x, _mm_set1_epi8(0x20));
    const __m128i marks = _mm_or_si128(_mm_or_si128(eq(x, '('), eq(x, ';')), _mm_or_si128(eq(x, ':'), eq(l, 'o')));
    const __m128i words = _mm_or_si128(_mm_or_si128(_mm_or_si128(eq(l, 'd'), eq(l, 'e')), _mm_or_si128(eq(l, 'i'), eq(l, 'm'))),
                                       eq(l, 'w'));
    // The digit after a G that lets it pass: '1'..'4' (unsigned: n - '1' <= 3), '8', '9'.
    const __m128i d = _mm_sub_epi8(n, _mm_set1_epi8('1'));
    const __m128i low = _mm_cmpeq_epi8(_mm_min_epu8(d, _mm_set1_epi8(3)), d);
    const __m128i safe = _mm_andnot_si128(_mm_and_si128(eq(n, '2'), eq(n2, '9')),
                                          _mm_or_si128(low, _mm_or_si128(eq(n, '8'), eq(n, '9'))));
    const __m128i g = _mm_andnot_si128(safe, eq(l, 'g'));
    if (const int hit = _mm_movemask_epi8(_mm_or_si128(_mm_or_si128(marks, words), g)))
      return q + __builtin_ctz((unsigned)hit);
  }
#endif
  for (; q < limit; ++q)
    if (stopsBulk((unsigned char)*q, q + 1 < end ? (unsigned char)q[1] : 0, q + 2 < end ? (unsigned char)q[2] : 0))
      return q;
  return limit;
}

// Whether only blanks, tabs, carriage returns and block skips stand between p and its line's start.
static bool atLineStart(const char *text, const char *p) {
  while (p > text && (p[-1] == ' ' || p[-1] == '\t' || p[-1] == '\r' || p[-1] == '/')) --p;
  return p == text || p[-1] == '\n';
}

// Where the line by line walk starts a block's body: at a line's start, or after its N number
// ("N", digits and blanks). Says whether q (not a digit or blank) is there.
static bool atBodyStart(const char *text, const char *q) {
  const char *s = q;
  while (s > text && ((s[-1] >= '0' && s[-1] <= '9') || s[-1] == ' ')) --s;
  if (s > text && up(s[-1]) == 'N' && atLineStart(text, s - 1)) return true;
  return atLineStart(text, q);
}

// The text from q on, once a block has been seen: what the line by line walk finds, stopping only
// where stopsBulk holds. False when something needs the whole program.
static bool scanBulk(const char *text, const char *q, const char *end, const SourceManager *sm, uint32_t file) {
  const char *released = q;
  while (q < end) {
    const char *limit = (size_t)(end - q) > kReleaseEvery ? q + kReleaseEvery : end;
    if ((q = skipBulk(q, limit, end)) < limit) {
      const char c = *q;
      if (c == '(' || c == ';') {
        // A comment to its closing parenthesis or the line's end; after ';' the line is done.
        q = c == ';' ? lineEnd(q, end) : skipComment(q, end);
      } else if (up(c) == 'O' || c == ':') {
        if (atBodyStart(text, q)) return false;  // a program number after a block: a subprogram, an o-word
        ++q;
      } else {
        // A Word letter: inside a longer word (one that starts before it) no keyword, as in scanBlock.
        const bool inside = q > text && letter(q[-1]) && !atBodyStart(text, q);
        if (inside) {
          while (q + 1 < end && letter(q[1])) ++q;
        } else if (needsWholeProgram(q, end)) {
          return false;
        }
        ++q;
      }
    }
    if (sm && (size_t)(q - released) >= kReleaseEvery) sm->released(file, (size_t)((released = q) - text));
  }
  return true;
}

// One pass over the text before streaming: a construct that needs the whole program (control
// flow, calls, subprograms) anywhere means the program is parsed as a whole. Being wrong towards
// "not streamable" only costs speed and memory; the stream itself rejects what slips through.
// (Folding this pass into the stream would need the sinks, the trace file and the diagnostics
// printed so far to be taken back when a late construct, such as a subprogram after M30, turns
// up.) Line by line up to the first block (an O line before it names the program), then in bulk
// (scanBulk); `byLines` keeps to the line by line walk (the unit test compares the two).
bool isoIsStreamable(std::string_view text, const SourceManager *sm, uint32_t file, bool byLines) {
  const char *q = text.data(), *end = q + text.size();
  // A mapped file's scanned pages go as the scan moves on, or the whole text would be resident.
  const char *released = q;
  if (text.size() >= 3 && std::memcmp(q, "\xEF\xBB\xBF", 3) == 0) q += 3;  // UTF-8 BOM
  bool seenContent = false;  // a block before: a later O line is a subprogram
  while (q < end) {
    if (seenContent && !byLines) return scanBulk(text.data(), q, end, sm, file);
    // A line's start: blanks, block skip, the block number (none of these bytes is a newline).
    while (q < end && (*q == ' ' || *q == '\t' || *q == '\r' || *q == '/')) ++q;
    if (q < end && up(*q) == 'N') {
      ++q;
      while (q < end && ((*q >= '0' && *q <= '9') || *q == ' ')) ++q;
    }
    if (q < end && (up(*q) == 'O' || *q == ':')) {  // O1234 or Fanuc :1234
      if (seenContent) return false;  // subprogram or RS274 o-word
      const char *r = q + 1;
      while (r < end && ((*r >= '0' && *r <= '9') || *r == ' ' || *r == '\t' || *r == '\r')) ++r;
      // o100 while ..., o<name> sub, o[#1] call, o#<sub> call: RS274NGC o-words.
      if (r < end && (letter(*r) || *r == '<' || *r == '[' || *r == '#')) return false;
      q = lineEnd(q, end);
    } else {
      if (!seenContent) seenContent = lineHasContent(q, lineEnd(q, end));
      if (!(q = scanBlock(q, end))) return false;
    }
    if (q < end) ++q;  // the newline
    if (sm && (size_t)(q - released) >= kReleaseEvery) sm->released(file, (size_t)((released = q) - text.data()));
  }
  return true;
}

struct IsoBlockStream::Impl {
  Impl(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags)
      : diags(diags), sm(sm), text(sm.text(fileId)), fileId(fileId),
        parser(diags, flavourForFile(sm.name(fileId)), opts.blockDeleteMask, opts.offsetMemory, opts.lathe),
        lower(opts, flavourForFile(sm.name(fileId)), diags) {
    lower.callsRefused = "needs the whole program (not streamable)";
    p = text.data();
    end = p + text.size();
    // Lines up to the last newline can take the parser's fast path without bounds checks.
    const void *nl = text.empty() ? nullptr : memrchr(text.data(), '\n', text.size());
    lastNewline = nl ? static_cast<const char *>(nl) : text.data();
    releasedTo = text.data();
    if (!lower.optionsValid()) {
      diags.error({}, "unknown decimal mode '" + opts.decimalMode + "' (calculator, is-b, is-c)", "options");
      p = end;
    }
  }
  Diagnostics &diags;
  const SourceManager &sm;
  std::string_view text;  // mapped: the pages read are released (SourceManager::released)
  uint32_t fileId;
  BlockParser parser;
  BlockLowerer lower;
  ParsedBlock block;
  const char *p, *end;
  const char *lastNewline;  // a line starting before it ends with a newline (the text's start: none)
  const char *releasedTo = nullptr;  // the text before it was last released (SourceManager::released)
  uint32_t lineNo = 0;
  bool content = false, ended = false, fatal = false;
};

IsoBlockStream::IsoBlockStream(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags)
    : impl_(std::make_unique<Impl>(sm, fileId, opts, diags)) {}

IsoBlockStream::~IsoBlockStream() = default;

uint64_t IsoBlockStream::leanReuses() const { return impl_->lower.leanReuses; }

bool IsoBlockStream::next(ir::Region &out, size_t maxBlocks, CmdSink *lean) {
  Impl &s = *impl_;
  size_t before = out.size();
  size_t blocks = 0;
  while (s.p < s.end && blocks < maxBlocks && !s.fatal && !s.ended) {
    const char *lineStart = s.p;
    ParsedBlock &b = s.block;
    ++s.lineNo;
    // A block of plain words is read up to its newline in one pass (no line search first); any
    // other line, and the last one when no newline ends it, go through parse().
    const char *nl = nullptr;
    if (s.p < s.lastNewline && s.parser.parsePlainLine(s.p, s.end, s.fileId, s.lineNo, b, nl)) {
      s.p = nl + 1;
    } else {
      nl = static_cast<const char *>(std::memchr(s.p, '\n', (size_t)(s.end - s.p)));
      const char *le = nl ? nl : s.end;
      std::string_view line(s.p, (size_t)(le - s.p));
      s.p = nl ? nl + 1 : s.end;
      if (!s.parser.parse(line, s.fileId, s.lineNo, b)) continue;
    }
    if (b.percent) {
      if (s.content) s.ended = true;  // closing '%': the rest is not part of the program
      continue;
    }
    if (!b.content) continue;
    if (b.programNumber >= 0 && !s.content) {  // names the program; its comments stay (Program.cpp)
      s.content = true;
      if (!b.comments.empty()) {
        out.push_back(s.lower.blockOp(b));
        s.lower.lowerComments(b, out);
      }
      continue;
    }
    if (b.programNumber >= 0 || b.stmt != StmtKind::None) {
      s.diags.error(b.loc, "control flow or subprograms need the whole program (not streamable)", "not-streamable");
      s.fatal = true;
      break;
    }
    if (!b.words.empty() || !b.assigns.empty()) s.content = true;
    if (lean) {
      // Commands go to the sink at once, so ops appended before must run first: the block is
      // read again by the next call.
      BlockLowerer::Lean r = s.lower.lowerLean(b, *lean, out.size() > before);
      if (r == BlockLowerer::Lean::Held) {
        s.p = lineStart;
        --s.lineNo;
        break;
      }
      if (r == BlockLowerer::Lean::Stopped) {
        s.fatal = true;
        break;
      }
      if (r != BlockLowerer::Lean::Fallback) {  // done, or an error reported as lowerActions would
        ++blocks;
        continue;
      }
    }
    ++blocks;
    out.push_back(s.lower.blockOp(b));
    s.lower.lowerComments(b, out);
    s.lower.lowerActions(b, out);
    if (s.fatal) break;
  }
  // The text read so far is only needed again for a diagnostic: its pages may go (the chunk's
  // ops keep locations, not text). A megabyte at a time, as the pre-scan: each release walks the
  // mapping from its start and flushes the TLB (madvise), which at every chunk of 4096 blocks
  // cost more system time than the whole run's user time.
  if ((size_t)(s.p - s.releasedTo) >= kReleaseEvery || s.p == s.end) {
    s.sm.released(s.fileId, (size_t)(s.p - s.text.data()));
    s.releasedTo = s.p;
  }
  return out.size() > before || (blocks > 0 && s.p < s.end && !s.fatal);
}

}  // namespace ncc::iso
