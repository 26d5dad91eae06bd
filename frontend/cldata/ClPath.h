// The lowering both CL front ends share (APT CL text, docs/APT.md; ADEM CLData, docs/CLDATA.md):
// the tool-path state a CL file implies (mode, feed, plane, where the tool is) and the NC IR
// each kind of CL record becomes. The readers differ in how a record spells its values; what
// a move, an arc, a feed or a tool load lowers to is decided here once.
#pragma once
#include "ir/Diagnostics.h"
#include "ir/NCIR.h"
#include "ir/SystemVars.h"

#include <cmath>
#include <optional>
#include <string>

namespace ncc::cld {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// A circle in CL terms: its centre, the axis the tool turns about (right-hand rule: +axis is
// counter-clockwise seen from its tip) and the radius.
struct ClArc {
  Vec3 c, axis;
  double r = 0;
  SourceLoc loc;  // where the circle was given (its start point is checked there)
};

// The module a CL file lowers to: dialect, name, and its one function "main" (returned, to be
// filled and then pushed into out.functions).
ir::Function beginClModule(SourceManager &sm, uint32_t file, ir::Module &out);

// A tool (or length offset) number the machine file can hold: a whole number from `from` to
// kMaxToolNumber. Checked before the value becomes an int (a larger double does not fit one).
inline bool isToolNumber(double v, int from = 1) { return v >= from && v <= kMaxToolNumber && v == std::floor(v); }

// How a front end names its records in the shared diagnostics.
struct ClWords {
  const char *feed;    // "FEDRAT", "[23]"
  const char *circle;  // "CIRCLE", "[183]"
};

class ClPath {
public:
  ClPath(Diagnostics &d, ir::Region &body, ClWords w) : d_(d), body_(&body), words_(w) {}
  virtual ~ClPath() = default;

protected:
  // What a message says of a location that has no line to show (a binary file's record).
  virtual std::string where(SourceLoc) const { return {}; }
  bool error(SourceLoc l, std::string msg, const char *rule = "unsupported-code") {
    d_.error(l, where(l) + msg, rule);
    return false;
  }
  void warning(SourceLoc l, std::string msg, const char *rule) { d_.warning(l, where(l) + msg, rule); }
  ir::Op &emit(ir::OpKind k, SourceLoc l) { return body_->emplace_back(k, l); }
  // Where the ops go from now on: a streamed front end lowers each chunk into the driver's region.
  void setBody(ir::Region &body) { body_ = &body; }
  static ir::ExprPtr num(double v) { return ir::Expr::number(v, ir::Type::Real); }

  // The program's start: mm, absolute, plane XY.
  void begin(SourceLoc l);
  void comment(std::string text, SourceLoc l);
  void setPlane(const char *p, SourceLoc l);
  void motion(const char *m, SourceLoc l);
  void units(bool inch, SourceLoc l);
  // Tool `t` into the spindle, its length offset `h` on: CL points are tool-tip points.
  void toolLoad(int t, int h, SourceLoc l);
  // A straight move to p (rapid or at the feed). A feed move needs a feed first.
  bool line(SourceLoc l, Vec3 p, bool rapid);
  // The arc from the current position to p on the circle `a`; both ends checked against its radius.
  bool arc(SourceLoc l, const ClArc &a, Vec3 p);
  bool feed(SourceLoc l, double value, bool perRev);
  void emitFeed(SourceLoc l);
  void spindleOn(SourceLoc l, double rpm, const char *dir);
  void spindle(SourceLoc l, const char *dir);
  void coolant(SourceLoc l, const char *which, bool on);
  bool dwell(SourceLoc l, double seconds);
  void stop(SourceLoc l, const char *kind);
  void end(SourceLoc l);  // the program's end, once
  void cutterCompOff(SourceLoc l);

  Diagnostics &d_;
  ir::Region *body_;
  ClWords words_;
  std::string mode_;
  std::string plane_ = "xy";
  bool inch_ = false;
  bool ended_ = false;
  bool feedSet_ = false;
  bool perRev_ = false;  // the last feed's mode and value
  double feed_ = 0;
  std::optional<Vec3> pos_;  // where the tool is, once a move said so
};

}  // namespace ncc::cld
