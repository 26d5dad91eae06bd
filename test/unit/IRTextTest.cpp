// NC IR text form: printing, parsing, round trip, parse errors, verifier rules, parser fuzzing.
#include "ir/NCIR.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace ncc;
using namespace ncc::ir;

namespace {

// The example of the text form from the design brief; it must print back byte for byte.
const char *kExample = R"(module "prog.nc" dialect=iso
source 1 "prog.nc"
source 2 "O1000.nc"
func @main loc(1:1:1) {
  block n=10 loc(1:3:1)
  mode motion=linear plane=xy loc(1:3:5)
  move X=10.0 Y=(add #1 2) loc(1:3:9)
  assign target=#2 value=(add #2 1.0) loc(1:4:1)
  while cond=(lt #2 #1) id=1 loc(1:5:1) {
    comment text="hello \"x\"" loc(1:6:1)
  }
  if cond=(eq #1 vacant) loc(1:7:1) {
    goto n=100 loc(1:7:12)
  } else {
  }
  block n=100 loc(1:8:1)
  call callee="O1000" count=2 frame=new a.1=1.0 loc(1:8:1)
}
func @O1000(REAL a, VAR INT b = 1) loc(2:1:1) {
  return loc(2:3:1)
}
)";

struct Ctx {
  SourceManager sm;
  Diagnostics diags{sm};
  Ctx() { diags.setCollect(true); }

  bool parse(const std::string &text, Module &m) {
    uint32_t id = sm.addBuffer("test.ncir", text);
    return parseModule(text, id, sm, diags, m);
  }
  std::string firstError() const {
    for (auto &d : diags.collected())
      if (d.severity == Severity::Error)
        return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " + d.message;
    return "";
  }
  bool hasMessage(const std::string &msg) const {
    for (auto &d : diags.collected())
      if (d.message == msg) return true;
    return false;
  }
};

// print -> parse -> print must reproduce the text exactly.
std::string roundTrip(const std::string &text, Ctx &c) {
  Module m;
  if (!c.parse(text, m)) return "parse failed: " + c.firstError();
  return printModule(m, c.sm);
}

}  // namespace

TEST(IRText, ExampleRoundTripsAndVerifies) {
  Ctx c;
  Module m;
  ASSERT_TRUE(c.parse(kExample, m)) << c.firstError();
  EXPECT_EQ(printModule(m, c.sm), kExample);
  EXPECT_TRUE(verifyModule(m, c.diags)) << c.firstError();
  ASSERT_EQ(m.functions.size(), 2u);
  EXPECT_EQ(m.functions[1].params[1].byRef, true);
  EXPECT_EQ(m.functions[1].params[1].type, Type::Int);
  const Op &mv = m.functions[0].body[2];
  EXPECT_EQ(mv.kind, OpKind::Move);
  EXPECT_EQ(mv.loc.line, 3u);
  EXPECT_EQ(mv.loc.col, 9u);
  EXPECT_EQ(c.sm.name(mv.loc.file), "prog.nc");
  EXPECT_EQ(c.sm.name(m.functions[1].loc.file), "O1000.nc");
  const Expr *y = mv.get("Y");
  ASSERT_TRUE(y);
  EXPECT_EQ(y->kind, ExprKind::Binary);
  EXPECT_EQ(y->op, OpCode::Add);
  EXPECT_EQ(y->args[0]->space, VarSpace::Numbered);
  EXPECT_EQ(y->args[1]->type, Type::Int);
  EXPECT_EQ(m.functions[0].body[4].regions.size(), 1u);
  EXPECT_EQ(m.functions[0].body[5].regions.size(), 2u);
}

TEST(IRText, ExprSpelling) {
  auto num = [](double v, Type t) { return printExpr(*Expr::number(v, t)); };
  EXPECT_EQ(num(5, Type::Int), "5");
  EXPECT_EQ(num(-3, Type::Int), "-3");
  EXPECT_EQ(num(2, Type::Real), "2.0");
  EXPECT_EQ(num(0.1, Type::Real), "0.1");
  EXPECT_EQ(num(1e-7, Type::Real), "1e-07");
  EXPECT_EQ(num(-0.5, Type::Real), "-0.5");
  EXPECT_EQ(num(2.5, Type::Int), "2.5");  // not integral: keeps its value
  EXPECT_EQ(printExpr(*Expr::boolean(true)), "true");
  EXPECT_EQ(printExpr(*Expr::string("a\"b\\c\nd")), R"("a\"b\\c\nd")");
  EXPECT_EQ(printExpr(*Expr::symbol("linear")), "linear");
  EXPECT_EQ(printExpr(*Expr::symbol("R5")), R"(sym"R5")");  // would read back as a parameter
  EXPECT_EQ(printExpr(*Expr::vacant()), "vacant");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::Numbered, "", Expr::number(5, Type::Int))), "#5");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::Numbered, "", Expr::var(VarSpace::Numbered, "", Expr::number(1, Type::Int)))),
            "#[#1]");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::Numbered, "", Expr::number(5, Type::Real))), "#[5.0]");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::RParam, "", Expr::number(12, Type::Int))), "R12");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::QParam, "QL", Expr::binary(OpCode::Add, Expr::number(1, Type::Int),
                                                                       Expr::number(2, Type::Int)))),
            "QL[(add 1 2)]");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::QParam, "Q", Expr::number(7, Type::Int))), "Q7");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::Local, "count")), "%count");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::Local, "arr", Expr::number(3, Type::Int))), "%arr[3]");
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::Global, "_g")), "%%_g");
  {
    ExprPtr m = Expr::var(VarSpace::Local, "M", Expr::number(1, Type::Int));
    m->args.push_back(Expr::var(VarSpace::Numbered, "", Expr::number(2, Type::Int)));
    m->args.push_back(Expr::number(0, Type::Int));
    EXPECT_EQ(printExpr(*m), "%M[1, #2, 0]");
  }
  EXPECT_EQ(printExpr(*Expr::var(VarSpace::System, "AA_IM", Expr::symbol("X"))), "$AA_IM[X]");
  EXPECT_EQ(printExpr(*Expr::unary(OpCode::Neg, Expr::var(VarSpace::Numbered, "", Expr::number(3, Type::Int)))),
            "(neg #3)");
  std::vector<ExprPtr> args;
  args.push_back(Expr::number(30, Type::Real));
  EXPECT_EQ(printExpr(*Expr::call("SIN", std::move(args))), "(SIN 30.0)");
}

TEST(IRText, NumbersReadBackExactly) {
  const double values[] = {0.1, 1.0 / 3, 1e-300, 5e-324, 1.7976931348623157e308, -123456.789, 1e21, -0.0};
  for (double v : values) {
    Ctx c;
    Module m;
    std::string text = "module \"x\" dialect=iso\nfunc @main() {\n  feed value=" +
                       printExpr(*Expr::number(v, Type::Real)) + "\n}\n";
    ASSERT_TRUE(c.parse(text, m)) << text << c.firstError();
    const Expr *e = m.functions[0].body[0].get("value");
    EXPECT_EQ(e->type, Type::Real);
    EXPECT_EQ(std::memcmp(&e->num, &v, sizeof v), 0) << text;
  }
  Ctx c;
  Module m;
  ASSERT_TRUE(c.parse("module \"x\" dialect=iso\nfunc @main() {\n  feed value=1e999\n  dwell seconds=nan\n}\n", m));
  EXPECT_TRUE(std::isinf(m.functions[0].body[0].get("value")->num));
  EXPECT_TRUE(std::isnan(m.functions[0].body[1].get("seconds")->num));
  EXPECT_EQ(printModule(m), "module \"x\" dialect=iso\nfunc @main {\n  feed value=1e999\n  dwell seconds=nan\n}\n");
}

TEST(IRText, NamesThatAreNotIdentifiersAreQuoted) {
  Module m;
  m.name = "a \"b\".nc";
  m.dialect = Dialect::Sinumerik;
  Function f;
  f.name = "L 10";
  Param p;
  p.name = "x y";
  p.type = Type::Frame;
  f.params.push_back(std::move(p));
  Op op(OpKind::Assign);
  op.set("target", Expr::var(VarSpace::Local, "my var"));
  op.set("value", Expr::symbol("two words"));
  f.body.push_back(std::move(op));
  Op c(OpKind::Call);
  c.set("callee", Expr::string("L 10"));
  c.set("a.\"k", Expr::symbol("QS"));
  f.body.push_back(std::move(c));
  m.functions.push_back(std::move(f));
  std::string text = printModule(m);
  EXPECT_NE(text.find(R"(func @"L 10"(FRAME "x y"))"), std::string::npos) << text;
  EXPECT_NE(text.find(R"(assign target=%"my var" value=sym"two words")"), std::string::npos) << text;
  Ctx ctx;
  EXPECT_EQ(roundTrip(text, ctx), text);
}

// ---------------------------------------------------------------- constructed modules

namespace {

// Builds random but printable modules: every expression and op form the printer knows.
class Gen {
public:
  explicit Gen(unsigned seed, uint32_t fileA, uint32_t fileB) : rng_(seed), fa_(fileA), fb_(fileB) {}

  Module module() {
    Module m;
    m.name = pick({"prog.nc", "main.mpf", "x y.h"});
    m.dialect = (Dialect)(r(5));
    unsigned nf = 1 + r(3);
    for (unsigned i = 0; i < nf; ++i) {
      Function f;
      f.name = i == 0 ? "main" : "O" + std::to_string(1000 + i);
      f.loc = loc();
      for (unsigned k = r(3); k > 0; --k) {
        Param p;
        p.name = "p" + std::to_string(k);
        p.type = (Type)(r(9));
        p.byRef = r(2);
        if (r(2)) p.defaultValue = expr(2);
        f.params.push_back(std::move(p));
      }
      f.body = region(2);
      m.functions.push_back(std::move(f));
    }
    return m;
  }

private:
  std::mt19937 rng_;
  uint32_t fa_, fb_;

  unsigned r(unsigned n) { return rng_() % n; }
  std::string pick(std::initializer_list<const char *> l) { return *(l.begin() + r((unsigned)l.size())); }

  SourceLoc loc() {
    if (r(4) == 0) return {};
    return SourceLoc{r(2) ? fa_ : fb_, 1 + r(500), r(80)};
  }

  ExprPtr leaf() {
    switch (r(8)) {
    case 0: return Expr::number((double)((int)r(2000) - 1000), Type::Int);
    case 1: return Expr::number(((double)rng_() / 7.0 - 3e8) * std::pow(10.0, (int)r(20) - 10), Type::Real);
    case 2: return Expr::string(pick({"", "hi", "q\"uote", "back\\slash", "nl\nx", "tab\tz", "\x01", "ümlaut"}));
    case 3: return Expr::boolean(r(2));
    case 4: return Expr::symbol(pick({"linear", "xy", "cw", "R", "QL", "true", "sym", "a b", "X", "Rapid", "R1"}));
    case 5: return Expr::vacant();
    default: {
      static const VarSpace spaces[] = {VarSpace::Numbered, VarSpace::RParam, VarSpace::QParam,
                                        VarSpace::Local, VarSpace::Global, VarSpace::System};
      VarSpace sp = spaces[r(6)];
      std::string name = sp == VarSpace::QParam ? pick({"Q", "QL", "QR", "QS"})
                         : (sp == VarSpace::Numbered || sp == VarSpace::RParam) ? ""
                                                                                : pick({"x", "AA_IM", "_v1", "a.b"});
      ExprPtr idx;
      if (sp == VarSpace::Numbered || sp == VarSpace::RParam || sp == VarSpace::QParam || r(2))
        idx = r(2) ? Expr::number(r(1000), Type::Int) : leafNumber();
      ExprPtr v = Expr::var(sp, name, std::move(idx));
      if ((sp == VarSpace::Local || sp == VarSpace::Global) && !v->args.empty())  // declared arrays: 1-3 indices
        for (unsigned extra = r(3); extra > 0; --extra) v->args.push_back(leafNumber());
      return v;
    }
    }
  }
  ExprPtr leafNumber() { return Expr::number(r(100) / 4.0, r(2) ? Type::Real : Type::Int); }

  ExprPtr expr(unsigned depth) {
    if (depth == 0 || r(3) == 0) return leaf();
    switch (r(3)) {
    case 0: return Expr::unary(r(2) ? OpCode::Neg : OpCode::Not, expr(depth - 1));
    case 1: return Expr::binary((OpCode)(3 + r(17)), expr(depth - 1), expr(depth - 1));
    default: {
      std::vector<ExprPtr> a;
      for (unsigned k = r(3); k > 0; --k) a.push_back(expr(depth - 1));
      return Expr::call(pick({"SIN", "ATAN2", "ABS"}), std::move(a));
    }
    }
  }

  Region region(unsigned depth) {
    Region rg;
    for (unsigned n = r(6); n > 0; --n) {
      Op op((OpKind)r((unsigned)OpKind::Count), loc());
      for (unsigned k = r(4); k > 0; --k)
        op.args.push_back({pick({"X", "value", "a.1", "n", "cond", "_k", "target"}), expr(3)});
      if (depth > 0)
        for (unsigned k = r(3); k > 0; --k) op.regions.push_back(region(depth - 1));
      rg.push_back(std::move(op));
    }
    return rg;
  }
};

}  // namespace

TEST(IRText, ConstructedModulesRoundTrip) {
  for (unsigned seed = 1; seed <= 300; ++seed) {
    Ctx c;
    uint32_t fa = c.sm.addBuffer("a.nc", "");
    uint32_t fb = c.sm.addBuffer("sub/b.spf", "");
    Gen g(seed, fa, fb);
    Module m = g.module();
    std::string text = printModule(m, c.sm);
    std::string again = roundTrip(text, c);
    ASSERT_EQ(again, text) << "seed " << seed;
    // Parsing maps sources back onto the same SourceManager files.
    Module m2;
    ASSERT_TRUE(c.parse(text, m2));
    ASSERT_EQ(m2.functions.size(), m.functions.size());
    for (size_t i = 0; i < m.functions.size(); ++i) {
      EXPECT_EQ(m2.functions[i].loc.file, m.functions[i].loc.valid() ? m.functions[i].loc.file : 0u);
      EXPECT_EQ(m2.functions[i].body.size(), m.functions[i].body.size());
    }
  }
}

// ---------------------------------------------------------------- parse errors

namespace {
std::string parseError(const std::string &text) {
  Ctx c;
  Module m;
  if (c.parse(text, m)) return "parsed";
  return c.firstError();
}
const std::string kHead = "module \"p\" dialect=iso\nsource 1 \"p.nc\"\nfunc @main() {\n";
}  // namespace

TEST(IRText, ParseErrorsPointAtTheProblem) {
  EXPECT_EQ(parseError(""), "1:1: expected 'module', found end of input");
  EXPECT_EQ(parseError("module \"p\" dialect=fanuc\n"), "1:20: unknown dialect 'fanuc'");
  EXPECT_EQ(parseError(kHead + "  mvoe X=1\n}\n"), "4:3: unknown op 'mvoe'");
  EXPECT_EQ(parseError(kHead + "  move X=\n}\n"), "5:1: expected an expression, found '}'");
  EXPECT_EQ(parseError(kHead + "  move X=(add 1 2\n}\n"), "5:1: expected an expression, found '}'");
  EXPECT_EQ(parseError(kHead + "  move X=1 loc(2:1:1)\n}\n"), "4:16: loc refers to undefined source 2");
  EXPECT_EQ(parseError(kHead + "  move X=1 loc(1:0:1)\n}\n"), "4:18: line must be at least 1");
  EXPECT_EQ(parseError(kHead + "  comment text=\"abc\n}\n"), "4:16: unterminated string");
  EXPECT_EQ(parseError(kHead + "  comment text=\"a\\qb\"\n}\n"), "4:18: unknown escape in string");
  EXPECT_EQ(parseError(kHead + "  move X=1.5.5\n}\n"), "4:10: malformed number");
  EXPECT_EQ(parseError(kHead + "  move X=#1.5\n}\n"), "4:11: parameter number must be an integer");
  EXPECT_EQ(parseError(kHead + "  move X=(add 1 2 3)\n}\n"), "4:11: operator 'add' takes 1 or 2 operands, found 3");
  EXPECT_EQ(parseError(kHead + "  move X=1 ^\n}\n"), "4:12: unexpected character '^'");
  EXPECT_EQ(parseError(kHead + "  if cond=true {\n"), "5:1: expected '}' before end of input");
  EXPECT_EQ(parseError("module \"p\" dialect=iso\nsource 1 \"a\"\nsource 1 \"b\"\n"), "3:8: source 1 is defined twice");
  EXPECT_EQ(parseError("module \"p\" dialect=iso\nfunc @main(REEL x) {\n}\n"), "2:12: unknown type 'REEL'");
  EXPECT_EQ(parseError("module \"p\" dialect=iso\nfunc @f() {\n}\nfunc @f() {\n}\n"), "4:7: function '@f' is defined twice");
  EXPECT_EQ(parseError(kHead + "}\ngarbage\n"), "5:1: expected 'func' or end of input, found 'garbage'");
}

TEST(IRText, ParseErrorDiagnosticQuotesTheNcirLine) {
  Ctx c;
  Module m;
  std::string text = kHead + "  move X=1 ^\n}\n";
  ASSERT_FALSE(c.parse(text, m));
  ASSERT_EQ(c.diags.collected().size(), 1u);
  EXPECT_EQ(c.diags.render(c.diags.collected()[0]),
            "test.ncir:4:12: error: unexpected character '^'\n  move X=1 ^\n           ^\n");
}

TEST(IRText, CommentsAndBlankLinesAreIgnored) {
  Ctx c;
  Module m;
  ASSERT_TRUE(c.parse("; RUN: x\nmodule \"p\" dialect=iso ; trailing\n\nfunc @main() { ; body\n  move X=1 ; c\n\n}\n", m))
      << c.firstError();
  EXPECT_EQ(printModule(m), "module \"p\" dialect=iso\nfunc @main {\n  move X=1\n}\n");
}

TEST(IRText, DeepNestingIsAnErrorNotACrash) {
  std::string deep;
  for (int i = 0; i < 5000; ++i) deep += "(neg ";
  EXPECT_EQ(parseError(kHead + "  move X=" + deep), "4:1005: nesting too deep");
  std::string regions;
  for (int i = 0; i < 5000; ++i) regions += "loop {\n";
  EXPECT_NE(parseError(kHead + regions).find("nesting too deep"), std::string::npos);
}

// ---------------------------------------------------------------- verifier

namespace {
// Verifies a function body given as text; returns all error messages joined by '\n'.
std::string verify(const std::string &body, const std::string &extra = "") {
  Ctx c;
  Module m;
  std::string text = "module \"p\" dialect=iso\nsource 1 \"p.nc\"\nfunc @main() loc(1:1:1) {\n" + body + "}\n" + extra;
  if (!c.parse(text, m)) return "parse: " + c.firstError();
  bool ok = verifyModule(m, c.diags);
  std::string out;
  for (auto &d : c.diags.collected()) out += (out.empty() ? "" : "\n") + d.message;
  if (ok != out.empty()) out += "\n(result disagrees with diagnostics)";
  return out;
}
}  // namespace

TEST(IRVerifier, Keys) {
  EXPECT_EQ(verify("move X=1 Y=2\n"), "");
  EXPECT_EQ(verify("move X=1 QQ=2\n"), "'move' has unknown argument 'QQ'");
  EXPECT_EQ(verify("feed\n"), "'feed' is missing required argument 'value'");
  EXPECT_EQ(verify("move X=1 X=2\n"), "'move' has argument 'X' twice");
  EXPECT_EQ(verify("call callee=\"main\" count=1 frame=shared a.X=1 a.1=2\n"), "");
  EXPECT_EQ(verify("call callee=\"main\" b=1\n"), "'call' has unknown argument 'b'");
  EXPECT_EQ(verify("call callee=\"main\" a.=1\n"), "'call' has unknown argument 'a.'");
}

TEST(IRVerifier, Regions) {
  EXPECT_EQ(verify("if cond=true {\n} else {\n}\n"), "");
  EXPECT_EQ(verify("if cond=true {\n} else {\n} else {\n}\n"), "'if' has 3 regions, expected 1 to 2");
  EXPECT_EQ(verify("while cond=true {\n} else {\n}\n"), "'while' has 2 regions, expected 1");
  EXPECT_EQ(verify("loop\n"), "'loop' has 0 regions, expected 1");
  EXPECT_EQ(verify("move X=1 {\n}\n"), "'move' has 1 region, expected 0");
}

TEST(IRVerifier, ModeValues) {
  EXPECT_EQ(verify("mode motion=arc_cw plane=zx units=mm distance=incremental feed_mode=per_rev\n"), "");
  EXPECT_EQ(verify("mode motion=xy\n"), "'mode' value 'xy' belongs to group 'plane', not 'motion'");
  EXPECT_EQ(verify("mode plane=diagonal\n"), "'mode' has unknown value 'diagonal' for 'plane'");
  EXPECT_EQ(verify("mode plane=\"xy\"\n"), "'mode' argument 'plane' must be a mode name");
  EXPECT_EQ(verify("mode gear=high\n"), "'mode' has unknown argument 'gear'");
}

TEST(IRVerifier, EnumeratedValuesAndVariables) {
  EXPECT_EQ(verify("spindle dir=cw\ncoolant flood=on mist=off\nstop kind=end_rewind\n"), "");
  EXPECT_EQ(verify("spindle dir=left\n"), "'spindle' argument 'dir' must be one of: cw ccw stop orient");
  EXPECT_EQ(verify("assign target=5 value=1\n"), "'assign' argument 'target' must be a variable");
  EXPECT_EQ(verify("declare var=%x type=REAL init=0.5\n"), "");
  EXPECT_EQ(verify("declare var=%x type=float\n"),
            "'declare' argument 'type' must be one of: int real bool char string symbol axis frame");
  EXPECT_EQ(verify("block n=#1\n"), "'block' argument 'n' must be a non-negative integer constant");
  EXPECT_EQ(verify("declare var=#1 type=REAL\n"), "'declare' argument 'var' must be a named variable (%name or %%name)");
  EXPECT_EQ(verify("declare var=%%g type=INT\n"), "");
}

TEST(IRVerifier, Expressions) {
  EXPECT_EQ(verify("move X=(ATAN2 1 2) Y=(neg (SIN #[#1]))\n"), "");
  EXPECT_EQ(verify("move X=(FOO 1)\n"), "'move' argument 'X': unknown function 'FOO'");
  EXPECT_EQ(verify("move X=(SIN 1 2)\n"), "'move' argument 'X': function 'SIN' takes 1 argument, found 2");
  EXPECT_EQ(verify("move X=(add 1)\n"), "'move' argument 'X': unary 'add' with 1 operand(s)");
  EXPECT_EQ(verify("move X=#[]\n"), "'move' argument 'X': numbered parameter without a number");
  // Shapes the text cannot express are built directly.
  Module m;
  Function f;
  f.name = "main";
  Op op(OpKind::Move);
  auto bin = Expr::binary(OpCode::Add, Expr::number(1, Type::Int), Expr::number(2, Type::Int));
  bin->args.pop_back();
  op.set("X", std::move(bin));
  op.set("Y", nullptr);
  op.set("Z", Expr::var(VarSpace::QParam, "QX", Expr::number(1, Type::Int)));
  f.body.push_back(std::move(op));
  m.functions.push_back(std::move(f));
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  EXPECT_FALSE(verifyModule(m, d));
  ASSERT_EQ(d.collected().size(), 3u);
  EXPECT_EQ(d.collected()[0].message, "'move' argument 'X': binary 'add' with 1 operand(s)");
  EXPECT_EQ(d.collected()[1].message, "'move' argument 'Y': missing expression");
  EXPECT_EQ(d.collected()[2].message, "'move' argument 'Z': Q parameter prefix 'QX' is not Q, QL, QR or QS");
}

TEST(IRVerifier, GotoTargets) {
  EXPECT_EQ(verify("goto n=20\nwhile cond=true {\n  block n=20\n}\n"), "");  // forward, into a region
  EXPECT_EQ(verify("goto n=30\nblock n=20\n"), "'goto' target block N30 is not in this function");
  EXPECT_EQ(verify("label name=\"L1\"\ngoto label=\"L1\"\n"), "");
  EXPECT_EQ(verify("goto label=\"L2\"\n"), "'goto' target label 'L2' is not in this function");
  EXPECT_EQ(verify("goto\n"), "'goto' needs a target: n= or label=");
  EXPECT_EQ(verify("label name=\"5\"\ngoto n=\"5\"\n"), "'goto' argument 'n' must be a number");
  EXPECT_EQ(verify("block n=5\ngoto label=5\n"), "'goto' argument 'label' must be a string");
  EXPECT_EQ(verify("goto label=(concat \"L\" R1)\n"), "");  // computed label (Sinumerik GOTOF "N"<<R10)
  EXPECT_EQ(verify("goto n=#1\n"), "");  // computed target: checked at run time
  EXPECT_EQ(verify("label name=\"A\"\nlabel name=\"A\"\n"), "label 'A' is defined twice in function '@main'");
  // A block of another function is not a target.
  EXPECT_EQ(verify("goto n=5\n", "func @O1() {\n  block n=5\n}\n"), "'goto' target block N5 is not in this function");
}

TEST(IRVerifier, CallsAndLoops) {
  EXPECT_EQ(verify("call callee=\"O1\"\n", "func @O1() {\n  return\n}\n"), "");
  EXPECT_EQ(verify("call callee=\"O2\"\n"), "'call' target 'O2' is not a function of this module");
  EXPECT_EQ(verify("call callee=5\n"), "'call' target 'O5' is not a function of this module");
  EXPECT_EQ(verify("call callee=2.5\n"), "'call' argument 'callee' must be a string or a program number");
  EXPECT_EQ(verify("call callee=x\n"), "'call' argument 'callee' must be a string or a program number");
  EXPECT_EQ(verify("break\n"), "'break' outside of a 'while' or 'loop'");
  EXPECT_EQ(verify("if cond=true {\n  continue\n}\n"), "'continue' outside of a 'while' or 'loop'");
  EXPECT_EQ(verify("loop count=3 {\n  if cond=true {\n    break\n  }\n  continue\n}\n"), "");
}

TEST(IRVerifier, ErrorsCarryTheOpLoc) {
  Ctx c;
  Module m;
  ASSERT_TRUE(c.parse(kHead + "  move QQ=1 loc(1:7:3)\n}\n", m));
  EXPECT_FALSE(verifyModule(m, c.diags));
  ASSERT_EQ(c.diags.collected().size(), 1u);
  const Diagnostic &d = c.diags.collected()[0];
  EXPECT_EQ(c.sm.name(d.loc.file), "p.nc");
  EXPECT_EQ(d.loc.line, 7u);
  EXPECT_EQ(d.loc.col, 3u);
  EXPECT_EQ(d.message, "'move' has unknown argument 'QQ'");
}

TEST(IRVerifier, EmptyModule) {
  Module m;
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  EXPECT_FALSE(verifyModule(m, d));
}

// ---------------------------------------------------------------- fuzz

// Random bytes and mutations of valid text: the parser must return (true or false) without
// crashing or hanging; whatever it accepts must verify without crashing and round trip.
TEST(IRTextFuzz, ParserNeverCrashes) {
  std::mt19937 rng(12345);
  std::vector<std::string> corpus = {kExample};
  {
    Ctx c;
    uint32_t fa = c.sm.addBuffer("a.nc", "");
    for (unsigned s = 1; s <= 20; ++s) {
      Gen g(1000 + s, fa, fa);
      corpus.push_back(printModule(g.module(), c.sm));
    }
  }
  const std::string alphabet = "()[]{}=,@#%$:;\"\\ \n\t-.0123456789eEaRQLS_xyzmovefunclocsym\x01\xff";
  unsigned accepted = 0;
  for (unsigned iter = 0; iter < 4000; ++iter) {
    std::string text = corpus[rng() % corpus.size()];
    unsigned kind = rng() % 4;
    if (kind == 0) {  // pure noise
      text.clear();
      for (unsigned n = rng() % 200; n > 0; --n) text += alphabet[rng() % alphabet.size()];
    } else {
      for (unsigned n = 1 + rng() % 6; n > 0 && !text.empty(); --n) {
        size_t pos = rng() % text.size();
        switch (rng() % 4) {
        case 0: text[pos] = alphabet[rng() % alphabet.size()]; break;
        case 1: text.erase(pos, 1 + rng() % 8); break;
        case 2: text.insert(pos, 1, alphabet[rng() % alphabet.size()]); break;
        default: text.insert(pos, text.substr(rng() % text.size(), rng() % 40)); break;
        }
      }
      if (kind == 3) text = text.substr(0, rng() % (text.size() + 1));  // truncation
    }
    Ctx c;
    c.diags.setErrorLimit(5);
    Module m;
    bool ok = c.parse(text, m);
    if (!ok) {
      ASSERT_EQ(c.diags.errorCount(), 1u) << text;
      continue;
    }
    ++accepted;
    verifyModule(m, c.diags);
    std::string printed = printModule(m, c.sm);
    ASSERT_EQ(roundTrip(printed, c), printed) << "input:\n" << text;
  }
  EXPECT_GT(accepted, 50u);  // the mutations must also exercise the accepting paths
}

// A readable source path is loaded, so verifier diagnostics quote the original program line.
TEST(IRText, ReadableSourcesAreLoaded) {
  std::string path = ::testing::TempDir() + "irtext_src.nc";
  {
    std::FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    std::fputs("N10 G1 X1\nN20 G1 QQ2\n", f);
    std::fclose(f);
  }
  Ctx c;
  Module m;
  std::string text = "module \"x\" dialect=iso\nsource 1 \"" + path + "\"\nfunc @main {\n  move QQ=2.0 loc(1:2:8)\n}\n";
  ASSERT_TRUE(c.parse(text, m)) << c.firstError();
  EXPECT_FALSE(verifyModule(m, c.diags));
  ASSERT_EQ(c.diags.collected().size(), 1u);
  EXPECT_EQ(c.diags.render(c.diags.collected()[0]),
            path + ":2:8: error: 'move' has unknown argument 'QQ'\nN20 G1 QQ2\n       ^\n");
  std::remove(path.c_str());
}
