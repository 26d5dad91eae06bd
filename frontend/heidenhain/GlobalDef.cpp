// The values of cycle parameter lines beside numbers (docs/HEIDENHAIN.md "Cycle parameter
// values"): FAUTO, FMAX, FU, FZ where the manual's parameter text allows them, PREDEF (the value
// of the GLOBAL DEF group that has the parameter, L1048-L1058) and QS strings; and the GLOBAL DEF
// blocks that give the PREDEF values (L948-L1158).
#include "frontend/heidenhain/Parser.h"
#include "ir/CycleFeed.h"
#include "ir/WordList.h"

#include <fmt/format.h>


namespace ncc::hei {

namespace {
// The GLOBAL DEF groups (L1073-L1158). The manual names the groups and describes their values;
// the block numbers and parameter numbers are the control's (general Klartext knowledge: TNC
// 640 user's manual, cycle programming), each parameter the one the cycles have for that value.
// A parameter belongs to one group, so PREDEF of Qn reads the group that has Qn.
struct GlobalGroup {
  int number;
  const char *title;
  const char *params;
};
constexpr GlobalGroup kGroups[] = {
    {100, "GENERAL", "Q200 Q204 Q253 Q208"},    // set-up clearance, 2nd set-up clearance, F positioning, F retract
    {105, "DRILLING", "Q256 Q211 Q210"},       // chip-breaking retraction, dwell at the bottom, at the top
    {110, "POCKET MILLING", "Q370 Q351 Q366"},  // overlap factor, climb/up-cut, plunging strategy
    {111, "CONTOUR MILLING", "Q2 Q6 Q7 Q9"},   // overlap, set-up clearance, clearance height, direction
    {120, "PROBING", "Q320 Q260 Q301"},         // set-up clearance, clearance height, move to clearance height
    {125, "POSITIONING", "Q345"},               // CYCL CALL PAT between the points (Patterns.cpp)
};


const GlobalGroup *groupOf(const std::string &q) {
  for (const GlobalGroup &g : kGroups)
    if (inWordList(g.params, q)) return &g;
  return nullptr;
}

// The value no GLOBAL DEF has given yet (PREDEF of it stops the run).
constexpr double kUnset = -1e99;

enum Keyword : unsigned { kwFmax = 1, kwFauto = 2, kwFu = 4, kwFz = 8 };
// The feed keywords each parameter's text allows (the first row that matches; cycles null: every
// cycle): Q206 L1842 … L7718, Q207 L4782 … L6001, Q208 L2234 and L9519, Q253 L2703 and L4760,
// Q254 L2707, Q385 L6118, Q512 L4789, Q11/Q12/Q19 L9359 … L9513, Q396 L23908.
struct KeywordRule {
  const char *q;
  const char *cycles;
  unsigned allowed;
};
constexpr KeywordRule kKeywords[] = {
    {"Q206", "256 257", kwFmax | kwFauto | kwFu | kwFz},
    {"Q206", "208 251 252 253 254 258 275", kwFauto | kwFu | kwFz},
    {"Q206", nullptr, kwFauto | kwFu},
    {"Q207", "262 263 264 265 267", kwFauto},
    {"Q207", nullptr, kwFauto | kwFu | kwFz},
    {"Q208", nullptr, kwFmax | kwFauto},
    {"Q253", nullptr, kwFmax | kwFauto},
    {"Q254", nullptr, kwFauto | kwFu},
    {"Q385", nullptr, kwFauto | kwFu | kwFz},
    {"Q512", nullptr, kwFauto},
    {"Q11", nullptr, kwFauto | kwFu | kwFz},
    {"Q12", nullptr, kwFauto | kwFu | kwFz},
    {"Q19", nullptr, kwFauto | kwFu | kwFz},
    {"Q396", nullptr, kwFmax | kwFauto},
};

unsigned keywordsOf(int cycle, const std::string &q) {
  for (const KeywordRule &r : kKeywords)
    if (q == r.q && (!r.cycles || inWordList(r.cycles, std::to_string(cycle)))) return r.allowed;
  return 0;
}

std::string keywordList(unsigned allowed) {
  std::string s = "a number";
  static const std::pair<Keyword, const char *> kNames[] = {{kwFmax, "FMAX"}, {kwFauto, "FAUTO"}, {kwFu, "FU"}, {kwFz, "FZ"}};
  for (auto [k, name] : kNames)
    if (allowed & k) s += std::string(", ") + name;
  return s;
}
}  // namespace

std::string globalDefVar(const std::string &q) { return "_HEI_GD_" + q; }
double globalDefUnset() { return kUnset; }

bool BlockParser::cycleValue(int cycle, const std::string &name, CycleValue &v, bool emit) {
  const Token &t = tok();
  v.at = loc(t);
  if (t.kind == Tok::String) {
    v.kind = CycleValue::Text;
    v.text = t.text;
    ++i_;
    return true;
  }
  if (t.isWord("PREDEF")) {
    const GlobalGroup *g = groupOf(name);
    if (!g || g->number == 125) {
      std::string groups;
      for (const GlobalGroup &k : kGroups)
        if (k.number != 125) groups += fmt::format("{}{}: {}", groups.empty() ? "" : ", ", k.number, k.params);
      return fail(t, fmt::format("{}=PREDEF: no GLOBAL DEF group has {} ({})", name, name, groups), "cycle-parameter");
    }
    ++i_;
    v.kind = CycleValue::Predef;
    std::string var = globalDefVar(name);
    f_.pp.globalDefVars.insert(var);
    v.value = Expr::var(ir::VarSpace::Global, var, nullptr, v.at);
    if (!emit) return true;
    // Given by a GLOBAL DEF that ran before this definition, else the run stops here.
    Op check(OpKind::If, v.at);
    check.set("cond", Expr::binary(OpCode::Eq, v.value->clone(), Expr::number(kUnset, ir::Type::Real), v.at));
    check.regions.emplace_back();
    Op stop(OpKind::Message, v.at);
    stop.set("text", Expr::string(fmt::format("{}=PREDEF: no GLOBAL DEF {} {} before this cycle gives {}", name, g->number,
                                              g->title, name),
                                  v.at));
    stop.set("kind", Expr::symbol("abort"));
    check.regions[0].push_back(std::move(stop));
    out().push_back(std::move(check));
    return true;
  }
  static const std::pair<const char *, Keyword> kWords[] = {{"FMAX", kwFmax}, {"FAUTO", kwFauto}, {"FU", kwFu}, {"FZ", kwFz}};
  for (auto [word, k] : kWords) {
    if (!t.isWord(word)) continue;
    const unsigned allowed = keywordsOf(cycle, name);
    if (!(allowed & k))
      return fail(t, fmt::format("{} of cycle {} takes {}, not {}", name, cycle, keywordList(allowed), word), "cycle-parameter");
    ++i_;
    if (k == kwFmax) {
      v.kind = CycleValue::Fmax;
      v.value = num(cyclefeed::kRapid, v.at);
    } else if (k == kwFauto) {  // the feed of the last TOOL CALL, taken now (L570)
      v.kind = CycleValue::Fauto;
      f_.pp.fauto = true;
      v.value = hglobal(kFauto, v.at);
    } else {  // FU 0.2, FZ 0.05: the executor converts them where the cycle runs (ir/CycleFeed.h)
      const Token &at = tok();
      ExprPtr f = signedValue();
      if (!f) return false;
      if (f->kind == ir::ExprKind::Number && !(f->num > 0 && f->num < cyclefeed::kBand))
        return fail(at, fmt::format("{} takes a feed per {} greater than 0", word, k == kwFu ? "revolution" : "tooth"),
                    "cycle-parameter");
      v.kind = k == kwFu ? CycleValue::PerRev : CycleValue::PerTooth;
      v.value = Expr::binary(OpCode::Sub, num(k == kwFu ? cyclefeed::kPerRev : cyclefeed::kPerTooth, v.at), std::move(f), v.at);
    }
    return true;
  }
  v.kind = CycleValue::Number;
  v.value = signedValue();
  return v.value != nullptr;
}

// GLOBAL DEF n <title> with its parameter lines: each value holds for the rest of the run (in the
// programs it calls too) until a GLOBAL DEF gives that parameter again [model]. 125 POSITIONING's
// Q345 (L3867-L3871; the text calls it Q352, L1273: the example's Q345 is the parameter's name on
// the control) makes CYCL CALL PAT move between the positions at the cycle's 2nd set-up clearance.
bool BlockParser::globalDef() {
  if (!expectWord("DEF")) return false;
  const Token &n = tok();
  const GlobalGroup *g = nullptr;
  for (const GlobalGroup &k : kGroups)
    if (n.kind == Tok::Number && n.isInt && n.num == k.number) g = &k;
  if (!g)
    return fail(n, fmt::format("GLOBAL DEF {}: the groups are 100 GENERAL, 105 DRILLING, 110 POCKET MILLING, 111 CONTOUR "
                               "MILLING, 120 PROBING and 125 POSITIONING",
                               n.text),
                "cycle-invalid");
  ++i_;
  while (!atEnd() && tok().line == n.line) ++i_;  // the title
  std::set<std::string> seen;
  const std::string block = fmt::format("GLOBAL DEF {} {}", g->number, g->title);
  while (!atEnd()) {
    const Token &q = tok();
    std::string name;
    if (!cycleParamName(g->number, seen, name, "GLOBAL DEF")) return false;
    if (!inWordList(g->params, name))
      return fail(q, fmt::format("{} is not a parameter of {} ({})", name, block, g->params), "cycle-parameter");
    CycleValue v;
    if (!cycleValue(g->number, name, v, true)) return false;
    if (v.kind == CycleValue::Text || v.kind == CycleValue::Predef)
      return f_.error(v.at, fmt::format("{} of {} takes a number", name, block), "cycle-parameter");
    if (g->number == 125) {
      f_.pp.global125 = true;
      out().push_back(assignOp(hglobal(kGlobal125, loc(q)), std::move(v.value), loc(q)));
      continue;
    }
    std::string var = globalDefVar(name);
    f_.pp.globalDefVars.insert(var);
    out().push_back(assignOp(Expr::var(ir::VarSpace::Global, var, nullptr, loc(q)), std::move(v.value), loc(q)));
  }
  if (seen.empty()) return fail(n, fmt::format("{} needs its parameter lines ({})", block, g->params), "cycle-parameter");
  return true;
}

}  // namespace ncc::hei
