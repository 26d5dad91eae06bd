// Executor: the one contour step that inserts a chamfer or a rounding at the corner between two
// moves (ISO `,C` `,R`; Sinumerik CHF/RND and Heidenhain CHF/RND use the same words). The first
// move waits until the second arrives; both are trimmed and the corner element goes between them.
// Lines in the active plane today; next to an arc it is an error until arcs are done.
#include "runtime/ExecutorImpl.h"

#include <cmath>

namespace ncc {

namespace {
constexpr int kA1[] = {0, 2, 1}, kA2[] = {1, 0, 2}, kD[] = {2, 1, 0};  // per Plane
}

bool Executor::Impl::cornerRequest(const MachineCmd &c) {
  if (c.has(Word::Chamfer) && c.has(Word::Round)) return error("a chamfer and a rounding in one block", "corner-invalid");
  double size = (c.has(Word::Chamfer) ? c.get(Word::Chamfer) : c.get(Word::Round)) * scale();
  if (!(size > 0)) return error("a chamfer or rounding must be greater than 0", "corner-invalid");
  if (prevBlockFrame || curBlockFrame)  // 808D manual L5950
    return error("a chamfer or rounding must not follow a coordinate-system change or reference-point return",
                 "corner-invalid");
  if (comp.active() || pf.scaleOn || st.feedMode == ModeValue::InverseTime)
    return error("a chamfer or rounding with cutter compensation, scaling or inverse-time feed is not supported",
                 "unsupported-code");
  corner.requested = true;
  corner.reqRound = c.has(Word::Round);
  corner.reqSize = size;
  return true;
}

void Executor::Impl::cornerFlush(const char *why) {
  if (!corner.active) return;
  corner.active = false;
  diags.warning(corner.move.loc, std::string(corner.round ? "rounding" : "chamfer") + " not inserted: " + why,
                "corner-not-inserted");
  sink.record(corner.move);
  for (auto &r : corner.held) sink.record(r);
  corner.held.clear();
}

bool Executor::Impl::cornerNext(const MotionRecord &nextIn) {
  MotionRecord first = corner.move, next = nextIn;
  const int pl = (int)first.plane, a1 = kA1[pl], a2 = kA2[pl], d = kD[pl];
  for (auto &h : corner.held)
    if (h.kind != RecordKind::Comment && h.kind != RecordKind::Message)
      return error("commands between a chamfer or rounding and the next move are not supported", "unsupported-code");
  if (next.kind == RecordKind::Arc)
    return error("a chamfer or rounding next to an arc is not supported yet", "unsupported-code");
  if (next.kind != RecordKind::Linear) return error("a chamfer or rounding needs a G1 move after it", "unsupported-code");
  // Moves that leave the plane (or turn a rotary axis): the controller does not insert it.
  bool inPlane = true;
  for (int i = 0; i < kAxes; ++i)
    if (i != a1 && i != a2 && (first.end[i] != first.start[i] || next.end[i] != next.start[i])) inPlane = false;
  if (!inPlane) {
    cornerFlush("a move leaves the plane");
    return emitMove(next);
  }
  double u1 = first.end[a1] - first.start[a1], u2 = first.end[a2] - first.start[a2];
  double v1 = next.end[a1] - next.start[a1], v2 = next.end[a2] - next.start[a2];
  double l1 = std::hypot(u1, u2), l2 = std::hypot(v1, v2);
  if (l1 == 0 || l2 == 0) return error("a chamfer or rounding between zero-length moves", "corner-invalid");
  u1 /= l1, u2 /= l1, v1 /= l2, v2 /= l2;
  double cross = u1 * v2 - u2 * v1, dot = u1 * v1 + u2 * v2;
  if (std::fabs(cross) < 1e-12 && dot > 0) {
    cornerFlush("the two moves are collinear");
    return emitMove(next);
  }
  if (std::fabs(cross) < 1e-12) return error("a chamfer or rounding where the path reverses", "corner-invalid");
  // The corner angle between the lines, half of it, and the distance from the corner to the
  // points where the element meets each line.
  double half = std::acos(std::max(-1.0, std::min(1.0, -dot))) / 2;
  double dist = corner.round ? corner.size / std::tan(half) : corner.size / (2 * std::sin(half));
  if (dist > l1 + 1e-9 || dist > l2 + 1e-9) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the %s does not fit: it takes %.4f mm of each move (%.4f and %.4f long)",
                  corner.round ? "rounding" : "chamfer", dist, l1, l2);
    return error(buf, "corner-invalid");
  }
  corner.active = false;
  const AxisVec p = first.end;
  first.end[a1] = p[a1] - u1 * dist, first.end[a2] = p[a2] - u2 * dist;
  next.start[a1] = p[a1] + v1 * dist, next.start[a2] = p[a2] + v2 * dist;
  MotionRecord elem = first;  // the block with the chamfer/rounding: its feed and source
  elem.start = first.end;
  elem.end = next.start;
  if (corner.round) {
    double b1 = v1 - u1, b2 = v2 - u2, bl = std::hypot(b1, b2);  // the bisector, into the corner
    double c = corner.size / std::sin(half);
    elem.kind = RecordKind::Arc;
    elem.center = {p[0], p[1], p[2]};
    elem.center[a1] = p[a1] + b1 / bl * c;
    elem.center[a2] = p[a2] + b2 / bl * c;
    elem.center[d] = p[d];
    elem.turns = cross > 0 ? 1 : -1;  // a left turn runs counter-clockwise
  }
  sink.record(first);
  sink.record(elem);
  for (auto &h : corner.held) sink.record(h);
  corner.held.clear();
  return emitMove(next);  // it may carry a corner request of its own
}

}  // namespace ncc
