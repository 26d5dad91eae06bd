// Work offsets, local shifts and tool length compensation in the emitted program, and the
// machine's travel (docs/EMIT.md "Work offsets", "Tool length", "Travel"). The stream is in
// machine coordinates; the written program selects the source's work offset (G54…), writes what
// remains of the source's translation as a local shift (ISO G52, Sinumerik TRANS) and its tool
// length compensation (ISO G43 H, Sinumerik D), and writes positions as machine coordinates minus
// what those codes add on the target (WrittenFrame::offset). What the target cannot express (a
// rotation, scaling or mirror, an offset number it has no code for, a tool length that is no
// table entry it can address) stays in the positions, and a comment says so: the path is the
// same either way, which `ncc translate --verify` checks.
#include "backends/emit/EmitterImpl.h"
#include "runtime/Geometry.h"
#include "runtime/WorkOffsetCode.h"

#include <fmt/format.h>

namespace ncc::emit::detail {

namespace {

// The codes of one target. Selection index 1..9 is the machine's g54…"g59.3"; 0 none.
struct FrameCodes {
  const char *shift;                    // local shift with X Y Z words; the same with none cancels
  bool shiftCancelNeedsZeros;           // ISO G52 cancels with X0 Y0 Z0, Sinumerik TRANS alone
  const char *lengthCode;               // with the offset number's word: G43 H1; Sinumerik D1 alone
  const char *lengthLetter;
  const char *lengthOff;
};

const FrameCodes kIsoCodes{"G52", true, "G43", "H", "G49"};
const FrameCodes kSinumerikCodes{"TRANS", false, "", "D", "D0"};
// NC-200: seed 003 shows no local shift and no tool length code (T.x is tool and offset, whose
// values it does not give): both stay in the positions.
const FrameCodes kNc200Codes{nullptr, false, nullptr, nullptr, nullptr};

// A target without these codes: everything stays in the positions (machine coordinates).
const FrameCodes *frameCodes(Target t) {
  if (t == Target::ISO) return &kIsoCodes;
  if (t == Target::Sinumerik) return &kSinumerikCodes;
  if (t == Target::Nc200) return &kNc200Codes;
  return nullptr;
}

// The code selecting work offset n on the target, empty when it has none. ISO: G54…G59, then
// G59.1-G59.3 for LinuxCNC and the 808D's G54 P1…P93 for the others (ncc reads both in .nc); no
// "no offset" selection. Sinumerik: G500, G54-G57, G505-G509 (its G510… are frames of their own
// table, not these slots). NC-200: origin n by (UAO,n) (seed 003 L1572, L1609-1611), (UAO,0)
// the zero origin; the machine's [offsets] g54… are its origins 1…9.
std::string selectionCode(Target t, const Machine &m, int n) {
  if (t == Target::ISO) return workOffsetCode(n, m.controller.family == "linuxcnc" ? OffsetCodes::LinuxCnc : OffsetCodes::Iso808);
  if (n < 0 || n > 9) return "";
  if (t == Target::Sinumerik) return workOffsetCode(n, OffsetCodes::Sinumerik);
  if (t == Target::Nc200) return fmt::format("(UAO,{})", n);
  return "";
}

// The source's selection, for notes (the source's dialect is not known here).
std::string sourceSelectionName(int selection) {
  static const char *kNames[] = {"G500", "G54", "G55", "G56", "G57", "G58/G505", "G59/G506",
                                 "G59.1/G507", "G59.2/G508", "G59.3/G509"};
  if (selection > 9 && selection <= Machine::kWorkOffsets) return workOffsetCode(selection, OffsetCodes::Iso808);
  return selection >= 0 && selection <= 9 ? kNames[selection] : "an unknown work offset";
}

bool near(double a, double b) { return std::fabs(a - b) <= 1e-9; }

bool linearIdentity(const FrameMatrix &m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!near(m[i * 4 + j], i == j ? 1 : 0)) return false;
  return true;
}

// The length an edge adds (geometry + wear), as the executor takes it.
double edgeLength(const ToolEdge &e) { return e.length + e.lengthWear; }

}  // namespace

// ISO G43 H<n>: offset number n, through the machine's offset_numbers when it has them (808D
// $TC_DPH), else tool n's edge 1 (docs/MACHINE.md "How numbers find edges").
bool offsetNumberLength(const Machine &machine_, int n, double &length) {
  const auto &map = machine_.controller.offsetNumbers;
  if (!map.empty()) {
    auto it = map.find(n);
    if (it == map.end()) return false;
    auto tool = machine_.toolTable.find(it->second.first);
    if (tool == machine_.toolTable.end()) return false;
    auto edge = tool->second.edges.find(it->second.second);
    if (edge == tool->second.edges.end()) return false;
    length = edgeLength(edge->second);
    return true;
  }
  const ToolData *t = n > 0 ? machine_.findTool(n) : nullptr;
  if (!t) return false;
  length = t->length;
  return true;
}

AxisVec storedBaseFrames(const Machine &machine_, bool selected) {
  const Controller &c = machine_.controller;
  AxisVec sum{};
  const bool kept = (c.resetModeMask & 1) && (c.resetModeMask & (1 << 14));
  if (!selected && !kept) return sum;
  for (auto [frames, count] : {std::pair{&machine_.ncBaseFrames, c.ncBaseFrames}, {&machine_.chanBaseFrames, c.baseFrames}})
    for (int i = 0; i < count && i < (int)frames->size(); ++i)
      if (c.baseFrameMask >> i & 1)
        for (int a = 0; a < kAxes; ++a) sum[a] += (*frames)[i][a];
  return sum;
}

AxisVec startFrame(const Machine &machine_) {
  AxisVec o = storedBaseFrames(machine_, false);
  const int r = machine_.controller.resetModeMask;
  const bool g500 = machine_.dialect == "sinumerik" && !((r & 1) && (r & (1 << 5)));
  if (!g500)
    for (int a = 0; a < kAxes; ++a) o[a] += machine_.workOffsets[0][a];
  return o;
}

// Sinumerik D<d>: the length edge d of the tool in the spindle adds; false when it has no such
// edge (a free tool number has edge 1 of zero data).
bool Emitter::spindleEdgeLength(int d, double &length) const {
  auto tool = machine_.toolTable.find(src_.spindleTool);
  if (tool == machine_.toolTable.end()) {
    length = 0;
    return d == 1 && src_.spindleTool > 0 && machine_.findTool(src_.spindleTool);
  }
  auto e = tool->second.edges.find(d);
  if (e == tool->second.edges.end()) return false;
  length = edgeLength(e->second);
  return true;
}

// The lowest D of the spindle tool whose length is `length`; 0 when none has it.
int Emitter::spindleEdgeWithLength(double length) const {
  auto tool = machine_.toolTable.find(src_.spindleTool);
  double l;
  if (tool == machine_.toolTable.end()) return spindleEdgeLength(1, l) && near(l, length) ? 1 : 0;
  for (auto &[d, e] : tool->second.edges)
    if (near(edgeLength(e), length)) return d;
  return 0;
}

bool Emitter::frameRecord(const MotionRecord &r) {
  switch (r.kind) {
  case RecordKind::FrameChange:
    src_.selection = workOffsetSelection(r);
    src_.matrix = frameMatrix(r);
    src_.axisShift = axisShift(r);
    src_.started = true;
    frameDirty_ = true;
    return true;
  case RecordKind::ToolLength:
    src_.toolZ = r.value, src_.toolX = r.value2, src_.toolH = (int)r.ivalue;
    src_.toolY = r.param("Y") ? *r.param("Y") : 0;  // a Sinumerik edge's length on Y
    frameDirty_ = true;
    return true;
  case RecordKind::ToolNumber:  // LinuxCNC M61: no motion; G43 without H would use it
    src_.spindleTool = (int)r.ivalue;
    return true;
  case RecordKind::ToolChange:
    src_.spindleTool = (int)r.ivalue;
    if (st_.target == Target::Sinumerik && !st_.lathe) {
      // The change block's D word (D0 by default) is the edge the target now has active.
      const std::string &w = st_.toolOffsetWord;
      written_.toolWord = w.size() > 1 && w[0] == 'D' ? std::atoi(w.c_str() + 1) : 1;
      double length = 0;
      if (written_.toolWord && !spindleEdgeLength(written_.toolWord, length)) length = 0;
      AxisVec o = written_.offset;
      o[2] += length - written_.toolZ;
      written_.toolZ = length;
      setWrittenOffset(o);
      frameDirty_ = true;
    }
    return false;  // written by the record switch
  default: return false;
  }
}

// The written program's offset changed: the controller's position stays, its written
// coordinates move the other way.
void Emitter::setWrittenOffset(const AxisVec &offset) {
  AxisVec old = written_.offset;
  written_.offset = offset;
  if (!posKnown_) return;
  for (int i = 0; i < kAxes; ++i) {
    if (old[i] == offset[i]) continue;
    pos_[i] += old[i] - offset[i];
    setPosText(i, written(i, pos_[i]));
  }
}

void Emitter::syncFrame(const MotionRecord &r) {
  frameDirty_ = false;
  const FrameCodes *codes = frameCodes(st_.target);
  if (!codes) return;
  if (!frameInit_) {  // the set-up blocks' selection is in force at the start, else the reset one (G54)
    frameInit_ = true;
    written_.selection = 1;
    bool selected = false;
    for (const std::string &blk : st_.setup)
      for (int i = 0; i <= Machine::kWorkOffsets; ++i) {  // the last match: "G54 P1" after "G54"
        std::string code = selectionCode(st_.target, machine_, i);
        if (!code.empty() && (" " + blk + " ").find(" " + code + " ") != std::string::npos)
          written_.selection = i, selected = true;
      }
    // A selection activates the stored base frames on the target (ncc's reader, as the Sinumerik
    // control, also in ISO mode); the NC-200 has none: there they stay in the positions.
    if (st_.target != Target::Nc200) written_.base = storedBaseFrames(machine_, selected);
  }
  std::vector<std::string> baked;
  // Before the first FrameChange the machine's G54 (and its base frames) is in force (the
  // executor writes one at the start only when it is not zero).
  FrameMatrix m = src_.matrix;
  AxisShift otherAxes = src_.axisShift;
  if (!src_.started) {
    AxisVec start = storedBaseFrames(machine_, false);
    for (int i = 0; i < kAxes; ++i) start[i] += machine_.workOffsets[0][i];
    for (int i = 0; i < 3; ++i) m[i * 4 + 3] = start[i];
    for (int i = 3; i < kAxes; ++i) otherAxes[i - 3] = start[i];
  }
  // The work offset: the source's when the target has a code for it, else the one in force
  // with the whole translation in the positions.
  int sel = written_.selection;
  const std::string selCode = selectionCode(st_.target, machine_, src_.selection);
  const bool selectable = !selCode.empty();
  if (selectable) sel = src_.selection;
  else baked.push_back(std::string("the frame of ") + sourceSelectionName(src_.selection));
  // What the target adds for the selection: its table entry after the stored base frames, which
  // a selection block makes active.
  const AxisVec base = sel != written_.selection && st_.target != Target::Nc200 ? storedBaseFrames(machine_, true)
                                                                               : written_.base;
  AxisVec offset = base;
  if (sel > 0)
    for (int i = 0; i < kAxes; ++i) offset[i] += machine_.workOffsets[sel - 1][i];
  // The rest of the translation as a local shift, rounded as the target reads it back; a
  // rotation, scaling or mirror stays in the positions (so does a shift of other axes).
  std::array<double, 3> shift{};
  if (!linearIdentity(m)) {
    baked.push_back("the rotation, scaling or mirror of the frame");
  } else if (selectable) {
    for (int i = 0; i < 3; ++i) {
      double want = m[i * 4 + 3] - offset[i];
      if (near(want, 0) || !machine_.axes[i].present) continue;
      if (st_.lathe || !codes->shift) {  // lathes: no local shift written (the turning G52 is not read back yet)
        // The NC-200 has no base frames: the machine's stay in the positions with the shift.
        baked.push_back(!st_.lathe && storedBaseFrames(machine_, true) != AxisVec{}
                            ? "the shift of the work offset and the Sinumerik base frames"
                            : "the shift of the work offset");
        shift = {};
        break;
      }
      shift[i] = readBack(i, want);
    }
  }
  for (int i = 3; i < kAxes; ++i)
    if (selectable && !near(otherAxes[i - 3], offset[i])) {
      baked.push_back("the shift of the rotary and U V W axes");
      break;
    }
  // Tool length compensation: written when the target addresses the same length.
  int toolWord = 0;
  if (st_.lathe || !codes->lengthOff || src_.toolX != 0 || src_.toolY != 0) {
    if (src_.toolZ != 0 || src_.toolX != 0 || src_.toolY != 0) baked.push_back(st_.lathe ? "the tool offsets" : "the tool length");
  } else if (st_.target == Target::ISO) {
    double length;
    if (src_.toolH > 0 && offsetNumberLength(machine_, src_.toolH, length) && near(length, src_.toolZ)) toolWord = src_.toolH;
    else if (src_.toolZ != 0) baked.push_back("the tool length");
  } else if (!src_.planeXY) {  // Sinumerik in G18/G19: the target's D would lie on Y or X
    if (src_.toolZ != 0) baked.push_back("the tool length");
  } else {
    double length;
    if (written_.toolWord && spindleEdgeLength(written_.toolWord, length) && near(length, src_.toolZ) &&
        !(src_.toolH == 0 && src_.toolZ == 0))
      toolWord = written_.toolWord;  // the edge in force still fits
    else if (src_.toolH != 0 || src_.toolZ != 0)
      toolWord = spindleEdgeWithLength(src_.toolZ);
    if (!toolWord && src_.toolZ != 0) baked.push_back("the tool length");
  }
  const double toolZ = toolWord ? src_.toolZ : 0;

  // Write what changed: the selection, the shift, the tool length, then the note.
  auto block = [&](const Words &w) {
    flushPending();
    writeBlock(w, r.blockNumber);
  };
  if (sel != written_.selection) {
    Words w;  // "G54 P1" is two words (the target's separator goes between them)
    for (size_t at = 0, sp; at < selCode.size(); at = sp + 1) {
      sp = std::min(selCode.find(' ', at), selCode.size());
      w.push_back(selCode.substr(at, sp - at));
    }
    block(w);
    written_.selection = sel;
    written_.base = base;
  }
  if (shift != written_.shift) {
    Words w{codes->shift};
    for (int i = 0; i < 3; ++i) {
      if (shift[i] == 0 && !(codes->shiftCancelNeedsZeros && written_.shift[i] != 0)) continue;
      std::string word;
      if (number(written(i, shift[i]), WordClass::Axis, axisWord(i), r, word)) w.push_back(word);
    }
    block(w);
    written_.shift = shift;
  }
  if (toolWord != written_.toolWord) {
    Words w;
    if (toolWord) push(w, codes->lengthCode), push(w, codes->lengthLetter + std::to_string(toolWord));
    else push(w, codes->lengthOff);
    block(w);
    written_.toolWord = toolWord;
  }
  written_.toolZ = toolZ;
  std::string note;
  for (const std::string &b : baked) note += (note.empty() ? "" : ", ") + b;
  if (note != written_.baked) {
    flushPending();
    comment(note.empty() ? "ncc: from here nothing is baked into the positions"
                         : "ncc: from here the positions include " + note + ": no code for it on this target");
    written_.baked = note;
  }
  AxisVec total = offset;
  for (int i = 0; i < 3; ++i) total[i] += shift[i];
  total[2] += toolZ;
  setWrittenOffset(total);
}

// A move outside an axis's travel (the machine's min/max, machine coordinates) is an error at
// its source block: the controller would stop there with a limit alarm. Arcs count with their
// extent, not only their end.
void Emitter::checkTravel(const MotionRecord &r) {
  AxisVec lo = r.end, hi = r.end;
  if (r.kind == RecordKind::Arc) {
    Vec3 alo, ahi;
    arcBounds(arcGeometry(r), r.start, r.end, alo, ahi);
    for (int i = 0; i < 3; ++i) lo[i] = std::fmin(lo[i], alo[i]), hi[i] = std::fmax(hi[i], ahi[i]);
  }
  for (int i = 0; i < kAxes; ++i) {
    const AxisLimits &a = machine_.axes[i];
    if (!a.present || (lo[i] >= a.minPos - 1e-9 && hi[i] <= a.maxPos + 1e-9)) continue;
    if (travelErrors_++) return;  // the first is reported, finish() counts the others
    bool below = lo[i] < a.minPos - 1e-9;
    diags_.error(r.loc,
                 fmt::format("the move leaves the travel of axis {}: it reaches {} {} {} (machine coordinates){}",
                             machine_.axisName(i), below ? lo[i] : hi[i], below ? "below its min" : "above its max",
                             below ? a.minPos : a.maxPos, r.loc.valid() ? "" : ": " + printMotionRecord(r)),
                 "out-of-travel");
    errors_ = true;
    return;
  }
}

const MotionRecord &Emitter::toWritten(const MotionRecord &r, MotionRecord &scratch) {
  const bool positions = isMoveRecord(r.kind) || r.kind == RecordKind::CycleBegin || r.kind == RecordKind::SpindleMode;
  if (!positions) return r;
  if (isMoveRecord(r.kind) && opts_.checkTravel) checkTravel(r);
  if (frameDirty_) syncFrame(r);
  const AxisVec &o = written_.offset;
  bool zero = true;
  for (double v : o) zero &= v == 0;
  if (zero) return r;
  scratch = r;
  for (int i = 0; i < kAxes; ++i) scratch.start[i] -= o[i], scratch.end[i] -= o[i];
  for (int i = 0; i < 3; ++i) scratch.center[i] -= o[i];
  switch (r.kind) {
  case RecordKind::Spline: {
    SplineData s = r.spline();
    for (auto &p : s.points)
      for (int i = 0; i < 3; ++i) p[i] -= o[i];
    scratch.setSpline(std::move(s));
    break;
  }
  case RecordKind::Probe: {
    ProbeData p = r.probe();
    for (int i = 0; i < kAxes; ++i) p.target[i] -= o[i];
    scratch.setProbe(p);
    break;
  }
  case RecordKind::CycleBegin:  // mx my mz: machine minus program; the written program's part is gone
    for (int i = 0; i < 3; ++i) {
      const std::string key = std::string("m") + (char)('x' + i);
      const double *m = r.param(key);
      if (m || o[i] != 0) scratch.setParam(key, (m ? *m : 0) - o[i]);
    }
    break;
  case RecordKind::SpindleMode: scratch.value2 -= o[0]; break;  // the spindle axis' X
  default: break;
  }
  return scratch;
}

void Emitter::finishFrame() {
  if (travelErrors_ > 1)
    diags_.note({}, fmt::format("{} more move{} the machine's travel", travelErrors_ - 1,
                                travelErrors_ == 2 ? " leaves" : "s leave"));
}

}  // namespace ncc::emit::detail
