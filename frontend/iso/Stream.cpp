// Streaming parse of flat programs (no control flow, calls or subprograms), block by block, so a
// million-line file never exists as one IR module.
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Lower.h"

#include <cstdint>
#include <cstring>

namespace ncc::iso {

static inline char up(char c) { return (c >= 'a' && c <= 'z') ? (char)(c - 32) : c; }
static inline bool letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// The scan's byte classes: most bytes of a part program are digits, signs and points (Other),
// which the scan only notes as content; one table lookup skips them.
enum class ByteClass : uint8_t { Other, Blank, Special };
struct ByteClasses {
  ByteClass c[256];
  constexpr ByteClasses() : c{} {
    for (int i = 0; i < 256; ++i) {
      bool l = (i >= 'A' && i <= 'Z') || (i >= 'a' && i <= 'z');
      bool s = i == '(' || i == ')' || i == ';' || i == '%';
      c[i] = l || s ? ByteClass::Special : i == ' ' || i == '\t' || i == '\r' ? ByteClass::Blank : ByteClass::Other;
    }
  }
};
static constexpr ByteClasses kBytes;

bool isoIsStreamable(std::string_view text, const SourceManager *sm, uint32_t file) {
  const char *p = text.data(), *end = p + text.size();
  // A mapped file's scanned pages go as the scan moves on, or the whole text would be resident.
  constexpr size_t kReleaseEvery = 1 << 20;
  const char *released = p;
  if (text.size() >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;  // UTF-8 BOM
  bool seenContent = false;  // a block before: a later O line is a subprogram
  while (p < end) {
    // One line.
    const char *nl = static_cast<const char *>(std::memchr(p, '\n', (size_t)(end - p)));
    const char *le = nl ? nl : end;
    const char *q = p;
    while (q < le && (*q == ' ' || *q == '\t' || *q == '\r' || *q == '/')) ++q;
    if (q < le && up(*q) == 'N') {  // skip the block number
      ++q;
      while (q < le && ((*q >= '0' && *q <= '9') || *q == ' ')) ++q;
    }
    if (q < le && (up(*q) == 'O' || *q == ':')) {  // O1234 or Fanuc :1234
      if (seenContent) return false;  // subprogram or RS274 o-word
      const char *r = q + 1;
      while (r < le && ((*r >= '0' && *r <= '9') || *r == ' ' || *r == '\t' || *r == '\r')) ++r;
      // o100 while ..., o<name> sub, o[#1] call, o#<sub> call: RS274NGC o-words.
      if (r < le && (letter(*r) || *r == '<' || *r == '[' || *r == '#')) return false;
      p = nl ? nl + 1 : end;
      continue;
    }
    int depth = 0;
    for (; q < le; ++q) {
      char c = *q;
      ByteClass k = kBytes.c[(unsigned char)c];
      if (k == ByteClass::Other) {  // not in a comment: content
        seenContent |= depth == 0;
        continue;
      }
      if (k == ByteClass::Blank) continue;
      if (c == '(') {
        ++depth;
        continue;
      }
      if (c == ')') {
        if (depth) --depth;
        continue;
      }
      if (depth) continue;
      if (c == ';') break;
      if (c == '%') continue;
      if (!letter(c)) {
        if (c != ' ' && c != '\t' && c != '\r') seenContent = true;
        continue;
      }
      seenContent = true;
      const char *b = q;
      while (q + 1 < le && letter(q[1])) ++q;
      size_t n = (size_t)(q - b + 1);
      if (n >= 2) {
        // Keywords that need the whole program; function names and operators are fine.
        char k0 = up(b[0]), k1 = up(b[1]);
        if ((n == 2 && k0 == 'I' && k1 == 'F') || (n == 2 && k0 == 'D' && k1 == 'O') ||
            (n == 3 && k0 == 'E' && k1 == 'N' && up(b[2]) == 'D') ||
            (n == 4 && k0 == 'G' && k1 == 'O' && up(b[2]) == 'T' && up(b[3]) == 'O') ||
            (n == 5 && k0 == 'W' && k1 == 'H' && up(b[2]) == 'I'))
          return false;
        continue;
      }
      char L = up(c);
      if (L != 'M' && L != 'G') continue;
      const char *r = q + 1;
      while (r < le && (*r == ' ' || *r == '\t')) ++r;
      if (r < le && (*r == '#' || *r == '[')) return false;  // computed code: play safe
      long v = 0;
      int digits = 0;
      while (r < le && *r >= '0' && *r <= '9' && digits < 9) v = v * 10 + (*r++ - '0'), ++digits;
      if (L == 'M' && (v == 98 || v == 99)) return false;
      if (L == 'G' && (v == 65 || v == 66 || v == 5) && (r >= le || *r != '.')) return false;
      // Lathe contour cycles G70-G73 run a block range (also G73 of a mill: playing safe).
      if (L == 'G' && v >= 70 && v <= 73 && (r >= le || *r != '.')) return false;
    }
    p = nl ? nl + 1 : end;
    if (sm && (size_t)(p - released) >= kReleaseEvery) sm->released(file, (size_t)((released = p) - text.data()));
  }
  return true;
}

struct IsoBlockStream::Impl {
  Impl(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags)
      : diags(diags), sm(sm), text(sm.text(fileId)), fileId(fileId),
        parser(diags, flavourForFile(sm.name(fileId)), opts.blockDeleteMask, opts.offsetMemory, opts.lathe),
        lower(opts, flavourForFile(sm.name(fileId)), diags) {
    lower.allowCalls = false;
    p = text.data();
    end = p + text.size();
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
  uint32_t lineNo = 0;
  bool content = false, ended = false, fatal = false;
};

IsoBlockStream::IsoBlockStream(SourceManager &sm, uint32_t fileId, const IsoOptions &opts, Diagnostics &diags)
    : impl_(std::make_unique<Impl>(sm, fileId, opts, diags)) {}

IsoBlockStream::~IsoBlockStream() = default;

bool IsoBlockStream::next(ir::Region &out, size_t maxBlocks, CmdSink *lean) {
  Impl &s = *impl_;
  size_t before = out.size();
  size_t blocks = 0;
  while (s.p < s.end && blocks < maxBlocks && !s.fatal && !s.ended) {
    const char *lineStart = s.p;
    const char *nl = static_cast<const char *>(std::memchr(s.p, '\n', (size_t)(s.end - s.p)));
    const char *le = nl ? nl : s.end;
    std::string_view line(s.p, (size_t)(le - s.p));
    s.p = nl ? nl + 1 : s.end;
    ++s.lineNo;
    ParsedBlock &b = s.block;
    if (!s.parser.parse(line, s.fileId, s.lineNo, b)) continue;
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
  // ops keep locations, not text).
  s.sm.released(s.fileId, (size_t)(s.p - s.text.data()));
  return out.size() > before || (blocks > 0 && s.p < s.end && !s.fatal);
}

}  // namespace ncc::iso
