// The number -> system variable map (ir/SystemParams.h) the ISO front end and both engines share.
#include "ir/SystemParams.h"

#include <gtest/gtest.h>

namespace {
using namespace ncc;

TEST(SystemParams, BuiltinNamesTheMap) {
  for (int i = 0; i < (int)ParamMap::Count; ++i) {
    ParamMap m;
    ASSERT_TRUE(paramMapFromBuiltin(paramMapBuiltin((ParamMap)i), m));
    EXPECT_EQ(m, (ParamMap)i);
  }
  ParamMap m;
  EXPECT_FALSE(paramMapFromBuiltin("SIN", m));
}

// The inline JIT test (plainRanges) and plainParameter are one table.
TEST(SystemParams, PlainRangesAgreeWithPlainParameter) {
  for (int i = 0; i < (int)ParamMap::Count; ++i) {
    const PlainRange *r = plainRanges((ParamMap)i);
    for (double n = -2; n < 15000; ++n) {
      bool in = false;
      for (int k = 0; k < kPlainRanges; ++k) in = in || (n >= r[k].first && n <= r[k].last);
      ASSERT_EQ(in, plainParameter((ParamMap)i, n)) << "map " << i << " #" << n;
      if (in) ASSERT_EQ(classifyParameter((ParamMap)i, (long)n).kind, SystemParam::Plain);
    }
  }
  EXPECT_EQ(plainRangesText(ParamMap::Rs274), "#0-#5000 or #5599-#5601");
}

TEST(SystemParams, NumbersByMap) {
  SystemParam p = classifyParameter(ParamMap::Rs274, 5250);  // G55 R
  ASSERT_EQ(p.kind, SystemParam::System);
  EXPECT_EQ(p.var.var, sysVarOf(SysFamily::WorkOffset, 2, 6));
  EXPECT_EQ(p.what, "work offset 2 R");
  EXPECT_EQ(classifyParameter(ParamMap::MacroB, 5250).kind, SystemParam::Unsupported);  // Fanuc G55 has no R
  p = classifyParameter(ParamMap::MacroBMemoryC, 2203);  // H3 geometry
  ASSERT_EQ(p.kind, SystemParam::System);
  EXPECT_EQ(p.var.tool, 3);
  EXPECT_EQ(p.var.var, sysVarOf(SysFamily::ToolData, 0, (int)ToolField::Length));
  EXPECT_EQ(classifyParameter(ParamMap::MacroB, 2203).kind, SystemParam::Unsupported);
  EXPECT_NE(classifyParameter(ParamMap::MacroBLathe, 2203).what.find("lathe"), std::string::npos);
  EXPECT_EQ(classifyParameter(ParamMap::MacroB, 3000).kind, SystemParam::Alarm);
  EXPECT_EQ(classifyParameter(ParamMap::Rs274, 3000).kind, SystemParam::Plain);
  EXPECT_EQ(classifyParameter(ParamMap::MacroB, 5021).var.var, sysVarOf(SysFamily::MachinePos, 0, 0));
  EXPECT_EQ(parameterNumber(5220.6), 5221);
  EXPECT_EQ(parameterNumber(1e300), 1e9);
}

// A sink that answers reads with the id and records writes.
struct Recorder : CmdSink {
  SysRef written;
  double value = 0;
  bool exec(const MachineCmd &) override { return true; }
  bool readSystem(const SysRef &v, double &out, std::string &) override {
    out = (double)v.var;
    return true;
  }
  bool writeSystem(const SysRef &v, double x, SourceLoc, std::string &) override {
    written = v;
    value = x;
    return true;
  }
};

TEST(SystemParams, AccessThroughTheSink) {
  Recorder sink;
  ValuePool pool;
  std::string err;
  double v = 0;
  ASSERT_TRUE(accessSystemParameter(sink, pool, ParamMap::Rs274, 5420, ParamAccess::Read, v, {}, err)) << err;
  EXPECT_EQ(v, (double)SysVar::PosX);
  v = 2.5;
  ASSERT_TRUE(accessSystemParameter(sink, pool, ParamMap::Rs274, 5241, ParamAccess::Write, v, {}, err)) << err;
  EXPECT_EQ(sink.written.var, sysVarOf(SysFamily::WorkOffset, 2, 0));
  EXPECT_EQ(sink.value, 2.5);
  EXPECT_FALSE(accessSystemParameter(sink, pool, ParamMap::Rs274, 5420, ParamAccess::Write, v, {}, err));
  EXPECT_EQ(err, "#5420 (current X) is read-only");
  EXPECT_FALSE(accessSystemParameter(sink, pool, ParamMap::Rs274, 5241, ParamAccess::Reference, v, {}, err));
  EXPECT_EQ(err, "#5241 (work offset 2 X) is controller state: it cannot be passed by reference");
  EXPECT_FALSE(accessSystemParameter(sink, pool, ParamMap::MacroB, 3006, ParamAccess::Write, v, {}, err));
  EXPECT_EQ(err, "#3006 (alarm and message stop) can only be assigned with a constant number");
  EXPECT_FALSE(accessSystemParameter(sink, pool, ParamMap::Rs274, 7000, ParamAccess::Read, v, {}, err));
  EXPECT_EQ(err, "parameter #7000 is out of range (rs274 has #1-#5602)");
}

}  // namespace
