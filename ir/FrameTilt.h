// The frame slot of the tilted working plane (Heidenhain cycle 19 and PLANE, runtime/
// ExecutorPlane.cpp, docs/HEIDENHAIN.md "Tilted working plane"): `frame slot=tilt action=set
// tilt=<form> position=<stay|turn|move>` with the form's values in words, `action=cancel` is
// PLANE RESET. Numbered after ir/FrameCopy.h's slot, kept here because nearly every file
// includes ir/MachineCmd.h. In the command the form and positioning sit in sub2's high bits.
//
// Words by form (angles in degrees, lengths in program units):
//   spatial   A B C = SPA SPB SPC (also cycle 19's angles)
//   projected A B C = PROPR PROMIN ROT        euler  A B C = EULPR EULNU EULROT
//   vector    I J K = BX BY BZ, X Y Z = NX NY NZ (directions, no unit)
//   points    X Y Z = P1, I J K = P2, U V W = P3
//   relative  one of A B C = SPA/SPB/SPC, incremental in the active plane
//   axial     A B C = the rotary axes' positions
// and for every form: F the positioning feed (none: rapid), R MOVE's DIST, H MB's retract (P 1:
// MBMAX), Q SEQ (+1/-1), E 1 for TABLE ROT.
#pragma once
#include "ir/FrameCopy.h"

namespace ncc {

constexpr uint8_t kFrameSlotTilt = kFrameSlotCopy + 1;
enum class TiltForm : uint8_t { None, Spatial, Projected, Euler, Vector, Points, Relative, Axial };
enum class TiltMove : uint8_t { Stay, Turn, Move };
constexpr unsigned kTiltFormShift = 8, kTiltMoveShift = 12;
inline TiltForm tiltForm(uint16_t sub2) { return (TiltForm)((sub2 >> kTiltFormShift) & 0xf); }
inline TiltMove tiltMove(uint16_t sub2) { return (TiltMove)((sub2 >> kTiltMoveShift) & 0x3); }

}  // namespace ncc
