// The typed value readers of the machine description (runtime/MachineReader.h).
#include "runtime/MachineReader.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace ncc::machine_reader {

std::string typeName(const toml::node &n) {
  switch (n.type()) {
  case toml::node_type::table: return "a table";
  case toml::node_type::array: return "an array";
  case toml::node_type::string: return "a string";
  case toml::node_type::integer: return "an integer";
  case toml::node_type::floating_point: return "a floating-point number";
  case toml::node_type::boolean: return "a boolean";
  default: return "a date or time";
  }
}

std::string num(double d) {
  if (d == std::floor(d) && std::fabs(d) < 1e15) return std::to_string((long long)d);
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, r.ptr);
}

bool isChoice(const char *choices, const std::string &v) {
  std::istringstream in(choices);
  std::string w;
  while (in >> w)
    if (w == v) return true;
  return false;
}

std::string choiceList(const char *choices) {
  std::istringstream in(choices);
  std::string w, out;
  while (in >> w) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::optional<double> readNumber(Ctx &c, const toml::node &n, const std::string &key) {
  if (auto d = n.value<double>(); d && (n.is_integer() || n.is_floating_point()) && std::isfinite(*d)) return d;
  c.error(n.source(), key + ": expected a number, got " + typeName(n));
  return std::nullopt;
}

std::optional<std::string> readString(Ctx &c, const toml::node &n, const std::string &key, const char *choices) {
  if (!n.is_string()) {
    c.error(n.source(), key + ": expected a string, got " + typeName(n));
    return std::nullopt;
  }
  std::string v = **n.as_string();
  if (choices && !isChoice(choices, v)) {
    c.error(n.source(), key + ": '" + v + "' is not one of " + choiceList(choices));
    return std::nullopt;
  }
  return v;
}

// [x, y, z (, a, b, c (, u, v, w))] into out; out is unchanged after a problem. Not inlined: GCC's bounds
// check otherwise warns about the instantiations for structs without an AxisVec member.
[[gnu::noinline]] void readAxisVec(Ctx &c, const toml::node &n, const std::string &key, AxisVec &out) {
  // An unquoted g59.1 is a dotted key (table g59, key 1): say how to write it.
  if (n.is_table())
    return c.error(n.source(), key + ": expected an array, got a table (quote keys with a dot: \"" + key + ".1\")");
  const toml::array *a = n.as_array();
  if (!a || a->size() < 3 || a->size() > (size_t)kAxes)
    return c.error(n.source(), key + ": expected an array of 3 to 9 numbers [x, y, z, a, b, c, u, v, w], got " +
                                   (a ? std::to_string(a->size()) + " elements" : typeName(n)));
  AxisVec v{};
  for (size_t i = 0; i < a->size(); ++i) {
    auto d = readNumber(c, *a->get(i), key + "[" + std::to_string(i) + "]");
    if (!d) return;
    v[i] = *d;
  }
  out = v;
}

// [x, y, z] into out; out is unchanged after a problem.
[[gnu::noinline]] bool readVec3(Ctx &c, const toml::node &n, const std::string &key, Vec3 &out) {
  const toml::array *a = n.as_array();
  if (!a || a->size() != 3) {
    c.error(n.source(), key + ": expected an array of 3 numbers [x, y, z], got " +
                            (a ? std::to_string(a->size()) + " elements" : typeName(n)));
    return false;
  }
  Vec3 v{};
  for (size_t i = 0; i < 3; ++i) {
    auto d = readNumber(c, *a->get(i), key + "[" + std::to_string(i) + "]");
    if (!d) return false;
    v[i] = *d;
  }
  out = v;
  return true;
}

// A direction: a unit vector, within 1e-4 (so 0.7071 passes for sin 45), then normalised.
bool readUnitVec(Ctx &c, const toml::node &n, const std::string &key, Vec3 &out) {
  Vec3 v;
  if (!readVec3(c, n, key, v)) return false;
  double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (len == 0) c.error(n.source(), key + ": the zero vector has no direction");
  else if (std::fabs(len - 1) > 1e-4) c.error(n.source(), key + ": expected a unit vector, its length is " + num(len));
  else {
    for (int i = 0; i < 3; ++i) out[i] = v[i] / len;
    return true;
  }
  return false;
}

}  // namespace ncc::machine_reader
