// Static lint rules on NC IR. Rules that need run-time state (motion without feed, arc end
// point off the circle, compensation without D) are reported by the executor while the
// program runs; `ncc lint` runs both.
#include "ir/ModeTable.h"
#include "passes/Pass.h"
#include "runtime/Geometry.h"

#include <fmt/format.h>

#include <cmath>

#include <set>

namespace ncc {
using namespace ir;

namespace {
struct Targets {
  std::set<int64_t> numbers;
  std::set<std::string> labels;
  bool anyNumber = false;  // a computed goto n=: every numbered block may be its target
};

void collectTargets(const Region &r, Targets &t) {
  for (const Op &op : r) {
    if (op.kind == OpKind::Goto) {
      if (const Expr *n = op.get("n"); n && n->kind == ExprKind::Number) t.numbers.insert((int64_t)n->num);
      else if (n) t.anyNumber = true;
      if (const Expr *l = op.get("label")) t.labels.insert(l->str);
    }
    for (auto &sub : op.regions) collectTargets(sub, t);
  }
}

bool isTarget(const Op &op, const Targets &t) {
  if (op.kind == OpKind::Label) return true;
  if (op.kind == OpKind::Block)
    if (const Expr *n = op.get("n"); n && (t.anyNumber || t.numbers.count((int64_t)n->num))) return true;
  return false;
}

bool endsProgram(const Op &op) {
  if (op.kind != OpKind::Stop) return false;
  const Expr *k = op.get("kind");
  return k && (k->str == "end" || k->str == "end_rewind");
}

void lintRegion(const Region &r, const Targets &t, bool isMain, Diagnostics &diags) {
  // After an unconditional transfer, code up to the next jump target never runs.
  const char *dead = nullptr;
  bool reported = false;  // report the first block of each dead stretch only
  for (const Op &op : r) {
    if (dead && isTarget(op, t)) dead = nullptr;
    if (dead && !reported && op.kind == OpKind::Block) {
      if (std::string_view(dead) == "code-after-end")
        diags.warning(op.loc, "code after the end of the program (M2/M30) is never executed", dead);
      else
        diags.warning(op.loc, "block is unreachable", dead);
      reported = true;
    }
    if (!dead) {
      reported = false;
      if (op.kind == OpKind::Goto || op.kind == OpKind::Return) dead = "unreachable-block";
      else if (isMain && endsProgram(op)) dead = "code-after-end";
    }
    for (auto &sub : op.regions) lintRegion(sub, t, false, diags);
  }
}
// R-form arcs that cannot reach their end point, found without running the program, so arcs
// in branches a run does not take are checked too. Follows straight-line code only: positions
// are known after constant absolute words and lost at anything that may change them
// unseen (jump targets, calls, loops, offsets, non-constant words).
class RArcCheck {
public:
  explicit RArcCheck(Diagnostics &d, const Targets &t) : diags_(d), targets_(t) {}

  // The function body: finds the modes that hold at every jump target first.
  void function(const Region &body) {
    for (const char *key : {"units", "plane", "distance"}) stableMode(body, key);
    region(body);
  }

  void region(const Region &r) {
    forget();
    for (const Op &op : r) {
      this->op(op);
      for (auto &sub : op.regions) {
        RArcCheck inner(*this);
        inner.region(sub);
      }
      if (!op.regions.empty()) {  // a branch or loop may have moved the tool
        forget();
        if (changesModes(op)) units_ = plane_ = motion_ = distance_ = ModeValue::Count;
      }
    }
  }

private:
  Diagnostics &diags_;
  const Targets &targets_;
  double pos_[3] = {};
  bool known_[3] = {};
  // Count = not known here.
  ModeValue units_ = ModeValue::MM, plane_ = ModeValue::XY, motion_ = ModeValue::Count,
            distance_ = ModeValue::Absolute;

  // Per key: the one value the function ever sets, when it is set at the top level before any
  // jump can happen (so every jump target sees it); Count otherwise.
  ModeValue stable_[3] = {ModeValue::Count, ModeValue::Count, ModeValue::Count};

  void forget() { known_[0] = known_[1] = known_[2] = false; }

  static void collectModes(const Region &r, const char *key, std::set<ModeValue> &values) {
    for (const Op &op : r) {
      if (op.kind == OpKind::Mode)
        if (const Expr *e = op.get(key); e) {
          ModeValue v;
          if (modeValueFromName(e->str, v)) values.insert(v);
        }
      for (auto &sub : op.regions) collectModes(sub, key, values);
    }
  }
  static bool changesModes(const Op &op) {
    if (op.kind == OpKind::Mode || op.kind == OpKind::Call) return true;
    for (auto &sub : op.regions)
      for (const Op &o : sub)
        if (changesModes(o)) return true;
    return false;
  }
  void stableMode(const Region &body, const char *key) {
    int slot = key[0] == 'u' ? 0 : key[0] == 'p' ? 1 : 2;
    static const ModeValue kDefault[] = {ModeValue::MM, ModeValue::XY, ModeValue::Absolute};
    std::set<ModeValue> values;
    collectModes(body, key, values);
    if (values.empty()) {
      stable_[slot] = kDefault[slot];
      return;
    }
    if (values.size() != 1) return;
    for (const Op &op : body) {
      if (op.kind == OpKind::Goto || op.kind == OpKind::Label || op.kind == OpKind::Call || !op.regions.empty())
        return;  // a jump may come before the setting
      if (op.kind == OpKind::Mode && op.get(key)) {
        stable_[slot] = *values.begin();
        return;
      }
    }
  }

  void op(const Op &op) {
    switch (op.kind) {
    case OpKind::Block:
      if (isTarget(op, targets_)) {  // reached by jumps too
        forget();
        units_ = stable_[0], plane_ = stable_[1], distance_ = stable_[2], motion_ = ModeValue::Count;
      }
      return;
    case OpKind::Comment: case OpKind::Message: case OpKind::Feed: case OpKind::Speed:
    case OpKind::ToolSelect: case OpKind::ToolChange: case OpKind::Spindle: case OpKind::Coolant:
    case OpKind::Dwell: case OpKind::CutterComp: case OpKind::Stop: case OpKind::Aux:
    case OpKind::Assign: case OpKind::Declare:
      return;
    case OpKind::Mode:
      for (auto &a : op.args) {
        ModeValue v;
        if (!a.value || !modeValueFromName(a.value->str, v)) continue;
        // LinuxCNC G5/G5.1 give the motion mode before them back after their block.
        if (a.key == "motion") {
          if (v != ModeValue::SplineCubic && v != ModeValue::SplineQuadratic) motion_ = v;
        }
        else if (a.key == "plane") plane_ = v;
        else if (a.key == "units") units_ = v, forget();
        else if (a.key == "distance") distance_ = v;
      }
      return;
    case OpKind::Move: move(op); return;
    default: forget(); return;  // offsets, homing, calls, jumps, labels, …
    }
  }

  void move(const Op &op) {
    static const char *kAxis[] = {"X", "Y", "Z"};
    double start[3];
    bool startKnown[3];
    for (int i = 0; i < 3; ++i) start[i] = pos_[i], startKnown[i] = known_[i];
    for (int i = 0; i < 3; ++i) {
      const Expr *e = op.get(kAxis[i]);
      if (!e) continue;
      bool inc = distance_ == ModeValue::Incremental;
      if (e->kind != ExprKind::Number || distance_ == ModeValue::Count || (inc && !known_[i])) {
        known_[i] = false;
        continue;
      }
      pos_[i] = inc ? pos_[i] + e->num : e->num;
      known_[i] = true;
    }
    const Expr *r = op.get("R");
    bool arc = motion_ == ModeValue::ArcCW || motion_ == ModeValue::ArcCCW;
    if (!arc || !r || r->kind != ExprKind::Number || units_ == ModeValue::Count || plane_ == ModeValue::Count)
      return;
    int a1 = plane_ == ModeValue::ZX ? 2 : plane_ == ModeValue::YZ ? 1 : 0;
    int a2 = plane_ == ModeValue::ZX ? 0 : plane_ == ModeValue::YZ ? 2 : 1;
    if (!startKnown[a1] || !startKnown[a2] || !known_[a1] || !known_[a2]) return;
    double scale = units_ == ModeValue::Inch ? 25.4 : 1.0;
    double half = std::hypot(pos_[a1] - start[a1], pos_[a2] - start[a2]) * scale / 2;
    if (half - std::fabs(r->num) * scale > kArcRadiusSlackMM)
      diags_.error(op.loc, "Arc radius too small to reach end point", "arc-radius-too-small");
  }
};

}  // namespace

bool runLint(Module &m, Diagnostics &diags, PassContext &) {
  for (size_t i = 0; i < m.functions.size(); ++i) {
    Targets t;
    collectTargets(m.functions[i].body, t);
    lintRegion(m.functions[i].body, t, i == 0, diags);
    RArcCheck(diags, t).function(m.functions[i].body);
  }
  return true;
}

}  // namespace ncc
