// Motion IR text: records -> text -> records keeps every printed field bit for bit (odd doubles,
// escapes, named numbers, normals); damaged text gives diagnostics, never a crash.
#include "ir/MotionIR.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace ncc;

namespace {

// Parses `text`; `ok` receives the result, and without it the parse must succeed. Diagnostics
// are rendered (as the driver would print them) to exercise their positions.
std::vector<MotionRecord> parse(const std::string &text, bool *ok = nullptr) {
  SourceManager sm;
  Diagnostics d(sm);
  d.setCollect(true);
  uint32_t f = sm.addBuffer("t.motion", text);
  MotionBuffer b;
  bool res = parseMotionText(sm, f, b, d);
  for (auto &x : d.collected()) EXPECT_FALSE(d.render(x).empty());
  if (ok) *ok = res;
  else EXPECT_TRUE(res) << (d.collected().empty() ? "" : d.collected()[0].message);
  return b.records;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(MotionText, RoundTripsOddNumbersAndStrings) {
  const double odd[] = {0.1 + 0.2, -0.0, 1e-310, 5e-324, 1.7976931348623157e308, -1e22, 123456789.123456789,
                        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  std::vector<MotionRecord> in;
  AxisVec pos{};
  for (double v : odd) {
    MotionRecord r;
    r.kind = RecordKind::Linear;
    r.start = pos;
    r.end = {v, -v, v / 3, 1, 2, 3};
    r.feed = v;
    r.blockNumber = 7;
    r.loc = {0, 3, 9};
    pos = r.end;
    in.push_back(r);
  }
  MotionRecord c;
  c.kind = RecordKind::Comment;
  c.text = "q\"b\\n\nt\tr\rx\x01\x7f end \xc3\xa9";
  c.text += '\0';  // a NUL byte too
  c.text += "after";
  c.start = c.end = pos;
  in.push_back(c);
  MotionRecord a;
  a.kind = RecordKind::Arc;
  a.start = pos;
  a.end = {1, 2, 3, 0, 0, 0};
  a.center = {0.1, 0.7, -3};
  a.turns = -3;
  a.feed = 250;
  a.setNormal({0, std::sqrt(0.5), std::sqrt(0.5)});
  in.push_back(a);
  MotionRecord cb;
  cb.kind = RecordKind::CycleBegin;
  cb.text = "iso.G83";
  cb.start = cb.end = a.end;
  ASSERT_TRUE(cb.setParam("X", 1.0 / 3));
  ASSERT_TRUE(cb.setParam("R_2", -0.0));
  ASSERT_FALSE(cb.setParam("toolong8", 1));
  ASSERT_FALSE(cb.setParam("9x", 1));
  in.push_back(cb);

  std::string text;
  MotionTextWriter w(text);
  for (auto &r : in) w.record(r);
  auto out = parse(text);
  ASSERT_EQ(out.size(), in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    SCOPED_TRACE(printMotionRecord(in[i]));
    EXPECT_EQ(out[i].kind, in[i].kind);
    for (int k = 0; k < kAxes; ++k) {
      EXPECT_TRUE(sameBits(out[i].start[k], in[i].start[k]));
      EXPECT_TRUE(sameBits(out[i].end[k], in[i].end[k]));
    }
    EXPECT_TRUE(sameBits(out[i].feed, in[i].feed));
    EXPECT_EQ(out[i].text, in[i].text);
    EXPECT_EQ(out[i].blockNumber, in[i].blockNumber);
    EXPECT_EQ(out[i].loc.line, in[i].loc.line);
    EXPECT_EQ(out[i].loc.col, in[i].loc.col);
    EXPECT_EQ(out[i].tiltedArc(), in[i].tiltedArc());
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(sameBits(out[i].arcNormal()[k], in[i].arcNormal()[k]));
      EXPECT_TRUE(sameBits(out[i].center[k], in[i].center[k]));
    }
    ASSERT_EQ(out[i].params().size(), in[i].params().size());
    for (size_t k = 0; k < in[i].params().size(); ++k) {
      EXPECT_EQ(out[i].params()[k].name(), in[i].params()[k].name());
      EXPECT_TRUE(sameBits(out[i].params()[k].value, in[i].params()[k].value));
    }
  }
  std::string again;
  MotionTextWriter w2(again);
  for (auto &r : out) w2.record(r);
  EXPECT_EQ(again, text);
}

TEST(MotionText, ExtraIsCopiedDeeply) {
  MotionRecord r;
  r.kind = RecordKind::FrameChange;
  r.setParam("m00", 1);
  MotionRecord copy = r;
  copy.setParam("m00", 2);
  EXPECT_EQ(*r.param("m00"), 1);
  EXPECT_EQ(*copy.param("m00"), 2);
  MotionRecord plain;
  EXPECT_EQ(plain.extra.get(), nullptr);  // ordinary records allocate nothing
  plain.kind = RecordKind::Arc;
  plain.plane = Plane::ZX;
  plain.setNormal({0, 1, 0});  // the plane's own axis: nothing stored
  EXPECT_FALSE(plain.tiltedArc());
  EXPECT_EQ(plain.extra.get(), nullptr);
  EXPECT_EQ(plain.arcNormal(), (std::array<double, 3>{0, 1, 0}));
}

TEST(MotionText, FrameMatrixAsNamedNumbers) {
  MotionRecord r;
  r.kind = RecordKind::FrameChange;
  r.text = "G68";
  FrameMatrix m{0, -1, 0, 10, 1, 0, 0, 20, 0, 0, 1, -5};
  setFrameMatrix(r, m);
  EXPECT_EQ(printMotionRecord(r),
            "frame_change \"G68\" m00=0 m01=-1 m02=0 m03=10 m10=1 m11=0 m12=0 m13=20 m20=0 m21=0 m22=1 m23=-5");
  auto back = parse(printMotionRecord(r) + "\n");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(frameMatrix(back[0]), m);
  auto partial = parse("frame_change m03=7\n");
  EXPECT_EQ(frameMatrix(partial[0]), (FrameMatrix{1, 0, 0, 7, 0, 1, 0, 0, 0, 0, 1, 0}));
}

// Damaged text (bytes flipped, lines cut) must give diagnostics or records, never a crash.
TEST(MotionText, DamagedTextNeverCrashes) {
  const std::string good =
      "rapid X1 Y2 Z3 A0 B0 C0 @1:1\n"
      "arc X1 Y2 Z3 A0 B0 C0 center(0, 0, 0) plane=xy normal=(0, 0.6, 0.8) turns=1 F100 N5 @2:1\n"
      "comment \"a\\\"b\\x41\" @3:1\n"
      "cycle_begin \"iso.G81\" X=1 Y=2 R=3 L=1 @4:1\n"
      "path_mode 2 0.01 0.005 exact_stop N7 @5:1\n"
      "aux B5 @6:1\n";
  std::mt19937 rng(42);
  const char alphabet[] = "XYZ09.-+e=()\",\\@: \nnax";
  for (int i = 0; i < 3000; ++i) {
    std::string t = good;
    int edits = 1 + (int)(rng() % 4);
    for (int k = 0; k < edits; ++k) {
      size_t at = rng() % t.size();
      switch (rng() % 3) {
      case 0: t[at] = alphabet[rng() % (sizeof alphabet - 1)]; break;
      case 1: t.erase(at, 1 + rng() % 5); break;
      default: t = t.substr(0, at) + alphabet[rng() % (sizeof alphabet - 1)] + t.substr(at); break;
      }
      if (t.empty()) t.push_back('x');
    }
    bool ok = false;
    auto records = parse(t, &ok);
    if (ok) {
      EXPECT_LE(records.size(), 6u);
    }
  }
}
