// ADEM CLData records lowered to NC IR: one table row per record code (kCodes) with its handler;
// its names and fields (seed 004 Appendix 2) are the code table of ir/AdemRecords.cpp, which the
// CLData writer (backends/emit/ClRecords.cpp) shares. What a move, a feed or a tool load becomes
// is ClPath's, shared with the APT front end (docs/CLDATA.md).
#include "ir/AdemRecords.h"
#include "frontend/cldata/CldFrontend.h"
#include "frontend/cldata/ClPath.h"
#include "frontend/cldata/ClStream.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace ncc::cld {

namespace {

class AdemLowerer : ClPath {
public:
  AdemLowerer(Diagnostics &d, ir::Region &body) : ClPath(d, body, {"feed record [23]", "[183]"}) {}
  // The program's start (before the first record), then each record in turn.
  void start(SourceLoc l) { begin(l); }
  bool lower(const AdemRecord &r);
  bool ended() const { return ended_; }
  bool finish() { return true; }  // nothing waits for a later record
  using ClPath::setBody;

  using Handler = bool (AdemLowerer::*)(const AdemRecord &);
  // The reader's half of a code's row; its names and fields (what both directions share) are
  // the row of the same code in ir/AdemRecords.cpp's layout table.
  struct Code {
    int code;
    Handler fn;
    const char *what;  // refuse/skip: why; step: the step's name
  };
  static const Code kCodes[];

private:
  // A binary file's record has no line: messages name it by its ordinal and byte offset.
  // Diagnostics are made while the record is lowered, so it is the current one.
  std::string where(SourceLoc l) const override {
    if (l.line != 0 || l.col == 0 || l.col != cur_->loc.col) return {};
    return fmt::format("record {} at byte {}: ", l.col, cur_->byte);
  }
  const Code *code_ = nullptr;  // the row of the record being lowered

  // A field that must be there (a number).
  bool need(const AdemRecord &r, int i, const char *what, double &v) {
    const AdemField *f = r.field(i);
    if (!f || f->isText) return error(r.loc, fmt::format("record [{}] needs FR[{}] ({})", r.code, i, what), "missing-word");
    v = f->num;
    return true;
  }
  double opt(const AdemRecord &r, int i, double dflt = 0) {
    const AdemField *f = r.field(i);
    return f && !f->isText ? f->num : dflt;
  }
  std::string text(const AdemRecord &r, int i) {
    const AdemField *f = r.field(i);
    return f ? (f->isText ? f->text : fmt::format("{}", f->num)) : std::string();
  }
  bool bad(const AdemRecord &r, int i, double v, const char *allowed) {
    const AdemField *f = r.field(i);
    return error(f ? f->loc : r.loc, fmt::format("FR[{}] of record [{}] is {}: {}", i, r.code, v, allowed));
  }
  // Texts joined with spaces, the empty ones left out.
  static std::string join(std::initializer_list<std::string> parts) {
    std::string o;
    for (auto &p : parts)
      if (!p.empty()) o += (o.empty() ? "" : " ") + p;
    return o;
  }

  bool refuse(const AdemRecord &r) { return error(r.loc, code_->what); }
  bool skip(const AdemRecord &r) {
    warning(r.loc, fmt::format("{}: skipped", code_->what), "lenient-syntax");
    return true;
  }
  bool program(const AdemRecord &r) {
    comment(join({"PROGRAM", text(r, 3), text(r, 4), text(r, 5), text(r, 6), text(r, 7), text(r, 8)}), r.loc);
    return true;
  }
  bool part(const AdemRecord &r) { return comment(join({"PART", text(r, 4), text(r, 5), text(r, 6)}), r.loc), true; }
  // The machine is --machine's, not the record's: kept for the translation.
  bool machine(const AdemRecord &r) { return comment(join({"MACHINE", text(r, 5)}), r.loc), true; }
  bool end(const AdemRecord &r) { return ClPath::end(r.loc), true; }
  bool stop(const AdemRecord &r) { return ClPath::stop(r.loc, r.code == 22 ? "program" : "optional"), true; }
  bool feed(const AdemRecord &r);
  bool rapid(const AdemRecord &) { return rapid_ = true, true; }
  bool spindle(const AdemRecord &r);
  bool coolant(const AdemRecord &r);
  bool dwell(const AdemRecord &r);
  bool tool(const AdemRecord &r);
  bool line(const AdemRecord &r);
  bool arc(const AdemRecord &r);
  bool step(const AdemRecord &r) { return comment(fmt::format("STEP {}", code_->what), r.loc), true; }
  bool clearance(const AdemRecord &r);
  bool insert(const AdemRecord &r) {
    warning(r.loc, "the NC insert [458] is kept as a comment, not sent to the controller", "lenient-syntax");
    return comment(text(r, 10), r.loc), true;
  }
  bool note(const AdemRecord &r) { return comment(text(r, 10), r.loc), true; }
  bool coolantOff(const AdemRecord &r) { return ClPath::coolant(r.loc, nullptr, false), true; }
  bool spindleOff(const AdemRecord &r) { return ClPath::spindle(r.loc, "stop"), true; }
  bool orient(const AdemRecord &r) { return ClPath::spindle(r.loc, "orient"), true; }
  bool lengthOn(const AdemRecord &r);
  bool lengthOff(const AdemRecord &r) {
    emit(ir::OpKind::ToolLength, r.loc).set("h", ir::Expr::number(0, ir::Type::Int));
    return true;
  }
  bool compOff(const AdemRecord &r) { return cutterCompOff(r.loc), true; }
  bool plane(const AdemRecord &r);
  bool transform(const AdemRecord &r);

  const AdemRecord *cur_ = nullptr;  // the record being lowered
  bool rapid_ = false;         // [25] until [23]
  int plane901_ = 0;           // [901] FR10: 0 XY, 1 YZ, 2 ZX
  int lengthH_ = -1;           // the length offset [35] chose
  bool dirWarned_ = false;
};

using L = AdemLowerer;

// The codes of seed 004 Appendix 1 the reader lowers (names and fields: ademLayout).
const AdemLowerer::Code AdemLowerer::kCodes[] = {
    {1, &L::program, nullptr},
    {2, &L::part, nullptr},
    {3, &L::machine, nullptr},
    {4, &L::end, nullptr},
    {6, &L::refuse, "the start point [6]: the manual gives no fields for it, so ncc cannot move there"},
    {22, &L::stop, nullptr},
    {23, &L::feed, nullptr},
    {24, &L::spindle, nullptr},
    {25, &L::rapid, nullptr},
    {26, &L::coolant, nullptr},
    {27, &L::dwell, nullptr},
    {28, &L::refuse, "the retract [28] goes where the machine passport puts the tool change, which ncc does not know"},
    {29, &L::refuse, "the re-clamp [29] (sheet punching) is not read"},
    {33, &L::stop, nullptr},
    {34, &L::refuse, "the table change [34] is not read"},
    {35, &L::tool, nullptr},
    {36, &L::refuse, "the cycle [36] is not read yet"},
    {39, &L::refuse, "the tool correction [39] is reserved to the adapter: the manual does not say what it does"},
    {40, &L::refuse, "the rotary positioning [40] is not read yet (it needs the machine's kinematics)"},
    {41, &L::refuse, "the multi-axis move [41] is not read yet (it needs the machine's kinematics)"},
    {45, &L::refuse, "the control point [45] is not read"},
    {94, &L::refuse, "the lathe thread [94] is not read"},
    {181, &L::line, nullptr},
    {182, &L::refuse, "the vector move [182]: the manual gives no fields for it, so ncc cannot move there"},
    {183, &L::arc, nullptr},
    {184, &L::refuse, "the vector arc [184] is not read yet (5-axis)"},
    {185, &L::refuse, "the second head's move [185] is not read"},
    {187, &L::refuse, "the second head's arc [187] is not read"},
    {189, &L::refuse, "the vector move [189] is not read yet (5-axis)"},
    {190, &L::refuse, "the curve move [190] is not read yet"},
    {191, &L::refuse, "the second head's curve [191] is not read"},
    {223, &L::refuse, "the subprogram call [223] is not read: the manual gives its repeat count (FR[4]) but no field naming the subprogram"},
    {227, &L::refuse, "the manual does not say what the record [227] does"},
    {252, &L::refuse, "subprograms [252] are not read: the manual gives the record no fields (no name; start and end alike)"},
    {301, &L::step, "mill"},
    {302, &L::step, "turn"},
    {303, &L::step, "bore (lathe)"},
    {304, &L::step, "tap"},
    {305, &L::step, "part off"},
    {306, &L::step, "punch"},
    {307, &L::step, "centre-drill"},
    {308, &L::step, "drill"},
    {309, &L::step, "ream"},
    {310, &L::step, "face"},
    {311, &L::step, "counterbore"},
    {312, &L::step, "engrave"},
    {314, &L::step, "bore (drilling)"},
    {315, &L::step, "cut"},
    {316, &L::step, "thread (lathe)"},
    {401, &L::skip, "the cycle-start point [401] is where the adapter's retracts go; it moves nothing by itself"},
    {402, &L::refuse, "the zone transform [402]: the manual gives no fields for it, so ncc cannot apply it"},
    {404, &L::refuse, "the zone's NC zero [404]: the manual gives no fields for it"},
    {405, &L::refuse, "the rotary-axes transform [405]: the manual gives no fields for it, so ncc cannot apply it"},
    {406, &L::refuse, "the initial machining point [406]: the manual gives no fields for it"},
    {451, &L::skip, "the safe position [451] is where the adapter's retracts go; it moves nothing by itself"},
    {452, &L::clearance, nullptr},
    {458, &L::insert, nullptr},
    {459, &L::refuse, "the user command [459] does what the postprocessor makes of it"},
    {460, &L::skip, "the user parameters [460] are data for the postprocessor"},
    {491, &L::skip, "the approximation tolerance [491] made the path; it does not change it"},
    {493, &L::refuse, "the turret [493] is not read"},
    {582, &L::note, nullptr},
    {700, &L::coolantOff, nullptr},
    {701, &L::spindleOff, nullptr},
    {703, &L::refuse, "the X length offset [703] is not read"},
    {704, &L::refuse, "the Y length offset [704] is not read"},
    {705, &L::lengthOn, nullptr},
    {706, &L::refuse, "the cutter radius compensation [706] is not read (its side is not in the record, and the CL path is already the tool's)"},
    {707, &L::refuse, "the X length offset [707] is not read"},
    {708, &L::refuse, "the Y length offset [708] is not read"},
    {709, &L::lengthOff, nullptr},
    {710, &L::compOff, nullptr},
    {711, &L::orient, nullptr},
    {713, &L::refuse, "subprograms [713] are not read: the manual gives the record no structure"},
    {799, &L::skip, "the record [799] is reserved (never translated)"},
    {900, &L::skip, "the depth of cut [900] is data for the postprocessor"},
    {901, &L::plane, nullptr},
    {902, &L::refuse, "the zone change [902]: the manual gives no fields for it"},
    {10123, &L::transform, nullptr},
};

const char *const kToolKinds[] = {"", "mill", "drill", "centre drill", "counterbore", "reamer", "tap", "turning tool",
                                  "punch", "wire", "laser", "torch"};

// kCodes is in code order.
const AdemLowerer::Code *findCode(int code) {
  auto end = std::end(AdemLowerer::kCodes);
  auto it = std::lower_bound(std::begin(AdemLowerer::kCodes), end, code, [](const AdemLowerer::Code &c, int k) { return c.code < k; });
  return it != end && it->code == code ? it : nullptr;
}

bool AdemLowerer::feed(const AdemRecord &r) {
  double unit, f;
  if (!need(r, 3, "the feed's unit", unit) || !need(r, 4, "the feed", f)) return false;
  if (unit != 1 && unit != 2) return bad(r, 3, unit, "1 (mm/min) or 2 (mm/rev) expected");
  rapid_ = false;
  return ClPath::feed(r.loc, f, unit == 2);
}

bool AdemLowerer::spindle(const AdemRecord &r) {
  double mode;
  if (!need(r, 3, "the spindle's mode", mode)) return false;
  if (mode == 1) return ClPath::spindle(r.loc, "stop"), true;
  if (mode == 3) return error(r.loc, "constant cutting speed [24] FR[3]=3 is not read (the manual does not say which diameter FR[8], FR[9] give)");
  if (mode == 4) return error(r.loc, "the oriented stop [24] FR[3]=4 is not read (the manual does not give the angle's unit)");
  if (mode != 0 && mode != 2) return bad(r, 3, mode, "0 (on), 1 (off), 2 (rpm), 3 (cutting speed) or 4 (oriented stop) expected");
  double rpm;
  if (!need(r, 4, "the speed", rpm)) return false;
  if (rpm <= 0) return error(r.loc, "the spindle speed must be positive", "bad-speed");
  // The direction is the adapter's variable DIR/SPIN, not a field of the record.
  if (!dirWarned_)
    warning(r.loc, "the record [24] has no direction (the manual lists none): the spindle turns clockwise", "missing-word");
  dirWarned_ = true;
  spindleOn(r.loc, rpm, "cw");
  return true;
}

bool AdemLowerer::coolant(const AdemRecord &r) {
  double on;
  if (!need(r, 3, "on or off", on)) return false;
  if (on == 0) return ClPath::coolant(r.loc, nullptr, false), true;
  if (on != 1) return bad(r, 3, on, "0 (off) or 1 (on) expected");
  double pipe = opt(r, 4);
  if (pipe != 0 && pipe != 1) return bad(r, 4, pipe, "the coolant line: only line 1 (flood) is read, which coolant another line carries is the machine's");
  ClPath::coolant(r.loc, "flood", true);
  return true;
}

bool AdemLowerer::dwell(const AdemRecord &r) {
  double kind, v;
  if (!need(r, 3, "seconds or revolutions", kind) || !need(r, 4, "the dwell", v)) return false;
  if (kind == 1) return error(r.loc, "a dwell in revolutions [27] FR[3]=1 is not read");
  if (kind != 0) return bad(r, 3, kind, "0 (seconds) or 1 (revolutions) expected");
  return ClPath::dwell(r.loc, v);
}

bool AdemLowerer::tool(const AdemRecord &r) {
  double pocket;
  if (!need(r, 4, "the pocket: `Позиция n` in the listing", pocket)) return false;
  if (!isToolNumber(pocket)) return bad(r, 4, pocket, fmt::format("the pocket, a whole number from 1 to {}", kMaxToolNumber).c_str());
  int h = (int)pocket;
  if (opt(r, 9) == 1) {  // the Z length offset's number, when the record gives one
    double z = opt(r, 10);
    if (!isToolNumber(z, 0)) return bad(r, 10, z, fmt::format("the Z offset's number, a whole number from 0 to {}", kMaxToolNumber).c_str());
    h = (int)z;
  }
  double kind = opt(r, 3);
  std::string what = kind >= 1 && kind <= 11 ? kToolKinds[(int)kind] : "";
  double g = opt(r, 19);
  if (g == 1 || g == 2) what = join({what, fmt::format("{} {}", g == 1 ? "R" : "D", opt(r, 20))});
  comment(join({fmt::format("TOOL {}", (int)pocket), what}), r.loc);
  toolLoad((int)pocket, h, r.loc);
  lengthH_ = h;
  return true;
}

bool AdemLowerer::line(const AdemRecord &r) {
  Vec3 p;
  if (!need(r, 3, "X", p.x) || !need(r, 4, "Y", p.y) || !need(r, 5, "Z", p.z)) return false;
  return ClPath::line(r.loc, p, rapid_);
}

bool AdemLowerer::arc(const AdemRecord &r) {
  Vec3 p;
  double cx, cy, rad;
  if (!need(r, 3, "X", p.x) || !need(r, 4, "Y", p.y) || !need(r, 5, "Z", p.z) || !need(r, 6, "the centre's X", cx) ||
      !need(r, 7, "the centre's Y", cy) || !need(r, 8, "the signed radius", rad))
    return false;
  double pl = opt(r, 9);
  if (pl != 0 && pl != 1 && pl != 2 && pl != 3) return bad(r, 9, pl, "0 (current), 1 (XY), 2 (YZ) or 3 (ZX) expected");
  if (pl == 0 && plane901_ != 0) pl = plane901_ == 1 ? 2 : 3;
  if (pl != 0 && pl != 1)
    return error(r.loc, "an arc [183] in the YZ or ZX plane: the manual does not say which coordinates FR[6] and FR[7] then hold");
  if (rad == 0) return bad(r, 8, rad, "the radius, negative clockwise, positive counter-clockwise");
  if (rapid_) return error(r.loc, "an arc [183] in rapid mode ([25] without a [23] after it)");
  if (!pos_) return error(r.loc, "an arc [183] before the tool position is known (no move before it)");
  // Clockwise seen from +Z is a turn about -Z; the centre's Z is the start's (only X, Y are given).
  ClArc a{{cx, cy, pos_->z}, {0, 0, rad > 0 ? 1.0 : -1.0}, std::fabs(rad), r.loc};
  return ClPath::arc(r.loc, a, p);
}

bool AdemLowerer::clearance(const AdemRecord &r) {
  double k;
  if (!need(r, 10, "the clearance plane's kind", k)) return false;
  if (k == 0 || k == 10) return true;  // off, or its modality off: nothing to route
  return error(r.loc, "the clearance plane [452]: the adapter routes rapid moves through it, ncc does not");
}

bool AdemLowerer::lengthOn(const AdemRecord &r) {
  if (lengthH_ < 0) return error(r.loc, "the Z length offset [705] before any tool load [35]: which offset is not known");
  emit(ir::OpKind::ToolLength, r.loc).set("h", ir::Expr::number(lengthH_, ir::Type::Int));
  return true;
}

bool AdemLowerer::plane(const AdemRecord &r) {
  double k;
  if (!need(r, 10, "the plane", k)) return false;
  if (k != 0 && k != 1 && k != 2) return bad(r, 10, k, "0 (XY), 1 (YZ) or 2 (ZX) expected");
  plane901_ = (int)k;
  return true;
}

bool AdemLowerer::transform(const AdemRecord &r) {
  // Only the identity: the manual's labels leave rows and columns of the matrix ambiguous.
  const double id[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  for (int i = 0; i < 12; ++i)
    if (std::fabs(opt(r, 3 + i, i % 4 == 0 && i < 9 ? 1 : 0) - id[i]) > 1e-9)
      return error(r.loc, "the feature-CS transform [10123] is read only as the identity (ncc does not shift or rotate CL data yet)");
  return true;
}

bool AdemLowerer::lower(const AdemRecord &r) {
  cur_ = &r;
  if (ended_) {
    warning(r.loc, fmt::format("record [{}] after the program's end [4] is not run", r.code), "code-after-end");
    return true;
  }
  if (!code_ || code_->code != r.code) code_ = findCode(r.code);
  if (!code_) {
    // Motion codes are 181-191: an unknown one may move the tool, the others are skipped.
    if (r.code >= 180 && r.code < 200) return error(r.loc, fmt::format("record [{}] is a motion code ncc does not know", r.code), "unknown-code");
    warning(r.loc, fmt::format("record [{}] is not in the manual's catalogue: skipped", r.code), "unknown-code");
    return true;
  }
  return (this->*(code_->fn))(r);
}

// Whether a listing is UTF-8 (else CP866) needs the whole file: looked at a megabyte at a time
// (cut before a byte that starts a character), each piece's pages released after it; -1 for a
// binary file.
int listingIsUtf8(SourceManager &sm, uint32_t file) {
  std::string_view t = sm.text(file);
  if (looksLikeAdemBinary(t)) return -1;
  constexpr size_t kPiece = 1 << 20;
  bool ok = true;
  for (size_t b = 0; ok && b < t.size();) {
    size_t e = std::min(t.size(), b + kPiece);
    while (e < t.size() && ((unsigned char)t[e] & 0xC0) == 0x80) ++e;
    ok = ademIsUtf8(t.substr(b, e - b));
    sm.released(file, e);
    b = e;
  }
  return ok;
}

}  // namespace

bool parseAdemProgram(SourceManager &sm, uint32_t fileId, Diagnostics &diags, ir::Module &out) {
  ir::Function fn = beginClModule(sm, fileId, out);
  std::string_view text = sm.text(fileId);
  std::vector<AdemError> errs;
  bool binary = looksLikeAdemBinary(text);
  auto recs = binary ? readAdemBinary(text, fileId, errs) : readAdemListing(text, fileId, errs);
  bool ok = reportAdemErrors(diags, errs);
  AdemLowerer lw(diags, fn.body);
  lw.start(binary ? SourceLoc{} : SourceLoc{fileId, 1, 1});
  for (auto &r : recs) ok &= lw.lower(r);
  out.functions.push_back(std::move(fn));
  return ok;
}

std::unique_ptr<BlockStream> openAdemStream(SourceManager &sm, uint32_t file, Diagnostics &diags) {
  const SourceLoc start = looksLikeAdemBinary(sm.text(file)) ? SourceLoc{} : SourceLoc{file, 1, 1};
  return std::make_unique<ClStream<AdemReader, AdemRecord, AdemError, AdemLowerer>>(
      sm, file, diags, start, reportAdemErrors, sm.text(file), file, listingIsUtf8(sm, file));
}

}  // namespace ncc::cld
