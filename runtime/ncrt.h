/* ncrt: the C ABI between compiled NC programs (JIT or AOT object files from backends/jit) and
 * the runtime. Generated code owns no state of its own: variable storage, limits and the command
 * target live in an ncrt_ctx, which wraps a command target (normally the Executor) and the
 * Diagnostics of the run.
 *
 * Calling convention of generated code (see docs/JIT.md):
 *   int ncc_program_main(ncrt_ctx *ctx);   returns NCRT_OK, NCRT_END or NCRT_ERROR
 * Every ncrt_exec* returns NCRT_OK, NCRT_END (a stop kind=end|end_rewind was executed: the
 * program ends) or NCRT_ERROR (already reported); generated code returns the status at once.
 */
#ifndef NCC_RUNTIME_NCRT_H
#define NCC_RUNTIME_NCRT_H

#include <stdint.h>

#ifdef __cplusplus
#include "ir/MachineCmd.h"
#include "ir/Strings.h"
#include "ir/CmdSink.h"  // where commands go (the Executor, or a recorder in tests)
#include "ir/ExecLimits.h"

#include <chrono>
#include <string>
#include <vector>
extern "C" {
typedef ncc::MachineCmd ncrt_cmd;
#else
typedef struct ncrt_cmd ncrt_cmd; /* ncc::MachineCmd, ir/MachineCmd.h */
#endif

typedef struct ncrt_ctx ncrt_ctx;

enum { NCRT_OK = 0, NCRT_END = 1, NCRT_ERROR = 2 };

/* Run-time faults whose message the runtime formats (it knows the limits); the texts are the
 * eval engine's (passes/Eval.cpp), so both engines report the same errors. */
enum {
  NCRT_FAULT_LOOP_LIMIT = 1,    /* loop did not terminate after N iterations (...) */
  NCRT_FAULT_BACKJUMP = 2,      /* backward jump repeated more than N times (...) */
  NCRT_FAULT_CALL_DEPTH = 3,    /* call depth limit N exceeded (...) */
  NCRT_FAULT_UNSET_VAR = 4,     /* variable 'name' used before assignment */
  NCRT_FAULT_NUMBERED = 5,      /* parameter number #lround(value) out of range */
  NCRT_FAULT_RPARAM = 6,        /* R parameter index lround(value) out of range */
  NCRT_FAULT_QPARAM = 7,        /* Q parameter index lround(value) out of range */
  NCRT_FAULT_INDEX = 8,         /* index value of array 'name' is not an integer in 0..N */
  NCRT_FAULT_UNSET_ELEM = 9,    /* array element 'name[value]' used before assignment */
  NCRT_FAULT_SYSVAR = 10        /* system variable 'name' is not available here */
};

/* Variable storage and limits, laid out for direct access from generated code. Numbered slots
 * start vacant, R and Q parameters as ir/Value.h says (0; QS the empty string); named globals
 * start unset (NCRT_UNSET_BITS), declared ones with their type's initial value (set by the
 * generated entry). */
typedef struct ncrt_storage {
  double *numbered;   /* #0 .. #(NCRT_NUMBERED-1); #1..#33 are never used here (frame locals) */
  double *rparam;     /* R0 .. R(NCRT_RPARAMS-1) */
  double *qparam;     /* q_spaces arrays of NCRT_QPARAMS, array i for Q prefix i (qPrefixIndex) */
  double *named;      /* named globals (%%name), then the global arrays (declared size, else kArrayElements) */
  uint64_t max_loop;  /* ExecLimits::maxLoopIterations */
  uint32_t max_depth; /* ExecLimits::maxCallDepth */
  uint32_t depth;     /* current call depth; main = 0 */
  int64_t poll;       /* loop iterations left until the next run-time check */
} ncrt_storage;

/* Bit pattern of an unset named variable (a NaN distinct from vacant, never produced by
 * arithmetic). */
#define NCRT_UNSET_BITS 0x7ff8dead0000f00dull
/* Array sizes (the eval engine's). */
#define NCRT_NUMBERED 100000
#define NCRT_RPARAMS 1000
#define NCRT_QPARAMS 2000
/* Loop iterations between two run-time limit checks. */
#define NCRT_POLL_INTERVAL 65536
/* Raised when the C ABI changes in a way abiFingerprint cannot see (a function's meaning). */
#define NCRT_ABI_VERSION 3

/* Allocates the storage for a program with the given number of named globals and Q prefix
 * arrays (1 + the highest qPrefixIndex it uses; 0 for none). */
ncrt_storage *ncrt_begin(ncrt_ctx *ctx, uint32_t named_globals, uint32_t q_spaces);
/* Sets n doubles to the unset pattern (a function's named local arrays). */
void ncrt_unset(double *p, uint64_t n);
/* Executes one command. */
int ncrt_exec(ncrt_ctx *ctx, const ncrt_cmd *cmd);
/* Executes n commands of a constant table. */
int ncrt_exec_table(ncrt_ctx *ctx, const ncrt_cmd *cmds, uint64_t n);
/* Executes `count` Block commands in a row that end with `last` (CmdSink::execBlocks: code
 * compiled to merge blocks calls this; count 0 does nothing). */
int ncrt_exec_blocks(ncrt_ctx *ctx, const ncrt_cmd *last, uint64_t count);
/* The `blocks` waiting Block commands ending with *last (none when 0), then the Mode command
 * *mode, in one call (CmdSink::execMode: a mode in force costs a compare). */
int ncrt_exec_mode(ncrt_ctx *ctx, const ncrt_cmd *last, uint64_t blocks, const ncrt_cmd *mode);
/* The same, then the Move command *move, in one call (CmdSink::execMove); mode may be null.
 * Code compiled to merge blocks calls this for a move whose operands make no runtime call. */
int ncrt_exec_move(ncrt_ctx *ctx, const ncrt_cmd *last, uint64_t blocks, const ncrt_cmd *mode, const ncrt_cmd *move);
/* Executes a packed command stream (ncc::ncrt::packCmd encoding) of nbytes bytes. */
int ncrt_exec_packed(ncrt_ctx *ctx, const uint8_t *data, uint64_t nbytes);
/* Reports a run-time error at a source location. */
void ncrt_error(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, const char *msg);
/* Reports one of the NCRT_FAULT_* errors; name/value complete the message. */
void ncrt_fault(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, uint32_t kind,
                const char *name, double value);
/* Called when storage->poll runs out: resets it and checks the run-time limit. Returns
 * NCRT_ERROR (reported at the given loc) when the limit is exceeded, else NCRT_OK. */
int ncrt_poll(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col);
/* Run-time texts (message texts, computed callees, concat before ncrt_str_intern): generated
 * code clears the context's text buffer, appends the leaves of a string expression in order,
 * then reads it. Values are appended as ncc::valueText (ir/Strings.h): strings as they are,
 * numbers as numberText (ncrt_str_num_fixed: fixedNumberText). */
void ncrt_str_clear(ncrt_ctx *ctx);
void ncrt_str_cat(ncrt_ctx *ctx, const char *s);
void ncrt_str_num(ncrt_ctx *ctx, double v);
/* System variables travel as an ncc::SysRef in one double (ir/SystemVars.h sysRefNumber). */
/* The value of system variable `ref` (named `name`) from the sink, or unset after an error at
   the loc (RunError::SysVar when the sink has none, or the sink's reason). */
double ncrt_sysvar(ncrt_ctx *ctx, double ref, const char *name, uint32_t file, uint32_t line, uint32_t col);
/* The SysRef of member (i, j, k) of family `family` (ir/SystemVars.h sysVarAt), or unset after
   an error at the loc. */
double ncrt_sysvar_at(ncrt_ctx *ctx, uint32_t family, double i, double j, double k, const char *name, uint32_t file,
                      uint32_t line, uint32_t col);
/* Writes system variable `ref`: 0, or unset after an error at the loc. */
double ncrt_sysvar_set(ncrt_ctx *ctx, double ref, double v, uint32_t file, uint32_t line, uint32_t col);
/* A computed parameter number n that map `map` (ncc::ParamMap) does not make plain storage:
   access 0 reads it (the value), 1 writes v (0), 2 is a by-reference argument (an error); unset
   after an error at the loc (ir/SystemParams.h accessSystemParameter, as the eval engine). */
double ncrt_param(ncrt_ctx *ctx, uint32_t map, uint32_t access, double n, double v, uint32_t file, uint32_t line,
                  uint32_t col);
void ncrt_str_num_fixed(ncrt_ctx *ctx, double v);  // fixedNumberText
const char *ncrt_str(ncrt_ctx *ctx);
/* modal_call: the program's modal-call function (i32 (ctx, storage, file, line, col)), which the
 * runtime calls after every move command it executes; it returns at once when no modal call is
 * set or one runs (docs/IR.md §5.5). Moves stay in constant runs. */
void ncrt_set_modal_hook(ncrt_ctx *ctx, void *fn);
/* SAVE (CmdSink saveModal/restoreModal) around a call: NCRT_OK or NCRT_ERROR (reported). */
int ncrt_save_modal(ncrt_ctx *ctx);
/* modal_trigger: the executor's modal cycle (cycleTriggerCmd), then the modal-call function, as after a move (none set: nothing). */
int ncrt_modal_trigger(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col);
int ncrt_restore_modal(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col);
/* A computed goto (ir/Jumps.h findJump over the function's `count` entries, an ir::JumpEntry
 * array): label != 0 searches the label named by the text buffer, else block number n. Returns
 * the entry's index, or -1 after reporting the missing target at the loc. */
int64_t ncrt_jump(ncrt_ctx *ctx, int label, double n, const void *entries, uint64_t count, uint32_t from, uint32_t dir,
                  uint32_t file, uint32_t line, uint32_t col);
/* A computed callee: the index in names[0..n) of the function named by the text buffer, or when
 * `numeric` by the program number `value` (O<n>). Reports the error at the loc and returns -1
 * when there is no such function. */
int64_t ncrt_callee(ncrt_ctx *ctx, int numeric, double value, const char *const *names, uint64_t n,
                    uint32_t file, uint32_t line, uint32_t col);
/* Typed values (ir/Strings.h). Functions returning a double return NCRT_UNSET_BITS after
 * reporting an error at the loc; generated code then returns NCRT_ERROR.
 *  ncrt_str_const   the handle of a string constant (len bytes)
 *  ncrt_str_intern  the handle of the text buffer (a concat built with ncrt_str_cat/num)
 *  ncrt_strfn       string builtin `index` of ir/Builtins.h builtinTable on n raw arguments
 *  ncrt_compare     a comparison (op eq..ge = 0..5) where an operand is a string
 *  ncrt_convert     a store into a variable of ValueType `type` (STRING: at most len bytes)
 *  ncrt_fill        n doubles set to v (declared arrays)
 *  ncrt_bad_index   reports declaredIndexMessage */
double ncrt_str_const(ncrt_ctx *ctx, const char *s, uint64_t len, uint32_t file, uint32_t line, uint32_t col);
double ncrt_str_intern(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col);
double ncrt_strfn(ncrt_ctx *ctx, uint32_t index, const double *args, uint32_t n, uint32_t file, uint32_t line,
                  uint32_t col);
double ncrt_compare(ncrt_ctx *ctx, int32_t op, double a, double b, uint32_t file, uint32_t line, uint32_t col);
double ncrt_convert(ncrt_ctx *ctx, uint32_t type, uint32_t len, const char *name, double v, uint32_t file,
                    uint32_t line, uint32_t col);
void ncrt_fill(double *p, uint64_t n, double v);
void ncrt_bad_index(ncrt_ctx *ctx, uint32_t file, uint32_t line, uint32_t col, const char *name, double index,
                    uint32_t dim, uint32_t rank, uint32_t extent);
/* Arithmetic of ir/Arith.h on num() operands (the divisor is checked by the caller). */
double ncrt_mod(double a, double b);
double ncrt_bitwise(int32_t op, double a, double b);  /* arithBitwise: NaN on non-integers */
double ncrt_idiv(double a, double b);
double ncrt_pow(double a, double b);

/* Running compiled programs (docs/AOT.md). An object from `ncc compile --emit=obj` defines the
 * entry and, beside it, a description of the program (ncc_program_info: the runtime ABI it was
 * compiled against, the machine, the source file names), so running it needs no source.
 * ncrt_main is `ncc run` for such a program: it takes ncc run's output options (--trace, -o, -q,
 * --plot, --samples, --plot-velocity, the limits, --machine to check the machine) and returns
 * the exit code (0 success, 1 errors, 2 usage). An executable from `ncc compile --emit=exe` is
 * this call; it is defined in libncc_aotrun (CMake: ncc::runtime). */
typedef int (*ncrt_entry)(ncrt_ctx *ctx);
int ncc_program_main(ncrt_ctx *ctx);
extern const unsigned char ncc_program_info[];
int ncrt_main(int argc, char **argv, ncrt_entry entry, const unsigned char *info);
/* The ncc version this runtime belongs to ("0.1.0"). */
const char *ncrt_version(void);

#ifdef __cplusplus
}  // extern "C"

namespace ncc {
namespace ncrt {
// Appends one command to a packed stream: kind sub sub2 nmodes modes[nmodes] (bytes), then
// LEB128 mask, blockNumber+1 (Block only), file, line, col, then the doubles of the mask words
// (8 bytes each, in word order), then for Comment/Message LEB128 length + text + NUL.
void packCmd(const MachineCmd &cmd, const char *text, std::string &out);

// Every C symbol compiled code may call (ncrt_* and the builtins' ncc_builtin_*), with its
// address: what the JIT and the object loader resolve an object's undefined symbols with.
struct RuntimeSymbol {
  const char *name;
  void *address;
};
const std::vector<RuntimeSymbol> &runtimeSymbols();

// Runs a compiled entry against the sink: true unless an error was reported (a program stopped
// by M2/M30 succeeded). Does not finish the sink's executor. hot: set to whether the run made
// NCRT_POLL_INTERVAL loop iterations or backward jumps (the JIT cache then optimises the code).
bool runEntry(ncrt_entry entry, CmdSink &sink, Diagnostics &diags, const ExecLimits &limits, bool *hot = nullptr);

// What an object carries beside its code (the ncc_program_info bytes): the layout compiled code
// was built against (abiFingerprint, a stale object is refused), the machine description it was
// compiled for (the front end read the program with its settings) and the source files, in file
// id order, with a hash of their text (messages show a source line only while it is unchanged).
struct ProgramInfo {
  uint64_t abi = 0;
  std::string nccVersion, machineName, machineText;
  std::string program;  // the program's file (summary, plot title)
  struct File {
    std::string name;
    uint64_t hash = 0;
  };
  std::vector<File> files;
};
uint64_t abiFingerprint();
uint64_t textHash(std::string_view text);  // FNV-1a
// An object file ends with a trailer holding the hash of what precedes it (ELF readers ignore
// bytes after the last section), so a damaged object is refused before its code runs.
std::string objectTrailer(std::string_view object);
bool hasObjectTrailer(std::string_view file);
std::string encodeProgramInfo(const ProgramInfo &info);
// `size`: the bytes available (the symbol's size); false with the reason when they are not a
// program description this runtime can read.
bool decodeProgramInfo(const unsigned char *data, size_t size, ProgramInfo &out, std::string &err);
}  // namespace ncrt
}  // namespace ncc

struct ncrt_ctx {
  ncrt_ctx(ncc::CmdSink &sink, ncc::Diagnostics &diags, const ncc::ExecLimits &limits);
  ncc::CmdSink &sink;
  ncc::Diagnostics &diags;
  ncc::ExecLimits limits;
  std::chrono::steady_clock::time_point start;
  ncrt_storage storage{};
  std::vector<double> numbered, rparam, qparam, named;
  bool ended = false;  // a stop kind=end|end_rewind was executed
  uint64_t polls = 0;  // ncrt_poll calls: NCRT_POLL_INTERVAL loop iterations or backward jumps each
  // A program with modal_call: its nc.modal.run, called after every move command executed.
  int (*modal_hook)(ncrt_ctx *, ncrt_storage *, uint32_t, uint32_t, uint32_t) = nullptr;
  std::string text;    // the run-time string being built (ncrt_str_*)
  ncc::ValuePool pool;  // the run's string values
};
#endif

#endif /* NCC_RUNTIME_NCRT_H */
