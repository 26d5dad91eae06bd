#include "runtime/Machine.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace ncc;

namespace {
const char *kMinimal = R"(schema = 1
[machine]
name = "tiny"
rapid_feed = 6000
[axes.X]
max_velocity = 6000
max_accel = 1000
)";

// A valid machine to append a problem to: X only, 3 lines.
const char *kBase = "schema = 1\n[axes.X]\nmax_velocity = 1\nmax_accel = 1\n";

std::string parseError(const std::string &text) {
  Machine m;
  std::string err;
  EXPECT_FALSE(Machine::parse(text, "m.toml", m, err)) << text;
  return err;
}

Machine parseOk(const std::string &text) {
  Machine m;
  std::string err;
  EXPECT_TRUE(Machine::parse(text, "m.toml", m, err)) << err;
  return m;
}
}  // namespace

TEST(Machine, DefaultIsEmbeddedAndComplete) {
  const Machine &m = Machine::builtinDefault();
  EXPECT_EQ(m.name, "default-mill");
  EXPECT_EQ(m.dialect, "iso");
  EXPECT_EQ(m.decimalMode, "calculator");
  EXPECT_EQ(m.kinematics, "xyz");
  EXPECT_DOUBLE_EQ(m.rapidFeed, 10000);
  EXPECT_DOUBLE_EQ(m.maxFeed, 5000);
  EXPECT_DOUBLE_EQ(m.arcTolerance, 0.002);
  EXPECT_DOUBLE_EQ(m.pathTolerance, 0.01);
  EXPECT_EQ(m.lookahead, 64);
  EXPECT_EQ(m.freeTools, 99);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(m.axes[i].present);
    EXPECT_FALSE(m.axes[i].rotary);
    EXPECT_DOUBLE_EQ(m.axes[i].maxVelocity, 10000);
  }
  for (int i = 3; i < kAxes; ++i) EXPECT_FALSE(m.axes[i].present);
  EXPECT_DOUBLE_EQ(m.axes[0].maxAccel, 2000);
  EXPECT_DOUBLE_EQ(m.axes[2].maxAccel, 1500);
  EXPECT_DOUBLE_EQ(m.axes[1].maxJerk, 50000);
  EXPECT_DOUBLE_EQ(m.axes[2].maxJerk, 40000);
  EXPECT_DOUBLE_EQ(m.axes[0].maxPos, 800);
  EXPECT_DOUBLE_EQ(m.axes[1].maxPos, 500);
  EXPECT_DOUBLE_EQ(m.axes[2].minPos, -500);
  ASSERT_EQ(m.tools.size(), 4u);
  EXPECT_DOUBLE_EQ(m.tools.at(1).length, 100);
  EXPECT_DOUBLE_EQ(m.tools.at(1).radius, 5);
  EXPECT_DOUBLE_EQ(m.tools.at(4).radius, 25);
  EXPECT_EQ(m.toolTable.at(3).name, "8 mm drill");
  EXPECT_EQ(m.controller.reset.size(), 13u);  // rs274's set and the programmable frame's slots
  // Emitter settings: the [emit.*] tables as text, nested keys dotted.
  EXPECT_EQ(m.get("emit.iso", "arc_style"), "ijk");
  EXPECT_EQ(m.get("emit.iso", "format.X"), "3");
  EXPECT_EQ(m.get("emit.iso", "block_numbers"), "true");
  EXPECT_EQ(m.get("emit.sinumerik", "program_header"), "; ncc output");
  EXPECT_EQ(m.get("emit.iso", "program_header"), "%");
  EXPECT_EQ(m.get("emit.iso", "nope", "dflt"), "dflt");
  EXPECT_NE(std::string(Machine::builtinDefaultText()).find("[axes.X]"), std::string::npos);
}

TEST(Machine, LoadDefaultByName) {
  Machine m;
  std::string err;
  ASSERT_TRUE(Machine::load("default", m, err)) << err;
  EXPECT_EQ(m.name, "default-mill");
}

TEST(Machine, ParsesEveryKey) {
  Machine m = parseOk(R"(# comment
schema = 1
kinematics = "xyz"
[machine]
name = "five-axis"   # trailing comment
dialect = "sinumerik"
decimal_mode = "is-b"
rapid_feed = 20000
max_feed = 8000.5
arc_tolerance = 0.005
path_tolerance = 0
lookahead = 16
free_tools = 12
[controller]
family = "sinumerik"
model = "840D sl"
gcode_system = "B"
plane = "G18"
diameter_programming = true
reset = ["plane", "units"]
r_params = 300
q_params = 10
real_tolerance = 1e-9
macro_calls = { M6 = "L6", "G65.1" = "O9010", G81 = "CYCLE81", M07 = { program = "O9002", kind = "subprogram" } }
[axes.X]
kind = "linear"
max_velocity = 20000
max_accel = 3000
max_jerk = 0
min = -400
max = 400.5
[axes.C]
max_velocity = 7200
max_accel = 1000
[axes.A]
kind = "linear"
max_velocity = 1
max_accel = 1
[offsets]
g54 = [10, 20, -30]
g55 = [1, 2, 3, 4, 5, 6.5]
g56 = [0, 0, 1]
g57 = [0, 0, 2]
g58 = [0, 0, 3]
g59 = [0, 0, 4]
"g59.1" = [0, 0, 5]
"g59.2" = [0, 0, 6]
"g59.3" = [7, 8, 9]
home1 = [0, 0, -2]
home2 = [0, 0, -1]
[[tools]]
number = 12
name = "drill"
edges = [{ d = 1, length = 55.5, radius = 2, length_wear = -0.5, radius_wear = 0.25 }]
[emit.iso]
arc_style = "r"
block_numbers = false
block_step = 5
format.X = 4
ratio = 0.25
[emit.sinumerik]
program_header = "; x # kept"
)");
  EXPECT_EQ(m.name, "five-axis");
  EXPECT_EQ(m.dialect, "sinumerik");
  EXPECT_EQ(m.decimalMode, "is-b");
  EXPECT_DOUBLE_EQ(m.rapidFeed, 20000);
  EXPECT_DOUBLE_EQ(m.maxFeed, 8000.5);
  EXPECT_DOUBLE_EQ(m.arcTolerance, 0.005);
  EXPECT_DOUBLE_EQ(m.pathTolerance, 0);
  EXPECT_EQ(m.lookahead, 16);
  EXPECT_EQ(m.freeTools, 12);
  const Controller &c = m.controller;
  EXPECT_EQ(c.family, "sinumerik");
  EXPECT_EQ(c.model, "840D sl");
  EXPECT_EQ(c.gcodeSystem, "B");
  EXPECT_EQ(c.plane, "G18");
  EXPECT_TRUE(c.diameterProgramming);
  EXPECT_EQ(c.reset, (std::vector<std::string>{"plane", "units"}));
  EXPECT_EQ(c.rParams, 300);
  EXPECT_EQ(c.qParams, 10);
  EXPECT_DOUBLE_EQ(c.realTolerance, 1e-9);
  using Call = Controller::MacroCall;
  EXPECT_EQ(c.macroCalls, (std::map<std::string, Call>{{"G65.1", {"O9010", "macro"}},
                                                       {"G81", {"CYCLE81", "macro"}},
                                                       {"M6", {"L6", "macro"}},
                                                       {"M7", {"O9002", "subprogram"}}}));
  EXPECT_TRUE(m.axes[0].present);
  EXPECT_FALSE(m.axes[1].present);  // not listed
  EXPECT_DOUBLE_EQ(m.axes[0].maxVelocity, 20000);
  EXPECT_DOUBLE_EQ(m.axes[0].maxAccel, 3000);
  EXPECT_DOUBLE_EQ(m.axes[0].maxJerk, 0);
  EXPECT_DOUBLE_EQ(m.axes[0].minPos, -400);
  EXPECT_DOUBLE_EQ(m.axes[0].maxPos, 400.5);
  EXPECT_TRUE(m.axes[5].present);
  EXPECT_TRUE(m.axes[5].rotary);   // A B C turn unless kind says otherwise
  EXPECT_FALSE(m.axes[3].rotary);
  EXPECT_DOUBLE_EQ(m.workOffsets[0][2], -30);
  EXPECT_DOUBLE_EQ(m.workOffsets[1][5], 6.5);
  for (int i = 2; i < 8; ++i) EXPECT_DOUBLE_EQ(m.workOffsets[i][2], i - 1) << i;
  EXPECT_DOUBLE_EQ(m.workOffsets[8][0], 7);
  EXPECT_DOUBLE_EQ(m.home1[2], -2);
  EXPECT_DOUBLE_EQ(m.home2[2], -1);
  // T/H/D numbers use edge 1 with its wear.
  EXPECT_DOUBLE_EQ(m.tools.at(12).length, 55);
  EXPECT_DOUBLE_EQ(m.tools.at(12).radius, 2.25);
  EXPECT_EQ(m.toolTable.at(12).name, "drill");
  EXPECT_DOUBLE_EQ(m.toolTable.at(12).edges.at(1).lengthWear, -0.5);
  EXPECT_EQ(m.get("emit.iso", "arc_style"), "r");
  EXPECT_EQ(m.get("emit.iso", "block_numbers"), "false");
  EXPECT_EQ(m.get("emit.iso", "block_step"), "5");
  EXPECT_EQ(m.get("emit.iso", "format.X"), "4");
  EXPECT_EQ(m.get("emit.iso", "ratio"), "0.25");
  EXPECT_EQ(m.get("emit.sinumerik", "program_header"), "; x # kept");
}

TEST(Machine, MissingKeysTakeDefaults) {
  Machine m = parseOk(kMinimal);
  Machine d;  // the struct's defaults are the schema's
  EXPECT_EQ(m.name, "tiny");
  EXPECT_EQ(m.dialect, "iso");
  EXPECT_EQ(m.decimalMode, "calculator");
  EXPECT_EQ(m.kinematics, "xyz");
  EXPECT_DOUBLE_EQ(m.maxFeed, 5000);
  EXPECT_DOUBLE_EQ(m.arcTolerance, 0.002);
  EXPECT_DOUBLE_EQ(m.pathTolerance, 0.01);
  EXPECT_EQ(m.lookahead, 64);
  EXPECT_EQ(m.freeTools, 0);
  EXPECT_DOUBLE_EQ(m.axes[0].maxJerk, 0);
  EXPECT_DOUBLE_EQ(m.axes[0].minPos, -1e9);
  EXPECT_DOUBLE_EQ(m.axes[0].maxPos, 1e9);
  EXPECT_FALSE(m.axes[0].rotary);
  EXPECT_EQ(m.controller.family, "iso");
  EXPECT_EQ(m.controller.gcodeSystem, "A");
  EXPECT_EQ(m.controller.plane, "G17");
  EXPECT_FALSE(m.controller.diameterProgramming);
  EXPECT_EQ(m.controller.reset.size(), 9u);  // without the key: rs274's set
  EXPECT_FALSE(m.controller.axesScaleEnable);
  EXPECT_DOUBLE_EQ(m.controller.scaleWeighting, 0.001);
  EXPECT_EQ(m.controller.rParams, 100);
  EXPECT_EQ(m.controller.qParams, 2000);
  EXPECT_DOUBLE_EQ(m.controller.realTolerance, d.controller.realTolerance);
  EXPECT_TRUE(m.controller.macroCalls.empty());
  for (auto &o : m.workOffsets) EXPECT_EQ(o, AxisVec{});
  EXPECT_TRUE(m.tools.empty());
  EXPECT_TRUE(m.sections.empty());
  // No tool table: every number is a tool.
  EXPECT_NE(m.findTool(7), nullptr);
}

TEST(Machine, ToolEdgesAndLookup) {
  Machine m = parseOk(std::string(kBase) + R"(
[machine]
free_tools = 5
[[tools]]
number = 7
name = "grooving insert"
[[tools.edges]]
d = 2
length = 30
radius = 0.4
[[tools.edges]]
d = 1
length = 31
radius = 0.2
radius_wear = 0.01
[[tools]]
number = 8
edges = [{ d = 3, length = 12 }]
)");
  ASSERT_EQ(m.toolTable.at(7).edges.size(), 2u);
  EXPECT_DOUBLE_EQ(m.toolTable.at(7).edges.at(2).radius, 0.4);
  EXPECT_DOUBLE_EQ(m.findTool(7)->length, 31);  // edge 1
  EXPECT_DOUBLE_EQ(m.findTool(7)->radius, 0.21);
  EXPECT_DOUBLE_EQ(m.findTool(8)->length, 12);  // the only edge
  EXPECT_NE(m.findTool(0), nullptr);
  EXPECT_NE(m.findTool(5), nullptr);  // free_tools
  EXPECT_DOUBLE_EQ(m.findTool(5)->length, 0);
  EXPECT_EQ(m.findTool(6), nullptr);
}

TEST(Machine, ToleratesBomAndCrlf) {
  Machine m = parseOk("\xEF\xBB\xBFschema = 1\r\n[machine]\r\nname = \"crlf\"\r\n[axes.Z]\r\nmax_velocity = 1\r\nmax_accel = 2\r\n");
  EXPECT_EQ(m.name, "crlf");
  EXPECT_DOUBLE_EQ(m.axes[2].maxAccel, 2);
}

// Every kind of problem, with the line and column it points at.
TEST(Machine, ErrorsAreLocated) {
  const std::string b = kBase;  // problems appended to it start on line 5
  const std::string x = "[axes.X]\nmax_velocity = 1\nmax_accel = 1\n";  // kBase without the schema line
  const struct {
    std::string text, error;
  } cases[] = {
      // Syntax (toml++'s message).
      {b + "[machine\n",
       "m.toml:5:9: error: Error while parsing table header: expected ']', saw '\\n'"},
      {b + "[machine]\nname = \"a\"\nname = \"b\"\n",
       "m.toml:7:8: error: Error while parsing key-value pair: cannot redefine existing string 'name'"},
      // Schema version.
      {"[axes.X]\nmax_velocity = 1\nmax_accel = 1\n",
       "m.toml:1:1: error: missing 'schema = 1' (the version of the machine description format)"},
      {"schema = 2\n",
       "m.toml:1:10: error: schema: this ncc reads machine descriptions of schema 1 (write schema = 1)"},
      // Unknown keys, at the key.
      {"schema = 1\naxis = 1\n" + x,
       "m.toml:2:1: error: unknown key 'axis' in the top level"},
      {b + "[machine]\n  max_veloctiy = 3\n",
       "m.toml:6:3: error: unknown key 'max_veloctiy' in [machine]"},
      {b + "present = true\n",
       "m.toml:5:1: error: unknown key 'present' in [axes.X]"},
      {b + "[controller]\nrparams = 1\n",
       "m.toml:6:1: error: unknown key 'rparams' in [controller]"},
      {b + "[offsets]\ng60 = [1, 2, 3]\n",
       "m.toml:6:1: error: unknown key 'g60' in [offsets]"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ d = 1 }]\ndiameter = 3\n",
       "m.toml:8:1: error: unknown key 'diameter' in [[tools]]"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ d = 1, lenght = 3 }]\n",
       "m.toml:7:19: error: unknown key 'lenght' in edge"},
      {b + "[emit.fanuc]\nx = 1\n",
       "m.toml:5:7: error: unknown emitter 'fanuc' in [emit] (iso, sinumerik, heidenhain, nc200)"},
      {b + "[axes.Q]\n",
       "m.toml:5:7: error: axis 'Q': the machine axes are X Y Z A B C U V W (name them with 'name')"},
      {b + "[axes.x]\n",
       "m.toml:5:7: error: axis 'x': the machine axes are X Y Z A B C U V W (name them with 'name')"},
      {b + "[axes.U]\nmax_velocity = 1\nmax_accel = 1\nkind = \"rotary\"\n",
       "m.toml:5:1: error: [axes.U]: U V W are linear axes (parallel to X Y Z)"},
      {b + "[axes.U]\nmax_velocity = 1\nmax_accel = 1\nname = \"x1\"\n",
       "m.toml:8:8: error: name: 'x1' is not an axis name (an upper-case letter, then upper-case letters, digits or '_', at most 8)"},
      {b + "[axes.U]\nmax_velocity = 1\nmax_accel = 1\nname = \"X\"\n",
       "m.toml:8:8: error: axis U: the name 'X' is already axis X's"},
      // Wrong types, at the value.
      {b + "[machine]\nrapid_feed = \"fast\"\n",
       "m.toml:6:14: error: rapid_feed: expected a number, got a string"},
      {b + "[machine]\nlookahead = 6.5\n",
       "m.toml:6:13: error: lookahead: expected an integer, got a floating-point number"},
      {b + "[machine]\nname = 3\n",
       "m.toml:6:8: error: name: expected a string, got an integer"},
      {b + "[controller]\ndiameter_programming = \"yes\"\n",
       "m.toml:6:24: error: diameter_programming: expected true or false, got a string"},
      {b + "[offsets]\ng54 = [1, 2]\n",
       "m.toml:6:7: error: g54: expected an array of 3 to 9 numbers [x, y, z, a, b, c, u, v, w], got 2 elements"},
      {b + "[offsets]\ng54 = [1, 2, \"z\"]\n",
       "m.toml:6:14: error: g54[2]: expected a number, got a string"},
      {b + "[controller]\nreset = \"all\"\n",
       "m.toml:6:9: error: reset: expected an array of strings, got a string"},
      {b + "[emit.iso]\nformat = [1]\n",
       "m.toml:6:10: error: format: expected a string, number or boolean, got an array"},
      {"schema = 1\nmachine = 1\n" + x,
       "m.toml:2:11: error: [machine]: expected a table, got an integer"},
      {"schema = 1\ntools = 1\n" + x,
       "m.toml:2:9: error: tools: expected an array of tables [[tools]], got an integer"},
      // Out of range and unknown choices.
      {b + "[machine]\nlookahead = 0\n",
       "m.toml:6:13: error: lookahead: must be 1..100000, got 0"},
      {b + "[machine]\nrapid_feed = 0\n",
       "m.toml:6:14: error: rapid_feed: must be > 0, got 0"},
      {b + "[machine]\nfree_tools = -1\n",
       "m.toml:6:14: error: free_tools: must be 0..99999, got -1"},
      {b + "[machine]\npath_tolerance = -0.5\n",
       "m.toml:6:18: error: path_tolerance: must be >= 0, got -0.5"},
      {b + "max_accel = 0\n",
       "m.toml:5:13: error: Error while parsing key-value pair: cannot redefine existing integer 'max_accel'"},
      {b + "max_jerk = -1\n",
       "m.toml:5:12: error: max_jerk: must be >= 0, got -1"},
      {b + "[machine]\ndecimal_mode = \"fanuc\"\n",
       "m.toml:6:16: error: decimal_mode: 'fanuc' is not one of calculator, is-b, is-c"},
      {b + "[machine]\ndialect = \"haas\"\n",
       "m.toml:6:11: error: dialect: 'haas' is not one of iso, fanuc, linuxcnc, sinumerik, heidenhain, cldata"},
      {b + "kind = \"spiral\"\n",
       "m.toml:5:8: error: kind: 'spiral' is not one of linear, rotary"},
      {b + "[controller]\ngcode_system = \"D\"\n",
       "m.toml:6:16: error: gcode_system: 'D' is not one of A, B, C"},
      {b + "[controller]\nreset = [\"plane\", \"everything\"]\n",
       "m.toml:6:19: error: reset: 'everything' is not one of motion, plane, distance, feed_mode, units, "
       "cutter_comp, tool_length, work_offset, g92, feed, spindle, coolant, path_mode, rotation, scaling, mirror, "
       "local_offset"},
      {"schema = 1\nkinematics = \"trunnion-ac\"\n[axes.X]\nmax_velocity = 1\nmax_accel = 1\n",
       "m.toml:2:14: error: kinematics: 'trunnion-ac' is not one of xyz, table-table, head-table, head-head"},
      {b + "[controller]\nmacro_calls = { T = \"O9000\" }\n",
       "m.toml:6:17: error: macro_calls: 'T' is not an M or G code (M6, G81, \"G65.1\")"},
      {b + "[controller]\nmacro_calls = { M6 = \"\" }\n",
       "m.toml:6:22: error: macro_calls.M6: the program name is empty"},
      {b + "[controller]\nmacro_calls = { M30 = \"O9000\" }\n",
       "m.toml:6:17: error: macro_calls: M30 is a code of the controller itself and cannot call a program"},
      {b + "[controller]\nmacro_calls = { M6 = { program = \"O9001\", kind = \"call\" } }\n",
       "m.toml:6:50: error: kind: 'call' is not one of macro, subprogram"},
      {b + "[controller]\nmacro_calls = { M6 = \"O9001\", M06 = \"O9002\" }\n",
       "m.toml:6:17: error: macro_calls: M6 is given twice"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ d = 1, radius = -1 }]\n",
       "m.toml:7:28: error: radius: must be >= 0, got -1"},
      // Required keys, at their table.
      {b + "[axes.Y]\nmax_accel = 100\n",
       "m.toml:5:1: error: [axes.Y] needs 'max_velocity'"},
      {b + "[[tools]]\nedges = [{ d = 1 }]\n",
       "m.toml:5:1: error: [[tools]] needs 'number'"},
      {b + "[[tools]]\nnumber = 1\n",
       "m.toml:5:1: error: [[tools]] needs 'edges'"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ length = 1 }]\n",
       "m.toml:7:10: error: edge needs 'd'"},
      {b + "[[tools]]\nnumber = 1\nedges = []\n",
       "m.toml:7:9: error: edges: expected a non-empty array of tables {d = 1, length = ..., radius = ...}"},
      // Whole-table and whole-machine checks.
      {b + "min = 5\nmax = 5\n",
       "m.toml:2:1: error: [axes.X]: min must be below max"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ d = 1 }]\n[[tools]]\nnumber = 1\nedges = [{ d = 1 }]\n",
       "m.toml:8:1: error: tool 1 appears twice"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ d = 1 }, { d = 1 }]\n",
       "m.toml:7:21: error: edge d = 1 appears twice"},
      {b + "[[tools]]\nnumber = 1\nedges = [{ d = 2 }, { d = 3 }]\n",
       "m.toml:5:1: error: tool 1 has several edges but no d = 1 (the edge T, H and D numbers use)"},
      {b + "[offsets]\ng59.1 = [1, 2, 3]\n",
       "m.toml:6:1: error: g59: expected an array, got a table (quote keys with a dot: \"g59.1\")"},
      {"schema = 1\n[machine]\nname = \"x\"\n",
       "m.toml:1:1: error: no linear axis (need at least one of [axes.X] [axes.Y] [axes.Z])"},
      {b + "kind = \"rotary\"\n",
       "m.toml:2:1: error: axis X: kinematics \"xyz\" needs it linear"},
  };
  for (auto &c : cases) EXPECT_EQ(parseError(c.text), c.error);
}

TEST(Machine, ReportsEveryProblemInFileOrder) {
  std::vector<MachineError> errors;
  Machine m;
  EXPECT_FALSE(Machine::parse(std::string(kBase) + "[machine]\nzz = 1\naa = 2\nlookahead = 0\n", "m.toml", m, errors));
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].line, 6u);
  EXPECT_EQ(errors[1].line, 7u);
  EXPECT_EQ(errors[2].line, 8u);
  EXPECT_EQ(errors[2].col, 13u);
}

TEST(Machine, LoadFileAndMissingFile) {
  std::string path = ::testing::TempDir() + "ncc-machine-test.toml";
  {
    std::ofstream f(path);
    f << kMinimal << "bogus = 1\n";
  }
  Machine m;
  std::string err;
  EXPECT_FALSE(Machine::load(path, m, err));
  EXPECT_EQ(err, path + ":8:1: error: unknown key 'bogus' in [axes.X]");
  std::remove(path.c_str());
  EXPECT_FALSE(Machine::load(path, m, err));
  EXPECT_EQ(err, path + ": error: cannot read machine description: No such file or directory");
}

// The shipped machines and every machine file of the tests load.
TEST(Machine, ShippedMachinesLoad) {
  std::string root = NCC_SOURCE_DIR;
  int n = 0;
  for (const char *dir : {"/runtime/machines", "/examples/machines", "/test/lit/emit/Inputs", "/test/lit/oracle/Inputs",
                          "/test/programs/sinumerik"})
    for (auto &e : std::filesystem::directory_iterator(root + dir)) {
      if (e.path().extension() != ".toml") continue;
      Machine m;
      std::string err;
      EXPECT_TRUE(Machine::load(e.path().string(), m, err)) << err;
      ++n;
    }
  EXPECT_EQ(n, 22);  // default, 11 examples (two mill-turn), 8 emitter test machines, the oracle machine, the shop programs' mill
  // The embedded text is the file.
  std::ifstream f(root + "/runtime/machines/default-mill.toml");
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, Machine::builtinDefaultText());
}

// U V W are machine axes (linear); `name` gives an axis the controller's name.
TEST(Machine, NamedAxesAndUVW) {
  const std::string text = "schema = 1\n"
                           "[axes.X]\nmax_velocity = 1\nmax_accel = 1\n"
                           "[axes.Z]\nmax_velocity = 1\nmax_accel = 1\nname = \"Z1\"\n"
                           "[axes.W]\nmax_velocity = 1\nmax_accel = 1\nname = \"Z2\"\n"
                           "[offsets]\ng54 = [1, 2, 3, 4, 5, 6, 7, 8, 9]\n";
  Machine m;
  std::string err;
  ASSERT_TRUE(Machine::parse(text, "m.toml", m, err)) << err;
  EXPECT_TRUE(m.axes[(int)Axis::W].present);
  EXPECT_FALSE(m.axes[(int)Axis::W].rotary);
  EXPECT_EQ(m.axisName(0), "X");
  EXPECT_EQ(m.axisName(2), "Z1");
  EXPECT_EQ(m.axisByName("Z2"), (int)Axis::W);
  EXPECT_EQ(m.axisByName("Z1"), (int)Axis::Z);
  EXPECT_EQ(m.axisByName("X"), (int)Axis::X);
  EXPECT_EQ(m.axisByName("Z"), -1);  // Z is called Z1 on this machine
  EXPECT_EQ(m.axisByName("Y"), -1);  // not described
  EXPECT_EQ(m.workOffsets[0][(int)Axis::W], 9);
}
