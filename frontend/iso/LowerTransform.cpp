// 808D ISO turning: G12.1/G13.1 polar coordinate interpolation (ISO-MOT-10, manual L1448-1543)
// and G07.1 cylindrical interpolation (ISO-MOT-09, L1390-1447, L5509-5654), which the manual
// bases on Siemens TRANSMIT and TRACYL: lowered to the same library entries as the Sinumerik
// front end's (trf.TRANSMIT, trf.TRACYL, trf.TRAFOOF with ISO=1, runtime/ExecutorTransform.cpp).
//   G12.1;          cycle entry="trf.TRANSMIT" a.ISO=1
//   G13.1;          cycle entry="trf.TRAFOOF" a.ISO=1
//   G07.1 C<r>;     cycle entry="trf.TRACYL" a.D=<2r> a.AXIS=5 a.ISO=1   (A: 3, B: 4)
//   G07.1 C0;       cycle entry="trf.TRAFOOF" a.ISO=1
// Each stands alone in its block (L1411, L1466): G07.1 with its one rotary-axis word.
#include "frontend/iso/LowerBlock.h"

#include <fmt/format.h>

namespace ncc::iso {

bool BlockLowerer::Block::transformOp() {
  GGroup grp = nonModal && nonModal->kind == GKind::Transform ? GGroup::NonModal : GGroup::Polar;
  const GCodeInfo *gi = G(grp);
  if (!gi || gi->kind != GKind::Transform) return true;
  const SourceLoc loc = gloc(grp);
  const std::string code = gName(gi->code10);
  if (L.flavour_ != Flavour::Fanuc) {
    L.diags_->error(loc, fmt::format("{} ({}) is not an RS274NGC code", code, gi->what), "unsupported-code");
    return false;
  }
  const uint32_t rotary = Words::bits("ABC");
  const uint32_t others = bw.present & ~(gi->arg == 2 ? rotary : 0u);
  if (nm || others || (groups & (groups - 1))) {
    L.diags_->error(loc, fmt::format("{} must be programmed in a block of its own{}", code,
                                     gi->arg == 2 ? " (with only the rotary axis and the cylinder's radius)" : ""),
                    "syntax");
    return false;
  }
  axesTaken = true;
  Op &op = emit(OpKind::Cycle, loc);
  op.set("a.ISO", Expr::number(1, ir::Type::Int, loc));
  if (gi->arg != 2) {
    op.set("entry", Expr::string(gi->arg == 1 ? "trf.TRANSMIT" : "trf.TRAFOOF", loc));
    return true;
  }
  int n = __builtin_popcount(bw.present & rotary);
  if (n != 1) {
    L.diags_->error(loc, "G07.1 needs one rotary axis word with the cylinder's radius (G07.1 C<r>; G07.1 C0 ends it)",
                    "missing-word");
    return false;
  }
  const char axis = bw.has('A') ? 'A' : bw.has('B') ? 'B' : 'C';
  const IsoWord &w = *bw.get(axis);
  if (w.expr) {
    L.diags_->error(w.loc, "G07.1: the cylinder's radius must be a constant (it decides between on and off)",
                    "unsupported-code");
    return false;
  }
  ExprPtr r = take(axis, Scale::Linear);
  const double radius = r->num;
  if (radius < 0) {
    L.diags_->error(w.loc, "G07.1: the cylinder's radius must not be negative", "bad-number");
    return false;
  }
  if (radius == 0) {
    op.set("entry", Expr::string("trf.TRAFOOF", loc));
    return true;
  }
  op.set("entry", Expr::string("trf.TRACYL", loc));
  op.set("a.D", Expr::number(2 * radius, ir::Type::Real, w.loc));
  op.set("a.AXIS", Expr::number(axis - 'A' + 3, ir::Type::Int, w.loc));
  return true;
}

}  // namespace ncc::iso
