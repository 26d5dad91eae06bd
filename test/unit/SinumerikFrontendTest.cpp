// Unit tests of the Sinumerik front end: the lexer, the G-code table, lowering to NC IR, and a
// bounded fuzz loop (mutated programs give diagnostics or a module the verifier accepts, never a
// crash or a hang).
// FEATURES: SIN-LEX-08 SIN-LEX-09 SIN-LEX-10 SIN-EXP-09
#include "frontend/sinumerik/Codes.h"
#include "frontend/sinumerik/Lexer.h"
#include "frontend/sinumerik/SinFrontend.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace ncc;
using namespace ncc::sin;

namespace {

struct Parsed {
  SourceManager sm;
  Diagnostics diags{sm};
  ir::Module module;
  bool ok = false;
  std::string text;
  explicit Parsed(const std::string &src) {
    diags.setCollect(true);
    uint32_t f = sm.addBuffer("t.mpf", src);
    SinOptions o;
    ok = parseSinumerikProgram(sm, f, o, diags, module);
    text = ir::printModule(module);
  }
  std::string firstError() const {
    for (auto &d : diags.collected())
      if (d.severity == Severity::Error) return d.message;
    return {};
  }
};

std::vector<Token> lex(const std::string &s) {
  std::vector<Token> t;
  std::string err;
  uint32_t col = 0;
  EXPECT_TRUE(lexLine(s, t, err, col)) << err;
  return t;
}

}  // namespace

TEST(SinLexer, NumbersAndConstants) {
  auto t = lex("R1=1.5EX-3 R2='H1f' R3='B101' R4=.25 ; comment");
  ASSERT_EQ(t.size(), 13u);
  EXPECT_EQ(t[0].text, "R1");
  EXPECT_EQ(t[0].digitsAt, 1u);
  EXPECT_DOUBLE_EQ(t[2].num, 1.5e-3);
  EXPECT_FALSE(t[2].isInt);
  EXPECT_DOUBLE_EQ(t[5].num, 31);
  EXPECT_DOUBLE_EQ(t[8].num, 5);
  EXPECT_DOUBLE_EQ(t[11].num, 0.25);
  EXPECT_EQ(t[12].kind, Tok::End);
}

TEST(SinLexer, NamesKeepTheirDigits) {
  auto t = lex("x10.5 G01 rVar1 $AA_IW[X]");
  EXPECT_EQ(t[0].text, "X10");
  EXPECT_TRUE(t[0].fraction);
  EXPECT_DOUBLE_EQ(t[0].num, 10.5);
  EXPECT_EQ(t[1].text, "G01");
  EXPECT_DOUBLE_EQ(t[1].num, 1);
  EXPECT_EQ(t[2].text, "RVAR1");
  EXPECT_EQ(t[2].digitsAt, 4u);
  EXPECT_EQ(t[3].text, "$AA_IW");
}

TEST(SinLexer, Errors) {
  std::vector<Token> t;
  std::string err;
  uint32_t col = 0;
  EXPECT_FALSE(lexLine("MSG(\"open", t, err, col));
  EXPECT_EQ(col, 5u);
  EXPECT_FALSE(lexLine("R1='H12", t, err, col));
  EXPECT_FALSE(lexLine("R1='B102'", t, err, col));
  EXPECT_NE(err.find("binary"), std::string::npos);
  EXPECT_FALSE(lexLine("R1=2 # 3", t, err, col));
}

TEST(SinCodes, GroupsAndInitialSettings) {
  size_t n = 0;
  const GCode *t = gcodeTable(n);
  std::map<int, int> defaults;
  std::set<int> groups;
  for (size_t i = 0; i < n; ++i) {
    groups.insert(t[i].group);
    if (t[i].isDefault) ++defaults[t[i].group];
  }
  EXPECT_EQ(groups.size(), 60u);
  // The table marks G71 and G710 (group 13) both as the initial setting: both are metric.
  for (auto &[g, c] : defaults) EXPECT_LE(c, g == 13 ? 2 : 1) << "group " << g;
  EXPECT_EQ(findGCode("G1").act, GAct::Mode);
  EXPECT_EQ(findGCode("G17").act, GAct::Mode);
  EXPECT_EQ(findGCode("G450").act, GAct::Default);
  EXPECT_EQ(findGCode("G33").act, GAct::Mode);
  EXPECT_EQ(findGCode("G335").act, GAct::Unsupported);
  EXPECT_EQ(findGCode("NOSUCH").code, nullptr);
}

TEST(SinLower, PrecedenceAndTolerance) {
  Parsed p("R1 = 1 < 2 AND 0\nR2 = 2 + 3 * 4 << \"x\"\nM30\n");
  ASSERT_TRUE(p.ok) << p.firstError();
  EXPECT_NE(p.text.find("value=(TOLLT 1 (and 2 0) 1e-12)"), std::string::npos) << p.text;
  EXPECT_NE(p.text.find("value=(concat (add 2 (mul 3 4)) \"x\")"), std::string::npos) << p.text;
}

TEST(SinLower, ControlStructures) {
  Parsed p("DEF INT II\nFOR II = 1 TO 3\nIF II == 2\nMSG(\"two\")\nENDIF\nENDFOR\nM30\n");
  ASSERT_TRUE(p.ok) << p.firstError();
  EXPECT_NE(p.text.find("while cond=(le %II 3)"), std::string::npos) << p.text;
  EXPECT_NE(p.text.find("assign target=%II value=(add %II 1)"), std::string::npos) << p.text;
  Parsed bad("WHILE R1 < 2\nENDIF\n");
  EXPECT_FALSE(bad.ok);
  EXPECT_EQ(bad.firstError(), "ENDIF closes WHILE opened at line 1");
}

TEST(SinLower, FramesAndMotion) {
  Parsed p("G17 G0 X10 Y=AC(5)\nAROT RPL=30\nG2 X0 Y0 CR=5\nM30\n");
  ASSERT_TRUE(p.ok) << p.firstError();
  EXPECT_NE(p.text.find("move X=10 Y=5 ac=Y"), std::string::npos) << p.text;
  EXPECT_NE(p.text.find("assign target=$_pframe value=(FRAME_CHAIN $_pframe (CROT \"Z\" 30))"), std::string::npos)
      << p.text;
  EXPECT_NE(p.text.find("move X=0 Y=0 R=5"), std::string::npos) << p.text;
}

// Mutated programs: every outcome is a diagnostic or a module the verifier accepts.
TEST(SinFuzz, MutatedProgramsNeverCrash) {
  const std::string seed =
      "DEF INT AA[3]=SET(1,2,3), NN\nDEF STRING[10] SS=\"ab\"\nN10 G17 G90 G0 X0 Y0 Z5\n"
      "FOR NN=0 TO 2\nIF AA[NN] > 1 GOTOF LAB\nENDFOR\nLAB: R1=R1+1 MSG(SS << R1)\n"
      "CASE (NN) OF 1 GOTOB LAB DEFAULT GOTOF ENDE\nREPEAT\nR2=R2+1\nUNTIL R2>=2\n"
      "TRANS X10\nG2 X10 Y0 I5 J0 F100\nENDE: M30\n";
  const char alphabet[] = "NXYZGRIJKFMT0123456789.=+-*/()[],:;\"'<>$_ \nABCDEFHLOPSUVW";
  std::mt19937 rng(42);
  for (int i = 0; i < 1500; ++i) {
    std::string s = seed;
    int edits = 1 + (int)(rng() % 6);
    for (int e = 0; e < edits; ++e) {
      size_t at = rng() % (s.size() + 1);
      switch (rng() % 3) {
      case 0: s.insert(s.begin() + (long)at, alphabet[rng() % (sizeof alphabet - 1)]); break;
      case 1:
        if (at < s.size()) s.erase(at, 1 + rng() % 4);
        break;
      default:
        if (at < s.size()) s[at] = alphabet[rng() % (sizeof alphabet - 1)];
      }
    }
    Parsed p(s);
    // Accepted programs go on to the verifier (a missing jump target is its error): either
    // way every error is located in the program.
    if (p.ok) ir::verifyModule(p.module, p.diags);
    for (auto &d : p.diags.collected()) EXPECT_GT(d.loc.line, 0u) << d.message << "\n" << s;
    if (!p.ok) EXPECT_TRUE(p.diags.hasErrors()) << s;
  }
}
