// TCH PROBE blocks (seed002b §2.9, HEI-TCH-01…03): the new form `TCH PROBE 410 <title>` with its
// parameter lines, and the old multi-block form `TCH PROBE 0.0 … Q5 X-` / `0.1 X+5 Y+0 Z-5`. All
// probe cycles act where they are defined (L14750): the block runs the cycle (ProbeGen.cpp).
#include "frontend/heidenhain/ProbeGen.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace ncc::hei {

namespace {
// The touch-probe cycles of the manual (seed002b §5.2): a number outside is no probe cycle.
bool knownProbeCycle(int n) {
  return n == 0 || n == 1 || n == 3 || n == 4 || (n >= 30 && n <= 33) || (n >= 400 && n <= 405) ||
         (n >= 408 && n <= 431) || n == 441 || (n >= 450 && n <= 453) || (n >= 460 && n <= 463) ||
         (n >= 480 && n <= 484) || (n >= 1400 && n <= 1499);
}

bool listed(std::string_view list, std::string_view q) {
  std::istringstream in{std::string(list)};
  for (std::string w; in >> w;)
    if (w == q || w.rfind(std::string(q) + "=", 0) == 0) return true;
  return false;
}
}  // namespace

bool BlockParser::tchProbe() {
  SourceLoc bl = loc(t_[0]);
  if (!expectWord("PROBE")) return false;
  const Token &n = tok();
  if (n.kind != Tok::Number) return fail(n, "TCH PROBE needs the cycle number");
  int number = (int)std::floor(n.num);
  int sub = n.isInt ? -1 : (int)std::lround((n.num - number) * 10);
  ++i_;
  if (!knownProbeCycle(number)) return fail(n, fmt::format("{} is not a touch-probe cycle", n.text), "cycle-invalid");
  // The probe table (the machine file) is in mm: an INCH program would read it as inches.
  if (f_.inch) return fail(t_[0], "touch-probe cycles in an INCH program are not simulated yet", "unsupported-code");
  if (sub >= 0) return oldProbeBlock(number, sub, n);
  while (!atEnd() && tok().line == n.line) ++i_;  // the title: free text
  const ProbeCycle *pc = findProbeCycle(number);
  ProbeCall call;
  call.number = number;
  call.loc = bl;
  call.table = f_.pp.opts.probe;
  std::set<std::string> seen;
  while (!atEnd()) {
    const Token &q = tok();
    std::string name;
    if (!cycleParamName(number, seen, name, "TCH PROBE")) return false;
    if (pc && !listed(pc->params, name))
      return fail(q, fmt::format("{} is not a parameter of touch-probe cycle {}", name, number), "cycle-parameter");
    // PREDEF: GLOBAL DEF 120 PROBING's value (Q320, Q260, Q301); FAUTO: the TOOL CALL's feed;
    // Q396=FMAX: the probe table's FMAX, which Q396=0 stands for in ncc's model (ProbeGen.cpp).
    CycleValue cv;
    if (!cycleValue(number, name, cv, pc != nullptr)) return false;
    if (!pc) continue;
    if (cv.kind == CycleValue::Text)
      return f_.error(cv.at, fmt::format("{}=\"…\" is not simulated yet", name), "unsupported-code");
    if (cv.kind == CycleValue::Fmax) cv.value = num(0, cv.at);
    call.given[name] = std::move(cv.value);
  }
  if (!pc)
    return fail(n, fmt::format("touch-probe cycle {} is not simulated yet (TCH PROBE)", number), "unsupported-code");
  std::istringstream in{std::string(pc->params)};
  for (std::string q; in >> q;) {
    if (call.given.count(q)) continue;
    std::string opt = std::string(pc->optional);
    size_t at = (" " + opt).find(" " + q + "=");
    if (at == std::string::npos)
      return fail(t_[0], fmt::format("TCH PROBE {} needs {}", number, q), "cycle-parameter");
    call.given[q] = num(std::stod(opt.substr(at + q.size() + 1)), bl);
  }
  Op note(OpKind::Comment, bl);
  note.set("text", Expr::string(fmt::format("TCH PROBE {}", number)));
  out().push_back(std::move(note));
  call.out = &out();
  call.vars = &f_.pp.probeVars;
  call.error = [&](std::string msg, const char *rule) { return fail(n, std::move(msg), rule); };
  if (number >= 400 && number <= 499) f_.pp.frames = true;  // the check of cycles 7, 8, 10, 11, 26
  return pc->lower(call);
}

// The old form: `0.0 <title> Qn X-` names the result parameter and the probing axis and
// direction, `0.1 X Y Z` the pre-position, which runs it. The other old cycles (1 polar datum,
// 3, 4 measuring, 30-33 TT) are refused at their n.0 block; their sub-blocks are then read only.
bool BlockParser::oldProbeBlock(int number, int sub, const Token &n) {
  auto &op = f_.oldProbe;
  if (sub == 0) {
    op.cycle = number;
    op.resultQ = -1;
    if (number != 0) {
      while (!atEnd()) ++i_;
      return fail(n, fmt::format("touch-probe cycle {} is not simulated yet (TCH PROBE {})", number, n.text), "unsupported-code");
    }
    // The title is free text up to the result parameter `Qn`, then the axis and direction `X-`.
    while (!atEnd() && !(tok().isWord("Q") && peek().kind == Tok::Number)) ++i_;
    if (atEnd()) return fail(tok(), "TCH PROBE 0.0 needs the result parameter Qn and the probing axis with its direction (X-)", "missing-word");
    const Token &qn = peek();
    if (!qn.isInt || qn.num > 1999) return fail(qn, "the result parameter is Q0 to Q1999 (L20850)", "cycle-parameter");
    i_ += 2;
    const Token &ax = tok();
    if (ax.kind != Tok::Word || ax.text.size() != 1 || std::string_view("XYZ").find(ax.text[0]) == std::string_view::npos)
      return fail(ax, "TCH PROBE 0.0: the probing axis X, Y or Z with its direction (X-) was expected", "cycle-parameter");
    ++i_;
    if (!tok().is("+") && !tok().is("-")) return fail(tok(), "TCH PROBE 0.0: the probing direction + or - was expected", "cycle-parameter");
    op.dir = tok().is("+") ? 1 : -1;
    op.axis = ax.text[0];
    ++i_;
    if (!atEnd()) return fail(tok(), fmt::format("unexpected '{}' in TCH PROBE 0.0", tok().text));
    op.resultQ = (int)qn.num;
    Op note(OpKind::Comment, loc(t_[0]));
    note.set("text", Expr::string(fmt::format("TCH PROBE 0.0 Q{} {}{}", op.resultQ, op.axis, op.dir > 0 ? '+' : '-')));
    out().push_back(std::move(note));
    return true;
  }
  if (op.cycle != number)
    return fail(n, fmt::format("TCH PROBE {} without TCH PROBE {}.0 before it", n.text, number), "cycle-invalid");
  if (number != 0) {  // refused at its n.0 already
    while (!atEnd()) ++i_;
    return true;
  }
  if (sub != 1 || op.resultQ < 0) return fail(n, "cycle 0 has the sub-blocks 0.0 and 0.1", "cycle-invalid");
  PathWords w;
  if (!words(w, kCoords, "TCH PROBE 0.1")) return false;
  ExprPtr pre[3];
  for (auto &c : w.coords) {
    size_t a = std::string_view("XYZ").find(c.axis);
    if (a == std::string_view::npos) return f_.error(c.loc, fmt::format("TCH PROBE 0.1 takes X, Y and Z, not {}", c.axis));
    if (c.inc) return f_.error(c.loc, "TCH PROBE 0.1 takes absolute coordinates");
    pre[a] = std::move(c.value);
  }
  if (!pre[0] || !pre[1] || !pre[2])
    return fail(t_[0], "TCH PROBE 0.1 needs the pre-position in X, Y and Z (L20858)", "missing-word");
  int resultQ = op.resultQ;
  op.resultQ = -1;  // one 0.1 per 0.0
  ProbeCall call;
  call.number = 0;
  call.loc = loc(t_[0]);
  call.table = f_.pp.opts.probe;
  call.out = &out();
  call.vars = &f_.pp.probeVars;
  call.error = [&](std::string msg, const char *rule) { return fail(n, std::move(msg), rule); };
  return lowerReferencePlane(call, resultQ, op.axis, op.dir, pre);
}

}  // namespace ncc::hei
