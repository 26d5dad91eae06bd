#include "frontend/cldata/ClPath.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc::cld {

using ir::Expr;
using ir::Op;
using ir::OpKind;

namespace {
constexpr double kTol = 0.001;  // mm: positions and radii that must agree (scaled in inch)
}

ir::Function beginClModule(SourceManager &sm, uint32_t file, ir::Module &out) {
  out.dialect = ir::Dialect::CLData;
  out.name = sm.name(file);
  out.functions.clear();
  ir::Function fn;
  fn.name = "main";
  fn.loc = {file, 1, 1};
  return fn;
}

void ClPath::begin(SourceLoc l) {
  emit(OpKind::Mode, l).set("units", Expr::symbol("mm")).set("distance", Expr::symbol("absolute")).set("plane", Expr::symbol("xy"));
}

void ClPath::comment(std::string text, SourceLoc l) { emit(OpKind::Comment, l).set("text", Expr::string(std::move(text))); }

void ClPath::setPlane(const char *p, SourceLoc l) {
  if (plane_ == p) return;
  plane_ = p;
  emit(OpKind::Mode, l).set("plane", Expr::symbol(p));
}

void ClPath::motion(const char *m, SourceLoc l) {
  if (mode_ == m) return;
  mode_ = m;
  emit(OpKind::Mode, l).set("motion", Expr::symbol(m));
}

void ClPath::units(bool inch, SourceLoc l) {
  inch_ = inch;
  emit(OpKind::Mode, l).set("units", Expr::symbol(inch ? "inch" : "mm"));
}

void ClPath::toolLoad(int t, int h, SourceLoc l) {
  emit(OpKind::ToolSelect, l).set("value", Expr::number(t, ir::Type::Int));
  emit(OpKind::ToolChange, l);
  emit(OpKind::ToolLength, l).set("h", Expr::number(h, ir::Type::Int));
}

bool ClPath::line(SourceLoc l, Vec3 p, bool rapid) {
  if (!rapid && !feedSet_) return error(l, fmt::format("a feed move before any {}", words_.feed), "motion-without-feed");
  motion(rapid ? "rapid" : "linear", l);
  Op &m = emit(OpKind::Move, l);
  m.set("X", num(p.x)).set("Y", num(p.y)).set("Z", num(p.z));
  pos_ = p;
  return true;
}

bool ClPath::arc(SourceLoc l, const ClArc &a, Vec3 p) {
  // The plane from the axis: it must be one of the coordinate axes.
  struct PlaneRow {
    const char *plane;
    int axis;  // 0 x, 1 y, 2 z: the plane's normal
  };
  static const PlaneRow kPlanes[] = {{"yz", 0}, {"zx", 1}, {"xy", 2}};
  double ax[3] = {a.axis.x, a.axis.y, a.axis.z};
  const PlaneRow *pl = nullptr;
  for (auto &row : kPlanes)
    if (std::fabs(std::fabs(ax[row.axis]) - 1) < 1e-6 && std::fabs(ax[(row.axis + 1) % 3]) < 1e-6 && std::fabs(ax[(row.axis + 2) % 3]) < 1e-6)
      pl = &row;
  if (!pl) return error(a.loc, fmt::format("{} with a tool axis that is not X, Y or Z: only arcs in the XY, ZX and YZ planes are read", words_.circle));
  if (!pos_) return error(a.loc, "an arc before the tool position is known (no move before it)");
  if (!feedSet_) return error(l, fmt::format("an arc before any {}", words_.feed), "motion-without-feed");
  // Start and end must lie at the radius from the centre, in the plane.
  double tol = inch_ ? kTol / 25.4 : kTol;
  auto inPlane = [&](Vec3 q) {
    double d[3] = {q.x - a.c.x, q.y - a.c.y, q.z - a.c.z};
    d[pl->axis] = 0;
    return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  };
  for (auto [q, end] : {std::pair{*pos_, false}, std::pair{p, true}}) {
    double rr = inPlane(q);
    if (std::fabs(rr - a.r) > tol)
      return error(end ? l : a.loc,
                   fmt::format("the arc's {} point is {:.4f} from the {} centre, its radius is {}", end ? "end" : "start", rr, words_.circle, a.r),
                   "arc-radius-mismatch");
  }
  setPlane(pl->plane, a.loc);
  motion(ax[pl->axis] > 0 ? "arc_ccw" : "arc_cw", a.loc);
  Op &m = emit(OpKind::Move, l);
  m.set("X", num(p.x)).set("Y", num(p.y)).set("Z", num(p.z));
  // The centre as offsets from the start (I J K incremental, the IR's default).
  const char *keys[3] = {"I", "J", "K"};
  double off[3] = {a.c.x - pos_->x, a.c.y - pos_->y, a.c.z - pos_->z};
  for (int k = 0; k < 3; ++k)
    if (k != pl->axis) m.set(keys[k], num(off[k]));
  pos_ = p;
  return true;
}

bool ClPath::feed(SourceLoc l, double value, bool perRev) {
  if (value <= 0) return error(l, fmt::format("{} must be positive", words_.feed), "bad-feed");
  perRev_ = perRev;
  feed_ = value;
  feedSet_ = true;
  emitFeed(l);
  if (mode_ == "rapid") motion("linear", l);
  return true;
}

void ClPath::emitFeed(SourceLoc l) {
  emit(OpKind::Mode, l).set("feed_mode", Expr::symbol(perRev_ ? "per_rev" : "per_minute"));
  emit(OpKind::Feed, l).set("value", num(feed_));
}

void ClPath::spindleOn(SourceLoc l, double rpm, const char *dir) {
  emit(OpKind::Speed, l).set("value", num(rpm));
  spindle(l, dir);
}

void ClPath::spindle(SourceLoc l, const char *dir) { emit(OpKind::Spindle, l).set("dir", Expr::symbol(dir)); }

void ClPath::coolant(SourceLoc l, const char *which, bool on) {
  Op c(OpKind::Coolant, l);
  if (which) c.set(which, Expr::symbol(on ? "on" : "off"));
  else c.set("flood", Expr::symbol("off")).set("mist", Expr::symbol("off"));  // null: every coolant off
  body_->push_back(std::move(c));
}

bool ClPath::dwell(SourceLoc l, double seconds) {
  if (seconds < 0) return error(l, "a dwell must not be negative", "bad-dwell");
  emit(OpKind::Dwell, l).set("seconds", num(seconds));
  return true;
}

void ClPath::stop(SourceLoc l, const char *kind) { emit(OpKind::Stop, l).set("kind", Expr::symbol(kind)); }

void ClPath::end(SourceLoc l) {
  if (!ended_) stop(l, "end");
  ended_ = true;
}

void ClPath::cutterCompOff(SourceLoc l) { emit(OpKind::CutterComp, l).set("side", Expr::symbol("off")); }

}  // namespace ncc::cld
