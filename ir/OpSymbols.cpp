#include "ir/OpSymbols.h"
#include "ir/FrameTilt.h"
#include "ir/MachineCmd.h"

#include <iterator>

namespace ncc::ir {

static const OpSymbol kOpSymbols[] = {
    {OpKind::Spindle, "dir", "cw", 1},
    {OpKind::Spindle, "dir", "ccw", 2},
    {OpKind::Spindle, "dir", "stop", 0},
    {OpKind::Spindle, "dir", "orient", 3},
    {OpKind::Spindle, "way", "cw", 0},
    {OpKind::Spindle, "way", "ccw", 1},
    {OpKind::Spindle, "way", "shortest", 2},
    {OpKind::Speed, "mode", "rpm", 1},
    {OpKind::Speed, "mode", "css", 2},
    {OpKind::Speed, "after_css", "keep", 0},  // sub2
    {OpKind::Speed, "after_css", "error", 1},
    {OpKind::Coolant, "flood", "on", 0},
    {OpKind::Coolant, "flood", "off", 1},
    {OpKind::Coolant, "mist", "on", 0},
    {OpKind::Coolant, "mist", "off", 1},
    {OpKind::CutterComp, "side", "off", 0},
    {OpKind::CutterComp, "side", "left", 1},
    {OpKind::CutterComp, "side", "right", 2},
    {OpKind::CutterComp, "d_default", "modal", 0},
    {OpKind::CutterComp, "d_default", "tool", 1},
    {OpKind::CutterComp, "entry", "corner", 0},
    {OpKind::CutterComp, "entry", "normal", 1},
    {OpKind::Message, "kind", "msg", (uint8_t)MessageKind::Msg},
    {OpKind::Message, "kind", "debug", (uint8_t)MessageKind::Debug},
    {OpKind::Message, "kind", "print", (uint8_t)MessageKind::Print},
    {OpKind::Message, "kind", "abort", (uint8_t)MessageKind::Abort},
    {OpKind::Message, "kind", "not_simulated", (uint8_t)MessageKind::NotSimulated},
    {OpKind::Stop, "kind", "program", (uint8_t)StopKind::Program},
    {OpKind::Stop, "kind", "optional", (uint8_t)StopKind::Optional},
    {OpKind::Stop, "kind", "end", (uint8_t)StopKind::End},
    {OpKind::Stop, "kind", "end_rewind", (uint8_t)StopKind::EndRewind},
    {OpKind::SetOffset, "kind", "g92", (uint8_t)SetOffsetKind::G92},
    {OpKind::SetOffset, "kind", "g92_1", (uint8_t)SetOffsetKind::G92Cancel},
    {OpKind::SetOffset, "kind", "g92_2", (uint8_t)SetOffsetKind::G92Suspend},
    {OpKind::SetOffset, "kind", "g92_3", (uint8_t)SetOffsetKind::G92Restore},
    {OpKind::SetOffset, "kind", "g10l2", (uint8_t)SetOffsetKind::G10L2},
    {OpKind::SetOffset, "kind", "g10l20", (uint8_t)SetOffsetKind::G10L20},
    {OpKind::SetOffset, "kind", "g28_1", (uint8_t)SetOffsetKind::StoreHome1},
    {OpKind::SetOffset, "kind", "g30_1", (uint8_t)SetOffsetKind::StoreHome2},
    {OpKind::SetOffset, "kind", "g52", (uint8_t)SetOffsetKind::G52},
    {OpKind::SetOffset, "kind", "tool_set", (uint8_t)SetOffsetKind::ToolSet},
    {OpKind::SetOffset, "kind", "tool_touch", (uint8_t)SetOffsetKind::ToolTouch},
    {OpKind::SetOffset, "kind", "tool_touch_g593", (uint8_t)SetOffsetKind::ToolTouchG593},
    {OpKind::SetOffset, "kind", "tool_length", (uint8_t)SetOffsetKind::ToolLength},
    {OpKind::SetOffset, "kind", "tool_length_wear", (uint8_t)SetOffsetKind::ToolLengthWear},
    {OpKind::SetOffset, "kind", "tool_radius", (uint8_t)SetOffsetKind::ToolRadius},
    {OpKind::SetOffset, "kind", "tool_radius_wear", (uint8_t)SetOffsetKind::ToolRadiusWear},
    {OpKind::SetOffset, "kind", "lathe_tool", (uint8_t)SetOffsetKind::LatheTool},
    {OpKind::SetOffset, "kind", "deldl", (uint8_t)SetOffsetKind::DeleteAdditive},
    {OpKind::Aux, "input", "digital", 0},
    {OpKind::Aux, "input", "analog", 1},
    {OpKind::ToolLength, "form", "table", (uint8_t)ToolLengthForm::Table},
    {OpKind::ToolLength, "form", "dynamic", (uint8_t)ToolLengthForm::Dynamic},
    {OpKind::ToolLength, "form", "add", (uint8_t)ToolLengthForm::Add},
    {OpKind::Frame, "slot", "local", (uint8_t)FrameSlot::Local},
    {OpKind::Frame, "slot", "rotation", (uint8_t)FrameSlot::Rotation},
    {OpKind::Frame, "slot", "scale", (uint8_t)FrameSlot::Scale},
    {OpKind::Frame, "slot", "mirror", (uint8_t)FrameSlot::Mirror},
    {OpKind::Frame, "slot", "copy", kFrameSlotCopy},
    {OpKind::Frame, "slot", "tilt", kFrameSlotTilt},
    {OpKind::Frame, "tilt", "spatial", (uint8_t)TiltForm::Spatial},
    {OpKind::Frame, "tilt", "projected", (uint8_t)TiltForm::Projected},
    {OpKind::Frame, "tilt", "euler", (uint8_t)TiltForm::Euler},
    {OpKind::Frame, "tilt", "vector", (uint8_t)TiltForm::Vector},
    {OpKind::Frame, "tilt", "points", (uint8_t)TiltForm::Points},
    {OpKind::Frame, "tilt", "relative", (uint8_t)TiltForm::Relative},
    {OpKind::Frame, "tilt", "axial", (uint8_t)TiltForm::Axial},
    {OpKind::Frame, "position", "stay", (uint8_t)TiltMove::Stay},
    {OpKind::Frame, "position", "turn", (uint8_t)TiltMove::Turn},
    {OpKind::Frame, "position", "move", (uint8_t)TiltMove::Move},
    {OpKind::Frame, "action", "set", (uint8_t)FrameAction::Set},
    {OpKind::Frame, "action", "cancel", (uint8_t)FrameAction::Cancel},
    {OpKind::Frame, "action", "step", kFrameActionStep},
    {OpKind::Frame, "form", "plane", 0},
    {OpKind::Frame, "form", "axis", kFrameFormAxis},
    {OpKind::Frame, "combine", "refuse", 0},
    {OpKind::Frame, "combine", "ordered", kFrameCombine},
    {OpKind::Contour, "action", "data", (uint8_t)ContourAction::Data},
    {OpKind::Contour, "action", "begin", (uint8_t)ContourAction::Begin},
    {OpKind::Contour, "action", "end", (uint8_t)ContourAction::End},
    {OpKind::Contour, "use", "finish", (uint8_t)ContourUse::Finish},
    {OpKind::Contour, "use", "rough_z", (uint8_t)ContourUse::RoughAlongZ},
    {OpKind::Contour, "use", "rough_x", (uint8_t)ContourUse::RoughAlongX},
    {OpKind::Contour, "use", "pattern", (uint8_t)ContourUse::PatternRepeat},
    {OpKind::Contour, "action", "run", (uint8_t)ContourAction::Run},
    {OpKind::Contour, "use", "outline", (uint8_t)ContourUse::Outline},
    {OpKind::Contour, "use", "island", (uint8_t)ContourUse::Island},
    {OpKind::Contour, "use", "pocket", (uint8_t)ContourUse::Pocket},
    {OpKind::Contour, "use", "subcontour", (uint8_t)ContourUse::Sub},
    {OpKind::Contour, "use", "pilot", (uint8_t)ContourUse::Pilot},
    {OpKind::Contour, "use", "floor", (uint8_t)ContourUse::Floor},
    {OpKind::Contour, "use", "side", (uint8_t)ContourUse::Side},
    {OpKind::Contour, "use", "train", (uint8_t)ContourUse::Train},
    {OpKind::Contour, "use", "rs274_finish", (uint8_t)ContourUse::Rs274Finish},
    {OpKind::Contour, "use", "rs274_rough_z", (uint8_t)ContourUse::Rs274RoughZ},
    {OpKind::Contour, "use", "rs274_rough_x", (uint8_t)ContourUse::Rs274RoughX},
    {OpKind::Contour, "use", "keep", (uint8_t)ContourUse::Keep},
    {OpKind::Contour, "use", "sin_table", (uint8_t)ContourUse::SinTable},
    {OpKind::Cycle, "action", "run", (uint8_t)CycleAction::Run},
    {OpKind::Cycle, "action", "define", (uint8_t)CycleAction::Define},
    {OpKind::Cycle, "action", "modal", (uint8_t)CycleAction::Modal},
    {OpKind::Cycle, "action", "call", (uint8_t)CycleAction::Call},
    {OpKind::Cycle, "action", "cancel", (uint8_t)CycleAction::Cancel},
    {OpKind::Cycle, "action", "trigger", (uint8_t)CycleAction::Trigger},
    {OpKind::Goto, "dir", "forward", 0},
    {OpKind::Goto, "dir", "backward", 1},
    {OpKind::Goto, "dir", "any", 2},
    {OpKind::Call, "frame", "new", 0},
    {OpKind::Call, "frame", "shared", 1},
    {OpKind::Declare, "type", "int", 0},
    {OpKind::Declare, "type", "real", 1},
    {OpKind::Declare, "type", "bool", 2},
    {OpKind::Declare, "type", "char", 3},
    {OpKind::Declare, "type", "string", 4},
    {OpKind::Declare, "type", "symbol", 5},
    {OpKind::Declare, "type", "axis", 6},
    {OpKind::Declare, "type", "frame", 7},
};

const OpSymbol *opSymbols(size_t &count) {
  count = std::size(kOpSymbols);
  return kOpSymbols;
}

std::string opSymbolValues(OpKind op, std::string_view key) {
  std::string out;
  for (auto &s : kOpSymbols)
    if (s.op == op && key == s.key) (out += out.empty() ? "" : " ") += s.value;
  return out;
}

bool opSymbolCode(OpKind op, std::string_view key, std::string_view value, uint8_t &code) {
  for (auto &s : kOpSymbols)
    if (s.op == op && key == s.key && value == s.value) return code = s.code, true;
  return false;
}

const char *opSymbolName(OpKind op, std::string_view key, uint8_t code) {
  for (auto &s : kOpSymbols)
    if (s.op == op && key == s.key && s.code == code) return s.value;
  return "?";
}

}  // namespace ncc::ir
