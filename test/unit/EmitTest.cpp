// Program emitters: hand-built Motion IR streams -> exact ISO / Sinumerik text.
#include "backends/emit/ArcGeometry.h"
#include "backends/emit/Emitter.h"
#include "backends/emit/WordFormat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ncc;
using namespace ncc::emit;

namespace {

// Builds a record stream the way the executor does: each motion starts where the last ended.
struct Stream {
  std::vector<MotionRecord> recs;
  AxisVec pos{};

  MotionRecord &add(RecordKind k) {
    recs.emplace_back();
    recs.back().kind = k;
    return recs.back();
  }
  void state(RecordKind k, int64_t iv = 0, double v = 0) {
    MotionRecord &r = add(k);
    r.ivalue = iv;
    r.value = v;
  }
  void text(RecordKind k, std::string t) { add(k).text = std::move(t); }
  MotionRecord &move(RecordKind k, double x, double y, double z, double feed = 0) {
    MotionRecord &r = add(k);
    r.start = pos;
    r.end = pos;
    r.end[0] = x, r.end[1] = y, r.end[2] = z;
    r.feed = feed;
    pos = r.end;
    return r;
  }
  MotionRecord &arc(double x, double y, double z, double cx, double cy, double cz, int turns,
                    Plane p = Plane::XY, double feed = 100) {
    MotionRecord &r = move(RecordKind::Arc, x, y, z, feed);
    r.center = {cx, cy, cz};
    r.turns = turns;
    r.plane = p;
    return r;
  }
};

struct Emit {
  SourceManager sm;
  Diagnostics diags{sm};
  Machine machine;
  Emit() { diags.setCollect(true); }

  std::string run(Target t, const Stream &s, std::string name = "", bool comments = true) {
    EmitOptions o;
    o.target = t;
    o.programName = std::move(name);
    o.comments = comments;
    std::string out;
    ok = emitProgram(machine, o, s.recs, out, diags);
    return out;
  }
  void set(const char *section, const char *key, const char *value) { machine.sections[section][key] = value; }
  bool ok = false;
};

Stream basicStream() {
  Stream s;
  s.move(RecordKind::Rapid, 10, 20, 5);
  s.state(RecordKind::FeedRate, 0, 200);
  s.move(RecordKind::Linear, 10, 20, -1, 200);
  s.move(RecordKind::Linear, 30, 20, -1, 200);
  s.move(RecordKind::Linear, 30.25, 20.0004, -1, 200);
  s.state(RecordKind::ProgramEnd, 30);
  return s;
}

}  // namespace

TEST(EmitWordFormat, Numbers) {
  NumberFormat f;
  std::string s;
  f.pointOnInteger = true;
  ASSERT_TRUE(formatNumber(10, f, s));
  EXPECT_EQ(s, "10.");
  ASSERT_TRUE(formatNumber(-0.25, f, s));
  EXPECT_EQ(s, "-0.25");
  ASSERT_TRUE(formatNumber(-0.0004, f, s));
  EXPECT_EQ(s, "0.");  // no negative zero
  ASSERT_TRUE(formatNumber(1.0005, f, s));
  EXPECT_EQ(s, "1.001");  // half away from zero
  f.pointOnInteger = false;
  ASSERT_TRUE(formatNumber(10, f, s));
  EXPECT_EQ(s, "10");
  f.trailingZeros = true;
  ASSERT_TRUE(formatNumber(12.5, f, s));
  EXPECT_EQ(s, "12.500");
  f.trailingZeros = false;
  f.leadingZero = false;
  f.plusSign = true;
  ASSERT_TRUE(formatNumber(0.5, f, s));
  EXPECT_EQ(s, "+.5");
  f.maxIntDigits = 4;
  EXPECT_FALSE(formatNumber(12345.5, f, s));
  EXPECT_FALSE(formatNumber(NAN, f, s));
  EXPECT_FALSE(formatNumber(INFINITY, f, s));
  EXPECT_FALSE(formatNumber(1e300, NumberFormat{}, s));
  EXPECT_EQ(formatInteger(7, 4), "0007");
  EXPECT_EQ(formatInteger(-7, 3), "-007");
  EXPECT_EQ(sanitizeText(" a (b)\tc ", "()", "[]"), "a [b] c");
}

TEST(EmitTarget, Names) {
  Target t;
  ASSERT_TRUE(targetFromName("ISO", t));
  EXPECT_EQ(t, Target::ISO);
  ASSERT_TRUE(targetFromName("sinumerik", t));
  EXPECT_EQ(t, Target::Sinumerik);
  ASSERT_TRUE(targetFromName("Siemens", t));
  for (const char *n : {"heidenhain", "Klartext", "TNC"}) {
    ASSERT_TRUE(targetFromName(n, t)) << n;
    EXPECT_EQ(t, Target::Heidenhain);
  }
  EXPECT_STREQ(targetName(Target::Heidenhain), "heidenhain");
  ASSERT_TRUE(targetFromName("APT", t));
  EXPECT_EQ(t, Target::Apt);
  for (const char *n : {"cldata", "ADEM"}) {
    ASSERT_TRUE(targetFromName(n, t)) << n;
    EXPECT_EQ(t, Target::Adem);
  }
  // The names --verify gives the driver as the dialect of the re-read output.
  EXPECT_STREQ(targetName(Target::Apt), "apt");
  EXPECT_STREQ(targetName(Target::Adem), "adem");
  EXPECT_FALSE(targetFromName("fanuc-klartext", t));
}

TEST(EmitISO, HeaderModalSuppressionAndEnd) {
  Emit e;
  EXPECT_EQ(e.run(Target::ISO, basicStream()),
            "%\nO0001\nG21\nG90 G17 G94 G54\n"
            "G0 X10. Y20. Z5.\n"
            "G1 Z-1. F200.\n"
            "X30.\n"
            "X30.25\n"
            "M30\n%\n");
  EXPECT_TRUE(e.ok);
  EXPECT_EQ(e.diags.collected().size(), 0u);
}

TEST(EmitISO, ProgramNumberAndName) {
  Emit e;
  Stream s;
  s.state(RecordKind::ProgramEnd, 2);
  EXPECT_EQ(e.run(Target::ISO, s, "1234"), "%\nO1234\nG21\nG90 G17 G94 G54\nM2\n%\n");
  EXPECT_EQ(e.run(Target::ISO, s, "part(1)"), "%\nO0001 (part[1])\nG21\nG90 G17 G94 G54\nM2\n%\n");
}

TEST(EmitSinumerik, HeaderNumberingModalSuppression) {
  Emit e;
  EXPECT_EQ(e.run(Target::Sinumerik, basicStream(), "PART1"),
            "; PART1\n"
            "N10 G71 G90 G17 G94 G54\n"
            "N20 G0 X10 Y20 Z5\n"
            "N30 G1 Z-1 F200\n"
            "N40 X30\n"
            "N50 X30.25\n"
            "N60 M30\n");
}

TEST(EmitISO, BlockNumberingSettings) {
  Emit e;
  e.set("emit.iso", "block_numbers", "renumber");
  e.set("emit.iso", "block_start", "100");
  e.set("emit.iso", "block_step", "5");
  e.set("emit.iso", "end_of_block", "semicolon");
  Stream s;
  s.text(RecordKind::Comment, "not numbered");
  s.move(RecordKind::Rapid, 1, 0, 0);
  EXPECT_EQ(e.run(Target::ISO, s),
            "%\nO0001\nN100 G21;\nN105 G90 G17 G94 G54;\n(not numbered)\nN110 G0 X1.;\nN115 M30;\n%\n");
  EXPECT_TRUE(e.ok);
}

TEST(EmitSinumerik, SourceBlockNumbersAndNoNumbers) {
  Emit e;
  e.set("emit.sinumerik", "block_numbers", "source");
  Stream s;
  s.move(RecordKind::Rapid, 1, 0, 0).blockNumber = 7;
  s.move(RecordKind::Rapid, 2, 0, 0);
  EXPECT_EQ(e.run(Target::Sinumerik, s), "G71 G90 G17 G94 G54\nN7 G0 X1\nX2\nM30\n");
  e.set("emit.sinumerik", "block_numbers", "off");
  EXPECT_EQ(e.run(Target::Sinumerik, s), "G71 G90 G17 G94 G54\nG0 X1\nX2\nM30\n");
}

TEST(EmitISO, ArcIJKAndRadiusForms) {
  Stream s;
  s.move(RecordKind::Rapid, 10, 0, 0);
  s.arc(0, 10, 0, 0, 0, 0, 1);    // 90 deg ccw
  s.arc(10, 0, 0, 0, 0, 0, -1);   // 90 deg cw back
  s.arc(0, 10, 0, 0, 0, 0, -1);   // 270 deg cw
  s.arc(0, 10, 0, 0, 0, 0, 1);    // full circle ccw
  Emit ijk;
  EXPECT_EQ(ijk.run(Target::ISO, s),
            "%\nO0001\nG21\nG90 G17 G94 G54\n"
            "G0 X10.\n"
            "G3 X0. Y10. I-10. J0. F100.\n"
            "G2 X10. Y0. I0. J-10.\n"
            "X0. Y10. I-10. J0.\n"
            "G3 I0. J-10.\n"
            "M30\n%\n");
  Emit r;
  r.set("emit.iso", "arc_style", "r");
  EXPECT_EQ(r.run(Target::ISO, s),
            "%\nO0001\nG21\nG90 G17 G94 G54\n"
            "G0 X10.\n"
            "G3 X0. Y10. R10. F100.\n"
            "G2 X10. Y0. R10.\n"
            "X0. Y10. R-10.\n"
            "G3 I0. J-10.\n"  // a full circle cannot be written with R
            "M30\n%\n");
}

TEST(EmitSinumerik, ArcRadiusAndHelixTurns) {
  Stream s;
  s.move(RecordKind::Rapid, 10, 0, 0);
  s.arc(-10, 0, -2, 0, 0, 0, 1);   // half turn helix
  s.arc(-10, 0, -8, 0, 0, 0, -3);  // two extra full turns, clockwise
  Emit e;
  e.set("emit.sinumerik", "arc_style", "r");
  e.set("emit.sinumerik", "block_numbers", "off");
  EXPECT_EQ(e.run(Target::Sinumerik, s),
            "G71 G90 G17 G94 G54\n"
            "G0 X10\n"
            "G3 X-10 Z-2 CR=10 F100\n"
            "G2 Z-8 I10 J0 TURN=2\n"
            "M30\n");
}

TEST(EmitISO, MultiTurnHelixPWordOrSplit) {
  Stream s;
  s.move(RecordKind::Rapid, 10, 0, 0);
  s.arc(-10, 0, -5, 0, 0, 0, 3);  // 2.5 turns ccw, 5 mm down: 2 mm per turn
  Emit w;
  EXPECT_EQ(w.run(Target::ISO, s),
            "%\nO0001\nG21\nG90 G17 G94 G54\nG0 X10.\nG3 X-10. Z-5. I-10. J0. P3 F100.\nM30\n%\n");
  Emit e;
  e.set("emit.iso", "helix_turns", "split");
  EXPECT_EQ(e.run(Target::ISO, s),
            "%\nO0001\nG21\nG90 G17 G94 G54\n"
            "G0 X10.\n"
            "G3 Z-2. I-10. J0. F100.\n"
            "Z-4. I-10. J0.\n"
            "X-10. Z-5. I-10. J0.\n"
            "M30\n%\n");
}

TEST(EmitISO, ArcInZXPlaneAndPlaneRecords) {
  Stream s;
  s.move(RecordKind::Rapid, 10, 0, 0);
  s.state(RecordKind::Plane, (int64_t)Plane::ZX);
  s.arc(0, 0, 10, 0, 0, 0, -1, Plane::ZX);  // from Z0 X10 clockwise (seen from +Y) to Z10 X0
  s.state(RecordKind::Plane, (int64_t)Plane::YZ);
  s.arc(0, 5, 15, 0, 0, 15, 1, Plane::YZ, 100);
  s.state(RecordKind::Plane, (int64_t)Plane::XY);
  s.move(RecordKind::Linear, 0, 0, 0, 100);
  Emit e;
  EXPECT_EQ(e.run(Target::ISO, s),
            "%\nO0001\nG21\nG90 G17 G94 G54\n"
            "G0 X10.\n"
            "G18\n"
            "G2 X0. Z10. I-10. K0. F100.\n"
            "G19\n"
            "G3 Y5. Z15. J0. K5.\n"
            "G17\n"
            "G1 Y0. Z0.\n"
            "M30\n%\n");
}

TEST(EmitISO, PlaneFromArcRecordWithoutPlaneRecord) {
  Stream s;
  s.arc(0, 0, 0, 5, 0, 0, 1, Plane::ZX);  // full circle, centre 5 mm along X
  Emit e;
  e.set("emit.iso", "program_header", "none");
  e.set("emit.iso", "program_footer", "none");
  e.set("emit.iso", "program_number", "no");
  e.set("emit.iso", "setup_blocks", "G21 | G90");
  EXPECT_EQ(e.run(Target::ISO, s), "G21\nG90\nG18 G3 I5. K0. F100.\nM30\n");
}

TEST(EmitISO, TinyArcBecomesLine) {
  Stream s;
  s.move(RecordKind::Rapid, 10, 0, 0);
  double a = 1e-5;  // 0.1 micrometre of arc: rounds to the start point
  s.arc(10 * std::cos(a), 10 * std::sin(a), 0, 0, 0, 0, 1);
  Emit e;
  e.set("emit.iso", "setup_blocks", "none");
  std::string out = e.run(Target::ISO, s);
  EXPECT_NE(out.find("G1 X10. F100.\n"), std::string::npos) << out;
  EXPECT_EQ(out.find("G3"), std::string::npos) << out;
}

// How a controller places the centre of an R-form arc.
static bool centerFromRadiusForTest(const double s[2], const double e[2], double r, bool ccw, double out[2]) {
  double mx = (s[0] + e[0]) / 2, my = (s[1] + e[1]) / 2, dx = e[0] - s[0], dy = e[1] - s[1];
  double chord = std::hypot(dx, dy), h2 = r * r - chord * chord / 4;
  if (chord == 0 || h2 < 0) return false;
  // Seen along the chord, a short counter-clockwise arc has its centre on the left.
  double side = ((r > 0) == ccw) ? 1 : -1, h = std::sqrt(h2);
  out[0] = mx - dy / chord * h * side;
  out[1] = my + dx / chord * h * side;
  return true;
}

TEST(EmitISO, ArcCentreIsConsistentAfterRounding) {
  // Random arcs with irrational coordinates. After rounding the end points to 0.001 mm and the
  // centre offsets to 0.001 or 0.0001 mm, the two radii must pass the controller's 0.002 mm arc check and
  // the written path (radius blended from start to end) must stay within 0.002 mm of an exact
  // original circle; the R form, where chosen, likewise.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-500, 500), rad(0.01, 300), ang(0, 6.283185307179586);
  for (int decimals : {3, 4}) {
  NumberFormat cf;
  cf.decimals = decimals;
  int radiusForms = 0;
  for (int i = 0; i < 20000; ++i) {
    double c[2] = {pos(rng), pos(rng)}, r = rad(rng), a0 = ang(rng), a1 = ang(rng);
    // Exact circle points, or points already 0.0015 mm off radius (accepted by the source run).
    double r1 = i % 3 == 0 && r > 1 ? r + 0.0015 : r;
    double s[2] = {roundTo(c[0] + r * std::cos(a0), 3), roundTo(c[1] + r * std::sin(a0), 3)};
    double e[2] = {roundTo(c[0] + r1 * std::cos(a1), 3), roundTo(c[1] + r1 * std::sin(a1), 3)};
    bool full = s[0] == e[0] && s[1] == e[1];
    bool ccw = i % 2;
    for (bool preferR : {false, true}) {
      ArcWords w = planArc(s, e, c, ccw, full, preferR, cf, 0.002);
      double cc[2] = {s[0] + w.offset[0], s[1] + w.offset[1]};
      if (w.useRadius) {
        ++radiusForms;
        ASSERT_FALSE(full);
        ASSERT_TRUE(centerFromRadiusForTest(s, e, w.radius, ccw, cc)) << i;
      }
      double rs = std::hypot(s[0] - cc[0], s[1] - cc[1]), re = std::hypot(e[0] - cc[0], e[1] - cc[1]);
      ASSERT_LT(std::fabs(rs - re), 0.002) << i;
      double sweep = sweepAngle(s, e, cc, ccw), a = std::atan2(s[1] - cc[1], s[0] - cc[0]);
      if (w.useRadius) {
        ASSERT_EQ(w.radius < 0, sweep > 3.14159265358979323846) << i;
      }
      for (int k = 0; k <= 16; ++k) {
        double t = a + (ccw ? 1 : -1) * sweep * k / 16, rho = rs + (re - rs) * k / 16;
        double p[2] = {cc[0] + rho * std::cos(t), cc[1] + rho * std::sin(t)};
        double dev = std::fabs(std::hypot(p[0] - c[0], p[1] - c[1]) - (r + (r1 - r) * k / 16));
        // A source arc already near the tolerance may need its centre moved (docs/EMIT.md), so
        // only exact arcs are held to the path bound.
        if (r1 == r) {
          ASSERT_LT(dev, 0.002) << i << " k=" << k << " r=" << r << " sweep=" << sweep;
        }
      }
    }
  }
  // R is the common case with 4 decimals; with 3 the rebuilt centre moves more often.
  EXPECT_GT(radiusForms, decimals == 4 ? 10000 : 4000) << decimals;
  }
}

TEST(EmitISO, DwellForms) {
  Stream s;
  s.state(RecordKind::Dwell, 0, 2.5);
  s.state(RecordKind::Dwell, 0, 3);
  Emit x;
  x.set("emit.iso", "setup_blocks", "none");
  EXPECT_EQ(x.run(Target::ISO, s), "%\nO0001\nG4 X2.5\nG4 X3.\nM30\n%\n");
  Emit p;
  p.set("emit.iso", "setup_blocks", "none");
  p.set("emit.iso", "dwell_word", "P");
  p.set("emit.iso", "dwell_unit", "ms");
  EXPECT_EQ(p.run(Target::ISO, s), "%\nO0001\nG4 P2500\nG4 P3000\nM30\n%\n");
  Emit sin;
  sin.set("emit.sinumerik", "setup_blocks", "none");
  EXPECT_EQ(sin.run(Target::Sinumerik, s), "N10 G4 F2.5\nN20 G4 F3\nN30 M30\n");
}

TEST(EmitBoth, ToolSpindleCoolant) {
  Stream s;
  s.state(RecordKind::ToolSelect, 3);
  s.state(RecordKind::ToolChange, 3);
  s.state(RecordKind::ToolLength, 0, 42.5);  // no H number: the length stays in the positions
  s.state(RecordKind::SpindleSpeed, 0, 1200);
  s.state(RecordKind::SpindleCW);
  s.state(RecordKind::CoolantFlood, 1);
  s.move(RecordKind::Rapid, 0, 0, 5);
  s.state(RecordKind::ToolSelect, 4);  // prepared, changed later
  s.state(RecordKind::CoolantMist, 1);
  s.state(RecordKind::CoolantFlood, 0);  // M9 drops mist too: switch it back on, in a block of its own
  s.state(RecordKind::SpindleStop);
  s.state(RecordKind::ToolChange, 4);
  s.state(RecordKind::CoolantFlood, 0);  // M9 = both off: one code
  s.state(RecordKind::CoolantMist, 0);
  s.state(RecordKind::SpindleSpeed, 0, 800.5);
  s.state(RecordKind::SpindleCCW);
  Emit iso;
  iso.set("emit.iso", "setup_blocks", "none");
  EXPECT_EQ(iso.run(Target::ISO, s),
            "%\nO0001\n"
            "T3 M6\n"
            "S1200 M3 M8\n"
            "(ncc: from here the positions include the tool length: no code for it on this target)\n"
            "G0 Z5.\n"
            "T4 M5 M9\n"
            "M7\n"
            "M6\n"
            "S800.5 M4 M9\n"
            "M30\n%\n");
  Emit sin;
  sin.set("emit.sinumerik", "setup_blocks", "none");
  sin.set("emit.sinumerik", "block_numbers", "off");
  EXPECT_EQ(sin.run(Target::Sinumerik, s),
            "T3 D0 M6\n"
            "S1200 M3 M8\n"
            "; ncc: from here the positions include the tool length: no code for it on this target\n"
            "G0 Z5\n"
            "T4 M5 M9\n"
            "M7\n"
            "D0 M6\n"
            "S800.5 M4 M9\n"
            "M30\n");
}

TEST(EmitBoth, CommentsAndMessages) {
  Stream s;
  s.text(RecordKind::Comment, "drill (deep) hole");
  s.text(RecordKind::Message, "check \"tool\" (T3)");
  Emit iso;
  iso.set("emit.iso", "setup_blocks", "none");
  EXPECT_EQ(iso.run(Target::ISO, s), "%\nO0001\n(drill [deep] hole)\n(MSG, check \"tool\" [T3])\nM30\n%\n");
  Stream msgLike;
  msgLike.text(RecordKind::Comment, "msg,not a message");
  EXPECT_EQ(iso.run(Target::ISO, msgLike), "%\nO0001\n(msg ,not a message)\nM30\n%\n");
  EXPECT_EQ(iso.run(Target::ISO, s, "", false), "%\nO0001\n(MSG, check \"tool\" [T3])\nM30\n%\n");
  Emit sin;
  sin.set("emit.sinumerik", "setup_blocks", "none");
  EXPECT_EQ(sin.run(Target::Sinumerik, s), "; drill (deep) hole\nN10 MSG(\"check 'tool' (T3)\")\nN20 M30\n");
}

TEST(EmitBoth, FeedModesStopsAuxExactStop) {
  Stream s;
  s.state(RecordKind::FeedMode, 1);
  s.state(RecordKind::FeedRate, 0, 0.15);
  s.move(RecordKind::Linear, 5, 0, 0, 150);
  s.move(RecordKind::Linear, 6, 0, 0, 150).exactStop = true;
  s.state(RecordKind::FeedMode, 2);  // inverse time: the executor's rates are mm/min
  s.state(RecordKind::FeedRate, 0, 2);
  s.move(RecordKind::Linear, 7, 0, 0, 2);  // 1 mm at 2 mm/min: half a minute, F2
  s.state(RecordKind::FeedRate, 0, 4);
  s.move(RecordKind::Linear, 8, 0, 0, 4);
  s.arc(18, 10, 0, 8, 10, 0, 1, Plane::XY, 10 * 3.14159265358979323846 / 2 * 3);  // quarter, r 10: F3
  s.arc(18, 10, -4, 8, 10, 0, 2, Plane::XY, std::hypot(10 * 3.14159265358979323846 * 4, 4) * 0.5);  // two turns: F0.5
  s.state(RecordKind::FeedMode, 0);
  s.state(RecordKind::PathMode, 1);
  s.state(RecordKind::FeedRate, 0, 300);
  s.move(RecordKind::Linear, 18, 10, -4, 300).exactStop = true;  // zero length: still written
  s.state(RecordKind::OptionalStop);
  s.state(RecordKind::ProgramStop);
  s.state(RecordKind::Aux, 123);
  Emit e;
  e.set("emit.iso", "setup_blocks", "none");
  e.set("emit.iso", "code_exact_stop_once", "G9");
  EXPECT_EQ(e.run(Target::ISO, s),
            "%\nO0001\n"
            "G95\n"
            "G1 X5. F0.15\n"
            "G9 X6.\n"
            "G93\n"
            "X7. F2.\n"
            "X8. F4.\n"
            "G3 X18. Y10. I0. J10. F3.\n"
            "Z-4. I-10. J0. P2 F0.5\n"
            "G94 G61\n"
            "G1 X18. F300.\n"
            "M1\nM0\nM123\nM30\n%\n");
}

TEST(EmitBoth, RotaryAxesAndNoProgramEnd) {
  Stream s;
  MotionRecord &r = s.move(RecordKind::Linear, 1, 2, 3, 500);
  r.end[3] = 90;
  r.end[5] = -45.5;
  Emit e;
  e.set("emit.sinumerik", "setup_blocks", "none");
  EXPECT_EQ(e.run(Target::Sinumerik, s), "N10 G1 X1 Y2 Z3 A90 C-45.5 F500\nN20 M30\n");
}

TEST(EmitBoth, BadValuesAreDiagnosed) {
  Stream s;
  s.move(RecordKind::Linear, NAN, 0, 0, 100);
  Emit e;
  std::string out = e.run(Target::ISO, s);
  EXPECT_FALSE(e.ok);
  ASSERT_GE(e.diags.collected().size(), 1u);
  EXPECT_NE(e.diags.collected()[0].message.find("cannot write X"), std::string::npos);

  Stream dw;
  dw.state(RecordKind::Dwell, 0, NAN);
  Emit d0;
  d0.run(Target::Sinumerik, dw);
  EXPECT_FALSE(d0.ok);
  ASSERT_GE(d0.diags.collected().size(), 1u);
  EXPECT_NE(d0.diags.collected()[0].message.find("cannot write F"), std::string::npos);

  Stream big;
  big.move(RecordKind::Rapid, 123456, 0, 0);
  Emit d;
  d.set("emit.iso", "axis_max_digits", "5");
  d.run(Target::ISO, big);
  EXPECT_FALSE(d.ok);
}

TEST(EmitBoth, MachineSectionErrorsAndWarnings) {
  Emit e;
  e.set("emit.iso", "arc_style", "spline");
  e.set("emit.iso", "colour", "red");
  EmitOptions o;
  std::string out;
  EXPECT_EQ(ProgramEmitter::create(e.machine, o, out, e.diags), nullptr);
  ASSERT_EQ(e.diags.collected().size(), 2u);
  EXPECT_EQ(e.diags.errorCount(), 1u);
  EXPECT_NE(e.diags.collected()[0].message.find("arc_style = 'spline'"), std::string::npos);
  EXPECT_NE(e.diags.collected()[1].message.find("unknown key 'colour'"), std::string::npos);
}

TEST(EmitBoth, FormatAndCodeOverrides) {
  Emit e;
  e.set("emit.iso", "setup_blocks", "none");
  e.set("emit.iso", "trailing_zeros", "yes");
  e.set("emit.iso", "feed_decimals", "0");
  e.set("emit.iso", "feed_point_on_integer", "no");
  e.set("emit.iso", "code_rapid", "G00");
  e.set("emit.iso", "code_linear", "G01");
  e.set("emit.iso", "tool_digits", "2");
  Stream s;
  s.state(RecordKind::ToolSelect, 5);
  s.move(RecordKind::Rapid, 1.5, 0, 0);
  s.move(RecordKind::Linear, 2, 0, 0, 99.6);
  // Without set-up blocks the controller's reset selection (G54) is taken to be in force.
  EXPECT_EQ(e.run(Target::ISO, s), "%\nO0001\nT05\nG00 X1.500\nG01 X2.000 F100\nM30\n%\n");
}

TEST(EmitBoth, StreamsToFile) {
  std::FILE *f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  SourceManager sm;
  Diagnostics diags(sm);
  EmitOptions o;
  o.target = Target::Sinumerik;
  Machine m;
  auto e = ProgramEmitter::create(m, o, f, diags);
  ASSERT_NE(e, nullptr);
  for (const MotionRecord &r : basicStream().recs) e->record(r);
  ASSERT_TRUE(e->finish(diags));
  EXPECT_EQ(e->blocksWritten(), 6u);
  std::rewind(f);
  char buf[512] = {};
  size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  EXPECT_EQ(std::string(buf, n),
            "N10 G71 G90 G17 G94 G54\nN20 G0 X10 Y20 Z5\nN30 G1 Z-1 F200\nN40 X30\nN50 X30.25\nN60 M30\n");
}

TEST(EmitBoth, DefaultMillFileKeys) {
  // The [emit.*] keys of runtime/machines/default-mill.toml (format.<LETTER>, program_header,
  // program_footer, block_numbers = true, block_every, line_ending).
  Stream s;
  s.move(RecordKind::Rapid, 1.23456, 0, 0);
  s.state(RecordKind::FeedRate, 0, 99.96);
  s.move(RecordKind::Linear, 2, 0, 0, 99.96);
  s.state(RecordKind::ProgramEnd, 30);
  Emit e;
  for (auto [k, v] : {std::pair{"block_numbers", "true"}, {"block_start", "10"}, {"block_step", "10"},
                      {"block_every", "2"}, {"program_header", "; ncc output"}, {"program_footer", "M30"},
                      {"format.X", "2"}, {"format.F", "1"}, {"format.CR", "3"}, {"line_ending", "crlf"}})
    e.set("emit.sinumerik", k, v);
  EXPECT_EQ(e.run(Target::Sinumerik, s, "parts/1234.mpf"),
            "; ncc output\r\n; 1234.mpf\r\nN10 G71 G90 G17 G94 G54\r\nG0 X1.23\r\nN20 G1 X2 F100\r\nM30\r\n");
  EXPECT_TRUE(e.ok);
  EXPECT_EQ(e.diags.warningCount(), 0u);
  // Without an end record the footer's M30 ends the program.
  s.recs.pop_back();
  EXPECT_EQ(e.run(Target::Sinumerik, s, ""),
            "; ncc output\r\nN10 G71 G90 G17 G94 G54\r\nG0 X1.23\r\nN20 G1 X2 F100\r\nM30\r\n");
  Emit iso;
  iso.set("emit.iso", "block_numbers", "false");
  EXPECT_EQ(iso.run(Target::ISO, s, "/x/1234.nc"), "%\nO1234\nG21\nG90 G17 G94 G54\nG0 X1.235\nG1 X2. F99.96\nM30\n%\n");
}

// Lathes (docs/EMIT.md "Lathes"): X words are diameters under diameter programming, the
// unchanged test works on the written diameter, arc centres stay radii; system A codes.
TEST(EmitLathe, DiametersToolsAndSpeedLimit) {
  Emit e;
  e.machine.controller.kind = "lathe";
  e.machine.controller.diameterProgramming = true;
  Stream s;
  s.state(RecordKind::ToolSelect, 3);
  s.state(RecordKind::ToolChange, 3);
  s.add(RecordKind::SpindleMode).ivalue = 0, s.recs.back().value = 2000;
  s.add(RecordKind::SpindleMode).ivalue = 1, s.recs.back().value = 2000;
  s.state(RecordKind::SpindleSpeed, 0, 150);
  s.state(RecordKind::FeedMode, 1);
  s.state(RecordKind::FeedRate, 0, 0.15);
  s.move(RecordKind::Rapid, 10.0003, 0, 2);
  s.move(RecordKind::Linear, 10.0004, 0, -5, 100);  // 20.0008 is written X20.001 again: not repeated
  s.arc(12.0004, 0, -7, 10.0004, 0, -7, 1, Plane::ZX);
  s.state(RecordKind::ProgramEnd, 30);
  std::string out = e.run(Target::ISO, s);
  ASSERT_TRUE(e.ok) << out;
  EXPECT_EQ(out, "%\nO0001\nG21\nG18 G98 G54\nT0300\nG50 S2000\nG96 S150 G99\nG0 X20.001 Z2.\nG1 Z-5. F0.15\n"
                 "G3 X24.001 Z-7. I-0.0001 K-2.\nM30\n%\n");  // I from the start the controller reads (20.001 / 2)
  // Tools above 99 have no T<tt>00 form; inverse time no code.
  Stream big;
  big.state(RecordKind::ToolSelect, 120);
  big.state(RecordKind::FeedMode, 2);
  e.run(Target::ISO, big);
  EXPECT_FALSE(e.ok);
}
