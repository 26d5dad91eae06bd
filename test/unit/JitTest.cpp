// JIT backend: builds NC IR by hand, runs it through ORC LLJIT and checks the MachineCmd
// stream the compiled code hands to the runtime.
#include "backends/jit/Jit.h"
#include "ir/Arith.h"
#include "ir/Builtins.h"
#include "ir/Value.h"
#include "passes/Eval.h"
#include "runtime/ncrt.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace ncc;
using namespace ncc::ir;

namespace {

struct Recorder : CmdSink {
  std::vector<MachineCmd> cmds;
  std::vector<std::string> texts;
  bool exec(const MachineCmd &c) override {
    cmds.push_back(c);
    texts.push_back(c.text ? c.text : "");
    cmds.back().text = nullptr;  // JIT memory is gone after the run
    return true;
  }
  std::vector<MachineCmd> of(CmdKind k) const {
    std::vector<MachineCmd> out;
    for (auto &c : cmds)
      if (c.kind == k) out.push_back(c);
    return out;
  }
};

SourceLoc L(uint32_t line, uint32_t col = 1) { return {1, line, col}; }
ExprPtr N(double v) { return Expr::number(v, Type::Real); }
ExprPtr Sym(const char *s) { return Expr::symbol(s); }
ExprPtr Var(int n, SourceLoc loc = L(1)) { return Expr::var(VarSpace::Numbered, "", N(n), loc); }
ExprPtr VarAt(ExprPtr idx) { return Expr::var(VarSpace::Numbered, "", std::move(idx), L(1)); }
ExprPtr Named(const char *n, VarSpace s = VarSpace::Local) { return Expr::var(s, n, nullptr, L(7, 3)); }
ExprPtr Bin(OpCode op, ExprPtr a, ExprPtr b, SourceLoc loc = L(1)) {
  return Expr::binary(op, std::move(a), std::move(b), loc);
}
ExprPtr Fn(const char *name, ExprPtr a) {
  std::vector<ExprPtr> args;
  args.push_back(std::move(a));
  return Expr::call(name, std::move(args), L(1));
}

void addArgs(Op &) {}
template <class... R> void addArgs(Op &o, const char *k, ExprPtr v, R &&...r) {
  o.set(k, std::move(v));
  addArgs(o, std::forward<R>(r)...);
}
template <class... R> Op mk(OpKind k, SourceLoc loc, R &&...r) {
  Op o(k, loc);
  addArgs(o, std::forward<R>(r)...);
  return o;
}
template <class... O> Region reg(O &&...ops) {
  Region r;
  (r.push_back(std::move(ops)), ...);
  return r;
}
Op withBody(Op o, Region body) {
  o.regions.push_back(std::move(body));
  return o;
}
Op assign(int n, ExprPtr v) { return mk(OpKind::Assign, L(2), "target", Var(n), "value", std::move(v)); }
Op block(int n) { return mk(OpKind::Block, L(n), "n", N(n)); }

Module module(Region mainBody) {
  Module m;
  m.name = "t.nc";
  Function f;
  f.name = "main";
  f.body = std::move(mainBody);
  m.functions.push_back(std::move(f));
  return m;
}
void addFunction(Module &m, const char *name, Region body) {
  Function f;
  f.name = name;
  f.body = std::move(body);
  m.functions.push_back(std::move(f));
}

struct Run {
  SourceManager sm;
  Diagnostics diags{sm};
  Recorder rec;
  bool ok = false;
  Run() {
    sm.addBuffer("t.nc", std::string(40, '\n'));
    diags.setCollect(true);
  }
  std::string errors() const {
    std::string s;
    for (auto &d : diags.collected()) s += d.message + "\n";
    return s;
  }
};

// Bitwise equality of what the executor reads from a command.
std::string diffCmd(const MachineCmd &a, const std::string &ta, const MachineCmd &b, const std::string &tb) {
  if (a.kind != b.kind || a.sub != b.sub || a.sub2 != b.sub2 || a.nmodes != b.nmodes || a.mask != b.mask ||
      a.blockNumber != b.blockNumber || a.loc.file != b.loc.file || a.loc.line != b.loc.line ||
      a.loc.col != b.loc.col || ta != tb)
    return "header differs";
  if (std::memcmp(a.modes, b.modes, a.nmodes)) return "modes differ";
  for (int w = 0; w < kWords; ++w)
    if ((a.mask & wordBit((Word)w)) && std::memcmp(&a.w[w], &b.w[w], sizeof(double)))
      return std::string("word ") + kWordKeys[w] + " differs";
  return "";
}

// Runs the module with the JIT and with the eval engine: both must give the same command
// stream, the same result and the same diagnostics.
std::unique_ptr<Run> run(const Module &m, jit::JitOptions opts = {}) {
  auto r = std::make_unique<Run>();
  r->ok = jit::runModule(m, r->rec, r->diags, opts);
  Run ref;
  Evaluator ev(ref.rec, ref.diags, opts.limits);
  ref.ok = ev.run(m);
  EXPECT_EQ(r->ok, ref.ok) << "eval: " << ref.errors() << "jit: " << r->errors();
  EXPECT_EQ(r->errors(), ref.errors());
  for (size_t i = 0; i < r->diags.collected().size() && i < ref.diags.collected().size(); ++i)
    EXPECT_EQ(r->diags.collected()[i].loc.line, ref.diags.collected()[i].loc.line) << i;
  EXPECT_EQ(r->rec.cmds.size(), ref.rec.cmds.size()) << "jit: " << r->errors() << "eval: " << ref.errors() << (r->rec.cmds.empty() ? -1 : (int)r->rec.cmds[0].kind);
  for (size_t i = 0; i < r->rec.cmds.size() && i < ref.rec.cmds.size(); ++i) {
    std::string d = diffCmd(r->rec.cmds[i], r->rec.texts[i], ref.rec.cmds[i], ref.rec.texts[i]);
    EXPECT_EQ(d, "") << "command " << i;
    if (!d.empty()) break;
  }
  return r;
}

double builtin(const char *name, double a) {
  double args[1] = {a};
  return findBuiltin(name)->fn(args);
}

}  // namespace

TEST(Jit, StraightLineCommands) {
  Module m = module(reg(block(10), mk(OpKind::Mode, L(10), "motion", Sym("linear"), "plane", Sym("xy")),
                        mk(OpKind::Feed, L(10), "value", N(100)),
                        mk(OpKind::Move, L(11), "X", N(1), "Y", N(2.5), "Z", Expr::vacant()),
                        mk(OpKind::Comment, L(12), "text", Expr::string("hello")),
                        mk(OpKind::Spindle, L(13), "dir", Sym("ccw")),
                        mk(OpKind::Coolant, L(13), "mist", Sym("on")),
                        mk(OpKind::Stop, L(14), "kind", Sym("end")),
                        mk(OpKind::Move, L(15), "X", N(99))));
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  auto &c = r->rec.cmds;
  ASSERT_EQ(c.size(), 8u);  // the move after the program end is not executed
  EXPECT_EQ(c[0].kind, CmdKind::Block);
  EXPECT_EQ(c[0].blockNumber, 10);
  EXPECT_EQ(c[1].kind, CmdKind::Mode);
  ASSERT_EQ(c[1].nmodes, 2);
  EXPECT_EQ(c[1].modes[0], ModeValue::Linear);
  EXPECT_EQ(c[1].modes[1], ModeValue::XY);
  EXPECT_EQ(c[2].get(Word::F), 100);
  EXPECT_EQ(c[3].mask, wordBit(Word::X) | wordBit(Word::Y));  // vacant Z is left out
  EXPECT_EQ(c[3].get(Word::Y), 2.5);
  EXPECT_EQ(c[3].loc.line, 11u);
  EXPECT_EQ(r->rec.texts[4], "hello");
  EXPECT_EQ(c[5].sub, 2);
  EXPECT_EQ(c[6].sub, 2);   // mist on
  EXPECT_EQ(c[6].sub2, 2);  // mist given
  EXPECT_EQ(c[7].sub, (uint8_t)StopKind::End);
}

// The benchmark's shape: WHILE with SIN/COS into a G1, compared with the builtin functions.
TEST(Jit, LoopWithTrigMatchesBuiltins) {
  Region body = reg(assign(3, Bin(OpCode::Mul, Var(2), N(0.36))),
                    assign(4, Bin(OpCode::Add, N(10), Bin(OpCode::Mul, Fn("FIX", Bin(OpCode::Div, Var(2), N(100))), N(0.01)))),
                    mk(OpKind::Move, L(5), "X", Bin(OpCode::Mul, Var(4), Fn("COS", Var(3))), "Y",
                       Bin(OpCode::Mul, Var(4), Fn("SIN", Var(3)))),
                    assign(2, Bin(OpCode::Add, Var(2), N(1))));
  Module m = module(reg(assign(1, N(300)), assign(2, N(0)),
                        withBody(mk(OpKind::While, L(3), "cond", Bin(OpCode::Lt, Var(2), Var(1))), std::move(body))));
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  auto moves = r->rec.of(CmdKind::Move);
  ASSERT_EQ(moves.size(), 300u);
  for (int i = 0; i < 300; i += 37) {
    double a = i * 0.36, rad = 10 + builtin("FIX", i / 100.0) * 0.01;
    EXPECT_EQ(moves[i].get(Word::X), rad * builtin("COS", a));
    EXPECT_EQ(moves[i].get(Word::Y), rad * builtin("SIN", a));
  }
}

TEST(Jit, GotoOutOfWhile) {
  Region body = reg(assign(1, Bin(OpCode::Add, Var(1), N(1))),
                    withBody(mk(OpKind::If, L(4), "cond", Bin(OpCode::Eq, Var(1), N(3))),
                             reg(mk(OpKind::Goto, L(4), "n", N(100)))),
                    mk(OpKind::Move, L(5), "Y", Var(1)));
  Module m = module(reg(withBody(mk(OpKind::While, L(3), "cond", N(1)), std::move(body)), block(100),
                        mk(OpKind::Move, L(6), "X", Var(1))));
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  auto moves = r->rec.of(CmdKind::Move);
  ASSERT_EQ(moves.size(), 3u);
  EXPECT_EQ(moves[1].get(Word::Y), 2);
  EXPECT_EQ(moves[2].get(Word::X), 3);
  EXPECT_EQ(r->rec.of(CmdKind::Block).at(0).blockNumber, 100);
}

// Backward goto loop (IF [#1 LT 3] GOTO 5) and a computed goto.
TEST(Jit, BackwardAndComputedGoto) {
  Module m = module(reg(assign(1, N(0)), block(5), assign(1, Bin(OpCode::Add, Var(1), N(1))),
                        mk(OpKind::Move, L(6), "X", Var(1)),
                        withBody(mk(OpKind::If, L(7), "cond", Bin(OpCode::Lt, Var(1), N(3))),
                                 reg(mk(OpKind::Goto, L(7), "n", N(5)))),
                        mk(OpKind::Goto, L(8), "n", N(30)), block(20),
                        mk(OpKind::Move, L(9), "Y", N(20)), block(30), mk(OpKind::Move, L(10), "Y", N(30))));
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  auto moves = r->rec.of(CmdKind::Move);
  ASSERT_EQ(moves.size(), 4u);
  EXPECT_EQ(moves[2].get(Word::X), 3);
  EXPECT_EQ(moves[3].get(Word::Y), 30);  // GOTO 30 skipped N20

  // A computed goto resolves when it runs: #1 is vacant, so it looks for N0 (ir/Jumps.h).
  Module bad = module(reg(mk(OpKind::Move, L(1), "X", N(1)), block(10),
                          mk(OpKind::Goto, L(8), "n", Bin(OpCode::Mul, Var(1), N(10)))));
  auto rb = run(bad);
  EXPECT_FALSE(rb->ok);
  EXPECT_EQ(rb->rec.of(CmdKind::Move).size(), 1u);
  EXPECT_EQ(rb->errors(), "jump to missing sequence number N0\n");
}

// G65 P9010 L2 A7 B#1: a new frame per call, args in #1/#2, the caller's #1 untouched.
TEST(Jit, CallWithNewFrame) {
  Module m = module(reg(assign(1, N(5)),
                        mk(OpKind::Call, L(3), "callee", Expr::string("O9010"), "count", N(2), "frame", Sym("new"),
                           "a.1", N(7), "a.2", Var(1)),
                        mk(OpKind::Move, L(4), "X", Var(1)), assign(3, N(1)),
                        mk(OpKind::Call, L(5), "callee", Expr::string("O9011"), "frame", Sym("shared")),
                        mk(OpKind::Move, L(6), "Z", Var(3))));
  addFunction(m, "O9010", reg(mk(OpKind::Move, L(20), "X", Var(1), "Y", Var(2), "Z", Var(3)),
                              assign(3, N(42)), mk(OpKind::Return, L(21))));
  addFunction(m, "O9011", reg(assign(3, Bin(OpCode::Add, Var(3), N(1)))));
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  auto moves = r->rec.of(CmdKind::Move);
  ASSERT_EQ(moves.size(), 4u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(moves[i].get(Word::X), 7);
    EXPECT_EQ(moves[i].get(Word::Y), 5);
    EXPECT_FALSE(moves[i].has(Word::Z));  // #3 is vacant in every fresh frame
  }
  EXPECT_EQ(moves[2].get(Word::X), 5);
  EXPECT_EQ(moves[3].get(Word::Z), 2);  // shared frame: the subprogram changed the caller's #3
}

TEST(Jit, VacantSemantics) {
  auto flag = [](OpCode op, ExprPtr a, ExprPtr b, Word w) {
    return mk(OpKind::Move, L(9), kWordKeys[(unsigned)w],
              Bin(op, std::move(a), std::move(b)));
  };
  Module m = module(reg(assign(2, Bin(OpCode::Add, Var(1), N(1))), assign(500, Expr::vacant()),
                        mk(OpKind::Move, L(3), "X", Var(2), "Y", Var(500), "Z", Expr::unary(OpCode::Neg, Var(1))),
                        flag(OpCode::Eq, Var(1), Expr::vacant(), Word::X),  // vacant EQ vacant: 1
                        flag(OpCode::Eq, Var(1), N(0), Word::X),            // vacant EQ 0: 0
                        flag(OpCode::Ne, Var(1), N(0), Word::X),            // 1
                        flag(OpCode::Lt, Var(1), N(1), Word::X),            // vacant counts as 0: 1
                        flag(OpCode::And, Var(1), N(1), Word::X),           // vacant is false: 0
                        flag(OpCode::Mod, N(-7), N(3), Word::X),            // sign of the divisor: 2
                        flag(OpCode::Mod, N(7), N(-3), Word::X)));          // -2
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  auto moves = r->rec.of(CmdKind::Move);
  ASSERT_EQ(moves.size(), 8u);
  EXPECT_EQ(moves[0].mask, wordBit(Word::X) | wordBit(Word::Z));
  EXPECT_EQ(moves[0].get(Word::X), 1);
  EXPECT_EQ(moves[0].get(Word::Z), 0);
  double expect[] = {1, 0, 1, 1, 0, 2, -2};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(moves[i + 1].get(Word::X), expect[i]) << i;
}

TEST(Jit, NamedVariablesAndIndexedAccess) {
  Module m = module(reg(mk(OpKind::Assign, L(2), "target", Named("r"), "value", N(4)),
                        mk(OpKind::Assign, L(2), "target", Named("g", VarSpace::Global), "value", N(6)),
                        mk(OpKind::Assign, L(2), "target", VarAt(Bin(OpCode::Add, Named("r"), N(100.4))), "value",
                           N(9)),  // #[104.4] = #104
                        mk(OpKind::Move, L(3), "X", Var(104), "Y", Named("g", VarSpace::Global)),
                        mk(OpKind::Move, L(4), "X", Named("unset"))));
  auto r = run(m);
  EXPECT_FALSE(r->ok);
  auto moves = r->rec.of(CmdKind::Move);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_EQ(moves[0].get(Word::X), 9);
  EXPECT_EQ(moves[0].get(Word::Y), 6);
  ASSERT_EQ(r->diags.collected().size(), 1u);
  EXPECT_EQ(r->diags.collected()[0].message, "variable 'unset' used before assignment");
  EXPECT_EQ(r->diags.collected()[0].loc.line, 7u);
}

TEST(Jit, RuntimeErrors) {
  struct Case {
    Module m;
    const char *msg;
    uint32_t line;
  };
  std::vector<Case> cases;
  cases.push_back({module(reg(mk(OpKind::Move, L(3), "X", Bin(OpCode::Div, N(1), Var(1), L(3, 8))))),
                   "division by zero", 3});
  cases.push_back({module(reg(assign(1, N(-1)), mk(OpKind::Move, L(4), "X", VarAt(Var(1))))),
                   "parameter number #-1 out of range", 1});
  cases.push_back({module(reg(mk(OpKind::Assign, L(2), "target", Var(0), "value", N(1)))),
                   "#0 is always vacant and cannot be assigned", 1});
  cases.push_back({module(reg(mk(OpKind::Goto, L(5), "n", N(77)))), "jump to missing sequence number N77", 5});
  cases.push_back({module(reg(mk(OpKind::Move, L(6), "X", Fn("SQRT", N(-1))))), "'SQRT' argument out of domain", 1});
  cases.push_back({module(reg(mk(OpKind::Move, L(6), "X", Fn("NOPE", N(1))))), "unknown function 'NOPE'", 1});
  cases.push_back({module(reg(mk(OpKind::Assign, L(2), "target", Expr::var(VarSpace::RParam, "", N(1000), L(4)),
                                 "value", N(1)))),
                   "R parameter index 1000 out of range", 4});
  for (auto &c : cases) {
    auto r = run(c.m);
    EXPECT_FALSE(r->ok) << c.msg;
    ASSERT_EQ(r->diags.collected().size(), 1u) << c.msg;
    EXPECT_EQ(r->diags.collected()[0].message, c.msg);
    EXPECT_EQ(r->diags.collected()[0].loc.line, c.line) << c.msg;
  }
}

// Runaway programs stop with a diagnostic, not a hang.
TEST(Jit, LimitsProduceErrors) {
  jit::JitOptions opts;
  opts.limits.maxLoopIterations = 1000;
  {
    Module m = module(reg(withBody(mk(OpKind::While, L(3), "cond", N(1)), reg(mk(OpKind::Move, L(4), "X", N(1))))));
    auto r = run(m, opts);
    EXPECT_FALSE(r->ok);
    EXPECT_EQ(r->rec.cmds.size(), 1000u);
    EXPECT_EQ(r->errors(), "loop did not terminate after 1000 iterations (limit --max-loop-iterations)\n");
    EXPECT_EQ(r->diags.collected().at(0).loc.line, 3u);
  }
  {
    Module m = module(reg(block(1), mk(OpKind::Goto, L(2), "n", N(1))));
    auto r = run(m, opts);
    EXPECT_FALSE(r->ok);
    EXPECT_EQ(r->errors(), "backward jump repeated more than 1000 times (limit --max-loop-iterations)\n");
    EXPECT_EQ(r->diags.collected().at(0).loc.line, 2u);
  }
  {
    Module m = module(reg(mk(OpKind::Call, L(2), "callee", Expr::string("O1"))));
    addFunction(m, "O1", reg(mk(OpKind::Call, L(9), "callee", Expr::string("O1"))));
    auto r = run(m);
    EXPECT_FALSE(r->ok);
    EXPECT_EQ(r->errors(), "call depth limit 64 exceeded (limit --max-call-depth)\n");
    EXPECT_EQ(r->diags.collected().at(0).loc.line, 9u);
  }
  {
    opts.limits.maxLoopIterations = 1ull << 40;
    opts.limits.maxSeconds = 0.05;
    Module m = module(reg(withBody(mk(OpKind::Loop, L(3)), reg(assign(1, Bin(OpCode::Add, Var(1), N(1)))))));
    SourceManager sm;
    Diagnostics diags(sm);
    diags.setCollect(true);
    Recorder rec;
    EXPECT_FALSE(jit::runModule(m, rec, diags, opts));  // (timing differs from eval: not compared)
    ASSERT_EQ(diags.collected().size(), 1u);
    EXPECT_EQ(diags.collected()[0].message, "run time limit of 0.05 s exceeded (limit --max-seconds)");
    // Call repetitions are time-checked too (count=1e308 of a cheap subprogram).
    Module c = module(reg(mk(OpKind::Call, L(4), "callee", Expr::string("O2"), "count", N(1e308))));
    addFunction(c, "O2", reg(assign(1, N(1))));
    Diagnostics d2(sm);
    d2.setCollect(true);
    EXPECT_FALSE(jit::runModule(c, rec, d2, opts));
    ASSERT_EQ(d2.collected().size(), 1u);
    EXPECT_EQ(d2.collected()[0].loc.line, 4u);
  }
}

// A long constant run becomes one packed table: every command arrives, in order.
TEST(Jit, FlatProgramIsOneTable) {
  Region body;
  for (int i = 0; i < 500; ++i) {
    body.push_back(block(i));
    body.push_back(mk(OpKind::Move, L(2), "X", N(i * 0.5), "Y", N(-i)));
  }
  body.push_back(mk(OpKind::Message, L(3), "text", Expr::string("done")));
  Module m = module(std::move(body));
  auto r = run(m);
  ASSERT_TRUE(r->ok) << r->errors();
  ASSERT_EQ(r->rec.cmds.size(), 1001u);
  EXPECT_EQ(r->rec.cmds[998].blockNumber, 499);
  EXPECT_EQ(r->rec.cmds[999].get(Word::X), 249.5);
  EXPECT_EQ(r->rec.texts[1000], "done");

  SourceManager sm;
  Diagnostics diags(sm);
  std::string ll;
  ASSERT_TRUE(jit::emitLLVM(m, ll, diags));
  EXPECT_NE(ll.find("@nc.table = private constant"), std::string::npos);
  size_t calls = 0;  // command calls; the first block waits for the table (ncrt_exec_blocks)
  for (size_t p = ll.find("call i32 @ncrt_exec"); p != std::string::npos; p = ll.find("call i32 @ncrt_exec", p + 1))
    calls += ll.compare(p, 26, "call i32 @ncrt_exec_blocks") != 0;
  EXPECT_EQ(calls, 1u);
}

TEST(Jit, EmitObjectWritesEntrySymbol) {
  Module m = module(reg(assign(1, N(2)), mk(OpKind::Move, L(2), "X", Fn("SQRT", Var(1)))));
  SourceManager sm;
  Diagnostics diags(sm);
  std::string path = ::testing::TempDir() + "/jit_test.o";
  ASSERT_TRUE(jit::emitObject(m, path, diags));
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string obj = ss.str();
  EXPECT_EQ(obj.compare(0, 4, "\x7f" "ELF"), 0);
  EXPECT_NE(obj.find("ncc_program_main"), std::string::npos);
  EXPECT_NE(obj.find("ncc_builtin_sqrt"), std::string::npos);
  // The object runs and gives the JIT's commands.
  ::Run r;
  ASSERT_TRUE(jit::runObjectFile(path, r.rec, r.diags, {})) << r.errors();
  ASSERT_EQ(r.rec.cmds.size(), 1u);
  EXPECT_EQ(r.rec.cmds[0].get(Word::X), std::sqrt(2.0));
  std::remove(path.c_str());
}

// Benchmark shape (macro_motion.nc): 1M iterations, one G1 each. Reports the time; the target
// (well under 0.5 s without trace output) is checked by hand, not asserted.
TEST(Jit, MacroMotionBenchmark) {
  struct Counter : CmdSink {
    uint64_t n = 0;
    double sum = 0;
    bool exec(const MachineCmd &c) override {
      ++n;
      sum += c.w[0];
      return true;
    }
  } counter;
  Region body = reg(assign(3, Bin(OpCode::Mul, Var(2), N(0.36))),
                    assign(4, Bin(OpCode::Add, N(10),
                                  Bin(OpCode::Mul,
                                      Bin(OpCode::Sub, Var(2), Bin(OpCode::Mul, Fn("FIX", Bin(OpCode::Div, Var(2), N(100))), N(100))),
                                      N(0.01)))),
                    mk(OpKind::Move, L(5), "X", Bin(OpCode::Mul, Var(4), Fn("COS", Var(3))), "Y",
                       Bin(OpCode::Mul, Var(4), Fn("SIN", Var(3))), "Z",
                       Bin(OpCode::Sub, N(0), Bin(OpCode::Div, Var(2), Var(1)))),
                    assign(2, Bin(OpCode::Add, Var(2), N(1))));
  Module m = module(reg(mk(OpKind::Mode, L(1), "motion", Sym("linear")), mk(OpKind::Feed, L(1), "value", N(2000)),
                        assign(1, N(1000000)), assign(2, N(0)),
                        withBody(mk(OpKind::While, L(3), "cond", Bin(OpCode::Lt, Var(2), Var(1))), std::move(body))));
  SourceManager sm;
  Diagnostics diags(sm);
  auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(jit::runModule(m, counter, diags, {}));
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(counter.n, 1000002u);
  std::printf("macro_motion 1M iterations: %.3f s (compile + run)\n", secs);
}

// The packed table encoding round-trips every field the executor reads.
TEST(Ncrt, PackedCommandsRoundTrip) {
  std::vector<MachineCmd> in(4);
  in[0].kind = CmdKind::Block;
  in[0].blockNumber = -1;
  in[0].loc = {3, 70000, 12};
  in[1].kind = CmdKind::Mode;
  in[1].nmodes = 2;
  in[1].modes[0] = ModeValue::ArcCCW;
  in[1].modes[1] = ModeValue::Inch;
  in[2].kind = CmdKind::Move;
  in[2].set(Word::X, -1.25);
  in[2].set(Word::E, 1e-300);
  in[2].set(Word::L, vacantValue());
  in[3].kind = CmdKind::Comment;
  in[3].text = "tool change (T1)";
  in[3].sub = 7;
  in[3].sub2 = 9;
  std::string bytes;
  for (auto &c : in) ncrt::packCmd(c, c.text, bytes);
  ::Run r;
  ncrt_ctx ctx(r.rec, r.diags, {});
  ASSERT_EQ(ncrt_exec_packed(&ctx, (const uint8_t *)bytes.data(), bytes.size()), NCRT_OK);
  ASSERT_EQ(r.rec.cmds.size(), in.size());
  for (size_t i = 0; i < in.size(); ++i)
    EXPECT_EQ(diffCmd(r.rec.cmds[i], r.rec.texts[i], in[i], in[i].text ? in[i].text : ""), "") << i;
  // A truncated stream is an internal error, not a crash.
  EXPECT_EQ(ncrt_exec_packed(&ctx, (const uint8_t *)bytes.data(), bytes.size() - 3), NCRT_ERROR);
  EXPECT_EQ(r.errors(), "internal error: malformed packed command table\n");
}

// Random programs (expressions over vacant/zero/negative values, loops, ifs, gotos, calls):
// both engines must agree on every command and every diagnostic.
namespace {
struct RandomProgram {
  uint64_t state;
  explicit RandomProgram(uint64_t seed) : state(seed * 0x9e3779b97f4a7c15ull + 1) {}
  unsigned pick(unsigned n) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (unsigned)(state % n);
  }
  ExprPtr leaf() {
    static const double kNums[] = {0, 1, -1, 2.5, -7, 3, 100, 0.36, 1e308};
    static const int kVars[] = {1, 2, 3, 4, 33, 100, 500, 0};
    switch (pick(6)) {
    case 0: return N(kNums[pick(9)]);
    case 1: return Expr::vacant(L(2));
    case 2: return Named(pick(2) ? "a" : "b", pick(2) ? VarSpace::Local : VarSpace::Global);
    case 3: return Expr::var(VarSpace::RParam, "", N(pick(3)), L(3));
    default: return Var(kVars[pick(8)], L(3, pick(9)));
    }
  }
  ExprPtr expr(int depth) {
    if (depth <= 0 || pick(3) == 0) return leaf();
    static const OpCode kOps[] = {OpCode::Add, OpCode::Sub, OpCode::Mul, OpCode::Div, OpCode::Mod, OpCode::Pow,
                                  OpCode::Eq,  OpCode::Ne,  OpCode::Lt,  OpCode::Ge,  OpCode::And, OpCode::Or,
                                  OpCode::Xor, OpCode::IDiv};
    static const char *kFns[] = {"SIN", "COS", "SQRT", "ABS", "FIX", "FUP", "ROUND", "ATAN2", "LN"};
    switch (pick(5)) {
    case 0: return Expr::unary(pick(2) ? OpCode::Neg : OpCode::Not, expr(depth - 1), L(4));
    case 1: {
      const char *fn = kFns[pick(9)];
      std::vector<ExprPtr> args;
      args.push_back(expr(depth - 1));
      if (!std::strcmp(fn, "ATAN2")) args.push_back(expr(depth - 1));
      return Expr::call(fn, std::move(args), L(5));
    }
    case 2: return VarAt(expr(depth - 1));
    default: return Bin(kOps[pick(14)], expr(depth - 1), expr(depth - 1), L(6, pick(50)));
    }
  }
  Region body(int depth, int &blocks) {
    Region r;
    unsigned n = 2 + pick(5);
    for (unsigned i = 0; i < n; ++i) {
      switch (depth > 0 ? pick(11) : pick(4)) {
      case 0: r.push_back(mk(OpKind::Assign, L(7), "target", Var((int)(1 + pick(4))), "value", expr(3))); break;
      case 1: r.push_back(mk(OpKind::Move, L(8), "X", expr(2), "Y", expr(2), "Z", N(pick(5)))); break;
      case 2: r.push_back(block(++blocks)); break;
      case 3: r.push_back(mk(OpKind::Assign, L(9), "target", VarAt(expr(1)), "value", expr(2))); break;
      case 4: {
        Op w = mk(OpKind::Loop, L(10), "count", expr(1));
        w.regions.push_back(body(depth - 1, blocks));
        r.push_back(std::move(w));
        break;
      }
      case 5: {
        Op f = mk(OpKind::If, L(11), "cond", expr(2));
        f.regions.push_back(body(depth - 1, blocks));
        if (pick(2)) f.regions.push_back(body(depth - 1, blocks));
        r.push_back(std::move(f));
        break;
      }
      case 6:
        if (blocks > 0) r.push_back(mk(OpKind::Goto, L(12), "n", N(1 + pick(blocks + 1))));
        break;
      case 7: {
        Op w = mk(OpKind::While, L(14), "cond", expr(2));
        w.regions.push_back(body(depth - 1, blocks));
        if (pick(2)) w.regions[0].push_back(Op(pick(2) ? OpKind::Break : OpKind::Continue, L(15)));
        r.push_back(std::move(w));
        break;
      }
      case 8:
        r.push_back(mk(OpKind::Assign, L(16), "target", Named(pick(2) ? "a" : "b", pick(2) ? VarSpace::Local : VarSpace::Global),
                       "value", expr(2)));
        break;
      case 9:
        r.push_back(mk(OpKind::Assign, L(17), "target", Expr::var(VarSpace::RParam, "", expr(1), L(17)), "value", expr(2)));
        break;
      default:
        r.push_back(mk(OpKind::Call, L(13), "callee", Expr::string("O1"), "frame", Sym(pick(2) ? "new" : "shared"),
                       "count", N(pick(3)), "a.1", expr(1), "a.2", expr(1)));  // huge counts never end
        break;
      }
    }
    return r;
  }
};
// A block before every op, as an ISO program has one per line.
Region withLines(Region in, int &n) {
  Region out;
  for (auto &op : in) {
    for (auto &sub : op.regions) sub = withLines(std::move(sub), n);
    out.push_back(block(1000 + ++n));
    out.push_back(std::move(op));
  }
  return out;
}

// Random program `seed` (main and O1; `lines`: a block before every op) and its limits.
Module randomModule(uint64_t seed, bool lines) {
  RandomProgram g(seed);
  int blocks = 0, subBlocks = 0;
  Region body = g.body(2, blocks), sub = g.body(1, subBlocks);
  Module m = module(lines ? withLines(std::move(body), blocks) : std::move(body));
  addFunction(m, "O1", lines ? withLines(std::move(sub), subBlocks) : std::move(sub));
  return m;
}

jit::JitOptions randomLimits() {
  jit::JitOptions opts;
  opts.limits.maxLoopIterations = 50;
  opts.limits.maxCallDepth = 4;
  return opts;
}
}  // namespace

TEST(Jit, RandomProgramsMatchEval) {
  jit::JitOptions opts = randomLimits();
  for (uint64_t seed = 1; seed <= 150; ++seed) {
    Module m = randomModule(seed, false);
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + printModule(m));
    run(m, opts);  // compares both engines
    if (::testing::Test::HasFailure()) break;
  }
}

// A target that takes runs of blocks merged (CmdSink::execBlocks; the default expands a run to
// `count` copies of its last block): the same commands as the eval engine in the same order,
// and every maximal run of blocks as long as the eval engine's, ending with the same block.
// Random programs (loops, gotos, calls) check where the JIT passes waiting blocks on.
TEST(Jit, RandomProgramsMergedBlocks) {
  struct Merging : Recorder {
    uint64_t merged = 0;  // blocks that came in a run of more than one
    bool mergesBlocks() const override { return true; }
    bool execBlocks(const MachineCmd &last, uint64_t count) override {
      merged += count > 1 ? count : 0;
      return CmdSink::execBlocks(last, count);
    }
  };
  uint64_t merged = 0;
  // Each maximal run of blocks as (length, last block's line and number), other commands as they are.
  auto runs = [](const Recorder &r) {
    std::vector<std::string> out;
    for (size_t i = 0; i < r.cmds.size();) {
      const MachineCmd &c = r.cmds[i];
      if (c.kind != CmdKind::Block) {
        out.push_back(std::to_string((int)c.kind) + " " + std::to_string(c.loc.line) + " " + std::to_string(c.mask));
        ++i;
        continue;
      }
      size_t j = i;
      while (j < r.cmds.size() && r.cmds[j].kind == CmdKind::Block) ++j;
      out.push_back("blocks " + std::to_string(j - i) + " last N" + std::to_string(r.cmds[j - 1].blockNumber));
      i = j;
    }
    return out;
  };
  jit::JitOptions opts = randomLimits();
  for (uint64_t seed = 1; seed <= 150; ++seed) {
    Module m = randomModule(seed, true);
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + printModule(m));
    ::Run jr, er;
    Merging merging;
    jr.ok = jit::runModule(m, merging, jr.diags, opts);
    Evaluator ev(er.rec, er.diags, opts.limits);
    er.ok = ev.run(m);
    EXPECT_EQ(jr.ok, er.ok);
    EXPECT_EQ(jr.errors(), er.errors());
    EXPECT_EQ(runs(merging), runs(er.rec));
    merged += merging.merged;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(merged, 100u);  // the programs do merge runs of blocks
}
