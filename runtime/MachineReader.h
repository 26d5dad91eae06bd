// The machine-description reader's machinery (runtime/Machine.cpp holds the schema): the error
// context, the key tables (a key sets a struct field or calls a reader), the typed value readers
// and the table walkers. Internal to runtime/Machine*.cpp.
#pragma once

#include "runtime/Geometry.h"
#include "runtime/Machine.h"

#include <toml++/toml.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace ncc::machine_reader {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Ctx {
  std::vector<MachineError> problems;
  void error(const toml::source_region &at, const std::string &msg) {
    // Implicit tables (the [axes] of [axes.X]) have no position: report them at the start.
    problems.push_back({std::max<uint32_t>(at.begin.line, 1), std::max<uint32_t>(at.begin.column, 1), msg});
  }
};

using NodeReader = void (*)(Ctx &, const toml::node &, void *obj);

// What a key sets: a field of the table's struct (its type decides the TOML type expected), or a
// reader for structured values.
template <class T>
using Field = std::variant<double T::*, int T::*, std::string T::*, bool T::*, AxisVec T::*, Vec3 T::*,
                           std::vector<std::string> T::*, NodeReader>;

template <class T> struct KeyDef {
  const char *key;
  Field<T> field;
  double lo = -kInf, hi = kInf;  // numbers: allowed range
  bool loOpen = false;           // lo itself is excluded
  const char *choices = nullptr; // strings: the allowed values, blank-separated
  bool required = false;
};

std::string typeName(const toml::node &n);
std::string num(double d);  // shortest text of a number, for messages
bool isChoice(const char *choices, const std::string &v);
std::string choiceList(const char *choices);
std::optional<double> readNumber(Ctx &c, const toml::node &n, const std::string &key);
std::optional<std::string> readString(Ctx &c, const toml::node &n, const std::string &key, const char *choices);
// [x, y, z (, a, b, c (, u, v, w))] into out; out is unchanged after a problem.
void readAxisVec(Ctx &c, const toml::node &n, const std::string &key, AxisVec &out);
// [x, y, z] into out; out is unchanged after a problem.
bool readVec3(Ctx &c, const toml::node &n, const std::string &key, Vec3 &out);
// A direction: a unit vector, within 1e-4, then normalised.
bool readUnitVec(Ctx &c, const toml::node &n, const std::string &key, Vec3 &out);

// Sets one key's field, or reports why not.
template <class T> void apply(Ctx &c, const KeyDef<T> &def, const toml::node &n, T &obj) {
  const std::string key = def.key;
  auto inRange = [&](double d) {
    if ((def.loOpen ? d > def.lo : d >= def.lo) && d <= def.hi) return true;
    std::string want = def.hi < kInf ? num(def.lo) + ".." + num(def.hi) : (def.loOpen ? "> " : ">= ") + num(def.lo);
    c.error(n.source(), key + ": must be " + want + ", got " + num(d));
    return false;
  };
  std::visit(
      [&](auto field) {
        using F = decltype(field);
        if constexpr (std::is_same_v<F, NodeReader>) {
          field(c, n, &obj);
        } else if constexpr (std::is_same_v<F, double T::*>) {
          if (auto d = readNumber(c, n, key); d && inRange(*d)) obj.*field = *d;
        } else if constexpr (std::is_same_v<F, int T::*>) {
          if (!n.is_integer()) return c.error(n.source(), key + ": expected an integer, got " + typeName(n));
          double d = (double)**n.as_integer();
          if (inRange(d)) obj.*field = (int)d;
        } else if constexpr (std::is_same_v<F, std::string T::*>) {
          if (auto s = readString(c, n, key, def.choices)) obj.*field = *s;
        } else if constexpr (std::is_same_v<F, bool T::*>) {
          if (!n.is_boolean()) return c.error(n.source(), key + ": expected true or false, got " + typeName(n));
          obj.*field = **n.as_boolean();
        } else if constexpr (std::is_same_v<F, AxisVec T::*>) {
          readAxisVec(c, n, key, obj.*field);
        } else if constexpr (std::is_same_v<F, Vec3 T::*>) {
          readVec3(c, n, key, obj.*field);
        } else {  // list of strings
          const toml::array *a = n.as_array();
          if (!a) return c.error(n.source(), key + ": expected an array of strings, got " + typeName(n));
          std::vector<std::string> v;
          for (const toml::node &e : *a)
            if (auto s = readString(c, e, key, def.choices)) v.push_back(*s);
          obj.*field = v;
        }
      },
      def.field);
}

// Reads table t into obj by the key table; unknown keys and missing required keys are errors.
template <class T, size_t N>
bool readTable(Ctx &c, const toml::node &node, const std::string &where, const KeyDef<T> (&keys)[N], T &obj) {
  const toml::table *t = node.as_table();
  if (!t) {
    c.error(node.source(), where + ": expected a table, got " + typeName(node));
    return false;
  }
  size_t before = c.problems.size();
  for (auto &&[k, v] : *t) {
    auto def = std::find_if(std::begin(keys), std::end(keys), [&](auto &d) { return k.str() == d.key; });
    if (def == std::end(keys))
      c.error(k.source(), "unknown key '" + std::string(k.str()) + "' in " + where);
    else
      apply(c, *def, v, obj);
  }
  for (auto &d : keys)
    if (d.required && !t->contains(d.key)) c.error(t->source(), where + " needs '" + d.key + "'");
  return c.problems.size() == before;
}

// The entries of a table value: f(key text, key, value) for each; `expected` (", got <type>"
// added) when the value is no table.
template <class F> void forEachEntry(Ctx &c, const toml::node &n, const std::string &expected, F f) {
  const toml::table *t = n.as_table();
  if (!t) return c.error(n.source(), expected + ", got " + typeName(n));
  for (auto &&[k, v] : *t) f(std::string(k.str()), k, v);
}

// A table of named tables ([axes.X], [emit.iso]): f(name, key, value) for each.
template <class F> void forEachNamed(Ctx &c, const toml::node &n, const std::string &what, F f) {
  forEachEntry(c, n, what + ": expected tables [" + what + ".NAME]", f);
}

}  // namespace ncc::machine_reader
