// The op -> machine-command table (passes/CmdTemplate.cpp) carries every key the verifier allows
// on a machine op: adding any allowed key to an op changes the MachineCmd it becomes. A key
// quietly dropped here would be a word the program says and the machine never sees.
#include "ir/ModeTable.h"
#include "ir/NCIR.h"
#include "passes/CmdTemplate.h"

#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <set>
#include <sstream>

using namespace ncc;
using namespace ir;

namespace {
std::vector<std::string> words(const char *list) {
  std::vector<std::string> out;
  std::istringstream in(list);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// A valid value for a key of an op: a symbol of its list, a mode of its group, or a number.
ExprPtr valueFor(OpKind op, const std::string &key) {
  static const std::map<std::string, const char *> kSymbols = {
      {"dir", "ccw"},       {"flood", "on"},   {"mist", "on"},   {"side", "left"}, {"d_default", "tool"},
      {"slot", "rotation"}, {"action", "set"}, {"form", "axis"}, {"ic", "X"}, {"ac", "Y"}, {"way", "shortest"},
      {"mode", "css"},      {"after_css", "error"}, {"entry", "normal"}, {"combine", "ordered"},
      {"tilt", "spatial"},  {"position", "turn"},
  };
  if (key == "text") return Expr::string("x");
  if (op == OpKind::ToolLength && key == "form") return Expr::symbol("dynamic");
  if (key == "input") return Expr::symbol("analog");
  if (op == OpKind::Contour && key == "action") return Expr::symbol("end");
  if (key == "use") return Expr::symbol("pattern");
  if (key == "rapid") return Expr::boolean(false);
  if (key == "kind") {
    const char *k = op == OpKind::Stop ? "end" : op == OpKind::SetOffset ? "g92" : "debug";
    return Expr::symbol(k);
  }
  if (auto it = kSymbols.find(key); it != kSymbols.end()) return Expr::symbol(it->second);
  ModeGroup g;
  if (op == OpKind::Mode && modeGroupFromName(key, g)) {
    ModeValue last = ModeValue::Count;  // the group's last value: not the executor's default
    for (int v = 0; v < (int)ModeValue::Count; ++v)
      if (modeValueInfo((ModeValue)v).group == g) last = (ModeValue)v;
    return Expr::symbol(modeValueInfo(last).name);
  }
  return Expr::number(key == "ref" ? 2 : 3, Type::Int);
}

bool sameCmd(const CmdTemplate &a, const CmdTemplate &b) {
  const MachineCmd &x = a.base, &y = b.base;
  if (x.kind != y.kind || x.sub != y.sub || x.sub2 != y.sub2 || x.nmodes != y.nmodes || x.mask != y.mask ||
      x.blockNumber != y.blockNumber || (x.text == nullptr) != (y.text == nullptr) || a.slots.size() != b.slots.size() ||
      (a.text == nullptr) != (b.text == nullptr))
    return false;
  for (unsigned i = 0; i < x.nmodes; ++i)
    if (x.modes[i] != y.modes[i]) return false;
  return std::memcmp(x.w, y.w, sizeof x.w) == 0;
}
}  // namespace

TEST(CmdTemplate, EveryAllowedKeyReachesTheMachineCommand) {
  // Keys the engines consume before a command exists: the block-delete level of a block.
  const std::set<std::pair<OpKind, std::string>> kConsumedByEngines = {{OpKind::Block, "skip"}};
  int checked = 0;
  for (int k = 0; k < (int)OpKind::Count; ++k) {
    OpKind kind = (OpKind)k;
    if (!isMachineOp(kind)) continue;
    const OpInfo &info = opInfo(kind);
    if (std::string_view(info.allowed) == "*") continue;  // `cycle`: keys from the library (below)
    Op base(kind, {});
    for (auto &r : words(info.required)) base.set(r, valueFor(kind, r));
    if (kind == OpKind::Frame) base.set("slot", Expr::symbol("rotation")), base.set("action", Expr::symbol("set"));
    SourceManager sm;
  Diagnostics diags(sm);  // the table reports no errors for valid ops
    CmdTemplate without;
    ASSERT_TRUE(buildCmdTemplate(base, without, diags)) << info.name;
    for (auto &key : words(info.allowed)) {
      if (kConsumedByEngines.count({kind, key})) continue;
      Op op(kind, {});
      for (auto &r : words(info.required)) op.set(r, valueFor(kind, r));
      op.set(key, valueFor(kind, key));
      CmdTemplate with;
      ASSERT_TRUE(buildCmdTemplate(op, with, diags)) << info.name << " " << key;
      EXPECT_FALSE(sameCmd(without, with)) << "'" << info.name << "' drops its key '" << key << "'";
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

// The cycle op's arguments are positional words: parameter i of the entry is word i, the
// pattern's follow; the one constant string is the text (docs/IR.md §5.8).
TEST(CmdTemplate, CycleArgumentsArePositionalWords) {
  SourceManager sm;
  Diagnostics diags(sm);
  Op op(OpKind::Cycle, {});
  op.set("entry", Expr::string("sin.CYCLE81"));
  op.set("pattern", Expr::string("sin.HOLES1"));
  op.set("a.DP", Expr::number(-20, Type::Real));  // CYCLE81's 4th parameter
  op.set("p.NUM", Expr::number(3, Type::Real));   // HOLES1's 6th, after CYCLE81's 9
  op.set("p._HIDE", Expr::string("2"));           // HOLES1's 9th
  CmdTemplate t;
  ASSERT_TRUE(buildCmdTemplate(op, t, diags));
  EXPECT_EQ(t.base.kind, CmdKind::Cycle);
  EXPECT_EQ(t.base.mask, wordBit((Word)3) | wordBit((Word)14));
  EXPECT_EQ(t.base.get((Word)3), -20);
  EXPECT_EQ(t.base.get((Word)14), 3);
  EXPECT_STREQ(t.base.text, "2");
  EXPECT_EQ(t.base.sub >> kCycleTextShift, 9 + 8 + 1);
  Op back = cmdToOp(t.base);
  ASSERT_TRUE(back.get("p._HIDE"));
  EXPECT_EQ(back.get("p._HIDE")->str, "2");
  EXPECT_EQ(back.get("a.DP")->num, -20);
}
