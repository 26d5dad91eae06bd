// Region pockets (docs/IR.md §5.6): `contour … end use=outline` and `use=island` captures collect
// a region (runtime/cycles/Region.h), `contour action=run use=pocket` roughs it out with the tool
// in the spindle. The Heidenhain SL cycles (14 + 20 + 22) and Sinumerik CYCLE62 + CYCLE63 map
// onto these ops.
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/Contour.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

bool Executor::Impl::regionCapture(const MachineCmd &c, const Contour &ct) {
  const bool island = (ContourUse)c.sub2 == ContourUse::Island;
  // The region is the programmed path (a front end drops Heidenhain's RL/RR in contour subprograms).
  if (comp.active()) return error("a region contour must be captured with cutter compensation off", "contour-invalid");
  if (island && region.plane < 0) return error("an island needs its outline first (contour use=outline)", "contour-invalid");
  if (island && region.plane != (int)plane()) return error("an island must lie in the plane of its outline", "contour-invalid");
  RegionLoop loop;
  loop.start = {ct.start.a, ct.start.b};
  for (const ContourElem &e : ct.elems)  // a rapid is a line here: only the shape counts
    loop.segs.push_back({{e.end.a, e.end.b}, e.kind == ContourKind::Arc, {e.centre.a, e.centre.b}, e.ccw});
  Polygon p;
  std::string err;
  if (!regionPolygon(loop, island, kRegionChordTolerance, p, err)) return error(err, "contour-invalid");
  if (!island) {
    region = PocketRegion{(int)plane(), std::move(p), {}, {}, {}};
    return true;
  }
  if (!islandInside(region, p, kRegionChordTolerance)) return error("the island reaches outside the outline", "contour-invalid");
  region.islands.push_back(std::move(p));
  return true;
}

// An SL sub-contour: a pocket or an island by its direction and RL/RR (the manual, L8853-L8860);
// cycle 14's labels collect in order, `contour action=data use=subcontour` starts anew.
// A contour formula's operand (`end use=subcontour P=n`: QCn, Heidenhain DECLARE CONTOUR or CONTOUR
// DEF) is always a pocket; it declares n for the formula steps that follow.
bool Executor::Impl::regionSub(const MachineCmd &c, const Contour &ct) {
  const bool operand = c.has(Word::P);
  if (!region.subs.empty() && region.plane != (int)plane())
    return error("the sub-contours of an SL contour must lie in one plane", "contour-invalid");
  if (!region.subs.empty() && operand == region.formula.empty())
    return error("an SL contour takes cycle 14's sub-contours or a contour formula's, not both", "contour-invalid");
  if (!operand && region.subs.size() >= 12) return error("an SL contour has at most 12 sub-contours (cycle 14, L9013)", "contour-invalid");
  if (operand && region.subs.size() >= 128) return error("a contour formula has at most 128 contours (L11788)", "contour-invalid");
  if (operand && c.has(Word::Depth) && c.get(Word::Depth) != 0)
    return error("a contour's own depth (DEPTH, FCL 2) is not simulated yet", "unsupported-code");
  if (operand && capture.side != 0)
    return error("a contour of a contour formula takes no radius compensation: it is always a pocket (L11843)", "contour-invalid");
  RegionLoop loop;
  loop.start = {ct.start.a, ct.start.b};
  for (const ContourElem &e : ct.elems)
    loop.segs.push_back({{e.end.a, e.end.b}, e.kind == ContourKind::Arc, {e.centre.a, e.centre.b}, e.ccw});
  SubContour sub;
  std::string err;
  if (!(operand ? formulaOperand(loop, kRegionChordTolerance, sub, err) : subContour(loop, capture.side, kRegionChordTolerance, sub, err)))
    return error(err, "contour-invalid");
  if (region.subs.empty()) region = PocketRegion{(int)plane(), {}, {}, {}, {}};
  if (operand) region.formula.push_back({FormulaStep::Declare, (int)c.get(Word::P), (int)region.subs.size()});
  region.subs.push_back(std::move(sub));
  return true;
}

bool Executor::Impl::regionRun(const MachineCmd &c) {
  if (region.plane < 0) return error("a region pocket needs an outline first (contour use=outline)", "contour-invalid");
  if (region.plane != (int)plane()) return error("a region pocket runs in the plane its outline was captured in", "contour-invalid");
  if (!compForbids("Cannot use canned cycles with cutter compensation on")) return false;
  if (linearFrame()) return error("contour cycles under a rotation, scaling or mirror are not supported", "unsupported-code");
  if (st.css) return error("region pockets under constant surface speed (G96) are not supported", "unsupported-code");
  auto has = [&](PocketParam p) { return c.has(kPocketParams[(int)p].word); };
  auto get = [&](PocketParam p, double def) { return has(p) ? c.get(kPocketParams[(int)p].word) : def; };
  for (PocketParam p : {PocketParam::Depth, PocketParam::Surface, PocketParam::Clearance})
    if (!has(p)) return error(fmt::format("the pocket needs '{}'", kPocketParams[(int)p].key()), "missing-word");
  if (has(PocketParam::Stepover) == has(PocketParam::Overlap))
    return error("the pocket needs one of 'stepover' (mm) and 'overlap' (x the tool radius)", "missing-word");
  const double direction = get(PocketParam::Direction, 1);
  if (direction != 1 && direction != -1) return error("'direction' must be 1 (climb) or -1 (up-cut)", "bad-number");
  if (st.toolInSpindle <= 0 || !(toolNumberData(st.toolInSpindle).radius > 0))
    return error("a region pocket needs a tool with a radius in the spindle", "missing-word");
  RegionPocketJob j;
  const ContourUse use = (ContourUse)c.sub2;
  const double k = scale();
  j.plane = (int)plane();
  const AxisVec here = programPosition();
  const int n = planeAxes(plane()).n;
  for (int i = 0; i < 3; ++i) j.at[i] = here[i] + frameOffset(i);
  j.toolRadius = toolNumberData(st.toolInSpindle).radius;
  if (use == ContourUse::Pilot && c.has(Word::T) && c.get(Word::T) != 0) {  // the rough-out tool's radius
    const double t = c.get(Word::T);
    if (!checkTool(t, "the rough-out tool")) return false;
    j.toolRadius = toolNumberData((int)t).radius;
    if (!(j.toolRadius > 0)) return error(fmt::format("rough-out tool {} has no radius", t), "cycle-invalid");
  }
  j.depth = get(PocketParam::Depth, 0) * k, j.infeed = get(PocketParam::Infeed, 0) * k;
  j.surface = get(PocketParam::Surface, 0) * k + frameOffset(n);
  j.clearance = get(PocketParam::Clearance, 0) * k;
  j.height = has(PocketParam::Height) ? get(PocketParam::Height, 0) * k + frameOffset(n) : j.surface + j.clearance;
  const double overlap = get(PocketParam::Overlap, 0);
  if (has(PocketParam::Overlap) && !(overlap > 0 && overlap <= 2))
    return error("'overlap' must lie in 0 … 2 (x the tool radius)", "bad-number");
  j.stepover = has(PocketParam::Overlap) ? overlap * j.toolRadius : get(PocketParam::Stepover, 0) * k;
  j.sideAllowance = get(PocketParam::SideAllowance, 0) * k, j.floorAllowance = get(PocketParam::FloorAllowance, 0) * k;
  j.plungeFeed = get(PocketParam::PlungeFeed, 0) * k, j.feed = get(PocketParam::Feed, 0) * k;
  j.retractFeed = get(PocketParam::RetractFeed, -1) * (has(PocketParam::RetractFeed) ? k : 1);
  j.cornerRadius = get(PocketParam::CornerRadius, 0) * k;
  if (j.plungeFeed < 0 || j.feed < 0 || (has(PocketParam::RetractFeed) && j.retractFeed < 0))
    return error("the pocket's feeds must not be negative", "bad-number");
  if (use == ContourUse::Floor) {  // one level at the full depth over the floor the roughing left
    j.done = j.depth - j.floorAllowance, j.floorAllowance = 0, j.infeed = 0, j.cornerRadius = 0;
  }
  // Climb milling with M3 runs the outer walls counter-clockwise; M4 or up-cut reverses.
  j.ccw = (direction > 0) != (st.spindle == 2);
  std::vector<CycleStep> steps;
  std::string err;
  static const char *const kWhat[] = {"region pocket", "pilot drilling", "floor finishing"};
  const int what = use == ContourUse::Pilot ? 1 : use == ContourUse::Floor ? 2 : 0;
  if (!(use == ContourUse::Pilot ? regionPilot(region, j, steps, err) : regionPocket(region, j, steps, err)))
    return error(fmt::format("{}: {}", kWhat[what], err), "cycle-invalid");
  for (const CycleStep &s : steps)
    if (s.kind == CycleStepKind::Feed && s.feed <= 0 && !checkFeed("the region pocket")) return false;
  if (use == ContourUse::Pocket) lastRoughTool = st.toolInSpindle;
  MotionRecord begin = record(RecordKind::CycleBegin);
  static const char *const kBracket[] = {"contour.pocket", "contour.pilot", "contour.floor"};
  begin.text = kBracket[what];
  for (auto &p : kPocketParams)
    if (c.has(p.word)) begin.setParam(p.bracket, c.get(p.word));
  emit(begin);
  return runSteps(steps);
}

}  // namespace ncc
