// Executor motion: straight moves, arcs (centre and radius forms, helices, turns), G28/G30, G53
// and canned cycles. Positions are computed in the machine frame (mm); words are converted with
// the unit scale and the current offsets (ExecutorImpl.h).
#include "runtime/ExecutorImpl.h"
#include "runtime/Geometry.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace ncc {

namespace {

// Plane axes of arcs: first, second, normal axis; the centre-offset words of the two plane axes.
struct ArcAxes {
  int a1, a2, d;
  Word o1, o2;
  char l1, l2;
};
constexpr ArcAxes kArcAxes[] = {
    {0, 1, 2, Word::I, Word::J, 'X', 'Y'},
    {2, 0, 1, Word::K, Word::I, 'Z', 'X'},
    {1, 2, 0, Word::J, Word::K, 'Y', 'Z'},
};

// rs274's rule for centre-form arcs: an error when the start and end radii differ by more than
// 100 x the absolute tolerance, or by more than the absolute tolerance AND by more than 0.1 %
// of the larger radius. The absolute tolerance is 0.01 x 2 x sqrt(2) mm in mm programs and
// 0.001 x 2 x sqrt(2) inch in inch programs (rs274ngc CENTER_ARC_RADIUS_TOLERANCE_*).
constexpr double kArcRelTolerance = 0.001;
constexpr double kArcAbsTolMM = 0.02 * M_SQRT2, kArcAbsTolInch = 0.002 * M_SQRT2;

// Words that give a move a target: the axes and RS274NGC's polar @ ^.
const WordMask kTargetMask = kAxisMask | wordBit(Word::PolarR) | wordBit(Word::PolarA);

}  // namespace

double Executor::Impl::moveFeed(double lengthMM) const {
  switch (st.feedMode) {
  case ModeValue::PerRev: return feedMM * st.speed;
  case ModeValue::InverseTime: return lengthMM * feedMM;
  default: return feedMM;
  }
}

void Executor::Impl::inverseTimeRate(double mmPerMin) {
  if (st.feedMode != ModeValue::InverseTime) return;
  MotionRecord f = record(RecordKind::FeedRate);
  f.value = mmPerMin;
  emit(f);
}

bool Executor::Impl::checkFeed(const char *code) {
  // An SL sub-contour or a contour table (CONTPRON) is only read: the feeds come later.
  if (capture.active && (capture.sl || capture.table)) return true;
  if (st.feedMode == ModeValue::InverseTime) {
    // Inverse time: every feed move carries its own F.
    if (feedInBlock && feedMM > 0) return true;
    return error(std::string("F word missing with inverse time ") + code + " move", "motion-without-feed");
  }
  if (feedMM > 0) return true;
  return error(std::string("Cannot do ") + code + " with zero feed rate", "motion-without-feed");
}

bool Executor::Impl::moveTo(RecordKind k, const AxisVec &to, bool exactStop, double feed) {
  MotionRecord r = record(k);
  r.end = to;
  r.exactStop = exactStop || st.pathMode == ModeValue::ExactStop;
  if (k == RecordKind::Linear) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) d2 += (to[i] - r.start[i]) * (to[i] - r.start[i]);
    r.feed = feed > 0 ? feed : cssPerRev() ? cssFeed(r) : moveFeed(std::sqrt(d2));
    if (feed <= 0) inverseTimeRate(r.feed);
  }
  st.position = to;
  return emitMove(r);
}

bool Executor::Impl::emitMove(const MotionRecord &r) {
  if (stopOnce && !r.exactStop) {  // G9: this block's moves end at rest
    MotionRecord s = r;
    s.exactStop = true;
    return emitMove(s);
  }
  if (!cssBeforeMove(r)) return false;
  notePath(r);
  if (corner.active) return cornerNext(r);
  if (corner.requested) {
    corner.requested = false;
    if (r.kind != RecordKind::Linear && r.kind != RecordKind::Arc)
      return error("a chamfer or rounding needs a G1, G2 or G3 move", "unsupported-code");
    corner.active = true;
    corner.move = r;
    corner.round = corner.reqRound, corner.size = corner.reqSize, corner.leg = corner.reqLeg;
    corner.nextAxis = corner.reqNextAxis, corner.nextSign = corner.reqNextSign;
    return true;
  }
  return pathOut(r);
}

bool Executor::Impl::pathOut(const MotionRecord &r) {
  if (comp.active()) return comp.add(toCompPlane(r, compOut.plane)) || error(comp.error(), comp.rule());
  if (compExit) {
    compExit = false;
    if (r.kind == RecordKind::Arc)
      return error("The move just after exiting cutter compensation mode must be straight, not an arc",
                   "cutcomp-exit-arc");
    MotionRecord x = r;
    x.start = compOut.toMachine(comp.toolPosition());
    emit(x);
    return true;
  }
  emit(r);
  return true;
}

bool Executor::Impl::execMove(const MachineCmd &c) {
  if (tapOpen && st.motion != ModeValue::TapOut && (c.mask & kTargetMask))
    return error("a G331 tap must be followed by its G332 back out of the hole", "thread-invalid");
  const bool turnCorner = st.motion == ModeValue::Linear && (c.has(Word::I) || c.has(Word::K) || c.has(Word::R));
  if ((c.has(Word::Chamfer) || c.has(Word::ChamferLeg) || c.has(Word::Round) || turnCorner) && !cornerRequest(c)) return false;
  if (c.has(Word::PolyIndex)) return polyCoefficients(c);
  if (poly.outside && !polyOutsideMove()) return false;
  switch (st.motion) {
  case ModeValue::Rapid:
    if (!(c.mask & kTargetMask)) return true;
    return moveTo(RecordKind::Rapid, target(c));
  case ModeValue::Linear:
    if (!(c.mask & kTargetMask)) return true;
    if (!checkFeed("G1")) return false;
    return moveTo(RecordKind::Linear, target(c));
  case ModeValue::ArcCW:
  case ModeValue::ArcCCW: return arc(c, st.motion == ModeValue::ArcCW);
  case ModeValue::ArcThrough: return arcThrough(c);
  case ModeValue::ArcTangent: return arcTangent(c);
  case ModeValue::CycleOff:
    if (!(c.mask & kTargetMask)) return true;
    return error("Cannot use axis values with G80", "motion-mode-none");
  case ModeValue::SplineCubic:
  case ModeValue::SplineQuadratic: return bezier(c, st.motion == ModeValue::SplineCubic);
  case ModeValue::Nurbs: return nurbsPoint(c);
  case ModeValue::SplineAkima:
  case ModeValue::SplineB:
  case ModeValue::SplineC: return sinSplinePoint(c);
  case ModeValue::Poly: return polyMove(c);
  case ModeValue::TurnAlongZ:
  case ModeValue::TurnAlongX:
  case ModeValue::ThreadSingle: return turnCycle(c);
  case ModeValue::Thread:
  case ModeValue::ThreadVariable: return threadMove(c);
  case ModeValue::RigidTap: return rigidTap(c);
  case ModeValue::ThreadLead: return leadThread(c);
  case ModeValue::TapIn:
  case ModeValue::TapOut: return positionTap(c, st.motion == ModeValue::TapIn);
  case ModeValue::ThreadCycle: return threadCycle(c);
  case ModeValue::ThreadMulti: return threadMulti(c);
  case ModeValue::PeckAlongZ:
  case ModeValue::PeckAlongX: return peckCycle(c);
  case ModeValue::ProbeToward:
  case ModeValue::ProbeTowardNoError:
  case ModeValue::ProbeAway:
  case ModeValue::ProbeAwayNoError:
  case ModeValue::Skip:
    if (!(c.mask & kTargetMask)) return true;
    return probeMove(c);
  case ModeValue::NurbsEnd:  // rs274 has no motion mode after G5.3
    if (!(c.mask & kTargetMask)) return true;
    return error("Cannot use axis values without a g code that uses them", "motion-mode-none");
  default:
    if (!compForbids("Cannot use canned cycles with cutter compensation on")) return false;
    if (c.sub || c.sub2) return error("per-axis absolute/incremental words in a canned cycle are not supported", "unsupported-code");
    return cycle(c);
  }
}

void Executor::Impl::plainMove(const MachineCmd &c) {
  // target() without a frame: each axis word plus offset(i), the same sums in the same order.
  const bool inc = st.distance == ModeValue::Incremental;
  const double unit = scale(), xUnit = axisScale(0);
  AxisVec to = st.position;
  for (WordMask m = c.mask; m; m &= m - 1) {
    const int i = __builtin_ctzll(m);
    const double v = c.w[i] * (i == 0 ? xUnit : isLengthAxis(i) ? unit : 1.0);
    const double off = offset(i);
    to[i] = (inc ? to[i] - off + v : v) + off;
  }
  // notePath: a move in XYZ becomes the last path by staying in plainRecord (lastPathPlain); a
  // move that is not keeps the one before, taken out of plainRecord before it is reused.
  const bool pathMove = to[0] != st.position[0] || to[1] != st.position[1] || to[2] != st.position[2];
  if (!pathMove && lastPathPlain) lastPath = lastPathNow(), lastPathPlain = false;
  if (pathMove) lastPathPlain = true;
  // moveTo's record (record() + end, exactStop, feed), then emit straight to the sink.
  const RecordKind k = st.motion == ModeValue::Linear ? RecordKind::Linear : RecordKind::Rapid;
  MotionRecord &r = plainRecord;
  r.kind = k;
  r.plane = plane();
  r.blockNumber = blockNumber;
  r.loc = loc;
  r.start = st.position;
  r.end = to;
  r.exactStop = st.pathMode == ModeValue::ExactStop;
  r.feed = k == RecordKind::Linear ? moveFeed(0) : 0;  // not inverse time: the length does not matter
  st.position = to;
  threadChain = false;
  route.record(r);  // `sink` is route: called on the final class, not through the base
}

bool Executor::Impl::arc(const MachineCmd &c, bool cw) {
  const ArcAxes &ax = kArcAxes[(int)plane()];
  const char *code = cw ? "G2" : "G3";
  if (!checkFeed(code)) return false;
  if (Vec3 tn; pf.tiltOn && !tiltedNormal(tn, &c)) return false;  // an arc turning the chain
  // Under a programmable frame the arc may land in another principal plane, or in a tilted one
  // (3-D G68): its machine plane and normal, and whether it turns the other way (a mirror).
  bool flip = false;
  Plane outPlane = plane();
  bool tilted = false;
  std::array<double, 3> machineNormal = planeNormal(plane());
  if (!frameKeepsPlane(plane(), flip)) {
    if (rotated() || !pf.similar())
      return error(rotated() ? "arcs outside the XY plane with a rotated coordinate system are not supported"
                             : "an arc under a frame that scales its axes unequally is not supported",
                   "unsupported-code");
    const Affine out = outLinear();
    Vec3 n = out.applyLinear(planeNormal(plane()));
    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double &v : n) v /= len;
    flip = out.det() < 0;  // a mirror reverses the turn about the mapped normal
    machineNormal = n;
    tilted = true;
    for (int i = 0; i < 3; ++i)  // a principal axis after all: that plane, turning about +axis
      if (n[(i + 1) % 3] == 0 && n[(i + 2) % 3] == 0) {
        static const Plane kAxisPlane[] = {Plane::YZ, Plane::ZX, Plane::XY};
        outPlane = kAxisPlane[i];
        if (n[i] < 0) flip = !flip;
        machineNormal = planeNormal(outPlane);
        tilted = false;
      }
  }
  AxisVec end = target(c);
  // Computed in the offset frame (ExecutorImpl.h): I J K and R are program values.
  const AxisVec start = frameIn(st.position);
  AxisVec fend = frameIn(end);
  const bool inch = st.units == ModeValue::Inch;
  const double s1 = start[ax.a1], s2 = start[ax.a2];
  double e1 = fend[ax.a1], e2 = fend[ax.a2];
  double c1, c2;
  // The offset word of the axis normal to the plane (K in G17, J in G18, I in G19).
  static const Word kNormalWord[] = {Word::K, Word::J, Word::I};
  static const char *kPlaneNames[] = {"xy", "xz", "yz"};
  Word normal = kNormalWord[(int)plane()];
  if (c.has(normal))
    return error(std::string(kWordKeys[(int)normal]) + " word given for arc in " + kPlaneNames[(int)plane()] +
                     " plane",
                 "arc-invalid");
  if (!c.has(Word::R) && !c.has(ax.o1) && !c.has(ax.o2) && !c.has(Word::Opening))
    return error("R i j k words all missing for arc", "arc-invalid");
  // Sinumerik AR= (degrees, 0 < AR < 360): with the end point it gives the radius, with the
  // centre the end point (the plane's end coordinates must then be left out).
  const bool opening = c.has(Word::Opening), openingCentre = opening && (c.has(ax.o1) || c.has(ax.o2));
  const double ar = c.get(Word::Opening);
  if (opening && !(ar > 0 && ar < 360)) return error("the opening angle AR must lie between 0 and 360 degrees", "arc-invalid");
  if (opening && c.has(Word::R)) return error("an arc takes one of a radius and an opening angle", "arc-invalid");
  if (openingCentre && (c.has((Word)ax.a1) || c.has((Word)ax.a2)))
    return error(std::string("an arc with its centre and opening angle takes no end point in the plane (") + ax.l1 + ", " +
                     ax.l2 + ")",
                 "arc-invalid");
  if (c.has(Word::R) || (opening && !openingCentre)) {
    double dx0 = e1 - s1, dy0 = e2 - s2, chord0 = std::hypot(dx0, dy0);
    // The chord subtends AR at the centre: r = (chord / 2) / sin(AR / 2), past 180 the long way.
    double rr = c.has(Word::R) ? c.get(Word::R) * scale()
                               : chord0 / 2 / std::sin(ar * M_PI / 360) * (ar > 180 ? -1.0 : 1.0);
    double dx = e1 - s1, dy = e2 - s2, chord = std::hypot(dx, dy);
    if (chord == 0) return error("Current point same as end point of arc", "arc-invalid");
    double half = chord / 2, h = 0;
    if (std::fabs(rr) < half) {
      if (half - std::fabs(rr) > kArcRadiusSlackMM)
        return error("Arc radius too small to reach end point", "arc-radius-too-small");
    } else {
      h = std::sqrt(rr * rr - half * half);
    }
    // Centre left of the chord for a short CCW arc, right for CW; a negative R takes the long way.
    double side = (cw ? -1.0 : 1.0) * (rr < 0 ? -1.0 : 1.0);
    c1 = (s1 + e1) / 2 - side * h * dy / chord;
    c2 = (s2 + e2) / 2 + side * h * dx / chord;
  } else {
    double o1 = c.get(ax.o1) * scale(), o2 = c.get(ax.o2) * scale();
    // G90.1/G91.1, unless the word is absolute or incremental on its own (Sinumerik I=AC(..)).
    auto absolute = [&](Word w) {
      return c.sub & wordBit(w) ? false : c.sub2 & wordBit(w) ? true : st.arcDistance == ModeValue::ArcAbsolute;
    };
    c1 = absolute(ax.o1) ? o1 + frameOffset(ax.a1) : s1 + o1;
    c2 = absolute(ax.o2) ? o2 + frameOffset(ax.a2) : s2 + o2;
    if (openingCentre) {  // the start turned about the centre by AR, clockwise under G2
      double a = (cw ? -ar : ar) * M_PI / 180, u = s1 - c1, v = s2 - c2;
      e1 = c1 + u * std::cos(a) - v * std::sin(a);
      e2 = c2 + u * std::sin(a) + v * std::cos(a);
      fend[ax.a1] = e1, fend[ax.a2] = e2;
      end = frameOut(fend);
    }
    double r1 = std::hypot(s1 - c1, s2 - c2), r2 = std::hypot(e1 - c1, e2 - c2);
    if (r1 == 0) return error("Zero-radius arc", "arc-invalid");
    double absErr = std::fabs(r1 - r2), relErr = absErr / std::max(r1, r2);
    double tol = std::max(machine.arcTolerance, inch ? kArcAbsTolInch * 25.4 : kArcAbsTolMM);
    if (absErr > 100 * tol || (absErr > tol && relErr > kArcRelTolerance)) {
      // rs274's message, in program units.
      double k = 1 / scale();
      double p1 = frameOffset(ax.a1), p2 = frameOffset(ax.a2);
      char buf[512];
      std::snprintf(buf, sizeof buf,
                    "Radius to end of arc differs from radius to start: start=(%c%.4f,%c%.4f) "
                    "center=(%c%.4f,%c%.4f) end=(%c%.4f,%c%.4f) r1=%.4f r2=%.4f abs_err=%.4g "
                    "rel_err=%.4f%%",
                    ax.l1, (s1 - p1) * k, ax.l2, (s2 - p2) * k, ax.l1, (c1 - p1) * k, ax.l2,
                    (c2 - p2) * k, ax.l1, (e1 - p1) * k, ax.l2, (e2 - p2) * k, r1 * k, r2 * k,
                    absErr * k, relErr * 100);
      return error(buf, "arc-radius-mismatch");
    }
  }
  int turns = 1;
  if (c.has(Word::P)) {
    double p = c.get(Word::P);
    if (p != std::floor(p)) return error("P value not an integer with G2 or G3", "arc-invalid");
    if (p < 1) return error("P value should be 1 or greater with G2 or G3", "arc-invalid");
    if (p > 1e6) return error("P value too large with G2 or G3", "arc-invalid");
    turns = (int)p;
  }
  MotionRecord r = record(RecordKind::Arc);
  r.plane = outPlane;
  if (tilted) r.setNormal(machineNormal);
  r.end = end;
  AxisVec centre = start;
  centre[ax.a1] = c1;
  centre[ax.a2] = c2;
  centre = frameOut(centre);
  r.center = {centre[0], centre[1], centre[2]};
  r.turns = cw != flip ? -turns : turns;
  r.exactStop = st.pathMode == ModeValue::ExactStop;
  // Path length (for inverse-time feed): swept angle times radius, with the helix; on the
  // machine (a scaled frame scales it).
  double a0 = std::atan2(s2 - c2, s1 - c1), a1 = std::atan2(e2 - c2, e1 - c1);
  double sweep = cw ? a0 - a1 : a1 - a0;
  if (sweep <= 1e-12) sweep += 2 * M_PI;
  sweep += 2 * M_PI * (turns - 1);
  double radius = std::hypot(s1 - c1, s2 - c2), height = end[ax.d] - start[ax.d];
  if (pf.linear) {  // on the machine: the centre lies in the start's plane, the helix along the normal
    radius = std::sqrt(std::pow(st.position[0] - centre[0], 2) + std::pow(st.position[1] - centre[1], 2) +
                       std::pow(st.position[2] - centre[2], 2));
    height = 0;
    for (int i = 0; i < 3; ++i) height += (end[i] - st.position[i]) * machineNormal[i];
  }
  r.feed = cssPerRev() ? cssFeed(r) : moveFeed(std::hypot(sweep * radius, height));
  inverseTimeRate(r.feed);
  st.position = end;
  return emitMove(r);
}

bool Executor::Impl::splineAllowed(const MachineCmd &c, const char *code) {
  const bool nurbsBlock = st.motion == ModeValue::Nurbs;
  if (c.mask & (wordBit(Word::Z) | wordBit(Word::A) | wordBit(Word::B) | wordBit(Word::C)))
    return error(nurbsBlock ? "G5.2 control points take X and Y only (rs274 ignores Z, A, B and C words there)"
                            : "Splines may not have motion in Z, A, B, or C",
                 "spline-invalid");
  if (!compForbids(nurbsBlock ? "Cannot convert spline with cutter radius compensation (rs274 would run a G5.2 NURBS "
                                "uncompensated)"
                              : "Cannot convert spline with cutter radius compensation"))
    return false;
  if (compExit) return error("The move just after exiting cutter compensation mode must be straight, not a spline", "cutcomp-exit-arc");
  if (plane() != Plane::XY)
    return error(nurbsBlock ? "Splines must be in the XY plane (rs274 would draw a G5.2 NURBS in XY whatever the plane)"
                            : "Splines must be in the XY plane",
                 "spline-invalid");
  if (linearFrame())
    return error("splines under a rotated, scaled or mirrored coordinate system are not supported", "unsupported-code");
  if (st.feedMode == ModeValue::InverseTime)
    return error(std::string(code) + " in inverse time feed (G93) is not supported: rs274 gives a spline no feed rate",
                 "unsupported-code");
  if (st.feedMode == ModeValue::PerMinute && !(feedMM > 0))  // rs274's messages
    return error(nurbsBlock ? "Cannot make a NURBS with 0 feedrate" : "Cannot make arc with zero feed rate",
                 "motion-without-feed");
  return checkFeed(code);
}

// Emits the Spline record from the start (st.position) through `pts` (machine XYZ; the last one
// the end) of order `order`, and leaves the machine at its end. A curve Motion IR cannot hold
// (a non-finite point or weight from computed words) is an error.
bool Executor::Impl::emitSpline(const std::vector<std::array<double, 3>> &pts, int order, std::vector<double> weights) {
  MotionRecord r = record(RecordKind::Spline);
  SplineData s;
  s.degree = order - 1;
  s.points.assign(pts.begin() + 1, pts.end() - 1);
  s.weights = std::move(weights);
  for (int i = 0; i < 3; ++i) r.end[i] = pts.back()[i];
  r.setSpline(std::move(s));
  if (std::string why = splineError(r); !why.empty()) return error(why, "spline-invalid");
  r.exactStop = st.pathMode == ModeValue::ExactStop;
  if (cssPerRev()) return error("a spline with feed per revolution under constant surface speed (G96) is not supported", "unsupported-code");
  r.feed = moveFeed(splineLength(r));
  st.position = r.end;
  return emitMove(r);
}

bool Executor::Impl::bezier(const MachineCmd &c, bool cubic) {
  const char *code = cubic ? "G5" : "G5.1";
  st.motion = splineReturn;
  if (!(c.mask & kTargetMask)) return error("All axes missing with motion code", "spline-invalid");
  if (!splineAllowed(c, code)) return false;
  const bool i = c.has(Word::I), j = c.has(Word::J);
  if (!cubic && !(i && j)) return error("Must specify both I and J with G5.1", "spline-invalid");
  if (i != j) return error("Must specify both I and J, or neither", "spline-invalid");
  if (cubic && !(c.has(Word::P) && c.has(Word::Q))) return error("Must specify both P and Q with G5", "spline-invalid");
  // Offsets in program units, translated like the positions (no frame turns them: splineAllowed).
  const double k = scale();
  const AxisVec end = target(c);
  std::array<double, 3> s{st.position[0], st.position[1], st.position[2]}, e{end[0], end[1], end[2]};
  double i1 = i ? c.get(Word::I) : splineIJ[0], j1 = i ? c.get(Word::J) : splineIJ[1];
  std::vector<std::array<double, 3>> pts{s, {s[0] + i1 * k, s[1] + j1 * k, s[2]}};
  if (cubic) {
    pts.push_back({e[0] + c.get(Word::P) * k, e[1] + c.get(Word::Q) * k, e[2]});
    splineIJ = {-c.get(Word::P), -c.get(Word::Q)};
  }
  pts.push_back(e);
  return emitSpline(pts, cubic ? 4 : 3, {});
}

bool Executor::Impl::nurbsPoint(const MachineCmd &c) {
  if (!splineAllowed(c, "G5.2")) return false;
  const bool x = c.has(Word::X), y = c.has(Word::Y), p = c.has(Word::P);
  if (x != y) return error("You must specify both X and Y coordinates for Control Points", "spline-invalid");
  if (!x && p && nurbs.open) return error("Can specify P without X and Y only for the first control point", "spline-invalid");
  // rs274 checks P only once the curve has points: a first G5.2 X Y without P gets the
  // weight -1 there, which ncc refuses.
  if (x && !(p && c.get(Word::P) > 0))
    return error(nurbs.open || p ? "Must specify positive weight P for every Control Point"
                                 : "Must specify positive weight P for every Control Point (rs274 gives a first point "
                                   "without P the weight -1)",
                 "spline-invalid");
  if (!nurbs.open) {
    nurbs = Nurbs{};
    nurbs.open = true;
    nurbs.frame = lastFrame;
    nurbs.units = st.units;
    nurbs.points.push_back({st.position[0], st.position[1], st.position[2]});
    nurbs.weights.push_back(!x && p && c.get(Word::P) > 0 ? c.get(Word::P) : 1.0);  // rs274: else 1
  }
  if (c.has(Word::L)) {
    double l = c.get(Word::L);
    if (l != std::floor(l)) return error("L value not an integer with G5.2", "spline-invalid");
    if (l > 16) return error("G5.2 L (the NURBS order) above 16 is not supported", "unsupported-code");
    if (l > 3) nurbs.order = (int)l;  // rs274: L <= 3 keeps the order 3
  }
  if (x) {
    // rs274 keeps the current position at the curve's start until G5.3, so G91 control points
    // are relative to the start: target() does the same.
    AxisVec t = target(c);
    nurbs.points.push_back({t[0], t[1], t[2]});
    nurbs.weights.push_back(c.get(Word::P));
  }
  return true;
}

bool Executor::Impl::nurbsEnd() {
  if (st.motion != ModeValue::Nurbs || !nurbs.open) return error("Cannot use G5.3 without G5.2 first", "spline-invalid");
  // rs274 keeps the points in program units and converts them at G5.3: a change of offsets or
  // units in between would move the earlier points. Compensation, plane and frame must still
  // allow the curve.
  if (lastFrame != nurbs.frame || st.units != nurbs.units)
    return error("the coordinate system or the units changed inside a G5.2 NURBS (rs274 would apply the new ones to "
                 "every control point)",
                 "spline-invalid");
  if (!splineAllowed(MachineCmd{}, "G5.3")) return false;
  if (nurbs.points.size() < (size_t)nurbs.order)
    return error("You must specify a number of control points at least equal to the order L = " +
                     std::to_string(nurbs.order),
                 "spline-invalid");
  Nurbs n = std::move(nurbs);
  nurbs = Nurbs{};
  return emitSpline(n.points, n.order, std::move(n.weights));
}

bool Executor::Impl::execHome(const MachineCmd &c) {
  // Rapid through the intermediate point (program coordinates), then the named axes (all when
  // none is named) to the stored reference position (machine coordinates).
  if (!compForbids("Cannot use g28 or g30 with cutter radius comp")) return false;
  if (!frameForbids(c.sub == 2 ? "G30" : "G28")) return false;
  if (!moveTo(RecordKind::Rapid, target(c))) return false;
  // rs274 replaces the named axes' program coordinates by the reference point's: under a
  // rotated coordinate system G28 X moves along the program X axis (frameIn/frameOut).
  const AxisVec home = frameIn(this->home[c.sub == 2 ? 1 : 0]);
  bool any = c.mask & kAxisMask;
  AxisVec t = frameIn(st.position);
  for (int i = 0; i < kAxes; ++i)
    if (!any || c.has((Word)i)) t[i] = home[i];
  return moveTo(RecordKind::Rapid, frameOut(t));
}

bool Executor::Impl::execMachineMove(const MachineCmd &c) {
  if (!compForbids("Cannot use g53 with cutter radius comp")) return false;
  AxisVec t = st.position;
  for (int i = 0; i < kAxes; ++i)
    if (c.has((Word)i)) t[i] = c.get((Word)i) * axisScale(i);
  if (c.sub == 1) {
    if (!checkFeed("G1")) return false;
    return moveTo(RecordKind::Linear, t);
  }
  return moveTo(RecordKind::Rapid, t);
}

AxisVec toCompPlane(const AxisVec &v, Plane p) {
  AxisVec o = v;
  if (p == Plane::ZX) o[0] = v[2], o[1] = v[0], o[2] = v[1];
  else if (p == Plane::YZ) o[0] = v[1], o[1] = v[2], o[2] = v[0];
  return o;
}

AxisVec fromCompPlane(const AxisVec &v, Plane p) {
  AxisVec o = v;
  if (p == Plane::ZX) o[2] = v[0], o[0] = v[1], o[1] = v[2];
  else if (p == Plane::YZ) o[1] = v[0], o[2] = v[1], o[0] = v[2];
  return o;
}

static MotionRecord turned(const MotionRecord &r, Plane p, bool in) {
  if (p == Plane::XY) return r;
  MotionRecord o = r;
  auto f = [&](const AxisVec &v) { return in ? toCompPlane(v, p) : fromCompPlane(v, p); };
  o.start = f(r.start);
  o.end = f(r.end);
  AxisVec c{};
  c[0] = r.center[0], c[1] = r.center[1], c[2] = r.center[2];
  c = f(c);
  o.center = {c[0], c[1], c[2]};
  o.plane = in ? Plane::XY : p;
  return o;
}

MotionRecord toCompPlane(const MotionRecord &r, Plane p) { return turned(r, p, true); }
MotionRecord fromCompPlane(const MotionRecord &r, Plane p) { return turned(r, p, false); }

}  // namespace ncc
