// Unit tests of the ISO front end: block parser, Macro B expressions, lowering, program
// structure, streaming, and a bounded fuzz loop (random bytes and mutated programs must give
// diagnostics, never a crash or a hang).
// FEATURES: ISO-LEX-01 ISO-LEX-02 ISO-LEX-03 ISO-LEX-04 ISO-LEX-05 ISO-LEX-06 ISO-MAC-08
#include "frontend/iso/IsoFrontend.h"
#include "frontend/iso/Syntax.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

using namespace ncc;
using namespace ncc::iso;

namespace {

struct Parsed {
  SourceManager sm;
  Diagnostics diags{sm};
  ir::Module module;
  bool ok = false;
  std::string text;  // printed IR
  Parsed(const std::string &src, const char *name = "t.nc", IsoOptions opts = {}) {
    diags.setCollect(true);
    uint32_t f = sm.addBuffer(name, src);
    ok = parseIsoProgram(sm, f, opts, diags, module);
    text = ir::printModule(module);
  }
  std::string firstError() const {
    for (auto &d : diags.collected())
      if (d.severity == Severity::Error) return d.message + " [" + d.rule + "]";
    return {};
  }
};

std::string streamText(const std::string &src, size_t chunk, bool &ok, IsoOptions opts = {}) {
  SourceManager sm;
  Diagnostics diags(sm);
  diags.setCollect(true);
  uint32_t f = sm.addBuffer("t.nc", src);
  IsoBlockStream s(sm, f, opts, diags);
  ir::Module m;
  m.name = "t.nc";
  m.functions.emplace_back();
  m.functions[0].name = "main";
  m.functions[0].loc = {f, 1, 1};
  ir::Region r;
  size_t calls = 0;
  while (s.next(r, chunk)) {
    ++calls;
    for (auto &op : r) m.functions[0].body.push_back(std::move(op));
    r.clear();
    if (calls > 100000) break;
  }
  for (auto &op : r) m.functions[0].body.push_back(std::move(op));
  ok = !diags.hasErrors();
  return ir::printModule(m);
}

}  // namespace

TEST(IsoBlockParser, WordsCommentsAndBlockNumber) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser p(d, Flavour::Fanuc, 0);
  ParsedBlock b;
  ASSERT_TRUE(p.parse("  n0010 g1x-1.5 Y.25 (a (nested) c) Z#3 ;tail", 1, 7, b));
  EXPECT_TRUE(b.content);
  EXPECT_EQ(b.n, 10);
  EXPECT_EQ(b.loc.line, 7u);
  EXPECT_EQ(b.loc.col, 3u);
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[0].letter, 'G');
  EXPECT_EQ(b.words[0].value, 1);
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(b.words[1].value, -1.5);
  EXPECT_TRUE(b.words[1].hasPoint);
  EXPECT_EQ(b.words[1].loc.col, 11u);
  EXPECT_EQ(b.words[2].value, 0.25);
  ASSERT_TRUE(b.words[3].expr);
  EXPECT_EQ(ir::printExpr(*b.words[3].expr), "#3");
  ASSERT_EQ(b.comments.size(), 2u);
  EXPECT_EQ(b.comments[0].text, "a (nested) c");
  EXPECT_EQ(b.comments[1].text, "tail");
  EXPECT_FALSE(d.hasErrors());
}

// Word values are the correctly rounded doubles of their decimals (from_chars), whether the
// parser takes its fast path (< 2^53 digits, <= 22 after the point) or not.
TEST(IsoBlockParser, NumbersMatchFromChars) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser p(d, Flavour::Fanuc, 0);
  std::vector<std::string> texts = {"0", "0.", ".5", "1.866", "0.1", "0.3", "123456.789", "9007199254740991",
                                    "9007199254740992", "9007199254740993", "90071992547409920.5",
                                    "0.1234567890123456789012", "0.12345678901234567890123", "1.7976931348623157",
                                    "000000000000000000000012.5", "4503599627370495.5", "0.0000000000000000000001"};
  std::mt19937_64 rng(6);
  for (int i = 0; i < 2000; ++i) {
    std::string t = std::to_string(rng() % 100000000000ull);
    size_t point = rng() % (t.size() + 1);
    t.insert(point, ".");
    texts.push_back(t);
  }
  for (const std::string &t : texts) {
    ParsedBlock b;
    ASSERT_TRUE(p.parse("X" + t, 1, 1, b)) << t;
    ASSERT_EQ(b.words.size(), 1u) << t;
    std::string digits = t.back() == '.' ? t.substr(0, t.size() - 1) : t;
    double want = 0;
    std::from_chars(digits.data(), digits.data() + digits.size(), want, std::chars_format::fixed);
    EXPECT_EQ(b.words[0].value, want) << t;
  }
  EXPECT_FALSE(d.hasErrors());
}

// A program file is read whole and exactly (several read chunks, NUL and CR bytes kept).
TEST(SourceManagerFile, ReadsWholeFileExactly) {
  std::string path = ::testing::TempDir() + "ncc-source-read.ngc";
  std::string bytes;
  std::mt19937 rng(7);
  for (int i = 0; i < 200000; ++i) bytes.push_back((char)(rng() % 256));
  {
    std::FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    ASSERT_EQ(std::fwrite(bytes.data(), 1, bytes.size(), f), bytes.size());
    std::fclose(f);
  }
  SourceManager sm;
  uint32_t id = sm.addFile(path);
  ASSERT_NE(id, 0u);
  EXPECT_EQ(sm.text(id), bytes);
  EXPECT_EQ(sm.addFile(path + ".missing"), 0u);
  std::remove(path.c_str());
}

TEST(IsoBlockParser, EmptyAndPercentLines) {
  SourceManager sm;
  Diagnostics d(sm);
  BlockParser p(d, Flavour::Fanuc, 0);
  ParsedBlock b;
  ASSERT_TRUE(p.parse("   \r", 1, 1, b));
  EXPECT_FALSE(b.content);
  ASSERT_TRUE(p.parse(";", 1, 1, b));
  EXPECT_FALSE(b.content);
  ASSERT_TRUE(p.parse("%", 1, 1, b));
  EXPECT_TRUE(b.percent);
  ASSERT_TRUE(p.parse("O1234 (NAME)", 1, 1, b));
  EXPECT_EQ(b.programNumber, 1234);
}

TEST(IsoProgram, CrLfAndByteOrderMark) {
  Parsed p("\xEF\xBB\xBFO100\r\nG1 X1 ; c\r\n(n)\r\nM30\r\n");
  ASSERT_TRUE(p.ok) << p.firstError();
  EXPECT_NE(p.text.find("comment text=\"c\" loc(1:2:7)"), std::string::npos) << p.text;
  EXPECT_NE(p.text.find("comment text=\"n\" loc(1:3:1)"), std::string::npos) << p.text;
  EXPECT_TRUE(isoIsStreamable("\xEF\xBB\xBFO100\r\nG1 X1\r\n"));
}

TEST(IsoBlockParser, BlockSkipLevels) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser off(d, Flavour::Fanuc, 0), on3(d, Flavour::Fanuc, 1u << 3);
  ParsedBlock b;
  ASSERT_TRUE(off.parse("/3 X1 /2 Y2", 1, 1, b));
  EXPECT_EQ(b.skip, 3);
  EXPECT_EQ(b.words.size(), 2u);
  ASSERT_TRUE(on3.parse("X1 /3 Y2", 1, 1, b));
  EXPECT_EQ(b.words.size(), 1u);
  ASSERT_TRUE(on3.parse("/3 X1", 1, 1, b));
  EXPECT_FALSE(b.content);
  ASSERT_TRUE(on3.parse("X1 (/3) Y2", 1, 1, b));
  EXPECT_EQ(b.words.size(), 2u);
  EXPECT_FALSE(d.hasErrors());
}

TEST(IsoBlockParser, SyntaxErrorsPointAtTheWord) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser p(d, Flavour::Fanuc, 0);
  ParsedBlock b;
  EXPECT_FALSE(p.parse("G1 X", 1, 1, b));
  EXPECT_FALSE(p.parse("G1 X1 ?", 1, 2, b));
  EXPECT_FALSE(p.parse("G1 (unclosed", 1, 3, b));
  EXPECT_FALSE(p.parse("XY10", 1, 4, b));
  ASSERT_EQ(d.collected().size(), 4u);
  EXPECT_EQ(d.collected()[1].loc.col, 7u);
  EXPECT_EQ(d.collected()[1].message, "unexpected character '?'");
  EXPECT_EQ(d.collected()[2].loc.col, 4u);
  EXPECT_EQ(d.collected()[3].rule, "unknown-code");
}

// The parser's fast path for blocks of plain words (parsePlainWords) gives what the general
// path gives: a trailing comment sends the same block through parseItems, and every word,
// value (sign of zero included), point flag, location and the block number must agree.
TEST(IsoBlockParser, PlainWordsFastPathMatchesGeneralPath) {
  const char *lines[] = {"G1 X-1.5 Y.25",        "X+.5 Y-.5",          "X - 1.5 Y+ 2",          "X5. Y-0 Z-0.",
                         "x1y2z3",               "N10 G1 X1",          "n0010 g1x-1.5",         "N10",
                         "X1 N5 Y2",             "G1\tX1\r",           "X 1",                   "X123456789012345",
                         "X.123456789012345",    "X1234567890123456",  "X0.0000000000000001",   "X1e5",
                         "X1E-5 Y2",             "G2 X5.246 Y-0.079 I2.912 J0", "X000000000000001.5", "N007 X1"};
  for (Flavour fl : {Flavour::Fanuc, Flavour::RS274}) {
    for (const char *line : lines) {
      SCOPED_TRACE(line);
      SourceManager sm;
      Diagnostics d(sm);
      d.setCollect(true);
      BlockParser p(d, fl, 0);
      ParsedBlock fast, general;
      ASSERT_TRUE(p.parse(line, 1, 1, fast));
      ASSERT_TRUE(p.parse(std::string(line) + " (c)", 1, 1, general));
      EXPECT_EQ(fast.n, general.n);
      EXPECT_TRUE(fast.content);
      EXPECT_TRUE(fast.comments.empty());
      ASSERT_EQ(fast.words.size(), general.words.size());
      for (size_t i = 0; i < fast.words.size(); ++i) {
        const IsoWord &a = fast.words[i], &b = general.words[i];
        EXPECT_EQ(a.letter, b.letter);
        EXPECT_EQ(a.hasPoint, b.hasPoint);
        EXPECT_EQ(a.value, b.value);
        EXPECT_EQ(std::signbit(a.value), std::signbit(b.value));
        EXPECT_EQ(a.loc.col, b.loc.col);
        EXPECT_FALSE(a.expr);
      }
      EXPECT_FALSE(d.hasErrors());
    }
  }
}

// The same comparison on random lines of words (a letter, blanks, a sign, digits with points,
// now and then a stray byte): a line and its twin with a comment are accepted or refused alike,
// and when accepted, read alike.
TEST(IsoBlockParser, PlainWordsFastPathMatchesGeneralPathRandomly) {
  std::mt19937 rng(66);
  auto pick = [&](const std::string &from) { return from[rng() % from.size()]; };
  auto randomLine = [&] {
    std::string line;
    for (int words = 1 + (int)(rng() % 5); words > 0; --words) {
      line.push_back(pick("GXYZIJFNxgn"));
      while (rng() % 4 == 0) line.push_back(pick(" \t"));
      if (rng() % 3 == 0) line.push_back(pick("+-"));
      while (rng() % 4 == 0) line.push_back(' ');
      for (int n = (int)(rng() % 19); n > 0; --n) line.push_back(rng() % 8 == 0 ? '.' : pick("0123456789"));
      while (rng() % 3 == 0) line.push_back(' ');
      if (rng() % 40 == 0) line.push_back(pick("e?#;/"));
    }
    return line;
  };
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser fanuc(d, Flavour::Fanuc, 0), rs274(d, Flavour::RS274, 0);
  ParsedBlock fast, general;
  int accepted = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::string line = randomLine();
    BlockParser &p = i % 2 ? rs274 : fanuc;
    bool a = p.parse(line, 1, 1, fast), b = p.parse(line + " (c)", 1, 1, general);
    ASSERT_EQ(a, b) << line;
    if (!a) continue;
    ++accepted;
    EXPECT_EQ(fast.n, general.n) << line;
    ASSERT_EQ(fast.words.size(), general.words.size()) << line;
    for (size_t k = 0; k < fast.words.size(); ++k) {
      EXPECT_EQ(fast.words[k].letter, general.words[k].letter) << line;
      EXPECT_EQ(fast.words[k].hasPoint, general.words[k].hasPoint) << line;
      EXPECT_EQ(fast.words[k].value, general.words[k].value) << line;
      EXPECT_EQ(std::signbit(fast.words[k].value), std::signbit(general.words[k].value)) << line;
      EXPECT_EQ(fast.words[k].loc.col, general.words[k].loc.col) << line;
    }
  }
  EXPECT_GT(accepted, 4000);  // the comparison is not vacuous
}

// The stream's line path (parsePlainLine: read to the newline, no line search first) takes a
// line only when parse() takes it on its fast path, and reads it alike: words, values (sign of
// zero included), points, columns, the block number, the block's location; its end is the
// line's newline. Random texts of plain-looking lines with blanks, CR, empty lines, block skips,
// comments and stray bytes; one ParsedBlock each, reused line after line as the stream does.
TEST(IsoBlockParser, PlainLineMatchesParse) {
  std::mt19937 rng(606);
  auto pick = [&](const std::string &from) { return from[rng() % from.size()]; };
  auto randomLine = [&] {
    std::string line;
    while (rng() % 5 == 0) line.push_back(pick(" \t"));
    if (rng() % 50 == 0) line.push_back(pick("%/(O"));
    for (int words = (int)(rng() % 6); words > 0; --words) {
      line.push_back(pick("GXYZIJFNxgnMO"));
      while (rng() % 4 == 0) line.push_back(pick(" \t\v\f"));
      if (rng() % 3 == 0) line.push_back(pick("+-"));
      while (rng() % 4 == 0) line.push_back(' ');
      for (int n = (int)(rng() % 19); n > 0; --n) line.push_back(rng() % 8 == 0 ? '.' : pick("0123456789"));
      while (rng() % 3 == 0) line.push_back(' ');
      if (rng() % 40 == 0) line.push_back(pick("e?#;/(\r"));
    }
    if (rng() % 10 == 0) line.push_back('\r');
    return line;
  };
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  int taken = 0;
  for (int round = 0; round < 400; ++round) {
    std::string text;
    std::vector<size_t> starts;
    for (int i = 0; i < 100; ++i) starts.push_back(text.size()), text += randomLine() + "\n";
    BlockParser p(d, round % 2 ? Flavour::RS274 : Flavour::Fanuc, 0);
    ParsedBlock line, whole;
    for (size_t i = 0; i < starts.size(); ++i) {
      const char *b = text.data() + starts[i], *nl = nullptr;
      const char *e = text.data() + text.find('\n', starts[i]);
      const std::string_view view(b, (size_t)(e - b));
      const uint32_t lineNo = (uint32_t)i + 2;
      const bool fast = p.parsePlainLine(b, text.data() + text.size(), 3, lineNo, line, nl);
      const bool ok = p.parse(view, 3, lineNo, whole);
      ASSERT_EQ(fast, ok && whole.plain) << view;
      if (!fast) continue;
      ++taken;
      EXPECT_EQ(nl, e) << view;
      EXPECT_TRUE(line.plain && line.content) << view;
      EXPECT_EQ(line.n, whole.n) << view;
      EXPECT_EQ(line.loc.line, whole.loc.line) << view;
      EXPECT_EQ(line.loc.col, whole.loc.col) << view;
      ASSERT_EQ(line.words.size(), whole.words.size()) << view;
      for (size_t k = 0; k < line.words.size(); ++k) {
        const IsoWord &x = line.words[k], &y = whole.words[k];
        EXPECT_EQ(x.letter, y.letter) << view;
        EXPECT_EQ(x.hasPoint, y.hasPoint) << view;
        EXPECT_EQ(x.value, y.value) << view;
        EXPECT_EQ(std::signbit(x.value), std::signbit(y.value)) << view;
        EXPECT_EQ(x.loc.file, y.loc.file) << view;
        EXPECT_EQ(x.loc.line, y.loc.line) << view;
        EXPECT_EQ(x.loc.col, y.loc.col) << view;
      }
    }
  }
  EXPECT_GT(taken, 5000);  // the comparison is not vacuous
}

// One ParsedBlock reused line after line (as the stream does): a plain block after a general
// one, a general one after a plain one, and a fast path given up half way leave nothing behind.
TEST(IsoBlockParser, PlainAndGeneralBlocksAlternate) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser p(d, Flavour::Fanuc, 0);
  ParsedBlock b;
  ASSERT_TRUE(p.parse("N5 G1 X1 Y2 Z3", 1, 1, b));
  EXPECT_TRUE(b.plain);
  ASSERT_TRUE(p.parse("G1 X1 Y2 Z3 (c) #1=2", 1, 2, b));  // the fast path reads three words, then gives up
  EXPECT_FALSE(b.plain);
  EXPECT_EQ(b.n, -1);
  EXPECT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.comments.size(), 1u);
  EXPECT_EQ(b.assigns.size(), 1u);
  ASSERT_TRUE(p.parse("X4", 1, 3, b));
  EXPECT_TRUE(b.plain);
  EXPECT_EQ(b.words.size(), 1u);
  EXPECT_TRUE(b.comments.empty());
  EXPECT_TRUE(b.assigns.empty());
  EXPECT_EQ(b.loc.line, 3u);
  ASSERT_TRUE(p.parse("  ", 1, 4, b));
  EXPECT_FALSE(b.content);
  EXPECT_TRUE(b.words.empty());
  ASSERT_TRUE(p.parse("IF [#1 EQ 2] GOTO 5", 1, 5, b));
  EXPECT_EQ(b.stmt, StmtKind::IfGoto);
  ASSERT_TRUE(p.parse("N7 Y1", 1, 6, b));
  EXPECT_EQ(b.stmt, StmtKind::None);
  EXPECT_FALSE(b.cond);
  EXPECT_EQ(b.n, 7);
  EXPECT_FALSE(d.hasErrors());
}

// Malformed plain-looking blocks leave the fast path before any diagnostic: the general path
// reports them, with its message and column.
TEST(IsoBlockParser, PlainWordsFastPathLeavesErrorsToTheGeneralPath) {
  struct Case {
    const char *line;
    unsigned col;
    const char *message;
  } cases[] = {
      {"G1 X", 5, "missing value after 'X'"},
      {"G1 X-", 6, "missing value after 'X'"},
      {"G1 X.", 5, "missing value after 'X'"},
      {"G1 X- Y1", 7, "missing value after 'X'"},
      {"G1 X1.2.3", 8, "unexpected character '.'"},
      {"G1 X1?", 6, "unexpected character '?'"},
      {"N-1 X1", 2, "N needs a block number"},
      {"N1.5 X1", 1, "block number must be an integer below 10^15"},
      {"N1 X1 N2", 7, "two N words in one block"},
      {"X1 O5", 4, "O (program number / o-word) must start the block"},
      {"G1 XY10", 4, "unknown word 'XY'"},
      {"G1 X1 Y#", 8, "'#' needs a variable number"},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.line);
    SourceManager sm;
    Diagnostics d(sm);
    d.setCollect(true);
    BlockParser p(d, Flavour::Fanuc, 0);
    ParsedBlock b;
    EXPECT_FALSE(p.parse(c.line, 1, 1, b));
    ASSERT_EQ(d.collected().size(), 1u);
    EXPECT_EQ(d.collected()[0].loc.col, c.col);
    EXPECT_EQ(d.collected()[0].message, c.message);
  }
}

static std::string exprOf(const char *src, Flavour fl = Flavour::Fanuc) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  BlockParser p(d, fl, 0);
  ParsedBlock b;
  std::string line = std::string("#1=") + src;
  if (!p.parse(line, 1, 1, b) || b.assigns.empty()) return "<error>";
  return ir::printExpr(*b.assigns[0].value);
}

TEST(IsoExpr, FanucPrecedence) {
  EXPECT_EQ(exprOf("1+2*3"), "(add 1 (mul 2 3))");
  EXPECT_EQ(exprOf("1-2-3"), "(sub (sub 1 2) 3)");
  // Fanuc: AND/OR/XOR on values are bitwise; joining comparisons they stay logical.
  EXPECT_EQ(exprOf("#1 AND #2 OR #3"), "(bor (band #1 #2) #3)");
  EXPECT_EQ(exprOf("[#1 EQ 1] AND [#2 EQ 2]"), "(and (eq #1 1) (eq #2 2))");
  EXPECT_EQ(exprOf("FIX[#1] + FUP[#2]"), "(add (TRUNC #1) (AWAYFROMZERO #2))");
  EXPECT_EQ(exprOf("#1 + 1 GT #2 * 2"), "(gt (add #1 1) (mul #2 2))");
  EXPECT_EQ(exprOf("7 MOD 3"), "(mod 7 3)");
  EXPECT_EQ(exprOf("-[#1]"), "(neg #1)");
  EXPECT_EQ(exprOf("-2"), "-2");
  EXPECT_EQ(exprOf("#0"), "vacant");
  EXPECT_EQ(exprOf("ATAN[1]/[2]"), "(ATAN2 1 2)");
  EXPECT_EQ(exprOf("atan[1]/2"), "(div (ATAN 1) 2)");
  EXPECT_EQ(exprOf("2**3"), "<error>");  // no power operator in Macro B
}

TEST(IsoExpr, RS274Precedence) {
  EXPECT_EQ(exprOf("#1 LT 2 AND #2 GT 3", Flavour::RS274), "(and (lt #1 2) (gt #2 3))");
  EXPECT_EQ(exprOf("2 ** 3 ** 2", Flavour::RS274), "(pow 2 (pow 3 2))");
  EXPECT_EQ(exprOf("1 + 2 * 3 MOD 4", Flavour::RS274), "(add 1 (mod (mul 2 3) 4))");
  EXPECT_EQ(exprOf("#<_Global> + #<lo cal>", Flavour::RS274), "(add %%_global %local)");
}

TEST(IsoExpr, DeepNestingIsAnErrorNotACrash) {
  std::string deep(5000, '[');
  EXPECT_EQ(exprOf(deep.c_str()), "<error>");
  std::string minus(5000, '-');
  EXPECT_EQ(exprOf((minus + "1").c_str()), "<error>");
  std::string vars(5000, '#');
  EXPECT_EQ(exprOf((vars + "1").c_str()), "<error>");
}

TEST(IsoLower, ExecutionOrderOfOneBlock) {
  Parsed p("N5 M8 G1 G17 G21 G90 G94 G54 G43 H2 G41 D3 X1 F100 S200 T4 M6 M3 M5000\n");
  ASSERT_TRUE(p.ok) << p.firstError();
  const auto &body = p.module.functions[0].body;
  std::vector<std::string> kinds;
  for (auto &op : body) kinds.push_back(ir::opInfo(op.kind).name);
  std::vector<std::string> want = {"block", "mode",        "feed",        "speed",       "tool_select",
                                   "tool_change", "spindle", "coolant",   "mode",        "mode",
                                   "cutter_comp", "tool_length", "work_offset", "mode", "mode",
                                   "move",  "aux"};
  EXPECT_EQ(kinds, want);
  EXPECT_EQ(ir::printExpr(*body[1].get("feed_mode")), "per_minute");
  EXPECT_EQ(ir::printExpr(*body[13].get("distance")), "absolute");
  EXPECT_EQ(ir::printExpr(*body[14].get("motion")), "linear");
}

TEST(IsoLower, DecimalModeScalesOnlyWordsWithoutPoint) {
  IsoOptions o;
  o.decimalMode = "is-b";
  Parsed p("G1 X1234 Y5. Z#1 F100\n", "t.nc", o);
  ASSERT_TRUE(p.ok) << p.firstError();
  const ir::Op &move = p.module.functions[0].body.back();
  EXPECT_EQ(move.get("X")->num, 1.234);
  EXPECT_EQ(move.get("Y")->num, 5.0);
  EXPECT_EQ(ir::printExpr(*move.get("Z")), "#1");
  o.decimalMode = "bogus";
  Parsed bad("G1 X1\n", "t.nc", o);
  EXPECT_FALSE(bad.ok);
}

TEST(IsoLower, ModalGroupConflictAndUnknownCode) {
  Parsed p("G90 G91 X10\n");
  EXPECT_FALSE(p.ok);
  EXPECT_EQ(p.firstError(), "two G codes from the same modal group: G90 and G91 [modal-group-conflict]");
  Parsed u("G7 X1\n");
  EXPECT_EQ(u.firstError(), "unknown G code G7 [unknown-code]");
  Parsed m("M3 M8 M10 M11 M12 M13\n");
  EXPECT_EQ(m.firstError(), "more than 5 M codes in one block [too-many-m-codes]");
}

TEST(IsoProgram, SubprogramsInTheSameFile) {
  Parsed p("%\nO100\nM98 P0200\nG65 P300 A1 X2\nM30\n%\nO0200\nG1 X1\nM99\n%\nO300\n#100=#1+#24\nM99\n%\n");
  ASSERT_TRUE(p.ok) << p.firstError();
  ASSERT_EQ(p.module.functions.size(), 3u);
  EXPECT_EQ(p.module.functions[0].name, "main");
  EXPECT_EQ(p.module.functions[1].name, "O200");
  EXPECT_EQ(p.module.functions[2].name, "O300");
  EXPECT_NE(p.text.find("call callee=\"O300\" count=1 frame=new a.1=1 a.24=2"), std::string::npos) << p.text;
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  EXPECT_TRUE(ir::verifyModule(p.module, d));
}

TEST(IsoProgram, MissingSubprogramIsReportedAtTheCall) {
  Parsed p("G1 X1\nM98 P9999\n", "/nonexistent-dir/t.nc");
  EXPECT_FALSE(p.ok);
  ASSERT_FALSE(p.diags.collected().empty());
  EXPECT_EQ(p.diags.collected()[0].loc.line, 2u);
  EXPECT_EQ(p.diags.collected()[0].rule, "missing-subprogram");
}

TEST(IsoProgram, LoopNestingChecked) {
  Parsed ok("WHILE [#1 LT 2] DO1\nDO2\nEND2\nEND1\n");
  EXPECT_TRUE(ok.ok) << ok.firstError();
  Parsed bad("WHILE [#1 LT 2] DO1\nEND2\n");
  EXPECT_FALSE(bad.ok);
  EXPECT_EQ(bad.firstError(), "END2 does not match DO1 [loop-mismatch]");
  Parsed stray("END1\n");
  EXPECT_EQ(stray.firstError(), "END1 without WHILE ... DO1 [loop-mismatch]");
}

TEST(IsoProgram, RS274OWords) {
  Parsed p("o<sq> sub\n#<r> = [#1 ** 2]\no<sq> endsub\n#<i>=0\no100 while [#<i> LT 3]\n"
           "o101 if [#<i> EQ 1]\nG1 X1\no101 elseif [#<i> EQ 2]\nG1 X2\no101 else\nG1 X3\no101 endif\n"
           "o<sq> call [#<i>]\n#<i>=[#<i>+1]\no100 endwhile\no102 do\no102 while [0]\no103 repeat [2]\no103 endrepeat\nM2\n",
           "t.ngc");
  ASSERT_TRUE(p.ok) << p.firstError() << p.text;
  ASSERT_EQ(p.module.functions.size(), 2u);
  EXPECT_EQ(p.module.functions[1].name, "sq");
  EXPECT_NE(p.text.find("call callee=\"sq\" frame=new a.1=%i"), std::string::npos) << p.text;
  EXPECT_NE(p.text.find("loop count=2"), std::string::npos) << p.text;
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  EXPECT_TRUE(ir::verifyModule(p.module, d));
}

TEST(IsoStream, Streamability) {
  EXPECT_TRUE(isoIsStreamable("%\nO1000 (X)\nG1 X1\n#1=2 (IF in a comment)\nG2 X1 I1 ; WHILE\nM30\n%\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\nIF [#1 GT 1] GOTO 5\n"));
  EXPECT_FALSE(isoIsStreamable("WHILE [1] DO1\nEND1\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\nGOTO 5\n"));
  EXPECT_FALSE(isoIsStreamable("M98 P1000\n"));
  EXPECT_FALSE(isoIsStreamable("m99\n"));
  EXPECT_FALSE(isoIsStreamable("G65 P1 A1\n"));
  EXPECT_FALSE(isoIsStreamable("G66 P1\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\nM30\nO2000\nM99\n"));
  EXPECT_FALSE(isoIsStreamable("o100 while [1]\no100 endwhile\n"));
  EXPECT_TRUE(isoIsStreamable("G1 X[SIN[30]] Y#<_a>\n"));
}

// The pre-scan's edges: what it skips (comments, nested or unclosed, text after ';', function
// names, words that only contain a keyword), what it must see in either case, and the Fanuc
// abbreviations of the statements (GO 10 is a GOTO).
TEST(IsoStream, StreamabilityEdges) {
  EXPECT_TRUE(isoIsStreamable("G1 X1 (a (IF) b) Y2 (GOTO\nM30\n"));
  EXPECT_TRUE(isoIsStreamable("G1 X1 ; GOTO 5 (\nG1 X2\n"));
  EXPECT_TRUE(isoIsStreamable("G1 X[FIX[1.5]+ROUND[2]+EXP[1]+ABS[-1]] Y[1 MOD 2] Z[1 EQ 1]\n"));
  EXPECT_TRUE(isoIsStreamable("G1 X1\nXIF\nAGOTO 5\n"));  // no keyword: the parser reports these
  EXPECT_TRUE(isoIsStreamable("G5.1 Q1\nG64 G61 G17 G0 X1\nM3 M8 M990\n"));
  EXPECT_TRUE(isoIsStreamable("(only a comment)\n%\nN10\nO100\nG1 X1\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\ng65 p1\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1 M 98 P100\n"));
  EXPECT_FALSE(isoIsStreamable("G5 P1\n"));
  EXPECT_FALSE(isoIsStreamable("G71 P10 Q20\n"));
  EXPECT_FALSE(isoIsStreamable("M#1\n"));
  EXPECT_FALSE(isoIsStreamable("G[1]\n"));
  EXPECT_FALSE(isoIsStreamable("N10 G1 X1\nN20 O200\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1 (c) ENDWHILE\nEND1\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\nGO 3\nG1 X2\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\nwh [#1 LT 2] do1\n"));
  EXPECT_FALSE(isoIsStreamable("G1 X1\nEN1\n"));
}

// After the first block the pre-scan stops only at the bytes that may matter (the bulk scan);
// it must decide as the line by line walk does, on random programs made of the pieces both
// look at: every statement word, G/M codes that do and do not need the whole program (G0 5,
// G05, G 65, G1 G17 G80), O and ':' at a line's start, after N, inside words and comments,
// block skips, ';', nested and unclosed comments, CR LF, lower case, and the text's end
// anywhere, and with the pieces near the sixteen-byte steps (runs of plain words between).
TEST(IsoStream, BulkPreScanDecidesAsLineByLine) {
  static const char *kPieces[] = {
      "G1 X1.5 Y-2", "G01", "G0", "G00 Z1", "G05", "G5.1", "G 65", "G65", "G66", "G70", "G73", "G74", "G17", "G80",
      "G4 P1", "G9", "G8", "G28", "G290", "G291", "g290", "G29", "G2", "g1", "g05", "g 66", "M98", "M99", "M3", "M 98", "m98", "M#1", "G[1]", "G #1",
      "IF", "GOTO 5", "GO", "DO1", "END1", "EN", "WHILE", "WH", "XIF", "AGOTO", "COS[1]", "ROUND", "O100", "o100",
      ":100", "N10", "N", "N 20", "NG65", "N10G65", "N10 O2", "/", "/N5 O1", "(IF)", "(a (GOTO) b)", "(unclosed",
      ";M98", "; (", "#1=2", "D1", "E1", "I1", "W1", "MOVE", "\r", " ", "\t", "%", "X", "0", "5", "6", "7"};
  std::mt19937 rng(6);
  for (int round = 0; round < 60000; ++round) {
    std::string src;
    const int lines = 1 + int(rng() % 6);
    for (int l = 0; l < lines; ++l) {
      if (rng() % 3 == 0) src += std::string(rng() % 20, 'X');  // shifts the pieces against the steps
      for (int k = int(rng() % 4); k >= 0; --k) {
        src += kPieces[rng() % std::size(kPieces)];
        if (rng() % 2) src += ' ';
      }
      if (l + 1 < lines || rng() % 2) src += rng() % 4 ? "\n" : "\r\n";
    }
    ASSERT_EQ(isoIsStreamable(src), isoIsStreamable(src, nullptr, 0, true)) << src;
  }
}

TEST(IsoStream, SameOpsAsWholeProgramParse) {
  std::string src = "(head)\nG21 G90 G17 G94\nG0 X0 Y0 Z1\nF1500\n";
  for (int i = 0; i < 50; ++i) src += "G1 X" + std::to_string(i) + ".5 Y-" + std::to_string(i) + "\n";
  src += "G2 X1 Y1 I1 J0\nM2\n";
  Parsed whole(src);
  ASSERT_TRUE(whole.ok);
  for (size_t chunk : {1, 7, 4096}) {
    bool ok;
    EXPECT_EQ(streamText(src, chunk, ok), whole.text) << "chunk " << chunk;
    EXPECT_TRUE(ok);
  }
}

TEST(IsoStream, ControlFlowIsAFatalError) {
  bool ok;
  std::string t = streamText("G1 X1\nWHILE [1] DO1\nEND1\n", 100, ok);
  EXPECT_FALSE(ok);
}

// Random bytes and mutated valid programs: every input must finish with either success or
// reported errors. Bounded so the test stays fast.
TEST(IsoFuzz, RandomInputNeverCrashes) {
  // NCC_FUZZ_ITERS / NCC_FUZZ_SEED allow longer runs (e.g. under the sanitizer build).
  const char *itersEnv = std::getenv("NCC_FUZZ_ITERS"), *seedEnv = std::getenv("NCC_FUZZ_SEED");
  const int iters = itersEnv ? std::atoi(itersEnv) : 6000;
  std::mt19937 rng(seedEnv ? (unsigned)std::atoi(seedEnv) : 20261122u);
  const std::string seeds[] = {
      "%\nO1\nN10 G1 X1. Y-2 F100 (c (n))\n#1=[#2+SIN[30]]*2\nIF [#1 GT 2] GOTO 10\n"
      "WHILE [#1 LT 5] DO1\n#1=#1+1\nEND1\nM98 P2\nG65 P2 A1\nM30\n%\nO2\nG81 X1 Z-1 R1 K2\nM99\n%\n",
      "o100 while [#<i> LT 3]\n#<i>=[#<i>+1]\no100 endwhile\no<s> sub\no<s> endsub\nM2\n",
  };
  const char alphabet[] = "GXYZMNOPQRIJK#[]()/;%=+-*. 0123456789\nIFGOTOWHILEDOENDabcSIN<>_,$\t";
  for (int iter = 0; iter < iters; ++iter) {
    std::string src;
    int mode = iter % 3;
    if (mode == 0) {
      size_t n = rng() % 200;
      for (size_t i = 0; i < n; ++i) src.push_back((char)(rng() & 0xff));
    } else if (mode == 1) {
      size_t n = rng() % 300;
      for (size_t i = 0; i < n; ++i) src.push_back(alphabet[rng() % (sizeof(alphabet) - 1)]);
    } else {
      src = seeds[rng() % 2];
      for (int k = 0; k < 1 + (int)(rng() % 6); ++k) {
        size_t pos = rng() % (src.size() + 1);
        switch (rng() % 3) {
        case 0: src.insert(pos, 1, alphabet[rng() % (sizeof(alphabet) - 1)]); break;
        case 1: if (pos < src.size()) src.erase(pos, 1); break;
        default: if (pos < src.size()) src[pos] = (char)(rng() & 0xff); break;
        }
      }
    }
    const char *name = (iter & 4) ? "f.ngc" : "/nonexistent-dir/f.nc";
    Parsed p(src, name);
    if (!p.ok) {
      EXPECT_TRUE(p.diags.hasErrors()) << "failure without a diagnostic for input:\n" << src;
    } else {
      SourceManager sm;
      Diagnostics d(sm);
      d.setCollect(true);
      bool valid = ir::verifyModule(p.module, d);
      std::string why;
      for (auto &x : d.collected()) why += x.message + "\n";
      EXPECT_TRUE(valid) << why << "invalid IR for input:\n" << src << "\n" << p.text;
    }
    if (isoIsStreamable(src)) {
      bool ok;
      streamText(src, 3, ok);
    }
  }
}
