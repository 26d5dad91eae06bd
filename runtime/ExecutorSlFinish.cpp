// Heidenhain SL side finishing (cycle 24: `contour action=run use=side` on the collected region)
// and contour train (cycle 25: `contour … end use=train` on a captured open contour with its
// RL/RR noted), runtime/cycles/SlFinish.h; docs/IR.md §5.6, docs/HEIDENHAIN.md "SL cycles".
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/Contour.h"
#include "runtime/cycles/SlFinish.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
double word(const MachineCmd &c, Word w, double def) { return c.has(w) ? c.get(w) : def; }
}  // namespace

// The cycle bracket with the keys the consumer got, then its steps.
static bool bracketed(Executor::Impl &x, const MachineCmd &c, const char *what, const std::vector<CycleStep> &steps) {
  MotionRecord begin = x.record(RecordKind::CycleBegin);
  begin.text = what;
  for (auto &p : kPocketParams)
    if (c.has(p.word)) begin.setParam(p.bracket, c.get(p.word));
  x.emit(begin);
  return x.runSteps(steps);
}

bool Executor::Impl::regionSide(const MachineCmd &c) {
  if (region.plane < 0 || region.subs.empty()) return error("side finishing needs an SL contour first (use=subcontour)", "contour-invalid");
  if (region.plane != (int)plane()) return error("side finishing runs in the plane its contour was captured in", "contour-invalid");
  if (!compForbids("Cannot use canned cycles with cutter compensation on")) return false;
  if (linearFrame()) return error("contour cycles under a rotation, scaling or mirror are not supported", "unsupported-code");
  for (Word w : {Word::Depth, Word::Surface, Word::Clearance})
    if (!c.has(w)) return error(fmt::format("side finishing needs '{}'", kWordKeys[(int)w]), "missing-word");
  const double direction = word(c, Word::Direction, 1);
  if (direction != 1 && direction != -1) return error("cycle 24: Q9 must be +1 or -1", "bad-number");
  if (st.toolInSpindle <= 0 || !(toolNumberData(st.toolInSpindle).radius > 0))
    return error("side finishing needs a tool with a radius in the spindle", "missing-word");
  // The rough-out tool (Q438): -1 the one of the last roughing (none: radius 0), 0 none, else its number.
  const double rough = word(c, Word::T, -1);
  double roughRadius = 0;
  if (rough > 0) {
    if (!checkTool(rough, "the rough-out tool")) return false;
    roughRadius = toolNumberData((int)rough).radius;
  } else if (rough == -1) {
    roughRadius = lastRoughTool > 0 ? toolNumberData(lastRoughTool).radius : 0;
  } else if (rough != 0) {
    return error("the rough-out tool must be -1 (the last roughing's), 0 (none) or a tool number", "bad-number");
  }
  const double k = scale();
  SideFinishJob j;
  j.plane = (int)plane();
  const int n = planeAxes(plane()).n;
  const AxisVec here = programPosition();
  for (int i = 0; i < 3; ++i) j.at[i] = here[i] + frameOffset(i);
  j.toolRadius = toolNumberData(st.toolInSpindle).radius;
  j.depth = c.get(Word::Depth) * k, j.infeed = word(c, Word::Infeed, 0) * k;
  j.surface = c.get(Word::Surface) * k + frameOffset(n);
  j.clearance = c.get(Word::Clearance) * k;
  j.height = c.has(Word::Height) ? c.get(Word::Height) * k + frameOffset(n) : j.surface + j.clearance;
  j.finishAllowance = word(c, Word::FinishAllowance, 0) * k;
  const double roughAllowance = word(c, Word::SideAllowance, 0) * k;
  j.plungeFeed = word(c, Word::PlungeFeed, 0) * k, j.feed = word(c, Word::RoughFeed, 0) * k;
  if (j.plungeFeed < 0 || j.feed < 0) return error("the feeds must not be negative", "bad-number");
  // L9723-L9729: the finishing tool with its allowance must stay inside what the roughing left.
  if (!(j.finishAllowance + j.toolRadius < roughAllowance + roughRadius))
    return error(fmt::format("side finishing: tool radius too large (Q14 {:g} + the tool's radius {:g} must be less than "
                             "cycle 20's Q3 {:g} + the rough-out tool's radius {:g})",
                             j.finishAllowance, j.toolRadius, roughAllowance, roughRadius),
                 "cycle-invalid");
  j.ccw = (direction > 0) != (st.spindle == 2);
  std::vector<CycleStep> steps;
  std::string err;
  if (!sideFinish(region, j, steps, err)) return error("side finishing: " + err, "cycle-invalid");
  for (const CycleStep &s : steps)
    if (s.kind != CycleStepKind::Rapid && s.feed <= 0 && !checkFeed("side finishing")) return false;
  return bracketed(*this, c, "contour.side", steps);
}

bool Executor::Impl::contourTrainRun(const MachineCmd &c, const Contour &ct) {
  for (Word w : {Word::Depth, Word::Surface, Word::Height})
    if (!c.has(w)) return error(fmt::format("the contour train needs '{}'", kWordKeys[(int)w]), "missing-word");
  const double k = scale();
  TrainJob j;
  j.depth = c.get(Word::Depth) * k;
  if (j.depth == 0) return true;  // L9868: depth 0, the cycle does nothing
  if (j.depth < 0) return error("the contour train upward (a positive Q1) is not simulated", "unsupported-code");
  int side = capture.side == 1 ? 1 : -1;
  double allowance = word(c, Word::SideAllowance, 0) * k;
  if (c.has(Word::I)) {  // cycle 270 (L10239-L10305): the approach and the compensation come from it
    if (capture.side != 0)
      return error("with cycle 270 the contour train's contour must not have RL or RR (L10247)", "contour-invalid");
    j.approach = (int)c.get(Word::I);
    const double comp = word(c, Word::P, -1);
    j.radius = word(c, Word::R, 0) * k, j.angle = word(c, Word::E, 0), j.distance = word(c, Word::D, 0) * k;
    if (j.approach < 1 || j.approach > 3 || j.approach != c.get(Word::I))
      return error("cycle 270: Q390 must be 1 (arc), 2 (tangential line) or 3 (normal line)", "bad-number");
    if (comp != 0 && comp != 1 && comp != 2) return error("cycle 270: Q391 must be 0 (R0), 1 (RL) or 2 (RR)", "bad-number");
    if (j.approach == 1 && !(j.radius > 0 && j.angle > 0 && j.angle < 360))
      return error("cycle 270: the approach arc needs Q392 > 0 and Q393 between 0 and 360 degrees", "bad-number");
    if (j.approach > 1 && !(j.distance > 0)) return error("cycle 270: the approach line needs Q394 > 0", "bad-number");
    if (comp == 0 && (j.approach != 2 || allowance != 0))
      return error("cycle 270 with R0 (Q391=0): only the tangential line (Q390=2) and no side allowance Q3 have a side to "
                   "take",
                   "cycle-invalid");
    side = comp == 0 ? 0 : comp == 1 ? 1 : -1;
  } else if (capture.side != 1 && capture.side != 2) {
    return error("the contour train's contour needs RL or RR (or cycle 270): the side of the contour to mill", "contour-invalid");
  }
  if (ct.elems.size() < 2) return error("the contour train's contour needs a first point and at least one element", "contour-invalid");
  if (st.toolInSpindle <= 0 || !(toolNumberData(st.toolInSpindle).radius > 0))
    return error("the contour train needs a tool with a radius in the spindle", "missing-word");
  const double direction = word(c, Word::Direction, 1);
  if (direction != 1 && direction != -1 && direction != 0) return error("cycle 25: Q15 must be +1 (climb), -1 (up-cut) or 0 (alternating)", "bad-number");
  // The first element only leads to the contour's first point (the subprogram's first block).
  std::vector<PathElem> elems;
  Pt2 from = ct.elems[0].end;
  for (size_t i = 1; i < ct.elems.size(); ++i) {
    const ContourElem &e = ct.elems[i];
    PathElem p{e.kind == ContourKind::Arc, {from.a, from.b}, {e.end.a, e.end.b}, {e.centre.a, e.centre.b}, e.ccw ? 1 : -1};
    if (!p.arc) p.dir = 0;
    if (std::hypot(p.end.x - p.start.x, p.end.y - p.start.y) > 1e-9 || p.arc) elems.push_back(p);
    from = e.end;
  }
  if (elems.empty()) return error("the contour train's contour has no length", "contour-invalid");
  j.plane = (int)plane();
  const int n = planeAxes(plane()).n;
  const AxisVec here = programPosition();
  for (int i = 0; i < 3; ++i) j.at[i] = here[i] + frameOffset(i);
  j.side = side;
  j.offset = side == 0 ? 0 : toolNumberData(st.toolInSpindle).radius + allowance;
  j.infeed = std::fabs(word(c, Word::Infeed, 0)) * k;
  j.surface = c.get(Word::Surface) * k + frameOffset(n);
  j.height = c.get(Word::Height) * k + frameOffset(n);
  j.extension = word(c, Word::Extension, 0) * k;
  if (j.extension < 0) return error("the path extension must not be negative", "bad-number");
  j.plungeFeed = word(c, Word::PlungeFeed, 0) * k, j.feed = word(c, Word::RoughFeed, 0) * k;
  if (j.plungeFeed < 0 || j.feed < 0) return error("the feeds must not be negative", "bad-number");
  // Climb with M3: the tool left of its path (RL); M4 turns it round. R0 (270): the programmed direction.
  const bool programmedClimb = side == 0 || (j.side > 0) != (st.spindle == 2);
  j.alternate = direction == 0;
  j.forward = direction == 0 || side == 0 || (direction > 0) == programmedClimb;
  std::vector<CycleStep> steps;
  std::string err;
  if (!contourTrain(elems, j, steps, err)) return error("contour train: " + err, "cycle-invalid");
  for (const CycleStep &s : steps)
    if (s.kind != CycleStepKind::Rapid && s.feed <= 0 && !checkFeed("the contour train")) return false;
  return bracketed(*this, c, "contour.train", steps);
}

}  // namespace ncc
