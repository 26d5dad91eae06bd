#include "runtime/Machine.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace ncc;

namespace {
const char *kMinimal = R"(
[machine]
name = tiny
rapid_feed = 6000
[axis.X]
max_velocity = 6000
max_accel = 1000
)";

std::string parseError(const std::string &text) {
  Machine m;
  std::string err;
  EXPECT_FALSE(Machine::parse(text, "machine.ini", m, err)) << text;
  return err;
}
}  // namespace

TEST(Machine, DefaultIsEmbeddedAndComplete) {
  const Machine &m = Machine::builtinDefault();
  EXPECT_EQ(m.name, "default-mill");
  EXPECT_EQ(m.dialect, "iso");
  EXPECT_EQ(m.decimalMode, "calculator");
  EXPECT_DOUBLE_EQ(m.rapidFeed, 10000);
  EXPECT_DOUBLE_EQ(m.maxFeed, 5000);
  EXPECT_DOUBLE_EQ(m.arcTolerance, 0.002);
  EXPECT_EQ(m.lookahead, 64);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(m.axes[i].present);
    EXPECT_FALSE(m.axes[i].rotary);
    EXPECT_DOUBLE_EQ(m.axes[i].maxVelocity, 10000);
    EXPECT_GT(m.axes[i].maxAccel, 0);
    EXPECT_GT(m.axes[i].maxJerk, 0);
  }
  for (int i = 3; i < kAxes; ++i) EXPECT_FALSE(m.axes[i].present);
  EXPECT_DOUBLE_EQ(m.axes[0].maxPos, 800);
  EXPECT_DOUBLE_EQ(m.axes[2].minPos, -500);
  ASSERT_EQ(m.tools.size(), 4u);
  EXPECT_DOUBLE_EQ(m.tools.at(1).radius, 5);
  EXPECT_DOUBLE_EQ(m.tools.at(4).radius, 25);
  // Emitter settings live in free sections.
  EXPECT_EQ(m.get("emit.iso", "arc_style"), "ijk");
  EXPECT_EQ(m.get("emit.iso", "format.X"), "3");
  EXPECT_EQ(m.get("emit.sinumerik", "program_header"), "; ncc output");
  EXPECT_EQ(m.get("emit.iso", "program_header"), "%");
  EXPECT_EQ(m.get("emit.iso", "nope", "dflt"), "dflt");
  EXPECT_NE(std::string(Machine::builtinDefaultText()).find("[axis.X]"), std::string::npos);
}

TEST(Machine, LoadDefaultByName) {
  Machine m;
  std::string err;
  ASSERT_TRUE(Machine::load("default", m, err)) << err;
  EXPECT_EQ(m.name, "default-mill");
}

TEST(Machine, ParsesAllSections) {
  const char *text = R"(# comment
; another comment
[machine]
name = five-axis   # trailing comment
dialect = sinumerik
decimal_mode = is-b
rapid_feed = 20000
max_feed = 8000
arc_tolerance = 0.005
path_tolerance = 0.02
lookahead = 16
[axis.x]
max_velocity = 20000
max_accel = 3000
max_jerk = 0
min = -400
max = 400
[axis.C]
max_velocity = 7200
max_accel = 1000
[offsets]
g54 = 10 20 -30
g55 = 1, 2, 3, 4, 5, 6
g59.3 = 7 8 9
home2 = 0 0 -1
[tool.12]
length = 55.5
radius = 2
[custom]
anything = "quoted # kept"
)";
  Machine m;
  std::string err;
  ASSERT_TRUE(Machine::parse(text, "m.ini", m, err)) << err;
  EXPECT_EQ(m.name, "five-axis");
  EXPECT_EQ(m.dialect, "sinumerik");
  EXPECT_EQ(m.decimalMode, "is-b");
  EXPECT_DOUBLE_EQ(m.rapidFeed, 20000);
  EXPECT_DOUBLE_EQ(m.pathTolerance, 0.02);
  EXPECT_EQ(m.lookahead, 16);
  EXPECT_TRUE(m.axes[0].present);
  EXPECT_FALSE(m.axes[1].present);  // not listed
  EXPECT_DOUBLE_EQ(m.axes[0].maxJerk, 0);
  EXPECT_DOUBLE_EQ(m.axes[0].minPos, -400);
  EXPECT_TRUE(m.axes[5].present);
  EXPECT_TRUE(m.axes[5].rotary);
  EXPECT_DOUBLE_EQ(m.workOffsets[0][2], -30);
  EXPECT_DOUBLE_EQ(m.workOffsets[1][5], 6);
  EXPECT_DOUBLE_EQ(m.workOffsets[8][0], 7);
  EXPECT_DOUBLE_EQ(m.home2[2], -1);
  EXPECT_DOUBLE_EQ(m.tools.at(12).length, 55.5);
  EXPECT_EQ(m.get("custom", "anything"), "quoted # kept");
  EXPECT_EQ(m.get("axis.X", "max_accel"), "3000");
}

TEST(Machine, ToleratesBomAndCrlf) {
  Machine m;
  std::string err;
  ASSERT_TRUE(Machine::parse("\xEF\xBB\xBF[machine]\r\nname = crlf\r\n[axis.Z]\r\nmax_velocity = 1\r\nmax_accel = 2\r\n",
                             "w.ini", m, err))
      << err;
  EXPECT_EQ(m.name, "crlf");
  EXPECT_DOUBLE_EQ(m.axes[2].maxAccel, 2);
}

TEST(Machine, MissingKeysTakeDefaults) {
  Machine m;
  std::string err;
  ASSERT_TRUE(Machine::parse(kMinimal, "t.ini", m, err)) << err;
  EXPECT_EQ(m.name, "tiny");
  EXPECT_DOUBLE_EQ(m.maxFeed, 5000);
  EXPECT_EQ(m.lookahead, 64);
  EXPECT_DOUBLE_EQ(m.axes[0].maxJerk, 0);
}

TEST(Machine, ErrorsNameFileAndLine) {
  EXPECT_EQ(parseError("[axis.X]\nmax_velocity = 1\nmax_accel = 1\nmax_veloctiy = 3\n"),
            "machine.ini:4: unknown key 'max_veloctiy' in [axis.X]");
  EXPECT_EQ(parseError("[machine]\nrapid_feed = fast\n"),
            "machine.ini:2: rapid_feed: expected a number, got 'fast'");
  EXPECT_EQ(parseError("[machine]\nlookahead = 0\n"), "machine.ini:2: lookahead: lookahead must be 1..100000");
  EXPECT_EQ(parseError("name = x\n"), "machine.ini:1: key 'name' outside a section");
  EXPECT_EQ(parseError("[machine\n"), "machine.ini:1: missing ']' in section header");
  EXPECT_EQ(parseError("[axis.Q]\n"), "machine.ini:1: unknown axis section [axis.Q] (axes are X Y Z A B C)");
  EXPECT_EQ(parseError("[tool.x]\n"), "machine.ini:1: bad tool section [tool.x] (expected [tool.N], N = 0..99999)");
  EXPECT_EQ(parseError("[machine]\njunk\n"), "machine.ini:2: expected 'key = value' or '[section]'");
  EXPECT_EQ(parseError("[machine]\nname = a\nname = b\n"), "machine.ini:3: duplicate key 'name' in [machine]");
  EXPECT_EQ(parseError("[offsets]\ng54 = 1 2\n"),
            "machine.ini:2: g54: expected 3 to 6 numbers (x y z [a b c]), got '1 2'");
  EXPECT_EQ(parseError("[offsets]\ng60 = 1 2 3\n"), "machine.ini:2: unknown key 'g60' in [offsets]");
  EXPECT_EQ(parseError("[machine]\ndecimal_mode = fanuc\n"),
            "machine.ini:2: decimal_mode: decimal_mode must be calculator, is-b or is-c, got 'fanuc'");
  EXPECT_EQ(parseError("[axis.X]\npresent = maybe\n"), "machine.ini:2: present: expected true or false, got 'maybe'");
  EXPECT_EQ(parseError("[axis.X]\nmax_accel = -1\n"), "machine.ini:2: max_accel: value must be > 0");
  // Whole-section checks point at the section header.
  EXPECT_EQ(parseError("[machine]\n\n[axis.Y]\nmax_accel = 100\n"),
            "machine.ini:3: present axis [axis.Y] needs max_velocity");
  EXPECT_EQ(parseError("[axis.X]\nmax_velocity = 1\nmax_accel = 1\nmin = 5\nmax = 5\n"),
            "machine.ini:1: [axis.X]: min must be below max");
  EXPECT_NE(parseError("[machine]\nname = x\n").find("no linear axis present"), std::string::npos);
}

TEST(Machine, LoadFileAndMissingFile) {
  std::string path = ::testing::TempDir() + "ncc-machine-test.ini";
  {
    std::ofstream f(path);
    f << kMinimal << "bogus = 1\n";
  }
  Machine m;
  std::string err;
  EXPECT_FALSE(Machine::load(path, m, err));
  EXPECT_EQ(err, path + ":8: unknown key 'bogus' in [axis.X]");
  std::remove(path.c_str());
  EXPECT_FALSE(Machine::load(path, m, err));
  EXPECT_NE(err.find("cannot read machine description"), std::string::npos);
}

TEST(Machine, SampleMachinesParse) {
  for (const char *name : {"examples/machines/five-axis-trunnion.ini"}) {
    std::string path = std::string(NCC_SOURCE_DIR) + "/" + name;
    Machine m;
    std::string err;
    ASSERT_TRUE(Machine::load(path, m, err)) << err;
    EXPECT_TRUE(m.axes[3].present);
    EXPECT_TRUE(m.axes[3].rotary);
  }
}
