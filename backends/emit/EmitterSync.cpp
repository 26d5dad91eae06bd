// The spindle-synchronised records of the emitter: threads (docs/IR.md §9), oriented stops and
// constant surface speed.
#include "backends/emit/EmitterImpl.h"

namespace ncc::emit::detail {

// LinuxCNC: G33 X Y Z K<lead per unit of path>, G33.1 for a rigid tap (its return record is
// the tap's own retract); a chain is refused (rs274 traces every G33 block as a synchronisation
// of its own). Sinumerik: G33 with the lead on the address of the axis that travels most (I X,
// J Y, K Z), SF= the start angle; it runs consecutive G33 blocks as one thread; a rigid tap is
// G331 in and G332 out with the lead on the tool axis' address, after an SPOS.
std::string Emitter::threadRefusal(const MotionRecord &r) const {
  if (st_.target == Target::Nc200) return nc200ThreadRefusal(r);
  if (latheIso()) {  // the 808D/Fanuc lathe's G32 (system B G33)
    if (r.sync == ThreadSync::TapIn || r.sync == ThreadSync::TapOut) return "rigid tapping is not written for lathes";
    return {};
  }
  const bool lcnc = st_.target == Target::ISO && machine_.controller.family == "linuxcnc";
  if (!lcnc && st_.target != Target::Sinumerik)
    return "only LinuxCNC (G33, G33.1: an ISO target of [controller] family \"linuxcnc\") and Sinumerik (G33, G331/G332) are written";
  if (r.sync == ThreadSync::TapIn || r.sync == ThreadSync::TapOut) {
    if (!lcnc && !spindlePositioned_)
      return "a Sinumerik rigid tap (G331/G332) needs the spindle in position control (an oriented stop before it)";
    return {};
  }
  if (lcnc && r.value2 != 0) return "LinuxCNC's G33 has no start angle";
  if (lcnc && threadLeadChange(r) != 0) return "LinuxCNC has no variable-lead thread";
  if (lcnc && r.sync == ThreadSync::Chain)
    return "each LinuxCNC G33 block starts a synchronisation of its own, as rs274 traces it: a chained thread cannot be written";
  if (!lcnc && r.sync == ThreadSync::Index && afterThread_)
    return "Sinumerik chains consecutive G33 blocks: a new synchronisation right after a thread cannot be written";
  return {};
}

void Emitter::thread(const MotionRecord &r) {
  flushPending();
  ensurePosition(r);
  if (st_.target == Target::Nc200) return nc200Thread(r);
  const bool sin = st_.target == Target::Sinumerik;
  if (r.sync == ThreadSync::TapOut && !sin) {  // G33.1 has already come back: only the position follows
    notePosition(r.end, 3);
    return;
  }
  Words w;
  if (r.exactStop && pathMode_ != 1) push(w, code(Code::ExactStopOnce));
  const bool tap = r.sync == ThreadSync::TapIn || r.sync == ThreadSync::TapOut;
  const bool variable = threadLeadChange(r) != 0;  // Sinumerik G34/G35: F the lead change
  const char *g = tap ? (!sin ? "G33.1" : r.sync == ThreadSync::TapIn ? "G331" : "G332")
                      : variable ? (threadLeadChange(r) > 0 ? "G34" : "G35") : "G33";
  if (latheIso()) g = variable ? "G34" : st_.threadCode.c_str();  // the 808D's G34 F K
  if (motion_ != g) push(w, g);
  motion_ = g;
  size_t before = w.size();
  axisWords(r.end, w, r);
  if (w.size() == before) w.push_back("Z" + posText_[2]);  // a zero-length record stays a block
  std::string word;
  if (latheIso()) {
    latheThreadWords(r, w);
  } else if (st_.target == Target::Sinumerik) {
    int main = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(r.end[i] - r.start[i]) > std::fabs(r.end[main] - r.start[main])) main = i;
    if (number(threadAxisLead(r, main), WordClass::Center, std::string(1, kCenterLetters[main]), r, word))
      w.push_back(word);
    if (variable) {  // the change of the main axis' lead per revolution, without its sign
      double ratio = r.value > 0 ? threadAxisLead(r, main) / r.value : 0;
      if (number(std::fabs(threadLeadChange(r)) * ratio, WordClass::Center, "F", r, word)) w.push_back(word);
      feedText_.clear();  // F is no feed here: the next feed move writes its own
    }
    // SF= stays in force (it sets the thread start angle setting data): written on the first
    // thread and when it changes.
    if (!tap && r.sync == ThreadSync::Index && !(r.value2 == startAngle_) && number(r.value2, WordClass::Rotary, "SF=", r, word)) {
      w.push_back(word);
      startAngle_ = r.value2;
    }
  } else if (number(threadPathLead(r), WordClass::Center, "K", r, word)) {
    w.push_back(word);
  }
  writeBlock(w, r.blockNumber);
}

// The 808D/Fanuc lathe thread (seed 001 2.6): F the lead along the axis the executor measures it
// on (Z up to a 45 degree taper, X beyond), Q the start angle of a new synchronisation; a thread
// block without Q right after a thread chains on, so a new one after a thread writes Q0 too. F
// stays the modal feed on the controller. G34 adds K, the lead's change per revolution along the
// same axis (it always starts a synchronisation of its own).
void Emitter::latheThreadWords(const MotionRecord &r, Words &w) {
  const int along = std::fabs(r.end[0] - r.start[0]) <= std::fabs(r.end[2] - r.start[2]) ? 2 : 0;
  std::string word;
  if (number(threadAxisLead(r, along), WordClass::Feed, "F", r, word) && word != feedText_) w.push_back(word), feedText_ = word;
  if (const double dlead = threadLeadChange(r); dlead != 0) {
    const double ratio = r.value > 0 ? threadAxisLead(r, along) / r.value : 0;
    if (number(dlead * ratio, WordClass::Center, "K", r, word)) w.push_back(word);
    return;
  }
  if (r.sync == ThreadSync::Index && (afterThread_ || r.value2 != 0) && number(r.value2, WordClass::Rotary, "Q", r, word))
    w.push_back(word);
}

// An oriented spindle stop at an angle: LinuxCNC `M19 R P [Q]`, Sinumerik `SPOS=ACP|ACN|DC()`.
// Fanuc's M19 turns to the angle of a machine parameter, so no other ISO target can write one.
void Emitter::spindleOrient(const MotionRecord &r) {
  flushPending();
  spindlePositioned_ = true;
  double a = std::fmod(r.value, 360.0);
  if (a < 0) a += 360;  // the same orientation; M19 R takes 0..360
  std::string angle;
  if (!number(a, WordClass::Rotary, "", r, angle)) return;
  if (st_.target == Target::Sinumerik) {
    static const char *ways[] = {"ACP", "ACN", "DC"};
    writeBlock({"SPOS=" + std::string(ways[std::clamp<int64_t>(r.ivalue, 0, 2)]) + "(" + angle + ")"},
               r.blockNumber);
    return;
  }
  if (st_.target != Target::ISO || machine_.controller.family != "linuxcnc") {
    diags_.error(r.loc,
                 "the [" + st_.section + "] emitter writes an oriented spindle stop at an angle only for LinuxCNC "
                 "(M19 R P; Fanuc's M19 turns to a parameter angle): " + printMotionRecord(r),
                 "unsupported-code");
    errors_ = true;
    return;
  }
  Words w{"M19", "R" + angle, "P" + std::to_string(r.ivalue)};
  if (r.value2 > 0) {
    std::string q;
    if (!number(r.value2, WordClass::Dwell, "Q", r, q)) return;
    w.push_back(q);
  }
  writeBlock(w, r.blockNumber);
}

// Constant surface speed (docs/IR.md "spindle_mode"): LinuxCNC `G96 D<limit>` (the limit for that
// G96 only), Sinumerik `G96 LIMS=<limit> SCC[X]` (X the transverse axis the speed follows); the
// S word (m/min) follows from the spindle_speed record into the same block; `G97` for constant
// rpm. ISO lathes: the limit as G50 S (system A) / G92 S (B) in a block of its own, then G96 S.
// Other ISO targets are refused: a Fanuc/808D G96 needs a lathe. The written program's X0 must be
// the spindle axis the surface speed is measured from (r.value2 is in written coordinates here:
// not 0 when a tool X offset or a frame stays in the positions, EmitterFrame.cpp).
void Emitter::spindleMode(const MotionRecord &r) {
  auto refuse = [&](const std::string &why) {
    diags_.error(r.loc, "the [" + st_.section + "] emitter " + why + ": " + printMotionRecord(r), "unsupported-code");
    errors_ = true;
  };
  const bool css = r.ivalue != 0;
  const bool linuxcnc = st_.target == Target::ISO && machine_.controller.family == "linuxcnc";
  const bool latheIso = this->latheIso();
  if (css && !linuxcnc && !latheIso && st_.target != Target::Sinumerik)
    return refuse("writes constant surface speed (G96) only for LinuxCNC, Sinumerik and ISO lathes");
  if (css && std::fabs(r.value2) > 1e-9)
    return refuse("writes positions whose X0 is not the spindle axis constant surface speed measures from "
                  "(it is at written X" + std::to_string(r.value2) + ": a tool X offset or frame kept in the positions)");
  if (r.ivalue == 2) return;
  std::string limit;
  if (r.value > 0 && !number(r.value, WordClass::Speed, "", r, limit)) return;
  // Sinumerik's LIMS and the lathe's G50 S are modal: a limit, once written, cannot be taken back.
  if ((st_.target == Target::Sinumerik || latheIso) && css && speedLimit_ > 0 && !(r.value > 0))
    return refuse(latheIso ? "cannot take back a spindle-speed limit (" + st_.speedLimitCode + " S) once written"
                           : "cannot take back a spindle-speed limit (LIMS) once written");
  if (latheIso && r.value > 0 && r.value != speedLimit_) {  // its own block, before the G96 that uses it
    flushPending();
    writeBlock({st_.speedLimitCode, "S" + limit}, r.blockNumber);
    speedLimit_ = r.value;
  }
  const bool wasCss = cssWritten_;
  cssWritten_ = css;
  if (latheIso && css && wasCss) return;  // a new limit under G96: its block was enough
  if (!css && !wasCss) return;  // constant rpm already (a limit alone, or G97 again)
  // G97 runs before M3-M5 of its block (rs274 order): after a stop it goes in a block of its own.
  if (!css && (pendingGroups_ & (1u << (unsigned)PendingGroup::Spindle))) flushPending();
  addPending(PendingGroup::SpindleMode, css ? "G96" : "G97", r);
  cssNeedsS_ = css && wasCss;
  if (!css || !(r.value > 0) || latheIso) return;
  if (st_.target == Target::Sinumerik) {
    if (r.value != speedLimit_) pending_.push_back("LIMS=" + limit);
    pending_.push_back("SCC[X]");
  } else {
    pending_.push_back("D" + limit);
  }
  speedLimit_ = r.value;
}

}  // namespace ncc::emit::detail
