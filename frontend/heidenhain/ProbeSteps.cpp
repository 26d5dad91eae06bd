// The shared steps and features of the touch-probe cycles (ProbeSteps.h).
#include "frontend/heidenhain/ProbeSteps.h"

namespace ncc::hei::probe {

E Gen::v(const std::string &name) {
  std::string full = "_HEI_TP_" + name;
  c_.vars->insert(full);
  return hglobal(full.c_str(), c_.loc);
}
void Gen::emit(Op o) {
  o.loc = c_.loc;
  c_.out->push_back(std::move(o));
}
void Gen::when(E cond, ir::Region then, ir::Region otherwise) {
  Op o(OpKind::If, c_.loc);
  o.set("cond", std::move(cond));
  o.regions.push_back(std::move(then));
  if (!otherwise.empty()) o.regions.push_back(std::move(otherwise));
  emit(std::move(o));
}
void Gen::message(E cond, const std::string &text, const char *kind) {
  Op m(OpKind::Message, c_.loc);
  m.set("text", Expr::string(text, c_.loc));
  m.set("kind", Expr::symbol(kind));
  ir::Region r;
  r.push_back(std::move(m));
  when(std::move(cond), std::move(r));
}
void Gen::feed(E value) {
  Op o(OpKind::Feed, c_.loc);
  o.set("value", std::move(value));
  emit(std::move(o));
}
void Gen::motion(const char *mode) {
  Op m(OpKind::Mode, c_.loc);
  m.set("motion", Expr::symbol(mode));
  emit(std::move(m));
}
// Cycle 441 may replace FMAX by its Q396 (the variable F441, 0: not set) and F_PREPOS by its
// Q397 (P441: 0 not set, 1 at Q396, 2 at machine rapid).
void Gen::position(E x, E y, E z, bool prepos) {
  auto atFeed = [&] {
    feed(add(v("F441"), mul(eq(v("F441"), 0), n(c_.table.fmax))));
    motion("linear");
  };
  if (prepos) {
    E rapid = c_.table.preposRapid ? ne(v("P441"), 1) : eq(v("P441"), 2);
    when(std::move(rapid), region([&] { motion("rapid"); }), region(atFeed));
  } else {
    atFeed();
  }
  Op mv(OpKind::Move, c_.loc);
  if (x) mv.set("X", std::move(x));
  if (y) mv.set("Y", std::move(y));
  if (z) mv.set("Z", std::move(z));
  emit(std::move(mv));
}
void Gen::rapidBack(E x, E y, E z) {
  motion("rapid");
  Op mv(OpKind::Move, c_.loc);
  mv.set("X", std::move(x));
  mv.set("Y", std::move(y));
  mv.set("Z", std::move(z));
  emit(std::move(mv));
}
void Gen::offset(const char *kind, const char *axis, E value) {
  Op o(OpKind::SetOffset, c_.loc);
  o.set("kind", Expr::symbol(kind));
  o.set("index", Expr::number(0, ir::Type::Int));
  o.set(axis, std::move(value));
  emit(std::move(o));
}

void Gen::begin() {
  needsProbe();
  noTransforms(c_.number >= 400 && c_.number <= 499);
  for (auto &[q, e] : c_.given) set(q, e->clone());
  set("R", dv(sys("_tool_diameter"), n(2)));
  set("FEED", sys("_feed"));
  if (c_.given.count("Q320")) set("CLR", add(n(c_.table.setUp), p("Q320")));  // before the ball's surface
  else set("CLR", n(c_.table.setUp));  // 401, 416, 418, 430 have no Q320
}
// The probe is the tool in the spindle: a TOOL CALL must come first (L16241, HEI-TOOL-04).
void Gen::needsProbe() {
  abortIf(bin(OpCode::Le, sys("_current_tool"), n(0)),
          fmt::format("TCH PROBE {} needs the touch probe in the spindle: a TOOL CALL before it (L16241)", c_.number));
}
void Gen::end() {
  ir::Region back;
  Op f(OpKind::Feed, c_.loc);
  f.set("value", v("FEED"));
  back.push_back(std::move(f));
  when(bin(OpCode::Gt, v("FEED"), n(0)), std::move(back));
}
void Gen::approach(E x, E y, E z, bool prepos) {
  when(bin(OpCode::Lt, sys("_z"), p("Q260")), region([&] { position(nullptr, nullptr, p("Q260"), prepos); }));
  position(std::move(x), std::move(y), nullptr, prepos);
  position(nullptr, nullptr, std::move(z), prepos);
}

void Gen::prePoint(const std::string &k, E ex, E ey, E dx, E dy) {
  set("DX" + k, std::move(dx));
  set("DY" + k, std::move(dy));
  E off = add(v("CLR"), v("R"));
  set("PX" + k, sub(std::move(ex), mul(off->clone(), v("DX" + k))));
  set("PY" + k, sub(std::move(ey), mul(std::move(off), v("DY" + k))));
}
void Gen::fromPoint(const std::string &k, E px, E py, E dx, E dy) {
  set("DX" + k, std::move(dx));
  set("DY" + k, std::move(dy));
  set("PX" + k, std::move(px));
  set("PY" + k, std::move(py));
}
void Gen::probePlane(const std::string &k) {
  feed(n(c_.table.feed));
  motion("probe_toward");
  Op mv(OpKind::Move, c_.loc);
  mv.set("X", add(v("PX" + k), mul(n(c_.table.dist), v("DX" + k))));
  mv.set("Y", add(v("PY" + k), mul(n(c_.table.dist), v("DY" + k))));
  emit(std::move(mv));
  set("MX" + k, add(sys("_probe_x"), mul(v("R"), v("DX" + k))));
  set("MY" + k, add(sys("_probe_y"), mul(v("R"), v("DY" + k))));
  rapidBack(v("PX" + k), v("PY" + k), sys("_z"));
}
void Gen::probeAxis(const std::string &k, E x, E y, E z, bool first) {
  set("PZ" + k, add(std::move(z), v("CLR")));
  approach(std::move(x), std::move(y), v("PZ" + k), first);
  feed(n(c_.table.feed));
  motion("probe_toward");
  Op mv(OpKind::Move, c_.loc);
  mv.set("Z", sub(v("PZ" + k), n(c_.table.dist)));
  emit(std::move(mv));
  set("MZ" + k, sys("_probe_z"));
  rapidBack(sys("_x"), sys("_y"), v("PZ" + k));
}
void Gen::between(const std::string &k, bool viaClearance, E arcCcw, const char *cx, const char *cy,
                  const char *height) {
  if (viaClearance) toClearance();
  if (arcCcw) {
    // The direction of the circle's points: Q247 > 0 counter-clockwise.
    for (int ccw = 0; ccw < 2; ++ccw) {
      ir::Region r = region([&] {
        feed(n(c_.table.fmax));
        motion(ccw ? "arc_ccw" : "arc_cw");
        Op mv(OpKind::Move, c_.loc);
        mv.set("X", v("PX" + k));
        mv.set("Y", v("PY" + k));
        mv.set("I", v(cx));
        mv.set("J", v(cy));
        mv.set("ac", Expr::symbol("IJ"));
        emit(std::move(mv));
      });
      when(bin(ccw ? OpCode::Ne : OpCode::Eq, arcCcw->clone(), n(0)), std::move(r));
    }
  } else {
    position(v("PX" + k), v("PY" + k), nullptr);
  }
  if (viaClearance) position(nullptr, nullptr, measureZ(height));
}
void Gen::betweenByQ301(const std::string &k, const char *height) {
  when(eq(p("Q301"), 1), region([&] { between(k, true, nullptr, nullptr, nullptr, height); }),
       region([&] { between(k, false, nullptr, nullptr, nullptr, height); }));
}

// The probe cycles 400-499 run without cycles 7, 8, 10, 11, 26 active (L14755-L14765, HEI-TCH-04):
// their results would be in a shifted system and the datum written wrong.
void Gen::noTransforms(bool frames) {
  if (!frames) return;
  E active = ne(hglobal(kShiftX), 0);
  for (const char *g : {kShiftY, kShiftZ, kRot, kMirror[0], kMirror[1]})
    active = bin(OpCode::Or, std::move(active), ne(hglobal(g), 0));
  for (const char *g : {kScl, kAxisScl[0], kAxisScl[1], kAxisScl[2]})
    active = bin(OpCode::Or, std::move(active), ne(hglobal(g), 1));
  abortIf(std::move(active), fmt::format("TCH PROBE {}: cycles 7, 8, 10, 11 and 26 must be reset before a touch-probe "
                                         "cycle 400-499 (L14755)",
                                         c_.number));
}

// Q305 = 0 makes the measured point the active preset's origin with the values valX/valY/Q333
// (the display is set, whatever Q303 says); Q305 > 0 writes a row of the datum (Q303=0) or preset
// table (Q303=1) that only cycle 7 #n or 247 would activate (both refused by ncc): no effect on
// the motion. Q303=-1 is an error (L17460).
void Gen::datum(E mx, E my, E mz, const char *valX, const char *valY) {
  abortIf(eq(p("Q303"), -1),
          fmt::format("TCH PROBE {}: Q303=-1 (an imported program) is an error: set Q303 to 0 or 1 (L17460)", c_.number));
  Op o(OpKind::SetOffset, c_.loc);
  o.set("kind", Expr::symbol("g10l20"));
  o.set("index", Expr::number(0, ir::Type::Int));
  if (mx) o.set("X", add(sub(sys("_x"), std::move(mx)), p(valX)));
  if (my) o.set("Y", add(sub(sys("_y"), std::move(my)), p(valY)));
  if (mz) o.set("Z", add(sub(sys("_z"), std::move(mz)), p("Q333")));
  ir::Region r;
  r.push_back(std::move(o));
  r.back().loc = c_.loc;
  when(eq(p("Q305"), 0), std::move(r));
}
// Q381=1: the datum in the probe axis too, probed at (Q382, Q383) onto Q384 (L17676-L17709).
void Gen::axisDatumProbe() {
  set("MZA", n(0));
  when(eq(p("Q381"), 1), region([&] {
         probeAxis("A", p("Q382"), p("Q383"), p("Q384"));
         toClearance();
       }));
}
// The Z datum's measured value when Q381=1; else Q333, which leaves Z reading as it does.
E Gen::axisDatumZ() { return add(mul(eq(p("Q381"), 1), v("MZA")), mul(ne(p("Q381"), 1), p("Q333"))); }

bool literalChoice(ProbeCall &c, const char *q, std::initializer_list<int> allowed, const char *what, int &out) {
  auto it = c.given.find(q);
  if (it != c.given.end() && it->second->kind == ir::ExprKind::Number)
    for (int a : allowed)
      if (it->second->num == a) {
        out = a;
        return true;
      }
  std::string list;
  for (int a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
  size_t last = list.rfind(", ");
  if (last != std::string::npos) list.replace(last, 2, " or ");
  return c.error(fmt::format("TCH PROBE {}: {} ({}) must be the number {}", c.number, q, what, list), "cycle-parameter");
}

CircleProbe circleOf(Gen &g, const char *cx, const char *cy, int count, bool inside) {
  CircleProbe cp;
  cp.cx = g.p(cx);
  cp.cy = g.p(cy);
  cp.dia = g.p("Q262");
  cp.start = g.p("Q325");
  cp.step = g.p("Q247");
  cp.count = count;
  cp.inside = inside;
  return cp;
}

void probeCircle(Gen &g, CircleProbe cp) {
  double s = cp.inside ? 1 : -1;
  const std::string &key = cp.key;
  auto pk = [&](int k) { return key + std::to_string(k); };
  g.set(key + "NCX", std::move(cp.cx));
  g.set(key + "NCY", std::move(cp.cy));
  if (cp.dia) g.set(key + "RAD", dv(std::move(cp.dia), n(2)));
  for (int k = 1; k <= cp.count; ++k) {
    std::string a = key + "A" + std::to_string(k);
    g.set(a, add(cp.start->clone(), mul(n(k - 1), cp.step->clone())));
    auto cosA = [&] { return fn("COS", g.v(a)); };
    auto sinA = [&] { return fn("SIN", g.v(a)); };
    if (cp.fromCentre)
      g.fromPoint(pk(k), g.v(key + "NCX"), g.v(key + "NCY"), cosA(), sinA());
    else
      g.prePoint(pk(k), add(g.v(key + "NCX"), mul(g.v(key + "RAD"), cosA())),
                 add(g.v(key + "NCY"), mul(g.v(key + "RAD"), sinA())), mul(n(s), cosA()), mul(n(s), sinA()));
  }
  g.approach(g.v("PX" + pk(1)), g.v("PY" + pk(1)), g.measureZ(cp.height), cp.first);
  for (int k = 1; k <= cp.count; ++k) {
    if (k > 1 && !cp.fromCentre) {
      // Q301 = 1 over the clearance height, else at the measuring height; Q365 = 1 on an arc
      // about the nominal centre, 0 a straight line.
      for (int b = 0; b < 4; ++b) {
        bool up = b & 1, arc = b & 2;
        std::string cx = key + "NCX", cy = key + "NCY";
        ir::Region r = g.region([&] {
          g.between(pk(k), up, arc ? bin(OpCode::Gt, cp.step->clone(), n(0)) : nullptr, cx.c_str(), cy.c_str(),
                    cp.height);
        });
        g.when(bin(OpCode::And, eq(eq(g.p("Q301"), 1), up), eq(eq(g.p("Q365"), 1), arc)), std::move(r));
      }
    }
    g.probePlane(pk(k));
  }
  g.toClearance();
  fitCircle(g, key, cp.count);
}

// The circle through the points: a least-squares fit (Kasa) on the points less their mean,
// [Suu Suv; Suv Svv] (uc, vc) = (Suuu + Suvv, Svvv + Svuu) / 2; exact for points on a circle
// [model: the manual gives no formula].
void fitCircle(Gen &g, const std::string &key, int count) {
  auto sum = [&](auto term) {
    E e = term(1);
    for (int k = 2; k <= count; ++k) e = add(std::move(e), term(k));
    return e;
  };
  auto X = [&](int k) { return g.v("MX" + key + std::to_string(k)); };
  auto Y = [&](int k) { return g.v("MY" + key + std::to_string(k)); };
  auto U = [&](int k) { return sub(X(k), g.v(key + "MUX")); };
  auto V = [&](int k) { return sub(Y(k), g.v(key + "MUY")); };
  auto w = [&](const char *name) { return g.v(key + name); };
  g.set(key + "MUX", dv(sum(X), n(count)));
  g.set(key + "MUY", dv(sum(Y), n(count)));
  g.set(key + "SUU", sum([&](int k) { return mul(U(k), U(k)); }));
  g.set(key + "SVV", sum([&](int k) { return mul(V(k), V(k)); }));
  g.set(key + "SUV", sum([&](int k) { return mul(U(k), V(k)); }));
  g.set(key + "BU", dv(sum([&](int k) { return mul(U(k), add(mul(U(k), U(k)), mul(V(k), V(k)))); }), n(2)));
  g.set(key + "BV", dv(sum([&](int k) { return mul(V(k), add(mul(U(k), U(k)), mul(V(k), V(k)))); }), n(2)));
  g.set(key + "DET", sub(mul(w("SUU"), w("SVV")), mul(w("SUV"), w("SUV"))));
  g.abortIf(bin(OpCode::Lt, fn("ABS", w("DET")), n(1e-12)),
            fmt::format("TCH PROBE {}: the probed points lie on a line: no circle", g.c_.number));
  g.set(key + "UC", dv(sub(mul(w("BU"), w("SVV")), mul(w("BV"), w("SUV"))), w("DET")));
  g.set(key + "VC", dv(sub(mul(w("SUU"), w("BV")), mul(w("SUV"), w("BU"))), w("DET")));
  g.set(key + "CX", add(w("MUX"), w("UC")));
  g.set(key + "CY", add(w("MUY"), w("VC")));
  g.set(key + "DIA", mul(n(2), fn("SQRT", add(add(mul(w("UC"), w("UC")), mul(w("VC"), w("VC"))),
                                              dv(add(w("SUU"), w("SVV")), n(count))))));
}

E lineAngle(E ax, E ay, E bx, E by) {
  return fn("ATAN2_SIGNED", sub(std::move(by), std::move(ay)), sub(std::move(bx), std::move(ax)));
}

// Points 1 at the X− side, 2 X+, 3 Y−, 4 Y+ (inside: from the centre outward; outside: inward).
void probeRectangle(Gen &g, RectNames q, bool inside) {
  E half1 = dv(g.p(q.side1), n(2)), half2 = dv(g.p(q.side2), n(2));
  double s = inside ? 1 : -1;
  g.prePoint("1", sub(g.p(q.cx), half1->clone()), g.p(q.cy), n(-s), n(0));
  g.prePoint("2", add(g.p(q.cx), half1->clone()), g.p(q.cy), n(s), n(0));
  g.prePoint("3", g.p(q.cx), sub(g.p(q.cy), half2->clone()), n(0), n(-s));
  g.prePoint("4", g.p(q.cx), add(g.p(q.cy), half2->clone()), n(0), n(s));
  if (!inside)  // at the measuring height the way round the stud is the control's own
    g.abortIf(eq(g.p("Q301"), 0), fmt::format("TCH PROBE {} with Q301=0 (axis-parallel moves at the measuring height "
                                              "round the stud) is not simulated yet",
                                              g.c_.number));
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  for (int k = 1; k <= 4; ++k) {
    if (k > 1) g.betweenByQ301(std::to_string(k));
    g.probePlane(std::to_string(k));
  }
  g.toClearance();
  g.set("CX", dv(add(g.v("MX1"), g.v("MX2")), n(2)));
  g.set("CY", dv(add(g.v("MY3"), g.v("MY4")), n(2)));
}

void sizeLimits(Gen &g, std::vector<E> &rework, std::vector<E> &scrap, E value, const char *maxQ, const char *minQ,
                bool studLike) {
  E over = bin(OpCode::And, ne(g.p(maxQ), 0), bin(OpCode::Gt, value->clone(), g.p(maxQ)));
  E under = bin(OpCode::And, ne(g.p(minQ), 0), bin(OpCode::Lt, std::move(value), g.p(minQ)));
  (studLike ? rework : scrap).push_back(std::move(over));
  (studLike ? scrap : rework).push_back(std::move(under));
}

void measuringStatus(Gen &g, const std::vector<E> &reworkIf, const std::vector<E> &scrapIf) {
  auto any = [](const std::vector<E> &conds) {
    E e = n(0);
    for (const E &c : conds) e = bin(OpCode::Or, std::move(e), c->clone());
    return e;
  };
  // Scrap wins over rework [model]: the manual sets one flag per violation, not which.
  g.set("SCRAP", any(scrapIf));
  g.set("REWORK", bin(OpCode::And, any(reworkIf), eq(g.v("SCRAP"), 0)));
  g.setQ(182, g.v("SCRAP"));
  g.setQ(181, g.v("REWORK"));
  g.setQ(180, bin(OpCode::And, eq(g.v("SCRAP"), 0), eq(g.v("REWORK"), 0)));
  if (g.c_.given.count("Q309"))
    g.abortIf(bin(OpCode::And, eq(g.p("Q309"), 1), eq(qp(180), 0)),
              fmt::format("TCH PROBE {}: a measured value is out of tolerance (Q309=1: the program stops, L21254)",
                          g.c_.number));
}

void measuringOptions(Gen &g, bool hasTool) {
  // The log TCHPRnnn.TXT (Q281=1) and its display (2) do not change the run: a note on stderr.
  g.message(ne(g.p("Q281"), 0),
            fmt::format("TCH PROBE {}: the measuring log TCHPR{}.TXT (Q281) is not written by ncc", g.c_.number,
                        g.c_.number),
            "print");
  if (hasTool)
    g.abortIf(ne(g.p("Q330"), 0),
              fmt::format("TCH PROBE {}: tool monitoring (Q330 other than 0: DR of that tool corrected) is not "
                          "simulated yet",
                          g.c_.number));
}

}  // namespace ncc::hei::probe
