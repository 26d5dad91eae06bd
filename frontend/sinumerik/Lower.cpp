// A block's machine words to NC IR ops, in one fixed order (the order the controller applies
// them within a block): F, S, T, M6, D, spindle, coolant, modes, cutter compensation, work
// offset, dwell, the move, then program stops and returns.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

namespace ncc::sin {

using ir::Expr;
using ir::ExprPtr;
using ir::Op;
using ir::OpKind;

namespace {
// M functions with a meaning of their own; every other M is an aux function.
enum class MAct : uint8_t { Stop, End, Return, ToolChange, Spindle, Coolant };
struct MRow {
  int code;
  MAct act;
  const char *arg;  // stop kind, spindle dir, coolant key=value
};
const MRow kM[] = {
    {0, MAct::Stop, "program"}, {1, MAct::Stop, "optional"}, {2, MAct::End, "end"}, {30, MAct::End, "end_rewind"},
    {17, MAct::Return, ""},     {6, MAct::ToolChange, ""},  {3, MAct::Spindle, "cw"}, {4, MAct::Spindle, "ccw"},
    {5, MAct::Spindle, "stop"}, {7, MAct::Coolant, "mist"}, {8, MAct::Coolant, "flood"}, {9, MAct::Coolant, "off"},
};
const MRow *findM(int code) {
  for (auto &m : kM)
    if (m.code == code) return &m;
  return nullptr;
}
}  // namespace

bool BlockParser::lowerWords() {
  ir::Region &out = f_.cur();
  auto word = [&](std::string_view a) -> Word * {
    for (auto &w : words_)
      if (w.addr == a) return &w;
    return nullptr;
  };
  auto take = [&](std::string_view a) -> ExprPtr {
    Word *w = word(a);
    if (!w) return nullptr;
    w->addr.clear();
    return std::move(w->value);
  };
  const GInfo *dwell = nullptr, *offset = nullptr, *machine = nullptr, *comp = nullptr, *pole = nullptr;
  const GInfo *spindleMode = nullptr, *smoothing = nullptr, *floatTap = nullptr;
  SourceLoc gLoc[2];  // where G641… and G63 stand
  Op mode(OpKind::Mode, loc(t_[0]));
  for (auto &[g, l] : gcodes_) {
    switch (g.act) {
    case GAct::Mode:
    case GAct::Units: {
      ModeGroup grp = modeValueInfo(g.mode).group;
      mode.set(modeGroupName(grp), Expr::symbol(modeValueInfo(g.mode).name));
      mode.loc = l;
      f_.followMode(g.mode);
      if (g.act == GAct::Units) f_.noteUnits(g.code->name);  // the contour tables' unit code (Contour.cpp)
      if (grp == ModeGroup::Motion) f_.leadChange = g.arg;  // G34/G35: the lead's change
      break;
    }
    case GAct::Pole: pole = &g; break;
    case GAct::Dwell: dwell = &g; break;
    case GAct::WorkOffset: offset = &g; break;
    case GAct::MachineCoord: machine = &g; break;
    case GAct::CutterComp: comp = &g; break;
    case GAct::SpindleMode: spindleMode = &g; break;
    case GAct::Smoothing: smoothing = &g, gLoc[0] = l; break;
    case GAct::FloatTap: floatTap = &g, gLoc[1] = l; break;
    default: break;
    }
  }
  SourceLoc bl = loc(t_[0]);
  if (pole) return lowerPole(*pole, out);
  if (dwell) {
    // G4 F<seconds> or G4 S<revolutions>, alone in its block (L: G4 programming).
    for (auto &w : words_)
      if (!w.addr.empty() && w.addr != "F" && w.addr != "S")
        return fail(t_[0], fmt::format("G4 must stand alone in its block (found {})", w.addr), "dwell-with-motion");
    if (word("F") && word("S")) return fail(t_[0], "G4 takes F<seconds> or S<revolutions>, not both", "dwell-with-motion");
    Op d(OpKind::Dwell, bl);
    if (ExprPtr s = take("S")) {
      // S revolutions of the spindle at its programmed speed: 60·S / rpm seconds. A stopped
      // spindle never turns them: an alarm, not a guessed time.
      auto sys = [&](const char *n) { return Expr::var(ir::VarSpace::System, n, nullptr, bl); };
      out.push_back(spindleAlarm(true, "G4 S (a dwell in spindle revolutions) needs the spindle turning (S and M3/M4)"));
      d.set("seconds", Expr::binary(ir::OpCode::Div, Expr::binary(ir::OpCode::Mul, Expr::number(60, ir::Type::Int), std::move(s), bl),
                                    sys("_rpm"), bl));
    } else if (ExprPtr f = take("F")) {
      d.set("seconds", std::move(f));
    } else {
      return fail(t_[0], "G4 needs F<seconds> or S<revolutions>", "missing-word");
    }
    out.push_back(std::move(d));
  }
  // G34/G35: F is the lead's change per revolution, a word of the thread move, not a feed.
  ExprPtr leadChange;
  bool axisWord = false;
  for (auto &w : words_) axisWord = axisWord || (!w.addr.empty() && findAddress(w.addr)->kind == Addr::Axis);
  if (f_.motion == ModeValue::ThreadLead && f_.leadChange != 0 && (axisWord || word("F"))) {
    leadChange = take("F");
    if (!leadChange) return fail(t_[0], "G34/G35 needs F, the lead's change per revolution", "missing-word");
    if (f_.leadChange < 0) leadChange = Expr::unary(ir::OpCode::Neg, std::move(leadChange), bl);
  }
  bool hadFeedOrSpeed = word("F") || word("S");
  if (ExprPtr f = take("F")) {
    Op o(OpKind::Feed, bl);
    o.set("value", std::move(f));
    out.push_back(std::move(o));
  }
  if (!lowerSpindleMode(spindleMode, take("S"), take("LIMS"), mode, out)) return false;
  if (!lowerSmoothing(smoothing, gLoc[0], mode)) return false;
  if (ExprPtr t = take("T")) {
    if (t->kind == ir::ExprKind::String) return fail(t_[0], "tool names (T=\"…\") need tool management, which is not simulated", "unsupported-code");
    Op o(OpKind::ToolSelect, bl);
    o.set("value", std::move(t));
    out.push_back(std::move(o));
  }
  std::vector<std::pair<const MRow *, SourceLoc>> ms;
  for (auto &[code, l] : mcodes_) ms.push_back({findM(code), l});
  bool changed = false;
  for (auto &[m, l] : ms)
    if (m && m->act == MAct::ToolChange) {
      out.push_back(Op(OpKind::ToolChange, l));
      changed = true;
    }
  // D: the cutting edge of the tool in the spindle (MD20270: D1 after a tool change), its length
  // and the radius of G41/G42; D0 cancels. DL=n: the edge's additive offset set (SIN-TOL-04),
  // with D (selected with it) or alone: then it counts from the next block, after this block's
  // move (example 39, L16983-L16991: "DL=2 … output in the next block").
  ExprPtr dl = take("DL");
  std::optional<Op> dlAfterMove;
  if (ExprPtr d = take("D")) {
    if (d->kind != ir::ExprKind::Number || d->num < 0 || d->num != std::floor(d->num))
      return fail(t_[0], "D takes a constant edge number (D0, D1, D2 …)", "unsupported-code");
    if (d->num == 0 && dl) return fail(t_[0], "DL needs a cutting edge: D0 cancels the tool offset", "unused-word");
    Op o(OpKind::ToolLength, bl);
    if (d->num == 0) o.set("h", Expr::number(0, ir::Type::Int));
    else o.set("D", std::move(d));
    if (dl) o.set("dl", std::move(dl));
    out.push_back(std::move(o));
  } else if (changed) {
    // The change's own edge: `h=0 D=1` is D1 (or the tool's only edge), none for an empty spindle.
    Op o(OpKind::ToolLength, bl);
    o.set("h", Expr::number(0, ir::Type::Int));
    o.set("D", Expr::number(1, ir::Type::Int));
    if (dl) o.set("dl", std::move(dl));
    out.push_back(std::move(o));
  } else if (dl) {
    dlAfterMove.emplace(OpKind::ToolLength, bl);
    dlAfterMove->set("dl", std::move(dl));
  }
  for (auto &[m, l] : ms) {
    if (!m) continue;
    if (m->act == MAct::Spindle) {
      Op o(OpKind::Spindle, l);
      o.set("dir", Expr::symbol(m->arg));
      out.push_back(std::move(o));
    } else if (m->act == MAct::Coolant) {
      Op o(OpKind::Coolant, l);
      if (std::string_view(m->arg) == "off") {
        o.set("flood", Expr::symbol("off"));
        o.set("mist", Expr::symbol("off"));
      } else {
        o.set(m->arg, Expr::symbol("on"));
      }
      out.push_back(std::move(o));
    }
  }
  for (auto &[code, l] : mcodes_)
    if (!findM(code)) {
      Op o(OpKind::Aux, l);
      o.set("m", Expr::number(code, ir::Type::Int));
      out.push_back(std::move(o));
    }
  if (!mode.args.empty()) out.push_back(std::move(mode));
  if (comp) {
    static const char *kSide[] = {"off", "left", "right"};
    Op o(OpKind::CutterComp, bl);
    o.set("side", Expr::symbol(kSide[comp->arg]));
    if (comp->arg) o.set("d_default", Expr::symbol("tool"));
    out.push_back(std::move(o));
  }
  if (offset) {  // G500 is index 0: no settable frame (the executor activates the stored base frames)
    Op o(OpKind::WorkOffset, bl);
    o.set("index", Expr::number(offset->arg, ir::Type::Int));
    out.push_back(std::move(o));
  }
  // The move: every word left.
  ExprPtr denominator;
  if (!poly_.empty() && !lowerPoly(out, denominator)) return false;
  Op mv(OpKind::Move, bl);
  std::string ac, ic;
  bool any = false, path = false;
  if (leadChange) mv.set("dlead", std::move(leadChange));
  if (denominator) {
    mv.set("denominator", std::move(denominator));
    any = true;
  }
  if (word("AP") || word("RP")) {
    if (!lowerPolarMove(mv, ac, out)) return false;
    any = path = true;
  }
  for (auto &w : words_) {
    if (w.addr.empty()) continue;
    const AddrInfo *a = findAddress(w.addr);
    std::string key = w.addr;
    switch (a->kind) {
    case Addr::Axis: path = true; break;
    case Addr::Center: break;
    case Addr::Via:  // I1 J1 K1: the intermediate point's X Y Z
      key = std::string("via_") + (char)('x' + (w.addr[0] - 'I'));
      if (w.mode) return fail(t_[0], fmt::format("{}=AC()/IC() is not simulated", w.addr), "unsupported-code");
      break;
    case Addr::Radius: key = "R"; break;
    case Addr::Opening: key = "opening"; break;
    case Addr::Turns:
      // TURN=n: n full turns beyond the programmed arc, the core's turn count n + 1 (RS274NGC's P).
      if (f_.motion != ModeValue::ArcCW && f_.motion != ModeValue::ArcCCW && f_.motion != ModeValue::Count)
        return fail(t_[0], "TURN= (extra full turns) needs G2 or G3", "arc-invalid");
      if (w.value->kind == ir::ExprKind::Number && (w.value->num < 0 || w.value->num > 999 || w.value->num != std::floor(w.value->num)))
        return fail(t_[0], "TURN= takes a whole number of turns from 0 to 999", "arc-invalid");
      key = "P";
      w.value = Expr::binary(ir::OpCode::Add, std::move(w.value), Expr::number(1, ir::Type::Int), w.loc);
      break;
    case Addr::SplinePoint: key = w.addr == "PW" ? "weight" : w.addr == "SD" ? "degree" : "interval"; break;
    case Addr::StartAngle:  // SF: the executor's thread start angle (modal, kept by G33 blocks)
      if (f_.motion != ModeValue::ThreadLead)
        return failAt(w.loc, "SF= (a thread's start angle) is simulated in a G33 block", "unsupported-code");
      key = "Q";
      break;
    case Addr::Corner:  // CHF the chamfer's length, CHR its legs along the two moves
      key = w.addr == "CHF" ? "chamfer" : w.addr == "CHR" ? "chamfer_leg" : "round";
      break;
    default: return fail(t_[0], fmt::format("address {} cannot be used here", w.addr), "unused-word");
    }
    if (w.mode && a->kind != Addr::Axis && a->kind != Addr::Center && a->kind != Addr::Via)
      return fail(t_[0], fmt::format("{}=AC()/IC() is only for coordinates", w.addr));
    if (w.mode == 'A') ac += w.addr;
    if (w.mode == 'I') ic += w.addr;
    mv.set(key, std::move(w.value));
    mv.loc = w.loc;
    any = true;
  }
  if (mv.get("dlead") && !path) return fail(t_[0], "G34/G35 needs the thread's end point in its block", "missing-word");
  if (machine) {
    // G53 / G153 / SUPA: this block's positions in machine coordinates (non-modal).
    if (!path) return fail(t_[0], fmt::format("{} needs axis positions in its block", machine->code->name), "missing-word");
    if (f_.motion != ModeValue::Rapid && f_.motion != ModeValue::Linear)
      return fail(t_[0], fmt::format("{} is simulated with G0 or G1 active (programmed before in this subprogram)", machine->code->name),
                  "unsupported-code");
    if (!ac.empty() || !ic.empty() || mv.args.size() != 0) {
      for (auto &a : mv.args)
        if (findAddress(a.key) == nullptr || findAddress(a.key)->kind != Addr::Axis)
          return fail(t_[0], fmt::format("{} takes axis positions only", machine->code->name));
      if (!ic.empty()) return fail(t_[0], fmt::format("IC() under {} is not simulated", machine->code->name), "unsupported-code");
    }
    Op o(OpKind::MachineMove, bl);
    o.set("rapid", Expr::boolean(f_.motion == ModeValue::Rapid));
    for (auto &a : mv.args) o.set(a.key, std::move(a.value));
    out.push_back(std::move(o));
  } else if (any) {
    if (!ac.empty()) mv.set("ac", Expr::symbol(ac));
    if (!ic.empty()) mv.set("ic", Expr::symbol(ic));
    if (floatTap && dlAfterMove) return fail(t_[0], "DL in a G63 block is not simulated: program it in its own block", "unsupported-code");
    if (floatTap) return lowerFloatTap(gLoc[1], path, std::move(mv), out);
    out.push_back(std::move(mv));
  } else if (floatTap) {
    return failAt(gLoc[1], "G63 needs the tapping move in its block", "missing-word");
  } else if (f_.pp.modalCalls && (f_.motion == ModeValue::Rapid || f_.motion == ModeValue::Linear)) {
    // MCALL also runs after a block with G0/G1 alone or with F or S under G0/G1 (L8470-L8479).
    bool g01 = false;
    for (auto &[g, l] : gcodes_) g01 = g01 || g.mode == ModeValue::Rapid || g.mode == ModeValue::Linear;
    if (g01 || hadFeedOrSpeed) out.push_back(Op(OpKind::ModalTrigger, bl));
  }
  if (dlAfterMove) out.push_back(std::move(*dlAfterMove));
  for (auto &[m, l] : ms) {
    if (!m) continue;
    if (m->act == MAct::Stop) {
      Op o(OpKind::Stop, l);
      o.set("kind", Expr::symbol(m->arg));
      out.push_back(std::move(o));
    } else if (m->act == MAct::End || m->act == MAct::Return) {
      // M2/M30 end the main program; in a subprogram they return like M17 (L8299).
      if (m->act == MAct::End && f_.isMain) {
        Op o(OpKind::Stop, l);
        o.set("kind", Expr::symbol(m->arg));
        out.push_back(std::move(o));
      } else {
        out.push_back(Op(OpKind::Return, l));
      }
    }
  }
  return true;
}

// G96/G961/G962 S<m/min> and G97/G971/G972: the spindle mode, the feed type they set, and
// LIMS=<rpm>, the limit of constant cutting speed (modal, also alone).
bool BlockParser::lowerSpindleMode(const GInfo *g, ExprPtr s, ExprPtr lims, Op &mode, ir::Region &out) {
  SourceLoc bl = loc(t_[0]);
  if (!g && !s && !lims) return true;
  Op o(OpKind::Speed, bl);
  if (s) o.set("value", std::move(s));
  if (lims) o.set("limit", std::move(lims));
  if (g) {
    const SpindleModeArg &a = spindleModeArg(g->arg);
    o.set("mode", Expr::symbol(a.css ? "css" : "rpm"));
    if (a.feed != ModeValue::Count) mode.set("feed_mode", Expr::symbol(modeValueInfo(a.feed).name));
  }
  out.push_back(std::move(o));
  return true;
}

// G641 ADIS=d, G642/G643/G645 [CTOL=t]: continuous path whose corners are rounded within the
// distance or tolerance, the planner's blending tolerance (G64 P; docs/SINUMERIK.md
// "Continuous path"). ADIS and CTOL count in their block only; ADISPOS (rounding of G0) is 0.
bool BlockParser::lowerSmoothing(const GInfo *g, SourceLoc gl, Op &mode) {
  auto find = [&](std::string_view a) -> Word * {
    for (auto &w : words_)
      if (w.addr == a) return &w;
    return nullptr;
  };
  Word *adis = find("ADIS"), *ctol = find("CTOL"), *adispos = find("ADISPOS");
  if (adispos) {
    if (adispos->value->kind != ir::ExprKind::Number || adispos->value->num != 0)
      return failAt(adispos->loc, "ADISPOS (rounding of G0 moves) other than 0 is not simulated: ncc's rapid moves stop",
                    "unsupported-code");
    adispos->addr.clear();
  }
  Word *given = !g ? nullptr : g->arg == 1 ? adis : ctol;
  const char *want = g && g->arg == 1 ? "ADIS" : "CTOL";
  for (Word *w : {adis, ctol})
    if (w && w != given)
      return failAt(w->loc, g ? fmt::format("{} does not go with {} (it takes {})", w->addr, g->code->name, want)
                              : fmt::format("{}= is simulated in the block of the G641/G642 it belongs to", w->addr),
                    "unsupported-code");
  if (!g) return true;
  if (g->arg == 1 && !given)
    return failAt(gl, "G641 needs its rounding distance ADIS= in the block", "missing-word");
  mode.set("path_mode", Expr::symbol("continuous"));
  if (given) {
    mode.set("tolerance", std::move(given->value));
    given->addr.clear();
  }
  return true;
}

// G63 Z… F…: tapping with a compensating chuck, a straight feed at the programmed F (S x lead):
// the chuck takes up the difference. Non-modal: the block moves as G1, then the motion mode the
// program had comes back.
// An alarm at run time when the spindle stands (or, with `speed`, has no speed): what G4 S and
// G63 need, which the program text alone cannot tell.
Op BlockParser::spindleAlarm(bool speed, const char *msg) {
  SourceLoc bl = loc(t_[0]);
  auto sys = [&](const char *n) { return Expr::var(ir::VarSpace::System, n, nullptr, bl); };
  ExprPtr stopped = Expr::unary(ir::OpCode::Not, sys("_spindle_on"), bl);
  if (speed)
    stopped = Expr::binary(ir::OpCode::Or, std::move(stopped),
                           Expr::binary(ir::OpCode::Le, sys("_rpm"), Expr::number(0, ir::Type::Int), bl), bl);
  Op check(OpKind::If, bl);
  check.set("cond", std::move(stopped));
  check.regions.emplace_back();
  Op alarm(OpKind::Message, bl);
  alarm.set("text", Expr::string(msg, bl));
  alarm.set("kind", Expr::symbol("abort"));
  check.regions[0].push_back(std::move(alarm));
  return check;
}

bool BlockParser::lowerFloatTap(SourceLoc gl, bool path, Op mv, ir::Region &out) {
  SourceLoc bl = loc(t_[0]);
  if (!path) return failAt(gl, "G63 needs the tapping move in its block", "missing-word");
  if (f_.motion == ModeValue::Count || !isPathMotion(f_.motion))
    return failAt(gl, "G63 is simulated with G0-G3 active (programmed before in this subprogram)", "unsupported-code");
  auto motion = [&](ModeValue v) {
    Op m(OpKind::Mode, bl);
    m.set("motion", Expr::symbol(modeValueInfo(v).name));
    return m;
  };
  out.push_back(spindleAlarm(false, "G63 (tapping with a compensating chuck) needs the spindle turning (M3/M4)"));
  out.push_back(motion(ModeValue::Linear));
  out.push_back(std::move(mv));
  if (f_.motion != ModeValue::Linear) out.push_back(motion(f_.motion));
  return true;
}

}  // namespace ncc::sin
