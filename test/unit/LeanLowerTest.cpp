// The lean path of the ISO stream (BlockLowerer::lowerLean) against the ops path: the same
// program streamed with and without a lean sink must give the same machine commands in the
// same order (the ops through buildCmdTemplate), the same diagnostics, and the plain blocks
// must really take the lean path.
#include "frontend/iso/IsoFrontend.h"
#include "passes/CmdTemplate.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace ncc;
using namespace ncc::iso;

namespace {

class Recorder : public CmdSink {
public:
  std::vector<MachineCmd> cmds;
  size_t direct = 0;  // commands that came from the lean path
  bool exec(const MachineCmd &c) override {
    cmds.push_back(c);
    ++direct;
    return true;
  }
};

struct Streamed {
  std::vector<MachineCmd> cmds;
  size_t direct = 0;
  uint64_t reuses = 0;  // blocks that took a decision cached for their shape
  std::vector<std::string> diags;
};

Streamed stream(const std::string &src, const char *name, bool lean, IsoOptions opts = {}) {
  SourceManager sm;
  Diagnostics diags(sm);
  diags.setCollect(true);
  uint32_t f = sm.addBuffer(name, src);
  IsoBlockStream s(sm, f, opts, diags);
  Recorder rec;
  ir::Region r;
  CmdTemplate t;
  auto drain = [&] {
    for (const ir::Op &op : r) {
      if (!isMachineOp(op.kind)) continue;  // #1=2: the ops path both times
      EXPECT_TRUE(buildCmdTemplate(op, t, diags));
      rec.cmds.push_back(t.base);  // X#1: its slot unevaluated, the ops path both times
    }
    r.clear();
  };
  for (int calls = 0; calls < 10000; ++calls) {
    bool more = s.next(r, 3, lean ? &rec : nullptr);  // small chunks: held blocks at the seams
    drain();
    if (!more) break;
  }
  Streamed out;
  out.cmds = std::move(rec.cmds);
  out.direct = rec.direct;
  out.reuses = s.leanReuses();
  for (auto &d : diags.collected())
    out.diags.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + " " + d.message + " [" + d.rule + "]");
  return out;
}

void expectSameCmd(const MachineCmd &a, const MachineCmd &b, size_t i) {
  SCOPED_TRACE("command " + std::to_string(i));
  EXPECT_EQ((int)a.kind, (int)b.kind);
  EXPECT_EQ(a.sub, b.sub);
  EXPECT_EQ(a.sub2, b.sub2);
  ASSERT_EQ(a.nmodes, b.nmodes);
  for (int k = 0; k < a.nmodes; ++k) EXPECT_EQ((int)a.modes[k], (int)b.modes[k]);
  EXPECT_EQ(a.mask, b.mask);
  EXPECT_EQ(a.blockNumber, b.blockNumber);
  EXPECT_EQ(a.loc.file, b.loc.file);
  EXPECT_EQ(a.loc.line, b.loc.line);
  EXPECT_EQ(a.loc.col, b.loc.col);
  EXPECT_EQ(a.text == nullptr, b.text == nullptr);
  for (int k = 0; k < kWords; ++k) EXPECT_EQ(a.w[k], b.w[k]) << "word " << kWordKeys[k];
}

// Returns how many commands took the lean path.
size_t expectSame(const std::string &src, const char *name, IsoOptions opts = {}) {
  Streamed ops = stream(src, name, false, opts), lean = stream(src, name, true, opts);
  EXPECT_EQ(ops.direct, 0u);
  EXPECT_EQ(ops.diags, lean.diags);
  // A program with errors never runs (the driver stops after the stream's call): its commands
  // need not agree.
  for (const std::string &d : ops.diags)
    if (d.find("[unused-word]") != std::string::npos || d.find("[modal-group-conflict]") != std::string::npos ||
        d.find("[unknown-code]") != std::string::npos)
      return lean.direct;
  EXPECT_EQ(ops.cmds.size(), lean.cmds.size());
  for (size_t i = 0; i < ops.cmds.size() && i < lean.cmds.size(); ++i) expectSameCmd(ops.cmds[i], lean.cmds[i], i);
  return lean.direct;
}

const char *const kMill =
    "%\n"
    "O0001\n"
    "G21 G90 G17 G94\n"
    "N5 G0 X0 Y0 Z1\n"
    "F1500\n"
    "G1 X1.866 Y-0.237 Z-0.993\n"
    "X3.5 Y1.52\n"
    "G2 X5.246 Y-0.079 I2.912 J0\n"
    "G3 X1 Y1 R2.5\n"
    "I1 J1\n"                     // an arc from I J alone
    "G91 G1 X1 A90\n"
    "G90 G18 G2 X1 Z1 I0.5 K0.5\n"
    "G17 G20 X1 Y1\n"
    "G21 G61 G0 Z5\n"
    "G64 X2\n"
    "G1 X1 (a comment)\n"          // comments, parameters, M and S codes: the ops path
    "#1=2\n"
    "G1 X#1\n"
    "M3 S1000\n"
    "G54 X4\n"
    "G93 G1 X2 F10\n"
    "G94 F0\n"                     // a warning on Fanuc, the same way
    "G81 X1 Y1 Z-1 R1\n"
    "X2\n"                         // a cycle's position: the ops path
    "G80 G0 X0\n"
    "M30\n"
    "%\n";

TEST(LeanLower, ErrorsReportedTheSame) {
  // Two codes of one group, an unused word (the ops path reports it), an unknown code.
  const char *src = "G1 X1 F10\nG98 G99 X3\nG0 G1 X1\nG1 X1 P2\nG12.7 X1\nG1 X2\nG0 I1\n";
  for (const char *name : {"t.nc", "t.ngc"}) {
    Streamed lean = stream(src, name, true);
    EXPECT_EQ(lean.diags.size(), 5u);
    EXPECT_EQ(expectSame(src, name), 7u);  // lines 1 and 6
  }
}

// G codes are looked up once per number (the lowerer's cache): an unknown one is still reported
// every time, in both flavours, and G1. G01 G1.0 are G1 (each of these blocks is lean: Block, Mode, Move).
TEST(LeanLower, GCodeCacheKeepsErrorsAndSpellings) {
  const char *src = "G1 X1 F10\nG13 X1\nG13 X2\nG1. X3\nG01 X4\nG1.0 X5\nG0 X6\nG00 X7\n";
  for (const char *name : {"t.nc", "t.ngc"}) {
    SCOPED_TRACE(name);
    Streamed lean = stream(src, name, true);
    std::vector<std::string> want = {"2:1 unknown G code G13 [unknown-code]", "3:1 unknown G code G13 [unknown-code]"};
    EXPECT_EQ(lean.diags, want);
    EXPECT_EQ(expectSame(src, name), 4u + 5 * 3u);  // line 1: Block, Mode, Feed, Move
  }
}

// The lean classification (codes already looked up) leaves every conflict and duplicate to
// classify(): two codes of a group, a duplicate word, M codes, after the codes are in the cache.
TEST(LeanLower, LeanClassifyLeavesConflictsToClassify) {
  const char *src = "G0 X0\nG1 X1 F10\nG17 X2\nG18 G17 X1\nG1 G0 X2\nG1 X2 X3\nG1 X1 M3\nG0 X5 Y1\nG1 X4 Y1\n";
  for (const char *name : {"t.nc", "t.ngc"}) {
    SCOPED_TRACE(name);
    Streamed lean = stream(src, name, true);
    ASSERT_EQ(lean.diags.size(), 3u);
    EXPECT_NE(lean.diags[0].find("4:5 two G codes from the same modal group"), std::string::npos) << lean.diags[0];
    EXPECT_NE(lean.diags[1].find("5:4 two G codes from the same modal group"), std::string::npos) << lean.diags[1];
    EXPECT_NE(lean.diags[2].find("6:7 two X words in one block"), std::string::npos) << lean.diags[2];
    expectSame(src, name);
  }
}

TEST(LeanLower, MillFanucSameCommands) { EXPECT_GT(expectSame(kMill, "t.nc"), 30u); }

TEST(LeanLower, MillRs274SameCommands) { EXPECT_GT(expectSame(kMill, "t.ngc"), 30u); }

TEST(LeanLower, DecimalModesScaleAsTheOpsPath) {
  const char *src = "G21 G90\nG1 X1000 Y2.5 Z-300 A45 F1500\nG95 F20 X1\nG20 X1000 F100\nG2 X10 I5 J0\nM30\n";
  for (const char *mode : {"calculator", "is-b", "is-c"}) {
    SCOPED_TRACE(mode);
    IsoOptions opts;
    opts.decimalMode = mode;
    EXPECT_GT(expectSame(src, "t.nc", opts), 10u);
  }
}

// A move block's decision is reused for the next block of the same shape (letters and G codes in
// order) only while everything it read is unchanged: each program here changes one such thing
// between two blocks of one shape, and the commands and messages must stay the ops path's.
TEST(LeanLower, ShapeCacheFollowsUnits) {
  // IS-B: X2000 is 2 mm, or 0.2 inch after G20 (a cached divisor 1000 would give 2 inches).
  const char *src = "G21 G90 G1 X1000 F100\nX2000\nX3000\nG20\nX2000\nX3000\nG21\nX4000\nM30\n";
  IsoOptions opts;
  opts.decimalMode = "is-b";
  Streamed lean = stream(src, "t.nc", true, opts);
  EXPECT_GE(lean.reuses, 3u);  // X3000 twice, X4000
  expectSame(src, "t.nc", opts);
}

TEST(LeanLower, ShapeCacheFollowsMotionMode) {
  // I J are the arc's under G2, unused words under G1: the last block is an error, although its
  // shape took the lean path under G2.
  const char *src = "G2 X1 Y0 I0.5 J0 F100\nX2 Y0 I0.5 J0\nX3 Y0 I0.5 J0\nG1 X3\nX4 Y0 I0.5 J0\n";
  for (const char *name : {"t.nc", "t.ngc"}) {
    SCOPED_TRACE(name);
    Streamed lean = stream(src, name, true);
    ASSERT_EQ(lean.diags.size(), 2u);  // I and J
    for (const std::string &d : lean.diags) EXPECT_EQ(d.rfind("5:", 0), 0u) << d;
    EXPECT_GE(lean.reuses, 1u);
    expectSame(src, name);
  }
  // LinuxCNC's G80 leaves no motion mode (the last path motion is still G2): the arc's shape
  // after it is an error.
  const char *g80 = "G2 X1 Y0 I0.5 J0 F100\nX2 Y0 I0.5 J0\nX3 Y0 I0.5 J0\nG80\nX4 Y0 I0.5 J0\n";
  Streamed lean = stream(g80, "t.ngc", true);
  ASSERT_EQ(lean.diags.size(), 2u);
  for (const std::string &d : lean.diags) EXPECT_EQ(d.rfind("5:", 0), 0u) << d;
  EXPECT_EQ(lean.reuses, 1u);
  expectSame(g80, "t.ngc");
}

TEST(LeanLower, ShapeCacheKeepsWordOrderAndSpelling) {
  // The motion code's place (the Mode command's column) is the shape's, the code is the key's:
  // G0 X5 has G1 X3's letters and state but not its code. G01 and G1.0 are G1; more than 8
  // words have no shape. Reused: X4 G1, G1 X7 (G1 X3's, beside G0 X5's), G1.0 X8, G1.0 X9, X3.
  const char *src = "G1 X1 F100\nX2 G1\nG1 X3\nX4 G1\nG0 X5\nG01 X6\nG1 X7\nG1.0 X8\nG1.0 X9\n"
                    "G0 X1 Y2 Z3 A4 B5 C6 U7 V8 W9\nG0 X1 Y2 Z3 A4 B5 C6 U7 V8 W9\nG17 X1\nX2\nG18 X1\nX2\n"
                    "G91 X1\nX2\nX3\nM30\n";
  Streamed lean = stream(src, "t.ngc", true);
  EXPECT_EQ(lean.reuses, 5u);
  EXPECT_GT(expectSame(src, "t.ngc"), 40u);
}

TEST(LeanLower, LatheTakesTheOpsPath) {
  IsoOptions opts;
  opts.lathe = true;
  EXPECT_EQ(expectSame("G18 G90\nG0 X10 Z1\nG1 U-2 W-1 F0.2\nM30\n", "t.nc", opts), 0u);
}

}  // namespace
