#include "ir/NCIR.h"
#include "ir/ModeTable.h"
#include "ir/Diagnostics.h"
#include "ir/SystemVars.h"
#include <gtest/gtest.h>

using namespace ncc;

TEST(OpTable, NamesRoundTrip) {
  for (unsigned k = 0; k < (unsigned)ir::OpKind::Count; ++k) {
    ir::OpKind out;
    ASSERT_TRUE(ir::opKindFromName(ir::opInfo((ir::OpKind)k).name, out));
    EXPECT_EQ((unsigned)out, k);
  }
}

TEST(ModeTable, ValueNamesRoundTrip) {
  for (unsigned v = 0; v < (unsigned)ModeValue::Count; ++v) {
    ModeValue out;
    ASSERT_TRUE(modeValueFromName(modeValueInfo((ModeValue)v).name, out));
    EXPECT_EQ((unsigned)out, v);
  }
}

TEST(Json, EscapesQuotesBackslashesAndControls) {
  std::string s;
  appendJsonEscaped(s, "a\"b\\c\nd\x01");
  EXPECT_EQ(s, "a\\\"b\\\\c\\nd\\u0001");
}

// Compiled code carries a SysRef as one double: exact at the largest tool, edge and id.
TEST(SystemVars, RefNumberRoundTrips) {
  for (SysRef r : {SysRef{SysVar::VersionMajor}, SysRef{(SysVar)(kSysVarIds - 1), kMaxToolNumber, kMaxToolNumber},
                   SysRef{(SysVar)kToolDataIds, 1, 0}}) {
    SysRef back = sysRefFromNumber(sysRefNumber(r));
    EXPECT_EQ(back.var, r.var);
    EXPECT_EQ(back.tool, r.tool);
    EXPECT_EQ(back.edge, r.edge);
  }
}

TEST(SystemVars, ToolDataIndices) {
  SysRef r = sysVarAt(SysFamily::ToolData, 12, 3, 2);
  EXPECT_EQ(sysVarInfo(r.var).family, SysFamily::ToolData);
  EXPECT_EQ(sysVarInfo(r.var).axis, (int)ToolField::LengthWear);
  EXPECT_EQ(r.tool, 12);
  EXPECT_EQ(r.edge, 3);
  EXPECT_EQ(sysVarAt(SysFamily::ToolData, 0, 1, 0).var, kNoSysVar);       // tool 0: no offsets
  EXPECT_EQ(sysVarAt(SysFamily::ToolData, 1, 1, kToolFields).var, kNoSysVar);  // no field 61
  EXPECT_EQ(sysVarAt(SysFamily::ToolData, 1.5, 1, 0).var, kNoSysVar);     // not an integer
  EXPECT_EQ(sysVarAt(SysFamily::ToolData, 100000, 1, 0).var, kNoSysVar);  // beyond the machine file's range
  SysVar v;
  EXPECT_FALSE(sysVarFromName("_tool_data_length", v));  // no flat name: it needs a tool and an edge
  EXPECT_TRUE(sysVarWritable(r.var));
}
