// The eval engine and the program-level passes, on modules written in NC IR text.
#include "ir/NCIR.h"
#include "ir/Value.h"
#include "passes/Eval.h"
#include "passes/Pass.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ncc;

namespace {

struct Recorder : CmdSink {
  std::vector<MachineCmd> cmds;
  std::vector<std::string> texts;
  bool exec(const MachineCmd &c) override {
    cmds.push_back(c);
    texts.push_back(c.text ? c.text : "");
    return true;
  }
  std::vector<MachineCmd> moves() const {
    std::vector<MachineCmd> out;
    for (auto &c : cmds)
      if (c.kind == CmdKind::Move) out.push_back(c);
    return out;
  }
};

struct Fixture {
  SourceManager sm;
  Diagnostics diags{sm};
  ir::Module m;
  Recorder rec;
  Fixture() { diags.setCollect(true); }
  bool parse(const std::string &body) {
    std::string text = "module \"t.ncir\" dialect=iso\nsource 1 \"t.ncir\"\n" + body;
    uint32_t f = sm.addBuffer("t.ncir", text);
    return ir::parseModule(text, f, sm, diags, m) && ir::verifyModule(m, diags);
  }
  bool run(ExecLimits limits = {}) {
    Evaluator ev(rec, diags, limits);
    return ev.run(m);
  }
  std::string firstError() const {
    for (auto &d : diags.collected())
      if (d.severity == Severity::Error) return d.message;
    return "";
  }
};

}  // namespace

TEST(Eval, WhileLoopWithTrigonometry) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#1 value=0
  while cond=(lt #1 4) id=1 {
    move X=(mul 10.0 (COS (mul #1 90.0))) Y=(mul 10.0 (SIN (mul #1 90.0)))
    assign target=#1 value=(add #1 1)
  }
}
)")) << f.firstError();
  ASSERT_TRUE(f.run()) << f.firstError();
  auto mv = f.rec.moves();
  ASSERT_EQ(mv.size(), 4u);
  EXPECT_NEAR(mv[1].get(Word::X), 0.0, 1e-12);
  EXPECT_NEAR(mv[1].get(Word::Y), 10.0, 1e-12);
  EXPECT_NEAR(mv[2].get(Word::X), -10.0, 1e-12);
}

TEST(Eval, VacantSemantics) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#2 value=(add #1 5)
  if cond=(eq #1 vacant) {
    assign target=#3 value=1
  }
  if cond=(eq #1 0) {
    assign target=#4 value=1
  }
  move X=#2 Y=#1 Z=#3 A=#4
}
)"));
  ASSERT_TRUE(f.run()) << f.firstError();
  auto mv = f.rec.moves();
  ASSERT_EQ(mv.size(), 1u);
  EXPECT_EQ(mv[0].get(Word::X), 5.0);   // vacant counts as 0 in arithmetic
  EXPECT_FALSE(mv[0].has(Word::Y));     // a vacant word is not programmed
  EXPECT_EQ(mv[0].get(Word::Z), 1.0);   // vacant EQ vacant
  EXPECT_FALSE(mv[0].has(Word::A));     // vacant EQ 0 is false: #4 stays vacant
}

TEST(Eval, GotoOutOfLoopAndSequenceSearch) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#1 value=0
  while cond=true id=1 {
    assign target=#1 value=(add #1 1)
    if cond=(ge #1 3) {
      goto n=50
    }
  }
  move X=99.0
  block n=50
  move X=#1
}
)"));
  ASSERT_TRUE(f.run()) << f.firstError();
  auto mv = f.rec.moves();
  ASSERT_EQ(mv.size(), 1u);
  EXPECT_EQ(mv[0].get(Word::X), 3.0);
}

TEST(Eval, CallWithNewFrameKeepsCallerLocals) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#1 value=7
  call callee="O9001" count=2 frame=new a.1=2.5 a.24=(add #1 1)
  move X=#1 Y=#100
}
func @O9001 {
  move X=#24 Y=#1
  assign target=#100 value=(add #100 1)
  assign target=#1 value=123
}
)"));
  ASSERT_TRUE(f.run()) << f.firstError();
  auto mv = f.rec.moves();
  ASSERT_EQ(mv.size(), 3u);
  EXPECT_EQ(mv[0].get(Word::X), 8.0);
  EXPECT_EQ(mv[0].get(Word::Y), 2.5);
  EXPECT_EQ(mv[2].get(Word::X), 7.0);  // the callee's #1 is its own
  EXPECT_EQ(mv[2].get(Word::Y), 2.0);  // commons are shared; vacant + 1 twice
}

TEST(Eval, SharedFrameCallSeesCallerLocals) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#1 value=1
  call callee="O1" frame=shared
  move X=#1
}
func @O1 {
  assign target=#1 value=(add #1 1)
}
)"));
  ASSERT_TRUE(f.run()) << f.firstError();
  EXPECT_EQ(f.rec.moves()[0].get(Word::X), 2.0);
}

TEST(Eval, EndlessLoopStopsAtLimit) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  while cond=true id=1 loc(1:3:1) {
    assign target=#1 value=(add #1 1)
  }
}
)"));
  ExecLimits lim;
  lim.maxLoopIterations = 1000;
  EXPECT_FALSE(f.run(lim));
  EXPECT_NE(f.firstError().find("loop did not terminate after 1000 iterations"), std::string::npos);
  EXPECT_EQ(f.diags.collected()[0].loc.line, 3u);
}

TEST(Eval, BackwardGotoLoopStopsAtLimit) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  block n=10
  goto n=10
}
)"));
  ExecLimits lim;
  lim.maxLoopIterations = 500;
  EXPECT_FALSE(f.run(lim));
  EXPECT_NE(f.firstError().find("backward jump"), std::string::npos);
}

TEST(Eval, RecursionStopsAtCallDepth) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  call callee="O1" frame=new
}
func @O1 {
  call callee="O1" frame=new
}
)"));
  EXPECT_FALSE(f.run());
  EXPECT_NE(f.firstError().find("call depth limit 64 exceeded"), std::string::npos);
}

TEST(Eval, DivisionByZeroIsAnError) {
  Fixture f;
  ASSERT_TRUE(f.parse("func @main {\n  assign target=#1 value=(div 1.0 #2) loc(1:3:7)\n}\n"));
  EXPECT_FALSE(f.run());
  EXPECT_EQ(f.firstError(), "division by zero");
}

TEST(Eval, ProgramEndStopsExecution) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  move X=1.0
  stop kind=end_rewind
  move X=2.0
}
)"));
  ASSERT_TRUE(f.run());
  EXPECT_EQ(f.rec.moves().size(), 1u);
}

TEST(Eval, RepeatLoopRunsCountTimes) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  loop count=3 {
    move X=1.0
  }
}
)"));
  ASSERT_TRUE(f.run());
  EXPECT_EQ(f.rec.moves().size(), 3u);
}

TEST(Passes, FoldComputesConstants) {
  Fixture f;
  ASSERT_TRUE(f.parse("func @main {\n  move X=(add 1.0 (mul 2.0 3.0)) Y=(SQRT 16.0) Z=(div 1.0 0.0)\n}\n"));
  PassContext ctx;
  ASSERT_TRUE(runPasses(f.m, {"fold"}, f.diags, ctx));
  std::string text = ir::printModule(f.m);
  EXPECT_NE(text.find("move X=7.0 Y=4.0 Z=(div 1.0 0.0)"), std::string::npos) << text;
}

TEST(Passes, EvalFlattensLoops) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#1 value=0
  while cond=(lt #1 2) id=1 {
    move X=#1
    assign target=#1 value=(add #1 1)
  }
}
)"));
  PassContext ctx;
  ASSERT_TRUE(runPasses(f.m, {"eval"}, f.diags, ctx)) << f.firstError();
  std::string text = ir::printModule(f.m);
  EXPECT_NE(text.find("move X=0.0\n  move X=1.0\n}"), std::string::npos) << text;
  EXPECT_EQ(text.find("while"), std::string::npos);
}

TEST(Passes, LintFindsUnreachableAndCodeAfterEnd) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  block n=1 loc(1:3:1)
  goto n=3 loc(1:3:4)
  block n=2 loc(1:4:1)
  move X=1.0
  block n=3 loc(1:5:1)
  stop kind=end loc(1:5:4)
  block n=4 loc(1:6:1)
  move X=2.0
}
)"));
  PassContext ctx;
  ASSERT_TRUE(runPasses(f.m, {"lint"}, f.diags, ctx));
  auto &d = f.diags.collected();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].rule, "unreachable-block");
  EXPECT_EQ(d[0].loc.line, 4u);
  EXPECT_EQ(d[1].rule, "code-after-end");
  EXPECT_EQ(d[1].loc.line, 6u);
}

TEST(Passes, SemaRejectsUnknownFunctionAndCallee) {
  Fixture f;
  std::string text = "module \"t.ncir\" dialect=iso\nfunc @main {\n  call callee=\"O77\"\n}\n";
  uint32_t id = f.sm.addBuffer("t.ncir", text);
  ASSERT_TRUE(ir::parseModule(text, id, f.sm, f.diags, f.m));
  PassContext ctx;
  EXPECT_FALSE(runPasses(f.m, {"sema"}, f.diags, ctx));
  EXPECT_NE(f.firstError().find("unknown program 'O77'"), std::string::npos);
}

TEST(Eval, LocalsEndAtThirtyThree) {
  Fixture f;
  ASSERT_TRUE(f.parse(R"(func @main {
  assign target=#33 value=1
  assign target=#34 value=1
  call callee="O1" frame=new
  move X=#33 Y=#34
}
func @O1 {
  assign target=#33 value=5
  assign target=#34 value=5
}
)"));
  ASSERT_TRUE(f.run()) << f.firstError();
  EXPECT_EQ(f.rec.moves()[0].get(Word::X), 1.0);  // #33: the callee had its own
  EXPECT_EQ(f.rec.moves()[0].get(Word::Y), 5.0);  // #34: shared
}
