// The APT records lowered to NC IR, one handler per major word (kTable). CL coordinates are
// absolute tool-tip positions, so the front end knows where the tool is after each move and
// checks arcs against it (docs/APT.md); what each kind of record becomes is ClPath's, shared
// with the ADEM CLData front end.
#include "frontend/cldata/CldFrontend.h"
#include "frontend/cldata/ClPath.h"
#include "frontend/cldata/ClStream.h"
#include "frontend/cldata/Records.h"
#include "ir/AptWords.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

namespace ncc::cld {

using ir::Expr;
using ir::Op;
using ir::OpKind;

namespace {

// Records that describe the job but cannot change the tool path: read with a warning.
const char *const kIgnored[] = {"PAINT", "DISPLY", "PLOT", "SEQNO", "INTOL", "OUTTOL", "TOLER", "CLEARP",
                                "TOOLNO", "PITCH", "LINTOL", "PPLOT", "TRACUT_OFF", "OPNAME", "TPRINT"};

class Lowerer : ClPath {
public:
  Lowerer(Diagnostics &d, ir::Region &body) : ClPath(d, body, {"FEDRAT", "CIRCLE"}) {}
  void start(SourceLoc l) { begin(l); }
  bool lower(const Record &r);
  bool finish();  // after the last record
  bool ended() const { return ended_; }
  using ClPath::setBody;

private:
  using Handler = bool (Lowerer::*)(const Record &);
  struct Entry {
    const char *word;
    Handler fn;
  };
  static const Entry kTable[];

  using ClPath::comment;
  // The numbers of a record; at least `min`, at most `max`.
  bool numbers(const Record &r, size_t min, size_t max, std::vector<double> &v, size_t from = 0);
  bool word(const Record &r, size_t i, std::string &out);
  bool moveTo(const Record &r, Vec3 p, bool rapid);
  bool cycleAt(const Record &r, Vec3 p);

  bool comment(const Record &r) { return comment(r.rest, r.loc), true; }
  bool keep(const Record &r) { return comment(fmt::format("{}/{}", r.word, r.rest), r.loc), true; }
  bool insert(const Record &r) {
    d_.warning(r.loc, "INSERT text is kept as a comment, not sent to the controller", "lenient-syntax");
    return comment(r);
  }
  bool partno(const Record &r) { return comment("PARTNO " + r.rest, r.loc), true; }
  bool units(const Record &r);
  bool multax(const Record &r);
  bool loadtl(const Record &r);
  bool cutter(const Record &r);
  bool from(const Record &r);
  bool go(const Record &r);
  bool godlta(const Record &r);
  bool rapid(const Record &r) { return rapidNext_ = true, true; }
  bool fedrat(const Record &r);
  bool spindl(const Record &r);
  bool coolnt(const Record &r);
  bool circle(const Record &r);
  bool cycle(const Record &r);
  bool cutcom(const Record &r);
  bool tlaxis(const Record &r);
  bool stop(const Record &r);
  bool delay(const Record &r);
  bool end(const Record &r) { return ClPath::end(r.loc), true; }
  bool msys(const Record &r);

  bool rapidNext_ = false;
  std::optional<ClArc> arc_;  // a CIRCLE waiting for the GOTO that ends its arc
  struct Cycle {
    const AptCycleWord *kind;
    double depth, feed, clear;
    SourceLoc loc;
  };
  std::optional<Cycle> cycle_;
};

const Lowerer::Entry Lowerer::kTable[] = {
    {"PARTNO", &Lowerer::partno}, {"MACHIN", &Lowerer::keep},   {"TLDATA", &Lowerer::keep},
    {"PPRINT", &Lowerer::comment}, {"INSERT", &Lowerer::insert}, {"UNITS", &Lowerer::units},
    {"MULTAX", &Lowerer::multax}, {"LOADTL", &Lowerer::loadtl}, {"CUTTER", &Lowerer::cutter},
    {"FROM", &Lowerer::from},     {"GOTO", &Lowerer::go},       {"GODLTA", &Lowerer::godlta},
    {"RAPID", &Lowerer::rapid},   {"FEDRAT", &Lowerer::fedrat}, {"SPINDL", &Lowerer::spindl},
    {"COOLNT", &Lowerer::coolnt}, {"CIRCLE", &Lowerer::circle}, {"CYCLE", &Lowerer::cycle},
    {"CUTCOM", &Lowerer::cutcom}, {"TLAXIS", &Lowerer::tlaxis}, {"STOP", &Lowerer::stop},
    {"OPSTOP", &Lowerer::stop},   {"DELAY", &Lowerer::delay},   {"END", &Lowerer::end},
    {"FINI", &Lowerer::end},      {"MSYS", &Lowerer::msys},
};

bool Lowerer::numbers(const Record &r, size_t min, size_t max, std::vector<double> &v, size_t from) {
  if (r.params.size() < from + min || r.params.size() > from + max)
    return error(r.loc, min == max ? fmt::format("{} takes {} numbers", r.word, min)
                                   : fmt::format("{} takes {} to {} numbers", r.word, min, max), "syntax");
  for (size_t i = from; i < r.params.size(); ++i) {
    if (!r.params[i].isNumber) return error(r.params[i].loc, fmt::format("a number expected, not '{}'", r.params[i].text), "syntax");
    v.push_back(r.params[i].value);
  }
  return true;
}

bool Lowerer::word(const Record &r, size_t i, std::string &out) {
  if (i >= r.params.size()) return error(r.loc, fmt::format("{} needs a word here", r.word), "syntax");
  out = r.params[i].text;
  return true;
}

bool Lowerer::units(const Record &r) {
  std::string w;
  if (!word(r, 0, w)) return false;
  if (w != "MM" && w != "INCHES") return error(r.params[0].loc, fmt::format("UNITS/{}: MM or INCHES expected", w));
  ClPath::units(w == "INCHES", r.loc);
  return true;
}

bool Lowerer::multax(const Record &r) {
  if (r.params.size() == 1 && r.params[0].text == "OFF") return true;
  return error(r.loc, "MULTAX: 5-axis tool vectors are not read yet (they need the machine's kinematics); only 3-axis CL data");
}

bool Lowerer::loadtl(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 1, 1, v)) return false;
  if (!isToolNumber(v[0]))
    return error(r.params[0].loc, fmt::format("LOADTL needs a tool number (a whole number from 1 to {})", kMaxToolNumber), "syntax");
  toolLoad((int)v[0], (int)v[0], r.loc);
  return true;
}

bool Lowerer::cutter(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 1, 7, v)) return false;
  comment(fmt::format("CUTTER/{}", r.rest), r.loc);  // the path is the tool tip's: kept (docs/APT.md)
  return true;
}

bool Lowerer::moveTo(const Record &r, Vec3 p, bool rapid) {
  if (arc_) {
    ClArc a = *arc_;
    arc_.reset();
    return arc(r.loc, a, p);
  }
  if (cycle_ && !rapid) return cycleAt(r, p);
  return line(r.loc, p, rapid);
}

bool Lowerer::from(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 3, 6, v)) return false;
  if (v.size() != 3) return error(r.loc, "FROM with a tool axis: only 3-axis CL data is read");
  return moveTo(r, {v[0], v[1], v[2]}, true);
}

bool Lowerer::go(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 3, 6, v)) return false;
  if (v.size() == 4 || v.size() == 5) return error(r.loc, "GOTO takes x,y,z or x,y,z,i,j,k", "syntax");
  if (v.size() == 6 && (std::fabs(v[3]) > 1e-9 || std::fabs(v[4]) > 1e-9 || v[5] <= 0))
    return error(r.params[3].loc, fmt::format("GOTO with the tool axis ({},{},{}): only a vertical tool axis (0,0,1) is read without the machine's kinematics",
                                              r.params[3].text, r.params[4].text, r.params[5].text));
  bool rapid = rapidNext_;
  rapidNext_ = false;
  return moveTo(r, {v[0], v[1], v[2]}, rapid);
}

bool Lowerer::godlta(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 1, 3, v)) return false;
  if (!pos_) return error(r.loc, "GODLTA before the tool position is known (no FROM or GOTO before it)");
  if (v.size() == 1) v = {0, 0, v[0]};  // GODLTA/d: along the tool axis
  if (v.size() != 3) return error(r.loc, "GODLTA takes dz or dx,dy,dz", "syntax");
  bool rapid = rapidNext_;
  rapidNext_ = false;
  return moveTo(r, {pos_->x + v[0], pos_->y + v[1], pos_->z + v[2]}, rapid);
}

bool Lowerer::fedrat(const Record &r) {
  // FEDRAT/f[,unit] or FEDRAT/unit,f (NX writes both orders)
  size_t n = 0;
  std::string unit;
  std::optional<double> f;
  for (auto &p : r.params) {
    if (p.isNumber) f = p.value, ++n;
    else unit = p.text;
  }
  if (n != 1 || r.params.size() > 2) return error(r.loc, "FEDRAT takes a feed and its unit", "syntax");
  const AptFeedUnit *u = aptFind(kAptFeedUnits, [&](auto &k) { return unit == k.word; });
  if (!unit.empty() && !u) return error(r.loc, fmt::format("FEDRAT unit {}: MMPM, IPM, MMPR or IPR expected", unit));
  if (u && u->inch != inch_)
    return error(r.loc, fmt::format("FEDRAT/{} in a program in {}: the feed's unit must be the program's", unit, inch_ ? "inches" : "mm"));
  return feed(r.loc, *f, u && u->perRev);
}

bool Lowerer::spindl(const Record &r) {
  if (r.params.size() == 1 && r.params[0].text == "OFF") {
    spindle(r.loc, "stop");
    return true;
  }
  std::optional<double> rpm;
  const char *dir = nullptr;
  for (auto &p : r.params) {
    if (p.isNumber && !rpm) rpm = p.value;
    else if (auto *d = aptFind(kAptSpindleDirs, [&](auto &k) { return p.text == k.word; })) dir = d->dir;
    else if (p.text != "RPM") return error(p.loc, fmt::format("SPINDL/{} is not read (rpm with CLW or CCLW, or OFF)", p.text));
  }
  if (!rpm || *rpm <= 0) return error(r.loc, "SPINDL needs a positive speed in rpm", "bad-speed");
  if (!dir) dir = "cw";  // ISO 4343: CLW is the default
  spindleOn(r.loc, *rpm, dir);
  return true;
}

bool Lowerer::coolnt(const Record &r) {
  std::string w;
  if (!word(r, 0, w)) return false;
  if (auto *c = aptFind(kAptCoolants, [&](auto &k) { return w == k.word; })) coolant(r.loc, c->coolant, c->coolant != nullptr);
  else return error(r.params[0].loc, fmt::format("COOLNT/{} is not read (ON, FLOOD, MIST or OFF)", w));
  return true;
}

bool Lowerer::circle(const Record &r) {
  std::vector<double> v;
  if (r.params.size() < 7) return error(r.loc, "CIRCLE takes xc,yc,zc,i,j,k,r", "syntax");
  for (size_t i = 0; i < 7; ++i) {
    if (!r.params[i].isNumber) return error(r.params[i].loc, fmt::format("a number expected, not '{}'", r.params[i].text), "syntax");
    v.push_back(r.params[i].value);
  }
  // Parameters after the radius (tolerances, the CAM's extra data) describe the same circle.
  if (arc_) return error(r.loc, "CIRCLE after a CIRCLE without the GOTO that ends it", "syntax");
  if (cycle_) return error(r.loc, "CIRCLE inside a CYCLE: CYCLE/OFF first", "syntax");
  if (!pos_) return error(r.loc, "CIRCLE before the tool position is known (no FROM or GOTO before it)");
  arc_ = ClArc{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], r.loc};
  return true;
}

bool Lowerer::cycle(const Record &r) {
  std::string w;
  if (!word(r, 0, w)) return false;
  if (w == "OFF") {
    if (cycle_ && feedSet_) emitFeed(r.loc);  // the FEDRAT before the cycle again
    cycle_.reset();
    return true;
  }
  const AptCycleWord *k = aptFind(kAptCycles, [&](auto &c) { return w == c.word; });
  if (!k) return error(r.params[0].loc, fmt::format("CYCLE/{} is not a cycle ncc reads", w));
  if (!k->entry)
    return error(r.params[0].loc, fmt::format("CYCLE/{}: the cycle library has no entry that does exactly the same", w));
  // CYCLE/DRILL|BORE, depth, MMPM|IPM, feed, clearance: nothing else (dwell, RAPTO, peck) is read.
  if (r.params.size() != 5 || !r.params[1].isNumber || r.params[2].isNumber || !r.params[3].isNumber || !r.params[4].isNumber)
    return error(r.loc, fmt::format("CYCLE/{} is read as CYCLE/{},depth,MMPM|IPM,feed,clearance", w, w), "syntax");
  const std::string &u = r.params[2].text;
  if (u != (inch_ ? "IPM" : "MMPM")) return error(r.params[2].loc, fmt::format("the cycle's feed unit {} is not the program's", u));
  if (r.params[1].value <= 0 || r.params[3].value <= 0 || r.params[4].value < 0)
    return error(r.loc, "the cycle's depth and feed must be positive, its clearance not negative", "cycle-invalid");
  cycle_ = Cycle{k, r.params[1].value, r.params[3].value, r.params[4].value, r.loc};
  return true;
}

// One hole: to the point above it in the plane at rapid, then the library cycle with the hole's
// top at z (ISO G81/G85 with G99: the R plane is the clearance above the top).
bool Lowerer::cycleAt(const Record &r, Vec3 p) {
  const Cycle &c = *cycle_;
  setPlane("xy", r.loc);  // the library cycles drill along the plane's normal: Z
  motion("rapid", r.loc);
  emit(OpKind::Move, r.loc).set("X", num(p.x)).set("Y", num(p.y));
  emit(OpKind::Mode, c.loc).set("feed_mode", Expr::symbol("per_minute"));
  emit(OpKind::Feed, c.loc).set("value", num(c.feed));
  Op &o = emit(OpKind::Cycle, r.loc);
  o.set("entry", Expr::string(c.kind->entry));
  o.set("a.RTP", num(p.z + c.clear)).set("a.RFP", num(p.z)).set("a.SDIS", num(c.clear)).set("a.DP", num(p.z - c.depth));
  if (std::string_view(c.kind->entry) == "sin.CYCLE85")
    o.set("a.FFR", num(c.feed)).set("a.RFF", num(c.feed));
  pos_ = Vec3{p.x, p.y, p.z + c.clear};  // CYCLE81/85 end at RTP
  return true;
}

bool Lowerer::cutcom(const Record &r) {
  if (r.params.size() == 1 && r.params[0].text == "OFF") {
    cutterCompOff(r.loc);
    return true;
  }
  return error(r.loc, "CUTCOM: only CUTCOM/OFF is read (the CL path is already the tool's)");
}

bool Lowerer::tlaxis(const Record &r) {
  std::vector<double> v;
  if (r.params.size() == 3 && numbers(r, 3, 3, v) && std::fabs(v[0]) < 1e-9 && std::fabs(v[1]) < 1e-9 && v[2] > 0) return true;
  return error(r.loc, "TLAXIS: only the vertical tool axis 0,0,1 is read without the machine's kinematics");
}

bool Lowerer::stop(const Record &r) {
  ClPath::stop(r.loc, r.word == "STOP" ? "program" : "optional");
  return true;
}

bool Lowerer::delay(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 1, 1, v)) return false;
  if (v[0] < 0) return error(r.params[0].loc, "DELAY must not be negative", "bad-dwell");
  return dwell(r.loc, v[0]);
}

bool Lowerer::msys(const Record &r) {
  std::vector<double> v;
  if (!numbers(r, 9, 9, v)) return false;
  const double id[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (int i = 0; i < 9; ++i)
    if (std::fabs(v[i] - id[i]) > 1e-9)
      return error(r.loc, "MSYS with a shifted or rotated system is not read yet (only the identity)");
  return true;
}

bool Lowerer::lower(const Record &r) {
  if (r.word.empty()) {
    if (r.loc.valid() && !r.rest.empty()) comment(r.rest, r.loc);
    return true;
  }
  if (ended_ && r.word != "FINI") {
    d_.warning(r.loc, fmt::format("{} after the program's end is not run", r.word), "code-after-end");
    return true;
  }
  const Entry *e = nullptr;
  for (auto &t : kTable)
    if (r.word == t.word) e = &t;
  if (e) {
    if (arc_ && r.word != "GOTO" && r.word != "PPRINT" && r.word != "FINI" && r.word != "END")
      return error(r.loc, fmt::format("{} between CIRCLE and the GOTO that ends its arc", r.word), "syntax");
    return (this->*(e->fn))(r);
  }
  bool ignored = false;
  for (auto *w : kIgnored) ignored = ignored || r.word == w;
  if (!ignored) return error(r.loc, fmt::format("{} is not a record ncc reads", r.word), "unknown-code");
  d_.warning(r.loc, fmt::format("{} does not change the tool path: skipped", r.word), "lenient-syntax");
  return true;
}

bool Lowerer::finish() {
  if (arc_) return error(arc_->loc, "CIRCLE without the GOTO that ends its arc", "syntax");
  return true;
}

bool reportRecordErrors(Diagnostics &d, const std::vector<RecordError> &errs) {
  for (auto &e : errs) d.error(e.loc, e.message, "syntax");
  return errs.empty();
}

}  // namespace

bool parseAptProgram(SourceManager &sm, uint32_t fileId, Diagnostics &diags, ir::Module &out) {
  ir::Function fn = beginClModule(sm, fileId, out);
  std::vector<RecordError> errs;
  auto recs = readRecords(sm.text(fileId), fileId, errs);
  bool ok = reportRecordErrors(diags, errs);
  Lowerer lw(diags, fn.body);
  lw.start({fileId, 1, 1});
  for (auto &r : recs) ok &= lw.lower(r);
  ok &= lw.finish();
  out.functions.push_back(std::move(fn));
  return ok;
}

std::unique_ptr<BlockStream> openAptStream(SourceManager &sm, uint32_t file, Diagnostics &diags) {
  return std::make_unique<ClStream<RecordReader, Record, RecordError, Lowerer>>(sm, file, diags, SourceLoc{file, 1, 1},
                                                                                reportRecordErrors, sm.text(file), file);
}

}  // namespace ncc::cld
