// The touch-probe cycles as NC IR (docs/PROBING.md "Heidenhain touch-probe cycles"). The probe is
// the tool in the spindle: its controlled point is the stylus's south pole (the tool length's
// end), the ball centre R above it (R the tool radius, `$_tool_diameter` / 2). Each probing is
// LinuxCNC's G38.2 (a miss is an error: the manual's "no deflection within DIST") from the
// pre-position toward the nominal point for DIST, at the probe table's F; the probe-results file
// says where it switched; the probe goes back to the pre-position at rapid (L14516-L14540).
#include "frontend/heidenhain/ProbeGen.h"

#include <fmt/format.h>

namespace ncc::hei {

namespace {
using E = ExprPtr;

E n(double v) { return Expr::number(v, ir::Type::Real); }
E bin(OpCode op, E a, E b) { return Expr::binary(op, std::move(a), std::move(b)); }
E add(E a, E b) { return bin(OpCode::Add, std::move(a), std::move(b)); }
E sub(E a, E b) { return bin(OpCode::Sub, std::move(a), std::move(b)); }
E mul(E a, E b) { return bin(OpCode::Mul, std::move(a), std::move(b)); }
E dv(E a, E b) { return bin(OpCode::Div, std::move(a), std::move(b)); }
E sys(const char *v) { return Expr::var(ir::VarSpace::System, v, nullptr); }
E qp(int q) { return Expr::var(ir::VarSpace::QParam, "Q", Expr::number(q, ir::Type::Int)); }
E fn(const char *name, E a, E b = nullptr) {
  std::vector<E> args;
  args.push_back(std::move(a));
  if (b) args.push_back(std::move(b));
  return Expr::call(name, std::move(args));
}
const char *const kAxisName[3] = {"X", "Y", "Z"};

// The ops of one probe cycle: scratch variables `%%_HEI_TP_…` (program-wide), moves, results.
class Gen {
public:
  explicit Gen(ProbeCall &c) : c_(c) {}
  ProbeCall &c_;

  E v(const std::string &name) {
    std::string full = "_HEI_TP_" + name;
    c_.vars->insert(full);
    return hglobal(full.c_str(), c_.loc);
  }
  E p(const char *q) { return v(q); }  // a parameter, frozen at the start
  void emit(Op o) {
    o.loc = c_.loc;
    c_.out->push_back(std::move(o));
  }
  void set(const std::string &name, E value) { emit(assignOp(v(name), std::move(value), c_.loc)); }
  void setQ(int q, E value) { emit(assignOp(qp(q), std::move(value), c_.loc)); }
  void when(E cond, ir::Region then) {
    Op o(OpKind::If, c_.loc);
    o.set("cond", std::move(cond));
    o.regions.push_back(std::move(then));
    emit(std::move(o));
  }
  void abortIf(E cond, const std::string &text) {
    Op m(OpKind::Message, c_.loc);
    m.set("text", Expr::string(text, c_.loc));
    m.set("kind", Expr::symbol("abort"));
    ir::Region r;
    r.push_back(std::move(m));
    when(std::move(cond), std::move(r));
  }
  void feed(E value) {
    Op o(OpKind::Feed, c_.loc);
    o.set("value", std::move(value));
    emit(std::move(o));
  }
  void motion(const char *mode) {
    Op m(OpKind::Mode, c_.loc);
    m.set("motion", Expr::symbol(mode));
    emit(std::move(m));
  }
  // A positioning move: pre-positioning (the first point of a cycle, F_PREPOS: machine rapid or
  // FMAX) or between the probing points (always the table's FMAX, L14824).
  void position(E x, E y, E z, bool prepos = false) {
    if (prepos && c_.table.preposRapid) {
      motion("rapid");
    } else {
      feed(n(c_.table.fmax));
      motion("linear");
    }
    Op mv(OpKind::Move, c_.loc);
    if (x) mv.set("X", std::move(x));
    if (y) mv.set("Y", std::move(y));
    if (z) mv.set("Z", std::move(z));
    emit(std::move(mv));
  }
  void rapidBack(E x, E y, E z) {  // the return to the probing's start: at rapid (L14538)
    motion("rapid");
    Op mv(OpKind::Move, c_.loc);
    mv.set("X", std::move(x));
    mv.set("Y", std::move(y));
    mv.set("Z", std::move(z));
    emit(std::move(mv));
  }

  // The start of every cycle: parameters frozen, the ball radius, the modal feed kept.
  void begin() {
    needsProbe();
    noTransforms(c_.number >= 400 && c_.number <= 499);
    for (auto &[q, e] : c_.given) set(q, e->clone());
    set("R", dv(sys("_tool_diameter"), n(2)));
    set("FEED", sys("_feed"));
    set("CLR", add(n(c_.table.setUp), p("Q320")));  // SET_UP + Q320: before the ball's surface
  }
  // The probe is the tool in the spindle: a TOOL CALL must come first (L16241, HEI-TOOL-04).
  void needsProbe() {
    abortIf(bin(OpCode::Le, sys("_current_tool"), n(0)),
            fmt::format("TCH PROBE {} needs the touch probe in the spindle: a TOOL CALL before it (L16241)", c_.number));
  }
  void end() {
    ir::Region back;
    Op f(OpKind::Feed, c_.loc);
    f.set("value", v("FEED"));
    back.push_back(std::move(f));
    when(bin(OpCode::Gt, v("FEED"), n(0)), std::move(back));
  }
  // The measuring height of the ball centre Q261 as the south pole's Z.
  E measureZ() { return sub(p("Q261"), v("R")); }
  // The positioning logic (L14792-L14806): below the clearance height Q260 the probe first goes
  // up to it; then in the plane to (x, y), then down to z.
  void approach(E x, E y, E z) {
    when(bin(OpCode::Lt, sys("_z"), p("Q260")), region([&] { position(nullptr, nullptr, p("Q260"), true); }));
    position(std::move(x), std::move(y), nullptr, true);
    position(nullptr, nullptr, std::move(z), true);
  }
  void toClearance() { position(nullptr, nullptr, p("Q260")); }

  // Probing point k in the plane: the nominal contact point (ex, ey) probed in the unit direction
  // (dx, dy). The ball centre starts CLR + R before it (PREk), probes for DIST, goes back; the
  // measured surface point (MXk, MYk) is the ball centre where it switched plus R along d.
  void prePoint(int k, E ex, E ey, E dx, E dy) {
    std::string s = std::to_string(k);
    set("DX" + s, std::move(dx));
    set("DY" + s, std::move(dy));
    E off = add(v("CLR"), v("R"));
    set("PX" + s, sub(std::move(ex), mul(off->clone(), v("DX" + s))));
    set("PY" + s, sub(std::move(ey), mul(std::move(off), v("DY" + s))));
  }
  void probePlane(int k) {
    std::string s = std::to_string(k);
    feed(n(c_.table.feed));
    motion("probe_toward");
    Op mv(OpKind::Move, c_.loc);
    mv.set("X", add(v("PX" + s), mul(n(c_.table.dist), v("DX" + s))));
    mv.set("Y", add(v("PY" + s), mul(n(c_.table.dist), v("DY" + s))));
    emit(std::move(mv));
    set("MX" + s, add(sys("_probe_x"), mul(v("R"), v("DX" + s))));
    set("MY" + s, add(sys("_probe_y"), mul(v("R"), v("DY" + s))));
    rapidBack(v("PX" + s), v("PY" + s), sys("_z"));
  }
  // Probing down the probe axis at (x, y) onto the nominal surface z: MZk is the south pole's Z.
  void probeAxis(const std::string &k, E x, E y, E z) {
    set("PZ" + k, add(std::move(z), v("CLR")));
    approach(std::move(x), std::move(y), v("PZ" + k));
    feed(n(c_.table.feed));
    motion("probe_toward");
    Op mv(OpKind::Move, c_.loc);
    mv.set("Z", sub(v("PZ" + k), n(c_.table.dist)));
    emit(std::move(mv));
    set("MZ" + k, sys("_probe_z"));
    rapidBack(sys("_x"), sys("_y"), v("PZ" + k));
  }
  // To the pre-position of point k from the one before: at the measuring height (Q301=0) or
  // over the clearance height (Q301=1); on an arc about (cx, cy) when `arc` says so.
  void between(int k, bool viaClearance, E arcCcw = nullptr, const char *cx = nullptr, const char *cy = nullptr) {
    std::string s = std::to_string(k);
    if (viaClearance) toClearance();
    if (arcCcw) {
      // The direction of the circle's points: Q247 > 0 counter-clockwise.
      for (int ccw = 0; ccw < 2; ++ccw) {
        ir::Region r = region([&] {
          feed(n(c_.table.fmax));
          motion(ccw ? "arc_ccw" : "arc_cw");
          Op mv(OpKind::Move, c_.loc);
          mv.set("X", v("PX" + s));
          mv.set("Y", v("PY" + s));
          mv.set("I", v(cx));
          mv.set("J", v(cy));
          mv.set("ac", Expr::symbol("IJ"));
          emit(std::move(mv));
        });
        when(bin(ccw ? OpCode::Ne : OpCode::Eq, arcCcw->clone(), n(0)), std::move(r));
      }
    } else {
      position(v("PX" + s), v("PY" + s), nullptr);
    }
    if (viaClearance) position(nullptr, nullptr, measureZ());
  }

  // The ops `body` writes, as a region (of an `if`).
  template <class F>
  ir::Region region(F body) {
    ir::Region r;
    ir::Region *saved = c_.out;
    c_.out = &r;
    body();
    c_.out = saved;
    return r;
  }
  // To point k over the clearance height (Q301=1) or at the measuring height.
  void betweenByQ301(int k) {
    Op o(OpKind::If, c_.loc);
    o.set("cond", bin(OpCode::Eq, p("Q301"), n(1)));
    o.regions.push_back(region([&] { between(k, true); }));
    o.regions.push_back(region([&] { between(k, false); }));
    emit(std::move(o));
  }

  // The probe cycles 400-499 run without cycles 7, 8, 10, 11, 26 active (L14755-L14765, HEI-TCH-04):
  // their results would be in a shifted system and the datum written wrong.
  void noTransforms(bool frames) {
    if (!frames) return;
    E active = bin(OpCode::Ne, hglobal(kShiftX), n(0));
    for (const char *g : {kShiftY, kShiftZ, kRot, kMirror[0], kMirror[1]})
      active = bin(OpCode::Or, std::move(active), bin(OpCode::Ne, hglobal(g), n(0)));
    for (const char *g : {kScl, kAxisScl[0], kAxisScl[1], kAxisScl[2]})
      active = bin(OpCode::Or, std::move(active), bin(OpCode::Ne, hglobal(g), n(1)));
    abortIf(std::move(active), fmt::format("TCH PROBE {}: cycles 7, 8, 10, 11 and 26 must be reset before a touch-probe "
                                           "cycle 400-499 (L14755)",
                                           c_.number));
  }

  // Writes the datum (408-419, L17426-L17475): Q305 = 0 makes the measured point the active
  // preset's origin with the values Q331/Q332/Q333 (the display is set, whatever Q303 says);
  // Q305 > 0 writes a row of the datum (Q303=0) or preset table (Q303=1) that only cycle 7 #n or
  // 247 would activate (both refused by ncc): no effect on the motion. Q303=-1 is an error.
  void datum(E mx, E my, E mz) {
    abortIf(bin(OpCode::Eq, p("Q303"), n(-1)),
            fmt::format("TCH PROBE {}: Q303=-1 (an imported program) is an error: set Q303 to 0 or 1 (L17460)", c_.number));
    Op o(OpKind::SetOffset, c_.loc);
    o.set("kind", Expr::symbol("g10l20"));
    o.set("index", Expr::number(0, ir::Type::Int));
    if (mx) o.set("X", add(sub(sys("_x"), std::move(mx)), p("Q331")));
    if (my) o.set("Y", add(sub(sys("_y"), std::move(my)), p("Q332")));
    if (mz) o.set("Z", add(sub(sys("_z"), std::move(mz)), p("Q333")));
    ir::Region r;
    r.push_back(std::move(o));
    r.back().loc = c_.loc;
    when(bin(OpCode::Eq, p("Q305"), n(0)), std::move(r));
  }
  // Q381=1: the datum in the probe axis too, probed at (Q382, Q383) onto Q384 (L17676-L17709).
  void axisDatumProbe() {
    set("MZA", n(0));
    when(bin(OpCode::Eq, p("Q381"), n(1)), region([&] {
           probeAxis("A", p("Q382"), p("Q383"), p("Q384"));
           toClearance();
         }));
  }
  // The Z datum's measured value when Q381=1; else Q333, which leaves Z reading as it does.
  E axisDatumZ() {
    return add(mul(bin(OpCode::Eq, p("Q381"), n(1)), v("MZA")), mul(bin(OpCode::Ne, p("Q381"), n(1)), p("Q333")));
  }
};

// 410 / 411 (L17935-L18424): the rectangle's four sides, 1 and 2 on ax1 (X), 3 and 4 on ax2 (Y).
bool rectangle(ProbeCall &c, bool inside) {
  Gen g(c);
  g.begin();
  E half1 = dv(g.p("Q323"), n(2)), half2 = dv(g.p("Q324"), n(2));
  double s = inside ? 1 : -1;  // inside: from the centre outward; outside: from outside inward
  g.prePoint(1, sub(g.p("Q321"), half1->clone()), g.p("Q322"), n(-s), n(0));
  g.prePoint(2, add(g.p("Q321"), half1->clone()), g.p("Q322"), n(s), n(0));
  g.prePoint(3, g.p("Q321"), sub(g.p("Q322"), half2->clone()), n(0), n(-s));
  g.prePoint(4, g.p("Q321"), add(g.p("Q322"), half2->clone()), n(0), n(s));
  if (!inside)  // at the measuring height the way round the stud is the control's own
    g.abortIf(bin(OpCode::Eq, g.p("Q301"), n(0)),
              "TCH PROBE 411 with Q301=0 (axis-parallel moves at the measuring height round the stud) is not simulated yet");
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  for (int k = 1; k <= 4; ++k) {
    if (k > 1) {
      g.betweenByQ301(k);
    }
    g.probePlane(k);
  }
  g.toClearance();
  g.set("CX", dv(add(g.v("MX1"), g.v("MX2")), n(2)));
  g.set("CY", dv(add(g.v("MY3"), g.v("MY4")), n(2)));
  g.axisDatumProbe();
  g.setQ(151, g.v("CX"));
  g.setQ(152, g.v("CY"));
  g.setQ(154, fn("ABS", sub(g.v("MX2"), g.v("MX1"))));
  g.setQ(155, fn("ABS", sub(g.v("MY4"), g.v("MY3"))));
  g.datum(g.v("CX"), g.v("CY"), g.axisDatumZ());
  g.end();
  return true;
}
bool cycle410(ProbeCall &c) { return rectangle(c, true); }
bool cycle411(ProbeCall &c) { return rectangle(c, false); }

// 412 / 413 (L18425-L19007): Q423 points (3 or 4) on the circle from Q325 in steps of Q247,
// probed radially (outward in a hole, inward on a stud). The centre and diameter are the circle
// through them: a least-squares fit (Kasa), exact for points on a circle [model: the manual
// gives no formula].
bool circle(ProbeCall &c, bool inside) {
  Gen g(c);
  auto it = c.given.find("Q423");
  int count = 4;
  if (it != c.given.end()) {
    const Expr &e = *it->second;
    if (e.kind != ir::ExprKind::Number || (e.num != 3 && e.num != 4))
      return c.error(fmt::format("TCH PROBE {}: Q423 (the number of probing points) must be the number 3 or 4", c.number),
                     "cycle-parameter");
    count = (int)e.num;
  }
  g.begin();
  g.set("RAD", dv(g.p("Q262"), n(2)));
  double s = inside ? 1 : -1;
  for (int k = 1; k <= count; ++k) {
    std::string a = "A" + std::to_string(k);
    g.set(a, add(g.p("Q325"), mul(n(k - 1), g.p("Q247"))));
    auto cosA = [&] { return fn("COS", g.v(a)); };
    auto sinA = [&] { return fn("SIN", g.v(a)); };
    g.prePoint(k, add(g.p("Q321"), mul(g.v("RAD"), cosA())), add(g.p("Q322"), mul(g.v("RAD"), sinA())),
               mul(n(s), cosA()), mul(n(s), sinA()));
  }
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  g.set("CCX", g.p("Q321"));
  g.set("CCY", g.p("Q322"));
  for (int k = 1; k <= count; ++k) {
    if (k > 1) {
      // Q301 = 1 over the clearance height, else at the measuring height; Q365 = 1 on an arc
      // about the nominal centre, 0 a straight line.
      for (int b = 0; b < 4; ++b) {
        bool up = b & 1, arc = b & 2;
        ir::Region r = g.region([&] { g.between(k, up, arc ? bin(OpCode::Gt, g.p("Q247"), n(0)) : nullptr, "CCX", "CCY"); });
        g.when(bin(OpCode::And, bin(OpCode::Eq, bin(OpCode::Eq, g.p("Q301"), n(1)), n(up)),
                   bin(OpCode::Eq, bin(OpCode::Eq, g.p("Q365"), n(1)), n(arc))),
               std::move(r));
      }
    }
    g.probePlane(k);
  }
  g.toClearance();
  // Kasa fit on the points less their mean: [Suu Suv; Suv Svv] (uc, vc) = (Suuu + Suvv, Svvv + Svuu) / 2.
  auto sum = [&](auto term) {
    E e = term(1);
    for (int k = 2; k <= count; ++k) e = add(std::move(e), term(k));
    return e;
  };
  auto U = [&](int k) { return sub(g.v("MX" + std::to_string(k)), g.v("MUX")); };
  auto V = [&](int k) { return sub(g.v("MY" + std::to_string(k)), g.v("MUY")); };
  g.set("MUX", dv(sum([&](int k) { return g.v("MX" + std::to_string(k)); }), n(count)));
  g.set("MUY", dv(sum([&](int k) { return g.v("MY" + std::to_string(k)); }), n(count)));
  g.set("SUU", sum([&](int k) { return mul(U(k), U(k)); }));
  g.set("SVV", sum([&](int k) { return mul(V(k), V(k)); }));
  g.set("SUV", sum([&](int k) { return mul(U(k), V(k)); }));
  g.set("BU", dv(sum([&](int k) { return mul(U(k), add(mul(U(k), U(k)), mul(V(k), V(k)))); }), n(2)));
  g.set("BV", dv(sum([&](int k) { return mul(V(k), add(mul(U(k), U(k)), mul(V(k), V(k)))); }), n(2)));
  g.set("DET", sub(mul(g.v("SUU"), g.v("SVV")), mul(g.v("SUV"), g.v("SUV"))));
  g.abortIf(bin(OpCode::Lt, fn("ABS", g.v("DET")), n(1e-12)),
            fmt::format("TCH PROBE {}: the probed points lie on a line: no circle", c.number));
  g.set("UC", dv(sub(mul(g.v("BU"), g.v("SVV")), mul(g.v("BV"), g.v("SUV"))), g.v("DET")));
  g.set("VC", dv(sub(mul(g.v("SUU"), g.v("BV")), mul(g.v("SUV"), g.v("BU"))), g.v("DET")));
  g.set("CX", add(g.v("MUX"), g.v("UC")));
  g.set("CY", add(g.v("MUY"), g.v("VC")));
  g.set("DIA", mul(n(2), fn("SQRT", add(add(mul(g.v("UC"), g.v("UC")), mul(g.v("VC"), g.v("VC"))),
                                         dv(add(g.v("SUU"), g.v("SVV")), n(count))))));
  g.axisDatumProbe();
  g.setQ(151, g.v("CX"));
  g.setQ(152, g.v("CY"));
  g.setQ(153, g.v("DIA"));
  g.datum(g.v("CX"), g.v("CY"), g.axisDatumZ());
  g.end();
  return true;
}
bool cycle412(ProbeCall &c) { return circle(c, true); }
bool cycle413(ProbeCall &c) { return circle(c, false); }

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

// 419 DATUM IN ONE AXIS (L20166-L20346): one probing at (Q263, Q264) along axis Q272 (1 X, 2 Y,
// 3 the probe axis Z) in the direction Q267; the datum Q333 in that axis (L20255-L20274: the
// datum value of every axis is Q333).
bool cycle419(ProbeCall &c) {
  Gen g(c);
  auto it = c.given.find("Q272");
  if (it == c.given.end() || it->second->kind != ir::ExprKind::Number ||
      (it->second->num != 1 && it->second->num != 2 && it->second->num != 3))
    return c.error("TCH PROBE 419: Q272 (the measuring axis) must be the number 1, 2 or 3", "cycle-parameter");
  int axis = (int)it->second->num;
  g.begin();
  g.abortIf(bin(OpCode::And, bin(OpCode::Ne, g.p("Q267"), n(1)), bin(OpCode::Ne, g.p("Q267"), n(-1))),
            "TCH PROBE 419: Q267 (the direction) must be +1 or -1");
  if (axis == 3) {
    g.abortIf(bin(OpCode::Ne, g.p("Q267"), n(-1)),
              "TCH PROBE 419 in the probe axis with Q267=+1 (probing upward) is not simulated yet");
    // Onto the measuring height Q261 as the nominal surface, from above.
    g.probeAxis("1", g.p("Q263"), g.p("Q264"), g.p("Q261"));
    g.toClearance();
    g.datum(nullptr, nullptr, g.v("MZ1"));
  } else {
    E dx = axis == 1 ? g.p("Q267") : n(0), dy = axis == 2 ? g.p("Q267") : n(0);
    g.prePoint(1, g.p("Q263"), g.p("Q264"), std::move(dx), std::move(dy));
    g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
    g.probePlane(1);
    g.toClearance();
    g.set("Q331", g.p("Q333"));
    g.set("Q332", g.p("Q333"));
    if (axis == 1) g.datum(g.v("MX1"), nullptr, nullptr);
    else g.datum(nullptr, g.v("MY1"), nullptr);
  }
  g.end();
  return true;
}

// 400 BASIC ROTATION (L16211-L16362): two points on a line along ax1 (Q272=1) or ax2 (Q272=2),
// probed in the direction Q267 across it; the basic rotation is the line's angle less its
// nominal angle Q307, set on the active preset (Q305=0: the manual mode's ROT, L16353). The
// cycle cancels an active basic rotation first (L16243).
bool cycle400(ProbeCall &c) {
  Gen g(c);
  auto it = c.given.find("Q272");
  if (it == c.given.end() || it->second->kind != ir::ExprKind::Number || (it->second->num != 1 && it->second->num != 2))
    return c.error("TCH PROBE 400: Q272 (the measuring axis) must be the number 1 or 2", "cycle-parameter");
  int axis = (int)it->second->num;
  g.begin();
  g.abortIf(bin(OpCode::Ne, g.p("Q305"), n(0)),
            "TCH PROBE 400 with Q305 other than 0 (the rotation into a preset-table row) is not simulated yet");
  Op off(OpKind::SetOffset, c.loc);
  off.set("kind", Expr::symbol("g10l2"));
  off.set("index", Expr::number(0, ir::Type::Int));
  off.set("R", n(0));
  g.emit(std::move(off));
  for (int k = 1; k <= 2; ++k) {
    E dx = axis == 2 ? g.p("Q267") : n(0), dy = axis == 1 ? g.p("Q267") : n(0);
    g.prePoint(k, g.p(k == 1 ? "Q263" : "Q265"), g.p(k == 1 ? "Q264" : "Q266"), std::move(dx), std::move(dy));
  }
  g.approach(g.v("PX1"), g.v("PY1"), g.measureZ());
  g.probePlane(1);
  g.betweenByQ301(2);
  g.probePlane(2);
  g.toClearance();
  // The line from point 1 to point 2 against ax1 (Q272=2: against ax2, 90 less).
  g.set("ROT", sub(sub(fn("ATAN2_SIGNED", sub(g.v("MY2"), g.v("MY1")), sub(g.v("MX2"), g.v("MX1"))),
                       n(axis == 2 ? 90 : 0)),
                   g.p("Q307")));
  Op rot(OpKind::SetOffset, c.loc);
  rot.set("kind", Expr::symbol("g10l2"));
  rot.set("index", Expr::number(0, ir::Type::Int));
  rot.set("R", g.v("ROT"));
  g.emit(std::move(rot));
  g.end();
  return true;
}

const ProbeCycle kProbeCycles[] = {
    {400, "Q263 Q264 Q265 Q266 Q272 Q267 Q261 Q320 Q260 Q301 Q307 Q305", "", cycle400},
    {410, "Q321 Q322 Q323 Q324 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle410},
    {411, "Q321 Q322 Q323 Q324 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0", cycle411},
    {412, "Q321 Q322 Q262 Q325 Q247 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333 Q423 Q365",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0 Q423=4 Q365=0", cycle412},
    {413, "Q321 Q322 Q262 Q325 Q247 Q261 Q320 Q260 Q301 Q305 Q331 Q332 Q303 Q381 Q382 Q383 Q384 Q333 Q423 Q365",
     "Q331=0 Q332=0 Q381=0 Q382=0 Q383=0 Q384=0 Q333=0 Q423=4 Q365=0", cycle413},
    {417, "Q263 Q264 Q294 Q320 Q260 Q305 Q333 Q303", "Q333=0", cycle417},
    {419, "Q263 Q264 Q261 Q320 Q260 Q272 Q267 Q305 Q333 Q303", "Q333=0", cycle419},
};
}  // namespace

const ProbeCycle *findProbeCycle(int number) {
  for (const ProbeCycle &p : kProbeCycles)
    if (p.number == number) return &p;
  return nullptr;
}

// Cycle 0 (L20805-L20864): a rapid 3-D move to the pre-position, one probing along the axis, back
// to the start; Q<n> the measured coordinate (the surface: the ball's radius added in the plane,
// the south pole in the probe axis), Q115-Q117 where the probe switched (X Y Z of its controlled
// point, without the radius: L20819-L20822).
bool lowerReferencePlane(ProbeCall &c, int resultQ, char axis, int dir, ExprPtr pre[3]) {
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
