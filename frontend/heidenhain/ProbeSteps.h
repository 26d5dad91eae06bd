// The building blocks of the Heidenhain touch-probe cycles (docs/PROBING.md "Heidenhain
// touch-probe cycles"): `Gen` writes one cycle's NC IR ops (scratch variables, positioning and
// probing moves, results), and the shared features — a circle of probing points, a rectangle, two
// points on a line or across a width, one point — serve every cycle that probes that shape, so a
// cycle is its parameter names plus the features it probes and what it does with the result.
// The probe is the tool in the spindle: its controlled point is the stylus's south pole (the tool
// length's end), the ball centre R above it (R the tool radius, `$_tool_diameter` / 2). Each
// probing is LinuxCNC's G38.2 (a miss is an error: the manual's "no deflection within DIST") from
// the pre-position toward the nominal point for DIST, at the probe table's F; the probe-results
// file says where it switched; the probe goes back to the pre-position at rapid (L14516-L14540).
#pragma once
#include "frontend/heidenhain/ProbeGen.h"

#include <fmt/format.h>

#include <string>

namespace ncc::hei::probe {

using E = ExprPtr;

inline E n(double v) { return Expr::number(v, ir::Type::Real); }
inline E bin(OpCode op, E a, E b) { return Expr::binary(op, std::move(a), std::move(b)); }
inline E add(E a, E b) { return bin(OpCode::Add, std::move(a), std::move(b)); }
inline E sub(E a, E b) { return bin(OpCode::Sub, std::move(a), std::move(b)); }
inline E mul(E a, E b) { return bin(OpCode::Mul, std::move(a), std::move(b)); }
inline E dv(E a, E b) { return bin(OpCode::Div, std::move(a), std::move(b)); }
inline E eq(E a, double b) { return bin(OpCode::Eq, std::move(a), n(b)); }
inline E ne(E a, double b) { return bin(OpCode::Ne, std::move(a), n(b)); }
inline E sys(const char *v) { return Expr::var(ir::VarSpace::System, v, nullptr); }
inline E qp(int q) { return Expr::var(ir::VarSpace::QParam, "Q", Expr::number(q, ir::Type::Int)); }
inline E fn(const char *name, E a, E b = nullptr) {
  std::vector<E> args;
  args.push_back(std::move(a));
  if (b) args.push_back(std::move(b));
  return Expr::call(name, std::move(args));
}

// The ops of one probe cycle: scratch variables `%%_HEI_TP_…` (program-wide), moves, results.
// A probing point is named by a key ("1", "H2_3"): its unit direction DXk/DYk, its start PXk/PYk
// and the measured surface point MXk/MYk.
class Gen {
public:
  explicit Gen(ProbeCall &c) : c_(c) {}
  ProbeCall &c_;

  E v(const std::string &name);
  E p(const char *q) { return v(q); }  // a parameter, frozen at the start
  void emit(Op o);
  void set(const std::string &name, E value) { emit(assignOp(v(name), std::move(value), c_.loc)); }
  void setQ(int q, E value) { emit(assignOp(qp(q), std::move(value), c_.loc)); }
  void when(E cond, ir::Region then, ir::Region otherwise = {});
  void message(E cond, const std::string &text, const char *kind);
  void abortIf(E cond, const std::string &text) { message(std::move(cond), text, "abort"); }
  void feed(E value);
  void motion(const char *mode);
  // A positioning move: pre-positioning (F_PREPOS: machine rapid or FMAX) or between the probing
  // points (always the table's FMAX, L14824).
  void position(E x, E y, E z, bool prepos = false);
  void rapidBack(E x, E y, E z);  // the return to the probing's start: at rapid (L14538)
  void offset(const char *kind, const char *axis, E value);  // set_offset of the active system

  // The start of every cycle: parameters frozen, the ball radius, the modal feed kept.
  void begin();
  void needsProbe();
  void end();
  // The ball centre's measuring height (Q261 or another) as the south pole's Z.
  E measureZ(const char *height = "Q261") { return sub(p(height), v("R")); }
  // The positioning logic (L14792-L14806): below the clearance height Q260 the probe first goes
  // up to it; then in the plane to (x, y), then down to z.
  void approach(E x, E y, E z, bool prepos = true);
  void toClearance() { position(nullptr, nullptr, p("Q260")); }

  // Point k probes the nominal contact point (ex, ey) in the unit direction (dx, dy), starting
  // SET_UP + Q320 + R before it; `fromPoint` starts at (px, py) itself (a hole probed from its centre).
  void prePoint(const std::string &k, E ex, E ey, E dx, E dy);
  void fromPoint(const std::string &k, E px, E py, E dx, E dy);
  void probePlane(const std::string &k);
  // Probing down the probe axis at (x, y) onto the nominal surface z: MZk is the south pole's Z;
  // the way there is the pre-positioning (`first`) or at FMAX.
  void probeAxis(const std::string &k, E x, E y, E z, bool first = true);
  // To the start of point k from the one before: at the measuring height or over the clearance
  // height; on an arc about (cx, cy) when arcCcw is given (its value: counter-clockwise).
  void between(const std::string &k, bool viaClearance, E arcCcw = nullptr, const char *cx = nullptr,
               const char *cy = nullptr, const char *height = "Q261");
  void betweenByQ301(const std::string &k, const char *height = "Q261");

  template <class F>
  ir::Region region(F body) {
    ir::Region r;
    ir::Region *saved = c_.out;
    c_.out = &r;
    body();
    c_.out = saved;
    return r;
  }

  void noTransforms(bool frames);
  // The datum (408-419, L17426-L17475) from the measured point; valX/valY the values it gets.
  void datum(E mx, E my, E mz, const char *valX = "Q331", const char *valY = "Q332");
  void axisDatumProbe();  // Q381=1: the probe axis too, at (Q382, Q383) onto Q384
  E axisDatumZ();
  // The basic rotation of the active preset (G10 L2 R: about its origin).
  void basicRotation(E angle) { offset("g10l2", "R", std::move(angle)); }
};

// A literal parameter whose value picks the probe sequence (Q272, Q423, Q308): its value, or an
// error at the block when it is not one of `allowed` (a number written in the block).
bool literalChoice(ProbeCall &c, const char *q, std::initializer_list<int> allowed, const char *what, int &out);

// A circle of probing points (412/413, 421/422, 402, and the holes of 401, 416, 418, 430). The
// fitted centre and diameter go to <key>CX, <key>CY, <key>DIA.
struct CircleProbe {
  std::string key;
  E cx, cy, dia, start, step;  // nominal centre and diameter, first angle, angle step
  int count = 4;
  bool inside = true;
  bool fromCentre = false;   // a hole probed outward from its nominal centre (no diameter given)
  bool first = true;         // the cycle's first feature: pre-positioning; else from Q260 at FMAX
  const char *height = "Q261";
};
void probeCircle(Gen &g, CircleProbe cp);
// The circle of 412/413 and 421/422: centre (cx, cy), diameter Q262, from Q325 in steps of Q247.
CircleProbe circleOf(Gen &g, const char *cx, const char *cy, int count, bool inside);
void fitCircle(Gen &g, const std::string &key, int count);
// The line from point a to point b: its angle to ax1, degrees (-180, 180].
E lineAngle(E ax, E ay, E bx, E by);

// The rectangle of 410/411, 423/424: sides 1 (X−) 2 (X+) 3 (Y−) 4 (Y+); its centre in CX, CY.
struct RectNames {
  const char *cx, *cy, *side1, *side2;
};
void probeRectangle(Gen &g, RectNames q, bool inside);

// Tolerance monitoring of the measuring cycles (L20708-L20748): each result against its limits
// (a limit 0 is not checked); the status Q180 (within), Q181 (rework), Q182 (scrap).
void measuringStatus(Gen &g, const std::vector<E> &reworkIf, const std::vector<E> &scrapIf);
// A size against max/min (0: no check): over max or under min, which of the two needs rework
// depends on whether the feature keeps material (a stud too big) or lost it (a hole too big).
void sizeLimits(Gen &g, std::vector<E> &rework, std::vector<E> &scrap, E value, const char *maxQ, const char *minQ,
                bool studLike);
// The measuring cycles' common parameters: Q281 (the log), Q330 (tool monitoring).
void measuringOptions(Gen &g, bool hasTool);

}  // namespace ncc::hei::probe
