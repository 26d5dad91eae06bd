// The touch-probe cycles as NC IR (docs/PROBING.md "Heidenhain touch-probe cycles"): the table of
// cycles (their parameters and builders), cycle 0 and the basic-rotation cycles 400-404. The
// datum cycles 408-419 are in ProbeDatum.cpp, the measuring cycles 420-431 in ProbeMeasure.cpp;
// the steps and features they share in ProbeSteps.cpp.
#include "frontend/heidenhain/ProbeCycles.h"

namespace ncc::hei {
namespace probe {
namespace {
const char *const kAxisName[3] = {"X", "Y", "Z"};

// 400-402 cancel an active basic rotation first (L16243); the new one is the measured line's
// angle less its nominal angle Q307, set on the active preset (Q305=0: the manual mode's ROT,
// L16353). 401/402 may turn the rotary table instead (Q402=1): not simulated.
void rotationStart(Gen &g, bool table) {
  g.abortIf(ne(g.p("Q305"), 0), fmt::format("TCH PROBE {} with Q305 other than 0 (the rotation into a preset-table "
                                            "row) is not simulated yet",
                                            g.c_.number));
  if (table)
    g.abortIf(eq(g.p("Q402"), 1), fmt::format("TCH PROBE {} with Q402=1 (aligning by turning the rotary table, "
                                              "L16402) is not simulated yet",
                                              g.c_.number));
  g.basicRotation(n(0));
}
void rotationEnd(Gen &g, E lineAngle) {
  g.set("ROT", sub(std::move(lineAngle), g.p("Q307")));
  g.basicRotation(g.v("ROT"));
}

// 400 BASIC ROTATION (L16211-L16362): two points on a line along ax1 (Q272=1) or ax2 (Q272=2),
// probed in the direction Q267 across it; against ax2 the angle is less 90 [model].
bool cycle400(ProbeCall &c) {
  Gen g(c);
  int axis;
  if (!literalChoice(c, "Q272", {1, 2}, "the measuring axis", axis)) return false;
  g.begin();
  rotationStart(g, false);
  twoPointLine(g, axis);
  rotationEnd(g, sub(lineAngle(g.v("MX1"), g.v("MY1"), g.v("MX2"), g.v("MY2")), n(axis == 2 ? 90 : 0)));
  g.end();
  return true;
}

// 401 ROT 2 HOLES (L16363-L16543): each hole probed 4 times from its nominal centre (no diameter
// is given: outward at 0, 90, 180, 270 degrees for DIST [model]), over Q260 to the second; the
// angle of the line from centre 1 to centre 2.
// 402 ROT 2 STUDS (L16544-L16759): 4 points on each stud's circle Q313/Q314 (from 0 degrees
// [model]), on arcs between them at the measuring height (Q301=0) or straight over Q260 (1),
// stud 2 at its own height Q315.
bool twoCircles(ProbeCall &c, bool studs) {
  Gen g(c);
  g.begin();
  rotationStart(g, true);
  if (studs) g.set("Q365", eq(g.p("Q301"), 0));  // the arcs of the stud circles
  for (int h = 1; h <= 2; ++h) {
    CircleProbe cp;
    cp.key = "H" + std::to_string(h) + "_";
    cp.cx = g.p(h == 1 ? "Q268" : "Q270");
    cp.cy = g.p(h == 1 ? "Q269" : "Q271");
    cp.start = n(0);
    cp.step = n(90);
    cp.first = h == 1;
    if (studs) {
      cp.inside = false;
      cp.dia = g.p(h == 1 ? "Q313" : "Q314");
      cp.height = h == 1 ? "Q261" : "Q315";
    } else {
      cp.fromCentre = true;
    }
    probeCircle(g, std::move(cp));
  }
  rotationEnd(g, lineAngle(g.v("H1_CX"), g.v("H1_CY"), g.v("H2_CX"), g.v("H2_CY")));
  g.end();
  return true;
}
bool cycle401(ProbeCall &c) { return twoCircles(c, false); }
bool cycle402(ProbeCall &c) { return twoCircles(c, true); }

// 404 SET BASIC ROTATION (L16997-L17051): no motion. Q305=-1 overwrites the active preset's
// rotation, 0 copies the preset to row 0 with the rotation and activates it: the same rotation of
// the active system in ncc (it has no preset table); > 0 stores it in a row without activating it:
// no effect. The manual's ">1" (L17049) reads ">0".
bool cycle404(ProbeCall &c) {
  Gen g(c);
  g.noTransforms(true);
  for (auto &[q, e] : c.given) g.set(q, e->clone());
  g.abortIf(bin(OpCode::Lt, g.p("Q305"), n(-1)), "TCH PROBE 404: Q305 (the preset row) is -1 to 99999 (L17032)");
  g.when(bin(OpCode::Le, g.p("Q305"), n(0)), g.region([&] { g.basicRotation(g.p("Q307")); }));
  return true;
}

// 441 FAST PROBING (L23876-L23957): no motion; the following probe cycles of the run position at
// Q396 instead of the table's FMAX (0: FMAX [model]) and pre-position at machine rapid (Q397=1)
// or at Q396 (0). Q399 (orient the probe before each probing) and Q400 (stop and show the
// results) change no path: read and not simulated. END PGM, M2, M30 reset it (L23887): the end of
// the run [model: an END PGM of a called program does not].
bool cycle441(ProbeCall &c) {
  Gen g(c);
  for (auto &[q, e] : c.given) g.set(q, e->clone());
  g.abortIf(bin(OpCode::Lt, g.p("Q396"), n(0)), "TCH PROBE 441: Q396 (the positioning feed) is 0 to 99999.999 (L23905)");
  g.abortIf(bin(OpCode::And, ne(g.p("Q397"), 0), ne(g.p("Q397"), 1)), "TCH PROBE 441: Q397 must be 0 or 1 (L23909)");
  g.set("F441", g.p("Q396"));
  g.set("P441", add(g.p("Q397"), n(1)));
  return true;
}

const ProbeCycle kProbeCycles[] = {
    {400, "Q263 Q264 Q265 Q266 Q272 Q267 Q261 Q320 Q260 Q301 Q307 Q305", "", cycle400},
    {401, "Q268 Q269 Q270 Q271 Q261 Q260 Q307 Q305 Q402 Q337", "Q402=0 Q337=0", cycle401},
    {402, "Q268 Q269 Q313 Q261 Q270 Q271 Q314 Q315 Q320 Q260 Q301 Q307 Q305 Q402 Q337", "Q402=0 Q337=0", cycle402},
    {404, "Q307 Q305", "", cycle404},
    {408, "Q321 Q322 Q311 Q272 Q261 Q320 Q260 Q301 Q305 Q405 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q405=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle408},
    {409, "Q321 Q322 Q311 Q272 Q261 Q320 Q260 Q305 Q405 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q405=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle409},
    {410, "Q321 Q322 Q323 Q324 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle410},
    {411, "Q321 Q322 Q323 Q324 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle411},
    {412, "Q321 Q322 Q262 Q325 Q247 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333 Q423 Q365",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0 Q423=4 Q365=0", cycle412},
    {413, "Q321 Q322 Q262 Q325 Q247 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333 Q423 Q365",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0 Q423=4 Q365=0", cycle413},
    {414, "Q263 Q264 Q326 Q296 Q297 Q327 Q261 Q320 Q260 Q301 Q304 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle414},
    {416, "Q273 Q274 Q262 Q291 Q292 Q293 Q261 Q260 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333 Q320",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0 Q320=0", cycle416},
    {417, "Q263 Q264 Q294 Q320 Q260 Q305 Q333 Q303", "Q333=0", cycle417},
    {418, "Q268 Q269 Q270 Q271 Q316 Q317 Q318 Q319 Q261 Q260 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle418},
    {419, "Q263 Q264 Q261 Q320 Q260 Q272 Q267 Q305 Q333 Q303", "Q333=0", cycle419},
    {420, "Q263 Q264 Q265 Q266 Q272 Q267 Q261 Q320 Q260 Q301 Q281", "Q281=0", cycle420},
    {421, "Q273 Q274 Q262 Q325 Q247 Q261 Q320 Q260 Q301 Q275 Q276 Q279 Q280 Q281 Q309 Q330 Q423 Q365 Q498 Q531",
     "Q275=0 Q276=0 Q279=0 Q280=0 Q281=0 Q309=0 Q330=0 Q423=4 Q365=0 Q498=0 Q531=0", cycle421},
    {422, "Q273 Q274 Q262 Q325 Q247 Q261 Q320 Q260 Q301 Q277 Q278 Q279 Q280 Q281 Q309 Q330 Q423 Q365 Q498 Q531",
     "Q277=0 Q278=0 Q279=0 Q280=0 Q281=0 Q309=0 Q330=0 Q423=4 Q365=0 Q498=0 Q531=0", cycle422},
    {423, "Q273 Q274 Q282 Q283 Q261 Q320 Q260 Q301 Q284 Q285 Q286 Q287 Q279 Q280 Q281 Q309 Q330",
     "Q284=0 Q285=0 Q286=0 Q287=0 Q279=0 Q280=0 Q281=0 Q309=0 Q330=0", cycle423},
    {424, "Q273 Q274 Q282 Q283 Q261 Q320 Q260 Q301 Q284 Q285 Q286 Q287 Q279 Q280 Q281 Q309 Q330",
     "Q284=0 Q285=0 Q286=0 Q287=0 Q279=0 Q280=0 Q281=0 Q309=0 Q330=0", cycle424},
    {426, "Q263 Q264 Q265 Q266 Q272 Q261 Q320 Q260 Q311 Q288 Q289 Q281 Q309 Q330",
     "Q288=0 Q289=0 Q281=0 Q309=0 Q330=0", cycle426},
    {427, "Q263 Q264 Q261 Q320 Q272 Q267 Q260 Q281 Q288 Q289 Q309 Q330 Q498 Q531",
     "Q281=0 Q288=0 Q289=0 Q309=0 Q330=0 Q498=0 Q531=0", cycle427},
    {430, "Q273 Q274 Q262 Q291 Q292 Q293 Q261 Q260 Q288 Q289 Q279 Q280 Q281 Q309 Q330",
     "Q288=0 Q289=0 Q279=0 Q280=0 Q281=0 Q309=0 Q330=0", cycle430},
    {431, "Q263 Q264 Q294 Q265 Q266 Q295 Q296 Q297 Q298 Q320 Q260 Q281", "Q281=0", cycle431},
    {441, "Q396 Q397 Q399 Q400", "Q399=0 Q400=0", cycle441},
};
}  // namespace

// 400 and 420: two points on a line along ax1 (axis 1) or ax2 (2), probed across it in the
// direction Q267 (L16214-L16238, L20934-L20977).
void twoPointLine(Gen &g, int axis) {
  for (int k = 1; k <= 2; ++k) {
    E dx = axis == 2 ? g.p("Q267") : n(0), dy = axis == 1 ? g.p("Q267") : n(0);
    g.prePoint(std::to_string(k), g.p(k == 1 ? "Q263" : "Q265"), g.p(k == 1 ? "Q264" : "Q266"), std::move(dx),
               std::move(dy));
  }
  g.abortIf(bin(OpCode::And, ne(g.p("Q267"), 1), ne(g.p("Q267"), -1)),
            fmt::format("TCH PROBE {}: Q267 (the direction) must be +1 or -1", g.c_.number));
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  g.probePlane("1");
  g.betweenByQ301("2");
  g.probePlane("2");
  g.toClearance();
}
}  // namespace probe

const ProbeCycle *findProbeCycle(int number) {
  for (const ProbeCycle &p : probe::kProbeCycles)
    if (p.number == number) return &p;
  return nullptr;
}

// Cycle 0 (L20805-L20864): a rapid 3-D move to the pre-position, one probing along the axis, back
// to the start; Q<n> the measured coordinate (the surface: the ball's radius added in the plane,
// the south pole in the probe axis), Q115-Q117 where the probe switched (X Y Z of its controlled
// point, without the radius: L20819-L20822).
bool lowerReferencePlane(ProbeCall &c, int resultQ, char axis, int dir, ExprPtr pre[3]) {
  using namespace probe;
  Gen g(c);
  g.needsProbe();
  g.set("R", dv(sys("_tool_diameter"), n(2)));
  g.set("FEED", sys("_feed"));
  for (int i = 0; i < 3; ++i) g.set(std::string("P") + kAxisName[i], std::move(pre[i]));
  g.position(g.v("PX"), g.v("PY"), g.v("PZ"), true);
  g.feed(n(c.table.feed));
  g.motion("probe_toward");
  int a = axis - 'X';
  Op mv(OpKind::Move, c.loc);
  mv.set(kAxisName[a], add(g.v(std::string("P") + kAxisName[a]), n(dir * c.table.dist)));
  g.emit(std::move(mv));
  static const char *const kProbeVar[3] = {"_probe_x", "_probe_y", "_probe_z"};
  E measured = sys(kProbeVar[a]);
  if (a != 2) measured = add(std::move(measured), mul(n(dir), g.v("R")));
  g.setQ(resultQ, std::move(measured));
  for (int i = 0; i < 3; ++i) g.setQ(115 + i, sys(kProbeVar[i]));
  g.rapidBack(g.v("PX"), g.v("PY"), g.v("PZ"));
  g.end();
  return true;
}

}  // namespace ncc::hei
