// The SL cycles (docs/HEIDENHAIN.md "SL cycles", manual L8830-L9670): 14 CONTOUR names the
// contour subprograms, 20 CONTOUR DATA the depths, allowances and heights, and CYCL CALL of 21
// PILOT DRILLING, 22 ROUGH-OUT or 23 FLOOR FINISHING captures each subprogram as a sub-contour
// (NC IR `contour action=begin|end use=subcontour` around its `call_section`: the core decides
// pocket or island from its direction and RL/RR) and runs the core's region consumer with the
// values the definitions froze (program-wide `%%_HEI_SL<cycle>_Q<n>`).
#include "frontend/heidenhain/Parser.h"
#include "ir/WordList.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::hei {

namespace {
struct SlCycle {
  int number;
  const char *name;
  const char *params;  // the parameters it takes, each once
};
constexpr SlCycle kSl[] = {
    {20, "CONTOUR DATA", "Q1 Q2 Q3 Q4 Q5 Q6 Q7 Q8 Q9"},
    {21, "PILOT DRILLING", "Q10 Q11 Q13"},
    {22, "ROUGH-OUT", "Q10 Q11 Q12 Q18 Q19 Q208 Q401 Q404"},
    {23, "FLOOR FINISHING", "Q11 Q12 Q208"},
    {24, "SIDE FINISHING", "Q9 Q10 Q11 Q12 Q14 Q438"},
    {25, "CONTOUR TRAIN", "Q1 Q3 Q5 Q7 Q10 Q11 Q12 Q15 Q18 Q446 Q447 Q448"},
    {270, "CONTOUR TRAIN DATA", "Q390 Q391 Q392 Q393 Q394"},
};

// The tool parameters a QS string may give by name, and the parameters of GLOBAL DEF 111.
constexpr const char *kToolParams = "Q13 Q18 Q438";
constexpr const char *kContourDefaults = "Q2 Q6 Q7 Q9";

const SlCycle *slRow(int number) {
  for (auto &c : kSl)
    if (c.number == number) return &c;
  return nullptr;
}


// Which consumer a machining cycle's call runs.
const char *slUse(int number) {
  static const char *const kUse[] = {"pilot", "pocket", "floor", "side", "train"};
  return kUse[number - 21];
}
}  // namespace

bool slCycle(int number) { return slRow(number) != nullptr; }

std::string slVar(int cycle, const std::string &q) { return fmt::format("_HEI_SL{}_{}", cycle, q); }

// CYCL DEF 14.1 <title> 1/2/3: up to 12 label numbers (L9001-L9021); each becomes a section
// call of the captures, resolved with the file's CALL LBLs (an undefined label is an error there).
bool BlockParser::contourLabels(const Token &n) {
  while (!atEnd() && tok().kind == Tok::Word) ++i_;  // the title
  std::vector<std::pair<std::string, SourceLoc>> labels;
  while (!atEnd()) {
    const Token &t = tok();
    if (t.kind != Tok::Number || !t.isInt || t.num < 1 || t.num > 65535)
      return fail(t, fmt::format("CYCL DEF {} lists label numbers 1 … 65535 (L9019)", n.text), "cycle-parameter");
    labels.push_back({labelOf(t), loc(t)});
    ++i_;
    if (!atEnd() && !tok().is("/")) return fail(tok(), fmt::format("'/' expected between the labels of CYCL DEF {}", n.text));
    if (!atEnd()) ++i_;
  }
  if (labels.empty()) return fail(n, fmt::format("CYCL DEF {} needs the contour's label numbers", n.text), "missing-word");
  if (labels.size() > 12) return fail(n, "cycle 14 lists at most 12 labels (L9013)", "cycle-parameter");
  f_.slLabels = std::move(labels);
  f_.slProgram.clear(), f_.contourDef.clear(), f_.slBroken = false;  // cycle 14 replaces a contour formula
  return true;
}

// CYCL DEF 20-25 and 270 with their parameter lines: the values go to program-wide variables now
// (a definition freezes them, as the library cycles' do); 20 is valid for 21-24 (L9181), 270 for
// 25 (L10250).
bool BlockParser::slDefinition(int number, const Token &n) {
  SourceLoc bl = loc(t_[0]);
  const SlCycle &row = *slRow(number);
  while (!atEnd() && tok().line == n.line) ++i_;  // the title: free text
  std::set<std::string> given;
  bool fmaxOut = false;
  while (!atEnd()) {
    const Token &q = tok();
    std::string name;
    if (!cycleParamName(number, given, name)) return false;
    // QS13, QS18, QS438: the tool by its name instead of Q13 … (L9360, L9484, L9802).
    const bool named = name.rfind("QS", 0) == 0;
    if (named) name = "Q" + name.substr(2);
    if (!inWordList(row.params, name) || (named && !inWordList(kToolParams, name)))
      return fail(q, fmt::format("{}{} is not a parameter of cycle {}", named ? "QS" : "Q", name.substr(1), number), "cycle-parameter");
    if (named && !given.insert(name).second)
      return fail(q, fmt::format("{} and QS{} both in CYCL DEF {}", name, name.substr(1), number), "cycle-parameter");
    CycleValue cv;
    if (!cycleValue(number, name, cv, true)) return false;
    ExprPtr v = std::move(cv.value);
    if (named != (cv.kind == CycleValue::Text))
      return f_.error(cv.at, named ? fmt::format("QS{} takes the tool's name in quotes", name.substr(1))
                                   : fmt::format("{} takes a number (QS{} the tool's name)", name, name.substr(1)),
                      "cycle-parameter");
    if (named && !(v = toolByName(cv.text, cv.at))) return false;
    if (cv.kind == CycleValue::Fmax) {  // Q208: the retract at rapid
      fmaxOut = true;
      continue;
    }
    if (cv.kind == CycleValue::PerRev || cv.kind == CycleValue::PerTooth)
      return f_.error(cv.at, fmt::format("{}={} in the SL cycles is not simulated yet", name, cv.kind == CycleValue::PerRev ? "FU" : "FZ"),
                      "unsupported-code");
    if (cv.kind == CycleValue::Predef && !inWordList(kContourDefaults, name))
      return f_.error(cv.at, fmt::format("{}=PREDEF: the SL cycles take PREDEF for the values of GLOBAL DEF 111 CONTOUR MILLING ({})",
                                         name, kContourDefaults),
                      "cycle-parameter");
    std::string var = slVar(number, name);
    f_.pp.slVars.insert(var);
    out().push_back(assignOp(Expr::var(ir::VarSpace::Global, var, nullptr, bl), std::move(v), bl));
  }
  Op note(OpKind::Comment, bl);
  note.set("text", Expr::string(fmt::format("CYCL DEF {} {}", number, row.name)));
  out().push_back(std::move(note));
  f_.cycleLoc = bl;
  f_.slGiven[number] = std::move(given);
  f_.slFmaxOut[number] = fmaxOut;
  if (number != 20 && number != 270) {  // a machining cycle: CYCL CALL runs it
    f_.cycle = number;
    f_.cycleRuns = false;
    f_.cycleSurface = false;
    f_.cycleProgram.clear();
    f_.m89 = false;
  }
  return true;
}

// CYCL CALL of an SL machining cycle: the sub-contours, then the consumer with the values of 20
// and of the cycle.
bool BlockParser::slCall(const std::string &how) {
  SourceLoc bl = loc(t_[0]);
  const int number = f_.cycle;
  if (!how.empty())
    return fail(t_[0], fmt::format("cycle {} by CYCL CALL{} is not simulated yet", number, how), "unsupported-code");
  const bool formula = !f_.slProgram.empty() || !f_.contourDef.empty();  // ContourFormula.cpp
  if (f_.slLabels.empty() && !formula && f_.slBroken) return false;  // its error is reported
  if (f_.slLabels.empty() && (!formula || number == 25))
    return fail(t_[0], fmt::format("cycle {} needs cycle 14 (CONTOUR) with the contour's labels before it{}", number,
                                   number == 25 ? " (L9872)" : " (or SEL CONTOUR, CONTOUR DEF)"),
                "cycle-invalid");
  if (number != 25 && !f_.slGiven.count(20))
    return fail(t_[0], fmt::format("cycle {} needs cycle 20 (CONTOUR DATA) before it (L9181)", number), "cycle-invalid");
  const std::set<std::string> &data = f_.slGiven[20], &own = f_.slGiven[number];
  auto value = [&](int cyc, const char *q) -> ExprPtr {
    const std::set<std::string> &g = cyc == 20 ? data : own;
    return g.count(q) ? Expr::var(ir::VarSpace::Global, slVar(cyc, q), nullptr, bl) : nullptr;
  };
  // What the cycle asks for beyond the core's consumers: refused where the values say so (when
  // the program runs if they are not literal numbers).
  struct Refusal {
    int cycle;
    const char *q;
    double allowed;
    const char *why;
  };
  static const Refusal kRefused[] = {
      {22, "Q18", 0, "fine roughing with a coarse roughing tool (Q18) is not simulated yet"},
      {22, "Q19", 0, "plunging along the tool table's ANGLE (Q19 not 0) is not simulated yet"},
      {22, "Q401", 100, "a feed factor Q401 below 100 % for full-width cuts is not simulated"},
      {25, "Q18", 0, "residual machining after a coarse roughing tool (Q18) is not simulated yet"},
  };
  for (const Refusal &r : kRefused) {
    if (r.cycle != number) continue;
    ExprPtr v = value(number, r.q);
    if (!v) continue;
    Op check(OpKind::If, bl);
    check.set("cond", Expr::binary(ir::OpCode::Ne, std::move(v), Expr::number(r.allowed, ir::Type::Real), bl));
    check.regions.emplace_back();
    Op stop(OpKind::Message, bl);
    stop.set("text", Expr::string(fmt::format("cycle {}: {}", number, r.why), bl));
    stop.set("kind", Expr::symbol("abort"));
    check.regions[0].push_back(std::move(stop));
    out().push_back(std::move(check));
  }
  PathWords w;  // CYCL CALL M3: the M functions around the call
  if (!words(w, kM, "CYCL CALL") || !emitBefore(w)) return false;
  if (number == 25) return trainCall(bl, w);
  Op reset(OpKind::Contour, bl);
  reset.set("action", Expr::symbol("data", bl));
  reset.set("use", Expr::symbol("subcontour", bl));
  out().push_back(std::move(reset));
  if (formula && !formulaCaptures(bl)) return false;
  for (auto &[label, at] : f_.slLabels) {
    subContourCapture("subcontour", label, at, bl);
    Op end(OpKind::Contour, at);
    end.set("action", Expr::symbol("end", bl));
    end.set("use", Expr::symbol("subcontour", bl));
    out().push_back(std::move(end));
  }
  Op run(OpKind::Contour, bl);
  run.set("action", Expr::symbol("run", bl));
  run.set("use", Expr::symbol(slUse(number), bl));
  auto key = [&](const char *k, ExprPtr v) {
    if (v) run.set(k, std::move(v));
  };
  auto abs = [&](ExprPtr v) -> ExprPtr {
    if (!v) return nullptr;
    std::vector<ExprPtr> args;
    args.push_back(std::move(v));
    return Expr::call("ABS", std::move(args), bl);
  };
  // Q1 is signed (its sign the direction, L9183): the core's depth runs down into the material.
  if (ExprPtr q1 = value(20, "Q1")) key("depth", Expr::unary(ir::OpCode::Neg, std::move(q1), bl));
  key("overlap", value(20, "Q2"));
  key("side_allowance", value(20, "Q3"));
  key("floor_allowance", value(20, "Q4"));
  key("surface", value(20, "Q5"));
  key("clearance", value(20, "Q6"));
  key("height", value(20, "Q7"));
  if (number != 24) key("direction", value(20, "Q9"));
  if (number == 21 || number == 22) key("corner_radius", value(20, "Q8"));  // 21 drills where 22 plunges
  if (number != 23) key("infeed", abs(value(number, "Q10")));
  if (number == 24) {  // its own direction, the allowance it leaves, the rough-out tool
    key("direction", value(24, "Q9"));
    key("finish_allowance", value(24, "Q14"));
    key("T", value(24, "Q438"));
  }
  key("plunge_feed", value(number, "Q11"));
  if (number != 21) key("feed", value(number, "Q12"));
  if (number != 21 && number != 24 && !f_.slFmaxOut[number]) key("retract_feed", value(number, "Q208"));
  if (number == 21) key("T", value(21, "Q13"));
  out().push_back(std::move(run));
  return emitAfter(w);
}

// The start of a capture of one label of cycle 14 (`use` subcontour or train) and its section
// call, located at the label in 14.1: an error of the sub-contour (open, crossing, no RL/RR) names it.
void BlockParser::subContourCapture(const char *use, const std::string &label, SourceLoc at, SourceLoc bl) {
  Op begin(OpKind::Contour, at);
  begin.set("action", Expr::symbol("begin", bl));
  begin.set("use", Expr::symbol(use, bl));
  out().push_back(std::move(begin));
  Op call(OpKind::CallSection, at);
  call.set("from", Expr::string(label));
  f_.calls.push_back({out().size(), label, false, at});
  out().push_back(std::move(call));
}

// Cycle 25 (L9841-L10009): only the first label of cycle 14, cycle 20 not needed; the captured
// open contour is milled at its RL/RR side with the cycle's own values.
bool BlockParser::trainCall(SourceLoc bl, PathWords &w) {
  auto &[label, at] = f_.slLabels.front();
  subContourCapture("train", label, at, bl);
  Op end(OpKind::Contour, bl);
  end.set("action", Expr::symbol("end", bl));
  end.set("use", Expr::symbol("train", bl));
  const std::set<std::string> &own = f_.slGiven[25];
  auto value = [&](const char *q) -> ExprPtr {
    return own.count(q) ? Expr::var(ir::VarSpace::Global, slVar(25, q), nullptr, bl) : nullptr;
  };
  auto key = [&](const char *k, ExprPtr v) {
    if (v) end.set(k, std::move(v));
  };
  if (ExprPtr q1 = value("Q1")) key("depth", Expr::unary(ir::OpCode::Neg, std::move(q1), bl));
  key("side_allowance", value("Q3"));
  key("surface", value("Q5"));
  key("height", value("Q7"));
  key("infeed", value("Q10"));  // the executor takes its size
  key("plunge_feed", value("Q11"));
  key("feed", value("Q12"));
  key("direction", value("Q15"));
  key("extension", value("Q448"));
  if (f_.slGiven.count(270)) {  // the approach and departure of cycle 270, in the words I P R E D
    const std::set<std::string> &data = f_.slGiven[270];
    static const char *const kData[][2] = {{"I", "Q390"}, {"P", "Q391"}, {"R", "Q392"}, {"E", "Q393"}, {"D", "Q394"}};
    for (auto &[k, q] : kData)
      key(k, data.count(q) ? Expr::var(ir::VarSpace::Global, slVar(270, q), nullptr, bl) : nullptr);
    if (!data.count("Q390") || !data.count("Q391"))
      return fail(t_[0], "cycle 270 needs Q390 and Q391 (the approach and the compensation)", "cycle-parameter");
  }
  out().push_back(std::move(end));
  return emitAfter(w);
}

}  // namespace ncc::hei
