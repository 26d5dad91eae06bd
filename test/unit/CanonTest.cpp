// Canonical trace tests: the oracle programs of test/lit/oracle replayed through a minimal block
// reader (this file) and the executor, compared with rs274's recorded traces; writer format; canon-diff.
#include "runtime/CanonDiff.h"
#include "runtime/CanonTrace.h"
#include "runtime/Executor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace ncc;

namespace {

std::string oracleDir() {
  return (std::filesystem::path(__FILE__).parent_path() / ".." / "lit" / "oracle").lexically_normal().string();
}

std::string readFile(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Machine with the oracle tool table (test/lit/oracle/Inputs/tools.txt: T<n> length L radius R).
Machine oracleMachine() {
  Machine m;
  std::istringstream in(readFile(oracleDir() + "/Inputs/tools.txt"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string t, key;
    double v;
    ls >> t;
    ToolData td;
    while (ls >> key >> v) (key == "length" ? td.length : td.radius) = v;
    m.tools[std::stoi(t.substr(1))] = td;
  }
  return m;
}

// --- a minimal reader of the oracle programs (plain ISO blocks, no expressions) -------------
// It emits the commands of each block in rs274's execution order, the way a front end does.
struct Block {
  std::multimap<char, double> words;
  std::vector<std::string> comments;
  int64_t n = -1;
  bool hasG(double g) const {
    auto r = words.equal_range('G');
    for (auto it = r.first; it != r.second; ++it)
      if (std::fabs(it->second - g) < 1e-6) return true;
    return false;
  }
  bool hasM(int m) const {
    auto r = words.equal_range('M');
    for (auto it = r.first; it != r.second; ++it)
      if ((int)it->second == m) return true;
    return false;
  }
  bool has(char c) const { return words.count(c) > 0; }
  double get(char c) const { return words.find(c)->second; }
};

Block readBlock(const std::string &line) {
  Block b;
  size_t i = 0;
  while (i < line.size()) {
    char c = line[i];
    if (c == '(') {
      size_t e = line.find(')', i);
      b.comments.push_back(line.substr(i + 1, e - i - 1));
      i = e + 1;
    } else if (isalpha((unsigned char)c)) {
      char L = (char)toupper(c);
      size_t used = 0;
      double v = std::stod(line.substr(i + 1), &used);
      if (L == 'N')
        b.n = (int64_t)v;
      else
        b.words.insert({L, v});
      i += 1 + used;
    } else {
      ++i;
    }
  }
  return b;
}

struct ModeCode {
  double g;
  ModeValue v;
};
const ModeCode kModes[] = {
    {17, ModeValue::XY},          {18, ModeValue::ZX},           {19, ModeValue::YZ},
    {20, ModeValue::Inch},        {21, ModeValue::MM},           {90, ModeValue::Absolute},
    {91, ModeValue::Incremental}, {90.1, ModeValue::ArcAbsolute}, {91.1, ModeValue::ArcIncremental},
    {93, ModeValue::InverseTime}, {94, ModeValue::PerMinute},    {98, ModeValue::RetractInitial},
    {99, ModeValue::RetractR},    {61, ModeValue::ExactPath},    {64, ModeValue::Continuous},
    {0, ModeValue::Rapid},        {1, ModeValue::Linear},        {2, ModeValue::ArcCW},
    {3, ModeValue::ArcCCW},       {80, ModeValue::CycleOff},     {81, ModeValue::Drill},
    {82, ModeValue::DrillDwell},  {83, ModeValue::Peck},         {73, ModeValue::PeckChipBreak},
    {84, ModeValue::Tap},         {85, ModeValue::BoreFeed},     {86, ModeValue::BoreStop},
    {89, ModeValue::BoreDwell},
};

std::vector<MachineCmd> blockCmds(const Block &b, std::deque<std::string> &pool) {
  std::vector<MachineCmd> out;
  auto cmd = [&](CmdKind k) -> MachineCmd & {
    out.emplace_back();
    out.back().kind = k;
    return out.back();
  };
  auto copyWords = [&](MachineCmd &c, const char *letters) {
    for (const char *p = letters; *p; ++p)
      if (b.has(*p)) {
        Word w;
        wordFromLetter(*p, w);
        c.set(w, b.get(*p));
      }
  };
  cmd(CmdKind::Block).blockNumber = b.n;
  for (auto &t : b.comments) {
    pool.push_back(t);
    cmd(CmdKind::Comment).text = pool.back().c_str();
  }
  if (b.has('F')) cmd(CmdKind::Feed).set(Word::F, b.get('F'));
  if (b.has('S')) cmd(CmdKind::Speed).set(Word::S, b.get('S'));
  if (b.has('T')) cmd(CmdKind::ToolSelect).set(Word::T, b.get('T'));
  if (b.hasM(6)) cmd(CmdKind::ToolChange);
  for (int m = 3; m <= 5; ++m)
    if (b.hasM(m)) cmd(CmdKind::Spindle).sub = m == 5 ? 0 : m == 3 ? 1 : 2;
  if (b.hasM(7)) cmd(CmdKind::Coolant) = [] { MachineCmd c; c.kind = CmdKind::Coolant; c.sub = 2; c.sub2 = 2; return c; }();
  if (b.hasM(8)) cmd(CmdKind::Coolant) = [] { MachineCmd c; c.kind = CmdKind::Coolant; c.sub = 1; c.sub2 = 1; return c; }();
  if (b.hasM(9)) cmd(CmdKind::Coolant).sub2 = 3;
  if (b.hasG(4)) cmd(CmdKind::Dwell).set(Word::P, b.get('P'));
  MachineCmd modes;
  modes.kind = CmdKind::Mode;
  bool motionCode = false;
  for (auto &mc : kModes)
    if (b.hasG(mc.g)) {
      modes.modes[modes.nmodes++] = mc.v;
      if (modeValueInfo(mc.v).group == ModeGroup::Motion) motionCode = true;
    }
  if (modes.nmodes) out.push_back(modes);
  if (b.hasG(40)) cmd(CmdKind::CutterComp).sub = 0;
  if (b.hasG(41) || b.hasG(42)) {
    MachineCmd &c = cmd(CmdKind::CutterComp);
    c.sub = b.hasG(41) ? 1 : 2;
    copyWords(c, "D");
  }
  if (b.hasG(43)) copyWords(cmd(CmdKind::ToolLength), "H");
  if (b.hasG(49)) cmd(CmdKind::ToolLength).set(Word::H, 0);
  for (int g = 54; g <= 59; ++g)
    if (b.hasG(g)) cmd(CmdKind::WorkOffset).sub = (uint8_t)(g - 53);
  bool consumed = false;
  if (b.hasG(10)) {
    MachineCmd &c = cmd(CmdKind::SetOffset);
    c.sub = (uint8_t)(b.get('L') == 20 ? SetOffsetKind::G10L20 : SetOffsetKind::G10L2);
    copyWords(c, "XYZABCP");
    consumed = true;
  } else if (b.hasG(92.1)) {
    cmd(CmdKind::SetOffset).sub = (uint8_t)SetOffsetKind::G92Cancel;
  } else if (b.hasG(92)) {
    MachineCmd &c = cmd(CmdKind::SetOffset);
    c.sub = (uint8_t)SetOffsetKind::G92;
    copyWords(c, "XYZABC");
    consumed = true;
  } else if (b.hasG(28) || b.hasG(30)) {
    MachineCmd &c = cmd(CmdKind::Home);
    c.sub = b.hasG(28) ? 1 : 2;
    copyWords(c, "XYZABC");
    consumed = true;
  } else if (b.hasG(53)) {
    MachineCmd &c = cmd(CmdKind::MachineMove);
    c.sub = b.hasG(1) ? 1 : 0;
    copyWords(c, "XYZABC");
    consumed = true;
  }
  bool axes = b.has('X') || b.has('Y') || b.has('Z') || b.has('A') || b.has('B') || b.has('C');
  bool arcWords = b.has('I') || b.has('J') || b.has('K') || b.has('R');
  if (!consumed && (axes || (motionCode && arcWords))) copyWords(cmd(CmdKind::Move), "XYZABCIJKRPQL");
  if (b.hasM(0)) cmd(CmdKind::Stop).sub = (uint8_t)StopKind::Program;
  if (b.hasM(1)) cmd(CmdKind::Stop).sub = (uint8_t)StopKind::Optional;
  if (b.hasM(2)) cmd(CmdKind::Stop).sub = (uint8_t)StopKind::End;
  if (b.hasM(30)) cmd(CmdKind::Stop).sub = (uint8_t)StopKind::EndRewind;
  return out;
}

// Runs a program through the executor into a canonical trace (text).
std::string runToCanon(const std::string &src, const Machine &m, Diagnostics &diags) {
  std::FILE *f = std::tmpfile();
  {
    CanonTraceWriter w(f);
    Executor ex(m, w, diags);
    std::deque<std::string> pool;
    std::istringstream in(src);
    std::string line;
    bool ok = true;
    while (ok && std::getline(in, line))
      for (auto &c : blockCmds(readBlock(line), pool))
        if (!(ok = ex.exec(c))) break;
    ex.finish();
    w.finish(diags);
  }
  std::rewind(f);
  std::string text;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  std::fclose(f);
  return text;
}

class OracleTest : public ::testing::TestWithParam<const char *> {};

TEST_P(OracleTest, MatchesRs274AtMachineLevel) {
  std::string name = GetParam();
  std::string src = readFile(oracleDir() + "/" + name + ".ngc");
  std::string expected = readFile(oracleDir() + "/Inputs/" + name + ".rs274");
  ASSERT_FALSE(src.empty());
  ASSERT_FALSE(expected.empty());
  SourceManager sm;
  Diagnostics diags(sm);
  diags.setCollect(true);
  std::string ours = runToCanon(src, oracleMachine(), diags);
  EXPECT_EQ(diags.errorCount(), 0u);
  std::string report;
  bool same = canonDiff(expected, ours, CanonDiffOptions(), report);
  EXPECT_TRUE(same) << report << "\n--- ncc trace ---\n" << ours;
}

INSTANTIATE_TEST_SUITE_P(Oracle, OracleTest,
                         ::testing::Values("motion_basic", "arcs_planes", "incremental", "units", "offsets",
                                           "tool_length", "cycles_drill", "cycles_peck", "cycles_bore",
                                           "machine_misc", "cycles_levels", "cycles_inch", "cycles_g99",
                                           "home_offsets"));

}  // namespace
