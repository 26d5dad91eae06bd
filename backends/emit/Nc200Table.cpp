// The Balt-System NC-200 output table (NC-100/110/200/210: one language, seed 003; docs/EMIT.md
// "NC-200"). Seed 003 is a list of changes per software version, not the programmer's manual, so
// it shows few of the words an NC program needs. What it shows is written as it shows it; what it
// does not show is either an ISO 6983 code the machine description can override (marked
// "assumed" below and in docs/EMIT.md) or, where a wrong guess would change the motion, left
// empty: the emitter then refuses the record (`unsupported-code`) instead of guessing.
#include "backends/emit/ControllerTable.h"

namespace ncc::emit {

namespace {

struct Nc200Code {
  Code code;
  const char *word;  // "" = not known from seed 003: the record is refused (or not written: timing only)
};

const Nc200Code kNc200Codes[] = {
    {Code::Rapid, "G0"},           // L481 (also bare "G"), L1092
    {Code::Linear, "G1"},          // L483
    {Code::ArcCW, "G2"},           // L485
    {Code::ArcCCW, "G3"},          // L736
    {Code::Dwell, ""},             // no dwell word in seed 003: refused (code_dwell + dwell_word set it)
    {Code::ExactStopOnce, "G09"},  // L813-820: deceleration to a stop at the block's end
    // The interpolation plane by abscissa and ordinate (L714-723): explicit about the sense of
    // G2/G3 and about which axis I and J belong to. G17 (L1580) is the same as (DPI,X,Y).
    {Code::PlaneXY, "(DPI,X,Y)"},
    {Code::PlaneZX, "(DPI,Z,X)"},
    {Code::PlaneYZ, "(DPI,Y,Z)"},
    {Code::PerMinute, "G94"},      // assumed (ISO 6983); F100 / F500 in the examples are per minute
    {Code::PerRev, "G95"},         // assumed (ISO 6983)
    {Code::InverseTime, ""},       // refused
    {Code::ExactPath, ""},         // path modes: timing only, not written (as on ISO lathes)
    {Code::ExactStop, ""},
    {Code::Continuous, ""},
    {Code::SpindleCW, "M3"},       // L1092, L2094-2099 (M03)
    {Code::SpindleCCW, "M4"},      // L2094-2099 (M04)
    {Code::SpindleStop, "M5"},     // assumed (ISO 6983)
    {Code::FloodOn, "M8"},         // L1092
    {Code::MistOn, "M7"},          // assumed (ISO 6983)
    {Code::CoolantOff, "M9"},      // assumed (ISO 6983)
    {Code::ToolChange, "M6"},      // L1091, L1573
    {Code::ProgramStop, "M0"},     // assumed (ISO 6983)
    {Code::OptionalStop, "M1"},    // assumed (ISO 6983)
    {Code::EndM2, "M2"},           // assumed (ISO 6983)
    {Code::EndM30, "M30"},         // assumed (ISO 6983)
};
static_assert(sizeof(kNc200Codes) / sizeof(kNc200Codes[0]) == (size_t)Code::Count);

}  // namespace

ControllerStyle nc200Style() {
  ControllerStyle s = defaultStyle(Target::ISO);  // the shared number formats, then NC-200's rules
  s.target = Target::Nc200;
  s.section = "emit.nc200";
  for (const Nc200Code &c : kNc200Codes) s.codes[(size_t)c.code] = c.word;
  // The examples write whole numbers without a point (X100, F100, K6, R120, S250) and decimals
  // with one (X-0.5, L5.1): 3 decimals as the other targets, 4 for centres and feeds.
  for (auto &f : s.formats) f.pointOnInteger = false;
  s.centerStyle = CenterStyle::AbsolutePlane;  // L729-740: G3 U-10 V0 I0 J0 from U10 V0
  s.arcStyle = ArcStyle::IJK;
  s.radiusWord = "R";                           // L485: G2Z-20X60R20
  s.helixAllowed = false;                       // no helical interpolation in seed 003
  s.helixTurns = HelixTurns::Split;
  s.maxArcSweep = 180;                          // a full circle (start = end) is two half circles
  s.dwellWord.clear();
  s.toolOffsetWord.clear();
  // T<tool>.<offset> (L1091 "T5.5"): offset 0, since the positions hold the tool's length and
  // offsets (assumed: offset 0 is none, as ISO lathes' T0500).
  s.toolSuffix = ".0";
  s.commentStyle = CommentStyle::Semicolon;     // assumed: ';' comments as in the PGCFIL/PLC listings (L285-306)
  s.messageStyle = MessageStyle::Comment;       // no operator-message code in seed 003
  s.planeOwnBlock = true;                       // three-letter codes stand alone in the examples
  s.numbering = Numbering::Renumber;            // N1, N2 … as in the examples (L481-487)
  s.blockStart = 1;
  s.blockStep = 1;
  s.programHeader.clear();
  s.programFooter.clear();
  s.programNumber = false;
  // Absolute positions from the first block, in origin 1 (the source's G54): the machine's reset
  // selects the zero origin (L1706-1708). Units: the controller's (PGCFIL G70=0: mm); seed 003
  // does not say which of G70/G71 is inch, so none is written.
  s.setup = {"G90 G94", "(DPI,X,Y)", "(UAO,1)"};
  s.setupPlane = Plane::XY;
  s.unverifiedNote =
      "ncc: NC-200 program (NC-100/110/200/210), UNVERIFIED: ncc has no NC-200 front end to read it back; "
      "metric controller (PGCFIL G70=0); origins (UAO,n) = the machine file's [offsets]";
  return s;
}

// A lathe: the plane is Z (abscissa) and X (ordinate) as in the examples (G34 Z-50 K5 along the
// abscissa, X0 K-5 along the ordinate, L886-911); X words are diameters under diameter programming
// (the profile of L479-487 closes only with X as a diameter and R as a radius). With diameters,
// arcs are written in the R form of that example, in pieces of at most 90 degrees (the sign of R
// beyond 180 degrees and whether J is a diameter are not in seed 003).
bool applyNc200Lathe(const Machine &m, ControllerStyle &s, Diagnostics &) {
  s.lathe = true;
  s.setupPlane = Plane::ZX;
  s.xScale = m.controller.diameterProgramming ? 2 : 1;
  s.setup = {"G90 G94", "(DPI,Z,X)", "(UAO,1)"};
  if (m.controller.diameterProgramming) {
    s.arcStyle = ArcStyle::R;
    s.maxArcSweep = 90;
  }
  return true;
}

}  // namespace ncc::emit
