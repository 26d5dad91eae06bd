// Operator semantics on run-time values (ir/Value.h rules), shared by the eval engine and the
// constant folder so both give the same numbers.
#pragma once
#include "ir/Arith.h"
#include "ir/NCIR.h"
#include "ir/Value.h"

namespace ncc {

enum class OpStatus { Ok, DivByZero, NotNumeric, NotInteger };

inline OpStatus applyBinary(ir::OpCode op, double a, double b, double &r) {
  using ir::OpCode;
  switch (op) {
  case OpCode::Add: r = num(a) + num(b); return OpStatus::Ok;
  case OpCode::Sub: r = num(a) - num(b); return OpStatus::Ok;
  case OpCode::Mul: r = num(a) * num(b); return OpStatus::Ok;
  case OpCode::Div:
    if (num(b) == 0) return OpStatus::DivByZero;
    r = num(a) / num(b);
    return OpStatus::Ok;
  case OpCode::IDiv:
    if (num(b) == 0) return OpStatus::DivByZero;
    r = arithIDiv(num(a), num(b));
    return OpStatus::Ok;
  case OpCode::Mod:
    if (num(b) == 0) return OpStatus::DivByZero;
    r = arithMod(num(a), num(b));
    return OpStatus::Ok;
  case OpCode::Pow: r = arithPow(num(a), num(b)); return OpStatus::Ok;
  case OpCode::Eq: r = valueEq(a, b); return OpStatus::Ok;
  case OpCode::Ne: r = 1.0 - valueEq(a, b); return OpStatus::Ok;
  case OpCode::Lt: r = num(a) < num(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::Le: r = num(a) <= num(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::Gt: r = num(a) > num(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::Ge: r = num(a) >= num(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::And: r = truthy(a) && truthy(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::Or: r = truthy(a) || truthy(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::Xor: r = truthy(a) != truthy(b) ? 1.0 : 0.0; return OpStatus::Ok;
  case OpCode::BAnd:
  case OpCode::BOr:
  case OpCode::BXor:
    r = arithBitwise((int)op - (int)OpCode::BAnd, a, b);
    return std::isnan(r) ? OpStatus::NotInteger : OpStatus::Ok;
  default: return OpStatus::NotNumeric;
  }
}

inline OpStatus applyUnary(ir::OpCode op, double a, double &r) {
  if (op == ir::OpCode::Neg) r = -num(a);
  else if (op == ir::OpCode::Not) r = truthy(a) ? 0.0 : 1.0;
  else return OpStatus::NotNumeric;
  return OpStatus::Ok;
}

}  // namespace ncc
