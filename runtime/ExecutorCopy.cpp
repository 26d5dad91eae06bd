// The 808D's contour repetition G72.1 / G72.2 (seed001 §2.16, manual L9988-10114; the front end's
// lowering is in frontend/iso/LowerCalls.cpp, the rules in docs/ISO-WORDS.md): the frame slot
// `copy`, innermost on the program side, holds k times the step while copy k of the subprogram
// runs. The step is a rotation about the active plane's normal through the centre the G72.1
// block names, or the shift I J K of G72.2.
//
// Unlike the other programmable-frame slots it may change with cutter compensation on: it only
// rotates or shifts (never mirrors or scales), and compensation works on the machine path
// (pathOut), so the side and the offset stay what they are. The manual's examples (figures 2-53
// and 2-54) repeat a contour under G41.
#include "runtime/ExecutorImpl.h"
#include "ir/FrameCopy.h"

namespace ncc {

bool Executor::Impl::execCopyFrame(const MachineCmd &c, int action) {
  if (action == (int)FrameAction::Set) {
    if (pf.copyOn)
      return error("G72.1/G72.2 in a program that G72.1/G72.2 repeats: the 808D manual does not describe nested "
                   "contour repetition",
                   "unsupported-code");
    pf.clearCopy();
    if (c.has(Word::R)) {
      const PlaneAxes ax = planeAxes(plane());
      if (!c.has((Word)ax.u) || !c.has((Word)ax.v))
        return error(std::string("G72.1 needs the centre of the rotation in the active plane: ") + kWordKeys[ax.u] +
                         " and " + kWordKeys[ax.v],
                     "missing-word");
      // The manual gives the centre as a point ("base point"), not a distance: in G91 it would be
      // relative to what? Refused rather than guessed.
      if (st.distance == ModeValue::Incremental)
        return error("G72.1 in G91: the manual does not say whether the centre X Y is incremental; program it in G90",
                     "unsupported-code");
      pf.copyAxis[ax.n] = 1;
      for (int i = 0; i < 3; ++i) pf.copyCentre[i] = c.has((Word)i) ? c.get((Word)i) * axisScale(i) : 0;
      pf.copyAngle = c.get(Word::R);
    }
    static const Word kShift[] = {Word::I, Word::J, Word::K};  // along X Y Z whatever the plane
    for (int i = 0; i < 3; ++i)
      if (c.has(kShift[i])) pf.copyShift[i] = c.get(kShift[i]) * axisScale(i);
    pf.copyOn = true;
  } else if (action == kFrameActionStep) {
    if (!pf.copyOn) return error("frame slot=copy action=step without a G72.1/G72.2 in force", "bad-command");
    ++pf.copyIndex;
  } else if (action == (int)FrameAction::Cancel) {
    pf.clearCopy();
  } else {
    return error("bad frame action", "bad-command");
  }
  pf.update();
  return true;
}

}  // namespace ncc
