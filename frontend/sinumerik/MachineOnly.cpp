// Machine-specific constructs (seed000a: synchronized actions, channel coordination, interrupts,
// axis exchange, couplings, oscillation, positioning axes …): the front end parses and checks
// them so `ncc lint` accepts a program that uses them and reports their syntax errors; they
// lower to `message kind=not_simulated`, which stops `ncc run` at the block with the construct's
// name (docs/SINUMERIK.md "Machine-specific constructs"). Which names these are, and their class,
// is the table below (names and meanings from the operator table sinumerik-operators.tsv).
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

namespace {
struct MachineConstruct {
  const char *name;
  const char *what;  // the class named in the diagnostic
};

constexpr const char *kSync = "synchronized action";
constexpr const char *kChannel = "channel coordination";
constexpr const char *kInterrupt = "interrupt routine";
constexpr const char *kAxisExchange = "axis exchange";
constexpr const char *kCoupling = "axis coupling";
constexpr const char *kOscillation = "oscillation";
constexpr const char *kPositioning = "positioning axis or spindle";
constexpr const char *kMeasuring = "measuring";

const MachineConstruct kConstructs[] = {
    {"ID", kSync},           {"IDS", kSync},           {"WHEN", kSync},          {"WHENEVER", kSync},
    {"FROM", kSync},         {"EVERY", kSync},         {"DO", kSync},            {"CANCEL", kSync},
    {"LOCK", kSync},         {"UNLOCK", kSync},        {"RESET", kSync},
    {"INIT", kChannel},      {"START", kChannel},      {"WAITM", kChannel},      {"WAITMC", kChannel},
    {"WAITE", kChannel},     {"SETM", kChannel},       {"CLEARM", kChannel},
    {"SETINT", kInterrupt},  {"CLRINT", kInterrupt},   {"ENABLE", kInterrupt},   {"DISABLE", kInterrupt},
    {"PRIO", kInterrupt},    {"BLSYNC", kInterrupt},   {"LIFTFAST", kInterrupt}, {"ALF", kInterrupt},
    {"RELEASE", kAxisExchange}, {"GET", kAxisExchange}, {"GETD", kAxisExchange}, {"AXTOCHAN", kAxisExchange},
    {"NEWCONF", kAxisExchange},
    {"TRAILON", kCoupling},  {"TRAILOF", kCoupling},   {"LEADON", kCoupling},    {"LEADOF", kCoupling},
    {"CTABDEF", kCoupling},  {"CTABEND", kCoupling},   {"CTABDEL", kCoupling},   {"EGDEF", kCoupling},
    {"EGON", kCoupling},     {"EGONSYN", kCoupling},   {"EGONSYNE", kCoupling},  {"EGOFS", kCoupling},
    {"EGOFC", kCoupling},    {"EGDEL", kCoupling},     {"COUPDEF", kCoupling},   {"COUPON", kCoupling},
    {"COUPONC", kCoupling},  {"COUPOF", kCoupling},    {"COUPOFS", kCoupling},   {"COUPDEL", kCoupling},
    {"COUPRES", kCoupling},
    {"OSCILL", kOscillation}, {"OS", kOscillation},    {"OSP1", kOscillation},   {"OSP2", kOscillation},
    {"OST1", kOscillation},  {"OST2", kOscillation},   {"OSE", kOscillation},    {"OSNSC", kOscillation},
    {"OSCTRL", kOscillation}, {"OSB", kOscillation},
    {"POS", kPositioning},   {"POSA", kPositioning},   {"SPOSA", kPositioning},
    {"WAITP", kPositioning}, {"WAITS", kPositioning},
    {"MEAS", kMeasuring},    {"MEAW", kMeasuring},     {"MEASA", kMeasuring},    {"MEAWA", kMeasuring},
};

// G codes of the operator table that belong to machine functions (by G group): a block with one
// is kept and stops a run like the constructs above. The repositioning modes (groups 26, 62) only
// say how a REPOS re-approaches, so alone they change nothing that ncc runs.
struct MachineGroup {
  int group;
  const char *what;  // null: accepted, no effect without the REPOS it parametrizes
};
const MachineGroup kMachineGroups[] = {
    {35, "punching and nibbling"}, {36, "punching and nibbling"}, {26, nullptr}, {62, nullptr},
};

// The keywords that open a synchronized action's condition.
const char *const kSyncConditions[] = {"WHEN", "WHENEVER", "FROM", "EVERY"};
bool isSyncCondition(const std::string &s) {
  for (const char *c : kSyncConditions)
    if (s == c) return true;
  return false;
}
}  // namespace

bool isSyncKeyword(const std::string &name) { return isSyncCondition(name) || name == "DO" || name == "ELSE"; }

bool BlockParser::machineConstruct(const std::string &kw) {
  const MachineConstruct *mc = nullptr;
  for (auto &c : kConstructs)
    if (kw == c.name) mc = &c;
  if (!mc || f_.vars.count(kw)) return false;
  const Token &at = tok();
  // A synchronized action is named by its condition keyword (WHENEVER), not by its ID=.
  std::string name = kw;
  if (mc->what == kSync)
    for (size_t j = i_; j < t_.size(); ++j)
      if (t_[j].kind == Tok::Name && (isSyncCondition(t_[j].text) || t_[j].text == "DO")) {
        name = t_[j].text;
        break;
      }
  // Positioning words and oscillation settings may also stand as address words (POS[X]=10):
  // all of them read the same as a synchronized action's actions.
  machineCtx_ = true;
  bool ok = mc->what == kSync ? syncAction() : machineItems(false);
  machineCtx_ = false;
  if (!ok) return true;  // the error is reported (failed_)
  ir::Op m(ir::OpKind::Message, loc(at));
  m.set("text", ir::Expr::string(fmt::format("'{}' ({}) is not simulated", name, mc->what)));
  m.set("kind", ir::Expr::symbol("not_simulated"));
  pre_.push_back(std::move(m));
  return true;
}

bool BlockParser::machineGCode(const GInfo &g, const Token &at) {
  const char *what = nullptr;
  bool known = false;
  for (auto &m : kMachineGroups)
    if (g.code->group == m.group) what = m.what, known = true;
  if (std::string_view(g.code->name).substr(0, 5) == "REPOS") what = "repositioning after an interrupt", known = true;
  if (!known) return false;
  if (!what) return true;
  ir::Op m(ir::OpKind::Message, loc(at));
  m.set("text", ir::Expr::string(fmt::format("'{}' ({}: {}) is not simulated", g.code->name, what, g.code->meaning)));
  m.set("kind", ir::Expr::symbol("not_simulated"));
  pre_.push_back(std::move(m));
  return true;
}

// [ID=n | IDS=n] [WHEN | WHENEVER | FROM | EVERY cond] DO action … [ELSE action …] (L…, seed000a
// §2.26): the condition is an expression, the actions assignments, address words and procedure
// calls; all of it to the end of the block.
bool BlockParser::syncAction() {
  if (tok().isName("ID") || tok().isName("IDS")) {
    ++i_;
    if (!expect("=")) return false;
    if (!expr(0)) return false;
  }
  if (tok().kind == Tok::Name && isSyncCondition(tok().text)) {
    std::string kw = tok().text;
    ++i_;
    if (tok().isName("DO")) return fail(tok(), fmt::format("{} needs a condition before DO", kw));
    ir::ExprPtr c = expr(0);
    if (!c) return false;
    if (stringy(*c)) return fail(t_[i_ - 1], fmt::format("the condition of {} is a string, not a BOOL", kw));
    if (!tok().isName("DO")) return fail(tok(), fmt::format("expected DO after the condition of {}", kw));
  }
  if (!tok().isName("DO")) return fail(tok(), "a synchronized action needs DO and its actions");
  ++i_;
  return machineItems(true);
}

// The rest of the block: NAME, NAME[index …], NAME(args), each optionally `= value`; a
// synchronized action's actions (`inSync`) may have one ELSE. At least one item.
bool BlockParser::machineItems(bool inSync) {
  bool any = false, sawElse = false;
  while (!atEnd()) {
    const Token &t = tok();
    if (t.kind != Tok::Name)
      return fail(t, fmt::format("expected {}, found '{}'", inSync ? "an action" : "a name", t.text));
    if (inSync && t.text == "ELSE") {
      if (sawElse || !any) return fail(t, sawElse ? "a second ELSE in a synchronized action" : "ELSE before an action");
      sawElse = true;
      any = false;
      ++i_;
      continue;
    }
    if (inSync && (isSyncCondition(t.text) || t.text == "DO"))
      return fail(t, fmt::format("'{}' inside the actions of a synchronized action", t.text));
    ++i_;
    std::vector<ir::ExprPtr> idx;
    if (tok().is("[") && !indexList(idx, true)) return false;
    if (tok().is("(")) {
      ++i_;
      if (!tok().is(")")) do {
          if (tok().is(",")) continue;  // an omitted argument
          if (!expr(0)) return false;
        } while (tok().is(",") && (++i_, true));
      if (!expect(")")) return false;
    }
    if (tok().is("=")) {
      ++i_;
      if (!expr(0)) return false;
    }
    any = true;
  }
  if (!any) return fail(tok(), inSync ? "expected an action at the end of the block" : "expected a name");
  return true;
}

}  // namespace ncc::sin
