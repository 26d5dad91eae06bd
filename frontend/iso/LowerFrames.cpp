// The ISO lowering of coordinate codes (LowerBlock.h): G10 offset and tool-offset writes,
// G92 and its variants, G28/G30, G53, the programmable frame (G52 G68 G51 G51.1), the 808D's
// extended work offsets (G54 P) and LinuxCNC's G43.1/G43.2.
#include "frontend/iso/LowerBlock.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc::iso {

// G10 forms that write tool offsets (P = tool or offset number). LinuxCNC: L1 sets length Z and
// radius R, L10/L11 the length that makes the current position Z in the current system / G59.3.
// Fanuc/808D milling: L10-L13 = length, length wear, radius, radius wear, the value in R; L1 = L11.
bool BlockLowerer::Block::toolOffsetOp(Op &op, int lv, IsoWord *l, SourceLoc loc) {
  static const struct {
    Flavour flavour;
    int l;
    const char *kind;
    bool axes;  // Z (and R) as LinuxCNC reads them; else R is the one value
  } kForms[] = {
      {Flavour::RS274, 1, "tool_set", true},          {Flavour::RS274, 10, "tool_touch", true},
      {Flavour::RS274, 11, "tool_touch_g593", true},  {Flavour::Fanuc, 10, "tool_length", false},
      {Flavour::Fanuc, 11, "tool_length_wear", false}, {Flavour::Fanuc, 1, "tool_length_wear", false},
      {Flavour::Fanuc, 12, "tool_radius", false},     {Flavour::Fanuc, 13, "tool_radius_wear", false},
  };
  const char *kind = nullptr;
  bool axes = false;
  for (auto &f : kForms)
    if (f.flavour == L.flavour_ && f.l == lv) kind = f.kind, axes = f.axes;
  if (!kind) {
    const char *known = L.flavour_ == Flavour::RS274 ? "L1, L2, L10, L11 and L20" : "L1, L2, L10-L13 and L20";
    L.diags_->error(l ? l->loc : loc,
                   l ? fmt::format("G10 L{} is not supported (only {})", l->value, known)
                     : fmt::format("G10 needs an L word ({})", known),
                   l ? "unsupported-code" : "missing-word");
    return false;
  }
  if (!bw.has('P')) {
    L.diags_->error(loc, "G10 needs a P word (the tool or offset number)", "missing-word");
    return false;
  }
  // ncc's tools have a length along Z and a radius: LinuxCNC's other table columns (X for
  // lathes, I J Q) would be silently dropped.
  for (char c : std::string_view(axes ? "XYABCIJQ" : "XYZABCIJQ"))
    if (bw.has(c)) {
      L.diags_->error(bw.get(c)->loc, fmt::format("G10 L{}: {} is not a tool offset ncc keeps (length Z, radius R)", lv, c),
                     "unsupported-code");
      return false;
    }
  if (!axes && !bw.has('R')) {
    L.diags_->error(loc, fmt::format("G10 L{} needs an R word (the offset value)", lv), "missing-word");
    return false;
  }
  bw.used |= 1u << ('L' - 'A');
  op.set("kind", Expr::symbol(kind, loc));
  op.set("index", take('P', Scale::None));
  if (bw.has('Z')) op.set("Z", take('Z', Scale::Linear));
  if (bw.has('R')) op.set("R", take('R', Scale::Linear));
  out.push_back(std::move(op));
  axesTaken = true;
  return true;
}

// The turning G10 forms name each value twice: the first letter of a pair sets it, the second adds
// to it (X U, Z W, ...); both in one block is an error.
bool BlockLowerer::Block::setOrAdd(const char *pairs, const char *code, const char *what) {
  for (; pairs[0] && pairs[1]; pairs += 2)
    if (bw.has(pairs[0]) && bw.has(pairs[1])) {
      L.diags_->error(bw.get(pairs[1])->loc,
                     fmt::format("{}: {} and {} in one block ({} adds to the {} {} sets)", code, pairs[0], pairs[1],
                                 pairs[1], what, pairs[0]),
                     "duplicate-word");
      return false;
    }
  return true;
}

// The 808D turning tool offset write G10 P X(U) Z(W) R(C) (manual L4297-4355): X Z R set, U W C
// add; which of wear and geometry P names is the executor's (LatheTool). Q is an error: the
// manual's table reads "cutting-edge length" where Fanuc has the imaginary tool tip.
bool BlockLowerer::Block::latheToolOffset(Op &op, SourceLoc loc) {
  if (!bw.has('P')) {
    L.diags_->error(loc, "G10 needs a P word (the offset number) or L2 (a work offset)", "missing-word");
    return false;
  }
  if (IsoWord *p = bw.get('P'); !p->expr && p->value == 0) return workpieceShift(op, loc);
  for (char c : std::string_view("QYV"))
    if (bw.has(c)) {
      L.diags_->error(bw.get(c)->loc,
                     c == 'Q' ? std::string("G10 Q is not supported: the 808D manual's table 1-22 calls it the cutting-edge length, "
                                                     "Fanuc the imaginary tool tip; set the edge's tip in the machine file")
                              : fmt::format("G10 {}: the lathe has no Y offset", c),
                     "unsupported-code");
      return false;
    }
  if (!setOrAdd("XUZWRC", "G10", "offset")) return false;
  op.set("kind", Expr::symbol("lathe_tool", loc));
  op.set("index", take('P', Scale::None));
  for (char c : std::string_view("XZRUWC"))
    if (bw.has(c)) add(op, c, take(c, Scale::Linear));
  out.push_back(std::move(op));
  axesTaken = true;
  return frameOps();
}

// The 808D's turning G10 P00 X(U) Z(W) C(H) (manual L4356-4363): writes the workpiece shift, which
// moves every workpiece coordinate system; X Z C absolute (in G91 added), U W H added, axes not
// programmed keep their shift. Lowered as `set_offset kind=lathe_tool index=0` with those words
// (runtime/ExecutorState.cpp `workpieceShift`: the external frame of the chain).
bool BlockLowerer::Block::workpieceShift(Op &op, SourceLoc loc) {
  for (char c : std::string_view("RQYVIJKABE"))
    if (bw.has(c)) {
      L.diags_->error(bw.get(c)->loc, fmt::format("G10 P00 writes the workpiece shift of X, Z and C: {} is not one of its words", c),
                     "unsupported-code");
      return false;
    }
  if (!setOrAdd("XUZWCH", "G10 P00", "shift")) return false;
  if (!bw.hasAny("XZCUWH")) {
    L.diags_->error(loc, "G10 P00 needs a shift: X(U), Z(W) or C(H)", "missing-word");
    return false;
  }
  op.set("kind", Expr::symbol("lathe_tool", loc));
  op.set("index", take('P', Scale::None));
  for (char c : std::string_view("XZUW"))
    if (bw.has(c)) add(op, c, take(c, Scale::Linear));
  for (char c : std::string_view("CH"))
    if (bw.has(c)) add(op, c, take(c, Scale::Rotary));
  out.push_back(std::move(op));
  axesTaken = true;
  return frameOps();
}

// The 808D's G10 L2 P<p> (manual L1982-1993, L6236-6243): p = 0 writes the external work offset
// (the PLC's, which ncc does not model), where rs274 writes the active system; in G91 the values
// are added to the offset, which ncc does not do yet. Both are errors, never an absolute write.
bool BlockLowerer::Block::fanucWorkOffsetWrite(SourceLoc loc) {
  IsoWord *p = bw.get('P');
  if (!p->expr && p->value == 0) {
    L.diags_->error(p->loc, "G10 L2 P0 writes the 808D's external work offset (set by the PLC): not supported",
                   "unsupported-code");
    return false;
  }
  if (L.distance_ == ModeValue::Incremental) {
    L.diags_->error(loc, "G10 L2 in G91 adds the values to the work offset (808D): not supported, write it in G90",
                   "unsupported-code");
    return false;
  }
  return true;
}

// Non-modal codes that take the axis words for themselves: G10/G92, G28/G30, G53.
bool BlockLowerer::Block::coordinateOps() {
  // A dwell leaves the axis words to the motion of its block (rs274 runs both, dwell first),
  // unless Fanuc's G4 X took X as the time.
  // G72.1's X Y Z are the rotation's centre (LowerCopy.cpp); with G72.2 they are unused words.
  axesTaken = macroCall || dwellTookAxis || offsetTookAxes || (nonModal && nonModal->kind == GKind::ContourCopy);
  if (nonModal && nonModal->kind == GKind::SetOffset) {
    SourceLoc loc = gloc(GGroup::NonModal);
    Op op(OpKind::SetOffset, loc);
    if (nonModal->arg == 0 && L.lathe_ && !bw.has('L')) return latheToolOffset(op, loc);
    if (nonModal->arg == 0) {  // G10 L<n> P<n>
      IsoWord *l = bw.get('L');
      int lv = l && !l->expr && l->value >= 0 && l->value < 100 ? (int)l->value : -1;
      if (lv != 2 && lv != 20) return toolOffsetOp(op, lv, l, loc);
      if (!bw.has('P')) {
        L.diags_->error(loc, "G10 needs a P word (work offset number)", "missing-word");
        return false;
      }
      bw.used |= 1u << ('L' - 'A');
      if (L.flavour_ == Flavour::Fanuc && lv == 2 && !fanucWorkOffsetWrite(loc)) return false;
      op.set("kind", Expr::symbol(lv == 2 ? "g10l2" : "g10l20", loc));
      op.set("index", take('P', Scale::None));
      // RS274NGC G10 L2 R<degrees>: the system's rotation about the Z axis (Fanuc has none).
      if (L.flavour_ == Flavour::RS274 && bw.has('R')) {
        if (lv == 20) {
          L.diags_->error(bw.get('R')->loc, "R not allowed in G10 L20", "syntax");
          return false;
        }
        op.set("R", take('R', Scale::None));
      }
    } else {
      static const char *kSetOffsetKinds[] = {"g10", "g92", "g92_1", "g92_2", "g92_3", "g28_1", "g30_1"};
      op.set("kind", Expr::symbol(kSetOffsetKinds[nonModal->arg], loc));
    }
    // G10 and G92 take axis values; Fanuc's G92.1 X0 Y0 names the axes to reset; otherwise the
    // block's axis words are a move in the current mode (rs274: `G92.1 X0` resets, then moves).
    bool takesAxes = nonModal->arg <= 1 || (nonModal->arg == 2 && L.flavour_ == Flavour::Fanuc);
    if (takesAxes) axisWords(op, offsetAxes(L.lathe_));
    out.push_back(std::move(op));
    axesTaken = takesAxes;
  }
  if (nonModal && nonModal->kind == GKind::Home) {
    SourceLoc loc = gloc(GGroup::NonModal);
    Op op(OpKind::Home, loc);
    ExprPtr ref = Expr::number(nonModal->arg, ir::Type::Int, loc);
    if (nonModal->arg == 2 && bw.has('P')) ref = take('P', Scale::None);  // G30 P3
    op.set("ref", std::move(ref));
    axisWords(op, offsetAxes(L.lathe_));
    if (L.lathe_ && !latheAxisWords(op)) return false;  // G28 U0 W0: home from where the tool is
    out.push_back(std::move(op));
    axesTaken = true;
  }
  if (nonModal && nonModal->kind == GKind::MachineCoord) {
    SourceLoc loc = gloc(GGroup::NonModal);
    Op op(OpKind::MachineMove, loc);
    op.set("rapid", Expr::boolean(L.motion_ == ModeValue::Rapid, loc));
    axisWords(op, offsetAxes(L.lathe_));
    out.push_back(std::move(op));
    axesTaken = true;
  }
  return frameOps();
}

// The programmable frame (runtime/Frame.h). Each code takes the block's axis words; the 808D
// manual (2.4.1.9-2.4.2.4) gives the formats: G52 X Y Z; G68 X Y R (2-D) or X Y Z I J K R (3-D);
// G69; G51 X Y Z P or X Y Z I J K (machine key axes_scale_enable), factors x scale_weighting;
// G50; G51.1 X Y Z (mirror positions); G50.1 X Y Z (the axes to cancel).
bool BlockLowerer::Block::frameOps() {
  static const GGroup kGroups[] = {GGroup::Mirror, GGroup::Scaling, GGroup::Rotation, GGroup::NonModal};
  const GCodeInfo *gi = nullptr;
  GGroup group = GGroup::Count;
  for (GGroup g : kGroups) {
    if (!G(g) || G(g)->kind != GKind::Frame) continue;
    if (gi) {
      L.diags_->error(gloc(g), fmt::format("{} and {} in one block: each takes the axis words", gName(gi->code10),
                                          gName(G(g)->code10)),
                     "modal-group-conflict");
      return false;
    }
    gi = G(g), group = g;
  }
  if (!gi) return true;
  SourceLoc loc = gloc(group);
  const bool on = gi->arg == 1;
  axesTaken = true;  // stray axis words are unused words, never a move
  if (L.flavour_ == Flavour::RS274) {
    if (gi->code10 != 520) {  // G69, G50.1: LinuxCNC has no rotation or mirror to cancel
      axesTaken = false;
      return true;
    }
    Op &op = emit(OpKind::SetOffset, loc);  // LinuxCNC's G52: the G92 register
    op.set("kind", Expr::symbol("g52", loc));
    axisWords(op, offsetAxes(L.lathe_));
    return true;
  }
  if (group == GGroup::Rotation)  // 808D: G68 and G69 blocks hold no other G code
    for (size_t g = 0; g < (size_t)GGroup::Count; ++g)
      if (G((GGroup)g) && (GGroup)g != GGroup::Rotation) {
        L.diags_->error(gs[g].word->loc,
                       fmt::format("{} must not share its block with other G codes", gName(gi->code10)), "syntax");
        return false;
      }
  static const char *kSlots[] = {"mirror", "scale", "rotation", "local"};  // by kGroups
  Op op(OpKind::Frame, loc);
  op.set("slot", Expr::symbol(kSlots[std::find(kGroups, kGroups + 4, group) - kGroups], loc));
  op.set("action", Expr::symbol(on ? "set" : "cancel", loc));
  switch (gi->code10) {
  case 680:
    op.set("form", Expr::symbol(bw.hasAny("IJK") ? "axis" : "plane", loc));
    axisWords(op, "XYZ");
    for (char c : std::string_view("IJK"))
      if (bw.has(c)) add(op, c, take(c, Scale::None));
    if (bw.has('R')) add(op, 'R', take('R', Scale::Rotary));
    break;
  case 510: {
    // The factor unit of the machine; P is one factor for all axes, I J K one per axis.
    const char *words = L.axesScaleEnable_ ? "IJK" : "P";
    const char *other = L.axesScaleEnable_ ? "P" : "IJK";
    if (bw.hasAny(other)) {
      char c = 0;
      for (const char *o = other; *o && !c; ++o)
        if (bw.has(*o)) c = *o;
      L.diags_->error(bw.get(c)->loc,
                     L.axesScaleEnable_
                         ? "G51 P on a machine with per-axis scaling (axes_scale_enable = true): program I J K"
                         : fmt::format("G51 {} needs per-axis scaling (machine [controller] axes_scale_enable = true)", c),
                     "unsupported-code");
      return false;
    }
    if (!bw.hasAny(words)) {
      L.diags_->error(loc, fmt::format("G51 needs {} (the setting-data default factor is not modelled)",
                                      L.axesScaleEnable_ ? "I, J or K" : "P"),
                     "missing-word");
      return false;
    }
    axisWords(op, "XYZ");
    for (const char *w = words; *w; ++w) {
      if (!bw.has(*w)) continue;
      IsoWord *f = bw.get(*w);
      if (!f->expr && (f->hasPoint || (*w == 'P' && f->value <= 0))) {
        L.diags_->error(f->loc,
                       f->hasPoint ? fmt::format("G51 {} is an integer in units of the scale weighting", *w)
                                   : std::string("G51 P must be greater than zero"),
                       "bad-number");
        return false;
      }
      ExprPtr e = take(*w, Scale::None);
      auto scaled = [&] {
        if (e->kind == ir::ExprKind::Number) return Expr::number(e->num * L.scaleWeighting_, ir::Type::Real, f->loc);
        return Expr::binary(ir::OpCode::Mul, e->clone(), Expr::number(L.scaleWeighting_, ir::Type::Real, f->loc),
                            f->loc);
      };
      if (*w == 'P')
        for (char c : std::string_view("IJK")) add(op, c, scaled());
      else
        add(op, *w, scaled());
    }
    break;
  }
  case 511: case 501: axisWords(op, "XYZ"); break;
  case 520: axisWords(op, offsetAxes(L.lathe_)); break;
  default: break;  // G69, G50
  }
  out.push_back(std::move(op));
  return true;
}


// 808D G54 P1…P93: the extended work offsets (manual L1972, L5426, L6224), the machine's
// [offsets] g54p table: settable offsets 7…99 after G54-G59's 1…6 (docs/IR.md `work_offset`). G54 P0, the external work
// offset, is set by the PLC: nothing in a program or a machine file says its value.
bool BlockLowerer::Block::extendedWorkOffset(int &index) {
  IsoWord *p = bw.get('P');
  if (p->expr || p->hasPoint || !(p->value >= 0 && p->value <= 93) || p->value != std::floor(p->value)) {
    L.diags_->error(p->loc, "G54 P needs a whole number 1 to 93 (an extended work offset) written as a constant",
                   "bad-offset-index");
    return false;
  }
  if (p->value == 0) {
    L.diags_->error(p->loc, "G54 P0 (the external work offset, set by the PLC) is not supported: its value is not known",
                   "unsupported-code");
    return false;
  }
  bw.used |= Words::bit('P');
  index = 6 + (int)p->value;
  return true;
}

// LinuxCNC G43.1 <axes>: each named axis's offset becomes its word, the others keep theirs;
// G43.2 H<n> (H0: the tool in the spindle) or <axes> adds tool n's length or the values to the
// active offsets. The axis words move the machine too when the block has a motion code
// (rs274: `G43.1 Z1 G0 X5` offsets X by 5 and moves to X5).
bool BlockLowerer::Block::offsetToolLength(bool add, SourceLoc loc) {
  const bool axes = bw.hasAny("XYZABCUVW");
  if (add && axes == bw.has('H')) {
    L.diags_->error(loc, axes ? "G43.2: Can not have both H and axis words" : "G43.2: No axes specified and H word missing",
                   axes ? "bad-command" : "missing-word");
    return false;
  }
  Op &op = emit(OpKind::ToolLength, loc);
  op.set("form", Expr::symbol(add ? "add" : "dynamic", loc));
  if (add && bw.has('H')) op.set("h", take('H', Scale::None));
  for (const char *a = "XYZABCUVW"; *a; ++a)
    if (bw.has(*a)) op.set(std::string(1, *a), literal(*bw.get(*a), factor(scaleOf(*a))));
  if (!G(GGroup::Motion)) {
    bw.used |= Words::bits("XYZABCUVW") & bw.present;
    offsetTookAxes = true;
  }
  return true;
}

}  // namespace ncc::iso
