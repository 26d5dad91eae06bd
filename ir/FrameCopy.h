// The frame slot of the 808D's contour repetition G72.1 / G72.2 (frontend/iso/LowerCopy.cpp,
// runtime/ExecutorCopy.cpp): `frame slot=copy` is the innermost slot, on the program side.
// `action=set` starts a repetition with its step (R degrees about the active plane's normal
// through X Y Z, or the shift I J K) at copy 0, `action=step` moves to the next copy (k times
// the step), `action=cancel` ends it. Numbered after ir/MachineCmd.h's FrameSlot and
// FrameAction, kept here because nearly every file includes that header.
#pragma once
#include "ir/MachineCmd.h"

namespace ncc {

constexpr uint8_t kFrameSlotCopy = (uint8_t)FrameSlot::Count;
constexpr uint8_t kFrameActionStep = (uint8_t)FrameAction::Set + 1;

}  // namespace ncc
