#include "ir/Strings.h"
#include "ir/NCIR.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

ValuePool::ValuePool() {
  strings_.emplace_back();
  index_.emplace(std::string_view(strings_.back()), 0);
}

bool ValuePool::intern(std::string_view s, double &out, std::string &error) {
  auto it = index_.find(s);
  if (it != index_.end()) {
    out = bitsValue(kStringTag | it->second);
    return true;
  }
  if (s.size() > kMaxStringBytes) {
    error = fmt::format("string of {} bytes exceeds the limit of {} bytes", s.size(), kMaxStringBytes);
    return false;
  }
  if (strings_.size() >= kMaxPoolStrings || bytes_ + s.size() > kMaxPoolBytes) {
    error = poolLimitMessage();
    return false;
  }
  uint32_t i = (uint32_t)strings_.size();
  strings_.emplace_back(s);
  bytes_ += s.size();
  index_.emplace(std::string_view(strings_.back()), i);
  out = bitsValue(kStringTag | i);
  return true;
}

std::string_view ValuePool::text(double v) const {
  if (!isString(v)) return {};
  uint64_t i = valueBits(v) & ~kStringTagMask;
  return i < strings_.size() ? std::string_view(strings_[i]) : std::string_view();
}

std::string poolLimitMessage() {
  return fmt::format("string pool limit exceeded: more than {} distinct strings or {} bytes in one run",
                     kMaxPoolStrings, kMaxPoolBytes);
}

std::string valueText(const ValuePool &pool, double v, bool fixed) {
  if (isString(v)) return std::string(pool.text(v));
  if (isFrame(v)) return frameText(pool.frames.get(v));
  return fixed ? fixedNumberText(v) : numberText(v);
}

static const char *const kValueTypeNames[] = {"any", "real", "int", "bool", "char", "string", "axis", "frame"};

bool valueTypeFromName(std::string_view n, ValueType &out) {
  for (unsigned i = 1; i < sizeof kValueTypeNames / sizeof *kValueTypeNames; ++i)
    if (n == kValueTypeNames[i]) {
      out = (ValueType)i;
      return true;
    }
  return false;
}
const char *valueTypeName(ValueType t) {
  unsigned i = (unsigned)t;
  return i < sizeof kValueTypeNames / sizeof *kValueTypeNames ? kValueTypeNames[i] : "?";
}

double initialValue(ValueType t) {
  return t == ValueType::Frame ? identityFrame() : holdsHandle(t) ? emptyString() : 0.0;
}

bool convertForStore(ValuePool &pool, ValueType t, uint32_t len, std::string_view name, double v, double &out,
                     std::string &error) {
  bool str = isString(v);
  auto mismatch = [&](const char *what) {
    error = fmt::format("cannot assign {} to {} variable '{}'", what, valueTypeName(t), name);
    return false;
  };
  if (t == ValueType::Frame || isFrame(v)) {
    if (t != ValueType::Frame && t != ValueType::Any) return mismatch("a frame");
    if (!isFrame(v)) return mismatch(str ? "a string" : "a number");
    out = v;
    return true;
  }
  switch (t) {
  case ValueType::Any: out = v; return true;
  case ValueType::Frame: break;  // above
  case ValueType::Real:
    if (str) return mismatch("a string");
    out = v;
    return true;
  case ValueType::Int: {
    if (str) return mismatch("a string");
    double r = std::round(num(v));
    if (!(r >= -2147483648.0 && r <= 2147483647.0)) {
      error = fmt::format("value {} is out of the range of int variable '{}'", numberText(num(v)), name);
      return false;
    }
    out = r;
    return true;
  }
  case ValueType::Bool:
    out = str ? (pool.text(v).empty() ? 0.0 : 1.0) : (truthy(v) ? 1.0 : 0.0);
    return true;
  case ValueType::Char: {
    if (str) {
      if (pool.text(v).size() > 1) return mismatch("a string of more than one character");
      out = v;
      return true;
    }
    double r = std::round(num(v));
    if (!(r >= 0 && r <= 255)) {
      error = fmt::format("value {} is not a character code 0..255 for char variable '{}'", numberText(num(v)), name);
      return false;
    }
    char c = (char)(unsigned char)r;
    return pool.intern(r == 0 ? std::string_view() : std::string_view(&c, 1), out, error);
  }
  case ValueType::String:
  case ValueType::Axis:
    if (!str) return mismatch("a number");
    if (t == ValueType::String && pool.text(v).size() > len) {
      error = fmt::format("string of {} characters does not fit string[{}] variable '{}'", pool.text(v).size(), len,
                          name);
      return false;
    }
    out = v;
    return true;
  }
  return mismatch("a value");
}

bool compareStrings(const ValuePool &pool, int op, double a, double b, double &out, std::string &error) {
  if (isFrame(a) || isFrame(b)) {  // frames have no order and no equality operator
    error = handleMessage(HandleUse::Operator, "frame", ir::opCodeName((ir::OpCode)((int)ir::OpCode::Eq + op)));
    return false;
  }
  if (!isString(a) || !isString(b)) {
    error = "cannot compare a string with a number";
    return false;
  }
  int c = pool.text(a).compare(pool.text(b));
  bool r = false;
  switch (op) {
  case 0: r = c == 0; break;
  case 1: r = c != 0; break;
  case 2: r = c < 0; break;
  case 3: r = c <= 0; break;
  case 4: r = c > 0; break;
  case 5: r = c >= 0; break;
  }
  out = r ? 1.0 : 0.0;
  return true;
}

std::string handleMessage(HandleUse use, std::string_view kind, std::string_view name) {
  switch (use) {
  case HandleUse::Operator: return fmt::format("operator '{}' needs numbers, found a {}", name, kind);
  case HandleUse::Builtin: return fmt::format("'{}' needs numbers, found a {}", name, kind);
  case HandleUse::AsNumber: return fmt::format("a {} is used where a number is needed", kind);
  case HandleUse::InParameter: return fmt::format("a {} cannot be stored in a numeric parameter", kind);
  }
  return {};
}
const char *handleKind(double v) { return isString(v) ? "string" : isFrame(v) ? "frame" : "number"; }

std::string arrayIndexMessage(std::string_view name, double index) {
  return declaredIndexMessage(name, index, 1, 1, kArrayElements);
}

std::string declaredIndexMessage(std::string_view name, double index, unsigned dim, unsigned rank, uint32_t extent) {
  if (rank <= 1)
    return fmt::format("index {} of array '{}' is not an integer in 0..{}", numberText(index), name, extent - 1);
  return fmt::format("index {} (dimension {}) of array '{}' is not an integer in 0..{}", numberText(index), dim, name,
                     extent - 1);
}

}  // namespace ncc
