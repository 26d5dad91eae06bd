// The 808D's contour repetition (seed001 §2.16, manual L9988-10114, docs/ISO-WORDS.md):
//   G72.1 X Y (Z) P L R   subprogram P runs L times, the coordinate system rotated by R about X Y
//   G72.2 I J K P L       subprogram P runs L times, shifted by I J K
// lowered to the frame slot `copy` (runtime/ExecutorCopy.cpp) around a loop of calls:
//   frame slot=copy action=set [X Y Z R | I J K]          copy 0: the identity
//   call callee="O<P>" count=1 frame=shared
//   loop count=L-1 { frame slot=copy action=step; call callee="O<P>" count=1 frame=shared }
//   frame slot=copy action=cancel
// The manual says the system turns (shifts) "before each call"; its figures 2-53 and 2-54 start
// the first copy at the programmed zero point (G72.2's copies join: the subprogram's end X110 is
// its start X30 plus I80), so copy k (k = 0 … L-1) runs with k times the step, as Fanuc's figure
// copy does. The rotation and the shift accumulate; after the last copy the slot is cancelled
// (the tool stays where the last copy ended) and the modes the subprogram set stay, as after
// M98.
#include "frontend/iso/LowerBlock.h"

#include <cmath>

namespace ncc::iso {

bool BlockLowerer::Block::contourCopy() {
  SourceLoc loc = gloc(GGroup::NonModal);
  const bool rotate = nonModal->arg == 1;
  const char *code = rotate ? "G72.1" : "G72.2";
  if (!callAllowed(loc, code)) return false;
  if (findM(MKind::Call) || macroCall) {
    L.diags_->error(loc, fmt::format("{} and another call (M98, G65, G66) in one block", code), "several-calls");
    return false;
  }
  long long prog;
  if (!programNumber(loc, code, prog)) return false;
  IsoWord *l = bw.get('L');
  if (!l) {
    L.diags_->error(loc, fmt::format("{} needs L (how often the subprogram runs; the manual gives no default)", code),
                   "missing-word");
    return false;
  }
  // A computed L would need a run-time check that it is a whole number >= 1 (copy 0 always runs).
  if (l->expr || l->value < 1 || l->value != std::floor(l->value) || l->hasPoint) {
    L.diags_->error(l->loc, fmt::format("{} L must be a constant whole number of repetitions, 1 or more", code),
                   "bad-number");
    return false;
  }
  if (rotate ? !bw.has('R') : !bw.hasAny("IJK")) {
    L.diags_->error(loc,
                   rotate ? std::string("G72.1 needs R (the angle the coordinate system turns by before each further call)")
                          : std::string("G72.2 needs I, J or K (the shift before each further call)"),
                   "missing-word");
    return false;
  }
  auto copyFrame = [&](const char *action) {
    Op op(OpKind::Frame, loc);
    op.set("slot", Expr::symbol("copy", loc));
    op.set("action", Expr::symbol(action, loc));
    return op;
  };
  Op set = copyFrame("set");
  if (rotate) {
    axisWords(set, "XYZ");  // the centre; the executor wants the active plane's two axes
    add(set, 'R', take('R', Scale::Rotary));
  } else {
    for (char c : std::string_view("IJK"))
      if (bw.has(c)) add(set, c, take(c, Scale::Linear));
  }
  out.push_back(std::move(set));
  // Copy 0, then L-1 times: the next copy's frame and the call (no frame change after the last).
  std::string callee = fmt::format("O{}", prog);
  L.calls.push_back({callee, loc});
  auto call = [&] {
    Op op(OpKind::Call, loc);
    op.set("callee", Expr::string(callee, loc));
    op.set("count", Expr::number(1, ir::Type::Int, loc));
    op.set("frame", Expr::symbol("shared", loc));
    return op;
  };
  out.push_back(call());
  bw.used |= Words::bit('L');
  if (l->value > 1) {
    Op loop(OpKind::Loop, loc);
    loop.set("count", Expr::number(l->value - 1, ir::Type::Int, l->loc));
    loop.regions.emplace_back();
    loop.regions[0].push_back(copyFrame("step"));
    loop.regions[0].push_back(call());
    out.push_back(std::move(loop));
  }
  out.push_back(copyFrame("cancel"));
  return true;
}

}  // namespace ncc::iso
