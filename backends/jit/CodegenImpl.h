// Internal to backends/jit: the code generator's state, shared by Codegen.cpp (module,
// functions, frames), CodegenCtl.cpp (statements, control flow), CodegenExpr.cpp (expressions,
// variables) and CodegenCmd.cpp (machine commands and constant tables).
//
// The generated code reproduces the eval engine (passes/Eval.cpp) exactly: same values, same
// command stream, same run-time errors with the same texts, at the same points of execution.
#pragma once
#include "ir/Value.h"
#include "ir/Decls.h"
#include "ir/Jumps.h"
#include "ir/NCIR.h"
#include "ir/SystemParams.h"
#include "passes/CmdTemplate.h"

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include <functional>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace ncc::jit {

// Frame layout: slot 0 unused, #1..#33 Macro B locals, then named locals.
constexpr int kFrameLocals = kMacroLocals;
using ir::DeclTable;
using ir::VarDecl;

// A value of an expression and whether it can be vacant at run time (variable reads);
// arithmetic results never are, so most vacant checks fold away at compile time.
// mayHandle: the value can be a handle, a string or a frame (ir/Value.h isHandle): loads of named
// variables that are not declared numeric, QS parameters, string constants and typed-builtin
// results. Only such values get a handle check where a number is needed, at `loc` (where the
// value came from).
struct Val {
  llvm::Value *v;
  bool mayVacant;
  bool mayHandle = false;
  SourceLoc loc = {};
};

// A named array's storage: its first slot and its number of elements.
struct ArraySlots {
  uint64_t offset = 0, size = 0;
};

// One NC function: its LLVM function, its frame layout and the errors the eval engine would
// raise when it first compiles it (reported when the function is first called).
struct FnInfo {
  const ir::Function *fn = nullptr;
  llvm::Function *F = nullptr;
  std::map<std::string, unsigned> locals;  // named locals: frame slot 34 + index
  std::map<std::string, ArraySlots> arrays;  // named local arrays in the activation's array block
  uint64_t arraySlots = 0;                   // doubles in that block
  unsigned frameSize = 35;                 // #0..#33, the named locals, the return value (unset: none)
  std::vector<std::pair<SourceLoc, std::string>> compileErrors;
  bool hasBlocks = false;  // a block op anywhere in the body
};

class Codegen {
public:
  Codegen(const ir::Module &src, llvm::LLVMContext &ctx, Diagnostics &diags, bool mergeBlocks);
  std::unique_ptr<llvm::Module> run();
  // A goto whose target is a constant (resolved when compiled); else computed when it runs.

private:
  // ------------------------------------------------ module level (Codegen.cpp)
  void declareRuntime();
  void markRuntimeOnly();
  void scanNames(FnInfo &fi, const ir::Region &r);
  void scanExprNames(FnInfo &fi, const ir::Expr &e);
  void emitFunction(FnInfo &fi);
  void emitEntry();
  void emitParamDefaults(FnInfo &fi);
  void startSections(FnInfo &fi);
  void initFrame(llvm::Value *frame, unsigned size, unsigned from);
  // ------------------------------------------------ control flow (CodegenCtl.cpp)
  void validate(FnInfo &fi);
  void scanTargets(const ir::Region &r);
  void emitRegion(const ir::Region &r);
  void emitOp(const ir::Op &op);
  void emitIf(const ir::Op &op);
  void emitLoop(const ir::Op &op);
  // Loop variables in slots (CodegenLoop.cpp).
  struct KeptVar {
    std::string key;
    llvm::Value *home, *slot;
  };
  std::string cacheKey(const ir::Expr &var);
  bool loopVars(const ir::Op &loop, std::vector<const ir::Expr *> &vars);
  std::vector<KeptVar> keepLoopVars(const ir::Op &loop);
  void releaseLoopVars(const std::vector<KeptVar> &kept);
  void emitGoto(const ir::Op &op);
  void emitCall(const ir::Op &op);
  llvm::Value *convertArg(FnInfo &fi, const std::string &key, Val v, SourceLoc loc);
  // Returns the callee's return value (unset bits when it returned none).
  llvm::Value *emitInvoke(FnInfo &fi, const std::vector<std::pair<std::string, llvm::Value *>> &args, bool newFrame,
                          SourceLoc loc);
  const ir::Op *resolveTarget(const ir::Op &go);
  void emitJumpTo(const ir::Op &go, const ir::Op *target);
  void emitBackJump(SourceLoc loc);  // counts a backward jump toward the loop limit
  void emitCallSection(const ir::Op &op);
  void scanModalCalls();
  void emitModalCall(const ir::Op &op);
  void emitModalRun();
  void startBody();
  bool calleeOf(const ir::Op &op, FnInfo *&fixed, llvm::Value *&index);
  void emitRepeated(llvm::Value *count, SourceLoc loc, const std::function<void()> &body);
  void switchOnFunction(llvm::Value *index, const std::vector<FnInfo *> &fns, const std::function<void(FnInfo &)> &body);
  std::vector<FnInfo *> allFunctions();
  unsigned functionIndex(const FnInfo &fi) const { return (unsigned)(fi.fn - src_.functions.data()); }
  static bool numberedKey(const std::string &k) { return !k.empty() && k[0] >= '0' && k[0] <= '9'; }
  void emitSectionEnd(const std::vector<const ir::Op *> &calls);
  llvm::BasicBlock *sectionReturn(const ir::Op &call);
  llvm::BasicBlock *targetBlock(const ir::Op *op);
  void emitTimeCheck(SourceLoc loc);
  // ------------------------------------------------ helpers (Codegen.cpp)
  llvm::BasicBlock *newBlock(const char *name);
  void startBlock(llvm::BasicBlock *bb);  // falls through from an open current block
  void ensureOpen();                      // after a terminator: continue in a dead block
  // An entry-block slot; `init` is stored at function entry (loop state is 0 there, as in the
  // eval engine, for gotos that jump into a loop body without entering the loop).
  llvm::Value *allocaEntry(llvm::Type *t, const char *name, llvm::Constant *init = nullptr);
  void checkStatus(llvm::Value *status);  // returns the status when it is not NCRT_OK
  // With mergeBlocks_, a Block command waits in blkCount/blkLast until a call that reaches the
  // target: sinkCall passes the waiting ones on first (flushBlocks, CmdSink::execBlocks), as do
  // the function's exits.
  llvm::CallInst *sinkCall(llvm::FunctionCallee f, llvm::ArrayRef<llvm::Value *> args);
  void flushBlocks(bool check = true);
  void emitBlockCmd(const MachineCmd &c);
  void emitReturn();  // flushBlocks, return NCRT_OK
  void failIf(llvm::Value *cond, SourceLoc loc, const std::string &msg);
  void fail(SourceLoc loc, const std::string &msg);  // unconditional; continues in a dead block
  void faultIf(llvm::Value *cond, SourceLoc loc, unsigned kind, const std::string &name, llvm::Value *value);
  llvm::Constant *cstring(const std::string &s);
  std::vector<llvm::Value *> locArgs(SourceLoc loc);
  // ------------------------------------------------ expressions (CodegenExpr.cpp)
  Val expr(const ir::Expr &e);
  llvm::Value *sysVarRef(const ir::Expr &var);
  Val binary(const ir::Expr &e);
  Val callBuiltin(const ir::Expr &e);
  llvm::Value *numOf(Val v);  // a handle is the error HandleUse::AsNumber at v.loc
  llvm::Value *numOf(Val v, SourceLoc loc, HandleUse use, std::string_view name = {});
  llvm::Value *isStr(llvm::Value *v);
  llvm::Value *isFrameHandle(llvm::Value *v);
  llvm::Value *isHandleBits(llvm::Value *v);
  // Fails with handleMessage(use, kind, name) when v is a handle (a string passes if stringsOk).
  void checkNotHandle(Val v, SourceLoc loc, HandleUse use, std::string_view name = {}, bool stringsOk = false);
  llvm::Value *checked(llvm::Value *result);  // unset bits (a reported error) -> fail
  Val stringConst(const std::string &s, SourceLoc loc);
  Val concat(const ir::Expr &e);
  Val compare(const ir::Expr &e, Val a, Val b);
  llvm::Value *convertFor(const ir::Expr &var, const VarDecl *d, Val value);
  const VarDecl *declOf(const ir::Expr &var);
  void collectLeaves(const ir::Expr &e, std::vector<const ir::Expr *> &out);
  llvm::Value *truthy(Val v);  // i1
  llvm::Value *isVacant(llvm::Value *v);
  llvm::Value *toDouble(llvm::Value *i1);
  llvm::Value *roundOf(llvm::Value *v);  // llvm.round: half away from zero, like lround
  llvm::Value *varPtr(const ir::Expr &var, bool write);
  llvm::Value *numberedPtr(const ir::Expr &var, bool write);
  llvm::Value *numberedSlot(const ir::Expr &var, llvm::Value *x, bool write);  // #[x], x computed
  // #[(NGC_PARAMETER e)] and the other maps (ir/SystemParams.h): plain numbers inline, the rest
  // through ncrt_param.
  llvm::Value *plainNumber(ParamMap m, llvm::Value *r);
  llvm::Value *splitComputed(const ir::Expr &e, ParamMap m, llvm::BasicBlock *plain, llvm::BasicBlock *sys);
  Val loadComputed(const ir::Expr &var, const ir::Expr &e, ParamMap m);
  void storeComputed(const ir::Expr &var, const ir::Expr &e, ParamMap m, Val value);
  llvm::Value *joined(llvm::Value *a, llvm::BasicBlock *aEnd, llvm::Value *b, llvm::BasicBlock *bEnd);  // a phi
  llvm::Value *elemPtr(const ir::Expr &var, llvm::Value *base);
  llvm::Value *declaredElemPtr(const ir::Expr &var, llvm::Value *base, const VarDecl &d);
  llvm::Value *paramPtr(const ir::Expr &var, llvm::Value *base, int64_t count, unsigned fault);
  Val loadVar(const ir::Expr &var);
  // Builds a string expression; ptr to its text. fixed: numbers as fixedNumberText.
  llvm::Value *stringValue(const ir::Expr &e, bool fixed = false);
  void appendString(const ir::Expr &e, bool fixed);
  void storeVar(const ir::Expr &var, Val value);
  // ------------------------------------------------ commands (CodegenCmd.cpp)
  void emitMachineOp(const ir::Op &op);
  void appendToRun(const MachineCmd &c);
  void flushRun();
  // A move whose operands make no runtime call takes the run's lone Mode command with it
  // (ncrt_exec_move): takeModeRun leaves it in pendingMode_ (flushing any other run), an error
  // while the operands are evaluated executes it first (flushPendingMode, from failIf/faultIf/fail).
  llvm::Value *takeModeRun();
  void flushPendingMode();
  llvm::Value *pendingMode_ = nullptr;
  void takeWaitingBlocks(llvm::Value *&last, llvm::Value *&count);  // and sets the count to 0
  void emitDynamicCmd(const CmdTemplate &t, bool oneCall);
  llvm::Value *cmdSiteSlot(const MachineCmd &base);
  void storeCmd(const MachineCmd &c, llvm::Value *slot);
  llvm::Constant *cmdConstant(const MachineCmd &c);

  const ir::Module &src_;
  llvm::LLVMContext &C;
  Diagnostics &diags_;
  bool mergeBlocks_;  // the target takes runs of blocks as one call (CmdSink::mergesBlocks)
  bool blkOn_ = false;  // mergeBlocks_ and the function being emitted has block ops
  std::unique_ptr<llvm::Module> M;
  llvm::IRBuilder<> B;
  bool failed_ = false;

  llvm::Type *dblTy, *i8Ty, *i16Ty, *i32Ty, *i64Ty, *i1Ty;
  llvm::PointerType *ptrTy;
  llvm::StructType *cmdTy, *storageTy;
  llvm::FunctionType *ncFnTy;
  llvm::FunctionCallee fBegin, fExec, fExecTable, fExecBlocks, fExecMode, fExecMove, fExecPacked, fError, fFault, fPoll, fMod, fIDiv, fPow, fBitwise;
  llvm::FunctionCallee fUnset, fStrClear, fStrCat, fStrNum, fStrNumFixed, fStr, fCallee, fSysVar, fSysVarAt, fSysVarSet;
  llvm::FunctionCallee fParam;  // ncrt_param: computed parameter numbers that are controller state
  llvm::FunctionCallee fStrConst, fStrIntern, fStrFn, fCompare, fConvert, fFill, fBadIndex, fJump, fSaveModal, fRestoreModal, fSetModalHook,
      fModalTrigger;
  std::map<std::string, llvm::FunctionCallee> builtins_;
  std::map<std::string, FnInfo> functions_;
  std::map<std::string, llvm::Constant *> strings_;
  // modal_call: the callee set (index into the module's functions, -1 none), whether a modal
  // callee runs, one argument slot per key any modal_call passes; the functions it may call.
  llvm::GlobalVariable *modalFn_ = nullptr, *modalIn_ = nullptr, *modalArgs_ = nullptr, *modalCount_ = nullptr;
  std::map<std::string, unsigned> modalKeys_;
  llvm::Function *modalRun_ = nullptr;  // nc.modal.run
  std::vector<llvm::Value *> dynLoc_;   // while emitting nc.modal.run: its location arguments
  std::vector<FnInfo *> modalCallees_;
  llvm::GlobalVariable *calleeNames = nullptr;  // names of the module's functions, for ncrt_callee
  std::map<std::string, unsigned> globalNames_;   // module-wide slots
  std::map<std::string, ArraySlots> globalArrays_;  // global arrays, stored after the scalars
  uint64_t globalArraySlots_ = 0;
  DeclTable decls_;
  unsigned qSpaces_ = 0;                          // Q prefix arrays: 1 + highest qPrefixIndex used

  // ------------------------------------------------ per function
  FnInfo *cur_ = nullptr;
  llvm::Function *F = nullptr;
  llvm::BasicBlock *entryBB = nullptr, *failBB = nullptr, *exitBB = nullptr;
  llvm::PHINode *exitPhi = nullptr;
  llvm::Value *ctxArg, *stArg, *frameArg;
  llvm::Value *numberedBase, *rBase, *qBase, *namedBase, *maxLoop, *depthPtr, *pollPtr;
  llvm::Value *localArrays = nullptr;  // this activation's named local arrays
  llvm::Value *lastIndex = nullptr;    // index of the last array element addressed
  llvm::Value *cmdSlot = nullptr, *argSlot = nullptr, *backJumps = nullptr, *scratch = nullptr;
  llvm::Value *blkCount = nullptr, *blkLast = nullptr;
  unsigned siteSlots_ = 0;  // commands in loops with a slot of their own (cmdSiteSlot)
  struct LoopTargets {
    llvm::BasicBlock *cont, *brk;
  };
  std::vector<LoopTargets> loops_;
  std::map<std::string, llvm::Value *> kept_;  // cacheKey -> the slot of an enclosing loop
  // Jump targets: every op in pre-order (the eval engine's instruction order), block numbers
  // and labels (the last definition of a label wins, as in the eval engine).
  std::unordered_map<const ir::Op *, unsigned> order_;
  std::vector<ir::JumpEntry> jumps_;      // block numbers and labels in pre-order (ir/Jumps.h)
  std::vector<const ir::Op *> jumpOps_;   // the op of each entry
  llvm::GlobalVariable *jumpTable_ = nullptr;  // jumps_ as a constant, once a computed goto needs it
  // call_section: where sections end, an id per call, the block after each call, and the
  // activation's section stack (depth, call ids, repetitions left).
  ir::SectionEnds sectionEnds_;
  std::unordered_map<const ir::Op *, unsigned> sectionIds_;
  std::unordered_map<const ir::Op *, llvm::BasicBlock *> sectionRet_;
  llvm::Value *sectionSp_ = nullptr, *sectionCalls_ = nullptr, *sectionLeft_ = nullptr;
  std::unordered_map<const ir::Op *, llvm::BasicBlock *> targetBBs_;
  std::vector<MachineCmd> run_;  // pending constant commands (text points into the IR)
  std::string packed_;           // or, for a long run, the packed encoding so far
};

}  // namespace ncc::jit
