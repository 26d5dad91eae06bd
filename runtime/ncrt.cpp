// The ncrt C ABI: storage, command execution and run-time errors for compiled NC programs.
#include "runtime/ncrt.h"
#include "ir/SystemAccess.h"
#include "ir/Jumps.h"
#include "ir/RunErrors.h"

#include "ir/Arith.h"
#include "ir/Builtins.h"
#include "ir/Diagnostics.h"
#include "ir/SystemParams.h"
#include "ir/SystemVars.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

using namespace ncc;

ncrt_ctx::ncrt_ctx(CmdSink &t, Diagnostics &d, const ExecLimits &l)
    : sink(t), diags(d), limits(l), start(std::chrono::steady_clock::now()) {}

static_assert(NCRT_UNSET_BITS == kUnsetBits, "generated code and ir/Value.h must agree on 'unset'");

static bool endsProgram(const MachineCmd &c) {
  return c.kind == CmdKind::Stop &&
         (c.sub == (uint8_t)StopKind::End || c.sub == (uint8_t)StopKind::EndRewind);
}

// One command through the target; the status generated code acts on.
static int execOne(ncrt_ctx *ctx, const MachineCmd &c) {
  if (!ctx->sink.exec(c)) return NCRT_ERROR;
  if (endsProgram(c)) {
    ctx->ended = true;
    return NCRT_END;
  }
  if (c.kind == CmdKind::Move && ctx->modal_hook)
    return ctx->modal_hook(ctx, &ctx->storage, c.loc.file, c.loc.line, c.loc.col);
  return NCRT_OK;
}

// ---------------------------------------------------------------- packed stream
// The commands whose text travels with them: comments, messages and a cycle's STRING argument
// (CYCLE940's _FORM, HOLES1's _HIDE), which a long packed run lost before.
static bool carriesText(CmdKind k) { return k == CmdKind::Comment || k == CmdKind::Message || k == CmdKind::Cycle; }

static void putVarint(uint64_t v, std::string &out) {
  do {
    uint8_t b = v & 0x7f;
    v >>= 7;
    out.push_back((char)(v ? b | 0x80 : b));
  } while (v);
}

static bool getVarint(const uint8_t *&p, const uint8_t *end, uint64_t &v) {
  v = 0;
  for (unsigned shift = 0; p < end && shift < 64; shift += 7) {
    uint8_t b = *p++;
    v |= (uint64_t)(b & 0x7f) << shift;
    if (!(b & 0x80)) return true;
  }
  return false;
}

namespace ncc::ncrt {
void packCmd(const MachineCmd &c, const char *text, std::string &out) {
  out.push_back((char)c.kind);
  for (uint16_t s : {c.sub, c.sub2}) out.push_back((char)(s & 0xff)), out.push_back((char)(s >> 8));
  out.push_back((char)c.nmodes);
  for (unsigned i = 0; i < c.nmodes; ++i) out.push_back((char)c.modes[i]);
  putVarint(c.mask, out);
  if (c.kind == CmdKind::Block) putVarint((uint64_t)(c.blockNumber + 1), out);
  putVarint(c.loc.file, out);
  putVarint(c.loc.line, out);
  putVarint(c.loc.col, out);
  for (int w = 0; w < kWords; ++w)
    if (c.mask & wordBit((Word)w)) out.append((const char *)&c.w[w], sizeof(double));
  if (carriesText(c.kind)) {
    size_t n = text ? std::strlen(text) : 0;
    putVarint(n, out);
    out.append(text ? text : "", n);
    out.push_back('\0');
  }
}
}  // namespace ncc::ncrt

// Decodes one command; false on a malformed stream (a compiler bug, reported as such).
static bool unpackCmd(const uint8_t *&p, const uint8_t *end, MachineCmd &c) {
  if (end - p < 6) return false;
  c = MachineCmd();
  c.kind = (CmdKind)p[0];
  c.sub = (uint16_t)(p[1] | p[2] << 8);
  c.sub2 = (uint16_t)(p[3] | p[4] << 8);
  c.nmodes = p[5];
  p += 6;
  if (c.kind >= CmdKind::Count || c.nmodes > kMaxModes || end - p < c.nmodes) return false;
  for (unsigned i = 0; i < c.nmodes; ++i) c.modes[i] = (ModeValue)*p++;
  uint64_t v;
  if (!getVarint(p, end, v)) return false;
  c.mask = v;
  if (c.kind == CmdKind::Block) {
    if (!getVarint(p, end, v)) return false;
    c.blockNumber = (int64_t)v - 1;
  }
  uint64_t f, l, col;
  if (!getVarint(p, end, f) || !getVarint(p, end, l) || !getVarint(p, end, col)) return false;
  c.loc = {(uint32_t)f, (uint32_t)l, (uint32_t)col};
  for (int w = 0; w < kWords; ++w)
    if (c.mask & wordBit((Word)w)) {
      if (end - p < 8) return false;
      std::memcpy(&c.w[w], p, sizeof(double));
      p += 8;
    }
  if (carriesText(c.kind)) {
    if (!getVarint(p, end, v) || (uint64_t)(end - p) < v + 1) return false;
    c.text = (const char *)p;
    p += v + 1;
  }
  return true;
}

// ---------------------------------------------------------------- C ABI
extern "C" {

ncrt_storage *ncrt_begin(ncrt_ctx *ctx, uint32_t namedGlobals, uint32_t qSpaces) {
  ctx->numbered.assign(NCRT_NUMBERED, vacantValue());
  ctx->rparam.assign(NCRT_RPARAMS, rParamStart());
  ctx->qparam.resize((size_t)NCRT_QPARAMS * qSpaces);
  for (uint32_t q = 0; q < qSpaces && q < (uint32_t)kQSpaces; ++q)
    std::fill_n(ctx->qparam.begin() + (size_t)q * NCRT_QPARAMS, NCRT_QPARAMS, qParamStart((int)q));
  ctx->named.assign(namedGlobals, unsetValue());
  ncrt_storage &s = ctx->storage;
  s.numbered = ctx->numbered.data();
  s.rparam = ctx->rparam.data();
  s.qparam = ctx->qparam.data();
  s.named = ctx->named.data();
  s.max_loop = ctx->limits.maxLoopIterations;
  s.max_depth = ctx->limits.maxCallDepth;
  s.depth = 0;
  s.poll = NCRT_POLL_INTERVAL;
  return &s;
}

void ncrt_unset(double *p, uint64_t n) { std::fill_n(p, n, unsetValue()); }

int ncrt_exec(ncrt_ctx *ctx, const ncrt_cmd *cmd) { return execOne(ctx, *cmd); }

int ncrt_exec_table(ncrt_ctx *ctx, const ncrt_cmd *cmds, uint64_t n) {
  for (uint64_t i = 0; i < n; ++i)
    if (int st = execOne(ctx, cmds[i])) return st;
  return NCRT_OK;
}

int ncrt_exec_blocks(ncrt_ctx *ctx, const ncrt_cmd *last, uint64_t count) {
  return !count || ctx->sink.execBlocks(*last, count) ? NCRT_OK : NCRT_ERROR;
}

int ncrt_exec_mode(ncrt_ctx *ctx, const ncrt_cmd *last, uint64_t blocks, const ncrt_cmd *mode) {
  return ctx->sink.execMode(last, blocks, *mode) ? NCRT_OK : NCRT_ERROR;  // a mode neither ends nor moves
}

// A move neither ends the program; the modal call runs after it as after any move (execOne).
int ncrt_exec_move(ncrt_ctx *ctx, const ncrt_cmd *last, uint64_t blocks, const ncrt_cmd *mode, const ncrt_cmd *move) {
  if (!ctx->sink.execMove(last, blocks, mode, *move)) return NCRT_ERROR;
  if (ctx->modal_hook) return ctx->modal_hook(ctx, &ctx->storage, move->loc.file, move->loc.line, move->loc.col);
  return NCRT_OK;
}

int ncrt_exec_packed(ncrt_ctx *ctx, const uint8_t *data, uint64_t nbytes) {
  const uint8_t *p = data, *end = data + nbytes;
  MachineCmd c;
  while (p < end) {
    if (!unpackCmd(p, end, c)) {
      ctx->diags.error({}, "internal error: malformed packed command table");
      return NCRT_ERROR;
    }
    if (int st = execOne(ctx, c)) return st;
  }
  return NCRT_OK;
}

void ncrt_error(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, const char *msg) {
  ctx->diags.error({file, line, col}, msg);
}

static_assert(NCRT_FAULT_LOOP_LIMIT == (unsigned)RunError::LoopLimit && NCRT_FAULT_BACKJUMP == (unsigned)RunError::BackJump &&
                  NCRT_FAULT_CALL_DEPTH == (unsigned)RunError::CallDepth && NCRT_FAULT_UNSET_VAR == (unsigned)RunError::UnsetVar &&
                  NCRT_FAULT_NUMBERED == (unsigned)RunError::Numbered && NCRT_FAULT_RPARAM == (unsigned)RunError::RParam &&
                  NCRT_FAULT_QPARAM == (unsigned)RunError::QParam && NCRT_FAULT_INDEX == (unsigned)RunError::Index &&
                  NCRT_FAULT_UNSET_ELEM == (unsigned)RunError::UnsetElem && NCRT_FAULT_SYSVAR == (unsigned)RunError::SysVar,
              "NCRT_FAULT_* must number the kinds as ir/RunErrors.h");

void ncrt_fault(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, uint32_t kind,
                const char *name, double value) {
  ctx->diags.error({file, line, col}, runErrorMessage((RunError)kind, ctx->limits, name ? name : "", value));
}

int ncrt_poll(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col) {
  ctx->storage.poll = NCRT_POLL_INTERVAL;
  ++ctx->polls;
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - ctx->start).count();
  if (ctx->limits.maxSeconds <= 0 || secs <= ctx->limits.maxSeconds) return NCRT_OK;
  ctx->diags.error({file, line, col},
                   runErrorMessage(RunError::TimeLimit, ctx->limits));
  return NCRT_ERROR;
}

// An error reported at the loc: the result generated code recognises.
static double failed(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, const std::string &msg) {
  ctx->diags.error({file, line, col}, msg);
  return unsetValue();
}

double ncrt_sysvar(ncrt_ctx *ctx, double ref, const char *name, uint32_t file, uint32_t line, uint32_t col) {
  double v;
  std::string err;
  SysRef r = sysRefFromNumber(ref);
  if ((int)r.var < kSysVarIds && readSystemValue(ctx->sink, ctx->pool, r, v, err)) return v;
  return failed(ctx, file, line, col, err.empty() ? runErrorMessage(RunError::SysVar, ctx->limits, name) : err);
}

double ncrt_sysvar_at(ncrt_ctx *ctx, uint32_t family, double i, double j, double k, const char *name, uint32_t file,
                      uint32_t line, uint32_t col) {
  SysRef r = sysVarAt((SysFamily)family, i, j, k);
  if (r.var == kNoSysVar) return failed(ctx, file, line, col, sysVarIndexMessage(name, (SysFamily)family, i, j, k));
  return sysRefNumber(r);
}

double ncrt_sysvar_set(ncrt_ctx *ctx, double ref, double v, uint32_t file, uint32_t line, uint32_t col) {
  std::string err;
  return writeSystemValue(ctx->sink, ctx->pool, sysRefFromNumber(ref), v, {file, line, col}, err)
             ? 0.0
             : failed(ctx, file, line, col, err);
}

double ncrt_param(ncrt_ctx *ctx, uint32_t map, uint32_t access, double n, double v, uint32_t file, uint32_t line,
                  uint32_t col) {
  std::string err;
  if (accessSystemParameter(ctx->sink, ctx->pool, (ParamMap)map, n, (ParamAccess)access, v, {file, line, col}, err))
    return access == (uint32_t)ParamAccess::Read ? v : 0.0;
  return failed(ctx, file, line, col, err);
}

void ncrt_str_clear(ncrt_ctx *ctx) { ctx->text.clear(); }
void ncrt_str_cat(ncrt_ctx *ctx, const char *s) { ctx->text += s; }
void ncrt_str_num(ncrt_ctx *ctx, double v) { ctx->text += valueText(ctx->pool, v); }
void ncrt_str_num_fixed(ncrt_ctx *ctx, double v) { ctx->text += valueText(ctx->pool, v, true); }
const char *ncrt_str(ncrt_ctx *ctx) { return ctx->text.c_str(); }

void ncrt_set_modal_hook(ncrt_ctx *ctx, void *fn) {
  ctx->modal_hook = reinterpret_cast<int (*)(ncrt_ctx *, ncrt_storage *, uint32_t, uint32_t, uint32_t)>(fn);
}

int ncrt_modal_trigger(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col) {
  if (!ctx->sink.exec(cycleTriggerCmd({file, line, col}))) return NCRT_ERROR;  // the executor's modal cycle
  return ctx->modal_hook ? ctx->modal_hook(ctx, &ctx->storage, file, line, col) : NCRT_OK;
}
int ncrt_save_modal(ncrt_ctx *ctx) { return ctx->sink.saveModal() ? NCRT_OK : NCRT_ERROR; }
int ncrt_restore_modal(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col) {
  return ctx->sink.restoreModal({file, line, col}) ? NCRT_OK : NCRT_ERROR;
}

static_assert(sizeof(ncc::ir::JumpEntry) == 24, "JumpEntry layout changed: update the JIT's jump table type");

int64_t ncrt_jump(ncrt_ctx *ctx, int label, double n, const void *entries, uint64_t count, uint32_t from, uint32_t dir,
                  uint32_t file, uint32_t line, uint32_t col) {
  int64_t t = ncc::ir::findJump(static_cast<const ncc::ir::JumpEntry *>(entries), count, label, n, ctx->text, from,
                                (ncc::ir::JumpDir)dir);
  if (t < 0) ctx->diags.error({file, line, col}, ncc::ir::missingJumpMessage(label, n, ctx->text));
  return t;
}

int64_t ncrt_callee(ncrt_ctx *ctx, int numeric, double value, const char *const *names, uint64_t n,
                    uint32_t file, uint32_t line, uint32_t col) {
  if (numeric && isString(value)) ctx->text = ctx->pool.text(value);
  else if (numeric && !programName(value, ctx->text)) {
    ctx->diags.error({file, line, col}, badProgramNumberMessage(value));
    return -1;
  }
  for (uint64_t i = 0; i < n; ++i)
    if (ctx->text == names[i]) return (int64_t)i;
  ctx->diags.error({file, line, col}, unknownProgramMessage(ctx->text));
  return -1;
}

double ncrt_str_const(ncrt_ctx *ctx, const char *s, uint64_t len, uint32_t file, uint32_t line, uint32_t col) {
  double h;
  std::string err;
  return ctx->pool.intern(std::string_view(s, len), h, err) ? h : failed(ctx, file, line, col, err);
}

double ncrt_str_intern(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col) {
  double h;
  std::string err;
  return ctx->pool.intern(ctx->text, h, err) ? h : failed(ctx, file, line, col, err);
}

double ncrt_strfn(ncrt_ctx *ctx, uint32_t index, const double *args, uint32_t n, uint32_t file, uint32_t line,
                  uint32_t col) {
  unsigned count = 0;
  const BuiltinInfo *tab = builtinTable(count);
  double r;
  std::string err;
  if (index >= count || !tab[index].sfn) return failed(ctx, file, line, col, "internal error: not a string builtin");
  return tab[index].sfn(ctx->pool, args, n, r, err) ? r : failed(ctx, file, line, col, err);
}

double ncrt_compare(ncrt_ctx *ctx, int32_t op, double a, double b, uint32_t file, uint32_t line, uint32_t col) {
  double r;
  std::string err;
  return compareStrings(ctx->pool, op, a, b, r, err) ? r : failed(ctx, file, line, col, err);
}

double ncrt_convert(ncrt_ctx *ctx, uint32_t type, uint32_t len, const char *name, double v, uint32_t file,
                    uint32_t line, uint32_t col) {
  double r;
  std::string err;
  return convertForStore(ctx->pool, (ValueType)type, len, name, v, r, err) ? r : failed(ctx, file, line, col, err);
}

void ncrt_fill(double *p, uint64_t n, double v) { std::fill_n(p, n, v); }

void ncrt_bad_index(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, const char *name, double index,
                    uint32_t dim, uint32_t rank, uint32_t extent) {
  failed(ctx, file, line, col, declaredIndexMessage(name, index, dim, rank, extent));
}

double ncrt_mod(double a, double b) { return arithMod(a, b); }
double ncrt_bitwise(int32_t op, double a, double b) { return arithBitwise(op, a, b); }
double ncrt_idiv(double a, double b) { return arithIDiv(a, b); }
double ncrt_pow(double a, double b) { return arithPow(a, b); }

}  // extern "C"

// ---------------------------------------------------------------- compiled programs
const char *ncrt_version(void) { return NCC_VERSION; }

namespace ncc::ncrt {

const std::vector<RuntimeSymbol> &runtimeSymbols() {
  static const std::vector<RuntimeSymbol> table = [] {
    std::vector<RuntimeSymbol> t;
    auto add = [&](const char *name, auto *fn) { t.push_back({name, reinterpret_cast<void *>(fn)}); };
    add("ncrt_begin", &ncrt_begin);
    add("ncrt_exec", &ncrt_exec);
    add("ncrt_exec_table", &ncrt_exec_table);
    add("ncrt_exec_packed", &ncrt_exec_packed);
    add("ncrt_exec_blocks", &ncrt_exec_blocks);
    add("ncrt_exec_mode", &ncrt_exec_mode);
    add("ncrt_exec_move", &ncrt_exec_move);
    add("ncrt_error", &ncrt_error);
    add("ncrt_fault", &ncrt_fault);
    add("ncrt_poll", &ncrt_poll);
    add("ncrt_mod", &ncrt_mod);
    add("ncrt_bitwise", &ncrt_bitwise);
    add("ncrt_idiv", &ncrt_idiv);
    add("ncrt_pow", &ncrt_pow);
    add("ncrt_unset", &ncrt_unset);
    add("ncrt_str_clear", &ncrt_str_clear);
    add("ncrt_str_cat", &ncrt_str_cat);
    add("ncrt_str_num", &ncrt_str_num);
    add("ncrt_sysvar", &ncrt_sysvar);
    add("ncrt_sysvar_at", &ncrt_sysvar_at);
    add("ncrt_sysvar_set", &ncrt_sysvar_set);
    add("ncrt_param", &ncrt_param);
    add("ncrt_str_num_fixed", &ncrt_str_num_fixed);
    add("ncrt_str", &ncrt_str);
    add("ncrt_callee", &ncrt_callee);
    add("ncrt_jump", &ncrt_jump);
    add("ncrt_save_modal", &ncrt_save_modal);
    add("ncrt_modal_trigger", &ncrt_modal_trigger);
    add("ncrt_set_modal_hook", &ncrt_set_modal_hook);
    add("ncrt_restore_modal", &ncrt_restore_modal);
    add("ncrt_str_const", &ncrt_str_const);
    add("ncrt_str_intern", &ncrt_str_intern);
    add("ncrt_strfn", &ncrt_strfn);
    add("ncrt_compare", &ncrt_compare);
    add("ncrt_convert", &ncrt_convert);
    add("ncrt_fill", &ncrt_fill);
    add("ncrt_bad_index", &ncrt_bad_index);
    unsigned n = 0;
    const BuiltinInfo *tab = builtinTable(n);
    for (unsigned i = 0; i < n; ++i)
      if (tab[i].fn) add(tab[i].symbol, tab[i].fn);
    return t;
  }();
  return table;
}

bool runEntry(ncrt_entry entry, CmdSink &sink, Diagnostics &diags, const ExecLimits &limits, bool *hot) {
  ncrt_ctx rt(sink, diags, limits);
  int status = entry(&rt);
  if (hot) *hot = rt.polls > 0;
  // As the eval engine: a program stopped by M2/M30 (or a failing sink) succeeded unless an
  // error was reported.
  if (status == NCRT_END) return !diags.hasErrors();
  return status == NCRT_OK;
}

uint64_t textHash(std::string_view text) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

static constexpr char kTrailerMagic[8] = {'N', 'C', 'C', 'S', 'U', 'M', '1', 0};

std::string objectTrailer(std::string_view object) {
  uint64_t h = textHash(object);
  return std::string(kTrailerMagic, 8) + std::string(reinterpret_cast<const char *>(&h), 8);
}

bool hasObjectTrailer(std::string_view file) {
  if (file.size() < 16) return false;
  std::string_view body = file.substr(0, file.size() - 16);
  return file.substr(body.size()) == objectTrailer(body);
}

// What generated code bakes in: command and storage layout, word and kind numbering, the
// builtin and system variable tables it indexes.
uint64_t abiFingerprint() {
  unsigned builtins = 0;
  builtinTable(builtins);
  const uint64_t parts[] = {NCRT_ABI_VERSION,         sizeof(MachineCmd),    offsetof(MachineCmd, w),
                            offsetof(MachineCmd, loc), kWords,                (uint64_t)CmdKind::Count,
                            kMaxModes,                sizeof(ncrt_storage),  builtins,
                            (uint64_t)kSysVarIds,     NCRT_NUMBERED,         NCRT_QPARAMS};
  return textHash(std::string_view(reinterpret_cast<const char *>(parts), sizeof parts));
}

// Layout: "NCCPROG1", u64 total size, u64 abi, strings (u32 length + bytes) version, machine
// name, machine text, program, u32 file count, then per file its name and u64 hash. Little endian.
static constexpr char kInfoMagic[8] = {'N', 'C', 'C', 'P', 'R', 'O', 'G', '1'};

std::string encodeProgramInfo(const ProgramInfo &info) {
  std::string out(kInfoMagic, sizeof kInfoMagic);
  auto u64 = [&](uint64_t v) { out.append(reinterpret_cast<const char *>(&v), 8); };
  auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char *>(&v), 4); };
  auto str = [&](const std::string &s) { u32((uint32_t)s.size()), out += s; };
  u64(0);  // the size, filled in below
  u64(info.abi);
  str(info.nccVersion);
  str(info.machineName);
  str(info.machineText);
  str(info.program);
  u32((uint32_t)info.files.size());
  for (auto &f : info.files) str(f.name), u64(f.hash);
  uint64_t size = out.size();
  std::memcpy(&out[8], &size, 8);
  return out;
}

bool decodeProgramInfo(const unsigned char *data, size_t size, ProgramInfo &out, std::string &err) {
  const unsigned char *p = data, *end = data + size;
  bool ok = true;
  auto take = [&](void *dst, size_t n) {
    if (!ok || (size_t)(end - p) < n) return ok = false;
    std::memcpy(dst, p, n);
    p += n;
    return true;
  };
  auto str = [&](std::string &s) {
    uint32_t n = 0;
    if (!take(&n, 4) || (size_t)(end - p) < n) return ok = false;
    s.assign(reinterpret_cast<const char *>(p), n);
    p += n;
    return true;
  };
  char magic[8];
  uint64_t total = 0;
  if (!take(magic, 8) || std::memcmp(magic, kInfoMagic, 8) || !take(&total, 8) || total > size) {
    err = "it holds no ncc program description";
    return false;
  }
  end = data + total;
  uint32_t files = 0;
  take(&out.abi, 8);
  if (ok && out.abi != abiFingerprint()) {
    str(out.nccVersion);
    err = fmt::format("it was compiled by another ncc ({}, runtime ABI {:016x}; this is {}, {:016x}): compile it again",
                      ok ? out.nccVersion : "unknown", out.abi, ncrt_version(), abiFingerprint());
    return false;
  }
  str(out.nccVersion), str(out.machineName), str(out.machineText), str(out.program), take(&files, 4);
  for (uint32_t i = 0; ok && i < files; ++i) {
    out.files.emplace_back();
    str(out.files.back().name), take(&out.files.back().hash, 8);
  }
  if (!ok || p != end) {
    err = "its program description is corrupt";
    return false;
  }
  return true;
}

}  // namespace ncc::ncrt
