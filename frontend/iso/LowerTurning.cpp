// The ISO lowering of the lathe's multiple repetitive cycles G70-G73 (808D manual 1.5.1, spec
// seed001 3.2) onto contour capture (docs/IR.md `contour`):
//
//   G71 U<depth> R<retract>            contour action=data use=rough_z U R
//   G71 P<ns> Q<nf> U<du> W<dw> F S T  (feed, speed, tool as usual, then)
//                                      contour action=begin
//                                      call_section from="N<ns>" to="N<nf>_to"
//                                      contour action=end use=rough_z U W
//                                      goto label="N<nf>_end"
//
// G72 (rough_x, W<depth> R), G73 (pattern, U W R: relief and divisions) alike; G70 P Q is
// use=finish without the goto. The blocks ns..nf run inside the capture; after G71-G73 the
// program goes on after block nf (the contour was only read), after G70 with the next block.
// placeContourLabels puts the labels (N<ns> before block ns, N<nf>_to after block nf's block op,
// N<nf>_end after its ops) and checks what the contour blocks may hold.
#include "frontend/iso/LowerBlock.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace ncc::iso {

namespace {
const char *const kUses[] = {"finish", "rough_z", "rough_x", "pattern"};  // G70..G73
// The first block's words (G71 U R, G72 W R, G73 U W R); G70 has none.
const char *const kDataWords[] = {"", "UR", "WR", "UWR"};
}  // namespace

bool BlockLowerer::Block::turnCycle() {
  if (!nonModal || nonModal->kind != GKind::TurnCycle) return true;
  if (L.flavour_ == Flavour::RS274) return rs274TurnCycle();
  const SourceLoc loc = gloc(GGroup::NonModal);
  const int code = nonModal->arg;
  const char *use = kUses[code - 70];
  axesTaken = true;  // U W are the cycle's; stray X Z are unused words
  if (G(GGroup::Motion)) {
    L.diags_->error(gloc(GGroup::Motion), fmt::format("G{} must not share its block with {}", code, gName(G(GGroup::Motion)->code10)),
                   "modal-group-conflict");
    return false;
  }
  if (!bw.has('P') && !bw.has('Q')) {
    if (code == 70) {
      L.diags_->error(loc, "G70 needs P and Q (the first and last contour block)", "missing-word");
      return false;
    }
    Op &op = emit(OpKind::Contour, loc);
    op.set("action", Expr::symbol("data", loc));
    op.set("use", Expr::symbol(use, loc));
    for (const char *w = kDataWords[code - 70]; *w; ++w) {
      if (!bw.has(*w)) {
        L.diags_->error(loc, fmt::format("G{} {} needs {} (the cycle data block)", code, kDataWords[code - 70], *w),
                       "missing-word");
        return false;
      }
      // G73 R is a count (divisions); the others lengths.
      add(op, *w, take(*w, code == 73 && *w == 'R' ? Scale::None : Scale::Linear));
    }
    return true;
  }
  long long range[2];
  for (int i = 0; i < 2; ++i) {
    char c = "PQ"[i];
    IsoWord *w = bw.get(c);
    if (!w) {
      L.diags_->error(loc, fmt::format("G{} needs P and Q (the first and last contour block)", code), "missing-word");
      return false;
    }
    if (w->expr || w->value < 0 || w->value != std::floor(w->value) || w->value > 99999999) {
      L.diags_->error(w->loc, fmt::format("G{} {} must be a constant block number", code, c), "syntax");
      return false;
    }
    bw.used |= Words::bit(c);
    range[i] = (long long)w->value;
  }
  if (!callAllowed(loc, fmt::format("G{}", code))) return false;
  emit(OpKind::Contour, loc).set("action", Expr::symbol("begin", loc));
  Op &sec = emit(OpKind::CallSection, loc);
  sec.set("from", Expr::string(fmt::format("N{}", range[0]), loc));
  sec.set("to", Expr::string(fmt::format("N{}_to", range[1]), loc));
  Op &end = emit(OpKind::Contour, loc);
  end.set("action", Expr::symbol("end", loc));
  end.set("use", Expr::symbol(use, loc));
  if (code != 70)
    for (char c : std::string_view("UW"))
      if (bw.has(c)) add(end, c, take(c, Scale::Linear));
  if (code != 70) emit(OpKind::Goto, loc).set("label", Expr::string(fmt::format("N{}_end", range[1]), loc));
  return true;
}

// LinuxCNC's G70/G71/G72 (2.9 documentation "G70 Finishing Cycle", "G71 G72 Roughing Cycles"):
//   G7x Q<sub> X Z [D I R U W] [E P]   mode motion=rapid; move X Z (rs274 goes to X Z first)
//                                      contour action=begin use=(as at end)
//                                      call callee="O<sub>" frame=new
//                                      contour action=end use=rs274_finish|rs274_rough_z|rs274_rough_x
//                                        D E I P R U W (type=1/2 for G7x.1/G7x.2)
//                                      mode motion=cycle_off
// The subroutine is the profile, run from X Z into the capture; the executor cuts it as rs274
// does (runtime/cycles/TurningRs274.h). rs274 leaves the mode of its last move (G0, G1, G2 or
// G3) in force afterwards; ncc leaves none, so axis words after the cycle need a motion code.
bool BlockLowerer::Block::rs274TurnCycle() {
  const SourceLoc loc = gloc(GGroup::NonModal);
  const int code10 = nonModal->arg;
  const std::string name = gName(code10);
  axesTaken = true;
  if (G(GGroup::Motion)) {
    L.diags_->error(gloc(GGroup::Motion), fmt::format("{} must not share its block with {}", name, gName(G(GGroup::Motion)->code10)),
                   "modal-group-conflict");
    return false;
  }
  IsoWord *q = bw.get('Q');
  if (!q) {
    L.diags_->error(loc, fmt::format("{} requires a Q word (the profile's subroutine number)", name), "missing-word");
    return false;
  }
  if (!q->expr && (q->value < 0 || q->value != std::floor(q->value) || q->value > 99999999)) {
    L.diags_->error(q->loc, fmt::format("{} Q must be a subroutine number", name), "syntax");
    return false;
  }
  bw.used |= Words::bit('Q');
  if (!callAllowed(loc, name)) return false;
  add(emit(OpKind::Mode, loc), "motion", Expr::symbol(modeValueInfo(ModeValue::Rapid).name, loc));
  if (bw.hasAny("XZ")) axisWords(emit(OpKind::Move, loc), "XZ");
  static const char *const kUse[] = {"rs274_finish", "rs274_rough_z", "rs274_rough_x"};
  Op &begin = emit(OpKind::Contour, loc);
  begin.set("action", Expr::symbol("begin", loc));
  begin.set("use", Expr::symbol(kUse[code10 / 10 - 70], loc));
  Op &call = emit(OpKind::Call, loc);
  if (q->expr) {  // Q[...]: the number is computed, its sub O<n> found when the call runs
    call.set("callee", q->expr->clone());
  } else {
    const std::string callee = fmt::format("O{}", (long long)q->value);
    L.calls.push_back({callee, loc});
    call.set("callee", Expr::string(callee, loc));
  }
  call.set("frame", Expr::symbol("new", loc));
  Op &end = emit(OpKind::Contour, loc);
  end.set("action", Expr::symbol("end", loc));
  end.set("use", Expr::symbol(kUse[code10 / 10 - 70], loc));
  // G70: D E the first and last pass's distance, P the passes; G71/G72: D the finishing distance,
  // I the depth of cut, R the retract, U W a shift. rs274 checks I > 0 for G70 too.
  for (char c : std::string_view(code10 == 700 ? "DEIP" : "DIR"))
    if (bw.has(c)) add(end, c, take(c, c == 'P' ? Scale::None : Scale::Linear));
  if (code10 % 10) end.set("type", Expr::number(code10 % 10, ir::Type::Int, loc));
  add(emit(OpKind::Mode, loc), "motion", Expr::symbol(modeValueInfo(ModeValue::CycleOff).name, loc));
  L.motion_ = ModeValue::CycleOff;
  return true;
}

namespace {

// What the 808D forbids in the contour blocks (manual 1.5.1 "Restrictions" 3): one-shot G codes
// other than G04, group-01 codes other than G00-G03, group 06 (inch/metric).
const char *forbiddenContourOp(const Op &op) {
  switch (op.kind) {
  case OpKind::Home: return "a reference point return (G28/G30)";
  case OpKind::MachineMove: return "G53";
  case OpKind::SetOffset: return "a coordinate or offset setting (G10/G50)";
  case OpKind::Frame: return "G52";
  case OpKind::Contour: return "a contour cycle (G70-G73)";
  case OpKind::Stop:
    if (const Expr *k = op.get("kind"); k && (k->str == "end" || k->str == "end_rewind")) return "a program end (M2/M30)";
    return nullptr;
  case OpKind::Mode:
    if (op.get("units")) return "G20/G21";
    if (const Expr *m = op.get("motion"))
      if (m->str != "rapid" && m->str != "linear" && m->str != "arc_cw" && m->str != "arc_ccw") return "a motion code other than G00-G03";
    return nullptr;
  case OpKind::Call:
    if (const Expr *f = op.get("frame"); f && f->str == "new") return "G65";
    return nullptr;
  default: return nullptr;
  }
}

bool checkContourOp(const Op &op, Diagnostics &diags) {
  bool ok = true;
  if (const char *what = forbiddenContourOp(op)) {
    diags.error(op.loc, fmt::format("{} is not allowed in the contour blocks of G70-G73", what), "contour-invalid");
    ok = false;
  }
  for (auto &sub : op.regions)
    for (auto &inner : sub) ok &= checkContourOp(inner, diags);
  return ok;
}

// G71/G72 type II (808D manual 1.5.1.2): the first contour block names both axes (X or U and Z
// or W; `W0` asks for type II without moving Z). The consumer learns it from type=2.
void markTypeII(Region &body, size_t first, Op *end) {
  const ir::Expr *use = end ? end->get("use") : nullptr;
  if (!use || (use->str != "rough_z" && use->str != "rough_x")) return;
  for (size_t i = first + 1; i < body.size() && body[i].kind != OpKind::Block; ++i)
    if (body[i].kind == OpKind::Move) {
      if (body[i].get("X") && body[i].get("Z")) end->set("type", Expr::number(2, ir::Type::Int, end->loc));
      return;
    }
}

long long blockNumber(const Op &op) {
  const Expr *n = op.kind == OpKind::Block ? op.get("n") : nullptr;
  return n ? (long long)n->num : -1;
}

}  // namespace

// G74/G75 (808D manual 1.5.1, L3660-3716): `G74 R<e>` and `G74 X(U) Z(W) P<Δi> Q<Δk> R<Δd> F`.
// P and Q are least input increments without a decimal point in every decimal mode (L3842-3843);
// R is a length. Whether R is e or Δd depends on the end-point words: the executor decides.
void BlockLowerer::Block::peckWords(Op &op) {
  for (char c : std::string_view("PQR"))
    if (bw.has(c)) add(op, c, take(c, c == 'R' ? Scale::Linear : Scale::Increment));
}

bool placeContourLabels(ir::Function &f, Diagnostics &diags) {
  // The ranges the function's contour cycles name (top level only: they follow the program).
  struct Range {
    long long from, to;
    SourceLoc loc;
    Op *end;  // the contour end op after the call_section
  };
  std::vector<Range> ranges;
  for (size_t i = 0; i < f.body.size(); ++i)
    if (Op &op = f.body[i]; op.kind == OpKind::CallSection)
      ranges.push_back({std::stoll(op.get("from")->str.substr(1)), std::stoll(op.get("to")->str.substr(1)), op.loc,
                        i + 1 < f.body.size() && f.body[i + 1].kind == OpKind::Contour ? &f.body[i + 1] : nullptr});  // N<n>, N<n>_to
  if (ranges.empty()) return true;
  Region &body = f.body;
  std::map<long long, size_t> at;  // block number -> index of its block op (the first one)
  for (size_t i = 0; i < body.size(); ++i)
    if (long long n = blockNumber(body[i]); n >= 0) at.emplace(n, i);
  bool ok = true;
  // Labels to insert before op index: (index, name), later sorted from the back.
  std::vector<std::pair<size_t, std::string>> labels;
  for (auto &r : ranges) {
    auto a = at.find(r.from), b = at.find(r.to);
    for (auto [it, n] : {std::pair{a, r.from}, std::pair{b, r.to}})
      if (it == at.end()) {
        diags.error(r.loc, fmt::format("there is no block N{} in this program (outside control structures)", n),
                    "missing-block");
        ok = false;
      }
    if (a == at.end() || b == at.end()) continue;
    if (a->second > b->second) {
      diags.error(r.loc, fmt::format("the contour block N{} comes after N{}", r.from, r.to), "contour-invalid");
      ok = false;
      continue;
    }
    size_t endAt = b->second + 1;
    while (endAt < body.size() && body[endAt].kind != OpKind::Block) ++endAt;
    for (size_t i = a->second; i < endAt; ++i) ok &= checkContourOp(body[i], diags);
    markTypeII(body, a->second, r.end);
    labels.push_back({a->second, fmt::format("N{}", r.from)});
    labels.push_back({b->second + 1, fmt::format("N{}_to", r.to)});  // a section's last block starts at its label
    labels.push_back({endAt, fmt::format("N{}_end", r.to)});
  }
  std::sort(labels.begin(), labels.end(), [](auto &x, auto &y) { return x.first > y.first || (x.first == y.first && x.second > y.second); });
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  for (auto &[i, name] : labels) {
    SourceLoc loc = i < body.size() ? body[i].loc : f.loc;
    Op label(OpKind::Label, loc);
    label.set("name", Expr::string(name, loc));
    body.insert(body.begin() + (long)i, std::move(label));
  }
  return ok;
}

}  // namespace ncc::iso

namespace ncc::iso {

// The spindle speed words: S, G96/G97 (group 02) and the spindle-speed limit, as one `speed` op
// (docs/IR.md): `speed value=S`, `speed mode=css value=S limit=?` (G96), `speed mode=rpm
// value=S?` (G97), `speed limit=L` (808D/Fanuc lathe G50 S in system A, G92 S in B: modal).
// LinuxCNC's G96 takes its limit from D, for this G96 only (no D: none, limit=0); its G97 without
// S after G96 keeps the surface speed control going, which ncc does not model (after_css=error).
bool BlockLowerer::Block::speedOp() {
  const bool rs274 = L.flavour_ == Flavour::RS274;
  const GCodeInfo *mode = G(GGroup::Spindle);
  const bool limitBlock = !rs274 && nonModal && nonModal->kind == GKind::SetOffset && nonModal->arg == 1 && bw.has('S');
  auto positive = [&](IsoWord *w, const char *what) {
    if (w->expr || w->value > 0) return true;
    L.diags_->error(w->loc, fmt::format("{} must be greater than 0", what), "bad-speed");
    return false;
  };
  if (limitBlock) {
    IsoWord *s = bw.get('S');
    if (!L.lathe_) {
      L.diags_->error(s->loc, fmt::format("{} S (spindle speed limit) needs a lathe (machine kind = \"lathe\")", gName(nonModal->code10)),
                     "unsupported-code");
      return false;
    }
    if (!positive(s, fmt::format("{} S (the spindle speed limit)", gName(nonModal->code10)).c_str())) return false;
    emit(OpKind::Speed, s->loc).set("limit", take('S', Scale::None));
  }
  if (!mode) {
    if (bw.has('S') && !limitBlock) emit(OpKind::Speed, bw.get('S')->loc).set("value", take('S', Scale::None));
    return true;
  }
  const SourceLoc loc = gloc(GGroup::Spindle);
  const bool css = mode->arg == 2;
  if (css && !rs274 && !L.lathe_) {
    L.diags_->error(loc, "G96 (constant surface speed) needs a lathe (machine kind = \"lathe\"): a milling spindle has no "
                        "radius to keep the speed at", "unsupported-code");
    return false;
  }
  if (css && (!bw.has('S') || limitBlock)) {
    L.diags_->error(loc, "G96 needs S (the surface speed, m/min or ft/min)", "missing-word");
    return false;
  }
  Op &op = emit(OpKind::Speed, loc);
  op.set("mode", Expr::symbol(css ? "css" : "rpm", loc));
  if (bw.has('S') && !limitBlock) op.set("value", take('S', Scale::None));
  if (rs274 && css) {
    IsoWord *d = G(GGroup::CutterComp) ? nullptr : bw.get('D');
    if (d && !positive(d, "G96 D (the spindle speed limit)")) return false;
    op.set("limit", d ? take('D', Scale::None) : Expr::number(0, ir::Type::Int, loc));
  }
  if (rs274 && !css) op.set("after_css", Expr::symbol("error", loc));
  return true;
}


// A lathe's T word (Fanuc T, two digits tool, two digits offset): T0101 selects and mounts tool 1
// and applies offset 1 (the X and Z offsets of tool 1's edge) at once, without G43; T0100
// cancels the offset.
bool BlockLowerer::Block::latheTool() {
  IsoWord *t = bw.get('T');
  if (t->expr || t->value < 0 || t->value != std::floor(t->value) || t->value > 9999) {
    L.diags_->error(t->loc, "a lathe T word is a constant tool and offset number T<tt><oo> (T0101)", "bad-number");
    return false;
  }
  bw.used |= Words::bit('T');
  auto n = [&](int v) { return Expr::number(v, ir::Type::Int, t->loc); };
  emit(OpKind::ToolSelect, t->loc).set("value", n((int)t->value / 100));
  emit(OpKind::ToolChange, t->loc);
  emit(OpKind::ToolLength, t->loc).set("h", n((int)t->value % 100));
  return true;
}

// G-code system A of a lathe: U and W are the incremental X and Z (`ic`); X with U (Z with W) is
// an error.
bool BlockLowerer::Block::latheAxisWords(Op &op) {
  if (L.system_ != 'A') {  // systems B and C program increments with G91
    for (char c : std::string_view("UW"))
      if (bw.has(c)) {
        L.diags_->error(bw.get(c)->loc,
                       fmt::format("{} in G-code system {}: the 808D manual does not say it is an increment (use G91)", c, L.system_),
                       "unsupported-code");
        return false;
      }
    return true;
  }
  std::string ic;
  for (auto [abs, inc] : {std::pair{'X', 'U'}, std::pair{'Z', 'W'}}) {
    if (bw.has(abs) && bw.has(inc)) {
      L.diags_->error(bw.get(inc)->loc, fmt::format("{} and {} in one block ({} is the incremental {})", abs, inc, inc, abs),
                     "duplicate-word");
      return false;
    }
    if (bw.has(inc)) add(op, abs, take(inc, Scale::Linear)), ic += abs;
  }
  if (!ic.empty()) op.set("ic", Expr::symbol(ic, op.loc));
  return true;
}

}  // namespace ncc::iso
