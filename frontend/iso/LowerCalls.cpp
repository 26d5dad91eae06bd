// Calls whose form is more than one op: the arguments of macro calls with the 808D call
// context, M99 P (ISO-M-04), and the G and M codes a machine configures to call a program
// (machine [controller] macro_calls; ISO-MAC-05/06, README.md "Macro calls by code").
#include "frontend/iso/LowerBlock.h"

#include <cmath>
#include <cstring>

namespace ncc::iso {

// Fanuc argument specification I: G65 address -> local variable number (0 = not an argument).
static const int kMacroArg[26] = {
    /*A*/ 1, /*B*/ 2, /*C*/ 3, /*D*/ 7, /*E*/ 8, /*F*/ 9, /*G*/ 0, /*H*/ 11, /*I*/ 4, /*J*/ 5,
    /*K*/ 6, /*L*/ 0, /*M*/ 13, /*N*/ 0, /*O*/ 0, /*P*/ 0, /*Q*/ 17, /*R*/ 18, /*S*/ 19, /*T*/ 20,
    /*U*/ 21, /*V*/ 22, /*W*/ 23, /*X*/ 24, /*Y*/ 25, /*Z*/ 26};

bool macroArguments(const std::vector<IsoWord> &words, const char *skip, Op &op, Diagnostics &diags) {
  // Argument specification II when I, J or K repeats: up to 10 sets I J K -> #4+3s, #5+3s,
  // #6+3s; a set ends when an address repeats or comes out of I-J-K order.
  int ijkCount[3] = {0, 0, 0};
  for (auto &w : words)
    if (w.letter >= 'I' && w.letter <= 'K') ++ijkCount[w.letter - 'I'];
  bool specII = ijkCount[0] > 1 || ijkCount[1] > 1 || ijkCount[2] > 1;
  int set = 0, lastPos = -1;
  // 808D $C_ALL_PROG / $C_TYP_PROG (seed L9603-9644): bit n for the n-th letter (A = bit 0)
  // given / written as a REAL (with a decimal point, or a value reference); I J K have one
  // bit each, always 0 in $C_TYP_PROG.
  double all = 0, typ = 0;
  uint32_t seen = 0;
  for (auto &w : words) {
    if (std::strchr(skip, w.letter)) continue;
    int local = w.letter >= 'A' && w.letter <= 'Z' ? kMacroArg[w.letter - 'A'] : 0;
    if (specII && w.letter >= 'I' && w.letter <= 'K') {
      int pos = w.letter - 'I';
      if (pos <= lastPos) ++set;
      lastPos = pos;
      if (set > 9) {
        diags.error(w.loc, "more than 10 I/J/K argument sets", "syntax");
        return false;
      }
      local = 4 + 3 * set + pos;
    }
    if (!local) {
      diags.error(w.loc, fmt::format("{} is not a macro argument", w.letter), "syntax");
      return false;
    }
    // As written: argument values are not scaled by the decimal mode. Later words win (D=#7 vs I2).
    op.set(fmt::format("a.{}", local), w.expr ? w.expr->clone() : Expr::number(w.value, w.hasPoint ? ir::Type::Real : ir::Type::Int, w.loc));
    uint32_t bit = 1u << (w.letter - 'A');
    if (!(seen & bit)) all += bit;
    bool ijk = w.letter >= 'I' && w.letter <= 'K';
    if (!(seen & bit) && !ijk && (w.hasPoint || w.expr)) typ += bit;
    seen |= bit;
  }
  // Program::stripCallContext drops them again where the callee does not read them.
  op.set("a._C_ALL_PROG", Expr::number(all, ir::Type::Int, op.loc));
  op.set("a._C_TYP_PROG", Expr::number(typ, ir::Type::Int, op.loc));
  return true;
}

static ExprPtr global(const char *name, SourceLoc loc) { return Expr::var(ir::VarSpace::Global, name, nullptr, loc); }

static Op assign(const char *name, ExprPtr value, SourceLoc loc) {
  Op op(OpKind::Assign, loc);
  op.set("target", global(name, loc));
  op.set("value", std::move(value));
  return op;
}

// M99 (808D L9276-9289): in a subprogram it returns; with P<n> the caller goes on at its block
// N<n>, searched forward from the call, then from the start (the caller's side is added by
// Program.cpp, which knows every call of the program). In the main program M99 starts the
// program again (the loop limit of backward jumps stops an endless repeat) and M99 P<n> goes to
// block N<n>.
bool BlockLowerer::Block::returnOp(SourceLoc loc) {
  ExprPtr block;
  if (bw.has('P')) {
    if (L.flavour_ == Flavour::RS274) {
      L.diags_->error(bw.get('P')->loc, "M99 P<n> (return to a block number) is not an RS274NGC word", "unsupported-code");
      return false;
    }
    IsoWord *p = bw.get('P');
    if (!p->expr && (p->value < 0 || p->value != std::floor(p->value))) {
      L.diags_->error(p->loc, "M99 P must be a block number (a whole number)", "syntax");
      return false;
    }
    block = take('P', Scale::None);
  }
  if (L.inMain && L.flavour_ == Flavour::Fanuc) {
    Op &go = emit(OpKind::Goto, loc);
    if (block) go.set("n", std::move(block));
    else go.set("label", Expr::string(kMainStart, loc));
    return true;
  }
  if (block) out.push_back(assign(kM99Block, std::move(block), loc));
  emit(OpKind::Return, loc);
  return true;
}

// ---- macro calls by code ------------------------------------------------------------------

static std::string codeName(char letter, int64_t code10) {
  return letter == 'G' ? gName((int32_t)code10) : fmt::format("M{}", code10 / 10);
}

static IsoWord copyWord(const IsoWord &w) {
  return {w.letter, w.hasPoint, w.value, w.expr ? w.expr->clone() : nullptr, w.loc};
}

static bool isCode(const IsoWord &w, char letter, double value) {
  return w.letter == letter && !w.expr && w.value == value;
}

bool BlockLowerer::codeCallOf(const ParsedBlock &b, const CodeCall *&call, const IsoWord *&word) {
  call = nullptr;
  word = nullptr;
  // In a G65/G66 block M is an argument; a G code that calls there is a second call.
  bool macroBlock = false;
  for (auto &w : b.words) macroBlock |= isCode(w, 'G', 65) || isCode(w, 'G', 66);
  for (auto &w : b.words) {
    if ((w.letter != 'G' && (w.letter != 'M' || macroBlock)) || w.expr || w.value < 0 || w.value > 1e9) continue;
    double t = w.value * 10;
    int64_t c10 = std::llround(t);
    if (std::fabs(t - (double)c10) > 1e-6) continue;
    for (auto &c : codeCalls_) {
      if (c.letter != w.letter || c.code10 != c10) continue;
      if (call) {
        diags_->error(w.loc, fmt::format("{} and {} both call a program: one macro or subprogram call per block (808D alarm 12722)",
                                         codeName(call->letter, call->code10), codeName(c.letter, c.code10)),
                      "several-calls");
        return false;
      }
      call = &c;
      word = &w;
    }
  }
  if (!call) return true;
  for (auto &w : b.words)
    if (isCode(w, 'G', 65) || isCode(w, 'G', 66) || isCode(w, 'M', 98) || isCode(w, 'G', 5)) {
      diags_->error(w.loc, fmt::format("{}{} cannot share a block with {}, which calls {}: one macro or subprogram call "
                                       "per block (808D alarm 12722)",
                                       w.letter, w.value, codeName(call->letter, call->code10), call->callee),
                    "several-calls");
      return false;
    }
  return true;
}

// `b` as its own codes would run it, in a program called by a code (where codes do not call):
// the ops into `out`. When that is an error (a G code that exists only as a macro: 808D alarm
// 12470; an argument no code uses), the error is the branch's: the run stops there with it.
bool BlockLowerer::plainCode(const ParsedBlock &b, const std::string &code, Region &out) {
  ParsedBlock pb;
  pb.loc = b.loc;
  pb.content = true;
  pb.n = b.n;
  for (auto &w : b.words) pb.words.push_back(copyWord(w));
  for (auto &w : b.corner) pb.corner.push_back(copyWord(w));
  Diagnostics scratch(diags_->sources());
  scratch.setCollect(true);
  Diagnostics *real = diags_;
  diags_ = &scratch;
  Region ops;
  bool ok = lowerPlain(pb, ops) && !scratch.hasErrors();
  diags_ = real;
  if (ok) {
    for (auto &op : ops) out.push_back(std::move(op));
    return true;
  }
  const Diagnostic *first = nullptr;
  for (auto &d : scratch.collected())
    if (!first && d.severity == Severity::Error) first = &d;
  std::string why = first ? first->message : "an error";
  if (first && first->rule == "unknown-code" && code[0] == 'G') why += " (808D alarm 12470)";
  Op stop(OpKind::Message, first ? first->loc : b.loc);
  stop.set("text", Expr::string(fmt::format("{} acts as the plain code in a program called by a code, and there: {}", code, why),
                                b.loc));
  stop.set("kind", Expr::symbol("abort", b.loc));
  out.push_back(std::move(stop));
  return true;
}

// A configured code: `if %%_macro_by_code == 0 { the call } else { the plain code }`. The flag
// is set while the called program runs, so neither it nor what it calls calls by code again
// (808D: no further M replacement in the replacement program; no G or M macros while a G macro
// is active; Fanuc likewise).
bool BlockLowerer::lowerCodeCall(ParsedBlock &b, const CodeCall &call, const IsoWord &word, Region &out) {
  SourceLoc loc = word.loc;
  std::string code = codeName(call.letter, call.code10);
  if (flavour_ == Flavour::RS274) {
    diags_->error(loc, fmt::format("{} calls {} by the machine's macro_calls: LinuxCNC remaps are not supported", code,
                                   call.callee), "unsupported-code");
    return false;
  }
  if (!b.assigns.empty()) {
    diags_->error(b.assigns.front().loc, fmt::format("an assignment cannot share a block with {}, which calls {}", code,
                                                     call.callee), "syntax");
    return false;
  }
  Op choice(OpKind::If, loc);
  choice.set("cond", Expr::binary(ir::OpCode::Eq, global(kByCodeFlag, loc), Expr::number(0, ir::Type::Int, loc), loc));
  choice.regions.resize(2);
  Modes before = modes();
  if (!plainCode(b, code, choice.regions[1])) return false;
  setModes(before);
  Region &then = choice.regions[0];

  if (callsRefused) {  // the ISO blocks of a Siemens-mode program: only where codes act as themselves
    Op stop(OpKind::Message, loc);
    stop.set("text", Expr::string(fmt::format("{} (a call of {}) {}", code, call.callee, callsRefused), loc));
    stop.set("kind", Expr::symbol("abort", loc));
    then.push_back(std::move(stop));
    // Outside a program called by a code the flag may never have been set (a Siemens-mode main).
    Op known(OpKind::If, loc);
    std::vector<ExprPtr> v;
    v.push_back(global(kByCodeFlag, loc));
    known.set("cond", Expr::call("EXISTS", std::move(v), loc));
    known.regions.resize(2);
    known.regions[1].push_back(then.front().clone());
    known.regions[0].push_back(std::move(choice));
    out.push_back(std::move(known));
    return true;
  }

  // The rest of the block: for a subprogram call every other word, before the call (Fanuc: the
  // block's move, then the subprogram); for a macro call the other G codes of a G macro, after
  // the call (808D: "G1 and G90 are active after the call"). An M macro, like G65, has none.
  ParsedBlock rest;
  rest.loc = b.loc;
  rest.content = true;
  for (auto &w : b.words) {
    if (&w == &word) continue;
    if (call.subprogram || w.letter == 'G' || w.letter == 'M') {
      if (!call.subprogram && (call.letter == 'M' || w.letter == 'M')) {
        diags_->error(w.loc, fmt::format("{} (a macro call of {}) must not share its block with other {} codes", code,
                                         call.callee, w.letter), "syntax");
        return false;
      }
      rest.words.push_back(copyWord(w));
    }
  }
  if (call.subprogram) {
    for (auto &w : b.corner) rest.corner.push_back(copyWord(w));
    if (!lowerPlain(rest, then)) return false;
  }
  calls.push_back({call.callee, loc});
  then.push_back(assign(kByCodeFlag, Expr::number(1, ir::Type::Int, loc), loc));
  Op &op = then.emplace_back(OpKind::Call, loc);
  op.set("callee", Expr::string(call.callee, loc));
  if (call.subprogram) {
    op.set("count", Expr::number(1, ir::Type::Int, loc));
    op.set("frame", Expr::symbol("shared", loc));
  } else {
    const IsoWord *count = nullptr;
    for (auto &w : b.words)
      if (w.letter == 'L') count = &w;
    op.set("count", count ? Block::literal(*count, 1.0) : Expr::number(1, ir::Type::Int, loc));
    op.set("frame", Expr::symbol("new", loc));
    if (!macroArguments(b.words, "GLM", op, *diags_)) return false;
    if (call.letter == 'G')  // 808D $C_G: the calling G code (G123 and G421 may share a program)
      op.set("a._C_G", Expr::number(call.code10 / 10.0, call.code10 % 10 ? ir::Type::Real : ir::Type::Int, loc));
  }
  then.push_back(assign(kByCodeFlag, Expr::number(0, ir::Type::Int, loc), loc));
  if (!call.subprogram && !rest.words.empty() && !lowerPlain(rest, then)) return false;
  out.push_back(std::move(choice));
  return true;
}

}  // namespace ncc::iso
