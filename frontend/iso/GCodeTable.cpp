// G-code and M-code tables of the ISO front end (milling codes of the Sinumerik 808D ISO dialect,
// which follow Fanuc; LinuxCNC extensions G59.x, G61.1, G90.1/G91.1).
#include "frontend/iso/Codes.h"
#include "ir/MachineCmd.h"

namespace ncc::iso {

const char *gGroupName(GGroup g) {
  static const char *names[] = {"non-modal", "motion", "plane", "distance", "arc distance", "feed mode",
                                "units", "cutter compensation", "tool length", "return level",
                                "work offset", "path mode", "spindle speed mode", "polar coordinates",
                                "scaling", "mirror", "modal macro", "rotation", "language"};
  static_assert(sizeof(names) / sizeof(names[0]) == (size_t)GGroup::Count);
  return names[(unsigned)g];
}

using MV = ModeValue;
#define MODE(c, grp, v, what) {c, GKind::Mode, GGroup::grp, MV::v, 0, what}
#define SPECIAL(c, kind, grp, arg, what) {c, GKind::kind, GGroup::grp, MV::Count, arg, what}
#define NOOP(c, grp, what) {c, GKind::NoOp, GGroup::grp, MV::Count, 0, what}
#define UNSUP(c, grp, what) {c, GKind::Unsupported, GGroup::grp, MV::Count, 0, what}

// Sorted by code10 (binary search).
static const GCodeInfo kGCodes[] = {
    MODE(0, Motion, Rapid, "rapid traverse"),
    MODE(10, Motion, Linear, "linear interpolation"),
    MODE(20, Motion, ArcCW, "circular interpolation CW"),
    MODE(30, Motion, ArcCCW, "circular interpolation CCW"),
    SPECIAL(40, Dwell, NonModal, 0, "dwell"),
    SPECIAL(50, SubCall, NonModal, 0, "subprogram call"),
    NOOP(51, NonModal, "high-speed cutting (ignored, spec ISO-SUB-02)"),
    UNSUP(52, NonModal, "NURBS block"),
    UNSUP(53, NonModal, "NURBS block end"),
    UNSUP(70, NonModal, "lathe diameter mode"),
    SPECIAL(71, Transform, NonModal, 2, "cylindrical interpolation"),
    NOOP(80, NonModal, "lathe radius mode (the default: X words are radii)"),
    UNSUP(90, NonModal, "one-shot exact stop"),
    SPECIAL(100, SetOffset, NonModal, 0, "data setting"),
    SPECIAL(121, Transform, Polar, 1, "polar coordinate interpolation"),
    SPECIAL(131, Transform, Polar, 0, "polar coordinate interpolation off"),
    NOOP(150, Polar, "polar coordinates off"),
    NOOP(160, Polar, "polar coordinates (the front end reads the move words, ISO-MOT-11)"),
    MODE(170, Plane, XY, "XY plane"),
    MODE(180, Plane, ZX, "ZX plane"),
    MODE(190, Plane, YZ, "YZ plane"),
    MODE(200, Units, Inch, "inch input"),
    MODE(210, Units, MM, "metric input"),
    UNSUP(270, NonModal, "reference position check"),
    SPECIAL(280, Home, NonModal, 1, "reference point return"),
    SPECIAL(281, SetOffset, NonModal, 5, "store reference point 1"),
    SPECIAL(300, Home, NonModal, 2, "2nd/3rd/4th reference point return"),
    // 808D G30.1 "reference point position" is listed without a format or meaning (L582, L5469;
    // Fanuc's G30.1 returns to the floating reference point): refused, not LinuxCNC's store.
    UNSUP(301, NonModal, "reference point position (listed without a description by the 808D manual)"),
    NOOP(310, NonModal, "skip function (the motion mode skip for its block, ISO-MEAS-01)"),
    UNSUP(320, Motion, "thread cutting"),
    UNSUP(330, Motion, "thread cutting"),
    UNSUP(340, Motion, "variable-lead thread cutting"),
    SPECIAL(400, CutterComp, CutterComp, 0, "cutter compensation off"),
    SPECIAL(410, CutterComp, CutterComp, 1, "cutter compensation left"),
    SPECIAL(420, CutterComp, CutterComp, 2, "cutter compensation right"),
    SPECIAL(430, ToolLength, ToolLength, 1, "tool length compensation +"),
    UNSUP(440, ToolLength, "negative tool length compensation"),
    SPECIAL(490, ToolLength, ToolLength, 0, "tool length compensation off"),
    SPECIAL(500, Frame, Scaling, 0, "scaling off"),
    SPECIAL(501, Frame, Mirror, 0, "programmable mirror off"),
    SPECIAL(510, Frame, Scaling, 1, "scaling"),
    SPECIAL(511, Frame, Mirror, 1, "programmable mirror"),
    SPECIAL(520, Frame, NonModal, 1, "local coordinate system"),
    SPECIAL(530, MachineCoord, NonModal, 0, "machine coordinates"),
    SPECIAL(540, WorkOffset, WorkOffset, 1, "work offset 1"),
    SPECIAL(550, WorkOffset, WorkOffset, 2, "work offset 2"),
    SPECIAL(560, WorkOffset, WorkOffset, 3, "work offset 3"),
    SPECIAL(570, WorkOffset, WorkOffset, 4, "work offset 4"),
    SPECIAL(580, WorkOffset, WorkOffset, 5, "work offset 5"),
    SPECIAL(590, WorkOffset, WorkOffset, 6, "work offset 6"),
    SPECIAL(591, WorkOffset, WorkOffset, 7, "work offset 7"),
    SPECIAL(592, WorkOffset, WorkOffset, 8, "work offset 8"),
    SPECIAL(593, WorkOffset, WorkOffset, 9, "work offset 9"),
    UNSUP(600, NonModal, "unidirectional positioning"),
    MODE(610, PathMode, ExactPath, "exact path mode"),
    MODE(611, PathMode, ExactStop, "exact stop mode"),
    UNSUP(630, PathMode, "tapping mode"),
    MODE(640, PathMode, Continuous, "continuous path mode"),
    SPECIAL(650, MacroCall, NonModal, 0, "macro call"),
    SPECIAL(660, ModalMacro, MacroModal, 0, "modal macro call"),
    SPECIAL(670, ModalMacro, MacroModal, 1, "modal macro call cancel"),
    SPECIAL(680, Frame, Rotation, 1, "coordinate rotation"),
    SPECIAL(690, Frame, Rotation, 0, "coordinate rotation off"),
    UNSUP(700, NonModal, "finishing cycle"),
    UNSUP(710, NonModal, "stock removal cycle"),
    UNSUP(720, NonModal, "stock removal cycle"),
    SPECIAL(721, ContourCopy, NonModal, 1, "rotational contour copy"),
    SPECIAL(722, ContourCopy, NonModal, 2, "linear contour copy"),
    MODE(730, Motion, PeckChipBreak, "high-speed peck drilling cycle"),
    MODE(740, Motion, TapLeft, "left-hand tapping cycle"),
    UNSUP(750, NonModal, "grooving cycle"),
    MODE(760, Motion, BoreFine, "fine boring cycle"),
    MODE(800, Motion, CycleOff, "canned cycle cancel"),
    MODE(810, Motion, Drill, "drilling cycle"),
    MODE(820, Motion, DrillDwell, "drilling cycle with dwell"),
    MODE(830, Motion, Peck, "peck drilling cycle"),
    MODE(840, Motion, Tap, "tapping cycle"),
    MODE(850, Motion, BoreFeed, "boring cycle"),
    MODE(860, Motion, BoreStop, "boring cycle, spindle stop"),
    MODE(870, Motion, BoreBack, "back boring cycle"),
    UNSUP(880, Motion, "boring cycle with manual retract"),
    MODE(890, Motion, BoreDwell, "boring cycle with dwell"),
    MODE(900, Distance, Absolute, "absolute programming"),
    MODE(901, ArcDistance, ArcAbsolute, "absolute arc centre"),
    MODE(910, Distance, Incremental, "incremental programming"),
    MODE(911, ArcDistance, ArcIncremental, "incremental arc centre"),
    SPECIAL(920, SetOffset, NonModal, 1, "coordinate system setting"),
    SPECIAL(921, SetOffset, NonModal, 2, "coordinate system setting reset"),
    SPECIAL(922, SetOffset, NonModal, 3, "coordinate system setting suspend"),
    SPECIAL(923, SetOffset, NonModal, 4, "coordinate system setting restore"),
    MODE(930, FeedMode, InverseTime, "inverse time feed"),
    MODE(940, FeedMode, PerMinute, "feed per minute"),
    MODE(950, FeedMode, PerRev, "feed per revolution"),
    SPECIAL(960, SpindleMode, Spindle, 2, "constant surface speed"),
    SPECIAL(970, SpindleMode, Spindle, 1, "constant surface speed off"),
    MODE(980, Retract, RetractInitial, "return to initial level"),
    MODE(990, Retract, RetractR, "return to R level"),
    UNSUP(2900, Language, "Siemens language mode"),
    NOOP(2910, Language, "ISO language mode"),
};

// RS274NGC (.ngc) codes whose number means something else in the 808D table above (G05 call,
// G05.1 ignored, G05.2/G05.3 unsupported there): LinuxCNC's splines.
static const GCodeInfo kRs274GCodes[] = {
    MODE(50, Motion, SplineCubic, "cubic spline"),
    MODE(51, Motion, SplineQuadratic, "quadratic spline"),
    MODE(52, Motion, Nurbs, "NURBS control point"),
    MODE(53, Motion, NurbsEnd, "NURBS end"),
    MODE(330, Motion, Thread, "spindle-synchronised motion"),
    MODE(331, Motion, RigidTap, "rigid tapping"),
    MODE(382, Motion, ProbeToward, "straight probe toward the work, error on a miss"),
    MODE(383, Motion, ProbeTowardNoError, "straight probe toward the work"),
    MODE(384, Motion, ProbeAway, "straight probe away from the work, error on a miss"),
    MODE(385, Motion, ProbeAwayNoError, "straight probe away from the work"),
    SPECIAL(301, SetOffset, NonModal, 6, "store reference point 2"),
    // G41.1/G42.1: the radius from a D diameter, a lathe orientation from L (arg 3, 4: left, right).
    SPECIAL(411, CutterComp, CutterComp, 3, "dynamic cutter compensation left"),
    SPECIAL(421, CutterComp, CutterComp, 4, "dynamic cutter compensation right"),
    SPECIAL(431, ToolLength, ToolLength, 2, "dynamic tool length offset"),
    SPECIAL(432, ToolLength, ToolLength, 3, "additional tool length offset"),
    MODE(760, Motion, ThreadCycle, "threading cycle"),
    // LinuxCNC's lathe contour cycles (Q the profile's subroutine; LowerTurning.cpp).
    SPECIAL(700, TurnCycle, NonModal, 700, "finishing cycle"),
    SPECIAL(710, TurnCycle, NonModal, 710, "stock removal in turning"),
    SPECIAL(711, TurnCycle, NonModal, 711, "stock removal in turning, no pockets"),
    SPECIAL(712, TurnCycle, NonModal, 712, "stock removal in turning, pockets only"),
    SPECIAL(720, TurnCycle, NonModal, 720, "stock removal in facing"),
    SPECIAL(721, TurnCycle, NonModal, 721, "stock removal in facing, no pockets"),
    SPECIAL(722, TurnCycle, NonModal, 722, "stock removal in facing, pockets only"),
};

const GCodeInfo *findRs274GCode(int32_t code10) {
  for (auto &g : kRs274GCodes)
    if (g.code10 == code10) return &g;
  return nullptr;
}

// The turning codes of G-code systems A, B and C (808D Tables 1-2, 1-4, the T column) whose meaning
// differs from the milling table above: those of both systems, those of one, then the milling
// codes each system has unchanged. Sorted by code10.
static const GCodeInfo kTurningBoth[] = {
    SPECIAL(410, CutterComp, CutterComp, 1, "tool nose radius compensation left"),
    SPECIAL(420, CutterComp, CutterComp, 2, "tool nose radius compensation right"),
    UNSUP(502, NonModal, "polygon turning off"),
    UNSUP(512, NonModal, "polygon turning"),
    UNSUP(680, NonModal, "turning coordinate rotation / double turret"),
    NOOP(690, NonModal, "turning coordinate rotation off"),
    SPECIAL(700, TurnCycle, NonModal, 70, "finishing cycle"),
    SPECIAL(710, TurnCycle, NonModal, 71, "stock removal in turning"),
    SPECIAL(720, TurnCycle, NonModal, 72, "stock removal in facing"),
    SPECIAL(730, TurnCycle, NonModal, 73, "pattern repeating cycle"),
    MODE(740, Motion, PeckAlongZ, "peck drilling / grooving along Z"),
    MODE(750, Motion, PeckAlongX, "peck grooving along X"),
    MODE(760, Motion, ThreadMulti, "multiple threading cycle"),
    UNSUP(830, Motion, "face deep-hole drilling cycle (C axis)"),
    UNSUP(840, Motion, "face tapping cycle (C axis)"),
    UNSUP(850, Motion, "face boring cycle (C axis)"),
    UNSUP(870, Motion, "side deep-hole drilling cycle (C axis)"),
    UNSUP(880, Motion, "side tapping cycle (C axis)"),
    UNSUP(890, Motion, "side boring cycle (C axis)"),
};
// System A: G50/G50.3 coordinate setting, G90/G92/G94 the single cycles, G98/G99 feed modes.
static const GCodeInfo kTurningA[] = {
    SPECIAL(500, SetOffset, NonModal, 1, "coordinate system setting"),
    SPECIAL(503, SetOffset, NonModal, 2, "work coordinate system reset"),
    MODE(900, Motion, TurnAlongZ, "longitudinal turning cycle"),
    MODE(320, Motion, Thread, "thread cutting"),
    MODE(340, Motion, ThreadVariable, "variable-lead thread cutting"),
    MODE(920, Motion, ThreadSingle, "thread cutting cycle"),
    MODE(940, Motion, TurnAlongX, "face turning cycle"),
    MODE(980, FeedMode, PerMinute, "feed per minute"),
    MODE(990, FeedMode, PerRev, "feed per revolution"),
};
static const int32_t kSharedA[] = {0,   10,  20,  30,  40,  50,  51,  71,  100, 121, 131, 170, 180,
                                   190, 200, 210, 270, 280, 300, 301, 310, 320, 340, 400, 520, 530,
                                   540, 550, 560, 570, 580, 590, 600, 650, 660, 670, 800, 960, 970,
                                   2900, 2910};
// System B: G77/G78/G79 the single cycles; G90/G91 distance, G94/G95 feed modes, G92/G92.1
// coordinate setting, G98/G99 return levels as in milling.
static const GCodeInfo kTurningB[] = {
    MODE(770, Motion, TurnAlongZ, "longitudinal turning cycle"),
    MODE(330, Motion, Thread, "thread cutting"),
    MODE(340, Motion, ThreadVariable, "variable-lead thread cutting"),
    MODE(780, Motion, ThreadSingle, "thread cutting cycle"),
    MODE(790, Motion, TurnAlongX, "face turning cycle"),
};
static const int32_t kSharedB[] = {0,   10,  20,  30,  40,  50,  51,  71,  100, 121, 131, 170, 180, 190,
                                   200, 210, 270, 280, 300, 301, 310, 330, 340, 400, 520, 530, 540, 550,
                                   560, 570, 580, 590, 600, 650, 660, 670, 800, 900, 910, 920, 921, 940,
                                   950, 960, 970, 980, 990, 2900, 2910};

// System C: system B with the single cycles G20/G21/G24, inch/metric G70/G71 and the multiple
// repetitive cycles two numbers up (G72-G78 for B's G70-G76; 808D Tables 1-2, 1-4).
static const GCodeInfo kTurningC[] = {
    MODE(200, Motion, TurnAlongZ, "longitudinal turning cycle"),
    MODE(210, Motion, ThreadSingle, "thread cutting cycle"),
    MODE(240, Motion, TurnAlongX, "face turning cycle"),
    MODE(330, Motion, Thread, "thread cutting"),
    MODE(340, Motion, ThreadVariable, "variable-lead thread cutting"),
    MODE(700, Units, Inch, "inch input"),
    MODE(710, Units, MM, "metric input"),
    SPECIAL(720, TurnCycle, NonModal, 70, "finishing cycle"),
    SPECIAL(730, TurnCycle, NonModal, 71, "stock removal in turning"),
    SPECIAL(740, TurnCycle, NonModal, 72, "stock removal in facing"),
    SPECIAL(750, TurnCycle, NonModal, 73, "pattern repeating cycle"),
    MODE(760, Motion, PeckAlongZ, "peck drilling / grooving along Z"),
    MODE(770, Motion, PeckAlongX, "peck grooving along X"),
    MODE(780, Motion, ThreadMulti, "multiple threading cycle"),
};
static const int32_t kSharedC[] = {0,   10,  20,  30,  40,  50,  51,  71,  100, 121, 131, 170, 180, 190,
                                   270, 280, 300, 301, 310, 400, 520, 530, 540, 550, 560, 570, 580, 590,
                                   600, 650, 660, 670, 800, 900, 910, 920, 921, 940, 950, 960, 970, 980,
                                   990, 2900, 2910};

const GCodeInfo *findTurningGCode(int32_t code10, char system) {
  auto own = [&](const auto &table) -> const GCodeInfo * {
    for (auto &g : table)
      if (g.code10 == code10) return &g;
    return nullptr;
  };
  auto shared = [&](const auto &list) -> const GCodeInfo * {
    for (int32_t c : list)
      if (c == code10) return findGCode(code10);
    return nullptr;
  };
  if (system == 'C') {
    if (const GCodeInfo *g = own(kTurningC)) return g;
    // The codes all systems share, except those C moved (G70-G76 are other codes there).
    if (code10 < 700 || code10 > 760)
      if (const GCodeInfo *g = own(kTurningBoth)) return g;
    return shared(kSharedC);
  }
  const bool b = system == 'B';
  if (const GCodeInfo *g = b ? own(kTurningB) : own(kTurningA)) return g;
  if (const GCodeInfo *g = own(kTurningBoth)) return g;
  return b ? shared(kSharedB) : shared(kSharedA);
}

const GCodeInfo *findGCode(int32_t code10) {
  size_t lo = 0, hi = sizeof(kGCodes) / sizeof(kGCodes[0]);
  while (lo < hi) {
    size_t mid = (lo + hi) / 2;
    if (kGCodes[mid].code10 < code10) lo = mid + 1;
    else hi = mid;
  }
  if (lo < sizeof(kGCodes) / sizeof(kGCodes[0]) && kGCodes[lo].code10 == code10) return &kGCodes[lo];
  return nullptr;
}

// Fanuc / 808D word lists (spec tables 2-14 .. 2-25) and LinuxCNC rs274's, which rejects P and
// Q where its cycle does not read them.
struct CycleWords {
  ModeValue cycle;
  const char *fanuc, *rs274;
};
static const CycleWords kCycleWords[] = {
    {MV::PeckChipBreak, "Q", "Q"}, {MV::TapLeft, "PQ", ""},  {MV::BoreFine, "PQ", ""},
    {MV::Drill, "", ""},           {MV::DrillDwell, "P", "P"}, {MV::Peck, "Q", "Q"},
    {MV::Tap, "PQ", ""},            {MV::BoreFeed, "", ""},  {MV::BoreStop, "", "P"},
    {MV::BoreBack, "PQ", ""},      {MV::BoreDwell, "P", "P"},
};

const char *cycleParamWords(ModeValue cycle, bool rs274) {
  for (auto &c : kCycleWords)
    if (c.cycle == cycle) return rs274 ? c.rs274 : c.fanuc;
  return "";
}

static const MCodeInfo kMCodes[] = {
    {0, MKind::Stop, MGroup::Stop, (int)StopKind::Program},
    {1, MKind::Stop, MGroup::Stop, (int)StopKind::Optional},
    {2, MKind::Stop, MGroup::Stop, (int)StopKind::End},
    {3, MKind::Spindle, MGroup::Spindle, 1},
    {4, MKind::Spindle, MGroup::Spindle, 2},
    {5, MKind::Spindle, MGroup::Spindle, 0},
    {19, MKind::Spindle, MGroup::Spindle, 3},  // LinuxCNC M19 R P Q; 808D: to SD43240
    {6, MKind::ToolChange, MGroup::ToolChange, 0},
    {7, MKind::Coolant, MGroup::Coolant, 7},
    {8, MKind::Coolant, MGroup::Coolant, 8},
    {9, MKind::Coolant, MGroup::Coolant, 9},
    {30, MKind::Stop, MGroup::Stop, (int)StopKind::EndRewind},
    {98, MKind::Call, MGroup::Sub, 0},
    {99, MKind::Return, MGroup::Sub, 0},
    // LinuxCNC's I/O codes (their words: BlockLowerer::Block::ioCode).
    {61, MKind::ToolNumber, MGroup::ToolChange, 0, "set the current tool number", true},  // Q
    {62, MKind::Io, MGroup::Io, 0, "digital output on, synchronized with motion", true},
    {63, MKind::Io, MGroup::Io, 0, "digital output off, synchronized with motion", true},
    {64, MKind::Io, MGroup::Io, 0, "digital output on, immediate", true},
    {65, MKind::Io, MGroup::Io, 0, "digital output off, immediate", true},
    {66, MKind::Io, MGroup::Io, 0, "wait on an input", true},
    {67, MKind::Io, MGroup::Io, 0, "analog output, synchronized with motion", true},
    {68, MKind::Io, MGroup::Io, 0, "analog output, immediate", true},
};

MCodeInfo findMCode(int32_t code, bool rs274) {
  for (auto &m : kMCodes)
    if (m.code == code && (rs274 || !m.rs274Only)) return m;
  return {code, MKind::Aux, MGroup::None, 0};
}

}  // namespace ncc::iso
