// The datum cycles 408-419 (L17426-L20346): the feature each probes (ProbeSteps.cpp), the
// results Q151-Q160, then the datum (Gen::datum, with Q381=1 the probe axis too).
#include "frontend/heidenhain/ProbeCycles.h"

namespace ncc::hei::probe {

namespace {
// After the plane points: the probe-axis datum probing (Q381), then the results and the datum.
void datumAndAxis(Gen &g, E mx, E my, const char *valX = "Q331", const char *valY = "Q332") {
  g.axisDatumProbe();
  g.datum(std::move(mx), std::move(my), g.axisDatumZ(), valX, valY);
}

// 408 SLOT CENTRE (L17486-L17721) / 409 RIDGE CENTRE (L17722-L17934): two points across the
// width Q311 about (Q321, Q322) along Q272, the − side first [model]: in the slot from inside
// outward, between them by Q301; on the ridge from outside inward, always over Q260 (409 has no
// Q301). Q166 the width, Q157 the centre line; the datum Q405 in the measuring axis.
bool width(ProbeCall &c, bool slot) {
  Gen g(c);
  int axis;
  if (!literalChoice(c, "Q272", {1, 2}, "the measuring axis", axis)) return false;
  g.begin();
  double s = slot ? 1 : -1;
  E half = dv(g.p("Q311"), n(2));
  for (int k = 1; k <= 2; ++k) {
    double side = k == 1 ? -1 : 1;
    E ex = g.p("Q321"), ey = g.p("Q322");
    if (axis == 1) ex = add(std::move(ex), mul(n(side), half->clone()));
    else ey = add(std::move(ey), mul(n(side), half->clone()));
    g.prePoint(std::to_string(k), std::move(ex), std::move(ey), n(axis == 1 ? side * s : 0), n(axis == 2 ? side * s : 0));
  }
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  g.probePlane("1");
  if (slot) g.betweenByQ301("2");
  else g.between("2", true);
  g.probePlane("2");
  g.toClearance();
  const char *m = axis == 1 ? "MX" : "MY";
  g.set("W", fn("ABS", sub(g.v(std::string(m) + "2"), g.v(std::string(m) + "1"))));
  g.set("C", dv(add(g.v(std::string(m) + "1"), g.v(std::string(m) + "2")), n(2)));
  g.setQ(166, g.v("W"));
  g.setQ(157, g.v("C"));
  datumAndAxis(g, axis == 1 ? g.v("C") : nullptr, axis == 2 ? g.v("C") : nullptr, "Q405", "Q405");
  g.end();
  return true;
}

// 410 / 411 (L17935-L18424): the rectangle's four sides about (Q321, Q322), Q323 x Q324.
bool rectangle(ProbeCall &c, bool inside) {
  Gen g(c);
  g.begin();
  probeRectangle(g, {"Q321", "Q322", "Q323", "Q324"}, inside);
  g.axisDatumProbe();
  g.setQ(151, g.v("CX"));
  g.setQ(152, g.v("CY"));
  g.setQ(154, fn("ABS", sub(g.v("MX2"), g.v("MX1"))));
  g.setQ(155, fn("ABS", sub(g.v("MY4"), g.v("MY3"))));
  g.datum(g.v("CX"), g.v("CY"), g.axisDatumZ());
  g.end();
  return true;
}

// 412 / 413 (L18425-L19007): Q423 points (3 or 4) on the circle from Q325 in steps of Q247,
// probed radially (outward in a hole, inward on a stud).
bool circle(ProbeCall &c, bool inside) {
  Gen g(c);
  int count;
  if (!literalChoice(c, "Q423", {3, 4}, "the number of probing points", count)) return false;
  g.begin();
  probeCircle(g, circleOf(g, "Q321", "Q322", count, inside));
  g.axisDatumProbe();
  g.setQ(151, g.v("CX"));
  g.setQ(152, g.v("CY"));
  g.setQ(153, g.v("DIA"));
  g.datum(g.v("CX"), g.v("CY"), g.axisDatumZ());
  g.end();
  return true;
}
}  // namespace

bool cycle408(ProbeCall &c) { return width(c, true); }
bool cycle409(ProbeCall &c) { return width(c, false); }
bool cycle410(ProbeCall &c) { return rectangle(c, true); }
bool cycle411(ProbeCall &c) { return rectangle(c, false); }
bool cycle412(ProbeCall &c) { return circle(c, true); }
bool cycle413(ProbeCall &c) { return circle(c, false); }

// 414 OUTSIDE CORNER (L19008-L19289): line 1 along ax1 probed along ax2 at point 1 (Q263, Q264)
// and point 2, Q326 from it; line 2 along ax2 probed along ax1 at point 3 (Q296, Q297) and point
// 4, Q327 from it. Which corner is meant follows from points 1 and 3 (the table L19073-L19103:
// A X1>X3 Y1<Y3, B X1<X3 Y1<Y3, C X1<X3 Y1>Y3, D X1>X3 Y1>Y3): the part lies toward point 3 from
// point 1 in ax2 and toward point 1 from point 3 in ax1, which gives both probing directions;
// points 2 and 4 lie away from the corner [model: the manual's figure]. Q151/Q152 the corner;
// Q304=1 also sets the basic rotation of line 1 (about the new datum [model]; an active basic
// rotation is cancelled first).
bool cycle414(ProbeCall &c) {
  Gen g(c);
  g.begin();
  auto sign = [&](E a) { return sub(bin(OpCode::Gt, a->clone(), n(0)), bin(OpCode::Lt, a->clone(), n(0))); };
  g.set("SX", sign(sub(g.p("Q263"), g.p("Q296"))));  // from the corner along line 1; probing ax1
  g.set("SY", sign(sub(g.p("Q297"), g.p("Q264"))));  // from the corner along line 2; probing ax2
  g.abortIf(bin(OpCode::Or, eq(g.v("SX"), 0), eq(g.v("SY"), 0)),
            "TCH PROBE 414: points 1 and 3 must differ in both axes: they name the corner (L19073)");
  g.when(eq(g.p("Q304"), 1), g.region([&] { g.basicRotation(n(0)); }));
  g.prePoint("1", g.p("Q263"), g.p("Q264"), n(0), g.v("SY"));
  g.prePoint("2", add(g.p("Q263"), mul(g.v("SX"), g.p("Q326"))), g.p("Q264"), n(0), g.v("SY"));
  g.prePoint("3", g.p("Q296"), g.p("Q297"), g.v("SX"), n(0));
  g.prePoint("4", g.p("Q296"), add(g.p("Q297"), mul(g.v("SY"), g.p("Q327"))), g.v("SX"), n(0));
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  for (int k = 1; k <= 4; ++k) {
    if (k > 1) g.betweenByQ301(std::to_string(k));
    g.probePlane(std::to_string(k));
  }
  g.toClearance();
  intersect(g, "K", {"MX1", "MY1"}, {"MX2", "MY2"}, {"MX3", "MY3"}, {"MX4", "MY4"});
  g.axisDatumProbe();
  g.setQ(151, g.v("KX"));
  g.setQ(152, g.v("KY"));
  g.datum(g.v("KX"), g.v("KY"), g.axisDatumZ());
  // Line 1's angle to ax1 within ±90 degrees, whichever way its points run.
  g.when(eq(g.p("Q304"), 1), g.region([&] {
           g.basicRotation(fn("ATAN", dv(sub(g.v("MY2"), g.v("MY1")), sub(g.v("MX2"), g.v("MX1")))));
         }));
  g.end();
  return true;
}

// 416 BOLT-CIRCLE CENTRE (L19538-L19779): three holes, each probed 4 times from its nominal
// centre; the circle through their centres: Q151/Q152, Q153 its diameter.
bool cycle416(ProbeCall &c) {
  Gen g(c);
  g.begin();
  boltCircle(g);
  g.axisDatumProbe();
  g.setQ(151, g.v("BCX"));
  g.setQ(152, g.v("BCY"));
  g.setQ(153, g.v("BDIA"));
  g.datum(g.v("BCX"), g.v("BCY"), g.axisDatumZ());
  g.end();
  return true;
}

// 417 DATUM IN PROBE AXIS (L19780-L19921): one probing down at (Q263, Q264) onto Q294.
bool cycle417(ProbeCall &c) {
  Gen g(c);
  g.begin();
  g.probeAxis("1", g.p("Q263"), g.p("Q264"), g.p("Q294"));
  g.toClearance();
  g.setQ(160, g.v("MZ1"));
  g.datum(nullptr, nullptr, g.v("MZ1"));
  g.end();
  return true;
}

// 418 CENTRE OF 4 HOLES (L19922-L20165): four holes probed from their centres (as 401), the
// datum where the lines from hole 1 to 3 and from 2 to 4 cross (Q151/Q152).
bool cycle418(ProbeCall &c) {
  Gen g(c);
  g.begin();
  static const char *const kCentre[4][2] = {{"Q268", "Q269"}, {"Q270", "Q271"}, {"Q316", "Q317"}, {"Q318", "Q319"}};
  for (int h = 0; h < 4; ++h) {
    CircleProbe cp;
    cp.key = "H" + std::to_string(h + 1) + "_";
    cp.cx = g.p(kCentre[h][0]);
    cp.cy = g.p(kCentre[h][1]);
    cp.start = n(0);
    cp.step = n(90);
    cp.fromCentre = true;
    cp.first = h == 0;
    probeCircle(g, std::move(cp));
  }
  intersect(g, "K", {"H1_CX", "H1_CY"}, {"H3_CX", "H3_CY"}, {"H2_CX", "H2_CY"}, {"H4_CX", "H4_CY"});
  g.axisDatumProbe();
  g.setQ(151, g.v("KX"));
  g.setQ(152, g.v("KY"));
  g.datum(g.v("KX"), g.v("KY"), g.axisDatumZ());
  g.end();
  return true;
}

// 419 DATUM IN ONE AXIS (L20166-L20346): the datum Q333 in the probed axis (L20255-L20274: the
// datum value of every axis is Q333).
bool cycle419(ProbeCall &c) {
  Gen g(c);
  int axis;
  if (!onePoint(g, axis)) return false;
  g.set("Q331", g.p("Q333"));
  g.set("Q332", g.p("Q333"));
  g.datum(axis == 1 ? g.v("M1") : nullptr, axis == 2 ? g.v("M1") : nullptr, axis == 3 ? g.v("M1") : nullptr);
  g.end();
  return true;
}

bool onePoint(Gen &g, int &axis) {
  if (!literalChoice(g.c_, "Q272", {1, 2, 3}, "the measuring axis", axis)) return false;
  g.begin();
  g.abortIf(bin(OpCode::And, ne(g.p("Q267"), 1), ne(g.p("Q267"), -1)),
            fmt::format("TCH PROBE {}: Q267 (the direction) must be +1 or -1", g.c_.number));
  if (axis == 3) {
    g.abortIf(ne(g.p("Q267"), -1), fmt::format("TCH PROBE {} in the probe axis with Q267=+1 (probing upward) is "
                                               "not simulated yet",
                                               g.c_.number));
    // Onto the measuring height Q261 as the nominal surface, from above.
    g.probeAxis("1", g.p("Q263"), g.p("Q264"), g.p("Q261"));
    g.toClearance();
    g.set("M1", g.v("MZ1"));
    return true;
  }
  E dx = axis == 1 ? g.p("Q267") : n(0), dy = axis == 2 ? g.p("Q267") : n(0);
  g.prePoint("1", g.p("Q263"), g.p("Q264"), std::move(dx), std::move(dy));
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  g.probePlane("1");
  g.toClearance();
  g.set("M1", g.v(axis == 1 ? "MX1" : "MY1"));
  return true;
}

void boltCircle(Gen &g) {
  static const char *const kAngle[3] = {"Q291", "Q292", "Q293"};
  g.set("BRAD", dv(g.p("Q262"), n(2)));
  for (int h = 0; h < 3; ++h) {
    CircleProbe cp;
    std::string key = "H" + std::to_string(h + 1) + "_";
    cp.key = key;
    cp.cx = add(g.p("Q273"), mul(g.v("BRAD"), fn("COS", g.p(kAngle[h]))));
    cp.cy = add(g.p("Q274"), mul(g.v("BRAD"), fn("SIN", g.p(kAngle[h]))));
    cp.start = n(0);
    cp.step = n(90);
    cp.fromCentre = true;
    cp.first = h == 0;
    probeCircle(g, std::move(cp));
    // The hole's centre as a point of the bolt circle.
    g.set("MXB" + std::to_string(h + 1), g.v(key + "CX"));
    g.set("MYB" + std::to_string(h + 1), g.v(key + "CY"));
  }
  fitCircle(g, "B", 3);
}

void intersect(Gen &g, const std::string &key, PointVars a1, PointVars a2, PointVars b1, PointVars b2) {
  auto d = [&](const std::string &to, const std::string &from) { return sub(g.v(to), g.v(from)); };
  g.set(key + "AX", d(a2.x, a1.x));
  g.set(key + "AY", d(a2.y, a1.y));
  g.set(key + "BX", d(b2.x, b1.x));
  g.set(key + "BY", d(b2.y, b1.y));
  g.set(key + "CR", sub(mul(g.v(key + "AX"), g.v(key + "BY")), mul(g.v(key + "AY"), g.v(key + "BX"))));
  g.abortIf(bin(OpCode::Lt, fn("ABS", g.v(key + "CR")), n(1e-12)),
            fmt::format("TCH PROBE {}: the measured lines are parallel: no point where they cross", g.c_.number));
  // a1 + t (a2 - a1) on the second line: t = ((b1 - a1) x (b2 - b1)) / ((a2 - a1) x (b2 - b1)).
  g.set(key + "T", dv(sub(mul(d(b1.x, a1.x), g.v(key + "BY")), mul(d(b1.y, a1.y), g.v(key + "BX"))), g.v(key + "CR")));
  g.set(key + "X", add(g.v(a1.x), mul(g.v(key + "T"), g.v(key + "AX"))));
  g.set(key + "Y", add(g.v(a1.y), mul(g.v(key + "T"), g.v(key + "AY"))));
}

}  // namespace ncc::hei::probe
