// Executor: the controller state programs read and write besides the modal state - tool data
// (the machine's table with the program's G10 and $_tool_data edits, the edges T, H and D
// numbers address) and the system variables of
// ir/SystemVars.h (readSystem / writeSystem, the CmdSink provider).
#include "runtime/ExecutorImpl.h"

#include "ir/Value.h"

#include <cmath>
#include <iterator>
#include <fmt/format.h>

namespace ncc {

namespace {
bool wholeNumber(double n) { return n >= 0 && n <= 1e9 && n == std::floor(n); }
ToolData resulting(const ToolEdge &e) {
  return {e.length + e.lengthWear, e.radius + e.radiusWear, e.xOffset + e.xWear, e.tip};
}
// rs274's text for a T, H or D number the table lacks; tool data references use it too.
std::string unknownTool(long long n) { return "Requested tool " + std::to_string(n) + " not found in the tool table"; }
}  // namespace

bool Executor::Impl::toolExists(double n) const { return wholeNumber(n) && machine.findTool((int)n); }

bool Executor::Impl::checkTool(double n, const char *word) {
  if (!wholeNumber(n)) return error(std::string(word) + " word must be a non-negative integer", "unknown-tool");
  if (!toolExists(n)) return error(unknownTool((long long)n), "unknown-tool");
  return true;
}

bool Executor::Impl::offsetRef(int n, int &t, int &d) const {
  const auto &map = machine.controller.offsetNumbers;
  if (!map.empty()) {
    auto it = map.find(n);
    if (it == map.end()) return false;
    t = it->second.first, d = it->second.second;
    return true;
  }
  if (n <= 0 || !toolExists(n)) return false;
  t = n, d = offsetEdge(n);
  return true;
}

std::string Executor::Impl::noOffsetMessage(long long n) const {
  return machine.controller.offsetNumbers.empty()
             ? unknownTool(n)
             : "offset number " + std::to_string(n) + " is not in the machine's offset_numbers";
}

bool Executor::Impl::offsetData(double n, const char *word, ToolData &out) {
  if (!wholeNumber(n)) return error(std::string(word) + " word must be a non-negative integer", "unknown-tool");
  out = {};
  int t, d;
  if (n == 0) return true;
  if (!offsetRef((int)n, t, d)) return error(noOffsetMessage((long long)n), "unknown-tool");
  out = resulting(edgeOf(t, d));
  return true;
}

ToolData Executor::Impl::edgeData(int t, int d) const { return resulting(edgeOf(t, d)); }

ToolData Executor::Impl::toolNumberData(int t) const { return resulting(edgeOf(t, offsetEdge(t))); }

namespace {
// A field of an edge by ToolField (the k of $_tool_data[t, d, k]): lengths in mm, the type and
// the cutting edge position as numbers (`length` false).
struct FieldRef {
  double *value;
  int *whole;
  bool length;
  double get() const { return value ? *value : *whole; }
};
// The type ($TC_DP1, 0..9999) and the cutting edge position ($TC_DP2, 0..9) are whole numbers.
bool toolNumberField(int f, double value, int &out, std::string &err) {
  const int hi = f == (int)ToolField::Type ? 9999 : 9;
  if (!(value >= 0 && value <= hi && value == std::floor(value))) {
    err = fmt::format("{} must be a whole number 0..{}, got {}", f == (int)ToolField::Type ? "the tool type" : "the cutting edge position",
                      hi, numberText(value));
    return false;
  }
  out = (int)value;
  return true;
}
FieldRef fieldOf(ToolEdge &e, int f) {
  static constexpr double ToolEdge::*kFields[] = {&ToolEdge::length,      &ToolEdge::radius,      &ToolEdge::lengthWear,
                                                  &ToolEdge::radiusWear,  nullptr,                nullptr,
                                                  &ToolEdge::length2,     &ToolEdge::length3,     &ToolEdge::length2Wear,
                                                  &ToolEdge::length3Wear, &ToolEdge::base1,       &ToolEdge::base2,
                                                  &ToolEdge::base3};
  static_assert(std::size(kFields) == (size_t)kToolSumFields);
  if (f == (int)ToolField::Type) return {nullptr, &e.type, false};
  if (f == (int)ToolField::CutPos) return {nullptr, &e.tip, false};
  if (f < kToolSumFields) return {&(e.*kFields[f]), nullptr, true};
  int i = f - (f < kToolSetupFields ? kToolSumFields : kToolSetupFields);
  auto &sets = f < kToolSetupFields ? e.sumWear : e.sumSetup;
  return {&sets[i / kDlParams][i % kDlParams], nullptr, true};
}
}  // namespace

// T/H/D numbers use edge 1, or the tool's only edge (Machine.cpp); a valid number the table
// lacks (free_tools, a machine without tools) has edge 1 alone, with zero data.
int Executor::Impl::offsetEdge(int t) const {
  auto it = machine.toolTable.find(t);
  if (it == machine.toolTable.end() || it->second.edges.count(1)) return 1;
  return it->second.edges.begin()->first;
}

bool Executor::Impl::hasEdge(int t, int d) const {
  if (t <= 0 || !toolExists(t)) return false;
  auto it = machine.toolTable.find(t);
  return it != machine.toolTable.end() ? it->second.edges.count(d) > 0 : d == 1;
}

ToolEdge Executor::Impl::edgeOf(int t, int d) const {
  if (auto it = edgeEdits.find({t, d}); it != edgeEdits.end()) return it->second;
  auto tt = machine.toolTable.find(t);
  if (tt == machine.toolTable.end()) return {};
  auto e = tt->second.edges.find(d);
  return e != tt->second.edges.end() ? e->second : ToolEdge{};
}

bool Executor::Impl::setEdge(int t, int d, const ToolEdge &e, std::string &err, const char *&rule) {
  rule = "bad-number";
  if (e.radius + e.radiusWear < 0) {
    err = "tool radius (geometry + wear) would be negative";
    return false;
  }
  ToolData data = resulting(e);
  // Fanuc with EVO/EVR = 1: the offsets in use change from the next block. A new radius in the
  // middle of a compensated path would need a transition ncc does not make.
  bool now = toolWrite == ToolWrite::Immediate;
  auto inUse = [&](int number) {
    int nt, nd;
    return number > 0 && offsetRef(number, nt, nd) && nt == t && nd == d;
  };
  // A Sinumerik D<n> edge in use is addressed by the spindle tool and n, not by a number.
  auto edgeInUse = [&](int edge) { return t == st.toolInSpindle && d == edge; };
  const bool radiusInUse = compEdge > 0 ? edgeInUse(compEdge) : inUse(cutterD);
  const bool lengthInUse = activeEdge > 0 ? edgeInUse(activeEdge) : inUse(st.toolLengthH);
  if (now && st.cutterComp != 0 && radiusInUse && data.radius != resulting(edgeOf(t, d)).radius) {
    rule = "unsupported-code";
    err = fmt::format("the radius of D{} changes during cutter compensation (tool_write \"immediate\"): not "
                      "supported; write it before G41/G42",
                      cutterD);
    return false;
  }
  edgeEdits[{t, d}] = e;
  if (now && lengthInUse && activeEdge > 0) {  // a Sinumerik edge: its whole length vector (X Y Z)
    Vec3 length;
    double radius;
    rule = "unsupported-code";
    return sinToolOffsets(t, d, activeDl, length, radius, err) && applySinTool();
  }
  if (now && lengthInUse && toolLength != data.length) {
    toolLength = data.length;
    MotionRecord r = record(RecordKind::ToolLength);
    r.value = toolLength;
    r.ivalue = st.toolLengthH;
    emit(r);
  }
  return true;
}

bool Executor::Impl::toolDataRef(const SysRef &r, int &t, int &d, std::string &err) const {
  t = r.tool, d = r.edge;
  if (r.edge == 0 && !offsetRef(r.tool, t, d)) err = noOffsetMessage(r.tool);
  else if (!toolExists(t)) err = unknownTool(t);
  else if (!hasEdge(t, d)) err = fmt::format("tool {} has no edge {}", t, d);
  return err.empty();
}

// LinuxCNC G43.1 (each given axis's offset becomes its word) and G43.2 (tool H's offsets, H0 the
// tool in the spindle, or the axis words added to the active ones). ncc keeps tool offsets on Z
// (the tool axis) and X (a lathe tool's): an offset on another axis is refused, not dropped. The
// offsets are no table entry's (H 0): a later table write does not replace them.
bool Executor::Impl::offsetToolLength(const MachineCmd &c, ToolLengthForm form) {
  const bool add = form == ToolLengthForm::Add;
  const char *code = add ? "G43.2" : "G43.1";
  double z = toolLength, x = toolOffsetX;
  if (c.has(Word::H)) {
    double h = c.get(Word::H);
    ToolData t;
    if (!offsetData(h == 0 ? st.toolInSpindle : h, "H", t)) return false;
    z += t.length;
    if (machine.controller.lathe()) x += t.xOffset;
  }
  for (int i = 0; i < kAxes; ++i) {
    if (!c.has((Word)i)) continue;
    double v = c.get((Word)i) * axisScale(i);
    double &slot = i == 2 ? z : x;
    if (i == 0 || i == 2) slot = add ? slot + v : v;
    else if (v != 0)
      return error(fmt::format("{} with an offset on the {} axis is not supported (ncc keeps tool offsets on X and Z)", code,
                               kAxisLetters[i]),
                   "unsupported-code");
  }
  toolLength = z, toolOffsetX = x;
  st.toolLengthH = 0;
  MotionRecord r = record(RecordKind::ToolLength);
  r.value = toolLength;
  r.value2 = toolOffsetX;
  r.ivalue = 0;
  emit(r);
  return true;
}

// LinuxCNC M61 Q<tool>: the tool in the spindle is declared without a change (nothing moves, the
// spindle keeps turning); G43 without H then uses its length. rs274 rounds Q to an integer.
bool Executor::Impl::setToolNumber(double q) {
  if (q < 0) return error("Need non-negative Q-word to specify tool number with M61", "bad-number");
  double n = std::floor(q + 0.5);
  if (n != 0 && !toolExists(n)) return error(unknownTool((long long)n), "unknown-tool");
  st.toolInSpindle = (int)n;
  MotionRecord r = record(RecordKind::ToolNumber);
  r.ivalue = st.toolInSpindle;
  emit(r);
  return true;
}

// The 808D turning form (SetOffsetKind::LatheTool): P1-P99 the wear, P101-P1600 the geometry of
// offset P (- 100) (MD20734 bit 1 = 0; the manual's OCR does not say which range is which, this
// is the Fanuc order); X (a diameter when X is) and Z the X and Z offsets, R the nose radius; U W
// C add to them. A change applies at the next T word that selects the offset.
bool Executor::Impl::latheToolOffset(const MachineCmd &c) {
  double p = c.get(Word::P);
  if (p == 0) return workpieceShift(c);
  if (!(p >= 1 && p <= 1600 && p != 100 && p == std::floor(p)))
    return error("G10 P must be 1-99 (wear) or 101-1600 (geometry: 100 + the offset number)", "bad-offset-index");
  const bool geometry = p > 100;
  const int n = (int)p - (geometry ? 100 : 0);
  ToolData data;
  if (!offsetData(n, "P", data)) return false;  // existing offsets only (808D: none can be created)
  int t, d;
  offsetRef(n, t, d);
  ToolEdge e = edgeOf(t, d);
  struct Field {
    Word set, add;
    double ToolEdge::*geometry, ToolEdge::*wear;
    double unit;
  };
  const Field kFields[] = {{Word::X, Word::U, &ToolEdge::xOffset, &ToolEdge::xWear, axisScale(0)},
                           {Word::Z, Word::W, &ToolEdge::length, &ToolEdge::lengthWear, scale()},
                           {Word::R, Word::C, &ToolEdge::radius, &ToolEdge::radiusWear, scale()}};
  for (auto &f : kFields) {
    double &v = e.*(geometry ? f.geometry : f.wear);
    if (c.has(f.set)) v = c.get(f.set) * f.unit;
    if (c.has(f.add)) v += c.get(f.add) * f.unit;
  }
  std::string err;
  const char *rule;
  return setEdge(t, d, e, err, rule) || error(err, rule);
}

// The 808D's turning G10 P00 (manual L4356-4363; front end: LowerFrames.cpp, index 0 of the
// lathe_tool form): the workpiece shift moves every workpiece coordinate system, so ncc keeps it in
// the external frame of the chain ($P_EXTFRAME, outside the settable frames) and applies it at
// once. X Z C set the shift (in G91 add to it), U W H add; X is a diameter when X is programmed so.
bool Executor::Impl::workpieceShift(const MachineCmd &c) {
  struct Field {
    int axis;
    Word set, add;
  };
  static const Field kFields[] = {{0, Word::X, Word::U}, {2, Word::Z, Word::W}, {5, Word::C, Word::H}};
  FrameValue &f = systemFrames[ExtFrame];
  const bool incremental = st.distance == ModeValue::Incremental;
  for (auto &k : kFields) {
    double unit = axisScale(k.axis);
    if (c.has(k.set)) f.coarse[k.axis] = (incremental ? f.coarse[k.axis] : 0) + c.get(k.set) * unit;
    if (c.has(k.add)) f.coarse[k.axis] += c.get(k.add) * unit;
  }
  updateChain();
  noteFrame("G10 P00");
  return true;
}

bool Executor::Impl::execToolOffset(const MachineCmd &c) {
  auto kind = (SetOffsetKind)c.sub;
  if (kind == SetOffsetKind::LatheTool) return latheToolOffset(c);
  if (kind == SetOffsetKind::DeleteAdditive) return deleteAdditive(c);
  if (!c.has(Word::P)) return error("G10 needs a P word (the tool or offset number)", "missing-word");
  ToolData data;
  if (!offsetData(c.get(Word::P), "P", data)) return false;  // existing numbers only (808D: none can be created)
  int n = (int)c.get(Word::P), t, d;
  if (n == 0) return error("tool 0 (no tool) has no offsets", "unknown-tool");
  offsetRef(n, t, d);
  ToolEdge e = edgeOf(t, d);
  double r = c.get(Word::R) * scale();
  switch (kind) {
  case SetOffsetKind::ToolSet:  // LinuxCNC's table holds one length and radius: no wear
    if (c.has(Word::Z)) e.length = c.get(Word::Z) * scale(), e.lengthWear = 0;
    if (c.has(Word::R)) e.radius = r, e.radiusWear = 0;
    break;
  case SetOffsetKind::ToolTouch:
  case SetOffsetKind::ToolTouchG593: {
    if (!frameForbids(kind == SetOffsetKind::ToolTouch ? "G10 L10" : "G10 L11")) return false;
    // rs274: the length that puts the tool tip at Z in the current system (L10) or in G59.3
    // (L11, where G92 does not count), from the machine position.
    double z0 = kind == SetOffsetKind::ToolTouch ? chainOffset[2] + g92[2] + pf.local[2] : g5x[8][2];
    if (c.has(Word::Z)) e.length = st.position[2] - z0 - c.get(Word::Z) * scale(), e.lengthWear = 0;
    if (c.has(Word::R)) e.radius = r, e.radiusWear = 0;
    break;
  }
  default: {
    // Fanuc adds the value in G91; the 808D manual does not say: only G90 is certain.
    if (st.distance == ModeValue::Incremental)
      return error("G10 L10-L13 in G91: whether R is added is not documented for this controller; program it in G90",
                   "unsupported-code");
    static constexpr ToolField kField[] = {ToolField::Length, ToolField::LengthWear, ToolField::Radius,
                                           ToolField::RadiusWear};  // ToolLength … ToolRadiusWear
    *fieldOf(e, (int)kField[(int)kind - (int)SetOffsetKind::ToolLength]).value = r;
    break;
  }
  }
  std::string err;
  const char *rule;
  return setEdge(t, d, e, err, rule) || error(err, rule);
}

bool Executor::readSystem(const SysRef &ref, double &out, std::string &err) const {
  SysVar v = ref.var;
  const Impl &x = *impl_;
  const ModalState &st = x.st;
  auto is = [&](bool b) { return b ? 1.0 : 0.0; };
  // G code x 10 of a mode value, as LinuxCNC reports modes (_motion_mode 800 = G80).
  auto code10 = [](ModeValue m) -> double {
    static const struct { ModeValue m; int code; } kCodes[] = {
        {ModeValue::Rapid, 0},         {ModeValue::Linear, 10},      {ModeValue::ArcCW, 20},
        {ModeValue::ArcCCW, 30},       {ModeValue::CycleOff, 800},   {ModeValue::PeckChipBreak, 730},
        {ModeValue::TapLeft, 740},     {ModeValue::BoreFine, 760},   {ModeValue::Drill, 810},
        {ModeValue::DrillDwell, 820},  {ModeValue::Peck, 830},       {ModeValue::Tap, 840},
        {ModeValue::BoreFeed, 850},    {ModeValue::BoreStop, 860},   {ModeValue::BoreBack, 870},
        {ModeValue::BoreDwell, 890},   {ModeValue::XY, 170},         {ModeValue::ZX, 180},
        {ModeValue::YZ, 190},          {ModeValue::Nurbs, 520},      {ModeValue::ProbeToward, 382},
        {ModeValue::ProbeTowardNoError, 383}, {ModeValue::ProbeAway, 384}, {ModeValue::ProbeAwayNoError, 385}, {ModeValue::Skip, 310}};
    for (auto &c : kCodes)
      if (c.m == m) return c.code;
    return -1;
  };
  static const double kCoordSystems[] = {540, 550, 560, 570, 580, 590, 591, 592, 593};
  SysVarInfo info = sysVarInfo(v);
  double unit;
  if (const double *p = x.storedOffset(info, unit)) {
    out = *p / unit;
    return true;
  }
  switch (info.family) {
  case SysFamily::SinTable: return x.sinTableRead(ref, out, err);  // ExecutorContourTable.cpp
  case SysFamily::MachinePos: out = st.position[info.axis] / x.axisScale(info.axis); return true;  // program units
  case SysFamily::ToolData: {
    int t, d;
    if (!x.toolDataRef(ref, t, d, err)) return false;
    ToolEdge e = x.edgeOf(t, d);
    FieldRef f = fieldOf(e, info.axis);
    out = f.length ? f.get() / x.paramUnit : f.get();
    return true;
  }
  case SysFamily::ToolOffset: {  // rs274 #5401…: the table entry of the tool in the spindle (not G43's)
    out = info.axis == 2 && st.toolInSpindle > 0 ? x.toolNumberData(st.toolInSpindle).length / x.paramUnit : 0;
    return true;
  }
  default: break;
  }
  int axis = -1;
  switch (v) {
  case SysVar::VersionMajor: out = 2.9; return true;  // the LinuxCNC interpreter ncc follows
  case SysVar::VersionMinor: out = 0; return true;
  case SysVar::Line: out = x.blockLoc.line; return true;
  case SysVar::MotionMode: out = code10(st.motion); return true;
  case SysVar::Plane: out = code10(st.plane); return true;
  case SysVar::CutterComp: out = 400 + 10 * st.cutterComp; return true;
  case SysVar::Metric: out = is(st.units == ModeValue::MM); return true;
  case SysVar::Imperial: out = is(st.units == ModeValue::Inch); return true;
  case SysVar::Absolute: out = is(st.distance == ModeValue::Absolute); return true;
  case SysVar::Incremental: out = is(st.distance == ModeValue::Incremental); return true;
  case SysVar::InverseTime: out = is(st.feedMode == ModeValue::InverseTime); return true;
  case SysVar::UnitsPerMinute: out = is(st.feedMode == ModeValue::PerMinute); return true;
  case SysVar::UnitsPerRev: out = is(st.feedMode == ModeValue::PerRev); return true;
  case SysVar::CoordSystem:  // LinuxCNC's systems only (an 808D G54 P<n> has no such number)
    if (st.workOffset > 9) return err = "#<_coord_system> has no value in an 808D G54 P<n> system", false;
    out = kCoordSystems[st.workOffset - 1];
    return true;
  case SysVar::ToolOffset: out = is(st.toolLengthH != 0); return true;
  case SysVar::RetractR: out = is(st.retract == ModeValue::RetractR); return true;
  case SysVar::RetractOldZ: out = is(st.retract == ModeValue::RetractInitial); return true;
  case SysVar::SpindleRpmMode: out = is(!st.css); return true;
  case SysVar::SpindleCssMode: out = is(st.css); return true;
  case SysVar::IjkAbsolute: out = is(st.arcDistance == ModeValue::ArcAbsolute); return true;
  case SysVar::LatheDiameter: out = 0; return true;
  case SysVar::LatheRadius: out = 1; return true;
  case SysVar::SpindleOn: out = is(st.spindle != 0); return true;
  case SysVar::SpindleCw: out = is(st.spindle == 1); return true;
  case SysVar::Mist: out = is(st.mist); return true;
  case SysVar::Flood: out = is(st.flood); return true;
  case SysVar::SpeedOverride:
  case SysVar::FeedOverride:
  case SysVar::FeedHold: out = 1; return true;  // enabled, as in rs274's stand-alone set-up
  case SysVar::AdaptiveFeed: out = 0; return true;
  case SysVar::Feed: out = st.feed; return true;
  case SysVar::Rpm: out = st.speed; return true;
  case SysVar::PosX: axis = 0; break;
  case SysVar::PosY: axis = 1; break;
  case SysVar::PosZ: axis = 2; break;
  case SysVar::PosA: axis = 3; break;
  case SysVar::PosB: axis = 4; break;
  case SysVar::PosC: axis = 5; break;
  case SysVar::PosU:
  case SysVar::PosV:
  case SysVar::PosW: out = 0; return true;  // no U V W axes
  case SysVar::CurrentTool:
  case SysVar::CurrentPocket: out = st.toolInSpindle; return true;  // pocket = tool number here
  case SysVar::SelectedTool:
  case SysVar::SelectedPocket: out = st.toolSelected; return true;
  case SysVar::RemapLevel:
  case SysVar::Task: out = 0; return true;
  case SysVar::G92On: out = is(x.g92On); return true;
  case SysVar::CoordSystemNumber: out = x.noSettableFrame ? 0 : st.workOffset; return true;  // G500: 0
  case SysVar::ChBfrMask: out = x.base.chMask; return true;
  case SysVar::NcBfrMask: out = x.base.ncMask; return true;
  case SysVar::ToolDiameter: {
    out = st.toolInSpindle > 0 ? 2 * x.toolNumberData(st.toolInSpindle).radius / x.paramUnit : 0;
    return true;
  }
  case SysVar::ToolLengthH: out = st.toolLengthH; return true;
  case SysVar::CutterD: out = x.cutterD; return true;
  case SysVar::DeldlStatus: out = x.deldlStatus; return true;
  case SysVar::ProbeX:
  case SysVar::ProbeY:
  case SysVar::ProbeZ:
  case SysVar::ProbeA:
  case SysVar::ProbeB:
  case SysVar::ProbeC:
  case SysVar::ProbeU:
  case SysVar::ProbeV:
  case SysVar::ProbeW: out = x.probeResult[(int)v - (int)SysVar::ProbeX]; return true;
  case SysVar::ProbeTripped: out = x.probeTripped; return true;
  case SysVar::PFrame:
  case SysVar::IFrame:
  case SysVar::ActFrame:  // FRAME values: readFrame (ExecutorFrames.cpp)
  case SysVar::ActBFrame:
  case SysVar::PartFrame:
  case SysVar::SetFrame:
  case SysVar::ExtFrame:
  case SysVar::Iso1Frame:
  case SysVar::Iso2Frame:
  case SysVar::Iso3Frame:
  case SysVar::GFrame:
  case SysVar::ToolFrame:
  case SysVar::WpFrame:
  case SysVar::TraFrame:
  case SysVar::Iso4Frame:
  case SysVar::CycFrame:
  case SysVar::Count: return false;
  case SysVar::PlaneA:
  case SysVar::PlaneB:
  case SysVar::PlaneC: return x.planeJoint((int)v - (int)SysVar::PlaneA, out, err);
  }
  // Positions: program coordinates (all offsets applied), in program units.
  out = x.programPosition()[axis] / x.axisScale(axis);
  return true;
}

// The stored value behind a writable family member, in mm (degrees for rotary axes and the
// rotation), and the unit programs read and write it in. The G92 values are the stored ones
// (rs274's #5211…: G92.2 zeroes the applied offsets only).
double *Executor::Impl::storedOffset(const SysVarInfo &info, double &unit) const {
  Impl &x = const_cast<Impl &>(*this);  // one lookup for readSystem and writeSystem
  unit = info.axis < 3 ? paramUnit : 1.0;  // X Y Z; A B C and R (axis 6 of a work offset) are angles
  switch (info.family) {
  case SysFamily::WorkOffset: return info.axis == 6 ? &x.g5xRotation[info.system - 1] : &x.g5x[info.system - 1][info.axis];
  case SysFamily::G92: return &x.g92Saved[info.axis];
  case SysFamily::Home1: return &x.home[0][info.axis];
  case SysFamily::Home2: return &x.home[1][info.axis];
  default: return nullptr;
  }
}

bool Executor::writeSystem(const SysRef &ref, double value, SourceLoc loc, std::string &err) {
  Impl &x = *impl_;
  Impl::PlainStateRefresh refresh{x};
  SysVarInfo info = sysVarInfo(ref.var);
  if (!sysVarWritable(ref.var)) {
    err = fmt::format("system variable '${}' is read-only", sysRefText(ref));
    return false;
  }
  if (ref.var >= SysVar::ProbeX && ref.var <= SysVar::ProbeTripped) {  // rs274 lets a program set them
    if (ref.var == SysVar::ProbeTripped) x.probeTripped = value;
    else x.probeResult[(int)ref.var - (int)SysVar::ProbeX] = value;
    return true;
  }
  if (ref.var == SysVar::ChBfrMask || ref.var == SysVar::NcBfrMask) {
    x.loc = loc;
    return x.writeBaseMask(ref.var, value, err);
  }
  if (!std::isfinite(value) || std::fabs(value) > 1e9) {
    err = fmt::format("system variable '${}': {} is not a valid offset", sysRefText(ref), numberText(value));
    return false;
  }
  if (info.family == SysFamily::ToolData) {
    int t, d;
    if (!x.toolDataRef(ref, t, d, err)) return false;
    ToolEdge e = x.edgeOf(t, d);
    FieldRef f = fieldOf(e, info.axis);
    if (f.value) *f.value = value * x.paramUnit;
    else if (!toolNumberField(info.axis, value, *f.whole, err)) return false;
    x.loc = loc;
    const char *rule;
    return x.setEdge(t, d, e, err, rule);
  }
  double unit;
  double *p = x.storedOffset(info, unit);  // sets unit: its own statement
  *p = value * unit;
  // G92 values wait for G92.3 and reference points for G28/G30, as in rs274; a work offset of
  // the active system applies now only where the controller says so.
  if (info.family == SysFamily::WorkOffset && info.system == x.st.workOffset && x.offsetWrite == OffsetWrite::Immediate) {
    x.applyWorkOffset();
    x.loc = loc;
    x.noteFrame("offset write");
  }
  return true;
}

}  // namespace ncc
