// Structure-keeping translation: blocks, modal codes, control flow and subprograms from the NC IR
// (docs/EMIT.md "Structure-keeping translation"). One line per source block where the target
// allows it; statements (assignments, control) take a line of their own in the block's order.
#include "backends/emit/StructuredImpl.h"
#include "backends/emit/WordFormat.h"
#include "runtime/WorkOffsetCode.h"

#include <fmt/format.h>

#include <cmath>
#include <string_view>

namespace ncc::emit::structured {

using ir::ExprKind;
using ir::OpKind;

// ---------------------------------------------------------------- tables
struct ModeCode {
  const char *group, *value, *iso, *sinumerik;
};
// The modal codes both readers give the same NC IR mode; others are refused. Exact stop and
// exact path are one G61 / G60 each way as in the flat writers (the same path, section "What
// is lost").
static const ModeCode kModes[] = {
    {"motion", "rapid", "G0", "G0"},           {"motion", "linear", "G1", "G1"},
    {"motion", "arc_cw", "G2", "G2"},          {"motion", "arc_ccw", "G3", "G3"},
    {"plane", "xy", "G17", "G17"},             {"plane", "zx", "G18", "G18"},
    {"plane", "yz", "G19", "G19"},             {"units", "mm", "G21", "G710"},
    {"units", "inch", "G20", "G700"},           {"distance", "absolute", "G90", "G90"},
    {"distance", "incremental", "G91", "G91"}, {"feed_mode", "per_minute", "G94", "G94"},
    {"feed_mode", "per_rev", "G95", "G95"},    {"feed_mode", "inverse_time", "G93", "G93"},
    {"path_mode", "continuous", "G64", "G64"},
    {"path_mode", "exact_path", "G61", "G60"}, {"path_mode", "exact_stop", "G61", "G60"},
    {"stop_once", "exact_stop_once", nullptr, "G9"},
};
// Work offsets 1..9 (docs/EMIT.md "Work offsets").
// The words of a move both readers take with the same meaning: axes, arc centre and radius.
struct MoveWord {
  const char *key, *iso, *sinumerik;
};
static const MoveWord kMoveWords[] = {
    {"X", "X", "X"}, {"Y", "Y", "Y"}, {"Z", "Z", "Z"}, {"A", "A", "A"}, {"B", "B", "B"},
    {"C", "C", "C"}, {"I", "I", "I"}, {"J", "J", "J"}, {"K", "K", "K"}, {"R", "R", "CR"},
};
static const char *const kStops[][2] = {{"program", "M0"}, {"optional", "M1"}, {"end", "M2"}, {"end_rewind", "M30"}};

static std::string symbolArg(const Op &o, std::string_view key) {
  const Expr *e = o.get(key);
  return e && (e->kind == ExprKind::Symbol || e->kind == ExprKind::String) ? e->str : std::string();
}

// ---------------------------------------------------------------- lines
void Writer::addWord(std::string w) {
  if (!cur_.trail.empty()) flush();
  cur_.words.push_back(std::move(w));
  curOpen_ = true;
}

void Writer::flush() {
  if (!curOpen_) return;
  std::string line = std::string(2 * indent_, ' ') + pendingPrefix_ + cur_.prefix;
  pendingPrefix_.clear();
  for (size_t i = 0; i < cur_.words.size(); ++i) line += (i ? " " : "") + cur_.words[i];
  if (!cur_.trail.empty()) line += (cur_.words.empty() ? "" : " ") + cur_.trail;
  while (!line.empty() && line.back() == ' ') line.pop_back();
  text_ += line + "\n";
  cur_ = Line{};
  curOpen_ = false;
}

void Writer::statement(std::string text) {
  flush();
  cur_.words.push_back(std::move(text));
  curOpen_ = true;
  flush();
}

void Writer::flushPrefix() {
  flush();
  if (pendingPrefix_.empty()) return;
  std::string p = pendingPrefix_;
  while (!p.empty() && p.back() == ' ') p.pop_back();
  text_ += p + "\n";
  pendingPrefix_.clear();
}

std::string Writer::newLabel() {
  if (!iso_) return fmt::format("NCC_L{}", nextLabel_++);
  while (blockNumbers_.count(nextN_)) ++nextN_;
  blockNumbers_.insert(nextN_);
  return std::to_string(nextN_++);
}

std::string Writer::jumpTo(const std::string &label, const char *dir) {
  return iso_ ? "GOTO " + label : std::string(dir) + " " + label;
}

void Writer::placeLabel(const std::string &label) {
  flushPrefix();
  pendingPrefix_ = iso_ ? "N" + label + " " : label + ": ";
}

// ---------------------------------------------------------------- ops
bool Writer::block(const Op &o) {
  flushPrefix();
  if (const Expr *skip = o.get("skip"))
    return fail(o.loc, fmt::format("a block-delete level /{}", skip->num));
  if (const Expr *n = o.get("n")) pendingPrefix_ += "N" + exactNumber(n->num, false) + " ";
  return true;
}

// Modes that act only on canned cycles, which this writer refuses: G98/G99 and G80 (Fanuc: the
// motion mode before the cycle comes back; LinuxCNC: no motion mode, so a program that runs
// gives one before its next move) change nothing in a program without cycles.
static const ModeCode kCycleOnly[] = {
    {"retract", "retract_initial", "", ""}, {"retract", "retract_r", "", ""},
    {"motion", "cycle_cancel", "", ""},     {"motion", "cycle_off", "", ""},
};

bool Writer::mode(const Op &o) {
  for (const ir::Arg &a : o.args) {
    std::string value = a.value->kind == ExprKind::Symbol ? a.value->str : "";
    bool cycleOnly = false;
    for (const ModeCode &m : kCycleOnly) cycleOnly |= a.key == m.group && value == m.value;
    if (cycleOnly) continue;
    const ModeCode *found = nullptr;
    for (const ModeCode &m : kModes)
      if (a.key == m.group && value == m.value) found = &m;
    const char *code = found ? (iso_ ? found->iso : found->sinumerik) : nullptr;
    if (!code) {
      bool cycle = a.key == "motion" && value != "rapid";
      return fail(o.loc, fmt::format("the modal code {}={}{}", a.key, value.empty() ? "<value>" : value,
                                     cycle ? " (canned cycles and special motion are not written yet)" : ""));
    }
    addWord(code);
  }
  return true;
}

bool Writer::move(const Op &o) {
  for (const ir::Arg &a : o.args) {
    const MoveWord *w = nullptr;
    for (const MoveWord &m : kMoveWords)
      if (a.key == m.key) w = &m;
    if (!w) return fail(o.loc, fmt::format("the move word '{}'", a.key));
    std::string s = iso_ ? w->iso : w->sinumerik;
    if (!iso_ && a.key == "R") s += "=";  // CR=5: the radius needs its '='
    std::string v;
    if (!word(*a.value, v)) return false;
    if (!iso_ && a.key == "R" && v[0] == '=') v = v.substr(1);
    addWord(s + v);
  }
  return true;
}

// The state words: F S T M, dwell, stops, comments and messages.
bool Writer::machineWord(const Op &o) {
  std::string v;
  auto valueWord = [&](const char *letter, const char *key) {
    const Expr *e = o.get(key);
    if (!word(*e, v)) return false;
    addWord(letter + v);
    return true;
  };
  switch (o.kind) {
  case OpKind::Feed: return valueWord("F", "value");
  case OpKind::Speed:
    if (o.args.size() != 1 || !o.get("value")) return fail(o.loc, "a spindle speed mode or limit (G96/G97)");
    return valueWord("S", "value");
  case OpKind::ToolSelect: return valueWord("T", "value");
  case OpKind::ToolChange:
    if (!o.args.empty()) return fail(o.loc, "a tool declared in the spindle (M61)");
    // Sinumerik's M6 takes the new tool's edge 1 into account; ISO's does not: D0 keeps it out
    // until the source's G43 (written D1).
    if (!iso_) addWord("D0");
    addWord("M6");
    return true;
  case OpKind::Spindle: {
    static const char *const kDirs[][2] = {{"cw", "M3"}, {"ccw", "M4"}, {"stop", "M5"}};
    std::string d = symbolArg(o, "dir");
    for (auto &k : kDirs)
      if (d == k[0] && o.args.size() == 1) return addWord(k[1]), true;
    return fail(o.loc, "an oriented spindle stop");
  }
  case OpKind::Coolant: {
    std::string flood = symbolArg(o, "flood"), mist = symbolArg(o, "mist");
    if (flood == "off" && mist == "off") return addWord("M9"), true;
    if (flood == "on" && mist.empty()) return addWord("M8"), true;
    if (mist == "on" && flood.empty()) return addWord("M7"), true;
    return fail(o.loc, "one coolant turned off alone");
  }
  case OpKind::Dwell: {
    if (!word(*o.get("seconds"), v)) return false;
    flush();
    addWord("G4");
    addWord((iso_ ? "X" : "F") + v);
    flush();
    return true;
  }
  case OpKind::Stop:
    for (auto &k : kStops)
      if (symbolArg(o, "kind") == k[0]) return addWord(k[1]), true;
    break;
  case OpKind::Aux: {
    const Expr *m = o.get("m");
    if (!m || o.args.size() != 1 || m->kind != ExprKind::Number) return fail(o.loc, "an auxiliary function other than M<n>");
    addWord("M" + exactNumber(m->num, false));
    return true;
  }
  case OpKind::WorkOffset: {
    const Expr *i = o.get("index");
    if (i->kind != ExprKind::Number || i->num < 0 || i->num > 9 || i->num != std::floor(i->num))
      return fail(o.loc, "a computed work offset");
    if (i->num == 0) {  // Sinumerik G500: no settable frame
      if (iso_) return fail(o.loc, "Sinumerik G500 (no settable frame)");
      return addWord("G500"), true;
    }
    // ISO keeps LinuxCNC's G59.1-G59.3 here: the structured writer has no machine family.
    addWord(workOffsetCode((int)i->num, iso_ ? OffsetCodes::LinuxCnc : OffsetCodes::Sinumerik));
    return true;
  }
  case OpKind::ToolLength: {
    const Expr *h = o.get("h");
    if (o.args.empty()) return addWord(iso_ ? "G43" : "D1"), true;  // the tool in the spindle
    if (h && o.args.size() == 1 && h->kind == ExprKind::Number && h->num == 0) return addWord(iso_ ? "G49" : "D0"), true;
    return fail(o.loc, "a tool length from another tool's offset (G43 H<n>: Sinumerik's D is an edge of the spindle tool)");
  }
  case OpKind::CutterComp:
    // G40 alone; G41/G42 take the radius from a D register (Fanuc) or the active edge (Sinumerik).
    if (symbolArg(o, "side") == "off" && o.args.size() == 1) return addWord("G40"), true;
    return fail(o.loc, "cutter compensation G41/G42 (the radius's source differs)");
  case OpKind::Comment: {
    if (!o_.comments) return true;
    const Expr *t = o.get("text");
    if (t->kind != ExprKind::String) return true;
    if (iso_) {
      std::string s = sanitizeText(t->str, "()", "[]");
      if (s.rfind("MSG,", 0) == 0) s.insert(3, " ");
      cur_.trail = "(" + s + ")";
    } else {
      cur_.trail = "; " + sanitizeText(t->str, "", "");
    }
    curOpen_ = true;
    return true;
  }
  case OpKind::Message: {
    const Expr *t = o.get("text");
    std::string kind = symbolArg(o, "kind");
    if (!kind.empty() && kind != "msg") return fail(o.loc, "a " + kind + " message");
    if (iso_) {
      if (t->kind != ExprKind::String) return fail(o.loc, "a computed message text");
      flush();
      cur_.trail = "(MSG, " + sanitizeText(t->str, "()", "[]") + ")";
      curOpen_ = true;
      flush();
      return true;
    }
    if (!expr(*t, v)) return false;
    statement("MSG(" + v + ")");
    return true;
  }
  default: break;
  }
  return fail(o.loc, fmt::format("the '{}' operation", ir::opInfo(o.kind).name));
}

bool Writer::declare(const Op &o) {
  const Expr *var = o.get("var");
  std::string type = symbolArg(o, "type");
  if (!var->args.empty()) return fail(o.loc, fmt::format("the array '{}'", var->str));
  bool boolean = type == "bool" && iso_;  // Sinumerik to Sinumerik is not written
  if (type != "real" && type != "int" && !boolean) return fail(o.loc, fmt::format("a {} variable ('{}')", type, var->str));
  const Expr *init = o.get("init");
  std::string v;
  if (iso_) {
    // A named local lives in a Fanuc common variable from #500 on, set where the DEF stands.
    Declared d{type == "int" ? ir::Type::Int : boolean ? ir::Type::Bool : ir::Type::Real, nextCommon_++};
    if (d.number > 999) return fail(o.loc, "more named variables than Fanuc's #500..#999");
    locals_[var->str] = d;
    if (init && !storeValue(*var, *init, v)) return false;
    statement(fmt::format("#{} = {}", d.number, init ? v : "0"));
    if (o_.comments) text_.back() = ' ', text_ += fmt::format("({})\n", var->str);
    return true;
  }
  locals_[var->str] = Declared{type == "int" ? ir::Type::Int : ir::Type::Real, 0};
  if (init && !expr(*init, v)) return false;
  std::string up = var->str;
  for (char &c : up) c = (char)std::toupper((unsigned char)c);
  statement(fmt::format("DEF {} {}{}", type == "int" ? "INT" : "REAL", up, init ? "=" + v : ""));
  return true;
}

// The jump's text: ISO `GOTO n` (labels as N numbers), Sinumerik GOTOF/GOTOB/GOTO.
bool Writer::gotoText(const Op &o, std::string &out) {
  const Expr *n = o.get("n"), *label = o.get("label");
  std::string dir = symbolArg(o, "dir");
  const char *sinDir = dir == "forward" ? "GOTOF" : dir == "backward" ? "GOTOB" : "GOTO";
  if (n && n->kind == ExprKind::Number) {
    // ISO's GOTO n searches forward then from the start: the same target when it is unique.
    std::string num = exactNumber(n->num, false);
    if (iso_ && dir != "any" && !dir.empty()) return fail(o.loc, fmt::format("a {} jump to a block number N{}", dir, num));
    out = iso_ ? "GOTO " + num : std::string(sinDir) + " N" + num;
    return true;
  }
  if (!label || label->kind != ExprKind::String) return fail(o.loc, "a computed jump target");
  if (!iso_) return out = std::string(sinDir) + " " + label->str, true;
  auto it = labelN_.find(label->str);
  if (it == labelN_.end()) it = labelN_.emplace(label->str, newLabel()).first;
  out = "GOTO " + it->second;
  return true;
}

bool Writer::jumpText(const Op &o, std::string &out) {
  if (o.kind == OpKind::Goto) return gotoText(o, out);
  if (breakTargets_.empty()) return fail(o.loc, "a break outside a loop");
  out = jumpTo(breakTargets_.back(), "GOTOF");
  return true;
}

bool Writer::ifOp(const Op &o, int depth) {
  std::string c;
  if (!condition(*o.get("cond"), c)) return false;
  const Region &then = o.regions[0];
  bool hasElse = o.regions.size() > 1 && !o.regions[1].empty();
  // A lone jump or break keeps its one-line form: IF [c] GOTO n / IF c GOTOF label.
  if (!hasElse && then.size() == 1 && (then[0].kind == OpKind::Goto || then[0].kind == OpKind::Break)) {
    std::string jump;
    if (!jumpText(then[0], jump)) return false;
    statement((iso_ ? "IF [" + c + "] " : "IF " + c + " ") + jump);
    return true;
  }
  if (!iso_) {
    statement("IF " + c);
    if (!region(then, depth + 1)) return false;
    if (hasElse) {
      flushPrefix();
      statement("ELSE");
      if (!region(o.regions[1], depth + 1)) return false;
    }
    flushPrefix();
    statement("ENDIF");
    return true;
  }
  // Fanuc Macro B: IF [c] THEN for one assignment; else jumps over the branches.
  if (!hasElse && then.size() == 1 && then[0].kind == OpKind::Assign) {
    std::string t, v;
    if (!variable(*then[0].get("target"), t) || !storeValue(*then[0].get("target"), *then[0].get("value"), v)) return false;
    statement("IF [" + c + "] THEN " + t + " = " + v);
    return true;
  }
  std::string thenL = newLabel(), endL = newLabel();
  statement("IF [" + c + "] GOTO " + thenL);
  if (hasElse && !region(o.regions[1], depth)) return false;
  flushPrefix();
  statement("GOTO " + endL);
  placeLabel(thenL);
  if (!region(then, depth)) return false;
  placeLabel(endL);
  return true;
}

// while / loop: Macro B WHILE [c] DOn .. ENDn (DOn alone: endless), n the nesting depth 1..3;
// Sinumerik WHILE/ENDWHILE, LOOP/ENDLOOP, REPEAT/UNTIL for a loop ending in `if c break`, FOR
// for a constant count. A break jumps past the end.
bool Writer::loopOp(const Op &o, int depth) {
  const Expr *cond = o.get("cond");
  const Expr *count = o.get("count");
  const Region &body = o.regions[0];
  if (iso_ && depth >= 3) return fail(o.loc, "a loop nested deeper than Fanuc's DO1..DO3");
  bool endless = o.kind == OpKind::Loop ? !count : cond->kind == ExprKind::Bool && cond->num != 0;
  std::string c, end = newLabel();
  if (cond && !endless && !condition(*cond, c)) return false;
  breakTargets_.push_back(end);
  bool used = false;  // whether a break jumps to `end`
  size_t mark = text_.size();
  bool ok = true;
  if (iso_) {
    if (count) return fail(o.loc, "a counted loop (Fanuc Macro B has no counter to spare)");
    statement(endless ? fmt::format("DO{}", depth + 1) : fmt::format("WHILE [{}] DO{}", c, depth + 1));
    ok = region(body, depth + 1);
    flushPrefix();
    statement(fmt::format("END{}", depth + 1));
  } else if (count) {
    if (count->kind != ExprKind::Number || count->num != std::floor(count->num))
      return fail(o.loc, "a loop count that is not a constant whole number");
    std::string k = fmt::format("NCC_K{}", counters_.size() + 1);
    counters_.push_back(k);
    statement(fmt::format("FOR {} = 1 TO {}", k, exactNumber(count->num, false)));
    ok = region(body, depth + 1);
    flushPrefix();
    statement("ENDFOR");
  } else if (endless && !body.empty() && body.back().kind == OpKind::If && body.back().regions.size() == 1 &&
             body.back().regions[0].size() == 1 && body.back().regions[0][0].kind == OpKind::Break) {
    // loop { ...; if c break } is REPEAT ... UNTIL c (the Sinumerik front end's own lowering).
    statement("REPEAT");
    Region head;
    for (size_t i = 0; i + 1 < body.size(); ++i) head.push_back(body[i].clone());
    ok = region(head, depth + 1);
    flushPrefix();
    std::string u;
    ok = ok && condition(*body.back().get("cond"), u);
    statement("UNTIL " + u);
  } else {
    statement(endless ? "LOOP" : "WHILE " + c);
    ok = region(body, depth + 1);
    flushPrefix();
    statement(endless ? "ENDLOOP" : "ENDWHILE");
  }
  breakTargets_.pop_back();
  used = text_.find(iso_ ? "GOTO " + end + "\n" : " " + end + "\n", mark) != std::string::npos;
  if (ok && used) placeLabel(end);
  return ok;
}

bool Writer::calleeName(const Op &o, const std::string &fn, std::string &out) {
  auto it = programNames_.find(fn);
  if (it == programNames_.end()) return fail(o.loc, fmt::format("a call to '{}', which is not part of the program", fn));
  out = it->second;
  return true;
}

bool Writer::callOp(const Op &o) {
  std::string fn, name;
  if (!ir::constantCallee(*o.get("callee"), fn)) return fail(o.loc, "a computed subprogram call");
  for (const ir::Arg &a : o.args)
    if (a.key != "callee" && a.key != "count" && a.key != "frame") return fail(o.loc, "a call with arguments (G65, PROC parameters)");
  // A new frame gives the callee fresh locals: Fanuc's #1..#33 (G65) have no place in
  // Sinumerik's global R parameters; a Sinumerik callee's locals are its DEFs, which the
  // translation sets again at each call (docs/EMIT.md).
  if (symbolArg(o, "frame") == "new" && m_.dialect != ir::Dialect::Sinumerik)
    return fail(o.loc, "a macro call with its own local variables (G65)");
  const ir::Function *f = m_.find(fn);
  if (f && !f->params.empty()) return fail(o.loc, fmt::format("a call of '{}', which has parameters", fn));
  if (!calleeName(o, fn, name)) return false;
  const Expr *count = o.get("count");
  std::string n;
  if (count && !(count->kind == ExprKind::Number && count->num == 1)) {
    if (count->kind != ExprKind::Number) return fail(o.loc, "a computed repetition count");
    n = exactNumber(count->num, false);
  }
  flush();
  statement(iso_ ? "M98 P" + name + (n.empty() ? "" : " L" + n) : name + (n.empty() ? "" : " P" + n));
  return true;
}

bool Writer::control(const Op &o, int depth) {
  switch (o.kind) {
  case OpKind::Assign: {
    std::string t, v;
    if (!variable(*o.get("target"), t) || !storeValue(*o.get("target"), *o.get("value"), v)) return false;
    statement(t + " = " + v);
    return true;
  }
  case OpKind::Declare: return declare(o);
  case OpKind::If: return ifOp(o, depth);
  case OpKind::While:
  case OpKind::Loop: return loopOp(o, depth);
  case OpKind::Break:
  case OpKind::Goto: {
    std::string jump;
    if (!jumpText(o, jump)) return false;
    statement(jump);
    return true;
  }
  case OpKind::Label:
    if (iso_) {
      const Expr *name = o.get("name");
      auto it = labelN_.find(name->str);
      if (it == labelN_.end()) it = labelN_.emplace(name->str, newLabel()).first;
      placeLabel(it->second);
    } else {
      placeLabel(o.get("name")->str);
    }
    return true;
  case OpKind::Call: return callOp(o);
  case OpKind::Return:
    if (o.get("value")) return fail(o.loc, "a return value");
    // M99 in a Fanuc main program starts it again; Sinumerik's M17 there ends it.
    if (iso_ && inMain_) return fail(o.loc, "a return from the main program (M99 would start it again)");
    addWord(iso_ ? "M99" : "M17");
    return true;
  default: break;
  }
  return fail(o.loc, fmt::format("the '{}' operation", ir::opInfo(o.kind).name));
}

bool Writer::op(const Op &o, int depth) {
  switch (o.kind) {
  case OpKind::Block: return block(o);
  case OpKind::Mode: return mode(o);
  case OpKind::Move: return move(o);
  case OpKind::Feed: case OpKind::Speed: case OpKind::ToolSelect: case OpKind::ToolChange:
  case OpKind::Spindle: case OpKind::Coolant: case OpKind::Dwell: case OpKind::Stop:
  case OpKind::Aux: case OpKind::WorkOffset: case OpKind::ToolLength: case OpKind::Comment: case OpKind::CutterComp:
  case OpKind::Message:
    return machineWord(o);
  default: return control(o, depth);
  }
}

bool Writer::region(const Region &r, int depth) {
  flush();
  int saved = indent_;
  indent_ = depth;
  bool ok = true;
  for (const Op &o : r)
    if (!(ok = op(o, depth))) break;
  flush();
  indent_ = saved;
  return ok;
}

// ---------------------------------------------------------------- functions and files
static void collectBlockNumbers(const Region &r, std::set<long long> &out) {
  for (const Op &o : r) {
    if (o.kind == OpKind::Block)
      if (const Expr *n = o.get("n")) out.insert((long long)n->num);
    for (const Region &sub : o.regions) collectBlockNumbers(sub, out);
  }
}

bool Writer::function(const ir::Function &f, StructuredFile &out) {
  text_.clear();
  cur_ = Line{};
  curOpen_ = false;
  pendingPrefix_.clear();
  blockNumbers_.clear();
  labelN_.clear();
  counters_.clear();
  if (!iso_) locals_.clear();  // ISO: named locals keep their #numbers program-wide
  collectBlockNumbers(f.body, blockNumbers_);
  inMain_ = &f == &m_.functions[0];
  if (!f.params.empty()) return fail(f.loc, fmt::format("the parameters of '{}'", f.name));
  bool ok = region(f.body, 0);
  flushPrefix();
  if (!ok) return false;
  bool main = &f == &m_.functions[0];
  std::string body = std::move(text_);
  text_.clear();
  if (!main) {
    // A subprogram ends with its return (M99 / M17) even where the source's fell off the end.
    std::string last = body.substr(body.rfind('\n', body.size() - 2) + 1);
    if (last.find(iso_ ? "M99" : "M17") == std::string::npos) body += iso_ ? "M99\n" : "M17\n";
  }
  std::string head;
  if (!iso_) {
    // Sinumerik wants every DEF before the first statement: the LinuxCNC named locals and the
    // loop counters are declared first (DEFs from the source are already at the start).
    for (auto &[name, d] : locals_) {
      std::string up = name;
      for (char &c : up) c = (char)std::toupper((unsigned char)c);
      if (body.find("DEF REAL " + up) == std::string::npos && body.find("DEF INT " + up) == std::string::npos)
        head += "DEF REAL " + up + "\n";
    }
    for (auto &k : counters_) head += "DEF INT " + k + "\n";
  }
  out.text = head + body;
  return true;
}

bool Writer::run(std::vector<StructuredFile> &files) {
  // Subprogram names: ISO O-numbers (O1234 from O1234 / L1234, others from 9001 on);
  // Sinumerik L-names for numbered programs, the name itself otherwise.
  int nextO = 9001;
  for (size_t i = 1; i < m_.functions.size(); ++i) {
    const std::string &n = m_.functions[i].name;
    bool numbered = n.size() > 1 && (n[0] == 'O' || n[0] == 'L') && n.size() <= 5 &&
                    n.find_first_not_of("0123456789", 1) == std::string::npos;
    std::string digits = numbered ? std::to_string(std::stoi(n.substr(1))) : "";
    programNames_[n] = iso_ ? (numbered ? digits : std::to_string(nextO++)) : (numbered ? "L" + digits : n);
  }
  files.clear();
  std::vector<StructuredFile> subs;
  StructuredFile mainFile;
  std::vector<std::string> bodies;
  for (size_t i = 0; i < m_.functions.size(); ++i) {
    StructuredFile f;
    if (!function(m_.functions[i], f)) return false;
    if (i == 0) mainFile = std::move(f);
    else {
      f.name = programNames_[m_.functions[i].name];
      subs.push_back(std::move(f));
    }
  }
  std::string name = o_.programName;
  if (size_t slash = name.find_last_of("/\\"); slash != std::string::npos) name = name.substr(slash + 1);
  if (iso_) {
    // One file: the main program, then each subprogram as O<n> ... M99 (docs/EMIT.md).
    std::string t = "%\nO0001";
    if (!name.empty()) t += " (" + sanitizeText(name, "()", "[]") + ")";
    t += "\n";
    // Sinumerik R parameters start at 0; Fanuc's #100.. start vacant: set the ones used.
    for (int r : rUsed_) t += fmt::format("#{} = 0\n", 100 + r);
    t += mainFile.text;
    for (size_t i = 0; i < subs.size(); ++i) {
      const std::string &src = m_.functions[i + 1].name;
      t += "O" + subs[i].name + (src != subs[i].name && src != "O" + subs[i].name && src != "L" + subs[i].name
                                     ? " (" + sanitizeText(src, "()", "[]") + ")" : "") + "\n";
      t += subs[i].text;
    }
    files.push_back({"", t + "%\n"});
    return true;
  }
  // Sinumerik: a file per program, the main program first.
  files.push_back({"", (name.empty() ? "" : "; " + name + "\n") + mainFile.text});
  for (auto &s : subs) files.push_back({s.name + ".SPF", s.text});
  return true;
}

}  // namespace ncc::emit::structured

namespace ncc::emit {

bool writeStructured(const ir::Module &m, const StructuredOptions &opts, std::vector<StructuredFile> &files,
                     Diagnostics &diags) {
  if (opts.target != Target::ISO && opts.target != Target::Sinumerik) {
    diags.error({}, fmt::format("structure-keeping translation writes ISO and Sinumerik programs; translate to {} without "
                                "--keep-structure", targetName(opts.target)),
                "unsupported-code");
    return false;
  }
  // The pairs written: ISO (Fanuc Macro B, LinuxCNC) to Sinumerik and Sinumerik to ISO.
  ir::Dialect from = opts.target == Target::ISO ? ir::Dialect::Sinumerik : ir::Dialect::ISO;
  if (m.dialect != from) {
    diags.error({}, fmt::format("structure-keeping translation writes ISO programs as Sinumerik and Sinumerik programs as "
                                "ISO; translate this {} program to {} without --keep-structure",
                                ir::dialectName(m.dialect), targetName(opts.target)),
                "unsupported-code");
    return false;
  }
  structured::Writer w(m, opts, diags);
  return w.run(files);
}

std::string structuredListing(const std::vector<StructuredFile> &files, Target target) {
  std::string out;
  for (size_t i = 0; i < files.size(); ++i) {
    if (i) out += (target == Target::ISO ? "(---- file " : "; ---- file ") + files[i].name + (target == Target::ISO ? ")\n" : "\n");
    out += files[i].text;
  }
  return out;
}

}  // namespace ncc::emit
