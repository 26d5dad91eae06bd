// The measuring cycles 420-431 (L20931-L22809): the feature each probes (ProbeSteps.cpp), the
// results Q150-Q166 (deviations: actual less nominal) and the status Q180-Q182 from the limits
// (L20708-L20748). Q281 (the log) and Q330 (tool monitoring): measuringOptions.
#include "frontend/heidenhain/ProbeCycles.h"

namespace ncc::hei::probe {

namespace {
// |deviation| over a position tolerance (0: not checked) is scrap [model: the manual does not
// say which flag a position sets].
void positionLimit(Gen &g, std::vector<E> &scrap, int devQ, const char *tolQ) {
  scrap.push_back(bin(OpCode::And, ne(g.p(tolQ), 0), bin(OpCode::Gt, fn("ABS", qp(devQ)), g.p(tolQ))));
}

// Q151-Q153 the circle <key>CX, <key>CY, <key>DIA; Q161-Q163 their deviations from Q273, Q274,
// Q262; the status from the diameter limits maxQ/minQ (all scrap: `allScrap`) and Q279/Q280.
void circleResults(Gen &g, const std::string &key, const char *maxQ, const char *minQ, bool studLike, bool allScrap) {
  static const char *const kNominal[3] = {"Q273", "Q274", "Q262"};
  static const char *const kResult[3] = {"CX", "CY", "DIA"};
  for (int i = 0; i < 3; ++i) {
    g.setQ(151 + i, g.v(key + kResult[i]));
    g.setQ(161 + i, sub(g.v(key + kResult[i]), g.p(kNominal[i])));
  }
  std::vector<E> rework, scrap;
  sizeLimits(g, allScrap ? scrap : rework, scrap, g.v(key + "DIA"), maxQ, minQ, studLike);
  positionLimit(g, scrap, 161, "Q279");
  positionLimit(g, scrap, 162, "Q280");
  measuringStatus(g, rework, scrap);
}

// 421 MEASURE HOLE (L21083-L21308) / 422 MEASURE STUD (L21309-L21538): as 412/413 about
// (Q273, Q274); Q151-Q153 centre and diameter, Q161-Q163 their deviations. The diameter limits
// (421 Q275/Q276, 422 Q277/Q278): a hole too small or a stud too big needs rework, the other
// way is scrap [model].
bool measureCircle(ProbeCall &c, bool inside) {
  Gen g(c);
  int count;
  if (!literalChoice(c, "Q423", {3, 4}, "the number of probing points", count)) return false;
  g.begin();
  measuringOptions(g, true);
  probeCircle(g, circleOf(g, "Q273", "Q274", count, inside));
  circleResults(g, "", inside ? "Q275" : "Q277", inside ? "Q276" : "Q278", !inside, false);
  g.end();
  return true;
}

// 423 MEASURE RECTANGLE INSIDE (L21539-L21740) / 424 OUTSIDE (L21741-L21938): as 410/411 about
// (Q273, Q274), Q282 x Q283; Q151/Q152 the centre, Q154/Q155 the sides, Q161/Q162, Q164/Q165
// their deviations; side limits Q284/Q285 and Q286/Q287, centre Q279/Q280. (The digest's erratum
// 16: the manual's section titles swap pocket and stud; the cycles' texts do not.)
bool measureRectangle(ProbeCall &c, bool inside) {
  Gen g(c);
  g.begin();
  measuringOptions(g, true);
  probeRectangle(g, {"Q273", "Q274", "Q282", "Q283"}, inside);
  g.set("S1", fn("ABS", sub(g.v("MX2"), g.v("MX1"))));
  g.set("S2", fn("ABS", sub(g.v("MY4"), g.v("MY3"))));
  g.setQ(151, g.v("CX"));
  g.setQ(152, g.v("CY"));
  g.setQ(154, g.v("S1"));
  g.setQ(155, g.v("S2"));
  g.setQ(161, sub(g.v("CX"), g.p("Q273")));
  g.setQ(162, sub(g.v("CY"), g.p("Q274")));
  g.setQ(164, sub(g.v("S1"), g.p("Q282")));
  g.setQ(165, sub(g.v("S2"), g.p("Q283")));
  std::vector<E> rework, scrap;
  sizeLimits(g, rework, scrap, g.v("S1"), "Q284", "Q285", !inside);
  sizeLimits(g, rework, scrap, g.v("S2"), "Q286", "Q287", !inside);
  positionLimit(g, scrap, 161, "Q279");
  positionLimit(g, scrap, 162, "Q280");
  measuringStatus(g, rework, scrap);
  g.end();
  return true;
}
}  // namespace

// 420 MEASURE ANGLE (L20931-L21082): the points of 400; Q150 the line's angle to ax1 (Q272=2: to
// ax2, less 90 [model], as 400). Q272=3 (the angle in the probe axis) is not simulated.
bool cycle420(ProbeCall &c) {
  Gen g(c);
  int axis;
  if (!literalChoice(c, "Q272", {1, 2, 3}, "the measuring axis", axis)) return false;
  if (axis == 3)
    return c.error("TCH PROBE 420 with Q272=3 (the angle in the probe axis, L20971) is not simulated yet",
                   "unsupported-code");
  g.begin();
  measuringOptions(g, false);
  twoPointLine(g, axis);
  g.setQ(150, sub(lineAngle(g.v("MX1"), g.v("MY1"), g.v("MX2"), g.v("MY2")), n(axis == 2 ? 90 : 0)));
  g.end();
  return true;
}

bool cycle421(ProbeCall &c) { return measureCircle(c, true); }
bool cycle422(ProbeCall &c) { return measureCircle(c, false); }
bool cycle423(ProbeCall &c) { return measureRectangle(c, true); }
bool cycle424(ProbeCall &c) { return measureRectangle(c, false); }

// 426 MEASURE RIDGE WIDTH (L22123-L22288): point 1 (Q263, Q264) probed in the − direction of
// Q272, point 2 (Q265, Q266) in the + direction, over Q260 between them. Q156 the width, Q157 the
// centre line, Q166 the width less Q311; the limits Q288/Q289 as a stud's.
bool cycle426(ProbeCall &c) {
  Gen g(c);
  int axis;
  if (!literalChoice(c, "Q272", {1, 2}, "the measuring axis", axis)) return false;
  g.begin();
  measuringOptions(g, true);
  for (int k = 1; k <= 2; ++k) {
    double d = k == 1 ? -1 : 1;
    g.prePoint(std::to_string(k), g.p(k == 1 ? "Q263" : "Q265"), g.p(k == 1 ? "Q264" : "Q266"), n(axis == 1 ? d : 0),
               n(axis == 2 ? d : 0));
  }
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  g.probePlane("1");
  g.between("2", true);
  g.probePlane("2");
  g.toClearance();
  std::string m = axis == 1 ? "MX" : "MY";
  g.set("W", fn("ABS", sub(g.v(m + "1"), g.v(m + "2"))));
  g.setQ(156, g.v("W"));
  g.setQ(157, dv(add(g.v(m + "1"), g.v(m + "2")), n(2)));
  g.setQ(166, sub(g.v("W"), g.p("Q311")));
  std::vector<E> rework, scrap;
  sizeLimits(g, rework, scrap, g.v("W"), "Q288", "Q289", true);
  measuringStatus(g, rework, scrap);
  g.end();
  return true;
}

// 427 MEASURE COORDINATE (L22289-L22456): the probing of 419; Q160 the measured coordinate, its
// limits Q288/Q289 as an outside dimension (over the maximum: rework, L20731-L20735).
bool cycle427(ProbeCall &c) {
  Gen g(c);
  int axis;
  if (!onePoint(g, axis)) return false;
  measuringOptions(g, true);
  g.setQ(160, g.v("M1"));
  std::vector<E> rework, scrap;
  sizeLimits(g, rework, scrap, g.v("M1"), "Q288", "Q289", true);
  measuringStatus(g, rework, scrap);
  g.end();
  return true;
}

// 430 MEASURE BOLT HOLE CIRCLE (L22457-L22636): the holes of 416; Q151-Q153 the circle,
// Q161-Q163 its deviations; the diameter limits Q288/Q289 and the centre Q279/Q280: every
// violation is scrap [model: a bolt circle is not reworked].
bool cycle430(ProbeCall &c) {
  Gen g(c);
  g.begin();
  measuringOptions(g, true);
  boltCircle(g);
  circleResults(g, "B", "Q288", "Q289", true, true);
  g.end();
  return true;
}

// 431 MEASURE PLANE (L22637-L22809): three probings down the probe axis, at (Q263, Q264) onto
// Q294, (Q265, Q266) onto Q295, (Q296, Q297) onto Q298, over Q260 between them. Q173-Q175 the
// measured Z. The plane's normal n (oriented up) gives the projection angles Q158 = atan2(-ny,
// nz) (about X) and Q159 = atan2(nx, nz) (about Y), and the spatial angles Q170-Q172 of a frame
// whose X runs from point 1 to point 2 and whose Z is n: R = Rz(C) Ry(B) Rx(A) (PLANE SPATIAL's
// order A, B, C about the fixed axes) [model: the manual gives no formula].
bool cycle431(ProbeCall &c) {
  Gen g(c);
  g.begin();
  measuringOptions(g, false);
  static const char *const kPoint[3][3] = {{"Q263", "Q264", "Q294"}, {"Q265", "Q266", "Q295"}, {"Q296", "Q297", "Q298"}};
  for (int k = 0; k < 3; ++k) {
    std::string s = std::to_string(k + 1);
    g.probeAxis(s, g.p(kPoint[k][0]), g.p(kPoint[k][1]), g.p(kPoint[k][2]), k == 0);
    g.toClearance();
    g.setQ(173 + k, g.v("MZ" + s));
  }
  auto d = [&](const char *q2, const char *q1) { return sub(g.p(q2), g.p(q1)); };
  g.set("UX", d("Q265", "Q263"));
  g.set("UY", d("Q266", "Q264"));
  g.set("UZ", sub(g.v("MZ2"), g.v("MZ1")));
  g.set("WX", d("Q296", "Q263"));
  g.set("WY", d("Q297", "Q264"));
  g.set("WZ", sub(g.v("MZ3"), g.v("MZ1")));
  auto cross = [&](const char *a1, const char *b2, const char *a2, const char *b1) {
    return sub(mul(g.v(a1), g.v(b2)), mul(g.v(a2), g.v(b1)));
  };
  g.set("NX", cross("UY", "WZ", "UZ", "WY"));
  g.set("NY", cross("UZ", "WX", "UX", "WZ"));
  g.set("NZ", cross("UX", "WY", "UY", "WX"));
  g.set("NL", fn("SQRT", add(add(mul(g.v("NX"), g.v("NX")), mul(g.v("NY"), g.v("NY"))), mul(g.v("NZ"), g.v("NZ")))));
  g.set("UL", fn("SQRT", add(add(mul(g.v("UX"), g.v("UX")), mul(g.v("UY"), g.v("UY"))), mul(g.v("UZ"), g.v("UZ")))));
  g.abortIf(bin(OpCode::Lt, g.v("NL"), n(1e-9)), "TCH PROBE 431: the three points lie on a line: no plane (L22683)");
  // Up: a normal that points down is turned over.
  g.set("NS", sub(n(1), mul(n(2), bin(OpCode::Lt, g.v("NZ"), n(0)))));
  for (const char *a : {"NX", "NY", "NZ"}) g.set(a, dv(mul(g.v(a), g.v("NS")), g.v("NL")));
  for (const char *a : {"UX", "UY", "UZ"}) g.set(a, dv(g.v(a), g.v("UL")));
  g.setQ(158, fn("ATAN2_SIGNED", sub(n(0), g.v("NY")), g.v("NZ")));
  g.setQ(159, fn("ATAN2_SIGNED", g.v("NX"), g.v("NZ")));
  // The frame's Y = n x u; R's row 2 is (UZ, YZ, NZ): A = atan2(YZ, NZ), B = -asin(UZ), C = atan2(UY, UX).
  g.set("YZ", cross("NX", "UY", "NY", "UX"));
  g.setQ(170, fn("ATAN2_SIGNED", g.v("YZ"), g.v("NZ")));
  g.setQ(171, sub(n(0), fn("ASIN", g.v("UZ"))));
  g.setQ(172, fn("ATAN2_SIGNED", g.v("UY"), g.v("UX")));
  g.end();
  return true;
}

}  // namespace ncc::hei::probe
