#include "ir/NCIR.h"
#include "ir/ModeTable.h"
#include "ir/Diagnostics.h"
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
