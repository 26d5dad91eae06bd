#include "passes/CycleOp.h"
#include "ir/OpSymbols.h"

#include <fmt/format.h>

namespace ncc {
using namespace ir;

static size_t paramCount(const CycleDef *d) { return d ? cycleParamNames(*d).size() : 0; }

Word cycleArgWord(const CycleOpShape &shape, bool ofPattern, int index) {
  return (Word)(index + (ofPattern ? (int)paramCount(shape.entry) : 0));
}

bool resolveCycleOp(const Op &op, CycleOpShape &out, std::string &err) {
  out = {};
  if (const Expr *a = op.get("action")) {
    uint8_t code;
    if (!opSymbolCode(OpKind::Cycle, "action", a->str, code)) {
      err = "'cycle' argument 'action' must be one of: " + opSymbolValues(OpKind::Cycle, "action");
      return false;
    }
    out.action = (CycleAction)code;
  }
  auto find = [&](const char *key, const CycleDef *&def, bool positions) {
    const Expr *e = op.get(key);
    if (!e) return true;
    def = findCycle(e->str);
    if (!def) err = fmt::format("'{}' is not an entry of the cycle library (ncc cycle --list)", e->str);
    else if (positions != !!def->positions)
      err = fmt::format("'{}' is {}: give it as {}=", e->str, positions ? "a machining cycle" : "a position pattern",
                        positions ? "entry" : "pattern");
    else return true;
    def = nullptr;
    return false;
  };
  if (!find("entry", out.entry, false) || !find("pattern", out.pattern, true)) return false;
  if (paramCount(out.entry) + paramCount(out.pattern) > (size_t)kCycleArgSlots) {
    err = fmt::format("'{}' with '{}' has more parameters than a command holds ({})", out.entry->name,
                      out.pattern->name, kCycleArgSlots);
    return false;
  }
  for (auto &a : op.args) {
    bool ofPattern = a.key.rfind("p.", 0) == 0;
    if (!ofPattern && a.key.rfind("a.", 0) != 0) continue;
    const CycleDef *def = ofPattern ? out.pattern : out.entry;
    std::string_view name = std::string_view(a.key).substr(2);
    if (!def) continue;  // the verifier reports an argument without its entry
    int index = cycleParamIndex(*def, name);
    if (index < 0) {
      err = fmt::format("{} has no parameter {} (it has: {})", def->name, name, def->params);
      return false;
    }
    if (a.value && a.value->kind == ExprKind::String) {
      std::string_view strings = def->strings ? def->strings : "";
      if (strings.find(name) == std::string_view::npos) {
        err = fmt::format("{} parameter {} takes a number, not a string", def->name, name);
        return false;
      }
      if (out.textWord >= 0) {
        err = fmt::format("{}: only one STRING argument is supported ({} is the second)", def->name, name);
        return false;
      }
      out.textWord = (int)cycleArgWord(out, ofPattern, index);
    }
  }
  return true;
}

}  // namespace ncc
