// Contour capture (MachineCmd Contour, docs/IR.md `contour`): between `begin` and `end` the
// executor runs the blocks as usual, but their records go to a capture instead of the sinks
// (RouteSink); `end` hands the captured path to a consumer: Finish replays it as it ran (ISO G70),
// the roughing consumers (G71 G72 G73, runtime/cycles/Turning.h) put the modal state back (the
// blocks were only read) and cut from the contour. Every consumer ends at the start point. Keep
// (Sinumerik CYCLE95) only puts the state back and keeps the contour for the library cycle after it.
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/Turning.h"
#include "runtime/cycles/TurningRs274.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

namespace {
const char *const kUseNames[] = {"contour.finish", "contour.rough_z", "contour.rough_x", "contour.pattern"};
const char *const kRs274Names[] = {"rs274.G70", "rs274.G71", "rs274.G72"};

bool rs274Use(ContourUse u) { return u >= ContourUse::Rs274Finish && u <= ContourUse::Rs274RoughX; }

// What a record inside a contour may be: motion becomes an element, state records are read
// (their effect is in the captured feeds), the rest has no place in a contour.
const char *forbiddenInContour(RecordKind k) {
  switch (k) {
  case RecordKind::Spline: return "a spline";
  case RecordKind::Thread: return "a thread";
  case RecordKind::Probe: return "a probe move";
  case RecordKind::CycleBegin: return "a canned cycle";
  case RecordKind::FrameChange: return "a change of the coordinate system";
  case RecordKind::ProgramEnd: case RecordKind::ProgramStop: case RecordKind::OptionalStop: return "a program stop";
  case RecordKind::ToolLength: case RecordKind::ToolChange: return "a tool change or tool offset";
  case RecordKind::Plane: return "a plane change";
  default: return nullptr;
  }
}
}  // namespace

bool Executor::Impl::contourData(const MachineCmd &c) {
  switch ((ContourUse)c.sub2) {
  case ContourUse::RoughAlongZ:
  case ContourUse::RoughAlongX: {
    // G71 U<depth> R<retract> / G72 W<depth> R<retract>: radius values, shared by both (808D
    // user data _ZSFI[30], _ZSFI[31]).
    Word w = c.has(Word::U) ? Word::U : Word::W;
    if (!c.has(w) || !c.has(Word::R)) return error("the cycle data block needs the depth of cut and R (retract)", "missing-word");
    roughDepth = c.get(w) * scale();
    roughRetract = c.get(Word::R) * scale();
    if (roughDepth <= 0) return error("the depth of cut must be greater than 0", "bad-number");
    if (roughRetract < 0) return error("the retract amount R must not be negative", "bad-number");
    roughSet = true;
    return true;
  }
  case ContourUse::PatternRepeat:
    // G73 U<relief X> W<relief Z> R<divisions> (808D _ZSFI[32..34]); the relief is a radius.
    if (!c.has(Word::U) || !c.has(Word::W) || !c.has(Word::R))
      return error("the pattern data block needs U (X relief), W (Z relief) and R (divisions)", "missing-word");
    patternReliefX = c.get(Word::U) * scale();
    patternReliefZ = c.get(Word::W) * scale();
    patternCount = c.get(Word::R);
    if (patternCount < 1 || patternCount != std::floor(patternCount) || patternCount > 10000)
      return error("the number of divisions R must be an integer of at least 1", "bad-number");
    patternSet = true;
    return true;
  case ContourUse::Sub:  // a new SL contour: the sub-contours collected so far are dropped
    if (c.has(Word::P) || c.has(Word::Q) || c.has(Word::R)) {  // a contour formula's step (docs/IR.md §5.6)
      if (region.formula.empty()) return error("a contour formula needs its contours declared before it", "contour-invalid");
      const Word w = c.has(Word::P) ? Word::P : c.has(Word::Q) ? Word::Q : Word::R;
      const FormulaStep::Kind k = w == Word::P ? FormulaStep::Push : w == Word::Q ? FormulaStep::Apply : FormulaStep::Store;
      region.formula.push_back({k, (int)c.get(w)});
      return true;
    }
    region = PocketRegion{};
    return true;
  default: return error("the finishing consumer takes no data", "syntax");
  }
}

bool Executor::Impl::execContour(const MachineCmd &c) {
  switch ((ContourAction)c.sub) {
  case ContourAction::Data: return contourData(c);
  case ContourAction::Begin:
    if (capture.active) return error("a contour cycle inside a contour", "contour-invalid");
    if ((ContourUse)c.sub2 == ContourUse::SinTable && !sinTableBegin(c)) return false;
    if (rs274Use((ContourUse)c.sub2) && !rs274ContourAllowed((ContourUse)c.sub2)) return false;
    if (linearFrame()) return error("contour cycles under a rotation, scaling or mirror are not supported", "unsupported-code");
    if (comp.active()) return error("contour cycles with cutter compensation on are not supported", "unsupported-code");
    cornerFlush("a contour begins");
    capture.active = true;
    capture.loc = loc;
    capture.records.clear();
    capture.compOn = false;
    capture.train = (ContourUse)c.sub2 == ContourUse::Train;
    capture.sl = (ContourUse)c.sub2 == ContourUse::Sub || capture.train, capture.side = 0;
    capture.table = (ContourUse)c.sub2 == ContourUse::SinTable;
    capture.st = st;
    capture.feedMM = feedMM, capture.toolLength = toolLength, capture.toolOffsetX = toolOffsetX, capture.toolOffsetY = toolOffsetY;
    capture.lastPath = lastPathNow();
    capture.blockNumber = blockNumber, capture.blockLoc = blockLoc;
    route.capture = &capture.records;
    return true;
  case ContourAction::Run:
    if ((ContourUse)c.sub2 == ContourUse::SinTable) return sinTableExec(c);  // EXECTAB (may be captured)
    if (capture.active) return error("a contour cycle inside a contour", "contour-invalid");
    if ((ContourUse)c.sub2 == ContourUse::Side) return regionSide(c);
    if ((ContourUse)c.sub2 != ContourUse::Pocket && (ContourUse)c.sub2 != ContourUse::Pilot &&
        (ContourUse)c.sub2 != ContourUse::Floor)
      return error("only the pocket, pilot, floor and side consumers run without a capture", "contour-invalid");
    return regionRun(c);
  case ContourAction::End:
    if (!capture.active) return error("a contour ends that did not begin", "contour-invalid");
    if (corner.active || corner.requested)
      return error("the last contour move must not end in a chamfer or rounding", "contour-invalid");
    route.capture = nullptr;
    capture.active = false;
    if (capture.table != ((ContourUse)c.sub2 == ContourUse::SinTable))
      return error("a contour table's capture must begin and end with use=sin_table", "contour-invalid");
    capture.table = false;
    // Compensation the contour turns on (808D: not in G71-G73, L3842-3843) ends in it (G70).
    if (capture.compOn && ((ContourUse)c.sub2 == ContourUse::Outline || (ContourUse)c.sub2 == ContourUse::Island))
      return error("a region contour must be captured with cutter compensation off", "contour-invalid");
    if (capture.compOn && (ContourUse)c.sub2 != ContourUse::Finish)
      return error("no tool nose radius compensation in the contour of G71-G73", "contour-invalid");
    if (comp.active()) return error("compensation turned on in the contour must be cancelled (G40) in it", "contour-invalid");
    return contourConsume(c);
  }
  return error("bad contour action", "contour-invalid");
}

// rs274's checks before it reads the profile of G70-G72 (it runs G70 under compensation, which
// ncc does not yet).
bool Executor::Impl::rs274ContourAllowed(ContourUse use) {
  if (plane() != Plane::ZX) return error("G70-G72 can only be used in the XZ plane (G18)", "unsupported-code");
  if (!comp.active()) return true;
  if (use == ContourUse::Rs274Finish) return error("G70 with cutter compensation on is not supported", "unsupported-code");
  return error("G71/G72 cannot be used with cutter compensation enabled", "cutcomp-conflict");
}

// The blocks were only read: the captured motion becomes a contour in the active plane and the
// state comes back as it was at `begin`.
bool Executor::Impl::capturedContour(Contour &ct) {
  SourceLoc at = loc;
  const PlaneAxes ax = planeAxes(plane());
  ct.start = {capture.st.position[ax.u], capture.st.position[ax.v]};
  for (auto &r : capture.records) {
    if (const char *what = forbiddenInContour(r.kind)) {
      diags.error(r.loc, fmt::format("{} is not allowed inside a contour", what), "contour-invalid");
      return false;
    }
    if (r.kind != RecordKind::Rapid && r.kind != RecordKind::Linear && r.kind != RecordKind::Arc) continue;
    for (int i = 0; i < kAxes; ++i)
      if (i != ax.u && i != ax.v && std::fabs(r.end[i] - r.start[i]) > 1e-9) {
        diags.error(r.loc, "a contour move leaves the plane of the contour", "contour-invalid");
        return false;
      }
    ContourElem e;
    e.kind = r.kind == RecordKind::Rapid ? ContourKind::Rapid : r.kind == RecordKind::Linear ? ContourKind::Line : ContourKind::Arc;
    e.end = {r.end[ax.u], r.end[ax.v]};
    e.feed = r.feed;
    e.loc = r.loc;
    if (r.kind == RecordKind::Arc) {
      if (r.tiltedArc() || r.plane != plane() || std::abs(r.turns) != 1) {
        diags.error(r.loc, "a contour arc must lie in the active plane and turn less than once", "contour-invalid");
        return false;
      }
      e.centre = {r.center[ax.u], r.center[ax.v]};
      e.ccw = r.turns > 0;
    }
    ct.elems.push_back(e);
  }
  st = capture.st;
  feedMM = capture.feedMM, toolLength = capture.toolLength, toolOffsetX = capture.toolOffsetX, toolOffsetY = capture.toolOffsetY;
  lastPath = capture.lastPath;
  lastPathPlain = false;
  blockNumber = capture.blockNumber, blockLoc = capture.blockLoc;
  loc = at;
  return true;
}

bool Executor::Impl::contourConsume(const MachineCmd &c) {
  const ContourUse use = (ContourUse)c.sub2;
  const AxisVec start = capture.st.position;
  if (use == ContourUse::Finish) {
    // The blocks ran for real (their F, S, T count): their records go out now, then back to the
    // start point at rapid.
    for (auto &r : capture.records) sink.record(r);
    blockNumber = capture.blockNumber, blockLoc = capture.blockLoc;
    return moveTo(RecordKind::Rapid, start);
  }
  if (use == ContourUse::Pocket) return error("the pocket consumer runs with action=run, not after a capture", "contour-invalid");
  Contour ct;
  if (!capturedContour(ct)) return false;
  if (use == ContourUse::Outline || use == ContourUse::Island) return regionCapture(c, ct);
  if (use == ContourUse::SinTable) return sinTableBuild(ct);
  if (use == ContourUse::Train || capture.train) {
    if (use != ContourUse::Train || !capture.train)
      return error("a contour train's capture must begin and end with use=train", "contour-invalid");
    return contourTrainRun(c, ct);
  }
  if (use == ContourUse::Sub) {
    if (!capture.sl) return error("an SL sub-contour's capture must begin with use=subcontour", "contour-invalid");
    return regionSub(c, ct);
  }
  if (capture.sl) return error("a capture begun with use=subcontour must end with it", "contour-invalid");
  if (use == ContourUse::Pilot || use == ContourUse::Floor || use == ContourUse::Side)
    return error("the pilot, floor and side consumers run with action=run, not after a capture", "contour-invalid");
  std::vector<ContourElem> moves;
  std::string err;
  // Plane coordinates of X and Z: the turning consumers need the ZX plane.
  if (plane() != Plane::ZX) return error("turning contour cycles need the ZX plane (G18)", "unsupported-code");
  if (rs274Use(use)) return rs274Contour(c, ct);
  if (use == ContourUse::Keep) {  // for the library cycle that follows (CYCLE95)
    keptContour.contour = ct;
    keptSet = true;
    return true;
  }
  const int ix = 1, iz = 0;  // G18: a = Z, b = X
  // The finishing allowance: U along X (a diameter when X is), W along Z, signed as programmed.
  double allowance[2] = {0, 0};
  allowance[ix] = c.has(Word::U) ? c.get(Word::U) * axisScale(0) : 0.0;
  allowance[iz] = c.has(Word::W) ? c.get(Word::W) * scale() : 0.0;
  if (use == ContourUse::PatternRepeat) {
    if (!patternSet) return error("G73 needs its data block first (U W R: relief and divisions)", "missing-word");
    PatternRepeat p;
    p.count = (int)patternCount;
    // The relief is along X and Z; in the plane's coordinates.
    double rel[2] = {0, 0};
    rel[ix] = patternReliefX, rel[iz] = patternReliefZ;
    p.relief = {rel[0], rel[1]};
    p.allowance = {allowance[0], allowance[1]};
    if (!patternRepeat(ct, p, moves, err)) return error(err, "contour-invalid");
  } else {
    if (!roughSet) return error("stock removal needs its data block first (depth of cut and retract)", "missing-word");
    StockRemoval s;
    s.cutAxis = use == ContourUse::RoughAlongZ ? iz : ix;
    s.cutName = use == ContourUse::RoughAlongZ ? "Z" : "X";
    s.depth = roughDepth, s.retract = roughRetract;
    s.typeII = c.has(Word::P) && c.get(Word::P) == 2;
    s.allowance = {allowance[0], allowance[1]};
    if (!stockRemoval(ct, s, moves, err)) return error(err, "contour-invalid");
  }
  return emitContourMoves(moves, kUseNames[(int)use]);
}

// LinuxCNC G70, G71 (.1 .2), G72 (.1 .2): the words of the cycle block (program units), the cut
// pattern rs274 makes (runtime/cycles/TurningRs274.h) from the contour read at the start point.
bool Executor::Impl::rs274Contour(const MachineCmd &c, const Contour &ct) {
  const int which = (int)c.sub2 - (int)ContourUse::Rs274Finish;
  Rs274Turning s;
  s.cycle = 70 + which;
  auto word = [&](Word w, double &v, double unit) {
    if (c.has(w)) v = c.get(w) * unit;
  };
  word(Word::D, s.d, scale()), word(Word::E, s.e, scale()), word(Word::I, s.i, scale());
  word(Word::R, s.r, scale()), word(Word::U, s.u, scale()), word(Word::W, s.w, scale());
  if (which == 0) word(Word::P, s.passes, 1.0);
  else if (c.has(Word::P)) s.sub = (int)c.get(Word::P);
  if (which == 0 && !(s.passes >= 1 && s.passes < 1e6))
    return error("G70 P (the number of passes) must be at least 1", "bad-number");
  std::vector<ContourElem> moves;
  std::string err;
  if (!rs274Turning(ct, s, moves, err)) return error(err, "contour-invalid");
  return emitContourMoves(moves, kRs274Names[which]);
}

// A consumer's moves (plane coordinates of the ZX plane) between its cycle records.
bool Executor::Impl::emitContourMoves(const std::vector<ContourElem> &moves, const char *name) {
  const PlaneAxes ax = planeAxes(plane());
  MotionRecord begin = record(RecordKind::CycleBegin);
  begin.text = name;
  emit(begin);
  for (auto &m : moves) {
    AxisVec to = st.position;
    to[ax.u] = m.end.a, to[ax.v] = m.end.b;
    bool ok = true;
    switch (m.kind) {
    case ContourKind::Rapid: ok = moveTo(RecordKind::Rapid, to); break;
    case ContourKind::Line: ok = checkFeed("G1") && moveTo(RecordKind::Linear, to); break;
    case ContourKind::Arc: {
      Vec3 centre = {st.position[0], st.position[1], st.position[2]};
      centre[ax.u] = m.centre.a, centre[ax.v] = m.centre.b;
      ok = checkFeed("G2/G3") && emitArc(to, centre, planeNormal(plane()), m.ccw ? 1 : -1);
      break;
    }
    }
    if (!ok) return false;
  }
  emit(record(RecordKind::CycleEnd));
  return true;
}

}  // namespace ncc
