// The progress line of long runs (utils/ncc/RunOutput.h): its text, and when it is shown.
#include "utils/ncc/RunOutput.h"

#include <gtest/gtest.h>

#include <cstdio>

using ncc::driver::ProgressLine;

TEST(ProgressLine, FormatsBlocksRateAndElapsedTime) {
  EXPECT_EQ(ProgressLine::format(1234567, 2.5), "\r1,234,567 blocks  493,826 blocks/s  2.5 s\x1b[K");
  EXPECT_EQ(ProgressLine::format(999, 1.0), "\r999 blocks  999 blocks/s  1.0 s\x1b[K");
  EXPECT_EQ(ProgressLine::format(1000, 0.0), "\r1,000 blocks  0 blocks/s  0.0 s\x1b[K");
}

TEST(ProgressLine, OnlyOnATerminalAndNotQuiet) {
  EXPECT_TRUE(ProgressLine::wanted(false, true));
  EXPECT_FALSE(ProgressLine::wanted(false, false));
  EXPECT_FALSE(ProgressLine::wanted(true, true));
}

// A short run draws nothing and leaves nothing to erase: the clock is read every kCheckEvery
// records, and the line waits kDelay seconds.
TEST(ProgressLine, ShortRunPrintsNothing) {
  char buf[256] = {};
  std::FILE *f = fmemopen(buf, sizeof buf, "w");
  ProgressLine p(f);
  ncc::MotionRecord r;
  for (uint32_t i = 0; i < 3 * ProgressLine::kCheckEvery; ++i) {
    r.loc = {1, i + 1, 1};
    p.record(r);
  }
  ncc::SourceManager sm;
  ncc::Diagnostics diags(sm);
  EXPECT_TRUE(p.finish(diags));
  std::fclose(f);
  EXPECT_STREQ(buf, "");
}
