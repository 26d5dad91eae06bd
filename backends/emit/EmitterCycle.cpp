// Sinumerik: a library cycle's bracket (cycle_begin "sin.CYCLE81" …, runtime/ExecutorCycle.cpp)
// written back as the native call instead of its expanded moves (docs/EMIT.md "Cycles"). The
// entry's absolute positions (CycleDef::coords) move by the bracket's machine-minus-program shift
// (mx my mz) less what the written program's offsets add (EmitterFrame.cpp adjusts mx my mz
// before this sees the bracket); a bracket under a rotation, scaling or
// mirror (frame=1), with a mode parameter set, or of an entry without coords keeps its moves.
#include "backends/emit/EmitterImpl.h"
#include "runtime/Geometry.h"
#include "runtime/cycles/Library.h"

#include <fmt/format.h>

namespace ncc::emit::detail {

namespace {
// Mode parameters change what the positions mean (incremental depths, another plane, another
// tool axis): a call with one set is not written back.
bool modeParam(std::string_view name) { return name.find("MODE") != std::string_view::npos || name == "_AXN"; }

// The shift of `name` in the entry's coords ("RTP:n …"): the axis role, 0 when not a position.
char coordRole(const CycleDef &d, std::string_view name) {
  std::string_view c = d.coords;
  for (size_t i = 0; i < c.size();) {
    size_t j = std::min(c.find(' ', i), c.size());
    std::string_view item = c.substr(i, j - i);
    if (item.size() > 2 && item.substr(0, item.size() - 2) == name) return item.back();
    i = j + 1;
  }
  return 0;
}
}  // namespace

// The argument list of `d` from the bracket (keys prefixed for a pattern), or false when the
// call cannot be written back exactly.
bool Emitter::cycleArguments(const MotionRecord &r, const CycleDef &d, const char *prefix, std::string &out) {
  if (!d.coords) return false;
  // STRING arguments follow the name in the bracket's text: "sin.HOLES1+sin.CYCLE81|p_HIDE=2,4".
  auto textArg = [&](std::string_view key, std::string &value) {
    std::string_view t = r.text;
    for (size_t bar = t.find('|'); bar != std::string_view::npos; bar = t.find('|', bar + 1)) {
      std::string_view item = t.substr(bar + 1, t.find('|', bar + 1) - bar - 1);
      if (item.substr(0, key.size()) == key && item.size() > key.size() && item[key.size()] == '=') {
        value = std::string(item.substr(key.size() + 1));
        return true;
      }
    }
    return false;
  };
  const ncc::PlaneAxes ax = ncc::planeAxes(plane_);
  std::vector<std::string> args;
  size_t used = 0;
  for (std::string_view name : cycleParamNames(d)) {
    const double *v = r.param(prefix + std::string(name));
    args.emplace_back();
    if (std::string text; textArg(prefix + std::string(name), text)) {
      if (text.find('"') != std::string::npos) return false;
      args.back() = "\"" + text + "\"";
      used = args.size();
      continue;
    }
    if (!v) continue;
    if (modeParam(name) && *v != 0) return false;
    double value = *v;
    if (char role = coordRole(d, name)) {
      int axis = role == 'n' ? ax.n : role == 'u' ? ax.u : ax.v;
      const double *m = r.param(std::string("m") + (char)('x' + axis));
      value += (m ? *m : 0) * (role == 'd' ? 2 : 1);  // 'd': a diameter along v (the lathe cycles' X)
    }
    NumberFormat f;
    f.decimals = 6;  // parameters keep more digits than the axes: a depth or an angle
    if (!formatNumber(value, f, args.back())) return false;
    used = args.size();
  }
  args.resize(used);  // trailing omitted parameters are left out, inner ones stay empty
  out = std::string(d.name + 4) + "(";
  for (size_t i = 0; i < args.size(); ++i) out += (i ? ", " : "") + args[i];
  out += ")";
  return true;
}

bool Emitter::nativeCycle(const MotionRecord &r) {
  // The call runs where the tool is: the written program must know that position.
  if (st_.target != Target::Sinumerik || r.param("frame") || !posKnown_) return false;
  std::string_view text = std::string_view(r.text).substr(0, r.text.find('|'));
  size_t plus = text.find('+');
  const CycleDef *pattern = plus != std::string_view::npos || (findCycle(text) && findCycle(text)->positions)
                                ? findCycle(text.substr(0, plus)) : nullptr;
  const CycleDef *cycle = plus != std::string_view::npos ? findCycle(text.substr(plus + 1)) : pattern ? nullptr : findCycle(text);
  if ((!pattern && !cycle) || (plus != std::string_view::npos && (!pattern || !cycle)))
    return false;
  for (const CycleDef *d : {pattern, cycle})
    if (d && std::string_view(d->name).substr(0, 4) != "sin.") return false;
  std::string call, positions;
  if ((cycle && !cycleArguments(r, *cycle, "", call)) || (pattern && !cycleArguments(r, *pattern, "p", positions)))
    return false;
  flushPending();
  if (cycle && haveProgrammedFeed_) {  // the cycle drills at the modal F
    Words w;
    feedWord(r, w, 0);
    if (!w.empty()) writeBlock(w, -1);
  }
  if (pattern && cycle) {
    writeBlock({"MCALL " + call}, r.blockNumber);
    writeBlock({positions}, -1);
    writeBlock({"MCALL"}, -1);
  } else {
    writeBlock({cycle ? call : positions}, r.blockNumber);
  }
  skipped_.active = true;
  return true;
}

// Inside a cycle written as its call: the records are the call's, only its end position counts.
void Emitter::skipCycleRecord(const MotionRecord &r) {
  if (AxisVec end; skipped_.closes(r, end)) notePosition(end, kAxes);
}

}  // namespace ncc::emit::detail
