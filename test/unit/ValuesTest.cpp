// Typed run-time values (ir/Strings.h, ir/Decls.h, string builtins of ir/Builtins.h): the rules
// both engines share, checked directly.
#include "ir/Arith.h"
#include "ir/Builtins.h"
#include "ir/Decls.h"
#include "ir/NCIR.h"
#include "ir/Strings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace ncc;

namespace {
double str(ValuePool &p, std::string_view s) {
  double h;
  std::string err;
  EXPECT_TRUE(p.intern(s, h, err)) << err;
  return h;
}
}  // namespace

TEST(Values, StringHandlesAreInternedNaNs) {
  ValuePool p;
  double a = str(p, "abc"), b = str(p, "abc"), c = str(p, "abd");
  EXPECT_TRUE(isString(a));
  EXPECT_TRUE(std::isnan(a));
  EXPECT_EQ(valueBits(a), valueBits(b));
  EXPECT_NE(valueBits(a), valueBits(c));
  EXPECT_EQ(p.text(c), "abd");
  EXPECT_EQ(valueBits(str(p, "")), kEmptyStringBits);
  EXPECT_FALSE(isString(vacantValue()));
  EXPECT_FALSE(isString(unsetValue()));
  EXPECT_FALSE(isString(std::nan("")));
  EXPECT_FALSE(isString(-std::nan("")));
  EXPECT_FALSE(isString(0.0 * INFINITY));
  EXPECT_EQ(valueText(p, a), "abc");
  EXPECT_EQ(valueText(p, 2.5), "2.5");
  EXPECT_EQ(valueText(p, a, true), "abc");
}

TEST(Values, StringLengthLimit) {
  ValuePool p;
  double h;
  std::string err;
  EXPECT_TRUE(p.intern(std::string(kMaxStringBytes, 'x'), h, err));
  EXPECT_FALSE(p.intern(std::string(kMaxStringBytes + 1, 'x'), h, err));
  EXPECT_EQ(err, "string of 65536 bytes exceeds the limit of 65535 bytes");
}

TEST(Values, ConvertForStore) {
  ValuePool p;
  double out;
  std::string err;
  auto conv = [&](ValueType t, double v, uint32_t len = 200) {
    err.clear();
    return convertForStore(p, t, len, "x", v, out, err);
  };
  ASSERT_TRUE(conv(ValueType::Int, 2.5));
  EXPECT_EQ(out, 3);
  ASSERT_TRUE(conv(ValueType::Int, -2.5));
  EXPECT_EQ(out, -3);
  ASSERT_TRUE(conv(ValueType::Int, vacantValue()));
  EXPECT_EQ(out, 0);
  EXPECT_FALSE(conv(ValueType::Int, 2147483648.0));
  EXPECT_EQ(err, "value 2147483648 is out of the range of int variable 'x'");
  ASSERT_TRUE(conv(ValueType::Bool, -0.1));
  EXPECT_EQ(out, 1);
  ASSERT_TRUE(conv(ValueType::Bool, str(p, "")));
  EXPECT_EQ(out, 0);
  ASSERT_TRUE(conv(ValueType::Char, 66));
  EXPECT_EQ(p.text(out), "B");
  EXPECT_FALSE(conv(ValueType::Char, str(p, "BC")));
  EXPECT_FALSE(conv(ValueType::String, 1.0));
  EXPECT_EQ(err, "cannot assign a number to string variable 'x'");
  EXPECT_FALSE(conv(ValueType::String, str(p, "abcd"), 3));
  EXPECT_EQ(err, "string of 4 characters does not fit string[3] variable 'x'");
  ASSERT_TRUE(conv(ValueType::Real, vacantValue()));
  EXPECT_TRUE(isVacant(out));
  EXPECT_FALSE(conv(ValueType::Real, str(p, "a")));
  EXPECT_EQ(valueBits(initialValue(ValueType::String)), kEmptyStringBits);
  EXPECT_EQ(initialValue(ValueType::Int), 0.0);
}

TEST(Values, CompareStrings) {
  ValuePool p;
  double r;
  std::string err;
  double a = str(p, "ab"), b = str(p, "abc"), B = str(p, "B");
  for (auto [op, x, y, want] : {std::tuple{0, a, a, 1.0}, {1, a, b, 1.0}, {2, a, b, 1.0}, {3, b, a, 0.0},
                                {4, a, B, 1.0}, {5, B, a, 0.0}}) {
    ASSERT_TRUE(compareStrings(p, op, x, y, r, err));
    EXPECT_EQ(r, want) << op;
  }
  EXPECT_FALSE(compareStrings(p, 0, a, 1.0, r, err));
  EXPECT_EQ(err, "cannot compare a string with a number");
}

TEST(Values, BuiltinTableIsConsistent) {
  unsigned n = 0;
  const BuiltinInfo *t = builtinTable(n);
  for (unsigned i = 0; i < n; ++i) {
    EXPECT_TRUE(!!t[i].fn != !!t[i].sfn) << t[i].name;
    if (t[i].sfn) EXPECT_EQ(std::string_view(t[i].args).size(), t[i].arity) << t[i].name;
    else EXPECT_NE(t[i].symbol, nullptr) << t[i].name;
  }
  const BuiltinInfo *sub = findBuiltin("SUBSTR");
  ASSERT_NE(sub, nullptr);
  EXPECT_TRUE(sub->accepts(2) && sub->accepts(3) && !sub->accepts(1));
  EXPECT_EQ(builtinArity(*sub), "2 or 3");
}

TEST(Values, StringBuiltins) {
  ValuePool p;
  auto call = [&](const char *name, std::vector<double> args, double &out, std::string &err) {
    const BuiltinInfo *b = findBuiltin(name);
    EXPECT_NE(b, nullptr);
    return b->sfn(p, args.data(), (unsigned)args.size(), out, err);
  };
  double r;
  std::string err;
  ASSERT_TRUE(call("SUBSTR", {str(p, "hello"), 1, 3}, r, err));
  EXPECT_EQ(p.text(r), "ell");
  ASSERT_TRUE(call("RINDEX", {str(p, "/a/b"), str(p, "/")}, r, err));
  EXPECT_EQ(r, 2);
  ASSERT_TRUE(call("MINDEX", {str(p, "/_N_MPF_DIR/_N_EXECUTE_MPF"), str(p, "M,N,O,P")}, r, err));
  EXPECT_EQ(r + 1, 3);  // the manual's example
  ASSERT_TRUE(call("NUMBER", {str(p, "1234.9876Ex-7")}, r, err));
  EXPECT_DOUBLE_EQ(r, 1234.9876e-7);
  ASSERT_TRUE(call("ISNUMBER", {str(p, "1234XYZ")}, r, err));
  EXPECT_EQ(r, 0);
  EXPECT_FALSE(call("NUMBER", {str(p, "12x")}, r, err));
  EXPECT_EQ(err, "'NUMBER' cannot convert \"12x\" to a number");
  EXPECT_FALSE(call("STRLEN", {5.0}, r, err));
  EXPECT_EQ(err, "'STRLEN' argument 1 must be a string");
}

TEST(Values, TolerantComparison) {
  const BuiltinInfo *gt = findBuiltin("TOLGT"), *eq = findBuiltin("TOLEQ");
  double a[3] = {std::fabs(61.02 - 61.01), 0.01, 1e-12};
  EXPECT_GT(a[0], a[1]);
  EXPECT_EQ(gt->fn(a), 0.0);
  EXPECT_EQ(eq->fn(a), 1.0);
  a[2] = 0;
  EXPECT_EQ(gt->fn(a), 1.0);
}

TEST(Values, DeclarationsAndTextForm) {
  SourceManager sm;
  Diagnostics diags(sm);
  ir::Module m;
  const char *text = "module \"d.nc\" dialect=sinumerik\nfunc @main {\n"
                     "  declare var=%M[2, 3, 4] type=int init=1\n"
                     "  declare var=%%S type=string len=8\n"
                     "  assign target=%M[1, (add #1 1), 3] value=%%S\n"
                     "}\n";
  ASSERT_TRUE(ir::parseModule(text, 0, sm, diags, m));
  EXPECT_NE(ir::printModule(m).find("assign target=%M[1, (add #1 1), 3] value=%%S"), std::string::npos);
  ir::DeclTable decls;
  ASSERT_TRUE(ir::collectDecls(m, decls, &diags));
  const ir::VarDecl *d = decls.find(m.functions[0], ir::VarSpace::Local, "M");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->rank, 3u);
  EXPECT_EQ(d->size(), 24u);
  EXPECT_EQ(d->type, ValueType::Int);
  const ir::VarDecl *s = decls.find(m.functions[0], ir::VarSpace::Global, "S");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->len, 8u);
  EXPECT_TRUE(ir::verifyModule(m, diags));
}

TEST(Values, PoolLimit) {
  ValuePool p;
  double h;
  std::string err;
  uint32_t i = 1;  // handle 0 is ""
  for (; i < kMaxPoolStrings; ++i)
    if (!p.intern(std::to_string(i), h, err)) break;
  EXPECT_EQ(i, kMaxPoolStrings);
  EXPECT_TRUE(p.intern("1", h, err));  // known strings still resolve
  EXPECT_FALSE(p.intern("new", h, err));
  EXPECT_EQ(err, poolLimitMessage());
  EXPECT_EQ(err, "string pool limit exceeded: more than 1000000 distinct strings or 67108864 bytes in one run");
}

// MOD's integer path must give fmod's result bit for bit (then the divisor's sign), so both
// engines and every earlier trace stay as they were.
TEST(Values, ModOfWholeNumbersEqualsFmod) {
  auto reference = [](double a, double b) {
    double r = std::fmod(a, b);
    if (r != 0 && ((r < 0) != (b < 0))) r += b;
    return r;
  };
  auto same = [&](double a, double b) {
    double want = reference(a, b), got = arithMod(a, b);
    if (std::isnan(want)) return std::isnan(got);
    return std::memcmp(&want, &got, sizeof want) == 0;
  };
  const double edge[] = {0.0, -0.0, 1, -1, 2, -2, 3, -3, 7, -7, 100, -100, 0.5, -0.5, 1e15, -1e15,
                         9007199254740991.0, -9007199254740991.0, 9007199254740992.0, 1e300,
                         INFINITY, -INFINITY, NAN};
  for (double a : edge)
    for (double b : edge) EXPECT_TRUE(same(a, b)) << a << " MOD " << b;
  std::mt19937_64 g(6);
  for (int i = 0; i < 200000; ++i) {
    double a = (double)(int64_t)(g() % 2000001) - 1000000, b = (double)(int64_t)(g() % 401) - 200;
    if (i % 3 == 0) a = std::ldexp((double)(int64_t)(g() >> 11), -(int)(g() % 8)) * (g() & 1 ? 1 : -1);
    ASSERT_TRUE(same(a, b)) << a << " MOD " << b;
  }
}
