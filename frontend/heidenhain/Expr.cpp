// Q parameters and formulas: `Q1 = 5 + Q2 * SIN(30)`, the values of address words (`X+Q1`),
// with the precedence of the TNC's formula entry (^ before * / before + -).
#include "frontend/heidenhain/Parser.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::hei {

ExprPtr num(double v, SourceLoc l) {
  return Expr::number(v, v == std::floor(v) && std::fabs(v) < 1e15 ? ir::Type::Int : ir::Type::Real, l);
}

namespace {
// Q global, QL local to its program (a declared local array, so CALL PGM gets fresh ones), QR kept.
struct QSpace {
  const char *prefix;
  int last;  // highest number (TNC 640)
};
const QSpace kQ[] = {{"Q", 1999}, {"QL", 499}, {"QR", 499}, {"QS", 1999}};

// The formula functions: one argument in degrees for the angles (the TNC's unit).
enum class Fn : uint8_t { Builtin, Log, Frac, Neg, Sgn, Sq };
struct FnRow {
  const char *name;
  Fn kind;
  const char *builtin;
};
const FnRow kFns[] = {
    {"SIN", Fn::Builtin, "SIN"}, {"COS", Fn::Builtin, "COS"},   {"TAN", Fn::Builtin, "TAN"},
    {"ASIN", Fn::Builtin, "ASIN"}, {"ACOS", Fn::Builtin, "ACOS"}, {"ATAN", Fn::Builtin, "ATAN"},
    {"SQRT", Fn::Builtin, "SQRT"}, {"LN", Fn::Builtin, "LN"},     {"EXP", Fn::Builtin, "EXP"},
    {"ABS", Fn::Builtin, "ABS"},   {"INT", Fn::Builtin, "TRUNC"}, {"LOG", Fn::Log, nullptr},
    {"FRAC", Fn::Frac, nullptr},   {"NEG", Fn::Neg, nullptr},     {"SGN", Fn::Sgn, nullptr},
    {"SQ", Fn::Sq, nullptr},
};

ExprPtr applyFn(const FnRow &f, ExprPtr a, SourceLoc l) {
  switch (f.kind) {
  case Fn::Builtin: {
    std::vector<ExprPtr> args;
    args.push_back(std::move(a));
    return Expr::call(f.builtin, std::move(args), l);
  }
  case Fn::Log: {  // log10 = ln / ln 10
    std::vector<ExprPtr> args;
    args.push_back(std::move(a));
    return Expr::binary(OpCode::Div, Expr::call("LN", std::move(args), l), Expr::number(std::log(10.0), ir::Type::Real), l);
  }
  case Fn::Frac: {  // x - INT x
    std::vector<ExprPtr> args;
    args.push_back(a->clone());
    ExprPtr whole = Expr::call("TRUNC", std::move(args), l);
    return Expr::binary(OpCode::Sub, std::move(a), std::move(whole), l);
  }
  case Fn::Neg: return Expr::unary(OpCode::Neg, std::move(a), l);
  case Fn::Sgn: {  // (x > 0) - (x < 0)
    ExprPtr copy = a->clone();
    ExprPtr gt = Expr::binary(OpCode::Gt, std::move(copy), num(0), l);
    return Expr::binary(OpCode::Sub, std::move(gt), Expr::binary(OpCode::Lt, std::move(a), num(0), l), l);
  }
  case Fn::Sq: {
    ExprPtr copy = a->clone();
    return Expr::binary(OpCode::Mul, std::move(copy), std::move(a), l);
  }
  }
  return a;
}
}  // namespace

ExprPtr BlockParser::qParam() {
  const Token &w = tok();
  for (auto &q : kQ) {
    if (!w.isWord(q.prefix)) continue;
    const Token &n = peek();
    if (n.kind != Tok::Number || !n.isInt) {
      fail(n, fmt::format("{} needs a parameter number", q.prefix));
      return nullptr;
    }
    if (n.num > q.last) {
      fail(n, fmt::format("{}{} is out of range ({}0 to {}{})", q.prefix, n.text, q.prefix, q.prefix, q.last));
      return nullptr;
    }
    SourceLoc l = loc(w);
    i_ += 2;
    ExprPtr index = Expr::number(n.num, ir::Type::Int, l);
    if (std::string_view(q.prefix) == "QL") {
      f_.usesQL = true;
      return Expr::var(ir::VarSpace::Local, "QL", std::move(index), l);
    }
    return Expr::var(ir::VarSpace::QParam, q.prefix, std::move(index), l);
  }
  fail(w, "a Q parameter (Q, QL, QR) was expected");
  return nullptr;
}

bool BlockParser::isString(const Expr &e) { return e.kind == ir::ExprKind::Var && e.space == ir::VarSpace::QParam && e.str == "QS"; }

// A string formula (the value of QS n = …): strings in quotes and QS parameters joined by `||`.
// [K] The string functions (STRF, TOCHAR, SUBSTR, TONUMB, INSTR, STRLEN, STRCOMP) are not read yet.
ExprPtr BlockParser::stringFormula() {
  ExprPtr a;
  while (true) {
    const Token &t = tok();
    ExprPtr b;
    if (t.kind == Tok::String) {
      b = Expr::string(t.text, loc(t));
      ++i_;
    } else if (t.isWord("QS")) {
      if (!(b = qParam())) return nullptr;
    } else {
      fail(t, t.kind == Tok::Word ? fmt::format("the string function {} is not simulated yet", t.text)
                                  : "a string in quotes or a QS parameter was expected",
           t.kind == Tok::Word ? "unsupported-code" : "syntax");
      return nullptr;
    }
    a = a ? Expr::binary(OpCode::Concat, std::move(a), std::move(b), loc(t)) : std::move(b);
    if (!(tok().is("|") && peek().is("|"))) return a;
    i_ += 2;
  }
}

ExprPtr BlockParser::signedValue() {
  bool neg = false;
  SourceLoc l = loc();
  while (tok().is("+") || tok().is("-")) {
    neg = neg != tok().is("-");
    ++i_;
  }
  ExprPtr v;
  if (tok().kind == Tok::Number) {
    v = Expr::number(neg ? -tok().num : tok().num, tok().isInt ? ir::Type::Int : ir::Type::Real, l);
    ++i_;
    return v;
  }
  if (tok().isWord("QS")) {
    fail(tok(), "a string parameter (QS) cannot stand for a number");
    return nullptr;
  }
  if (tok().kind == Tok::Word && (tok().text == "Q" || tok().text == "QL" || tok().text == "QR")) {
    v = qParam();
    if (v && neg) v = Expr::unary(OpCode::Neg, std::move(v), l);
    return v;
  }
  fail(tok(), "a number or a Q parameter was expected");
  return nullptr;
}

ExprPtr BlockParser::formula() {
  ExprPtr a = term();
  while (a && (tok().is("+") || tok().is("-"))) {
    OpCode op = tok().is("+") ? OpCode::Add : OpCode::Sub;
    SourceLoc l = loc();
    ++i_;
    ExprPtr b = term();
    if (!b) return nullptr;
    a = Expr::binary(op, std::move(a), std::move(b), l);
  }
  return a;
}

ExprPtr BlockParser::term() {
  ExprPtr a = factor();
  while (a && (tok().is("*") || tok().is("/"))) {
    OpCode op = tok().is("*") ? OpCode::Mul : OpCode::Div;
    SourceLoc l = loc();
    ++i_;
    ExprPtr b = factor();
    if (!b) return nullptr;
    a = Expr::binary(op, std::move(a), std::move(b), l);
  }
  return a;
}

ExprPtr BlockParser::factor() {
  ExprPtr a = unary();
  if (a && tok().is("^")) {  // right-associative: 2^3^2 = 2^9
    SourceLoc l = loc();
    ++i_;
    ExprPtr b = factor();
    if (!b) return nullptr;
    a = Expr::binary(OpCode::Pow, std::move(a), std::move(b), l);
  }
  return a;
}

ExprPtr BlockParser::unary() {
  if (tok().is("+") || tok().is("-")) {
    bool neg = tok().is("-");
    SourceLoc l = loc();
    ++i_;
    ExprPtr a = unary();
    if (!a) return nullptr;
    return neg ? Expr::unary(OpCode::Neg, std::move(a), l) : std::move(a);
  }
  if (tok().kind == Tok::Word)
    for (auto &f : kFns)
      if (tok().text == f.name) {  // SIN 30 and SIN(30) alike
        SourceLoc l = loc();
        ++i_;
        ExprPtr a = unary();
        if (!a) return nullptr;
        return applyFn(f, std::move(a), l);
      }
  return primary();
}

ExprPtr BlockParser::primary() {
  const Token &t = tok();
  if (t.kind == Tok::Number) {
    ++i_;
    return Expr::number(t.num, t.isInt ? ir::Type::Int : ir::Type::Real, loc(t));
  }
  if (t.is("(")) {
    ++i_;
    ExprPtr a = formula();
    if (!a) return nullptr;
    if (!tok().is(")")) {
      fail(tok(), "')' expected");
      return nullptr;
    }
    ++i_;
    return a;
  }
  if (t.isWord("PI")) {
    ++i_;
    return Expr::number(M_PI, ir::Type::Real, loc(t));
  }
  if (t.kind == Tok::Word && (t.text == "Q" || t.text == "QL" || t.text == "QR")) return qParam();
  if (t.isWord("QS") || t.kind == Tok::String) fail(t, "a string cannot stand in a numeric formula");
  else if (t.kind == Tok::End) fail(t, "the formula ends early");
  else fail(t, fmt::format("'{}' cannot stand in a formula", t.text));
  return nullptr;
}

}  // namespace ncc::hei
