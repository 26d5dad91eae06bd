// NC-200 threads: G34 (seed 003 §12.1, L741-911; docs/EMIT.md "NC-200"). A thread record is
// one `G34 X Z K±pitch [I±change] [R angle]` block:
//  * K is the pitch along the abscissa (Z on a lathe, K positive) or the ordinate (X, K negative),
//    whichever the taper travels more along (L767-778); unlike G33 it is measured along that axis,
//    not along the cone (L780-785), which is the Motion IR's axis lead (threadAxisLead);
//  * I is the pitch change per revolution along the same axis (L793-796), and a shrinking pitch
//    must not reach zero before the end: |I| <= K^2 / (2 (ZK - ZN)) (L841-862);
//  * R is the start angle after the spindle's zero, which makes multi-start threads from one
//    start point (L798-801, L864-884);
//  * consecutive G34 blocks are one thread (the cylinder-then-cone of figure 12.4, L906-909), so a
//    chained record is a G34 block without R, and a new synchronisation right after a thread
//    cannot be written;
//  * G09 may stand in the thread block (L813-820): the record's exact stop.
// Milling machines (the pitch "always positive", L787-788, along an axis the seed does not name),
// rigid tapping, a 45 degree taper (neither axis travels more) and Y motion are refused.
#include "backends/emit/EmitterImpl.h"

namespace ncc::emit::detail {

namespace {

// The axis G34's pitch is measured along on a lathe: 2 (Z, the abscissa) or 0 (X, the ordinate);
// -1 when both travel the same.
int pitchAxis(const MotionRecord &r) {
  double dz = std::fabs(r.end[2] - r.start[2]), dx = std::fabs(r.end[0] - r.start[0]);
  return dz > dx ? 2 : dx > dz ? 0 : -1;
}

// The pitch change per revolution along the pitch axis (the record's own is along its lead axis;
// on a straight move every axis' lead is the same multiple of it).
double pitchChange(const MotionRecord &r, int axis) {
  return r.value > 0 ? threadLeadChange(r) * threadAxisLead(r, axis) / r.value : 0;
}

}  // namespace

std::string Emitter::nc200ThreadRefusal(const MotionRecord &r) const {
  if (!st_.lathe)
    return "seed 003 gives G34's pitch axis for lathes only (on a milling machine the pitch is 'always positive', "
           "along an axis it does not name)";
  if (r.sync == ThreadSync::TapIn || r.sync == ThreadSync::TapOut) return "rigid tapping is not in seed 003";
  if (r.end[1] != r.start[1]) return "a lathe's G34 moves in Z and X only";
  const int axis = pitchAxis(r);
  if (axis < 0)
    return "a 45 degree taper: G34's K sign follows the axis the taper travels more along, and neither does";
  if (r.sync == ThreadSync::Index && afterThread_)
    return "consecutive G34 blocks run as one thread: a new synchronisation right after a thread cannot be written";
  if (threadLeadChange(r) < 0) {
    // The written (rounded) K and I must pass the controller's check.
    const int d = fmt(WordClass::Center).decimals;
    const double k = roundTo(threadAxisLead(r, axis), d), i = roundTo(pitchChange(r, axis), d);
    const double length = std::fabs(r.end[axis] - r.start[axis]);
    if (length > 0 && -i > k * k / (2 * length))
      return "the shrinking pitch breaks the controller's rule |I| <= K^2 / (2 (ZK - ZN)) after rounding";
  }
  return {};
}

void Emitter::nc200Thread(const MotionRecord &r) {
  const int axis = pitchAxis(r);
  Words w;
  if (r.exactStop && pathMode_ != 1) push(w, code(Code::ExactStopOnce));
  w.push_back("G34");  // in every thread block, as the seed writes it
  motion_ = "G34";
  size_t before = w.size();
  axisWords(r.end, w, r);
  if (w.size() == before) w.push_back("Z" + posText_[2]);  // a zero-length record stays a block
  std::string word;
  // K is required in every G34 block (L790-791); its sign names the axis.
  if (number((axis == 2 ? 1 : -1) * threadAxisLead(r, axis), WordClass::Center, "K", r, word)) w.push_back(word);
  if (threadLeadChange(r) != 0 && number(pitchChange(r, axis), WordClass::Center, "I", r, word)) w.push_back(word);
  if (r.sync == ThreadSync::Index && r.value2 != 0 && number(r.value2, WordClass::Rotary, "R", r, word))
    w.push_back(word);
  writeBlock(w, r.blockNumber);
}

}  // namespace ncc::emit::detail
