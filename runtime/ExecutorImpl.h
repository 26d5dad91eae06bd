// Private state of the executor, shared by its implementation files (Executor.cpp: dispatch,
// modes and offsets; ExecutorMotion.cpp: moves, arcs and canned cycles).
#pragma once
#include "runtime/CutterComp.h"
#include "runtime/Cycles.h"
#include "runtime/Frame.h"
#include "runtime/Kinematics.h"
#include "runtime/cycles/Contour.h"
#include "runtime/cycles/Library.h"
#include "runtime/cycles/Region.h"
#include "runtime/cycles/Thread.h"
#include "runtime/Executor.h"
#include "runtime/Transmit.h"

#include <optional>
#include <vector>

namespace ncc {

constexpr WordMask kAxisMask = (WordMask(1) << kAxes) - 1;  // the axis words X..W of a MachineCmd

// Cutter compensation computes in XY: records of a G18/G19 path reach it with their axes turned
// so that the plane's first and second axes are X and Y (a cyclic permutation, which keeps the
// turning sense: G18 Z->X, X->Y, Y->Z), and come back turned back through CompPlaneSink.
MotionRecord toCompPlane(const MotionRecord &r, Plane p);
MotionRecord fromCompPlane(const MotionRecord &r, Plane p);
AxisVec toCompPlane(const AxisVec &v, Plane p);
AxisVec fromCompPlane(const AxisVec &v, Plane p);
class CompPlaneSink : public MotionSink {
public:
  explicit CompPlaneSink(MotionSink &out) : out_(out) {}
  Plane plane = Plane::XY;
  // A lathe's imaginary tool tip (machine axes, mm): compensation moves the nose centre, the
  // machine position is the tip, this far from it (ExecutorTurning.cpp, noseTipShift).
  AxisVec shift{};
  void record(const MotionRecord &r) override {
    MotionRecord o = plane == Plane::XY ? r : fromCompPlane(r, plane);
    for (int i = 0; i < 3; ++i) {
      o.start[i] += shift[i], o.end[i] += shift[i];
      if (o.kind == RecordKind::Arc) o.center[i] += shift[i];
    }
    out_.record(o);
  }
  // The machine position of a compensation-plane (nose centre) position, and back.
  AxisVec toMachine(const AxisVec &v) const { return plus(fromCompPlane(v, plane), 1); }
  AxisVec toComp(const AxisVec &machinePos) const { return toCompPlane(plus(machinePos, -1), plane); }

private:
  AxisVec plus(AxisVec v, double k) const {
    for (int i = 0; i < 3; ++i) v[i] += k * shift[i];
    return v;
  }
  MotionSink &out_;
};

// Where the executor's records go: the sinks, or a contour capture (ExecutorContour.cpp) while
// one is active, so every path (moves, corners, compensation) is captured alike.
class RouteSink final : public MotionSink {
public:
  explicit RouteSink(MotionSink &out) : out(out) {}
  MotionSink &out;
  std::vector<MotionRecord> *capture = nullptr;
  MotionSink *transform = nullptr;  // a kinematic transformation's (ExecutorTransform.cpp)
  void record(const MotionRecord &r) override {
    if (capture) capture->push_back(r);
    else if (transform) transform->record(r);
    else out.record(r);
  }
};


// The [controller] reset list as bits (Executor.cpp: kResetGroups).
uint32_t resetGroupMask(const std::vector<std::string> &groups);

struct Executor::Impl {
  bool lintRun = false;  // Executor::setLintRun
  Impl(const Machine &m, MotionSink &s, Diagnostics &d)
      : route(s), machine(m), sink(route), diags(d), compOut(route), comp(compOut), trf(s, d) {
    std::copy(m.workOffsets.begin(), m.workOffsets.end(), g5x.begin());
    for (auto &[n, offsets] : m.settableFrames) g5x[n - 1] = offsets;
    offsetWrite = m.controller.offsetWritePolicy();
    toolWrite = m.controller.toolWritePolicy();
    paramUnit = m.controller.parameterUnits == "inch" ? 25.4 : 1.0;
    startFrames();
    home[0] = m.home1;
    home[1] = m.home2;
    // A Machine with no axis at all is an undescribed one (unit tests): every axis exists.
    axesDescribed = m.axes[0].present || m.axes[1].present || m.axes[2].present;
    for (int i = 0; i < kAxes; ++i)
      if ((axesDescribed || i >= kBaseAxes) && !m.axes[i].present) missingAxes |= wordBit((Word)i);
    resetMask = resetGroupMask(m.controller.reset);
  }
  RouteSink route;  // `sink` is this: the sinks, or a contour capture
  uint32_t resetMask = 0;  // what M2/M30 reset (the machine's [controller] reset list)
  bool axesDescribed = true;
  WordMask missingAxes = 0;  // the axis words checkAxisWords rejects
  const Machine &machine;
  MotionSink &sink;
  Diagnostics &diags;
  ModalState st;

  // Frame (runtime/Frame.h): machine = Rz(P(program) + G92) + G5x (+ tool length on Z), all
  // mm, where P is the programmable frame (G52 G68 G51 G51.1) and Rz the XY rotation of the
  // active coordinate system (G10 L2 R), rs274's order after P.
  ProgrammableFrame pf;
  // The last FRAME written to the programmable frame (ExecutorFrames.cpp), with the slots it
  // made: read back as written while the slots are still those.
  struct WrittenFrame {
    bool set = false;
    FrameValue frame;
    Affine composite;
    AxisVec local{};
  } pfValue;
  FrameValue programmableFrame() const;  // in program units
  // The work offset tables (what G10 L2 and parameter writes change) and the active system's
  // origin as applied: a written offset takes effect when the controller says (offset_write).
  // Systems 1..9 are the machine's nine [offsets] (ISO G54…G59.3); the 808D's G54 P1…P93 are 7..99
  // ([offsets] g54p), Sinumerik's G510…G599 10..99 ([offsets] settable).
  std::array<AxisVec, Machine::kWorkOffsets> g5x{};
  std::array<double, Machine::kWorkOffsets> g5xRotation{};  // degrees
  static_assert(Machine::kWorkOffsets == kUserFrames - 1);
  AxisVec g5xActive{};
  double g5xRotActive = 0;
  OffsetWrite offsetWrite = OffsetWrite::Immediate;
  double paramUnit = 1;  // mm per unit of offsets as programs read and write them
  double *storedOffset(const SysVarInfo &info, double &unit) const;
  void applyWorkOffset() {
    g5xActive = g5x[st.workOffset - 1], g5xRotActive = g5xRotation[st.workOffset - 1];
    settableFrameWritten = noSettableFrame = false;
    updateChain();
  }
  // Sinumerik G500: no settable frame ($P_IFRAME the identity, $P_UIFRNUM 0) until a G54….
  bool noSettableFrame = false;
  // The Sinumerik frames around the settable one (ExecutorFrames.cpp, docs/SINUMERIK.md "Frame
  // chain"), FRAME values in mm: the stored and active base frames of the channel and the NCU,
  // the masks choosing the active ones that enter the total base frame, and the system frames
  // ($P_PARTFRAME $P_SETFRAME $P_EXTFRAME outside the base frames, $P_TOOLFRAME $P_WPFRAME
  // $P_TRAFRAME between the settable and the programmable frame). Each holds offsets and a
  // rotation about Z, like a work offset.
  struct BaseFrames {
    std::array<FrameValue, kBaseFrames> chStored, chActive, ncStored, ncActive;
    int chMask = 0xff, ncMask = 0xff;
  } base;
  enum SystemFrame { PartFrame, SetFrame, ExtFrame, ToolFrame, WpFrame, TraFrame, kSystemFrames };
  std::array<FrameValue, kSystemFrames> systemFrames;
  void startFrames();  // the machine's stored frames, what is active after reset (MD20110)
  void activateBaseFrames() { base.chActive = base.chStored, base.ncActive = base.ncStored; }
  FrameValue totalBaseFrame() const;  // $P_ACTBFRAME, mm
  const FrameValue *baseFrame(const SysRef &ref, std::string &err) const;
  bool writeChainFrame(const SysRef &ref, const FrameValue &f, double unit, const std::string &what, std::string &err);
  bool writeBaseMask(SysVar v, double value, std::string &err);
  void selectNoSettableFrame();
  // What the motion sees of the settable link: the chain outside : settable : inside, folded
  // into one work offset and XY rotation (updateChain after any of them changes).
  AxisVec chainOffset{};
  double chainRot = 0;
  void updateChain();
  // The active settable frame was assigned ($P_IFRAME, Sinumerik G500) rather than read from the
  // table: no work offset is selected (the FrameChange record's `wcs` 0, docs/IR.md).
  bool settableFrameWritten = false;
  // G510…G599 have no number among the nine the emitters know: none, the transform carries them.
  // Sinumerik's G510…G599 are reported as no selection (the transform carries them: the emitters
  // name nine); the 808D's G54 P<n> keep their number (the emitters write their positions).
  int offsetSelection() const {
    return settableFrameWritten || (st.workOffset > 9 && machine.dialect == "sinumerik") ? 0 : st.workOffset;
  }
  // The settable frames $P_UIFR[0 … n-1] the machine has: Sinumerik's settable_frames, else the
  // nine work offsets and G500's 0.
  bool haveSettableFrame(const SysRef &ref, std::string &err) const;  // $P_UIFR[n]: n < settableFrames()
  int settableFrames() const { return machine.dialect == "sinumerik" ? machine.controller.settableFrames : 10; }
  AxisVec g92{};
  AxisVec g92Saved{};  // what G92.3 restores (G92.2 zeroes g92 only)
  bool g92On = false;  // G92 offsets applied (rs274 #5210)
  AxisVec home[2];     // G28 / G30 reference points (machine), G28.1 / G30.1 store them
  double toolLength = 0;
  double toolOffsetX = 0;  // a lathe tool's X offset (mm, machine X), with toolLength on Z
  double toolOffsetY = 0;  // a Sinumerik edge's length component on Y (G18 milling, G17 turning)
  double toolOffset(int axis) const {
    return axis == 2 ? toolLength : axis == 0 ? toolOffsetX : axis == 1 ? toolOffsetY : 0.0;
  }
  double feedMM = 0;
  bool feedInBlock = false;  // an F word in the current block (inverse time needs one per move)  // modal feed converted at the time F was given (mm/min, mm/rev or 1/min)

  int64_t blockNumber = -1;
  uint64_t blocks = 0;  // source blocks executed (summary)
  SourceLoc loc;       // of the command being executed
  SourceLoc blockLoc;  // of the current block

  // Canned cycle modal data (mm, as programmed: absolute or incremental).
  bool initialLevelValid = false;
  double initialLevel = 0;  // drilling-axis machine position when the cycle mode was entered
  ModeValue lastCycle = ModeValue::CycleOff;
  double cycleR = 0, cycleZ = 0, cycleQ = 0, cycleP = 0;
  bool haveQ = false;
  bool tapQ = false;  // a Q given since G84/G74 was entered: 808D peck tapping (machine peck_tapping)
  std::vector<CycleStep> steps;

  int cutterD = 0;
  // Sinumerik D<n>: the cutting edge of the spindle tool whose length is active (0: the ISO
  // offset number toolLengthH) and whose radius G41/G42 without D took (compEdge).
  int activeEdge = 0, compEdge = 0;
  int activeDl = 0;  // Sinumerik DL: the additive offset set of the active edge (0 none)
  // Cutter radius compensation: moves go through `comp` while it is active (radius > 0);
  // compExit marks the move after G40, which starts from the compensated position.
  CompPlaneSink compOut;  // declared before comp, which writes to it
  CutterComp comp;
  bool compExit = false;
  bool warnedAfterEnd = false;
  struct SavedModal {  // Sinumerik SAVE (Executor::saveModal)
    ModalState st;
    double pathTolerance, naiveTolerance;
    ProgrammableFrame pf;  // the programmable frame comes back too
    WrittenFrame pfValue;
  };
  std::vector<SavedModal> savedModal;
  double pathTolerance = 0;   // G64 P (mm)
  double naiveTolerance = 0;  // G64 Q (mm)

  // --- helpers (Executor.cpp) ---
  double scale() const { return st.units == ModeValue::Inch ? 25.4 : 1.0; }
  // mm per unit of an axis word; a diameter-programmed X (machine [controller]) is halved here,
  // so every dialect, offset word and position read-back shares it (arc I/K and R are radii).
  double axisScale(int axis) const {
    return axis == 0 && machine.controller.diameterProgramming ? scale() * 0.5 : isLengthAxis(axis) ? scale() : 1.0;
  }
  double offset(int axis) const {
    return chainOffset[axis] + g92[axis] + pf.local[axis] + toolOffset(axis);
  }
  double rotation() const { return chainRot; }
  // The "offset frame": program coordinates plus G92. Without rotation it is the machine frame
  // (frameOffset = every offset), so unrotated programs compute exactly as before; with a
  // rotation it is the frame before Rz, where only G92 offsets. Targets, arc centres and
  // cycles are computed in it and mapped to the machine with frameOut.
  // With a programmable mirror, scaling or rotation the offset frame is the program frame itself.
  bool rotated() const { return rotation() != 0; }
  bool linearFrame() const { return pf.linear || rotated(); }
  double frameOffset(int axis) const {
    return pf.linear ? 0.0 : rotated() ? g92[axis] + pf.local[axis] : offset(axis);
  }
  AxisVec frameIn(const AxisVec &machinePos) const;
  // The current position in program coordinates (mm), every offset and frame applied.
  AxisVec programPosition() const {
    AxisVec f = frameIn(st.position);
    for (int i = 0; i < kAxes; ++i) f[i] -= frameOffset(i);
    return f;
  }
  AxisVec frameOut(const AxisVec &framePos) const;
  Plane plane() const {
    switch (st.plane) {
    case ModeValue::ZX: return Plane::ZX;
    case ModeValue::YZ: return Plane::YZ;
    default: return Plane::XY;
    }
  }
  // A record of the current block at the current position (inline: built in place per move).
  MotionRecord record(RecordKind k) const {
    MotionRecord r;
    r.kind = k;
    r.plane = plane();
    r.blockNumber = blockNumber;
    r.loc = loc;
    r.start = r.end = st.position;
    return r;
  }
  // While a corner (chamfer/rounding) waits for its second move, records are held back.
  void emit(const MotionRecord &r) {
    if (isMoveRecord(r.kind) || r.kind == RecordKind::Dwell)
      threadChain = r.kind == RecordKind::Thread;
    if (sinSpline.open && !sinSpline.flushing) sinSpline.held.push_back({sinSpline.segs.size(), r});
    else if (corner.active) corner.held.push_back(r);
    else if (!(queuedBehindMotion(r.kind) && comp.hold(toCompPlane(r, compOut.plane)))) sink.record(r);
  }
  // What rs274 queues behind a move that cutter compensation still holds (its interp_queue: feed,
  // spindle, coolant, dwell, comments, M codes), so it takes effect where the program has it.
  static bool queuedBehindMotion(RecordKind k) {
    switch (k) {
    case RecordKind::Dwell: case RecordKind::SpindleSpeed: case RecordKind::SpindleCW: case RecordKind::SpindleCCW:
    case RecordKind::SpindleStop: case RecordKind::CoolantFlood: case RecordKind::CoolantMist:
    case RecordKind::FeedRate: case RecordKind::FeedMode: case RecordKind::Comment: case RecordKind::Aux:
    case RecordKind::SpindleMode: case RecordKind::SpindleOrient: return true;
    default: return false;
    }
  }
  // A chamfer or rounding between a move and the next (ExecutorCorner.cpp): `requested` by the
  // move being executed, `active` while its first move waits for the second.
  struct Corner {
    bool requested = false, active = false;
    bool reqRound = false, round = false;  // requested by the move being executed / of the active corner
    bool reqLeg = false, leg = false;      // a chamfer's size is its legs (Sinumerik CHR), not its length
    double reqSize = 0, size = 0;          // mm
    // The lathe form without a comma (G01 X.. K-3.): the axis (0 X, 2 Z; -1 any) and the sign
    // the next move must go along, requested / of the active corner.
    int reqNextAxis = -1, nextAxis = -1, reqNextSign = 0, nextSign = 0;
    MotionRecord move;
    std::vector<MotionRecord> held;
  } corner;
  bool prevBlockFrame = false, curBlockFrame = false;  // a coordinate change in the last/this block
  bool cornerRequest(const MachineCmd &c);
  bool turnCornerRequest(const MachineCmd &c);  // the lathe form without a comma
  bool cornerNext(const MotionRecord &next);
  bool cornerWithArc(MotionRecord first, MotionRecord next);
  // Not inserted (the manual's cases): the first move as programmed, then what was held.
  bool cornerFlush(const char *why);
  // Sends the first move (trimmed or not), the corner element if any (through cutter
  // compensation when it is on), and what was held.
  bool cornerRelease(const MotionRecord &first, const MotionRecord *elem);
  // Emits a programmed motion record, through cutter compensation when it is on.
  bool emitMove(const MotionRecord &r);
  // emitMove past the corner step: through cutter compensation, its exit move, or straight out.
  bool pathOut(const MotionRecord &r);
  // An oriented spindle stop (M19, cycles): the spindle stops at `angle` degrees. A cycle turns
  // the spindle on again itself (`inCycle`: the modal spindle state stays).
  bool orientSpindle(double angle, int way, double wait, bool inCycle = false);
  bool error(std::string msg, std::string rule) {
    diags.error(loc, std::move(msg), std::move(rule));
    return false;
  }
  void warning(std::string msg, std::string rule) { diags.warning(loc, std::move(msg), std::move(rule)); }
  // Machine-frame target of the axis words of `c` (absent axes keep their position).
  AxisVec target(const MachineCmd &c) const;

  bool execMode(const MachineCmd &c);
  bool modeRepeats(const MachineCmd &c) const;  // a G0/G1 already in force: execMode has nothing to do
  bool execToolLength(const MachineCmd &c);
  bool offsetToolLength(const MachineCmd &c, ToolLengthForm form);  // LinuxCNC G43.1 / G43.2
  bool setToolNumber(double q);                                     // LinuxCNC M61 Q
  bool ioCode(int code, const MachineCmd &c);                       // LinuxCNC M62-M68
  bool execSetOffset(const MachineCmd &c);
  bool execStop(const MachineCmd &c);
  bool execCutterComp(const MachineCmd &c);
  // A lathe's tool nose radius compensation: the shift from the nose centre to the imaginary
  // tool tip of edge `t` (compOut.shift), or an error where the tip cannot be honoured.
  // side 1 (G41) or 2 (G42); `rs274`: t.tip is an rs274 orientation (on any machine, in G18).
  bool noseTipShift(const ToolData &t, double radius, int side, bool rs274);
  // The 808D/Fanuc turning rules of G41/G42 apply; a LinuxCNC lathe keeps rs274's.
  bool isoLathe() const { return machine.controller.lathe() && machine.controller.family != "linuxcnc"; }
  bool compToolData(const MachineCmd &c, bool lathe, bool toolDefault, ToolData &t);
  bool dynamicCompData(const MachineCmd &c, int &side, ToolData &t);
  // G41/G42 in force without a nose radius: the T word that brings one starts it.
  bool noseCompAfterT();
  bool execFrame(const MachineCmd &c);
  bool execCopyFrame(const MachineCmd &c, int action);  // G72.1/G72.2 (ExecutorCopy.cpp)
  // --- the tilted working plane (ExecutorPlane.cpp): Heidenhain 19 / PLANE, pf's tilt slot ---
  bool execTilt(const MachineCmd &c);
  // On a machine with a rotary chain the tilt maps the workpiece-frame tip through the chain at the
  // joints of the position (tiltOut: frameOut's last step, tiltIn: frameIn's first).
  bool tiltMapped() const { return pf.tiltOn && !machine.chain.joints.empty(); }
  AxisVec tiltOut(AxisVec tip) const;
  AxisVec tiltIn(const AxisVec &machinePos) const;
  // The machine normal of the active plane's normal under the frame (arcs of cycles); false (an
  // error) for an arc block that turns a rotary axis of the chain.
  bool tiltedNormal(Vec3 &n, const MachineCmd *arc = nullptr);  // arc: its block (its rotary words)
  // The linear part of program -> machine for directions: the programmable frame, then on a chain
  // under the tilt the turn of the table at the current joints (arcs' planes and normals).
  Affine outLinear() const;
  bool planeJoint(int i, double &out, std::string &err) const;  // Q120-Q122
  std::optional<Kinematics> kinematics;  // the machine's chain (built at the first tilt)
  AxisVec planeJoints{};                  // the rotary positions of the last tilt
  std::string planeJointsProblem = "no working plane was tilted";  // why they are not known
  bool workpieceShift(const MachineCmd &c);  // 808D turning G10 P00 (ExecutorState.cpp)
  // Emits a FrameChange record when the program -> machine transform (without the tool length,
  // which has its own record) or the work offset selection differs from the last one emitted;
  // `what` names the cause.
  void noteFrame(const char *what);
  FrameMatrix lastFrame{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  AxisShift lastShift{};
  int lastSelection = 1;  // the work offset selection of the last FrameChange (G54 at the start)
  // Errors for what ncc does not do under a programmable mirror, scaling or rotation.
  bool frameForbids(const char *what);
  // The offset frame's plane `pl` maps onto the same machine plane with equal scale on both axes
  // (so an arc stays a circle in that plane); `flip` when it mirrors the plane.
  bool frameKeepsPlane(Plane pl, bool &flip) const;
  // Tool data (ExecutorState.cpp). T numbers name tools; an H or D offset number (and G10's P,
  // Fanuc's #2001…) names an edge: tool n's edge 1 or only edge, or on a machine with
  // offset_numbers (808D $TC_DPH) the edge it maps n to.
  bool toolExists(double n) const;              // T number n is valid (0 = no tool)
  bool checkTool(double n, const char *word);   // toolExists, or an error naming `word`
  bool offsetRef(int n, int &t, int &d) const;  // the edge offset number n > 0 addresses
  std::string noOffsetMessage(long long n) const;
  // Geometry + wear of offset number n (0: none); false after an error naming `word`.
  bool offsetData(double n, const char *word, ToolData &out);
  ToolData toolNumberData(int t) const;  // tool t's edge 1 or only edge (rs274 #5401, #5410)
  // Tool edges as the program changed them (G10 L1/L10-L13, `$_tool_data` writes), over the
  // machine's table, by (tool, edge). When a change reaches the offset in use is the machine's
  // tool_write (ToolWrite).
  std::map<std::pair<int, int>, ToolEdge> edgeEdits;
  ToolWrite toolWrite = ToolWrite::OnSelect;
  int offsetEdge(int t) const;          // tool t's edge 1 or only edge
  ToolData edgeData(int t, int d) const;  // edge d of tool t with the program's edits and wear
  bool hasEdge(int t, int d) const;     // t a valid tool with edge d
  ToolEdge edgeOf(int t, int d) const;  // geometry and wear, edited or the machine's
  // Stores an edit; false with the problem and its rule id.
  bool setEdge(int t, int d, const ToolEdge &e, std::string &err, const char *&rule);
  // The tool and edge of a tool data reference (edge 0: tool is an offset number); false with
  // the reason when the machine lacks them.
  bool toolDataRef(const SysRef &r, int &t, int &d, std::string &err) const;
  bool execToolOffset(const MachineCmd &c);
  // Sinumerik tool offsets (ExecutorSinTool.cpp): the length vector (X Y Z) and radius of edge d
  // of tool t with DL set dl; selection of an edge (D) and of a DL set; the plane's share.
  bool sinToolOffsets(int t, int d, int dl, Vec3 &length, double &radius, std::string &err) const;
  // DELDL (SetOffsetKind::DeleteAdditive): the status a program reads back ($_sin_deldl_status).
  bool deleteAdditive(const MachineCmd &c);
  double deldlStatus = 0;
  bool mirroredAxes(bool out[3]) const;
  bool applySinTool();
  bool selectSinEdge(int d, double dl);
  bool selectSinDl(double dl);
  bool sinPlaneChanged();
  bool sinRadius(int t, int d, double &radius);
  bool latheToolOffset(const MachineCmd &c);  // the 808D turning G10 P X Z R
  // Words of axes the machine lacks, and U V W, which the executor has no axes for.
  bool checkAxisWords(const MachineCmd &c);
  MotionRecord pathModeRecord() const;
  // rs274 refuses some motion while compensation is on (G28/G30, G53, canned cycles).
  bool compForbids(const char *msg) { return comp.active() ? error(msg, "cutcomp-conflict") : true; }

  // --- motion (ExecutorMotion.cpp) ---
  bool beginBlock(const MachineCmd &c) {
    prevBlockFrame = curBlockFrame;
    curBlockFrame = false;
    ++blocks;
    blockNumber = c.blockNumber;
    blockLoc = c.loc;
    feedInBlock = false;
    stopOnce = false;
    return true;
  }
  bool execCommand(const MachineCmd &c);  // Executor::exec past its fast paths
  bool execMove(const MachineCmd &c);
  // The plain move (issue 6, the flat path): a G0/G1 with axis words only while nothing that
  // reshapes or holds moves is active (frames, compensation, corners, splines, CSS, inverse time,
  // a modal cycle, G9, ...). plainMove does what execMove, moveTo, emitMove, pathOut and emit do
  // for it, into one reused record; plainMoveFits says when (Executor::exec).
  bool plainMoveFits(const MachineCmd &c) const;
  // plainMoveFits' conditions on the state, cached (issue 6): the state changes only in the
  // commands and calls that are neither a plain move, a block start nor a mode in force, and each
  // of those recomputes it on its way out (a PlainStateRefresh at its start).
  bool plainStateNow() const;
  bool plainState = false;
  struct PlainStateRefresh {
    Impl &x;
    ~PlainStateRefresh() { x.plainState = x.plainStateNow(); }
  };
  void plainMove(const MachineCmd &c);
  MotionRecord plainRecord;  // plainMove's record: only the fields record() and moveTo set change
  bool execHome(const MachineCmd &c);
  bool execMachineMove(const MachineCmd &c);
  // feed: mm/min of this move (a cycle step's own feed), 0 = the modal feed.
  bool moveTo(RecordKind k, const AxisVec &to, bool exactStop = false, double feed = 0);
  bool checkFeed(const char *code);
  double moveFeed(double lengthMM) const;
  // Spindle speed and constant surface speed (ExecutorSpindle.cpp).
  bool execSpeed(const MachineCmd &c);
  double cssOrigin() const { return offset(0); }  // machine X of the spindle axis (program X0)
  double cssOriginNoted = 0;  // the origin the last SpindleMode record gave
  // The spindle speed (rpm) CSS gives at machine X: the limits applied; +inf when unbounded.
  double cssRpm(double machineX) const;
  // Feed per revolution under CSS: the mean path speed of the move (mm/min, length / time).
  double cssFeed(const MotionRecord &r) const;
  // Before a move under CSS: the origin record when the program's X zero moved, errors for
  // what CSS does not support.
  bool cssBeforeMove(const MotionRecord &r);
  void spindleModeRecord(int mode);
  bool cssPerRev() const { return st.css && st.feedMode == ModeValue::PerRev; }
  // In inverse time each feed move gets its own rate record (mm/min), as rs274 prints it.
  void inverseTimeRate(double mmPerMin);
  bool arc(const MachineCmd &c, bool cw);
  // CIP and CT (ExecutorArcs.cpp): the circle is found from three points or from the tangent
  // the path leaves with, then emitted as any arc (emitArc, machine coordinates).
  bool arcThrough(const MachineCmd &c);
  bool arcTangent(const MachineCmd &c);
  // `feed` > 0: the move's own rate (library cycles), else the programmed one; `exactStop` as
  // moveTo's.
  bool emitArc(const AxisVec &end, const Vec3 &centre, const Vec3 &normal, int turns, double feed = 0,
               bool exactStop = false);
  // The last programmed path move, kept as plain data (no strings, nothing computed per move):
  // CT asks it for the direction the path leaves with (pathTangent).
  struct LastPath {
    RecordKind kind = RecordKind::Comment;  // Comment: none yet
    AxisVec start{}, end{};
    std::array<double, 3> center{}, normal{};
    int turns = 0;
    Plane plane = Plane::XY;
  } lastPath;
  // plainMove's move stays in plainRecord instead of being copied here per move (issue 6):
  // while lastPathPlain is set, the last path's kind, start and end are plainRecord's.
  bool lastPathPlain = false;
  LastPath lastPathNow() const {
    LastPath p = lastPath;
    if (lastPathPlain) p.kind = plainRecord.kind, p.start = plainRecord.start, p.end = plainRecord.end;
    return p;
  }
  void notePath(const MotionRecord &r);
  bool pathTangent(Vec3 &t) const;
  // LinuxCNC splines (ExecutorMotion.cpp), as rs274 (2.9) reads them: G5/G5.1 are one Spline
  // record each and give the motion mode back (`splineReturn`: rs274 keeps its mode); G5.2
  // blocks collect `nurbs` control points (machine XYZ) until G5.3 emits the curve.
  bool bezier(const MachineCmd &c, bool cubic);
  bool nurbsPoint(const MachineCmd &c);
  bool nurbsEnd();
  bool emitSpline(const std::vector<std::array<double, 3>> &pts, int order, std::vector<double> weights);
  // The checks every spline block passes (plane, compensation, frame, feed).
  bool splineAllowed(const MachineCmd &c, const char *code);
  ModeValue splineReturn = ModeValue::Rapid;
  std::array<double, 2> splineIJ{};  // G5 without I J: rs274's cycle_i/j, -P -Q of the last G5 (program units)
  struct Nurbs {
    bool open = false;
    int order = 3;
    std::vector<std::array<double, 3>> points;  // the start first
    std::vector<double> weights;
    FrameMatrix frame{};  // the program -> machine transform and units when the curve began
    ModeValue units = ModeValue::MM;
  } nurbs;
  // Sinumerik ASPLINE/BSPLINE/CSPLINE (ExecutorSinSpline.cpp): each move block adds a point
  // (machine coordinates); the curve needs the points after it, so it is emitted when the spline
  // ends (another motion mode, the program's end), with the records of the blocks in between
  // (`held`, after the segment they followed) in their place.
  struct SinSpline {
    bool open = false, flushing = false;
    ModeValue kind = ModeValue::SplineC;
    int degree = 3;                      // BSPLINE SD
    std::vector<AxisVec> points;         // the start first
    std::vector<double> weights;         // BSPLINE PW, one per point
    struct Seg {
      int64_t blockNumber;
      SourceLoc loc;
      double feed;
      bool exactStop;
    };
    std::vector<Seg> segs;               // the block of each point after the start
    std::vector<std::pair<size_t, MotionRecord>> held;  // (segments before it, record)
    Vec3 startTangent{};                 // BTAN: the direction the path had at the start
    bool hasStartTangent = false;
  } sinSpline;
  // POLY: the coefficients a_k of X Y Z and b_k of the denominator (k = 2..5, program units)
  // of the block being executed, cleared by its move.
  struct Poly {
    std::array<std::array<double, 4>, 6> a{};  // [k][axis]: X Y Z, the denominator at 3
    bool any = false;
    bool outside = false;  // polynomials of a block without POLY active: its move must be G1
  } poly;
  bool polyOutsideMove();
  bool polyCoefficients(const MachineCmd &c);
  bool polyMove(const MachineCmd &c);
  bool sinSplinePoint(const MachineCmd &c);
  bool sinSplineEnd();
  bool cycle(const MachineCmd &c);
  // --- lathe single cycles G90/G94 (ExecutorTurning.cpp) ---
  bool turnCycle(const MachineCmd &c);
  // The end point and taper of the last cycle of the mode (a repeat block gives only what
  // changes); reset when the mode is entered.
  bool turnSet = false;
  AxisVec turnEnd{};
  double turnTaper = 0;
  // --- lathe peck cycles G74/G75 (ExecutorTurning.cpp) ---
  bool peckCycle(const MachineCmd &c);
  double peckRetract = -1;  // e of the last G74/G75 R, mm; < 0: never programmed (the machine's)
  // --- thread cutting (ExecutorThread.cpp) ---
  // Spindle turning at a speed, no compensation, no rotation/scaling/mirror.
  bool threadAllowed(const char *code);
  // One thread record from the current position; its feed is the lead along the path x S.
  // `dlead`: the lead's change per revolution (808D G34), 0 for a constant lead.
  bool threadTo(const AxisVec &to, double lead, ThreadAxis along, ThreadSync sync, double angle, double dlead = 0);
  bool threadMove(const MachineCmd &c);   // G33 K (LinuxCNC), G32/G33 F Q (808D)
  bool rigidTap(const MachineCmd &c);     // G33.1
  bool leadThread(const MachineCmd &c);   // Sinumerik G33 I/J/K SF=
  bool positionTap(const MachineCmd &c, bool in);  // Sinumerik G331 / G332
  bool cycleRigidTap(const AxisVec &bottom, const CycleStep &s);  // a library cycle's RigidTap step
  bool spindlePositioned = false;  // SPOS/M19 put the spindle in position control; M3/M4/M5 end it
  double threadStartAngle = 0;     // Sinumerik SF= (modal): the start angle of the next thread
  bool tapOpen = false;            // a G331 tap waits for its G332 back to tapStart
  AxisVec tapStart{};
  double tapLead = 0;
  bool threadCycle(const MachineCmd &c);  // LinuxCNC G76
  bool threadMulti(const MachineCmd &c);  // 808D G76 (both blocks)
  bool threadSteps(const std::vector<ThreadStep> &steps, ThreadAxis along);
  bool threadChain = false;  // the last motion record was a thread (an 808D G32 may chain on)
  double threadSpeed = 0;    // the spindle of the last thread record (a chain must keep it)
  int threadSpindle = 0;
  bool stopOnce = false;  // a G9 in the current block (reset by the next block)
  ModeValue threadReturn = ModeValue::Rapid;  // the motion mode an 808D G76 (G74, G75) block gives back
  struct ThreadData {  // 808D G76 P(m r a) Q R, modal
    bool set = false;
    int finishPasses = 1;
    double chamfer = 0;  // in leads
    double toolAngle = 60, minCut = 0, allowance = 0;
  } threadData;
  // --- probing G38.2-G38.5 (ExecutorProbe.cpp) ---
  bool probeMove(const MachineCmd &c);
  AxisVec programUnits(const AxisVec &machinePos) const;  // program coordinates and units
  void probeResultsUnused();  // at the end of a run: a warning when lines of the file were left
  size_t probeNext = 0;    // the probe-results line the next probe move takes
  AxisVec probeResult{};   // #5061-#5069: the last probe's stop, program coordinates and units
  double probeTripped = 0;  // #5070: 1 after a trip (a program may write any value)
  // --- contour capture (ExecutorContour.cpp) ---
  bool execContour(const MachineCmd &c);
  struct Capture {
    bool active = false;
    SourceLoc loc;
    std::vector<MotionRecord> records;
    // What the captured blocks may change and a roughing consumer puts back.
    ModalState st;
    double feedMM = 0, toolLength = 0, toolOffsetX = 0, toolOffsetY = 0;
    LastPath lastPath;
    int64_t blockNumber = -1;
    SourceLoc blockLoc;
    bool compOn = false;  // G41/G42 ran in the contour (a lathe's G70 only)
    // An SL sub-contour (begin use=subcontour) or contour train (use=train): RL/RR are noted, not
    // run (its side: 1 left, 2 right); `train` for the latter.
    bool sl = false, train = false;
    int side = 0;
    bool table = false;  // a Sinumerik contour table's (use=sin_table): each move's modes are noted
  } capture;
  // Modal consumer data (ISO G71/G72 U R: layer depth and retract; G73 U W R: relief, count), mm.
  double roughDepth = 0, roughRetract = 0;
  bool roughSet = false;
  double patternReliefX = 0, patternReliefZ = 0, patternCount = 0;
  bool patternSet = false;
  // A contour kept for the next library cycle (use=keep, Sinumerik CYCLE95's NPP): ZX plane.
  CycleContour keptContour;
  bool keptSet = false;
  // Sinumerik contour tables (ExecutorContourTable.cpp): CONTPRON/CONTDCON's parameters, the
  // modes each captured move ran in, the table built at EXECUTE ($_sin_table), EXECTAB.
  struct SinTable {
    bool coded = false;  // CONTDCON (6 columns), else CONTPRON (11)
    int mode = 0;        // CONTPRON's machining mode: 0 G, 1 L, 2 N, 3 P
    int rows = 0;        // the program's array
    int unitHint = -1;   // the last G70 G71 G700 G710 the front end saw (0 … 3), -1 none
    struct Modes {
      SourceLoc loc;
      ModeValue distance, units, feedMode, pathMode;
      bool css, g9;
      double tolerance, feed;
    };
    std::vector<Modes> modes;
    bool built = false;
    std::vector<std::vector<double>> table;
    double undercuts = 0;
  } sinTable;
  bool sinTableBegin(const MachineCmd &c);
  void sinTableNote();  // a move under a table's capture: its modes
  bool sinTableBuild(const struct Contour &ct);
  bool sinTableExec(const MachineCmd &c);  // EXECTAB
  bool sinTableRead(const SysRef &ref, double &out, std::string &err) const;
  bool contourData(const MachineCmd &c);
  bool contourConsume(const MachineCmd &c);
  bool rs274Contour(const MachineCmd &c, const struct Contour &ct);  // LinuxCNC G70-G72
  bool rs274ContourAllowed(ContourUse use);
  bool emitContourMoves(const std::vector<struct ContourElem> &moves, const char *name);
  // The captured records as a contour in the active plane (the state put back as at `begin`).
  bool capturedContour(struct Contour &ct);
  // Region pockets (ExecutorRegion.cpp): the outline and islands collected so far.
  PocketRegion region;
  bool regionCapture(const MachineCmd &c, const struct Contour &ct);
  bool regionRun(const MachineCmd &c);
  bool regionSub(const MachineCmd &c, const struct Contour &ct);
  // Heidenhain 24 (run use=side) and 25 (end use=train), runtime/ExecutorSlFinish.cpp.
  bool regionSide(const MachineCmd &c);
  bool contourTrainRun(const MachineCmd &c, const struct Contour &ct);
  int lastRoughTool = 0;  // the tool of the last region roughing (24's Q438 = -1), 0: none
  // Cycles keep their geometry only under a rotation about the drilling axis: an error otherwise.
  bool cycleFrameOk();
  // Emits cycle steps (offset-frame positions) as records, the holes in exact-path mode.
  bool runSteps(const std::vector<CycleStep> &steps);
  // --- library cycles of the `cycle` op (ExecutorCycle.cpp, docs/IR.md §5.8) ---
  bool execCycle(const MachineCmd &c);
  bool runLibraryCycle(const CycleDef *cycle, const CycleArgs &args, const CycleDef *pattern,
                       const CycleArgs *patternArgs);  // Executor::runCycle at `loc`; a pattern alone positions
  // After a move with axis words: the modal cycle there (Sinumerik MCALL).
  bool modalCycleAfterMove(const MachineCmd &c);
  struct StoredCycle {
    const CycleDef *def = nullptr;  // action=define / modal; null: none
    CycleArgs args;
    bool modal = false;
  } storedCycle;
  // --- kinematic transformations TRANSMIT/TRACYL/G12.1/G07.1 (ExecutorTransform.cpp) ---
  TransformSink trf;  // route.transform while one is active
  struct TransformMode {
    bool iso = false;        // the ISO rules (the rotary axis word is the surface coordinate)
    const char *name = "";   // TRANSMIT, TRACYL, G12.1, G07.1
    ModeValue plane = ModeValue::XY;  // ISO: the plane before, restored at the end
    WordMask missingAxes = 0;
    bool inner = false;      // transformCommand runs the command it checked
  } trfMode;
  bool execTransform(const CycleDef &def, const CycleArgs &args, CycleAction action);
  bool transformCommand(const MachineCmd &c);  // every command while one is active
  bool transformOff();
};

}  // namespace ncc
